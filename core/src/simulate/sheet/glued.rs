//! The glued mesh of the two meshed pieces and the elastic shell's terms on it.

use super::flatmesh::{mesh_piece, FlatMesh};
use super::shell::{Edge, Hinge, Shell};
use crate::simulate::seam::SeamPieces;
use crate::order::pair_key;
use crate::simulate::metric::KeyMap;

/// The glued mesh of the two meshed pieces: seam vertices `0..n` shared, then A's interior
/// vertices, then B's. `faces[p]` are piece p's triangles in the surface's orientation (A's
/// counter-clockwise as meshed, B's reversed: its flat samples are mirrored, see
/// [`crate::simulate::seam`]); `flat[p][v]` is vertex v's position on piece p's flat piece (seam samples
/// have one on each piece; an interior vertex only on its own, the other piece's entry unused).
#[derive(Debug, Clone)]
pub struct SheetMesh {
    pub n: usize,
    pub faces: [Vec<[usize; 3]>; 2],
    pub flat: [Vec<[f64; 2]>; 2],
}

impl SheetMesh {
    /// Meshes both pieces with interior edges of about `interior` times the perimeter (never
    /// shorter than the mean seam step); `None` if either cannot be meshed.
    pub fn new(pieces: &SeamPieces, interior: f64) -> Option<Self> {
        let n = pieces.n;
        let step = pieces.flat[0].perimeter / n as f64;
        let edge = (interior * pieces.flat[0].perimeter).max(step);
        let max_area = 3f64.sqrt() / 4.0 * edge * edge;
        let meshes: [FlatMesh; 2] = [mesh_piece(&pieces.flat[0].pts, max_area)?, mesh_piece(&pieces.flat[1].pts, max_area)?];
        let ia = meshes[0].pts.len() - n;
        let total = n + ia + meshes[1].pts.len() - n;
        let global = |p: usize, v: usize| if p == 0 || v < n { v } else { v + ia };
        let mut faces: [Vec<[usize; 3]>; 2] = [Vec::new(), Vec::new()];
        let mut flat = [vec![[f64::NAN; 2]; total], vec![[f64::NAN; 2]; total]];
        for (p, m) in meshes.iter().enumerate() {
            for (v, q) in m.pts.iter().enumerate() {
                flat[p][global(p, v)] = *q;
            }
            faces[p] = m.tris.iter().map(|t| {
                let [a, b, c] = t.map(|v| global(p, v));
                if p == 0 { [a, b, c] } else { [a, c, b] }
            }).collect();
        }
        Some(SheetMesh { n, faces, flat })
    }

    pub fn vertex_count(&self) -> usize {
        self.flat[0].len()
    }

    /// Flat distance between `i` and `j` on piece `p`.
    pub fn rest(&self, p: usize, i: usize, j: usize) -> f64 {
        let (a, b) = (self.flat[p][i], self.flat[p][j]);
        (a[0] - b[0]).hypot(a[1] - b[1])
    }

    /// Flat area of triangle `t` of piece `p`.
    fn flat_area(&self, p: usize, t: [usize; 3]) -> f64 {
        let [a, b, c] = t.map(|v| self.flat[p][v]);
        ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs() / 2.0
    }

    /// The shell's terms: every edge of each piece at its flat length, and a hinge on every
    /// interior edge of each piece (none across the seam).
    pub fn shell(&self) -> Shell {
        let mut edges = Vec::new();
        let mut hinges = Vec::new();
        for p in 0..2 {
            // Each directed edge's triangle.
            let mut face_of = KeyMap::default();
            for (f, t) in self.faces[p].iter().enumerate() {
                for m in 0..3 {
                    face_of.insert(pair_key(t[m], t[(m + 1) % 3]), f);
                }
            }
            let tip = |t: [usize; 3], i: usize, j: usize| t.into_iter().find(|&v| v != i && v != j).expect("a triangle has three vertices");
            for t in &self.faces[p] {
                for m in 0..3 {
                    let (i, j) = (t[m], t[(m + 1) % 3]);
                    match face_of.get(&pair_key(j, i)) {
                        Some(&g) => {
                            if i < j {
                                let other = self.faces[p][g];
                                let len = self.rest(p, i, j);
                                edges.push(Edge { i, j, rest: len, piece: p as u8 });
                                let a = self.flat_area(p, *t) + self.flat_area(p, other);
                                hinges.push(Hinge { v: [i, j, tip(*t, i, j), tip(other, j, i)], weight: 3.0 * len * len / a });
                            }
                        }
                        None => edges.push(Edge { i, j, rest: self.rest(p, i, j), piece: p as u8 }),
                    }
                }
            }
        }
        Shell::new(self.vertex_count(), edges, hinges)
    }
}

