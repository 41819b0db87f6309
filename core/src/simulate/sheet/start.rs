//! The sheet's starting shape: the convex path's answer on the same seam samples, carried onto
//! the finer mesh. Its seam vertices are the seam vertices as they are; an interior vertex of a
//! piece goes where the piecewise-linear map of that piece's chord triangulation (flat polygon →
//! 3D) takes its flat position. So the start is the seam-vertex polyhedron itself, isometric up
//! to the convex path's residual strain, creases and all; the thick stages of the continuation
//! smooth the creases out.

use super::glued::SheetMesh;
use crate::form::place::barycentric;
use crate::simulate::mesh::Solution;
use crate::simulate::seam::SeamPieces;
use crate::simulate::vec3::{map_affine, V3};

/// The starting positions of every vertex of `mesh` (see the module docs).
pub fn lift(pieces: &SeamPieces, start: &Solution, mesh: &SheetMesh) -> Vec<V3> {
    lift_onto([&pieces.flat[0].pts, &pieces.flat[1].pts], start, mesh, &mesh.flat)
}

/// [`lift`] for a polyhedron `start` on the sample polygons `polygons` and the mesh's vertices
/// at the flat positions `flat` (e.g. the convex twins' and the meshes carried onto them).
/// `start` may be a coarser level of the seam, every `stride`-th sample (`stride = mesh.n /
/// start`'s vertex count): the seam vertices between its own are then carried like interior
/// ones, by both pieces' maps averaged (they lie just outside the coarse polygons, where the
/// nearest chord triangle's affine map extends).
pub fn lift_onto(polygons: [&[[f64; 2]]; 2], start: &Solution, mesh: &SheetMesh, flat: &[Vec<[f64; 2]>; 2]) -> Vec<V3> {
    let n = mesh.n;
    let stride = (n / start.x.len().max(1)).max(1);
    let mut x = vec![[0.0; 3]; mesh.vertex_count()];
    let mut hits = vec![0usize; mesh.vertex_count()];
    for k in (0..n).step_by(stride) {
        x[k] = start.x[k / stride];
    }
    for p in 0..2 {
        let f = polygons[p];
        let tris = &start.tri[p].tris;
        let mut own = vec![false; mesh.vertex_count()];
        mesh.faces[p].iter().flatten().for_each(|&v| own[v] = true);
        for v in 0..mesh.vertex_count() {
            if !own[v] || (v < n && v % stride == 0) {
                continue;
            }
            let q = flat[p][v];
            // The chord triangle holding q: the one whose least barycentric coordinate is
            // largest (≥ 0 inside; a point on a chord is in either neighbour).
            let best = tris
                .iter()
                .filter_map(|t| barycentric(&[f[t[0]], f[t[1]], f[t[2]]], q).map(|b| (b[0].min(b[1]).min(b[2]), t)))
                .max_by(|a, b| a.0.total_cmp(&b.0));
            if let Some((_, t)) = best {
                let tf = [f[t[0]], f[t[1]], f[t[2]]];
                let tx = [start.x[t[0]], start.x[t[1]], start.x[t[2]]];
                if let Some(y) = map_affine(tf, tx, q) {
                    let h = hits[v] as f64;
                    x[v] = [0, 1, 2].map(|a| (x[v][a] * h + y[a]) / (h + 1.0));
                    hits[v] += 1;
                }
            }
        }
    }
    x
}
