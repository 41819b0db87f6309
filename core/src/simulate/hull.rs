//! A restart for the multistart when every saddle start ends on a wrong branch: the triangulations
//! read off the convex hull of the best attempt.
//!
//! For convex pieces the D-form is the convex hull of its seam (Demaine & Price 2010), so the
//! hull of a shape that is merely close — the best of the failed attempts — names the chords the
//! solution needs. Its faces split along the seam polygon into A's and B's: a seam-vertex triangle
//! turns counter-clockwise seen from outside on A's side (vertex indices in cyclic order) and the
//! other way on B's. The local flips cannot always get there: near-square rectangles glued to a
//! circle stall with every saddle start (strain 10–40 %), and converge from their hull.
//!
//! The hull is found by brute force (every triple whose plane has all points on one side,
//! `O(n⁴)`), which is meant for the coarsest rungs only (32 seam vertices: ~10⁶ tests).

use super::metric::{self, Triangulation};
use super::seam::SeamPieces;
use super::solver::{cross, dot, sub, V3};

/// Largest number of seam vertices [`triangulations`] is tried on.
pub const MAX_VERTICES: usize = 64;

/// Outward faces `[i, j, k]` (counter-clockwise seen from outside, `i` the smallest index) of the
/// convex hull of `x`: triples whose plane has no point more than a relative 1e-9 outside.
/// Points that are coplanar on a face give overlapping triangles; [`triangulations`] then refuses.
fn faces(x: &[V3]) -> Vec<[usize; 3]> {
    let n = x.len();
    let c = x.iter().fold([0.0; 3], |s, p| [s[0] + p[0] / n as f64, s[1] + p[1] / n as f64, s[2] + p[2] / n as f64]);
    let size = x.iter().map(|p| dot(sub(*p, c), sub(*p, c))).fold(0.0, f64::max).sqrt();
    let mut out = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            for k in i + 1..n {
                if k == j {
                    continue;
                }
                let nrm = cross(sub(x[j], x[i]), sub(x[k], x[i]));
                let l = dot(nrm, nrm).sqrt();
                if !(l > 1e-12 * size * size) {
                    continue;
                }
                if (0..n).all(|m| dot(nrm, sub(x[m], x[i])) <= 1e-9 * size * l) {
                    out.push([i, j, k]);
                }
            }
        }
    }
    out
}

/// A's and B's triangulations read off the convex hull of `x` (see the module docs), or `None`
/// when the hull does not split into two proper triangulations of the flat pieces (a vertex
/// inside the hull, coplanar points, a face across the seam, a chord outside a non-convex piece).
pub fn triangulations(x: &[V3], pieces: &SeamPieces) -> Option<[Triangulation; 2]> {
    let n = pieces.n;
    if x.len() != n || n > MAX_VERTICES {
        return None;
    }
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for [i, j, k] in faces(x) {
        // Outward and counter-clockwise in index order: A's side. B's triangles are stored
        // counter-clockwise in B's (mirrored) flat piece, i.e. reversed.
        if j < k {
            a.push([i, j, k]);
        } else {
            b.push([i, k, j]);
        }
    }
    let mut out = Vec::with_capacity(2);
    for (p, tris) in [a, b].into_iter().enumerate() {
        let pts = &pieces.flat[p].pts;
        if tris.len() != n - 2 {
            return None;
        }
        let eps = 1e-12 * metric::size2(pts);
        let area2: f64 = tris.iter().map(|&[i, j, k]| metric::orient(pts[i], pts[j], pts[k])).sum();
        let polygon2: f64 = (0..n).map(|i| metric::orient([0.0, 0.0], pts[i], pts[(i + 1) % n])).sum();
        // Every directed edge once, every seam edge k → k+1 among them: a disc bounded by the
        // seam polygon. Its triangles all counter-clockwise and tiling the polygon's area: flat,
        // without folds, so a triangulation of the piece.
        let mut directed: Vec<(usize, usize)> = tris.iter().flat_map(|t| (0..3).map(move |m| (t[m], t[(m + 1) % 3]))).collect();
        let seam_ok = (0..n).all(|k| directed.contains(&(k, (k + 1) % n)));
        crate::order::sort_dedup_pairs(&mut directed);
        if directed.len() != 3 * (n - 2) || !seam_ok {
            return None;
        }
        if tris.iter().any(|&[i, j, k]| metric::orient(pts[i], pts[j], pts[k]) <= eps) || (area2 - polygon2).abs() > 1e-9 * polygon2.abs() {
            return None;
        }
        out.push(Triangulation::from_tris(n, tris));
    }
    let b = out.pop()?;
    let a = out.pop()?;
    Some([a, b])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::{Contour, Knot};
    use crate::simulate::{seam::Glue, solver, SimulateOptions};
    use kurbo::Point;

    fn ellipse(rx: f64, ry: f64) -> Contour {
        let k = 0.552_284_749_830_793_4;
        let knots = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)]
            .iter()
            .map(|&(x, y): &(f64, f64)| {
                let a = Point::new(rx * x, ry * y);
                let t = (-y * rx * k, x * ry * k);
                Knot { anchor: a, left: Point::new(a.x - t.0, a.y - t.1), right: Point::new(a.x + t.0, a.y + t.1) }
            })
            .collect();
        Contour::new(knots, 0).unwrap()
    }

    /// A convex solution is the hull of its vertices, so the triangulations read off that hull
    /// are realized by it isometrically: every hull chord has its flat length in its own piece.
    /// (They can differ from the solver's own only across coplanar quads, where either diagonal
    /// has its flat length; a face given to the wrong piece would not.)
    #[test]
    fn the_hull_of_a_convex_solution_is_realized_by_it() {
        let (a, b) = (ellipse(1.5, 1.0), ellipse(1.0, 1.0));
        let (pa, pb) = (crate::arclen::ArcTable::new(&a, 1e-13).total(), crate::arclen::ArcTable::new(&b, 1e-13).total());
        let b = b.transformed(kurbo::Affine::scale(pa / pb));
        let s = crate::simulate::simulate(&a, &b, &SimulateOptions { resolution: 64, ..Default::default() }).unwrap();
        assert!(s.stats.converged && s.stats.reflex_edges == 0, "{:?}", s.stats);
        let pieces = Glue::new(&a, &b, 0.0).unwrap().sample(64);
        let hull = triangulations(&s.vertices, &pieces).expect("a convex solution splits into two triangulations");
        for p in 0..2 {
            for (i, j) in hull[p].chords() {
                let (l, d) = (dot(sub(s.vertices[j], s.vertices[i]), sub(s.vertices[j], s.vertices[i])).sqrt(), pieces.chord(p, i, j));
                assert!((l / d - 1.0).abs() < 1e-6, "piece {p}, hull chord {i}-{j}: {l} in 3D, {d} flat");
            }
        }
    }

    #[test]
    fn a_point_inside_the_hull_is_refused() {
        let e = ellipse(2.0, 1.0);
        let p = crate::arclen::ArcTable::new(&e, 1e-13).total();
        let glue = Glue::new(&e, &e, 0.25 * p).unwrap();
        let (pieces, mut sol) = solver::solve(&glue, &SimulateOptions { resolution: 32, offset: 0.25 * p, ..Default::default() }).unwrap();
        let c = sol.x.iter().fold([0.0; 3], |s, q| [s[0] + q[0] / 32.0, s[1] + q[1] / 32.0, s[2] + q[2] / 32.0]);
        sol.x[5] = [0.5 * (sol.x[5][0] + c[0]), 0.5 * (sol.x[5][1] + c[1]), 0.5 * (sol.x[5][2] + c[2])];
        assert!(triangulations(&sol.x, &pieces).is_none(), "a dented vertex cannot split the hull into two triangulations");
    }
}
