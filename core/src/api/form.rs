//! `formFigures(form, options)` and `placeOnForm(form, points)`: the solved form as a design
//! object (casting figures, connectors on the surface). `form` is a `simulate` result (only the
//! fields named here are read). The geometry is in [`crate::form`].

use crate::error::{Error, Result};
use crate::form;
use serde::{Deserialize, Serialize};

/// Concrete, the default density of `formFigures` (kg/m³).
pub const DEFAULT_DENSITY: f64 = 2400.0;

/// The part of a `simulate` result these functions read.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct FormDto {
    pub vertices: Vec<[f64; 3]>,
    pub triangles: Vec<[usize; 3]>,
    #[serde(default)]
    pub piece: Vec<u8>,
    #[serde(default)]
    pub flat: Vec<[[f64; 2]; 3]>,
    #[serde(default)]
    pub stats: FormStatsDto,
}

/// `stats.volume` of the result (input units³).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct FormStatsDto {
    #[serde(default)]
    pub volume: f64,
}

/// `options` of `formFigures`; every field optional.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct FiguresOptionsDto {
    /// Millimetres per input unit (default 1: the form is in mm). Illustrator points: 25.4 / 72.
    #[serde(default)]
    pub mm_per_unit: Option<f64>,
    /// Density of the casting material in kg/m³ (default [`DEFAULT_DENSITY`], concrete).
    #[serde(default)]
    pub density: Option<f64>,
}

/// Result of `formFigures`: lengths in input units, volume in input units³.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct FiguresDto {
    pub volume: f64,
    pub litres: f64,
    /// Kilograms of material of `density` filling the form.
    pub mass: f64,
    pub density: f64,
    /// Principal extents (see [`crate::form::extents`]): least spread, most spread, the other.
    pub height: f64,
    pub width: f64,
    pub depth: f64,
    /// Unit axes of height, width and depth.
    pub axes: [[f64; 3]; 3],
    pub center: [f64; 3],
}

fn positive(name: &'static str, value: Option<f64>, default: f64, what: &str) -> Result<f64> {
    match value {
        None => Ok(default),
        Some(v) if v.is_finite() && v > 0.0 => Ok(v),
        Some(v) => Err(Error::Option { name, reason: format!("must be a positive number ({what}), got {v}") }),
    }
}

impl FormDto {
    /// Checks what the geometry indexes: finite vertices, triangle indices in range, and (when
    /// `flat` is needed) one piece and one flat triangle per triangle.
    fn check(&self, need_flat: bool) -> Result<()> {
        let bad = |detail: String| Err(Error::Shape { detail });
        if self.triangles.is_empty() {
            return bad("the form has no triangles (pass a simulate() result)".into());
        }
        if let Some(i) = self.vertices.iter().position(|v| !v.iter().all(|x| x.is_finite())) {
            return bad(format!("vertex {i} of the form is not a finite point"));
        }
        let n = self.vertices.len();
        if let Some(t) = self.triangles.iter().position(|t| t.iter().any(|&i| i >= n)) {
            return bad(format!("triangle {t} of the form names a vertex past the {n} vertices"));
        }
        if need_flat && (self.flat.len() != self.triangles.len() || self.piece.len() != self.triangles.len()) {
            return bad(format!(
                "the form has {} triangles but {} flat triangles and {} piece entries (pass a whole simulate() result)",
                self.triangles.len(),
                self.flat.len(),
                self.piece.len()
            ));
        }
        Ok(())
    }
}

/// `formFigures(form, options)`: volume (input units³ and litres), the mass of a casting of
/// `density`, and the principal extents.
pub fn figures(form: &FormDto, options: &FiguresOptionsDto) -> Result<FiguresDto> {
    let mm = positive("mmPerUnit", options.mm_per_unit, 1.0, "millimetres per unit of the form")?;
    let density = positive("density", options.density, DEFAULT_DENSITY, "kg/m³; concrete is about 2400")?;
    form.check(false)?;
    let e = form::principal_extents(&form.vertices, &form.triangles).ok_or_else(|| Error::Infeasible {
        reason: "The form has no surface area: there is nothing to measure.".into(),
    })?;
    let volume = form.stats.volume;
    let litres = volume * mm.powi(3) * 1e-6;
    Ok(FiguresDto {
        volume,
        litres,
        mass: litres * 1e-3 * density,
        density,
        height: e.height,
        width: e.width,
        depth: e.depth,
        axes: e.axes,
        center: e.center,
    })
}

/// `placeOnForm(form, [pointsOfA, pointsOfB])`: each flat point (input coordinates of its piece)
/// at its place on the 3D surface (see [`crate::form::place`]).
pub fn place(form: &FormDto, points: &[Vec<[f64; 2]>]) -> Result<Vec<Vec<[f64; 3]>>> {
    if points.len() != 2 {
        return Err(Error::PieceCount { wanted: "two lists of points (piece A, piece B)", got: points.len() });
    }
    form.check(true)?;
    points
        .iter()
        .enumerate()
        .map(|(k, list)| {
            list.iter()
                .enumerate()
                .map(|(i, &p)| {
                    if !(p[0].is_finite() && p[1].is_finite()) {
                        return Err(Error::Shape { detail: format!("point {i} of piece {} is not finite", ["A", "B"][k]) });
                    }
                    form::place(&form.vertices, &form.triangles, &form.piece, &form.flat, k as u8, p)
                        .map(|(at, _)| at)
                        .ok_or_else(|| Error::Infeasible {
                            reason: format!("Piece {} has no triangle on the form to place points on.", ["A", "B"][k]),
                        })
                })
                .collect()
        })
        .collect()
}
