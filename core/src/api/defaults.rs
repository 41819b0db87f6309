//! `defaults()`: the default connector options and how each is derived, as data, so that every
//! host shows and sends the same numbers (no host keeps its own). The values are the constants
//! of [`crate::connect::options`], which `connect` itself uses when an option is absent.
//!
//! A derived size is `pitch·p + length·l` (`p`, `l` the fields below) of the seam being
//! connected; a fixed one has `value`.

use crate::connect::leaves;
use crate::connect::options::{self as o, Kind};
use serde::{Deserialize, Serialize};

/// One option's default: a fixed `value` or a multiple of the pitch (and of the length).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DefaultDto {
    pub name: String,
    /// The kinds it applies to (`"stitch"`, `"teeth"`, `"leaves"`, `"hybrid"`).
    pub kinds: Vec<String>,
    /// For leaves: the leaf shape it applies to (`"tab"` or `"lock"`), else absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub leaf: Option<String>,
    /// A fixed default (number, string or boolean as JSON).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<serde_json_value::Value>,
    /// Derived: this fraction of the pitch…
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pitch: Option<f64>,
    /// …plus this fraction of the (tooth) length.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub length: Option<f64>,
    /// What the option means, in the user's words (for help texts and tooltips).
    pub help: String,
}

/// Result of `defaults()`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DefaultsDto {
    pub options: Vec<DefaultDto>,
    /// What `invert` does, per kind: the label each host shows next to it.
    pub invert: InvertDto,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct InvertDto {
    pub stitch: String,
    pub teeth: String,
    pub leaves: String,
    pub hybrid: String,
}

/// A JSON scalar without pulling in serde_json.
pub mod serde_json_value {
    use serde::{Deserialize, Serialize};

    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(untagged)]
    pub enum Value {
        Bool(bool),
        Number(f64),
        Text(String),
    }
}
use serde_json_value::Value;

fn kinds(k: &[Kind]) -> Vec<String> {
    k.iter().map(|&k| Kind::NAMES[k as usize].to_string()).collect()
}

fn fixed(name: &str, k: &[Kind], value: Value, help: &str) -> DefaultDto {
    DefaultDto { name: name.into(), kinds: kinds(k), leaf: None, value: Some(value), pitch: None, length: None, help: help.into() }
}

fn derived(name: &str, k: &[Kind], leaf: Option<&str>, pitch: f64, length: Option<f64>, help: &str) -> DefaultDto {
    DefaultDto { name: name.into(), kinds: kinds(k), leaf: leaf.map(Into::into), value: None, pitch: Some(pitch), length, help: help.into() }
}

/// `defaults()` → `{ options: [DefaultDto], invert: { stitch, teeth, leaves, hybrid } }`.
pub fn defaults() -> DefaultsDto {
    use Kind::*;
    let all = [Stitch, Teeth, Leaves, Hybrid];
    let holes = [Stitch, Hybrid];
    let teeth = [Teeth, Hybrid];
    DefaultsDto {
        options: vec![
            fixed("kind", &all, Value::Text("stitch".into()), "Stitch holes, teeth, leaves, or teeth with a hole each."),
            fixed("count", &all, Value::Number(o::DEFAULT_COUNT as f64), "Number of connectors on each piece (even for leaves, which alternate between the pieces)."),
            fixed("slide", &all, Value::Number(0.0), "Shift of every connector as a fraction of the distance between them. Left unset, connectors are shifted clear of the corners."),
            derived("diameter", &holes, None, o::DIAMETER_PER_PITCH, None, "Hole diameter, as the finished hole measures."),
            derived("inset", &[Stitch], None, o::INSET_PER_PITCH, None, "Distance from the seam line to the hole centres."),
            derived("inset", &[Hybrid], None, o::INSET_PER_PITCH, Some(0.5), "Distance from the seam line to the hole centres (beyond the gaps between the teeth)."),
            derived("length", &teeth, None, o::TEETH_LENGTH_PER_PITCH, None, "Tooth length, from the bottom of a gap to the tip of a tooth."),
            derived("length", &[Leaves], Some("tab"), o::TAB_LENGTH_PER_PITCH, None, "How far a leaf stands out of the edge."),
            derived("length", &[Leaves], Some("lock"), o::LOCK_LENGTH_PER_PITCH, None, "How far a locking leaf stands out of the edge (neck and head)."),
            fixed("angle", &teeth, Value::Number(o::DEFAULT_ANGLE), "Flank angle of the teeth in degrees: 90 is square, less narrows the teeth toward their tips, more than 90 makes dovetails that widen toward their tips and lock the pieces together."),
            fixed("leaf", &[Leaves], Value::Text("tab".into()), "tab: a rounded flap to glue. lock: a round head on a narrower neck that pushes through a slot cut in the other piece and holds without glue."),
            derived("width", &[Leaves], None, leaves::WIDTH, None, "Leaf (and locking head) width (fixed fraction of the pitch)."),
            derived("neck", &[Leaves], Some("lock"), leaves::NECK, None, "Neck width of a locking leaf, and length of its slot (fixed fraction of the pitch)."),
            derived("slot", &[Leaves], Some("lock"), leaves::SLOT, None, "Width of a slot across the edge (fixed fraction of the pitch)."),
            fixed("allowance", &[Stitch, Leaves], Value::Number(0.0), "Seam allowance: the cut line moves out by this much; holes and leaves stay on the seam line, which is scored so you can fold or stitch along it."),
            fixed("invert", &all, Value::Bool(false), "See `invert` for what it does with each kind."),
            fixed("kerf", &all, Value::Number(0.0), "Width of the laser cut, compensated so parts come out at their nominal size."),
        ],
        invert: InvertDto {
            stitch: o::invert_meaning(Stitch).into(),
            teeth: o::invert_meaning(Teeth).into(),
            leaves: o::invert_meaning(Leaves).into(),
            hybrid: o::invert_meaning(Hybrid).into(),
        },
    }
}
