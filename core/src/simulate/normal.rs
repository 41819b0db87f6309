//! The damped normal equations `(JᵀJ + λ·μ I) Δ = −Jᵀr` of the length equations, assembled
//! into a fixed sparse pattern and solved by a sparse LDLᵀ factorization (sprs-ldl: Davis'
//! LDL, "Algorithm 849") after an approximate-minimum-degree ordering ([`vertex_order`]).
//!
//! The pattern only depends on which vertex pairs carry a length equation, i.e. on the two
//! triangulations, which change only when chords are flipped. So the pattern, the ordering and
//! the symbolic factorization (elimination tree, column counts) are computed once per
//! triangulation and every Levenberg–Marquardt step only refills the values and redoes the
//! numeric factorization.
//!
//! Layout: unknown `3v + a` is coordinate `a` of vertex `v`. Every vertex pair `(v, w)` joined
//! by a length equation (and every `(v, v)`) is a dense, symmetric 3×3 block; column `3v + a`
//! stores the blocks of `v`'s sorted neighbours `w` (itself included), so entry
//! `(3w + b, 3v + a)` sits at `base[v] + a·3·deg[v] + 3·rank_v(w) + b`.

use sprs::{CsMat, PermOwnedI, SymmetryCheck};
use sprs_ldl::LdlNumeric;

/// The index in the value array of the block (row vertex, column vertex): entry `(b, a)` is at
/// `at + a·stride + b`.
#[derive(Debug, Clone, Copy)]
struct Block {
    at: usize,
    stride: usize,
}

impl Block {
    fn add(self, data: &mut [f64], m: &[[f64; 3]; 3], sign: f64) {
        for (a, row) in m.iter().enumerate() {
            for (b, v) in row.iter().enumerate() {
                data[self.at + a * self.stride + b] += sign * v;
            }
        }
    }
}

/// A pair `(i, j)` with its four blocks: (i,i), (j,j), (i,j), (j,i).
#[derive(Debug, Clone, Copy)]
struct PairSlots {
    ii: Block,
    jj: Block,
    ij: Block,
    ji: Block,
}

/// Sparse pattern + reusable factorization for one set of vertex pairs on `n` vertices.
pub struct NormalEquations {
    n3: usize,
    mat: CsMat<f64>,
    pairs: Vec<PairSlots>,
    /// Position of each diagonal entry `(k, k)` in the value array.
    diag: Vec<usize>,
    ldl: Option<LdlNumeric<f64, usize>>,
    /// The fill-reducing ordering ([`vertex_order`]); `None` falls back to the natural order.
    perm: Option<Vec<usize>>,
}

impl NormalEquations {
    /// The pattern for `n` vertices and the given pairs (`i != j`, each pair once).
    pub fn new(n: usize, pairs: &[(usize, usize)]) -> Self {
        let mut adj: Vec<Vec<usize>> = (0..n).map(|v| vec![v]).collect();
        for &(i, j) in pairs {
            adj[i].push(j);
            adj[j].push(i);
        }
        for a in &mut adj {
            crate::order::sort_dedup(a);
        }
        let n3 = 3 * n;
        let mut base = Vec::with_capacity(n);
        let (mut indptr, mut indices) = (Vec::with_capacity(n3 + 1), Vec::new());
        indptr.push(0);
        for (v, nb) in adj.iter().enumerate() {
            base.push(indices.len());
            let _ = v;
            for _a in 0..3 {
                for &w in nb {
                    indices.extend([3 * w, 3 * w + 1, 3 * w + 2]);
                }
                indptr.push(indices.len());
            }
        }
        let nnz = indices.len();
        let block = |v: usize, w: usize| -> Block {
            let rank = adj[v].binary_search(&w).expect("pair in pattern");
            Block { at: base[v] + 3 * rank, stride: 3 * adj[v].len() }
        };
        let slots = pairs.iter().map(|&(i, j)| PairSlots { ii: block(i, i), jj: block(j, j), ij: block(j, i), ji: block(i, j) }).collect();
        let diag = (0..n3)
            .map(|k| {
                let b = block(k / 3, k / 3);
                b.at + (k % 3) * b.stride + k % 3
            })
            .collect();
        let mat = CsMat::new_csc((n3, n3), indptr, indices, vec![0.0; nnz]);
        let perm = vertex_order(&adj);
        NormalEquations { n3, mat, pairs: slots, diag, ldl: None, perm }
    }

    /// Solves `(Σ_p w_p u_p u_pᵀ-blocks + λ·μ I) Δ = −g` for pairs `p` (in the order given to
    /// [`NormalEquations::new`]) with 3×3 blocks `m[p] = w u uᵀ`, where μ is the mean diagonal.
    /// `None` when the factorization meets a zero or non-finite pivot.
    pub fn solve(&mut self, blocks: &[[[f64; 3]; 3]], g: &[f64], lambda: f64) -> Option<Vec<f64>> {
        let data = self.mat.data_mut();
        data.iter_mut().for_each(|v| *v = 0.0);
        for (s, m) in self.pairs.iter().zip(blocks) {
            s.ii.add(data, m, 1.0);
            s.jj.add(data, m, 1.0);
            s.ij.add(data, m, -1.0);
            s.ji.add(data, m, -1.0);
        }
        let mu = self.diag.iter().map(|&k| data[k]).sum::<f64>() / self.n3 as f64;
        for &k in &self.diag {
            data[k] += lambda * mu;
        }
        let view = self.mat.view();
        match &mut self.ldl {
            Some(ldl) => ldl.update(view).ok()?,
            None => {
                let perm = match &self.perm {
                    Some(p) => PermOwnedI::new(p.clone()),
                    None => PermOwnedI::identity(self.n3),
                };
                self.ldl = Some(LdlNumeric::new_perm(view, perm, SymmetryCheck::DontCheckSymmetry).ok()?);
            }
        }
        let ldl = self.ldl.as_ref()?;
        if !ldl.d().iter().all(|d| d.is_finite() && *d > 0.0) {
            return None;
        }
        let rhs: Vec<f64> = g.iter().map(|v| -v).collect();
        let d: Vec<f64> = ldl.solve(&rhs);
        d.iter().all(|v| v.is_finite()).then_some(d)
    }
}

/// A fill-reducing ordering of the unknowns: approximate minimum degree (Amestoy, Davis & Duff,
/// SIAM J. Matrix Anal. Appl. 17(4), 1996; the `amd` crate) on the vertex graph, each vertex's
/// three unknowns kept together. The graph is the seam cycle plus the chords of both pieces,
/// two families of nearly parallel chords crossing at the offset's angle. On the D-forms of
/// `bench/simulate.bench.mjs` (256 seam vertices) AMD's factor needs 10–30 % fewer
/// nonzeros and multiplications than sprs-ldl's reverse Cuthill–McKee, and the factorization,
/// ~80 % of a solve, runs about twice as fast at the same iteration counts. `adj[v]`: `v`'s
/// sorted neighbours, `v` included. `None` if AMD refuses the graph or returns anything but a
/// permutation; AMD only refuses malformed input, which `adj` never is, so the natural order
/// used then is a safety net, not a tuned path. (It used to be sprs-ldl's reverse
/// Cuthill–McKee, whose never-run code cost ~12 KB of the .wasm.)
fn vertex_order(adj: &[Vec<usize>]) -> Option<Vec<usize>> {
    let n = adj.len();
    let mut ap = Vec::with_capacity(n + 1);
    let mut ai = Vec::new();
    ap.push(0usize);
    for nb in adj {
        ai.extend_from_slice(nb);
        ap.push(ai.len());
    }
    let (p, _, _) = amd::order(n, &ap, &ai, &amd::Control::default()).ok()?;
    let mut seen = vec![false; n];
    if p.len() != n || !p.iter().all(|&v| v < n && !std::mem::replace(&mut seen[v], true)) {
        return None;
    }
    Some(p.iter().flat_map(|&v| [3 * v, 3 * v + 1, 3 * v + 2]).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pairs of two convex pieces glued at a quarter-turn offset: the seam cycle plus a
    /// zigzag (strip) triangulation of each piece, B's turned by n/4 vertices; each pair once.
    fn crossing_strips(n: usize) -> Vec<(usize, usize)> {
        let mut pairs: Vec<(usize, usize)> = (0..n).map(|i| (i, (i + 1) % n)).collect();
        for shift in [0, n / 4] {
            let (mut a, mut b, mut step_b) = (1, n - 1, true);
            while b - a >= 2 {
                pairs.push(((a + shift) % n, (b + shift) % n));
                if step_b { b -= 1 } else { a += 1 }
                step_b = !step_b;
            }
        }
        let mut pairs: Vec<_> = pairs.into_iter().map(|(i, j)| (i.min(j), i.max(j))).collect();
        crate::order::sort_dedup_pairs(&mut pairs);
        pairs
    }

    /// 3×3 blocks `u uᵀ` of made-up but fixed unit directions, one per pair.
    fn blocks(pairs: &[(usize, usize)]) -> Vec<[[f64; 3]; 3]> {
        pairs
            .iter()
            .map(|&(i, j)| {
                let t = (i * 7 + j * 3) as f64;
                let u = [t.cos() * 0.6, t.sin() * 0.6, 0.8];
                [0, 1, 2].map(|a| [0, 1, 2].map(|b| u[a] * u[b]))
            })
            .collect()
    }

    /// Solves with `ne` twice (the second time through the reused symbolic factorization) and
    /// checks both against the dense matrix assembled independently: residual of `H d = −g`.
    fn check_against_dense(ne: &mut NormalEquations, n: usize, pairs: &[(usize, usize)], what: &str) {
        let blocks = blocks(pairs);
        let n3 = 3 * n;
        let g: Vec<f64> = (0..n3).map(|k| (k as f64 * 0.37).sin()).collect();
        let lambda = 0.3;
        for _ in 0..2 {
            let d = ne.solve(&blocks, &g, lambda).expect("SPD system");
            let mut h = vec![vec![0.0f64; n3]; n3];
            for (&(i, j), m) in pairs.iter().zip(&blocks) {
                for a in 0..3 {
                    for b in 0..3 {
                        h[3 * i + a][3 * i + b] += m[a][b];
                        h[3 * j + a][3 * j + b] += m[a][b];
                        h[3 * i + a][3 * j + b] -= m[a][b];
                        h[3 * j + a][3 * i + b] -= m[a][b];
                    }
                }
            }
            let mu = (0..n3).map(|k| h[k][k]).sum::<f64>() / n3 as f64;
            for (k, row) in h.iter_mut().enumerate() {
                row[k] += lambda * mu;
            }
            for k in 0..n3 {
                let r: f64 = (0..n3).map(|c| h[k][c] * d[c]).sum::<f64>() + g[k];
                assert!(r.abs() < 1e-12, "{what}, row {k}: residual wanted 0, got {r}");
            }
        }
    }

    #[test]
    fn solves_the_same_system_as_a_dense_elimination() {
        let chain = [(0, 1), (1, 2), (0, 2)];
        check_against_dense(&mut NormalEquations::new(3, &chain), 3, &chain, "triangle, AMD");
        let strips = crossing_strips(24);
        let mut ne = NormalEquations::new(24, &strips);
        assert!(ne.perm.is_some(), "AMD gave no ordering for the crossing strips");
        check_against_dense(&mut ne, 24, &strips, "crossing strips, AMD");
        // The fallback ordering (the natural one), used if AMD ever refuses a graph.
        let mut ne = NormalEquations::new(24, &strips);
        ne.perm = None;
        check_against_dense(&mut ne, 24, &strips, "crossing strips, natural order");
    }
}
