//! Clean corners: where connectors sit relative to the corners of the pieces.
//!
//! A hole `d` along the edge before a corner and `i` into the piece is only `d` (not `i`) from the
//! edge after a square corner, so holes just beside a corner bunch up and cross the edge; on the
//! corner itself the mitre keeps the inset from both sides ([`super::piece::Walked::inward_at`]).
//! When the user gives neither `slide` nor `start`, every connector on both pieces is shifted by the same `δ`
//! (so pairing and numbering are kept). For leaves `δ` maximises the smallest arc-length
//! distance from any corner of either piece to its nearest connector, a corner carrying a
//! connector counting as perfectly clear; the optimum of this max–min over `δ ∈ [0, p)` is at one
//! of finitely many candidates: a connector on a corner, or the midpoint between two corners'
//! residues `(s_c − start) mod p`. For holes arc length is not enough (at a square corner two
//! holes `p/2` either side of it coincide when the inset is `p/2`), so the score is the holes'
//! own clearance near the corners, from each other and from the edge, over the same candidates
//! and an even grid of shifts (see `connect::auto_slide`). Corners are anchors where the tangent turns
//! by more than [`CORNER_TURN`]; smooth outlines keep `δ = 0`.

use crate::libm_ext::LibmExt;
use super::piece::Walked;
use crate::arclen::{control_polygon_len, unit_tangent};

/// Turn of the tangent (radians) above which an anchor counts as a corner: 20°, more than any
/// corner of a 18-gon approximating a circle.
pub const CORNER_TURN: f64 = 20.0 * std::f64::consts::PI / 180.0;

/// Arc lengths (along the walk) of the corners of a piece.
pub fn corners(piece: &Walked) -> Vec<f64> {
    corners_turning(piece, CORNER_TURN, std::f64::consts::PI)
}

/// Arc lengths of the anchors where the tangent turns by more than `min` and at most `max`.
pub fn corners_turning(piece: &Walked, min: f64, max: f64) -> Vec<f64> {
    corner_turns(piece, min).into_iter().filter(|c| c.1 <= max).map(|c| c.0).collect()
}

/// The anchors where the tangent turns by more than `min` (radians): arc length along the
/// walk, the turn, and whether the corner is convex (turns with the walk).
pub fn corner_turns(piece: &Walked, min: f64) -> Vec<(f64, f64, bool)> {
    let table = &piece.table;
    let n = table.segment_count();
    let live: Vec<usize> = (0..n).filter(|&i| control_polygon_len(table.segment(i)) > 0.0).collect();
    let mut out = Vec::new();
    for (j, &i) in live.iter().enumerate() {
        let prev = live[(j + live.len() - 1) % live.len()];
        let (a, b) = (unit_tangent(table.segment(prev), 1.0), unit_tangent(table.segment(i), 0.0));
        let turn = a.dot(b).clamp(-1.0, 1.0).acos_m();
        if turn > min {
            out.push((table.segment_start(i), turn, a.cross(b) * piece.turn > 0.0));
        }
    }
    out
}

/// Corners' residues `(s_c − first_i) mod p`, over both pieces.
fn residues(first: [f64; 2], corners: [&[f64]; 2], pitch: f64) -> Vec<f64> {
    (0..2).flat_map(|i| corners[i].iter().map(move |&s| (s - first[i]).rem_euclid(pitch))).collect()
}

/// The shifts worth trying: 0, a connector on each corner, the midpoints between consecutive
/// residues, and 16 evenly spaced shifts (so that a score that is not the arc-length max–min,
/// like the holes' clearance, still finds a good one).
pub fn candidates(first: [f64; 2], corners: [&[f64]; 2], pitch: f64) -> Vec<f64> {
    let mut sorted = residues(first, corners, pitch);
    if sorted.is_empty() {
        return vec![0.0];
    }
    sorted.sort_by(f64::total_cmp);
    let mut out = vec![0.0];
    out.extend(sorted.iter().copied());
    for (j, &r) in sorted.iter().enumerate() {
        let next = if j + 1 < sorted.len() { sorted[j + 1] } else { sorted[0] + pitch };
        out.push((0.5 * (r + next)).rem_euclid(pitch));
    }
    out.extend((1..16).map(|j| pitch * j as f64 / 16.0));
    out
}

/// The smallest arc-length distance from a corner to its nearest connector after shifting all
/// connectors by `delta` (∞ when every corner carries a connector or there is none).
pub fn arc_score(first: [f64; 2], corners: [&[f64]; 2], pitch: f64, delta: f64) -> f64 {
    let on = 1e-9 * pitch;
    residues(first, corners, pitch)
        .iter()
        .map(|&r| {
            let x = (r - delta).rem_euclid(pitch);
            let d = x.min(pitch - x);
            if d <= on { f64::INFINITY } else { d }
        })
        .fold(f64::INFINITY, f64::min)
}

/// The shift among `candidates` with the highest `score`; 0 when 0 already scores `good`.
/// Ties go to the smaller shift (the user's start moves least).
pub fn best(candidates: &[f64], pitch: f64, good: f64, score: impl Fn(f64) -> f64) -> f64 {
    let base = score(0.0);
    if base >= good {
        return 0.0;
    }
    let size = |d: f64| d.min(pitch - d);
    let tie = 1e-9 * pitch;
    let mut best: (f64, f64) = (base, 0.0);
    for &d in candidates {
        let s = score(d);
        if s > best.0 + tie || (s >= best.0 - tie && size(d) < size(best.1) - tie) {
            best = (s, d);
        }
    }
    best.1
}

/// [`best`] by [`arc_score`]: the shift that keeps corners farthest from connectors.
pub fn shift(first: [f64; 2], corners: [&[f64]; 2], pitch: f64, good: f64) -> f64 {
    best(&candidates(first, corners, pitch), pitch, good, |d| arc_score(first, corners, pitch, d))
}

/// Stitch holes only, on pieces whose corners are all square or blunter (a hole on a sharper
/// corner sits so deep, `inset / sin(α/2)` for an angle α, that it meets its neighbours): a hole
/// on every corner of both pieces. The corners of both pieces, as arc
/// lengths from each piece's start, cut the seam into stretches; stretch j of length `L_j` gets
/// `n_j ≥ 1` evenly spaced connectors, the first on its corner, `n_j` by largest remainder of
/// `L_j / p` so that they add up to `count`. Pairing is kept (connector k is at the same arc
/// length from the start on both pieces); the spacing varies from stretch to stretch, so this is
/// used only when every spacing `L_j / n_j` is within 25 % of the pitch. Returns the connector
/// arc lengths from the start, in order, or `None`.
pub fn on_corners(first: [f64; 2], corners: [&[f64]; 2], perimeter: f64, count: usize) -> Option<Vec<f64>> {
    let mut u: Vec<f64> = (0..2).flat_map(|i| corners[i].iter().map(move |&s| (s - first[i]).rem_euclid(perimeter))).collect();
    u.sort_by(f64::total_cmp);
    u.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * perimeter);
    if u.len() > 1 && perimeter - u[u.len() - 1] + u[0] <= 1e-9 * perimeter {
        u.pop();
    }
    if u.is_empty() || u.len() > count {
        return None;
    }
    let pitch = perimeter / count as f64;
    let lens: Vec<f64> = (0..u.len()).map(|j| if j + 1 < u.len() { u[j + 1] - u[j] } else { u[0] + perimeter - u[j] }).collect();
    let mut n: Vec<usize> = lens.iter().map(|&l| ((l / pitch).floor() as usize).max(1)).collect();
    let mut total: usize = n.iter().sum();
    while total > count {
        // Take from the stretch whose spacing would stay largest.
        let j = (0..n.len()).filter(|&j| n[j] > 1).max_by(|&a, &b| (lens[a] / (n[a] - 1) as f64).total_cmp(&(lens[b] / (n[b] - 1) as f64)))?;
        n[j] -= 1;
        total -= 1;
    }
    while total < count {
        let j = (0..n.len()).max_by(|&a, &b| (lens[a] / n[a] as f64).total_cmp(&(lens[b] / n[b] as f64)))?;
        n[j] += 1;
        total += 1;
    }
    if lens.iter().zip(&n).any(|(&l, &k)| !(0.75 * pitch..=1.25 * pitch).contains(&(l / k as f64))) {
        return None;
    }
    let (u, lens, n) = (&u, &lens, &n);
    Some((0..u.len()).flat_map(|j| (0..n[j]).map(move |m| u[j] + lens[j] * m as f64 / n[j] as f64)).collect())
}

#[cfg(test)]
mod tests {
    use super::{on_corners, shift};

    #[test]
    fn a_hole_on_every_corner_of_the_issue_square() {
        let corners = [0.0, 41.6, 81.7, 123.3];
        let s = on_corners([0.0, 0.0], [&corners, &[]], 163.4, 24).unwrap();
        assert_eq!(s.len(), 24);
        for c in corners {
            assert!(s.iter().any(|&x| (x - c).abs() < 1e-9), "no connector on the corner at {c}: {s:?}");
        }
        let gaps: Vec<f64> = (0..24).map(|k| if k < 23 { s[k + 1] - s[k] } else { s[0] + 163.4 - s[k] }).collect();
        assert!(gaps.iter().all(|&g| (6.6..7.0).contains(&g)), "spacings {gaps:?}");
    }

    #[test]
    fn corners_between_connectors_go_to_the_middle_of_the_widest_gap() {
        // The 41.6 × 40.1 square of the issue with 24 connectors: residues 0, 0.752, 0, 0.76.
        let p = 2.0 * (41.6 + 40.1) / 24.0;
        let corners = [0.0, 41.6, 81.7, 123.3];
        let d = shift([0.0, 0.0], [&corners, &[]], p, 4.0f64.min(0.5 * p));
        let worst = corners.iter().map(|&s| { let x = (s - d).rem_euclid(p); x.min(p - x) }).fold(f64::INFINITY, f64::min);
        assert!(worst > 2.9, "wanted every corner ≥ 2.9 from a connector at pitch {p}, got {worst} (shift {d})");
    }

    #[test]
    fn corners_on_connectors_stay() {
        let d = shift([0.0, 0.0], [&[0.0, 10.0, 20.0, 30.0], &[]], 5.0, 2.0);
        assert_eq!(d, 0.0);
    }
}
