//! Clean corners: where connectors sit relative to the corners of the pieces.
//!
//! A hole `d` along the edge before a corner and `i` into the piece is only `d` (not `i`) from the
//! edge after a square corner, so holes just beside a corner bunch up and cross the edge; on the
//! corner itself the mitre keeps the inset from both sides ([`super::piece::Walked::inward_at`]).
//! When the user gives no `slide`, every connector on both pieces is shifted by the same `δ`
//! (so pairing and numbering are kept) chosen to maximise the smallest arc-length distance from
//! any corner of either piece to its nearest connector, a corner carrying a connector counting as
//! perfectly clear. The optimum of this max–min over `δ ∈ [0, p)` is at one of finitely many
//! candidates: a connector on a corner, or the midpoint between two corners' residues
//! `(s_c − start) mod p` (then both are equally far). Corners are anchors where the tangent turns
//! by more than [`CORNER_TURN`]; smooth outlines keep `δ = 0`.

use super::piece::Walked;
use crate::arclen::{control_polygon_len, unit_tangent};

/// Turn of the tangent (radians) above which an anchor counts as a corner: 20°, more than any
/// corner of a 18-gon approximating a circle.
pub const CORNER_TURN: f64 = 20.0 * std::f64::consts::PI / 180.0;

/// Arc lengths (along the walk) of the corners of a piece.
pub fn corners(piece: &Walked) -> Vec<f64> {
    let table = &piece.table;
    let n = table.segment_count();
    let live: Vec<usize> = (0..n).filter(|&i| control_polygon_len(table.segment(i)) > 0.0).collect();
    let mut out = Vec::new();
    for (j, &i) in live.iter().enumerate() {
        let prev = live[(j + live.len() - 1) % live.len()];
        let (a, b) = (unit_tangent(table.segment(prev), 1.0), unit_tangent(table.segment(i), 0.0));
        if a.dot(b).clamp(-1.0, 1.0).acos() > CORNER_TURN {
            out.push(table.segment_start(i));
        }
    }
    out
}

/// The shift `δ ∈ [0, p)` of all connectors (see the module comment), given each piece's first
/// connector position `first[i]` and its corners. Keeps 0 when every corner is already at least
/// `good` from its nearest connector (or on one).
pub fn shift(first: [f64; 2], corners: [&[f64]; 2], pitch: f64, good: f64) -> f64 {
    let on = 1e-9 * pitch;
    let residues: Vec<f64> = (0..2)
        .flat_map(|i| corners[i].iter().map(move |&s| (s - first[i]).rem_euclid(pitch)))
        .collect();
    if residues.is_empty() {
        return 0.0;
    }
    let score = |delta: f64| {
        residues
            .iter()
            .map(|&r| {
                let x = (r - delta).rem_euclid(pitch);
                let d = x.min(pitch - x);
                if d <= on { f64::INFINITY } else { d }
            })
            .fold(f64::INFINITY, f64::min)
    };
    let base = score(0.0);
    if base >= good {
        return 0.0;
    }
    let mut sorted = residues.clone();
    sorted.sort_by(f64::total_cmp);
    let mut candidates = sorted.clone();
    for (j, &r) in sorted.iter().enumerate() {
        let next = if j + 1 < sorted.len() { sorted[j + 1] } else { sorted[0] + pitch };
        candidates.push((0.5 * (r + next)).rem_euclid(pitch));
    }
    let mut best: (f64, f64) = (base, 0.0);
    for d in candidates {
        let s = score(d);
        // Ties go to the smaller shift (the user's start moves least).
        let size = d.min(pitch - d);
        if s > best.0 + on || (s >= best.0 - on && size < best.1.min(pitch - best.1) - on) {
            best = (s, d);
        }
    }
    best.1
}

#[cfg(test)]
mod tests {
    use super::shift;

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
