//! Stitch holes at corners sharper than square: along the inset line, not into the corner.
//!
//! A hole `inset` along the normal of a point `x` before a corner of interior angle `θ` is only
//! `x·sin θ − inset·cos θ` from the edge after it: every hole closer than
//! `cut = inset·cot(θ/2)` to the corner (`(inset + r)·cot(θ/2)` for the whole hole of radius
//! `r`) lies nearer the other edge than the inset, and two holes beside a 60° corner meet. The
//! inset line of the two edges (the points `inset` from the nearer one) turns at the mitre point
//! `M`, which is the normal offset of the point `cut` along either edge; the normal offsets of
//! the points within `cut` of the corner lie beyond `M`, off the inset line.
//!
//! So on a piece's convex corners sharper than square the holes keep to the inset line, and
//! off its tip: within a window `w` either side of the corner, the hole of the connector `x`
//! from the corner is the point `gap + x·(w − cut − gap)/w` from `M` along the inset line (the
//! normal offset of the point `cut + gap + x·(w − cut − gap)/w` from the corner, away from it).
//! Every such hole is at least `inset` from both edges; holes on opposite sides of the corner are
//! at least `2·gap·sin(θ/2)` apart, and `gap = `[`GAP`]`·r / sin(θ/2)` leaves a web of
//! `(GAP − 1)·2r` between them; holes on one side are spaced `(w − cut − gap)/w` as closely as
//! elsewhere. At `x = w` the hole is the ordinary normal offset again. `w` is [`REACH`]·`(cut + gap)`,
//! no more than the corner's share of each edge (edges are shared in proportion to their two
//! corners' cuts, so windows never overlap); a corner whose share leaves a spacing below
//! [`MIN_SPACING`] (an edge too short for its inset) keeps the plain normal offsets, and the
//! warnings name what does not fit. The connectors themselves (their arc lengths, their pairing
//! with the other piece) do not move; only where each piece's hole sits beside its connector
//! point.

use crate::libm_ext::LibmExt;
use super::phase::CORNER_TURN;
use super::piece::Walked;

/// How far the window reaches either side of a corner, in cuts.
pub const REACH: f64 = 4.0;

/// Smallest spacing of holes in a window relative to elsewhere (`(w − cut − gap)/w`).
pub const MIN_SPACING: f64 = 0.3;

/// Holes on opposite sides of a sharp corner stay this many hole diameters apart, centre to
/// centre, at least.
pub const GAP: f64 = 1.25;

/// A convex corner sharper than square and its window.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Window {
    /// Arc length of the corner along the walk.
    pub s: f64,
    /// `inset·cot(θ/2)`.
    pub cut: f64,
    /// Distance along the inset line from `M` to the nearest hole.
    pub gap: f64,
    /// Reach before and after the corner (0 when the window is not used on that side).
    pub before: f64,
    pub after: f64,
}

/// Corners of a piece: arc length, tangent turn (radians) and whether convex.
fn corners(piece: &Walked) -> Vec<(f64, f64, bool)> {
    super::phase::corner_turns(piece, CORNER_TURN)
}

/// The windows of a piece's convex corners sharper than square, for holes of radius `radius`
/// `inset` deep.
pub fn windows(piece: &Walked, inset: f64, radius: f64) -> Vec<Window> {
    let all = corners(piece);
    let per = piece.perimeter();
    let square = std::f64::consts::FRAC_PI_2 + 1e-6;
    // The cut of every corner (0 for square, blunter or concave ones: they bound windows only).
    let cuts: Vec<f64> = all
        .iter()
        .map(|&(_, turn, convex)| if convex && turn > square { inset * (0.5 * turn).tan_m() } else { 0.0 })
        .collect();
    let m = all.len();
    let mut out = Vec::new();
    for j in 0..m {
        if cuts[j] <= 0.0 {
            continue;
        }
        let (prev, next) = ((j + m - 1) % m, (j + 1) % m);
        let span = |a: usize, b: usize| {
            let d = (all[b].0 - all[a].0).rem_euclid(per);
            if d <= 0.0 { per } else { d }
        };
        let share = |len: f64, other: f64| len * cuts[j] / (cuts[j] + other);
        // Interior angle θ = π − turn: sin(θ/2) = cos(turn/2).
        let gap = GAP * radius / (0.5 * all[j].1).cos_m().max(1e-3);
        let reach = |len: f64, other: f64| {
            let w = (REACH * (cuts[j] + gap)).min(share(len, other));
            if (w - cuts[j] - gap) / w >= MIN_SPACING { w } else { 0.0 }
        };
        let (before, after) = if m == 1 {
            (reach(0.5 * per, 0.0), reach(0.5 * per, 0.0))
        } else {
            (reach(span(prev, j), cuts[prev]), reach(span(j, next), cuts[next]))
        };
        if before > 0.0 && after > 0.0 {
            out.push(Window { s: all[j].0, cut: cuts[j], gap, before, after });
        }
    }
    out
}

/// The arc length whose normal offset is the hole of the connector at arc length `s` (see the
/// module comment); `s` itself outside every window. The result may leave `[0, P)`.
pub fn shifted(windows: &[Window], perimeter: f64, s: f64) -> f64 {
    for w in windows {
        // Signed distance from the corner, in (−P/2, P/2].
        let mut x = (s - w.s).rem_euclid(perimeter);
        if x > 0.5 * perimeter {
            x -= perimeter;
        }
        let lead = w.cut + w.gap;
        if x >= 0.0 && x < w.after {
            return w.s + lead + x * (w.after - lead) / w.after;
        }
        if x < 0.0 && -x < w.before {
            return w.s - lead + x * (w.before - lead) / w.before;
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::{Contour, Knot};

    fn polygon(pts: &[(f64, f64)]) -> Walked {
        let knots = pts.iter().map(|&p| Knot { anchor: p.into(), left: p.into(), right: p.into() }).collect();
        Walked::new(&Contour::new(knots, 0).unwrap(), 0, true, 1e-10).unwrap()
    }

    #[test]
    fn an_equilateral_triangle_has_three_windows_of_four_cuts() {
        let h = 50.0 * 3f64.sqrt() / 2.0;
        let w = windows(&polygon(&[(0.0, 0.0), (50.0, 0.0), (25.0, h)]), 2.0, 0.5);
        let (cut, gap) = (2.0 * 3f64.sqrt(), 1.25 * 0.5 / 0.5); // 2·cot 30°, 1.25·r / sin 30°
        assert_eq!(w.len(), 3, "{w:?}");
        for c in &w {
            let reach = 4.0 * (cut + gap);
            assert!((c.cut - cut).abs() < 1e-9 && (c.gap - gap).abs() < 1e-9, "{c:?}");
            assert!((c.before - reach).abs() < 1e-9 && (c.after - reach).abs() < 1e-9, "{c:?}");
        }
    }

    #[test]
    fn squares_and_concave_corners_have_no_window() {
        assert!(windows(&polygon(&[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]), 2.0, 0.5).is_empty());
        // An arrow head: its three points are convex (windows), its notch at 2·√1700 + √200 concave.
        let w = windows(&polygon(&[(0.0, 0.0), (40.0, 10.0), (0.0, 20.0), (10.0, 10.0)]), 1.0, 0.25);
        let notch = 2.0 * 1700f64.sqrt() + 200f64.sqrt();
        assert_eq!(w.len(), 3, "{w:?}");
        assert!(w.iter().all(|c| (c.s - notch).abs() > 1.0), "{w:?}");
    }
}
