//! A mirror-symmetric mesh for a mirror-symmetric pair (issue 14's requirement 3).
//!
//! A pair whose two sample polygons are each symmetric about a line, by the same renumbering
//! of the seam `k ↦ 2j − k`, glues into a surface with a mirror plane, and its form must have
//! one. The samples are symmetric when the seam starts on an axis
//! ([`crate::simulate::anchor::canonical_start`]), but Delaunay refinement inserts its points in
//! its own order, so a piece meshed whole is not: the five lobes with a circle ended 0.6 % of
//! their size from symmetric, a heart drawn with corners 1.5 %. So such a piece is meshed as
//! its half on one side of the axis, the axis chord kept as a boundary of the half, and the
//! half's triangles reflected onto the other side: the mesh is then its own mirror image, seam
//! samples and all, and so are the shell's terms on it.
//!
//! The axis chord joins the two samples on the axis, `j` and `j + n/2`; it lies inside the
//! polygon (a simple polygon symmetric about a line meets it in one interval: two intervals
//! and a path between them, folded onto one side and closed by its reflection, would enclose
//! the gap between them). It is cut into steps graded like the refinement's triangles: the
//! seam step at its ends, growing by [`GRADE`] times the distance to the seam, at most the
//! interior edge.

use crate::libm_ext::LibmExt;
use super::flatmesh::{mean_step, mesh_polygon, Build, FlatMesh};
use super::saddle::distance_to_edge;
use crate::simulate::seam::SeamPieces;

/// How far (relative to the mean seam step) a sample may lie from its partner's reflection for
/// the polygon to count as symmetric. Started on an axis, the samples are mirror images up to
/// the arc lengths' accuracy and the seam density's ([`crate::simulate::density`]; the rounded
/// star with a circle, the steepest curvature of the tests, is 1.1e-5 of its step off at 128
/// and 256 seam vertices), and up to the drawing's own asymmetry, which may be up to
/// [`crate::simulate::anchor::MIRROR_TOLERANCE`] of its size. The seam samples on the mirrored
/// side are the drawn ones, so the triangles beside them move by at most this share of a step.
pub const MIRROR_SAMPLES: f64 = 0.05;

/// Growth of the axis chord's steps with the distance from the seam (a step at distance `d`
/// is the seam step plus `GRADE · d`): about the grading of Ruppert's refinement at 25°.
pub const GRADE: f64 = 0.5;

/// The seam sample `j` (`0 ≤ j < n/2`) such that both pieces' sample polygons are mirror
/// images of themselves under `k ↦ 2j − k (mod n)`, the first such from `j = 0`; `None` when
/// `n` is odd or there is none.
pub fn axis(pieces: &SeamPieces) -> Option<usize> {
    let n = pieces.n;
    if n < 4 || n % 2 != 0 {
        return None;
    }
    (0..n / 2).find(|&j| pieces.flat.iter().all(|f| symmetric(&f.pts, j)))
}

/// Reflection across the line through `a` and `b`.
fn reflection(a: [f64; 2], b: [f64; 2]) -> Option<impl Fn([f64; 2]) -> [f64; 2]> {
    let l = (b[0] - a[0]).hypot_m(b[1] - a[1]);
    if !(l > 0.0) || !l.is_finite() {
        return None;
    }
    let d = [(b[0] - a[0]) / l, (b[1] - a[1]) / l];
    Some(move |q: [f64; 2]| {
        let v = [q[0] - a[0], q[1] - a[1]];
        let along = v[0] * d[0] + v[1] * d[1];
        [a[0] + 2.0 * along * d[0] - v[0], a[1] + 2.0 * along * d[1] - v[1]]
    })
}

/// Whether the polygon `p` (`n` even) is its own mirror image under `k ↦ 2j − k`, the axis
/// through samples `j` and `j + n/2` ([`MIRROR_SAMPLES`]).
fn symmetric(p: &[[f64; 2]], j: usize) -> bool {
    let n = p.len();
    let m = n / 2;
    let Some(reflect) = reflection(p[j], p[(j + m) % n]) else { return false };
    let tolerance = MIRROR_SAMPLES * mean_step(p);
    (1..m).all(|k| {
        let (q, r) = (reflect(p[(j + k) % n]), p[(j + n - k) % n]);
        (q[0] - r[0]).hypot_m(q[1] - r[1]) <= tolerance
    })
}

/// Distance from `q` to the polygon `p`'s edges.
fn distance_to_polygon(p: &[[f64; 2]], q: [f64; 2]) -> f64 {
    let n = p.len();
    (0..n).map(|k| distance_to_edge(q, p[k], p[(k + 1) % n])).fold(f64::INFINITY, f64::min)
}

/// Points strictly inside the segment `from → to` (length `l`), at steps graded by `step(x)`:
/// as many as the integral of `1/step` along it, rounded, spaced evenly in that integral.
fn graded(from: [f64; 2], to: [f64; 2], step: &dyn Fn([f64; 2]) -> f64, fine: f64) -> Vec<[f64; 2]> {
    let l = (to[0] - from[0]).hypot_m(to[1] - from[1]);
    let at = |t: f64| [from[0] + t * (to[0] - from[0]), from[1] + t * (to[1] - from[1])];
    let samples = ((l / fine).ceil() as usize).clamp(1, 4096);
    let mut integral = vec![0.0; samples + 1];
    for s in 0..samples {
        let t = (s as f64 + 0.5) / samples as f64;
        integral[s + 1] = integral[s] + l / samples as f64 / step(at(t));
    }
    let total = integral[samples];
    let count = (total.round() as usize).max(1);
    let mut out = Vec::with_capacity(count - 1);
    let mut s = 0;
    for k in 1..count {
        let want = total * k as f64 / count as f64;
        while s + 1 < samples && integral[s + 1] < want {
            s += 1;
        }
        let t = (s as f64 + (want - integral[s]) / (integral[s + 1] - integral[s])) / samples as f64;
        out.push(at(t));
    }
    out
}

/// [`super::flatmesh::mesh_piece_with_fans`] made mirror-symmetric about the axis through
/// samples `j` and `j + n/2` of the counter-clockwise polygon `seam` (which [`axis`] found
/// symmetric): the half from `j` to `j + n/2` is meshed with the axis chord as its boundary and
/// reflected. The fans at seam samples and the points `inner` are taken on the half's side and
/// reflected: a point on the axis (within [`MIRROR_SAMPLES`] of a seam step) is kept on the
/// chord, one off it but within half a seam step of it is left out. `None` when the half cannot
/// be meshed or the whole is not a triangulated disk.
pub fn mesh_piece_mirrored(seam: &[[f64; 2]], max_area: f64, fans: &[usize], inner: &[[f64; 2]], j: usize) -> Option<FlatMesh> {
    let n = seam.len();
    if n < 4 || n % 2 != 0 || j >= n {
        return None;
    }
    let m = n / 2;
    let (q0, p0) = (seam[j], seam[(j + m) % n]);
    let reflect = reflection(q0, p0)?;
    let axis_len = (p0[0] - q0[0]).hypot_m(p0[1] - q0[1]);
    let dir = [(p0[0] - q0[0]) / axis_len, (p0[1] - q0[1]) / axis_len];
    let side = |q: [f64; 2]| dir[0] * (q[1] - q0[1]) - dir[1] * (q[0] - q0[0]);
    let sign = side(seam[(j + 1) % n]).signum();
    let step = mean_step(seam);
    let on_axis = MIRROR_SAMPLES * step;
    // The chord from sample j + n/2 back to sample j: the points of `inner` on it, and graded
    // steps between them.
    let mut stops: Vec<f64> = inner
        .iter()
        .filter(|&&q| side(q).abs() <= on_axis)
        .map(|q| (q[0] - q0[0]) * dir[0] + (q[1] - q0[1]) * dir[1])
        .filter(|&t| t > 0.5 * step && t < axis_len - 0.5 * step)
        .collect();
    stops.sort_by(|a, b| b.total_cmp(a));
    stops.dedup_by(|a, b| (*a - *b).abs() < 0.5 * step);
    let edge = (4.0 * max_area / 3f64.sqrt()).sqrt();
    let size_at = |q: [f64; 2]| (step + GRADE * distance_to_polygon(seam, q)).min(edge.max(step));
    let on_chord = |t: f64| [q0[0] + t * dir[0], q0[1] + t * dir[1]];
    let mut chord = Vec::new();
    let mut from = p0;
    for q in stops.iter().map(|&t| on_chord(t)).chain([q0]) {
        chord.extend(graded(from, q, &size_at, 0.5 * step));
        if q != q0 {
            chord.push(q);
        }
        from = q;
    }
    if chord.is_empty() {
        chord.push([(p0[0] + q0[0]) / 2.0, (p0[1] + q0[1]) / 2.0]);
    }
    let half: Vec<[f64; 2]> = (0..=m).map(|k| seam[(j + k) % n]).chain(chord.iter().copied()).collect();
    let half_fans: Vec<usize> = fans.iter().map(|&k| (k + n - j) % n).filter(|&k| k <= m).collect();
    let half_inner: Vec<[f64; 2]> = inner.iter().copied().filter(|&q| sign * side(q) > 0.5 * step).collect();
    let h = mesh_polygon(&half, max_area, &half_fans, &half_inner, Build::InOrder)?;
    // Vertices: the seam, the chord's, the half's interior, their reflections.
    let (c, hb) = (chord.len(), half.len());
    let interior = h.pts.len() - hb;
    let mut pts = seam.to_vec();
    pts.extend_from_slice(&chord);
    pts.extend_from_slice(&h.pts[hb..]);
    pts.extend(h.pts[hb..].iter().map(|&q| reflect(q)));
    let index = |v: usize, mirrored: bool| -> usize {
        if v <= m {
            if mirrored { (j + n - v) % n } else { (j + v) % n }
        } else if v < hb {
            n + v - (m + 1)
        } else {
            n + c + (v - hb) + if mirrored { interior } else { 0 }
        }
    };
    let mut tris = Vec::with_capacity(2 * h.tris.len());
    tris.extend(h.tris.iter().map(|t| t.map(|v| index(v, false))));
    tris.extend(h.tris.iter().map(|t| [index(t[0], true), index(t[2], true), index(t[1], true)]));
    let mesh = FlatMesh { pts, tris };
    mesh.is_disk(n).then_some(mesh)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// r = 55(1 + 0.12 sin 5θ) at `n` equal steps of θ from `start`.
    fn lobes_samples(n: usize, start: f64) -> Vec<[f64; 2]> {
        (0..n)
            .map(|k| {
                let t = start + std::f64::consts::TAU * k as f64 / n as f64;
                let r = 55.0 * (1.0 + 0.12 * (5.0 * t).sin_m());
                [r * t.cos_m(), r * t.sin_m()]
            })
            .collect()
    }

    /// A five-lobed polygon started on a lobe's tip (an axis): the mesh is its own mirror image
    /// (every vertex's reflection is a vertex, every triangle's a triangle), covers the polygon's
    /// area, keeps the seam, and a polygon started off its axes has none.
    #[test]
    fn a_symmetric_polygon_gets_a_mesh_that_is_its_own_mirror_image() {
        let n = 128;
        let lobes = |start: f64| lobes_samples(n, start);
        let seam = lobes(std::f64::consts::FRAC_PI_2 / 5.0);
        assert!(symmetric(&seam, 0), "started on a tip, the samples are symmetric about the tip's axis");
        assert!(!symmetric(&lobes(0.1), 0), "started off every axis, they are not about the first sample");
        let area = super::super::flatmesh::polygon_area(&seam);
        let mesh = mesh_piece_mirrored(&seam, area / 300.0, &[], &[], 0).expect("a mesh");
        assert_eq!(&mesh.pts[..n], &seam[..], "seam samples kept in order");
        let covered: f64 = mesh.tris.iter().map(|t| crate::simulate::metric::orient(mesh.pts[t[0]], mesh.pts[t[1]], mesh.pts[t[2]]) / 2.0).sum();
        assert!((covered - area).abs() < 1e-9 * area, "area wanted {area}, got {covered}");
        // Independent of how it was built: reflect every vertex across the line through the
        // samples 0 and n/2 and find it among the vertices.
        let (a, b) = (seam[0], seam[n / 2]);
        let l = (b[0] - a[0]).hypot_m(b[1] - a[1]);
        let d = [(b[0] - a[0]) / l, (b[1] - a[1]) / l];
        let mirror_of = |q: [f64; 2]| {
            let along = (q[0] - a[0]) * d[0] + (q[1] - a[1]) * d[1];
            [2.0 * (a[0] + along * d[0]) - q[0], 2.0 * (a[1] + along * d[1]) - q[1]]
        };
        let find = |q: [f64; 2]| mesh.pts.iter().position(|p| (p[0] - q[0]).hypot_m(p[1] - q[1]) < 1e-9 * l);
        let image: Vec<usize> = mesh.pts.iter().enumerate().map(|(v, &q)| find(mirror_of(q)).unwrap_or_else(|| panic!("vertex {v} at {q:?}: wanted its reflection among the vertices, got none"))).collect();
        let mut sorted: Vec<[usize; 3]> = mesh.tris.iter().map(|t| { let mut s = *t; s.sort(); s }).collect();
        sorted.sort();
        for t in &mesh.tris {
            let mut r = t.map(|v| image[v]);
            r.sort();
            assert!(sorted.binary_search(&r).is_ok(), "triangle {t:?}: wanted its reflection {r:?} in the mesh, got none");
        }
    }
}
