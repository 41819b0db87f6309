//! The isometry equations of the seam-vertex polyhedron and one damped Gauss–Newton
//! (Levenberg–Marquardt) step on them, shared by the convex and the sheet path.

use super::metric::{self, Triangulation};
use super::normal::NormalEquations;
use super::seam::SeamPieces;
use super::vec3::{norm, sub, V3};

/// A step shorter than this (relative to the shape's size) ends the iteration.
pub(crate) const STEP_TOL: f64 = 1e-11;

/// Largest residual strain of the length equations accepted as "converged".
pub const STRAIN_TOL: f64 = 1e-7;

/// One length equation: |x_i − x_j| = d.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Bar {
    pub(crate) i: usize,
    pub(crate) j: usize,
    pub(crate) d: f64,
}

/// The length equations: every chord of each piece at its flat length, and each seam edge once,
/// at the mean of A's and B's chord. (The two chords differ by `O(h³)`; one length per seam edge
/// makes the polyhedral metric consistent, so the square system has an exact solution and the
/// convexity of each chord is decided by geometry, not by least-squares noise.)
pub(crate) fn bars(pieces: &SeamPieces, tri: &[Triangulation; 2]) -> Vec<Bar> {
    let n = pieces.n;
    let mut out = Vec::with_capacity(3 * n);
    for (p, t) in tri.iter().enumerate() {
        for (i, j) in t.edges() {
            if metric::is_seam(n, i, j) && p == 1 {
                continue;
            }
            let d = bar_length(pieces, p, i, j);
            if d > 0.0 {
                out.push(Bar { i, j, d });
            }
        }
    }
    out
}

/// The length of edge i–j of piece `p` in the length equations: a chord's flat length, a seam
/// edge's mean of A's and B's chords (see [`bars`]).
pub(crate) fn bar_length(pieces: &SeamPieces, p: usize, i: usize, j: usize) -> f64 {
    if metric::is_seam(pieces.n, i, j) { 0.5 * (pieces.chord(0, i, j) + pieces.chord(1, i, j)) } else { pieces.chord(p, i, j) }
}

/// Sum of squared relative residuals `(|x_i − x_j| / d − 1)²`.
pub(crate) fn cost(x: &[V3], bars: &[Bar]) -> f64 {
    bars.iter().map(|b| (norm(sub(x[b.j], x[b.i])) / b.d - 1.0).powi(2)).sum()
}

pub(crate) fn max_strain(x: &[V3], bars: &[Bar]) -> f64 {
    bars.iter().map(|b| (norm(sub(x[b.j], x[b.i])) / b.d - 1.0).abs()).fold(0.0, f64::max)
}

/// Solves one damped Gauss–Newton step `(JᵀJ + λ·μ I) Δ = −Jᵀr` with the normal equations
/// pattern of `bars`; `None` if the factorization fails (then the caller raises λ).
pub(crate) fn step(x: &[V3], bars: &[Bar], lambda: f64, ne: &mut NormalEquations) -> Option<Vec<f64>> {
    let mut g = vec![0.0; 3 * x.len()];
    let mut blocks = Vec::with_capacity(bars.len());
    for b in bars {
        let e = sub(x[b.j], x[b.i]);
        let l = norm(e);
        let u = if l > 0.0 { [e[0] / l, e[1] / l, e[2] / l] } else { [1.0, 0.0, 0.0] };
        let r = l / b.d - 1.0;
        let w = 1.0 / (b.d * b.d);
        for a in 0..3 {
            g[3 * b.j + a] += u[a] * r / b.d;
            g[3 * b.i + a] -= u[a] * r / b.d;
        }
        blocks.push([0, 1, 2].map(|a| [0, 1, 2].map(|c| w * u[a] * u[c])));
    }
    ne.solve(&blocks, &g, lambda)
}

/// The sparse pattern of the normal equations of `bars` on `n` vertices.
pub(crate) fn pattern(n: usize, bars: &[Bar]) -> NormalEquations {
    let pairs: Vec<(usize, usize)> = bars.iter().map(|b| (b.i, b.j)).collect();
    NormalEquations::new(n, &pairs)
}

/// The pattern of `bars` after flips, in the ordering of the previous pattern `ne`
/// ([`NormalEquations::reordered_like`]).
pub(crate) fn repattern(ne: &NormalEquations, bars: &[Bar]) -> NormalEquations {
    let pairs: Vec<(usize, usize)> = bars.iter().map(|b| (b.i, b.j)).collect();
    ne.reordered_like(&pairs)
}
