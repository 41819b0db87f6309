//! The one error type of the core. Every message is written for the person holding the
//! mouse: it names the piece, the point or the segment, and says what to do — in plain words,
//! never a host's menu: each host replaces those phrases by its own commands from the one table
//! `messages/commands.json` (Illustrator's Object > Path > Join, Inkscape's Path > Combine…).

use crate::libm_ext::LibmExt;
use std::fmt;

/// Result alias used across the crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Everything that can go wrong with user input. The core never panics; it returns one of these.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// The input is not shaped like the contract (missing field, wrong type). `detail` says where.
    Shape { detail: String },
    /// A coordinate is NaN or infinite.
    NonFinite { piece: usize, point: usize, field: &'static str },
    /// A path with fewer than two points.
    TooFewPoints { piece: usize, count: usize },
    /// An open path where a closed outline is needed.
    OpenPath { piece: usize },
    /// The outline has no length at all (every point at the same place).
    ZeroLength { piece: usize },
    /// The outline crosses itself; segment indices are 0-based (segment i runs from point i to i+1).
    SelfIntersection { piece: usize, first: usize, second: usize },
    /// Wrong number of paths or pieces for the operation.
    PieceCount { wanted: &'static str, got: usize },
    /// An option is out of its range or has the wrong type.
    Option { name: &'static str, reason: String },
    /// Two pieces that must be stitched have different perimeters.
    PerimeterMismatch { a: f64, b: f64 },
    /// Nothing sensible can be made with these options (connectors do not fit, etc.).
    Infeasible { reason: String },
    /// SVG path data that cannot be read: 0-based character `position`, the text `near` it.
    SvgSyntax { position: usize, near: String, problem: String },
}

pub(crate) fn ordinal(piece: usize) -> String {
    match piece {
        0 => "first".into(),
        1 => "second".into(),
        2 => "third".into(),
        n => {
            let k = n + 1;
            let suffix = match (k % 10, k % 100) {
                (_, 11..=13) => "th",
                (1, _) => "st",
                (2, _) => "nd",
                (3, _) => "rd",
                _ => "th",
            };
            format!("{k}{suffix}")
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Shape { detail } => write!(f, "Invalid input: {detail}"),
            Error::NonFinite { piece, point, field } => write!(
                f,
                "The {} path has a coordinate that is not a finite number (point {}, {}). Check the shape for broken points.",
                ordinal(*piece), point + 1, field
            ),
            Error::TooFewPoints { piece, count } => write!(
                f,
                "The {} path has {} point{}; an outline needs at least 2.",
                ordinal(*piece), count, if *count == 1 { "" } else { "s" }
            ),
            Error::OpenPath { piece } => write!(
                f,
                "The {} path is open. D-form pieces must be closed outlines: close the path and try again.",
                ordinal(*piece)
            ),
            Error::ZeroLength { piece } => write!(f, "The {} path has zero length: all its points are in the same place.", ordinal(*piece)),
            Error::SelfIntersection { piece, first, second } if first == second => write!(
                f,
                "The {} path crosses itself: segment {} (the one leaving point {}) loops over itself. A D-form piece must be a simple outline.",
                ordinal(*piece), first + 1, first + 1
            ),
            Error::SelfIntersection { piece, first, second } => write!(
                f,
                "The {} path crosses itself: segment {} (the one leaving point {}) intersects segment {} (the one leaving point {}). A D-form piece must be a simple outline.",
                ordinal(*piece), first + 1, first + 1, second + 1, second + 1
            ),
            Error::PieceCount { wanted, got } => write!(f, "Expected {wanted}, got {got}."),
            Error::Option { name, reason } => write!(f, "Option `{name}`: {reason}"),
            Error::PerimeterMismatch { a, b } => write!(
                f,
                "The two pieces have different perimeters ({a} and {b}; they differ by {} %). Normalize them first so they can be stitched edge to edge.",
                two_significant(100.0 * (a - b).abs() / a.abs().max(b.abs()))
            ),
            Error::Infeasible { reason } => write!(f, "{reason}"),
            Error::SvgSyntax { position, near, problem } if near.is_empty() => {
                write!(f, "Could not read the SVG path data at its end (character {}): {problem}.", position + 1)
            }
            Error::SvgSyntax { position, near, problem } => write!(
                f,
                "Could not read the SVG path data at character {} (near \"{near}\"): {problem}.",
                position + 1
            ),
        }
    }
}

impl std::error::Error for Error {}

/// `x` rounded to two significant digits, for messages. Printed with `{}` (shortest round-trip),
/// so `9.8e-5` shows as `0.000098`: dividing the rounded integer by an exact power of ten gives the
/// double nearest the two-digit decimal. Users read "differ by 0.012 %" more easily than an
/// exponent.
pub fn two_significant(x: f64) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x;
    }
    let k = 1 - x.abs().log10_m().floor() as i32; // digits to keep after the decimal point
    if !(-22..=22).contains(&k) {
        return x;
    }
    let p = 10f64.powi(k.abs()); // exact for |k| ≤ 22
    if k >= 0 { (x * p).round() / p } else { (x / p).round() * p }
}

/// `x` rounded to `digits` significant digits (same printing as [`two_significant`]).
pub fn significant(x: f64, digits: i32) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x;
    }
    let k = digits - 1 - x.abs().log10_m().floor() as i32;
    if !(-22..=22).contains(&k) {
        return x;
    }
    let p = 10f64.powi(k.abs());
    if k >= 0 { (x * p).round() / p } else { (x / p).round() * p }
}

thread_local! {
    /// The name of the caller's unit while a call that has one runs ([`unit_scope`]).
    static UNIT: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
}

/// While the returned guard lives, [`len`] writes `name` after every length ("0.8 in"). A host
/// that sends its geometry in the user's unit names it, so messages say which unit they speak.
pub fn unit_scope(name: Option<&str>) -> UnitScope {
    let previous = UNIT.with(|u| u.replace(name.map(str::to_string)));
    UnitScope { previous }
}

/// Restores the unit of [`len`] when dropped.
pub struct UnitScope {
    previous: Option<String>,
}

impl Drop for UnitScope {
    fn drop(&mut self) {
        UNIT.with(|u| *u.borrow_mut() = self.previous.take());
    }
}

/// A length as people read it in a message: four significant digits ("55.64", "0.1235", "1235"),
/// in the caller's unit (the core has none; hosts convert before they call), followed by its
/// name when the caller gave one ([`unit_scope`]).
pub fn len(x: f64) -> String {
    // Beyond what decimal rounding covers (about 1e-19 to 1e25), four digits in e-notation.
    let huge = x.is_finite() && x != 0.0 && !(1e-18..1e24).contains(&x.abs());
    let v = if huge { format!("{x:.3e}") } else { significant(x, 4).to_string() };
    UNIT.with(|u| match &*u.borrow() {
        Some(name) => format!("{v} {name}"),
        None => v,
    })
}

/// An angle in degrees for a message, to 0.1° ("12.5").
pub fn deg(x: f64) -> String {
    if x.is_finite() { ((x * 10.0).round() / 10.0).to_string() } else { x.to_string() }
}

#[cfg(test)]
mod tests {
    use super::{deg, len, two_significant, unit_scope};

    #[test]
    fn message_numbers_are_rounded_for_people() {
        for (x, want) in [(55.636085526653936, "55.64"), (0.123456, "0.1235"), (1234.56, "1235"), (8.0, "8"), (-14.173228, "-14.17")] {
            assert_eq!(len(x), want, "len({x})");
        }
        {
            let _in = unit_scope(Some("in"));
            assert_eq!(len(0.799999), "0.8 in");
        }
        assert_eq!(len(0.799999), "0.8", "the unit ends with its scope");
        assert_eq!(len(1.2345678e306), "1.235e306", "far beyond decimal rounding");
        assert_eq!(len(-2.5e-30), "-2.500e-30");
        assert_eq!(len(f64::NAN), "NaN");
        assert_eq!(deg(10.04999), "10");
        assert_eq!(deg(107.46), "107.5");
    }

    #[test]
    fn two_significant_prints_two_digits() {
        for (x, want) in [(9.8123e-5, "0.000098"), (0.0123, "0.012"), (1.0, "1"), (12.49, "12"), (98765.0, "99000"), (0.0996, "0.1")] {
            let got = two_significant(x).to_string();
            assert_eq!(got, want, "two_significant({x}): wanted {want}, got {got}");
        }
    }
}
