//! The JSON-shaped API of the contract: plain DTOs in, plain DTOs out, every failure an
//! [`Error`] with a user-facing message. The WASM binding (`wasm.rs`) and the `dformer` CLI are
//! thin shells around these functions; no kurbo type crosses this boundary.

pub mod connect;
pub mod defaults;
pub mod form;
pub mod normalize;
pub mod path;
pub mod simulate;
pub mod svg;
pub mod value;

pub use defaults::defaults;
pub use normalize::normalize;
pub use svg::{path_from_svg, path_to_svg};

use crate::arclen::{DEFAULT_ACCURACY, MAX_ACCURACY, MIN_ACCURACY};
use crate::error::{Error, Result};
use crate::measure::{self, Orientation};
use crate::validate;
use path::{arr, PathDto};
use serde::{Deserialize, Serialize};

/// `{ min: [x, y], max: [x, y] }`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BoundsDto {
    pub min: [f64; 2],
    pub max: [f64; 2],
}

/// Result of `measure`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MeasureDto {
    pub perimeter: f64,
    pub area: f64,
    /// `"ccw"` or `"cw"`, for a y-up coordinate system.
    pub orientation: String,
    pub bounds: BoundsDto,
    pub centroid: [f64; 2],
}

/// Checks a user-supplied relative accuracy, defaulting to [`DEFAULT_ACCURACY`].
pub fn accuracy_or_default(accuracy: Option<f64>) -> Result<f64> {
    match accuracy {
        None => Ok(DEFAULT_ACCURACY),
        Some(a) if a.is_finite() && (MIN_ACCURACY..=MAX_ACCURACY).contains(&a) => Ok(a),
        Some(a) => Err(Error::Option {
            name: "accuracy",
            reason: format!(
                "must be a relative tolerance between {MIN_ACCURACY:e} and {MAX_ACCURACY} (default {DEFAULT_ACCURACY:e}), got {a}"
            ),
        }),
    }
}

/// `measure(path, accuracy?)`: perimeter (relative error ≤ `accuracy`), area, orientation
/// (y-up), tight bounds and centroid of one closed path.
pub fn measure(path: &PathDto, accuracy: Option<f64>) -> Result<MeasureDto> {
    let accuracy = accuracy_or_default(accuracy)?;
    let contour = path.to_contour(0)?;
    validate::check_outline(&contour, 0)?;
    let m = measure::measure(&contour, accuracy);
    if !(m.perimeter.is_finite() && m.area.is_finite()) {
        return Err(Error::Infeasible {
            reason: "The path is too large to measure: its coordinates are near the limit of floating-point numbers. Scale it down.".into(),
        });
    }
    Ok(MeasureDto {
        perimeter: m.perimeter,
        area: m.area,
        orientation: match m.orientation {
            Orientation::Ccw => "ccw",
            Orientation::Cw => "cw",
        }
        .into(),
        bounds: BoundsDto { min: arr(m.bounds.0), max: arr(m.bounds.1) },
        centroid: arr(m.centroid),
    })
}
