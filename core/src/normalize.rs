//! Perimeter normalization: scale each closed outline about a pivot so that all of them have
//! one target perimeter.
//!
//! A uniform scaling `p ↦ c + s (p − c)` maps a Bézier curve to the Bézier curve of the mapped
//! control points (affine invariance) and multiplies every arc length by exactly `s`, so
//! `s = target / perimeter` gives the target perimeter; the only error left is the rounding of
//! the new coordinates (≈ 1e-16 of their magnitude) and the relative accuracy of the two arc
//! lengths, which scale together because kurbo's quadrature decisions are scale-invariant.

use crate::arclen::ArcTable;
use crate::contour::{Contour, Knot};
use crate::error::{Error, Result};
use crate::measure;
use kurbo::{Point, Shape};

/// Which perimeter every outline gets.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    Largest,
    Smallest,
    /// Arithmetic mean of the perimeters.
    Mean,
    /// The first outline's perimeter (the first outline is left untouched).
    First,
    /// An explicit perimeter (finite, > 0).
    Value(f64),
}

/// The fixed point of each outline's scaling.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pivot {
    /// Centre of the outline's tight bounding box.
    Center,
    /// Centroid of the enclosed region.
    Centroid,
    /// Each outline's first anchor (the 2016 scripts' Modify Perimeter: the first node stays).
    Start,
    /// The same point for every outline.
    At(Point),
}

/// What `normalize` asks for, in the count error.
pub const PIECES_WANTED: &str = "at least 2 closed paths to normalize, or 1 with a number as the target perimeter";

/// Result of [`normalize`].
#[derive(Debug, Clone, PartialEq)]
pub struct Normalized {
    pub contours: Vec<Contour>,
    /// Scale factor applied to each outline.
    pub scales: Vec<f64>,
    /// The common perimeter.
    pub perimeter: f64,
}

/// Scales every contour about its pivot to the target perimeter (arc lengths to relative
/// `accuracy`). Contours must already be validated (see [`crate::validate::check_outline`]).
/// One outline is accepted with an explicit target perimeter (`Target::Value`); the relative
/// targets need at least two.
pub fn normalize(contours: &[Contour], target: Target, pivot: Pivot, accuracy: f64) -> Result<Normalized> {
    let single = matches!(target, Target::Value(_));
    if contours.is_empty() || (contours.len() < 2 && !single) {
        return Err(Error::PieceCount { wanted: PIECES_WANTED, got: contours.len() });
    }
    let perimeters: Vec<f64> = contours.iter().map(|c| ArcTable::new(c, accuracy).total()).collect();
    let target = match target {
        Target::Largest => perimeters.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        Target::Smallest => perimeters.iter().copied().fold(f64::INFINITY, f64::min),
        // Mean of halves: no overflow for perimeters near f64::MAX.
        Target::Mean => perimeters.iter().map(|p| p / perimeters.len() as f64).sum(),
        Target::First => perimeters.first().copied().unwrap_or(0.0),
        Target::Value(v) => v,
    };
    if !(target.is_finite() && target > 0.0) {
        return Err(Error::Option { name: "target", reason: format!("must be a positive, finite perimeter, got {}", crate::error::len(target)) });
    }
    let mut out = Vec::with_capacity(contours.len());
    let mut scales = Vec::with_capacity(contours.len());
    for (piece, (c, &p)) in contours.iter().zip(&perimeters).enumerate() {
        if !(p > 0.0 && p.is_finite()) {
            return Err(Error::ZeroLength { piece });
        }
        let s = target / p;
        let scaled = if s == 1.0 {
            c.clone()
        } else {
            let o = match pivot {
                Pivot::Center => {
                    let r = c.to_bezpath().bounding_box();
                    Point::new(r.x0 / 2.0 + r.x1 / 2.0, r.y0 / 2.0 + r.y1 / 2.0)
                }
                Pivot::Centroid => measure::measure(c, accuracy).centroid,
                Pivot::Start => c.knots()[0].anchor,
                Pivot::At(p) => p,
            };
            let map = |q: Point| Point::new(o.x + s * (q.x - o.x), o.y + s * (q.y - o.y));
            let knots = c
                .knots()
                .iter()
                .map(|k| Knot { anchor: map(k.anchor), left: map(k.left), right: map(k.right) })
                .collect();
            Contour::new(knots, piece).map_err(|_| Error::Option {
                name: "target",
                reason: format!(
                    "scaling the {} path by {s:.3e} to perimeter {} leaves the range of numbers; choose a smaller target",
                    crate::error::ordinal(piece),
                    crate::error::len(target)
                ),
            })?
        };
        out.push(scaled);
        scales.push(s);
    }
    Ok(Normalized { contours: out, scales, perimeter: target })
}
