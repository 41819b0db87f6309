//! Coarse to fine: a sheet's shape on a coarser mesh of the same pieces carried onto a finer one.
//!
//! Each vertex of the fine mesh goes where the coarse mesh's piecewise-linear map (flat piece →
//! 3D) takes its flat position on its own piece; a seam vertex, on both pieces, takes the mean
//! of the two. The coarse seam is every `stride`-th fine sample ([`SeamPieces::every`]), so those
//! seam vertices keep their coarse positions; the fine samples between them lie just off the
//! coarse polygon, where the nearest coarse triangle's affine map extends.
//!
//! [`SeamPieces::every`]: crate::simulate::seam::SeamPieces::every

use super::glued::SheetMesh;
use crate::form::place::barycentric;
use crate::simulate::vec3::{map_affine, V3};

/// Side of a cell of the point-location grid, in coarse triangles per cell (about).
const PER_CELL: f64 = 2.0;

/// The coarse triangles of one piece bucketed by a uniform grid over their bounding boxes, to
/// find the triangle holding a flat point without testing them all.
struct Grid {
    origin: [f64; 2],
    cell: f64,
    cols: usize,
    rows: usize,
    cells: Vec<Vec<usize>>,
}

impl Grid {
    fn new(tris: &[[[f64; 2]; 3]]) -> Option<Grid> {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for t in tris {
            for q in t {
                for a in 0..2 {
                    lo[a] = lo[a].min(q[a]);
                    hi[a] = hi[a].max(q[a]);
                }
            }
        }
        let area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
        if !(area > 0.0) || !area.is_finite() {
            return None;
        }
        let cell = (area * PER_CELL / tris.len() as f64).sqrt();
        let cols = (((hi[0] - lo[0]) / cell).ceil() as usize).max(1);
        let rows = (((hi[1] - lo[1]) / cell).ceil() as usize).max(1);
        let mut grid = Grid { origin: lo, cell, cols, rows, cells: vec![Vec::new(); cols * rows] };
        for (i, t) in tris.iter().enumerate() {
            let (c0, r0) = grid.at([t[0][0].min(t[1][0]).min(t[2][0]), t[0][1].min(t[1][1]).min(t[2][1])]);
            let (c1, r1) = grid.at([t[0][0].max(t[1][0]).max(t[2][0]), t[0][1].max(t[1][1]).max(t[2][1])]);
            for r in r0..=r1 {
                for c in c0..=c1 {
                    grid.cells[r * cols + c].push(i);
                }
            }
        }
        Some(grid)
    }

    /// The cell of `q`, clamped to the grid.
    fn at(&self, q: [f64; 2]) -> (usize, usize) {
        let f = |v: f64, o: f64, m: usize| (((v - o) / self.cell).floor().max(0.0) as usize).min(m - 1);
        (f(q[0], self.origin[0], self.cols), f(q[1], self.origin[1], self.rows))
    }

    /// Candidate triangles for `q`: those of the cells within one ring beyond the first ring
    /// around its cell that holds any (a point just off the coarse polygon may fall in an empty
    /// cell; the ring beyond lets a point near a cell's edge see its neighbours too).
    fn near(&self, q: [f64; 2]) -> Vec<usize> {
        let (c, r) = self.at(q);
        let within = |ring: usize| {
            let mut out = Vec::new();
            for rr in r.saturating_sub(ring)..=(r + ring).min(self.rows - 1) {
                for cc in c.saturating_sub(ring)..=(c + ring).min(self.cols - 1) {
                    out.extend_from_slice(&self.cells[rr * self.cols + cc]);
                }
            }
            out
        };
        let Some(ring) = (0..self.cols.max(self.rows)).find(|&k| !within(k).is_empty()) else { return Vec::new() };
        let mut out = within(ring + 1);
        out.sort_unstable();
        out.dedup();
        out
    }
}

/// The shape `x` of mesh `coarse` carried onto mesh `fine` (see the module docs). `fine.n`
/// must be a multiple of `coarse.n`; `None` otherwise or when a piece has no triangle with area.
pub fn carry(coarse: &SheetMesh, x: &[V3], fine: &SheetMesh) -> Option<Vec<V3>> {
    if coarse.n == 0 || fine.n % coarse.n != 0 || x.len() != coarse.vertex_count() {
        return None;
    }
    let stride = fine.n / coarse.n;
    let total = fine.vertex_count();
    let mut out = vec![[0.0; 3]; total];
    let mut hits = vec![0usize; total];
    for k in 0..coarse.n {
        out[k * stride] = x[k];
    }
    for p in 0..2 {
        let faces = &coarse.faces[p];
        let tris: Vec<[[f64; 2]; 3]> = faces.iter().map(|t| t.map(|v| coarse.flat[p][v])).collect();
        let grid = Grid::new(&tris)?;
        let mut own = vec![false; total];
        fine.faces[p].iter().flatten().for_each(|&v| own[v] = true);
        for v in 0..total {
            if !own[v] || (v < fine.n && v % stride == 0) {
                continue;
            }
            let q = fine.flat[p][v];
            let best = grid.near(q).into_iter().filter_map(|t| barycentric(&tris[t], q).map(|b| (b[0].min(b[1]).min(b[2]), t))).max_by(|a, b| a.0.total_cmp(&b.0));
            let Some((_, t)) = best else { return None };
            let y = map_affine(tris[t], faces[t].map(|i| x[i]), q)?;
            let h = hits[v] as f64;
            out[v] = [0, 1, 2].map(|a| (out[v][a] * h + y[a]) / (h + 1.0));
            hits[v] += 1;
        }
    }
    Some(out)
}
