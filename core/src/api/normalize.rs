//! `normalize(paths, options)` → `{ paths, scales, perimeter }`.

use super::path::{pt, PathDto};
use super::value::Value;
use super::accuracy_or_default;
use crate::error::{Error, Result};
use crate::normalize::{self, Pivot, Target};
use crate::validate;
use serde::{Deserialize, Serialize};

/// Options of `normalize`; every field optional, unknown fields ignored.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(default)]
pub struct NormalizeOptionsDto {
    /// `"largest" | "smallest" | "mean" | "first"` or a perimeter (number > 0). Default `"largest"`.
    pub target: Option<Value>,
    /// `"center"` (bounding-box centre, default) | `"centroid"` | `"start"` (first anchor) | `[x, y]`.
    pub pivot: Option<Value>,
    /// Relative accuracy of the perimeters (default [`crate::DEFAULT_ACCURACY`]).
    pub accuracy: Option<Value>,
}

/// Result of `normalize`: the scaled paths (same points, same order), the scale applied to
/// each, and the common perimeter.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NormalizeDto {
    pub paths: Vec<PathDto>,
    pub scales: Vec<f64>,
    pub perimeter: f64,
}

const TARGETS: &str = r#""largest", "smallest", "mean", "first" or a perimeter (a positive number)"#;

fn target(v: Option<&Value>) -> Result<Target> {
    let bad = |v: &Value| Error::Option { name: "target", reason: format!("must be {TARGETS}, got {v}") };
    match v {
        None | Some(Value::Null) => Ok(Target::Largest),
        Some(Value::Text(s)) => match s.as_str() {
            "largest" => Ok(Target::Largest),
            "smallest" => Ok(Target::Smallest),
            "mean" => Ok(Target::Mean),
            "first" => Ok(Target::First),
            _ => Err(bad(&Value::Text(s.clone()))),
        },
        Some(Value::Number(x)) if x.is_finite() && *x > 0.0 => Ok(Target::Value(*x)),
        // A number is a length: rounded for people, as in every message.
        Some(Value::Number(x)) => Err(Error::Option { name: "target", reason: format!("must be {TARGETS}, got {}", crate::error::len(*x)) }),
        Some(v) => Err(bad(v)),
    }
}

fn pivot(v: Option<&Value>) -> Result<Pivot> {
    match v {
        None | Some(Value::Null) => Ok(Pivot::Center),
        Some(Value::Text(s)) if s == "center" => Ok(Pivot::Center),
        Some(Value::Text(s)) if s == "centroid" => Ok(Pivot::Centroid),
        Some(Value::Text(s)) if s == "start" => Ok(Pivot::Start),
        Some(v) => match v.as_point() {
            Some(p) => Ok(Pivot::At(pt(p))),
            None => Err(Error::Option {
                name: "pivot",
                reason: format!(
                    r#"must be "center" (bounding-box centre), "centroid", "start" (each path's first anchor) or a point [x, y] of two finite numbers, got {v}"#
                ),
            }),
        },
    }
}

/// Reads an optional numeric accuracy option.
pub(crate) fn accuracy_option(v: Option<&Value>) -> Result<f64> {
    match v {
        None | Some(Value::Null) => accuracy_or_default(None),
        Some(Value::Number(a)) => accuracy_or_default(Some(*a)),
        Some(v) => Err(Error::Option { name: "accuracy", reason: format!("must be a number, got {v}") }),
    }
}

/// `normalize(paths, options)`: two or more closed paths (one, when `target` is a number) scaled about their pivots to one
/// perimeter. Options are checked before the paths, paths in order.
pub fn normalize(paths: &[PathDto], options: &NormalizeOptionsDto) -> Result<NormalizeDto> {
    let target = target(options.target.as_ref())?;
    let pivot = pivot(options.pivot.as_ref())?;
    let accuracy = accuracy_option(options.accuracy.as_ref())?;
    if paths.is_empty() || (paths.len() < 2 && !matches!(target, Target::Value(_))) {
        return Err(Error::PieceCount { wanted: normalize::PIECES_WANTED, got: paths.len() });
    }
    let contours = paths
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let c = p.to_contour(i)?;
            validate::check_outline(&c, i)?;
            Ok(c)
        })
        .collect::<Result<Vec<_>>>()?;
    let n = normalize::normalize(&contours, target, pivot, accuracy)?;
    Ok(NormalizeDto { paths: n.contours.iter().map(PathDto::from).collect(), scales: n.scales, perimeter: n.perimeter })
}
