//! A flat piece meshed with interior vertices: the seam samples, in order, as its boundary, and
//! quality triangles inside.
//!
//! The mesh is spade's constrained Delaunay triangulation of the sample polygon, refined by
//! Ruppert's algorithm (Delaunay refinement with off-centre Steiner points; Shewchuk, "Delaunay
//! refinement algorithms for triangular mesh generation", CGTA 22, 2002) to a minimum angle and
//! a maximum area. The boundary edges are kept whole: they are the seam edges, shared with the
//! other piece, whose samples are fixed by the gluing. With short boundary edges and a larger
//! allowed area the triangles grow away from the seam, which is where a D-form bends most.

use crate::libm_ext::LibmExt;
use crate::order::pair_key;
use crate::simulate::metric::KeyMap;
use spade::{AngleLimit, ConstrainedDelaunayTriangulation, Point2, RefinementParameters, Triangulation as _};

/// Smallest angle the refinement aims for (degrees): 25° terminates on any input with kept
/// boundary edges and gives bending hinges of bounded aspect.
const MIN_ANGLE: f64 = 25.0;

/// Largest angle of a fan triangle at its seam vertex in [`mesh_piece_with_fans`] (see
/// [`super::glued::CONE_DEFECT`] for why there are fans).
pub const FAN_ANGLE: f64 = 30.0 * std::f64::consts::PI / 180.0;

/// A meshed flat piece: `pts[..n]` the seam samples as given, then the interior vertices;
/// triangles counter-clockwise.
#[derive(Debug, Clone)]
pub struct FlatMesh {
    pub pts: Vec<[f64; 2]>,
    pub tris: Vec<[usize; 3]>,
}

/// Meshes the counter-clockwise polygon `seam` with triangles of area at most `max_area`.
/// `None` when the polygon cannot be meshed (crossing or repeated samples) or the result is not
/// a triangulated disk whose boundary is exactly the seam.
pub fn mesh_piece(seam: &[[f64; 2]], max_area: f64) -> Option<FlatMesh> {
    mesh_piece_with_fans(seam, max_area, &[], &[])
}

/// Interior angle (radians, in (0, 2π)) of the counter-clockwise polygon `p` at vertex `k`.
pub fn interior_angle(p: &[[f64; 2]], k: usize) -> f64 {
    let n = p.len();
    let (a, b, c) = (p[(k + n - 1) % n], p[k], p[(k + 1) % n]);
    let (u, v) = ([c[0] - b[0], c[1] - b[1]], [a[0] - b[0], a[1] - b[1]]);
    let t = (u[0] * v[1] - u[1] * v[0]).atan2_m(u[0] * v[0] + u[1] * v[1]);
    if t <= 0.0 { t + std::f64::consts::TAU } else { t }
}

/// Mean length of the two seam edges at vertex `k` of the polygon `p`.
pub fn seam_step(p: &[[f64; 2]], k: usize) -> f64 {
    let n = p.len();
    let (a, b, c) = (p[(k + n - 1) % n], p[k], p[(k + 1) % n]);
    0.5 * ((a[0] - b[0]).hypot_m(a[1] - b[1]) + (c[0] - b[0]).hypot_m(c[1] - b[1]))
}

/// Mean edge length of the closed polygon `p` (its mean seam step).
pub fn mean_step(p: &[[f64; 2]]) -> f64 {
    let n = p.len();
    (0..n).map(|k| (p[k][0] - p[(k + 1) % n][0]).hypot_m(p[k][1] - p[(k + 1) % n][1])).sum::<f64>() / n as f64
}

/// The closed polygon `p` as a kurbo path, for kurbo's point-in-shape test (non-zero winding).
pub fn outline(p: &[[f64; 2]]) -> kurbo::BezPath {
    let n = p.len();
    kurbo::BezPath::from_vec((0..=n).map(|k| {
        let q = kurbo::Point::new(p[k % n][0], p[k % n][1]);
        if k == 0 { kurbo::PathEl::MoveTo(q) } else { kurbo::PathEl::LineTo(q) }
    }).chain([kurbo::PathEl::ClosePath]).collect())
}

/// [`mesh_piece`] with a fan of extra vertices inside the piece around each seam vertex of
/// `fans`: one at the mean of its two seam steps' lengths on every ray that splits the vertex's
/// interior angle into equal parts of at most [`FAN_ANGLE`] (a ray point outside the polygon,
/// beside a neighbouring reflex corner, is left out). The refinement keeps these vertices and
/// may add more around them, so every triangle at such a vertex has its angle there at most
/// [`FAN_ANGLE`]. The points `inner` (inside the polygon, e.g. [`super::saddle::rows`]) are
/// kept as vertices too.
pub fn mesh_piece_with_fans(seam: &[[f64; 2]], max_area: f64, fans: &[usize], inner: &[[f64; 2]]) -> Option<FlatMesh> {
    mesh_polygon(seam, max_area, fans, inner, Build::Bulk)
}

/// How the polygon's constrained triangulation is built before it is refined.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Build {
    /// spade's bulk loading: fast, but a vertex it cannot place in its sweep (one at the same
    /// angle from the sweep's centre as another, as the collinear points of a mirror axis are)
    /// is inserted afterwards in the order of a randomly seeded hash set, and the mesh then
    /// differs from run to run.
    Bulk,
    /// The vertices inserted one by one in order, then the boundary edges: the same mesh on
    /// every run whatever the points' alignment ([`super::mirror`] meshes a half bounded by its
    /// axis so).
    InOrder,
}

/// [`mesh_piece_with_fans`], its triangulation built by `build`.
pub(super) fn mesh_polygon(seam: &[[f64; 2]], max_area: f64, fans: &[usize], inner: &[[f64; 2]], build: Build) -> Option<FlatMesh> {
    let n = seam.len();
    if n < 3 || !(max_area > 0.0 && max_area.is_finite()) {
        return None;
    }
    let vertices: Vec<Point2<f64>> = seam.iter().map(|p| Point2::new(p[0], p[1])).collect();
    let mut cdt = match build {
        Build::Bulk => {
            let edges: Vec<[usize; 2]> = (0..n).map(|k| [k, (k + 1) % n]).collect();
            ConstrainedDelaunayTriangulation::<Point2<f64>>::bulk_load_cdt(vertices, edges).ok()?
        }
        Build::InOrder => {
            let mut cdt = ConstrainedDelaunayTriangulation::<Point2<f64>>::new();
            let handles = vertices.into_iter().map(|v| cdt.insert(v).ok()).collect::<Option<Vec<_>>>()?;
            if cdt.num_vertices() != n {
                return None;
            }
            for k in 0..n {
                let (from, to) = (handles[k], handles[(k + 1) % n]);
                if !cdt.can_add_constraint(from, to) {
                    return None;
                }
                cdt.add_constraint(from, to);
            }
            cdt
        }
    };
    if cdt.num_vertices() != n || cdt.num_constraints() != n {
        return None;
    }
    let outline = (!fans.is_empty()).then(|| outline(seam));
    for &k in fans {
        let (b, c) = (seam[k], seam[(k + 1) % n]);
        let h = seam_step(seam, k);
        let angle = interior_angle(seam, k);
        let parts = (angle / FAN_ANGLE).ceil() as usize;
        let start = (c[1] - b[1]).atan2_m(c[0] - b[0]);
        for j in 1..parts {
            let t = start + angle * j as f64 / parts as f64;
            let q = [b[0] + h * t.cos_m(), b[1] + h * t.sin_m()];
            if !outline.as_ref().is_some_and(|o| kurbo::Shape::contains(o, kurbo::Point::new(q[0], q[1]))) {
                continue;
            }
            cdt.insert(Point2::new(q[0], q[1])).ok()?;
        }
    }
    for q in inner {
        cdt.insert(Point2::new(q[0], q[1])).ok()?;
    }
    let area = polygon_area(seam);
    let budget = ((8.0 * area / max_area) as usize).max(4 * n) + 1000;
    let params = RefinementParameters::<f64>::new()
        // The ratio `1 / (2 sin θ)` that `AngleLimit::from_deg` computes, its sine from libm
        // ([`LibmExt`]) rather than each system's maths library: the same mesh everywhere.
        .with_angle_limit(AngleLimit::from_radius_to_shortest_edge_ratio(0.5 / MIN_ANGLE.to_radians().sin_m()))
        .with_max_allowed_area(max_area)
        .with_max_additional_vertices(budget)
        .keep_constraint_edges()
        .exclude_outer_faces(true);
    let result = cdt.refine(params);
    let excluded: KeyMap = result.excluded_faces.iter().map(|f| (f.index() as u64, 0)).collect();
    // Seam samples keep their indices (bulk loading is stable); interior vertices are renumbered
    // after them in the order met.
    let mut index = vec![usize::MAX; cdt.num_vertices()];
    for (k, slot) in index.iter_mut().enumerate().take(n) {
        *slot = k;
    }
    let mut pts: Vec<[f64; 2]> = seam.to_vec();
    let mut tris = Vec::new();
    for face in cdt.inner_faces() {
        if excluded.contains_key(&(face.fix().index() as u64)) {
            continue;
        }
        let t = face.vertices().map(|v| {
            let k = v.fix().index();
            if index[k] == usize::MAX {
                index[k] = pts.len();
                let p = v.position();
                pts.push([p.x, p.y]);
            }
            index[k]
        });
        tris.push(t);
    }
    let mesh = FlatMesh { pts, tris };
    mesh.is_disk(n).then_some(mesh)
}

impl FlatMesh {
    /// Whether this is a triangulated disk (`F = n − 2 + 2I`, Euler) with every seam edge
    /// `k → k+1` on exactly one counter-clockwise triangle and every other edge on two.
    pub(super) fn is_disk(&self, n: usize) -> bool {
        let interior = self.pts.len() - n;
        if self.tris.len() != n - 2 + 2 * interior {
            return false;
        }
        let mut directed = KeyMap::default();
        for t in &self.tris {
            if crate::simulate::metric::orient(self.pts[t[0]], self.pts[t[1]], self.pts[t[2]]) <= 0.0 {
                return false;
            }
            for m in 0..3 {
                if directed.insert(pair_key(t[m], t[(m + 1) % 3]), 0).is_some() {
                    return false;
                }
            }
        }
        directed.keys().all(|&key| {
            let (a, b) = crate::order::unpair(key);
            let seam_forward = a < n && b < n && (a + 1) % n == b;
            seam_forward != directed.contains_key(&pair_key(b, a))
        }) && (0..n).all(|k| directed.contains_key(&pair_key(k, (k + 1) % n)))
    }
}

/// Area of a counter-clockwise polygon (shoelace).
pub(crate) fn polygon_area(p: &[[f64; 2]]) -> f64 {
    let n = p.len();
    (0..n).map(|k| p[k][0] * p[(k + 1) % n][1] - p[(k + 1) % n][0] * p[k][1]).sum::<f64>() / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A kidney-like polygon (non-convex): the mesh covers exactly its area, keeps every sample
    /// and edge of the boundary, and has interior vertices at about the asked-for density.
    #[test]
    fn meshes_a_nonconvex_polygon_into_a_disk_of_its_area() {
        let n = 96;
        let seam: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / n as f64;
                let r = 50.0 * (1.0 + 0.35 * (2.0 * t).cos_m() - 0.25 * t.cos_m());
                [r * t.cos_m(), r * t.sin_m()]
            })
            .collect();
        let area = polygon_area(&seam);
        let m = mesh_piece(&seam, area / 400.0).expect("a mesh");
        let covered: f64 = m.tris.iter().map(|t| crate::simulate::metric::orient(m.pts[t[0]], m.pts[t[1]], m.pts[t[2]]) / 2.0).sum();
        assert!((covered - area).abs() < 1e-9 * area, "area wanted {area}, got {covered}");
        assert_eq!(&m.pts[..n], &seam[..], "seam samples kept in order");
        assert!(m.tris.len() >= 400, "about area/max_area triangles at least: got {}", m.tris.len());
    }

    /// A 40 × 40 square sampled every 2 with fans at its four corners: still a disk of its area
    /// with its samples kept, and every triangle at a corner has its angle there at most 30°
    /// (without fans the refinement leaves each corner as one 90° triangle).
    #[test]
    fn fans_split_a_corner_into_triangles_of_at_most_30_degrees() {
        let side = 20;
        let mut seam = Vec::new();
        for (start, dir) in [([0.0, 0.0], [2.0, 0.0]), ([40.0, 0.0], [0.0, 2.0]), ([40.0, 40.0], [-2.0, 0.0]), ([0.0, 40.0], [0.0, -2.0])] {
            seam.extend((0..side).map(|k| [start[0] + dir[0] * k as f64, start[1] + dir[1] * k as f64]));
        }
        let corners = [0, side, 2 * side, 3 * side];
        let m = mesh_piece_with_fans(&seam, 40.0, &corners, &[]).expect("a mesh");
        let covered: f64 = m.tris.iter().map(|t| crate::simulate::metric::orient(m.pts[t[0]], m.pts[t[1]], m.pts[t[2]]) / 2.0).sum();
        assert!((covered - 1600.0).abs() < 1e-9 * 1600.0, "area wanted 1600, got {covered}");
        assert_eq!(&m.pts[..seam.len()], &seam[..], "seam samples kept in order");
        for &c in &corners {
            let mut total = 0.0;
            for t in m.tris.iter().filter(|t| t.contains(&c)) {
                let k = t.iter().position(|&v| v == c).unwrap();
                let (a, b) = (m.pts[t[(k + 1) % 3]], m.pts[t[(k + 2) % 3]]);
                let o = m.pts[c];
                let (u, v) = ([a[0] - o[0], a[1] - o[1]], [b[0] - o[0], b[1] - o[1]]);
                let angle = (u[0] * v[1] - u[1] * v[0]).atan2_m(u[0] * v[0] + u[1] * v[1]).to_degrees();
                assert!(angle <= 30.0 + 1e-9, "corner {c}: wanted fan angles ≤ 30°, got {angle:.2}°");
                total += angle;
            }
            assert!((total - 90.0).abs() < 1e-9, "corner {c}: the fan covers {total}°, wanted 90°");
        }
    }
}
