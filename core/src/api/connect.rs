//! `connect(pieces, options)` of the contract: DTOs and their conversions.
//! The geometry and every option's meaning and default are in [`crate::connect`].

#[cfg(target_arch = "wasm32")]
pub mod js;

use super::path::{arr, PathDto};
use crate::connect::{self, leaves::Slot, options::RawOptions, Connection, Hole, Label, PieceOut};
use crate::error::{Error, Result};
use crate::validate;
use serde::{Deserialize, Serialize};

/// `options` of `connect`; every field optional (see [`crate::connect::options`]).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct ConnectOptionsDto {
    #[serde(default)]
    pub kind: Option<String>,
    #[serde(default)]
    pub count: Option<f64>,
    #[serde(default)]
    pub pitch: Option<f64>,
    #[serde(default)]
    pub slide: Option<f64>,
    #[serde(default)]
    pub start: Option<[f64; 2]>,
    #[serde(default)]
    pub inset: Option<f64>,
    #[serde(default)]
    pub diameter: Option<f64>,
    #[serde(default)]
    pub length: Option<f64>,
    #[serde(default)]
    pub angle: Option<f64>,
    /// `"tab"` (default) or `"lock"`.
    #[serde(default)]
    pub leaf: Option<String>,
    /// Seam allowance: distance from the seam line out to the cut line (default 0).
    #[serde(default)]
    pub allowance: Option<f64>,
    #[serde(default)]
    pub invert: Option<bool>,
    #[serde(default)]
    pub kerf: Option<f64>,
    #[serde(default)]
    pub accuracy: Option<f64>,
    /// `false` when the host draws no numbers: `labels` come back empty and unwarned.
    #[serde(default)]
    pub labels: Option<bool>,
    /// The unit the pieces and lengths are in ("mm", "in", …: up to 8 letters), named after every
    /// length in messages and warnings; absent: bare numbers.
    #[serde(default)]
    pub unit: Option<String>,
}

impl From<&ConnectOptionsDto> for RawOptions {
    fn from(o: &ConnectOptionsDto) -> Self {
        RawOptions {
            kind: o.kind.clone(),
            count: o.count,
            pitch: o.pitch,
            slide: o.slide,
            start: o.start,
            inset: o.inset,
            diameter: o.diameter,
            length: o.length,
            angle: o.angle,
            leaf: o.leaf.clone(),
            allowance: o.allowance,
            invert: o.invert,
            kerf: o.kerf,
            accuracy: o.accuracy,
            labels: o.labels,
            unit: o.unit.clone(),
        }
    }
}

/// `{ center: [x, y], diameter, path }`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct HoleDto {
    pub center: [f64; 2],
    pub diameter: f64,
    pub path: PathDto,
}

impl From<&Hole> for HoleDto {
    fn from(h: &Hole) -> Self {
        HoleDto { center: arr(h.center), diameter: h.diameter, path: PathDto::from(&h.path) }
    }
}

/// `{ text, at: [x, y], angle, size }`: `size` is the text height that keeps the label's box
/// (`size` high, `(0.6·characters + 0.2)·size` wide, centred on `at`) clear of the holes, slots,
/// cut line and other labels.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LabelDto {
    pub text: String,
    pub at: [f64; 2],
    pub angle: f64,
    pub size: f64,
}

impl From<&Label> for LabelDto {
    fn from(l: &Label) -> Self {
        LabelDto { text: l.text.clone(), at: arr(l.at), angle: l.angle, size: l.size }
    }
}

impl From<&Slot> for PathDto {
    fn from(s: &Slot) -> Self {
        PathDto::from(&s.path)
    }
}

/// `PieceResult = { outline, holes, slots, seam?, labels, marks }`: with a seam allowance
/// `outline` is the cut line and `seam` the seam line (absent without one).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PieceResultDto {
    pub outline: PathDto,
    pub holes: Vec<HoleDto>,
    #[serde(default)]
    pub slots: Vec<PathDto>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seam: Option<PathDto>,
    pub labels: Vec<LabelDto>,
    pub marks: Vec<PathDto>,
}

impl PieceResultDto {
    /// `input` is returned as the outline, point for point, when the edge is unchanged.
    fn new(p: &PieceOut, input: &PathDto) -> Self {
        PieceResultDto {
            outline: p.outline.as_ref().map(PathDto::from).unwrap_or_else(|| input.clone()),
            holes: p.holes.iter().map(HoleDto::from).collect(),
            slots: p.slots.iter().map(PathDto::from).collect(),
            // The seam line is the input outline: handed back point for point.
            seam: p.seam.as_ref().map(|_| input.clone()),
            labels: p.labels.iter().map(LabelDto::from).collect(),
            marks: p.marks.iter().map(PathDto::from).collect(),
        }
    }
}

/// `{ count, pitch, slide, pieces: [PieceResult, PieceResult], warnings }`; `slide` is the one
/// used (as given, or chosen to keep connectors clear of corners when none was given).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ConnectDto {
    pub count: usize,
    pub pitch: f64,
    #[serde(default)]
    pub slide: f64,
    pub pieces: [PieceResultDto; 2],
    pub warnings: Vec<String>,
}

/// `connect(pieces, options)`: exactly two closed, simple pieces of equal perimeter.
pub fn connect(pieces: &[PathDto], options: &ConnectOptionsDto) -> Result<ConnectDto> {
    if pieces.len() != 2 {
        return Err(Error::PieceCount { wanted: "exactly two pieces to connect", got: pieces.len() });
    }
    let a = pieces[0].to_contour(0)?;
    let b = pieces[1].to_contour(1)?;
    validate::check_outline(&a, 0)?;
    validate::check_outline(&b, 1)?;
    let c: Connection = connect::connect(&a, &b, &RawOptions::from(options))?;
    Ok(ConnectDto {
        count: c.count,
        pitch: c.pitch,
        slide: c.slide,
        pieces: [PieceResultDto::new(&c.pieces[0], &pieces[0]), PieceResultDto::new(&c.pieces[1], &pieces[1])],
        warnings: c.warnings,
    })
}
