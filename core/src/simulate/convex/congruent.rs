//! Congruent pieces glued congruently: the flat, doubly covered form, laid out directly.
//!
//! When B's seam samples are A's turned and shifted (an ellipse with its copy at half its
//! perimeter, a rectangle with its copy at a corner opposite the first, any piece with its mirror
//! image at offset 0), the D-form is the flat sheet both pieces lie in, one on the other
//! (Alexandrov's degenerate case; for non-convex pieces a sheet that touches itself but does not
//! cross). The multistart finds it at offset 0 in one step per level, where the two sample
//! polygons are the same up to round-off. But at a congruent gluing other than the identity the
//! samples differ by the arc-length tables' accuracy (2e-8 of an 8:1 ellipse's size), the
//! saddle start lifts the sheet by about the square root of that, and the solve crawls back to
//! flat across an infinitesimally flexible sheet: 2,243 steps and 0.56 s native for the 8:1
//! ellipse with its copy at half its perimeter, 1,773 and 0.47 s for a 12:1 one (4 steps and
//! 3 ms at offset 0).
//!
//! So the pieces' sample polygons are first aligned by the rotation and shift that fit B's onto
//! A's best ([`super::super::fit`], as the multistart's starts do), and when every sample of
//! one then lies within [`NEAR`] of the other's, the average of the two layouts is tried as the
//! answer: it is taken when every chord of both pieces' triangulations is within
//! [`crate::simulate::isometry::STRAIN_TOL`] of its length there, what any converged answer of
//! this path meets. Pieces that are not congruent fail the first test in one pass over the
//! samples.

use crate::libm_ext::LibmExt;
use super::super::fit::Rigid;
use super::super::isometry::{bars, max_strain, STRAIN_TOL};
use super::super::metric::Triangulation;
use super::super::seam::SeamPieces;
use super::super::vec3::V3;
use super::starts::{initial_guess, Start};
use super::triangulate;

/// Largest distance, relative to the size of A's sample polygon, of a sample of B (aligned)
/// from its sample of A for the flat layout to be tried: 1e-6, well above the arc-length
/// tables' differences between congruent pieces and far below any gluing that is not congruent
/// (the Pebble with its mirror image 0.2 mm off: 2e-3).
pub const NEAR: f64 = 1e-6;

/// The flat doubly covered answer of `pieces` and both pieces' triangulations, when their
/// sample polygons are congruent (see the module docs); `None` otherwise.
pub(crate) fn flat_layout(pieces: &SeamPieces) -> Option<(Vec<V3>, [Triangulation; 2])> {
    if misfit(pieces)? > NEAR {
        return None;
    }
    let x = initial_guess(pieces, Start::Saddle(0.0));
    let tri = [triangulate(pieces, 0).ok()?, triangulate(pieces, 1).ok()?];
    (max_strain(&x, &bars(pieces, &tri)) <= STRAIN_TOL).then_some((x, tri))
}

/// The largest distance between a sample of A and the same sample of B turned and shifted onto
/// A by least squares ([`Rigid::fit`]), over the largest distance of A's samples from their
/// centroid; `None` for a degenerate polygon.
fn misfit(pieces: &SeamPieces) -> Option<f64> {
    let (a, b) = (&pieces.flat[0].pts, &pieces.flat[1].pts);
    let fit = Rigid::fit(b, a)?;
    let size = a.iter().map(|p| (p[0] - fit.to[0]).hypot_m(p[1] - fit.to[1])).fold(0.0, f64::max);
    if !(size > 0.0) {
        return None;
    }
    let far = a.iter().zip(b).map(|(p, q)| {
        let t = fit.apply(*q);
        (t[0] - p[0]).hypot_m(t[1] - p[1])
    });
    Some(far.fold(0.0, f64::max) / size)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simulate::seam::FlatPiece;

    fn piece(pts: Vec<[f64; 2]>) -> FlatPiece {
        let n = pts.len();
        let perimeter = (0..n).map(|k| (pts[(k + 1) % n][0] - pts[k][0]).hypot_m(pts[(k + 1) % n][1] - pts[k][1])).sum();
        let area = (0..n).map(|k| pts[k][0] * pts[(k + 1) % n][1] - pts[(k + 1) % n][0] * pts[k][1]).sum::<f64>() / 2.0;
        FlatPiece::on_chords(pts, area, perimeter)
    }

    /// An egg-shaped 24-gon and a copy of it turned by 0.7 rad and moved: laid out flat, every
    /// two vertices as far apart as on A's flat polygon; the same copy with one sample moved by
    /// 1 µm (1.7e-5 of the size) is no congruent gluing.
    #[test]
    fn a_turned_copy_lies_flat_and_a_nudged_one_does_not() {
        let n = 24;
        let a: Vec<[f64; 2]> = (0..n)
            .map(|k| std::f64::consts::TAU * k as f64 / n as f64)
            .map(|t| [60.0 * t.cos_m() + 6.0 * (2.0 * t).cos_m(), 30.0 * t.sin_m()])
            .collect();
        let (c, s) = (0.7f64.cos_m(), 0.7f64.sin_m());
        let b: Vec<[f64; 2]> = a.iter().map(|p| [c * p[0] - s * p[1] + 13.0, s * p[0] + c * p[1] - 4.0]).collect();
        let pieces = SeamPieces { n, flat: [piece(a.clone()), piece(b.clone())] };
        let (x, _) = flat_layout(&pieces).expect("a turned copy is a congruent gluing");
        assert!(x.iter().all(|p| p[2] == 0.0), "wanted every vertex in the plane z = 0");
        for i in 0..n {
            for j in 0..n {
                let flat = (a[j][0] - a[i][0]).hypot_m(a[j][1] - a[i][1]);
                let laid = ((x[j][0] - x[i][0]).powi(2) + (x[j][1] - x[i][1]).powi(2) + (x[j][2] - x[i][2]).powi(2)).sqrt();
                assert!((laid - flat).abs() <= 1e-12 * 60.0, "vertices {i}, {j}: wanted {flat}, got {laid}");
            }
        }
        let mut nudged = b;
        nudged[5][0] += 1e-3;
        let pieces = SeamPieces { n, flat: [piece(a), piece(nudged)] };
        assert!(flat_layout(&pieces).is_none(), "a copy with a sample moved by 1 µm is no congruent gluing");
    }
}
