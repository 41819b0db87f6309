//! The sheet path's answer as a [`Simulation`], its soundness and its figures, measured on the
//! returned mesh against the flat pieces (as [`crate::simulate::stats`] does for the
//! seam-vertex polyhedron).

use crate::libm_ext::LibmExt;
use super::hinge;
use super::shell::Shell;
use super::glued::SheetMesh;
use crate::simulate::checks::{faces_cross, FOLD_BEND};
use crate::order::pair_key;
use crate::simulate::metric::KeyMap;
use crate::simulate::seam::SeamPieces;
use crate::simulate::stats::{area_and_angle_sums, Stats, REFLEX_REPORT};
use crate::simulate::vec3::{centroid, cross, dot, map_affine, norm, sub, V3};
use crate::simulate::Simulation;
use std::f64::consts::TAU;

/// Signed volume enclosed by `faces` (outward positive).
pub fn signed_volume(x: &[V3], faces: &[[usize; 3]]) -> f64 {
    faces.iter().map(|&[a, b, c]| dot(x[a], cross(x[b], x[c]))).sum::<f64>() / 6.0
}

/// The largest bend (|dihedral angle|) across an interior edge of a piece.
pub fn max_bend(x: &[V3], shell: &Shell) -> f64 {
    shell.hinges.iter().map(|h| hinge::angle(x[h.v[0]], x[h.v[1]], x[h.v[2]], x[h.v[3]]).abs()).fold(0.0, f64::max)
}

/// Whether the glued mesh is what a sheet can be: no fold inside a piece (a bend above
/// [`FOLD_BEND`]), no two triangles crossing, and every directed edge on one triangle. (Two
/// meshed disks glued along their whole boundary are a closed 2-manifold unless both have a
/// chord between the same two seam samples, which [`SheetMesh::new`] splits; the heart glued to
/// its mirror image was called converged with such a chord on four triangles.)
pub fn sound(x: &[V3], shell: &Shell, faces: &[[usize; 3]]) -> bool {
    max_bend(x, shell) <= FOLD_BEND && edges_once(faces) && !faces_cross(x, faces)
}

/// Whether no directed edge is on two triangles.
fn edges_once(faces: &[[usize; 3]]) -> bool {
    let mut seen = KeyMap::default();
    faces.iter().all(|t| (0..3).all(|k| seen.insert(pair_key(t[k], t[(k + 1) % 3]), 0).is_none()))
}

/// Builds the output: vertices centred and outward, triangles in the surface's orientation,
/// their flat corners in the input's coordinates (B's samples un-mirrored), and the stats.
pub fn simulation(pieces: &SeamPieces, mesh: &SheetMesh, shell: &Shell, x: &[V3], iterations: usize, converged: bool) -> Simulation {
    let n = mesh.n;
    let c = centroid(x);
    let mut x: Vec<V3> = x.iter().map(|p| sub(*p, c)).collect();
    let all: Vec<[usize; 3]> = mesh.faces.iter().flatten().copied().collect();
    if signed_volume(&x, &all) < 0.0 {
        x.iter_mut().for_each(|p| p[2] = -p[2]);
    }
    let mut triangles = Vec::with_capacity(all.len());
    let mut piece = Vec::with_capacity(all.len());
    let mut flat = Vec::with_capacity(all.len());
    for p in 0..2 {
        for t in &mesh.faces[p] {
            let at = |v: usize| {
                let q = mesh.flat[p][v];
                if p == 0 { q } else { [-q[0], q[1]] }
            };
            triangles.push(*t);
            flat.push(t.map(at));
            piece.push(p as u8);
        }
    }

    let (mut max_strain, mut sum_strain) = (0.0f64, 0.0);
    for e in &shell.edges {
        let s = (norm(sub(x[e.j], x[e.i])) / e.rest - 1.0).abs();
        max_strain = max_strain.max(s);
        sum_strain += s;
    }

    // Seam gap: the true outline's midpoint of each seam edge, mapped through each piece's
    // triangle on that edge.
    let mut on_edge = [KeyMap::default(), KeyMap::default()];
    for p in 0..2 {
        for (f, t) in mesh.faces[p].iter().enumerate() {
            for m in 0..3 {
                on_edge[p].insert(pair_key(t[m], t[(m + 1) % 3]), f);
            }
        }
    }
    let mut seam_gap = 0.0f64;
    for k in 0..n {
        let k1 = (k + 1) % n;
        let mid = |p: usize| {
            let key = if p == 0 { pair_key(k, k1) } else { pair_key(k1, k) };
            let t = mesh.faces[p][*on_edge[p].get(&key)?];
            let f = t.map(|v| mesh.flat[p][v]);
            map_affine(f, t.map(|v| x[v]), pieces.flat[p].arc_mid[k])
        };
        if let (Some(a), Some(b)) = (mid(0), mid(1)) {
            seam_gap = seam_gap.max(norm(sub(a, b)));
        }
    }

    let (area, angle_sum) = area_and_angle_sums(&x, &triangles);
    let defect = |v: usize| (TAU - angle_sum[v]).abs();
    let flat_area = pieces.flat[0].area + pieces.flat[1].area;
    let reflex_edges = shell
        .hinges
        .iter()
        .filter(|h| (-hinge::angle(x[h.v[0]], x[h.v[1]], x[h.v[2]], x[h.v[3]])).sin_m() > REFLEX_REPORT)
        .count();
    let stats = Stats {
        max_strain,
        mean_strain: if shell.edges.is_empty() { 0.0 } else { sum_strain / shell.edges.len() as f64 },
        strain_floor: 0.0,
        seam_gap,
        area_error: if flat_area > 0.0 { (area - flat_area).abs() / flat_area } else { 0.0 },
        angle_defect_sum: (0..n).map(defect).sum(),
        interior_defect_sum: (n..x.len()).map(defect).sum(),
        reflex_edges,
        volume: signed_volume(&x, &all).abs(),
        area,
        iterations,
        flips: 0,
        converged,
        ms: 0.0,
        max_bend: 0.0,
        shortfall: None,
        offset_free: false,
    };
    Simulation { vertices: x, triangles, piece, seam: (0..n).collect(), flat, creases: Vec::new(), stats }
}
