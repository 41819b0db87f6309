//! Rows of interior vertices beside the seam where the glued surface is a saddle.
//!
//! Where a concave stretch of one piece meets the other, the two pieces' angles at a seam sample
//! add up to more than `2π`: the seam carries negative curvature. There each piece's fan of
//! triangles at the sample must bend along an edge that runs into the piece, the way a
//! developable surface bends along its rulings; a fan of the refinement's triangles, graded
//! from the seam step to five times that within two rows, holds no such edges, and the sheet
//! locks. Measured on 120 random pairs of two organic pieces (`simulate_survey`'s seed 11, and
//! seeds 23 and 5 of the same generator; 256 seam vertices): 9 ended strained by 1.3e-3 to
//! 4.1e-3 at every bending weight down to `kb/R² = 1e-10`, each at a run of seam edges
//! stretched on both pieces beside samples of total angle `2π + 2–4°`, the interior edges next
//! to them compressed as much. A uniformly finer interior freed some and locked others
//! (interior edges of 2 seam steps: 2 of 3, 6 s instead of 0.5). So the mesh gets, at each such
//! sample and in each piece, vertices on the bisector of the piece's angle at [`ROWS`] seam
//! steps: a short row of edges into the piece at every saddle sample, along which its fan can
//! bend. Of the 120 pairs, 109 converge with them (101 without), 2 end strained (9) and 9
//! crease (10); of the survey's 30 blobs with a circle, 30 (28). On 120 more (seeds 31, 47
//! and 59), which did not choose the rows, 110 converge with or without them, 4 end strained
//! (5) and 6 crease (5): where both pieces are concave at one place, 5–8° of excess per
//! sample, the rows do not free the sheet. More rows (also at 4 and 6 steps), or rows fanned
//! 35° either side of the bisector, converged 7–9 more of the 240, at 1.3–2.5 times the time.
//!
//! Only the sheet's thinning mesh gets them: the homotopy from convex twins
//! ([`super::homotopy`]) runs on the plain mesh, whose interior the twins' map was made for (the
//! heart with a circle, at 192 seam vertices, whose tip and dip are sharp, came out of a layered
//! homotopy 60 % strained).

use crate::libm_ext::LibmExt;
use super::glued::CONE_DEFECT;
use super::flatmesh::{interior_angle, mean_step, outline, seam_step};
use crate::simulate::seam::SeamPieces;
use kurbo::{Line, ParamCurveNearest, Point, Shape};
use std::f64::consts::TAU;

/// Smallest angle excess per unit of seam length, times `R = L/2π`, of a saddle sample: `0.36`
/// is 0.5° per seam step at 256 seam vertices. In a first trial on seed 11's pairs, 0.25°
/// converged no more of them (38 of 40 against 39).
pub const SADDLE_CURVATURE: f64 = 0.36;

/// Distances of a saddle sample's extra vertices from it, in seam steps. One row at 1 step
/// freed two of the three locked pairs of one seed, rows at 1 and 2 all three and locked
/// another.
pub const ROWS: [f64; 3] = [0.7, 1.5, 2.5];

/// The seam samples where the glued surface is a saddle: the two pieces' angles there exceed
/// `2π` by [`SADDLE_CURVATURE`]` / R` per unit of seam length, and by less than
/// [`CONE_DEFECT`] (a corner's cone point, which gets a fan instead).
pub fn samples(pieces: &SeamPieces) -> Vec<usize> {
    let n = pieces.n;
    let radius = pieces.flat[0].perimeter / TAU;
    let a = &pieces.flat[0].pts;
    (0..n)
        .filter(|&k| {
            let excess = interior_angle(a, k) + interior_angle(&pieces.flat[1].pts, k) - TAU;
            excess > SADDLE_CURVATURE * seam_step(a, k) / radius && excess < CONE_DEFECT
        })
        .collect()
}

/// The extra vertices inside the counter-clockwise polygon `seam` at the samples `at`: on the
/// bisector of the polygon's angle at each, [`ROWS`] seam steps in (the local step, or the mean
/// one where the samples are denser); a point outside the polygon or within half a step of any
/// seam edge (beside a neighbouring bay) is left out. With the local step alone, the rows in a
/// tight bay, sampled every 0.5 mm, stood 0.35 mm from the seam, and two pairs of the survey's
/// that had converged locked (4.7e-3 and 5.5e-3 strain).
pub fn rows(seam: &[[f64; 2]], at: &[usize]) -> Vec<[f64; 2]> {
    let n = seam.len();
    let mean = mean_step(seam);
    let shape = outline(seam);
    let mut out = Vec::new();
    for &k in at {
        let (b, c) = (seam[k], seam[(k + 1) % n]);
        let h = seam_step(seam, k).max(mean);
        let t = (c[1] - b[1]).atan2_m(c[0] - b[0]) + interior_angle(seam, k) / 2.0;
        for m in ROWS {
            let q = [b[0] + m * h * t.cos_m(), b[1] + m * h * t.sin_m()];
            if shape.contains(point(q)) && (0..n).all(|j| distance_to_edge(q, seam[j], seam[(j + 1) % n]) > 0.5 * h) {
                out.push(q);
            }
        }
    }
    out
}

fn point(q: [f64; 2]) -> Point {
    Point::new(q[0], q[1])
}

/// Distance from `q` to the segment `a–b`.
pub(super) fn distance_to_edge(q: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    Line::new(point(a), point(b)).nearest(point(q), 0.0).distance_sq.sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simulate::seam::FlatPiece;

    /// A circle glued to a circle with a bay: the saddle samples are the bay's, the rows lie
    /// inside each piece, a step or more from the seam, at the saddle samples only.
    #[test]
    fn rows_stand_beside_the_bay_only() {
        let n = 128;
        let circle: Vec<[f64; 2]> = (0..n).map(|k| {
            let t = TAU * k as f64 / n as f64;
            [50.0 * t.cos_m(), 50.0 * t.sin_m()]
        }).collect();
        // r = 50 − 8·exp(−(θ/0.3)²): concave around θ = 0 only, a dent of the radius there.
        let bay: Vec<[f64; 2]> = (0..n).map(|k| {
            let t = TAU * k as f64 / n as f64;
            let d = (t + std::f64::consts::PI).rem_euclid(TAU) - std::f64::consts::PI;
            let r = 50.0 - 8.0 * (-(d / 0.3).powi(2)).exp_m();
            [r * t.cos_m(), r * t.sin_m()]
        }).collect();
        let piece = |pts: Vec<[f64; 2]>| FlatPiece::on_chords(pts, 0.0, 0.0);
        let mut pieces = SeamPieces { n, flat: [piece(circle.clone()), piece(bay.clone())] };
        let perimeter: f64 = (0..n).map(|k| (circle[k][0] - circle[(k + 1) % n][0]).hypot_m(circle[k][1] - circle[(k + 1) % n][1])).sum();
        pieces.flat[0].perimeter = perimeter;
        let at = samples(&pieces);
        assert!(!at.is_empty(), "wanted saddle samples at the bay");
        for &k in &at {
            let d = (TAU * k as f64 / n as f64 + std::f64::consts::PI).rem_euclid(TAU) - std::f64::consts::PI;
            assert!(d.abs() < 0.6, "sample {k} (θ = {d:.2}) is no bay sample");
        }
        for (p, pts) in [(0, &circle), (1, &bay)] {
            let q = rows(pts, &at);
            assert!(q.len() >= at.len(), "piece {p}: wanted a row at each of {} samples, got {} points", at.len(), q.len());
            for v in q {
                assert!(outline(pts).contains(point(v)), "piece {p}: {v:?} is outside");
                let near = (0..n).map(|j| distance_to_edge(v, pts[j], pts[(j + 1) % n])).fold(f64::INFINITY, f64::min);
                assert!(near > 0.5 * seam_step(pts, 0) * 0.9, "piece {p}: {v:?} is {near:.3} mm from the seam");
            }
        }
    }
}
