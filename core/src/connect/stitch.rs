//! Stitch holes: one circle per connector, `inset` from the edge along the normal.
//!
//! The centre of connector k's hole is `B(s_k) + inset·n(s_k)`, with `B(s_k)` the point at arc
//! length `s_k` and `n` the unit normal pointing into the piece (out of it with `invert`). On a
//! straight or convex stretch its distance to the edge is exactly `inset`.
//!
//! Kerf: a laser burns away half its cut width on each side of the path, so a hole drawn with
//! diameter `d − kerf` comes out with diameter `d`. Holes are drawn that much smaller, and
//! `diameter` in the result is the drawn diameter.

use super::circle::circle;
use super::options::{Kind, Settings};
use super::sharp;
use super::spacing::locate_many;
use super::piece::Walked;
use super::spacing::Station;
use super::Hole;
use kurbo::Point;

/// +1 when holes go inside the piece, −1 with `invert`.
pub fn side(set: &Settings) -> f64 {
    if set.invert { -1.0 } else { 1.0 }
}

/// Hole centres of one piece, in connector order. Stitch holes inside the piece keep to the
/// inset line at corners sharper than square ([`sharp`]).
pub fn centers(piece: &Walked, stations: &[Station], set: &Settings) -> Vec<Point> {
    let depth = side(set) * set.inset;
    let mut out: Vec<Point> = stations.iter().map(|st| st.point + piece.inward_at(st) * depth).collect();
    if set.kind != Kind::Stitch || set.invert {
        return out;
    }
    let windows = sharp::windows(piece, set.inset, 0.5 * set.diameter);
    if windows.is_empty() {
        return out;
    }
    let per = piece.perimeter();
    let moved: Vec<(usize, f64)> = stations
        .iter()
        .enumerate()
        .filter_map(|(k, st)| {
            let s = sharp::shifted(&windows, per, st.s);
            (s != st.s).then_some((k, s))
        })
        .collect();
    let at = locate_many(&piece.table, &moved.iter().map(|m| m.1).collect::<Vec<_>>());
    for (&(k, _), st) in moved.iter().zip(&at) {
        out[k] = st.point + piece.inward(st.tangent) * depth;
    }
    out
}

/// The drawn holes (see the module comment for kerf). Holes run against the drawing direction
/// of the piece (`piece_ccw`), so a compound path of outline and holes fills correctly under
/// both fill rules.
pub fn holes(centers: &[Point], set: &Settings, piece_ccw: bool) -> Vec<Hole> {
    let diameter = set.diameter - set.kerf;
    centers
        .iter()
        .map(|&c| Hole { center: c, diameter, path: circle(c, 0.5 * diameter, !piece_ccw) })
        .collect()
}
