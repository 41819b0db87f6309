//! Options of `connect`: what the user may give, the checks, and the defaults.
//!
//! Units are the host's (points, px, mm); the core never assumes one. Every size that has a
//! default is therefore a fraction of the pitch `p` (the arc length between connectors), which
//! keeps proportions right at any scale:
//!
//! | option     | default                         | kinds                 |
//! |------------|---------------------------------|-----------------------|
//! | `kind`     | `"stitch"`                      |                       |
//! | `slide`    | `0`, shifted clear of corners when neither `slide` nor `start` is given ([`super::phase`]) | |
//! | `start`    | `[0, 0]` (the first anchors)    |                       |
//! | `diameter` | `p / 4`                         | stitch, hybrid        |
//! | `inset`    | `p / 2` (stitch), `length / 2 + p / 2` (hybrid) | stitch, hybrid |
//! | `length`   | `p / 2` (teeth, hybrid), `3p / 4` (tab leaves), `p` (locking leaves) | teeth, hybrid, leaves |
//! | `angle`    | `90` degrees (square crenellations; above 90 a dovetail) | teeth, hybrid |
//! | `leaf`     | `"tab"` (a glued tab; `"lock"`: a bulb on a neck and a slot on the other piece) | leaves |
//! | `allowance`| `0` (the cut line is the seam line) | stitch, leaves  |
//! | `invert`   | `false` (its meaning per kind: [`invert_meaning`]) |   |
//! | `kerf`     | `0`                             |                       |
//! | `accuracy` | [`DEFAULT_ACCURACY`](crate::arclen::DEFAULT_ACCURACY) (relative) | |
//!
//! Exactly one of `count` and `pitch` must be given (hosts start from [`DEFAULT_COUNT`]). A `pitch`
//! is rounded to the nearest whole number of connectors (at least 1; for leaves, which alternate
//! between the pieces, the nearest even number) and then adjusted so that it divides the perimeter
//! exactly. An odd `count` of leaves is refused, naming the nearest even counts: with an odd
//! count two neighbouring leaves would stand on the same piece where the seam closes.
//! The table is exported as data by [`crate::api::defaults`], which every host reads.

use crate::error::{len, Error, Result};

/// Most connectors accepted on one seam (more is surely a unit mistake).
pub const MAX_COUNT: usize = 10_000;

/// The number of connectors every host starts with.
pub const DEFAULT_COUNT: usize = 24;

/// Default flank angle of teeth, degrees: square crenellations.
pub const DEFAULT_ANGLE: f64 = 90.0;

/// Defaults of the sizes as fractions of the pitch `p` (and of the length, for the hybrid inset).
pub const DIAMETER_PER_PITCH: f64 = 0.25;
pub const INSET_PER_PITCH: f64 = 0.5;
pub const TEETH_LENGTH_PER_PITCH: f64 = 0.5;
pub const TAB_LENGTH_PER_PITCH: f64 = 0.75;
pub const LOCK_LENGTH_PER_PITCH: f64 = 1.0;

/// What `invert` does for each kind, in the words a host shows next to its checkbox.
pub fn invert_meaning(kind: Kind) -> &'static str {
    match kind {
        Kind::Stitch => "Holes outside the piece (on the other side of the seam line)",
        Kind::Teeth | Kind::Hybrid => "Swap teeth and gaps between the pieces (A starts with a gap)",
        Kind::Leaves => "Swap which piece carries each leaf (A starts with a landing spot)",
    }
}

/// How a leaf is shaped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Leaf {
    /// Straight sides and a round cap, for gluing.
    Tab,
    /// A round head on a narrower neck; the other piece gets a slot that holds the neck.
    Lock,
}

impl Leaf {
    pub const NAMES: [&'static str; 2] = ["tab", "lock"];

    pub fn parse(name: Option<&str>) -> Result<Leaf> {
        match name {
            None | Some("tab") => Ok(Leaf::Tab),
            Some("lock") => Ok(Leaf::Lock),
            Some(other) => Err(Error::Option { name: "leaf", reason: format!("must be \"tab\" (glued) or \"lock\" (a head on a neck, locked in a slot), got \"{other}\"") }),
        }
    }
}

/// What kind of connector to place.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Paired holes for stitching, lacing, rivets or cable ties.
    Stitch,
    /// Interlocking crenellations built into both outlines.
    Teeth,
    /// Rounded tabs, alternating between the pieces.
    Leaves,
    /// Teeth with a stitch hole at every connector.
    Hybrid,
}

impl Kind {
    /// The accepted names, in the order the error message lists them.
    pub const NAMES: [&'static str; 4] = ["stitch", "teeth", "leaves", "hybrid"];

    pub fn parse(name: &str) -> Result<Kind> {
        match name {
            "stitch" => Ok(Kind::Stitch),
            "teeth" => Ok(Kind::Teeth),
            "leaves" => Ok(Kind::Leaves),
            "hybrid" => Ok(Kind::Hybrid),
            other => Err(Error::Option {
                name: "kind",
                reason: format!(
                    "must be one of {}, got \"{}\"",
                    Kind::NAMES.map(|n| format!("\"{n}\"")).join(", "),
                    other
                ),
            }),
        }
    }

    pub fn has_holes(self) -> bool {
        matches!(self, Kind::Stitch | Kind::Hybrid)
    }

    pub fn has_teeth(self) -> bool {
        matches!(self, Kind::Teeth | Kind::Hybrid)
    }
}

/// The options exactly as given (every field optional), in core types.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RawOptions {
    pub kind: Option<String>,
    pub count: Option<f64>,
    pub pitch: Option<f64>,
    pub slide: Option<f64>,
    pub start: Option<[f64; 2]>,
    pub inset: Option<f64>,
    pub diameter: Option<f64>,
    pub length: Option<f64>,
    pub angle: Option<f64>,
    pub leaf: Option<String>,
    pub allowance: Option<f64>,
    pub invert: Option<bool>,
    pub kerf: Option<f64>,
    pub accuracy: Option<f64>,
    /// `false`: the host draws no numbers, so none are laid out or warned about.
    pub labels: Option<bool>,
    /// The name of the unit the pieces and lengths are in, written after every length in
    /// messages ("mm", "in"); none: bare numbers.
    pub unit: Option<String>,
}

/// Checked options with every default filled in, for a seam of known perimeter.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    pub kind: Kind,
    pub count: usize,
    /// Perimeter / count.
    pub pitch: f64,
    pub slide: f64,
    pub start: [f64; 2],
    /// Edge (seam line) to hole centre.
    pub inset: f64,
    /// Nominal hole diameter (what the finished hole measures).
    pub diameter: f64,
    /// Teeth: gap bottom to tooth tip. Leaves: how far a tab stands out of the edge.
    pub length: f64,
    /// Teeth flank angle against the edge inside the tooth, radians, in (0, π): π/2 square,
    /// less tapered, more a dovetail (wider at the tip).
    pub angle: f64,
    pub leaf: Leaf,
    /// Distance from the seam line out to the cut line.
    pub allowance: f64,
    pub invert: bool,
    pub kerf: f64,
}

fn bad(name: &'static str, reason: String) -> Error {
    Error::Option { name, reason }
}

/// A finite, strictly positive size (or the default when absent).
fn positive(name: &'static str, v: Option<f64>, default: f64) -> Result<f64> {
    match v {
        None => Ok(default),
        Some(x) if x.is_finite() && x > 0.0 => Ok(x),
        Some(x) => Err(bad(name, format!("must be a positive number, got {}", len(x)))),
    }
}

/// The unit's name for messages: 1 to 8 letters (a `µ`, a `²` or a `.` allowed), or none.
pub fn unit(raw: &RawOptions) -> Result<Option<&str>> {
    match raw.unit.as_deref() {
        None => Ok(None),
        Some(u) if (1..=8).contains(&u.chars().count()) && u.chars().all(|c| c.is_alphabetic() || "µ².".contains(c)) => Ok(Some(u)),
        Some(u) => Err(Error::Option { name: "unit", reason: format!("must be the name of a unit, 1 to 8 letters (\"mm\", \"in\"), got {u:?}") }),
    }
}

/// The kind, checked before anything is measured.
pub fn kind(raw: &RawOptions) -> Result<Kind> {
    raw.kind.as_deref().map(Kind::parse).unwrap_or(Ok(Kind::Stitch))
}

/// Number of connectors from `count` or `pitch` (exactly one of them) on a seam of `perimeter`.
pub fn count(raw: &RawOptions, perimeter: f64) -> Result<usize> {
    let n = plain_count(raw, perimeter)?;
    if kind(raw)? == Kind::Leaves && n % 2 == 1 {
        if raw.pitch.is_some() {
            // The nearest even count to perimeter / pitch.
            let x = perimeter / raw.pitch.unwrap_or(1.0);
            let even = 2.0 * (x / 2.0).round().max(1.0);
            return Ok((even as usize).min(MAX_COUNT));
        }
        let names = if n == 1 { "2".to_string() } else { format!("{} or {}", n - 1, n + 1) };
        return Err(bad(
            "count",
            format!("leaves alternate between the two pieces, so their number must be even, got {n}: use {names}"),
        ));
    }
    Ok(n)
}

/// `count` or `pitch` as a whole number of connectors, for any kind.
fn plain_count(raw: &RawOptions, perimeter: f64) -> Result<usize> {
    match (raw.count, raw.pitch) {
        (Some(_), Some(_)) => Err(bad("count", "give either `count` or `pitch`, not both".into())),
        (None, None) => Err(bad("count", "give either `count` (number of connectors) or `pitch` (distance between them)".into())),
        (Some(c), None) => {
            if !c.is_finite() || c.fract() != 0.0 || c < 1.0 || c > MAX_COUNT as f64 {
                Err(bad("count", format!("must be a whole number from 1 to {MAX_COUNT}, got {c}")))
            } else {
                Ok(c as usize)
            }
        }
        (None, Some(p)) => {
            if !(p.is_finite() && p > 0.0) {
                return Err(bad("pitch", format!("must be a positive number, got {}", len(p))));
            }
            let n = (perimeter / p).round().max(1.0);
            if n > MAX_COUNT as f64 {
                return Err(bad(
                    "pitch",
                    format!("{} on a perimeter of {} gives {n} connectors; at most {MAX_COUNT} are allowed", len(p), len(perimeter)),
                ));
            }
            Ok(n as usize)
        }
    }
}

/// Checks every option and fills the defaults (see the module table) for a seam of `perimeter`.
pub fn resolve(raw: &RawOptions, perimeter: f64) -> Result<Settings> {
    let kind = kind(raw)?;
    let count = count(raw, perimeter)?;
    let pitch = perimeter / count as f64;
    let slide = match raw.slide {
        None => 0.0,
        Some(s) if s.is_finite() && (0.0..=1.0).contains(&s) => s,
        Some(s) => return Err(bad("slide", format!("must be between 0 and 1 (a fraction of the pitch), got {s}"))),
    };
    let start = match raw.start {
        None => [0.0, 0.0],
        Some([a, b]) if a.is_finite() && b.is_finite() => [a, b],
        Some([a, b]) => return Err(bad("start", format!("must be two finite arc lengths [sA, sB], got [{a}, {b}]"))),
    };
    let leaf = Leaf::parse(raw.leaf.as_deref())?;
    let default_length = match (kind, leaf) {
        (Kind::Leaves, Leaf::Tab) => TAB_LENGTH_PER_PITCH * pitch,
        (Kind::Leaves, Leaf::Lock) => LOCK_LENGTH_PER_PITCH * pitch,
        _ => TEETH_LENGTH_PER_PITCH * pitch,
    };
    let length = positive("length", raw.length, default_length)?;
    let diameter = positive("diameter", raw.diameter, DIAMETER_PER_PITCH * pitch)?;
    let default_inset = if kind == Kind::Hybrid { 0.5 * length + INSET_PER_PITCH * pitch } else { INSET_PER_PITCH * pitch };
    let inset = positive("inset", raw.inset, default_inset)?;
    let angle = match raw.angle {
        None => DEFAULT_ANGLE,
        Some(a) if a.is_finite() && a > 0.0 && a < 180.0 => a,
        Some(a) => {
            return Err(bad(
                "angle",
                format!("must be a flank angle in degrees, more than 0 and less than 180 (90 square, more than 90 a dovetail), got {a}"),
            ))
        }
    };
    let allowance = match raw.allowance {
        None => 0.0,
        Some(a) if a.is_finite() && a >= 0.0 => a,
        Some(a) => return Err(bad("allowance", format!("must be zero or a positive distance from the seam line to the cut line, got {}", len(a)))),
    };
    if allowance > 0.0 && kind.has_teeth() {
        return Err(bad(
            "allowance",
            "teeth interlock on the seam line itself, so they take no seam allowance: set it to 0, or use stitch holes or leaves".into(),
        ));
    }
    let kerf = match raw.kerf {
        None => 0.0,
        Some(k) if k.is_finite() && k >= 0.0 => k,
        Some(k) => return Err(bad("kerf", format!("must be zero or a positive cut width, got {}", len(k)))),
    };
    if kind.has_holes() && kerf >= diameter {
        return Err(bad("kerf", format!("{} is not smaller than the hole diameter {}: the holes would vanish", len(kerf), len(diameter))));
    }
    Ok(Settings {
        kind,
        count,
        pitch,
        slide,
        start,
        inset,
        diameter,
        length,
        angle: angle.to_radians(),
        leaf,
        allowance,
        invert: raw.invert.unwrap_or(false),
        kerf,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn raw_count(c: f64) -> RawOptions {
        RawOptions { count: Some(c), ..Default::default() }
    }

    #[test]
    fn pitch_is_rounded_to_divide_the_perimeter() {
        let raw = RawOptions { pitch: Some(3.0), ..Default::default() };
        let s = resolve(&raw, 100.0).unwrap();
        assert_eq!(s.count, 33, "wanted 33 connectors, got {}", s.count);
        assert!((s.pitch * 33.0 - 100.0).abs() < 1e-12, "pitch {} does not divide 100", s.pitch);
    }

    #[test]
    fn defaults_scale_with_the_pitch() {
        let s = resolve(&raw_count(10.0), 100.0).unwrap();
        assert_eq!((s.kind, s.diameter, s.inset, s.slide), (Kind::Stitch, 2.5, 5.0, 0.0));
    }

    #[test]
    fn rejects_fractional_and_absurd_counts() {
        for c in [0.0, 2.5, 10_001.0, f64::NAN] {
            let e = resolve(&raw_count(c), 100.0).unwrap_err().to_string();
            assert!(e.contains("whole number from 1 to 10000"), "count {c}: got {e}");
        }
    }
}
