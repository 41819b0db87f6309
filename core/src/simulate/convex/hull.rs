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
//! The hull is incremental (`O(n·F)` plane tests, ~10⁵ at 256 seam vertices), so the restart
//! is tried on every rung of the ladder; the brute-force hull it replaces (every triple whose
//! plane has all points on one side, `O(n⁴)`) was limited to rungs of at most 64 vertices.

use crate::libm_ext::LibmExt;
use super::super::metric::{self, Triangulation};
use super::super::seam::SeamPieces;
use super::super::vec3::{centroid_and_radius, cross, dot, sub, V3};

/// Outward faces `[i, j, k]` (counter-clockwise seen from outside) of the convex hull of `x`, by
/// the incremental algorithm (Clarkson & Shor 1989; de Berg et al., *Computational Geometry*,
/// ch. 11): from a tetrahedron of extreme points, each further point that sees some face (lies
/// more than a relative 1e-9 above its plane) replaces the faces it sees by the cone from itself
/// to their horizon. `O(n·F)` plane tests, `F ≤ 2n − 4`. A point on or within 1e-9 of the hull
/// is left out; [`triangulations`] then refuses (every seam vertex must be a hull vertex).
fn faces(x: &[V3]) -> Vec<[usize; 3]> {
    let n = x.len();
    if n < 4 {
        return Vec::new();
    }
    let (_, size) = centroid_and_radius(x);
    let eps = 1e-9 * size;
    // Tetrahedron: the farthest point from x[0], the farthest from that line, the farthest from that plane.
    let far = |f: &dyn Fn(V3) -> f64| (0..n).max_by(|&a, &b| f(x[a]).total_cmp(&f(x[b]))).unwrap_or(0);
    let a = 0;
    let b = far(&|p| dot(sub(p, x[a]), sub(p, x[a])));
    let ab = sub(x[b], x[a]);
    let c3 = far(&|p| { let q = cross(ab, sub(p, x[a])); dot(q, q) });
    let nrm = cross(ab, sub(x[c3], x[a]));
    let d = far(&|p| dot(nrm, sub(p, x[a])).abs());
    let height = dot(nrm, sub(x[d], x[a]));
    if height.abs() <= eps * dot(nrm, nrm).sqrt() || !height.is_finite() {
        return Vec::new();
    }
    let (b, c3) = if height > 0.0 { (c3, b) } else { (b, c3) };
    let mut fs: Vec<[usize; 3]> = vec![[a, b, c3], [a, d, b], [b, d, c3], [c3, d, a]];
    let above = |f: &[usize; 3], p: V3| {
        let m = cross(sub(x[f[1]], x[f[0]]), sub(x[f[2]], x[f[0]]));
        dot(m, sub(p, x[f[0]])) > eps * dot(m, m).sqrt()
    };
    for p in 0..n {
        if p == a || p == b || p == c3 || p == d {
            continue;
        }
        let (seen, kept): (Vec<[usize; 3]>, Vec<[usize; 3]>) = fs.iter().partition(|f| above(f, x[p]));
        if seen.is_empty() {
            continue;
        }
        let mut edges: Vec<(usize, usize)> = seen.iter().flat_map(|f| (0..3).map(move |m| (f[m], f[(m + 1) % 3]))).collect();
        crate::order::sort_pairs(&mut edges);
        fs = kept;
        for &(u, v) in &edges {
            if edges.binary_search(&(v, u)).is_err() {
                fs.push([u, v, p]);
            }
        }
    }
    fs
}

/// A's and B's triangulations read off the convex hull of `x` (see the module docs), or `None`
/// when the hull does not split into two proper triangulations of the flat pieces (a vertex
/// inside the hull, coplanar points, a face across the seam, a chord outside a non-convex piece).
pub fn triangulations(x: &[V3], pieces: &SeamPieces) -> Option<[Triangulation; 2]> {
    let n = pieces.n;
    if x.len() != n {
        return None;
    }
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for f in faces(x) {
        // Smallest index first, cyclic order kept.
        let m = (0..3).min_by_key(|&m| f[m]).unwrap_or(0);
        let [i, j, k] = [f[m], f[(m + 1) % 3], f[(m + 2) % 3]];
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
        crate::order::sort_dedup_pairs(&mut directed);
        let seam_ok = (0..n).all(|k| directed.binary_search(&(k, (k + 1) % n)).is_ok());
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

/// Total turn `2π − (α_A + α_B)` below which a seam vertex counts as flat: both pieces straight
/// there (each interior angle π to round-off), so no vertex of the glued surface.
const FLAT_CURVATURE: f64 = 1e-9;

/// The seam vertices that are cone points of the glued surface when the gluing is *polyhedral*:
/// both pieces are convex polygons, so every seam vertex is either a corner of a piece (a cone point,
/// curvature `2π − α_A − α_B > 0`) or a sample on straight sides of both (total angle 2π: a flat
/// point of the surface). `None` when some piece is curved (more than a quarter of the seam
/// vertices are cone points) or fewer than four are (a doubly covered polygon at best).
///
/// The D-form of two convex polygons is then a convex *polyhedron* (Alexandrov's gluing theorem:
/// a convex polyhedral metric on the sphere is realized by a unique convex polyhedron, possibly
/// doubly covered; its vertices are exactly the metric's cone points). Its edges are shortest
/// paths between cone points.
pub fn cone_vertices(pieces: &SeamPieces) -> Option<Vec<usize>> {
    let n = pieces.n;
    let angle = |p: usize, k: usize| {
        let f = &pieces.flat[p].pts;
        let (a, b, c) = (f[(k + n - 1) % n], f[k], f[(k + 1) % n]);
        let (u, v) = ([a[0] - b[0], a[1] - b[1]], [c[0] - b[0], c[1] - b[1]]);
        // Interior angle of the counter-clockwise polygon at b: from b→c round to b→a.
        let ang = (v[0] * u[1] - v[1] * u[0]).atan2_m(v[0] * u[0] + v[1] * u[1]);
        if ang < 0.0 { ang + std::f64::consts::TAU } else { ang }
    };
    // Convex pieces only: a reflex corner is a saddle of the surface, not a polyhedron's vertex.
    if (0..2).any(|p| (0..n).any(|k| angle(p, k) > std::f64::consts::PI + FLAT_CURVATURE)) {
        return None;
    }
    let cones: Vec<usize> =
        (0..n).filter(|&k| std::f64::consts::TAU - angle(0, k) - angle(1, k) > FLAT_CURVATURE).collect();
    (cones.len() >= 4 && 4 * cones.len() <= n).then_some(cones)
}

/// Twice the signed area of the flat polygon through `idx` (indices into `pts`).
fn area2(pts: &[[f64; 2]], idx: &[usize]) -> f64 {
    (0..idx.len()).map(|m| metric::orient([0.0, 0.0], pts[idx[m]], pts[idx[(m + 1) % idx.len()]])).sum()
}

/// A's and B's triangulations of a polyhedral gluing (see [`cone_vertices`]) built around the
/// crease chords read off the convex hull of the *cone points* of `x`, or `None`.
///
/// [`triangulations`] cannot serve a polyhedral D-form: most of its seam vertices lie on flat
/// faces or straight creases, inside the hull to round-off, so the hull of all seam vertices
/// is degenerate. The polyhedron is the hull of its cone points, though, and each of its edges
/// between two cone points that are not neighbours along the seam is a shortest path. When it
/// stays in one piece it is a chord of that piece (the usual case: the 90×10 rectangle with a
/// square at 128 and at 160 seam vertices has all six interior creases so); one that crosses the
/// seam at a flat point is not a chord at all, and this restart then simply fails the caller's
/// checks (the solver then adds such crossings as seam vertices: `seam_crossings`). Of the two
/// pieces' chords between the same cone points only the shorter can be an edge (the straight
/// segment is at most as long as the path across the other piece, see the solver's `excess`),
/// so each hull edge goes to the piece with the shorter chord, when that chord is within a few
/// per cent of its 3D length (a hull edge of a shape far off is not a crease). Each piece's
/// polygon is cut along its creases and the parts ear-clipped ([`cut_along`]): every triangle
/// then lies in one face of the polyhedron (flat parts are triangulated any way), so
/// the isometry equations have the convex polyhedron as an exact solution, which the local
/// flips, deciding by dihedral signs that are round-off on coplanar triangles, cannot reach
/// (a 90×10 rectangle with a square stalled folded, strain 1.2e-7 with 5000 steps and flips).
pub fn cone_triangulations(x: &[V3], pieces: &SeamPieces) -> Option<[Triangulation; 2]> {
    let n = pieces.n;
    if x.len() != n {
        return None;
    }
    let cones = cone_vertices(pieces)?;
    let xc: Vec<V3> = cones.iter().map(|&k| x[k]).collect();
    let mut edges: Vec<(usize, usize)> = faces(&xc)
        .iter()
        .flat_map(|f| (0..3).map(move |m| (f[m], f[(m + 1) % 3])))
        .map(|(a, b)| (cones[a].min(cones[b]), cones[a].max(cones[b])))
        .collect();
    crate::order::sort_dedup_pairs(&mut edges);
    let m = cones.len();
    let mut chords: [Vec<(usize, usize)>; 2] = [Vec::new(), Vec::new()];
    for (u, v) in edges {
        let (cu, cv) = (cones.binary_search(&u).ok()?, cones.binary_search(&v).ok()?);
        if (cu + 1) % m == cv || (cv + 1) % m == cu {
            continue; // neighbours along the seam: the seam itself (straight in both pieces)
        }
        let (da, db) = (pieces.chord(0, u, v), pieces.chord(1, u, v));
        let p = if da <= db { 0 } else { 1 };
        let l = dot(sub(x[v], x[u]), sub(x[v], x[u])).sqrt();
        if (l / pieces.chord(p, u, v) - 1.0).abs() > 0.05 {
            continue;
        }
        // Not along the piece's outline (both sides of the chord must enclose area) and not
        // crossing a chord taken already (u < a < v < b interleaved).
        let pts = &pieces.flat[p].pts;
        let side: Vec<usize> = (u..=v).collect();
        let other: Vec<usize> = (v..n).chain(0..=u).collect();
        let tot = area2(pts, &(0..n).collect::<Vec<_>>()).abs();
        if area2(pts, &side) <= 1e-9 * tot || area2(pts, &other) <= 1e-9 * tot {
            continue;
        }
        if chords[p].iter().any(|&(a, b)| (u < a && a < v && v < b) || (a < u && u < b && b < v)) {
            continue;
        }
        chords[p].push((u, v));
    }
    cut_along(pieces, &chords)
}

/// Each piece's polygon cut along its chords (pairs of seam vertices, non-crossing) and the
/// parts ear-clipped, or `None` when the chords do not cut it into simple parts.
pub fn cut_along(pieces: &SeamPieces, chords: &[Vec<(usize, usize)>; 2]) -> Option<[Triangulation; 2]> {
    let n = pieces.n;
    let mut out: Vec<Triangulation> = Vec::with_capacity(2);
    for p in 0..2 {
        let pts = &pieces.flat[p].pts;
        // Cut the polygon along each chord, then ear-clip the parts.
        let mut parts: Vec<Vec<usize>> = vec![(0..n).collect()];
        for &(u, v) in &chords[p] {
            let k = parts.iter().position(|q| q.contains(&u) && q.contains(&v))?;
            let q = parts.swap_remove(k);
            let (iu, iv) = (q.iter().position(|&w| w == u)?, q.iter().position(|&w| w == v)?);
            let (a, b) = (iu.min(iv), iu.max(iv));
            parts.push(q[a..=b].to_vec());
            parts.push(q[b..].iter().chain(&q[..=a]).copied().collect());
        }
        let mut tris = Vec::with_capacity(n - 2);
        for q in &parts {
            let sub_pts: Vec<[f64; 2]> = q.iter().map(|&w| pts[w]).collect();
            let t = metric::ear_clip(&sub_pts)?;
            tris.extend(t.tris.iter().map(|&[a, b, c]| [q[a], q[b], q[c]]));
        }
        if tris.len() != n - 2 {
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
    use crate::simulate::{seam::Glue, solve, SimulateOptions};
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
        let (pieces, mut sol) = solve::solve(&glue, &SimulateOptions { resolution: 32, offset: 0.25 * p, ..Default::default() }).unwrap();
        let c = sol.x.iter().fold([0.0; 3], |s, q| [s[0] + q[0] / 32.0, s[1] + q[1] / 32.0, s[2] + q[2] / 32.0]);
        sol.x[5] = [0.5 * (sol.x[5][0] + c[0]), 0.5 * (sol.x[5][1] + c[1]), 0.5 * (sol.x[5][2] + c[2])];
        assert!(triangulations(&sol.x, &pieces).is_none(), "a dented vertex cannot split the hull into two triangulations");
    }
}
