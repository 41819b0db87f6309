//! The damped normal equations `(JᵀJ + λ·μ I) Δ = −Jᵀr` of the length equations, assembled
//! into a fixed sparse pattern and solved by a sparse LDLᵀ factorization with 3×3 blocks
//! after an approximate-minimum-degree ordering ([`vertex_order`]).
//!
//! Unknown `3v + a` is coordinate `a` of vertex `v`, and every entry of the matrix lives in a
//! dense, symmetric 3×3 block `(v, w)` for a vertex pair joined by a length equation (or
//! `v = w`). So the factorization works on the *vertex* graph with 3×3 blocks as its scalars:
//! Davis' up-looking LDLᵀ ("Algorithm 849: a concise sparse Cholesky factorization package",
//! ACM TOMS 31(4), 2005) with every `a·b` a 3×3 product and every division by a pivot a
//! product with the inverse of a 3×3 pivot block `D_k`. For row `k` it solves
//! `L_{0:k,0:k} y = A_{0:k,k}` over the row's pattern (the reach of `A`'s column `k` in the
//! elimination tree, Liu 1990), then `L_ki = y_iᵀ D_i⁻¹` and `D_k = A_kk − Σ_i L_ki y_i`. The
//! arithmetic is the scalar algorithm's, grouped by blocks (the same fill, the same flops), but
//! with a ninth of the index work and fixed-size inner loops. It replaced sprs-ldl's scalar LDL,
//! whose numeric factorization was 44 % of a cold solve: the crossed 2:1 ellipses of
//! `core/examples/simulate_bench.rs` (256 seam vertices) went from 25.8 to 15.5 ms native at the
//! same 130 steps and 1,140 flips, to the same volume (3.167794749884306 both), and the .wasm
//! sheds sprs and sprs-ldl.
//!
//! The pattern only depends on which vertex pairs carry a length equation, i.e. on the two
//! triangulations, which change only when chords are flipped. So the ordering, the
//! elimination tree and the column counts are computed once per triangulation
//! ([`NormalEquations::new`]) and every Levenberg–Marquardt step only refills the values and
//! redoes the numeric factorization.
//!
//! The matrix is SPD for `λ > 0` (`JᵀJ` is positive semidefinite), so every pivot block is SPD;
//! a pivot block that is not (round-off on a nearly singular system, a non-finite entry) makes
//! [`NormalEquations::solve`] return `None` and the caller raises λ.

/// A 3×3 block, row-major: `m[a][b]` is entry (row a, column b).
type B3 = [[f64; 3]; 3];

const ZERO: B3 = [[0.0; 3]; 3];

/// `a·b`.
fn mul(a: &B3, b: &B3) -> B3 {
    [0, 1, 2].map(|r| [0, 1, 2].map(|c| a[r][0] * b[0][c] + a[r][1] * b[1][c] + a[r][2] * b[2][c]))
}

/// `aᵀ·b`.
fn mul_tn(a: &B3, b: &B3) -> B3 {
    [0, 1, 2].map(|r| [0, 1, 2].map(|c| a[0][r] * b[0][c] + a[1][r] * b[1][c] + a[2][r] * b[2][c]))
}

/// `m -= d`.
fn sub_assign(m: &mut B3, d: &B3) {
    for r in 0..3 {
        for c in 0..3 {
            m[r][c] -= d[r][c];
        }
    }
}

/// The inverse of a symmetric positive definite 3×3 block by its Cholesky factor, or `None`
/// when a pivot is not positive and finite (the block is not SPD).
fn spd_inverse(m: &B3) -> Option<B3> {
    // m = R Rᵀ with R lower triangular.
    let r00 = m[0][0];
    if !(r00 > 0.0 && r00.is_finite()) {
        return None;
    }
    let r00 = r00.sqrt();
    let r10 = m[1][0] / r00;
    let r20 = m[2][0] / r00;
    let d1 = m[1][1] - r10 * r10;
    if !(d1 > 0.0 && d1.is_finite()) {
        return None;
    }
    let r11 = d1.sqrt();
    let r21 = (m[2][1] - r20 * r10) / r11;
    let d2 = m[2][2] - r20 * r20 - r21 * r21;
    if !(d2 > 0.0 && d2.is_finite()) {
        return None;
    }
    let r22 = d2.sqrt();
    // S = R⁻¹ (lower triangular), m⁻¹ = Sᵀ S.
    let s00 = 1.0 / r00;
    let s11 = 1.0 / r11;
    let s22 = 1.0 / r22;
    let s10 = -r10 * s00 / r11;
    let s21 = -r21 * s11 / r22;
    let s20 = -(r20 * s00 + r21 * s10) / r22;
    let s = [[s00, 0.0, 0.0], [s10, s11, 0.0], [s20, s21, s22]];
    let inv = mul_tn(&s, &s);
    inv.iter().flatten().all(|v| v.is_finite()).then_some(inv)
}

/// No parent in the elimination tree.
const NONE: usize = usize::MAX;

/// Sparse pattern + reusable symbolic factorization for one set of vertex pairs on `n`
/// vertices, in the AMD order: vertex `v` is block row/column `pos[v]`.
pub struct NormalEquations {
    n: usize,
    /// `order[k]`: the vertex eliminated `k`-th; `pos` its inverse.
    order: Vec<usize>,
    pos: Vec<usize>,
    /// The strictly upper part of the (permuted) matrix by columns: column `k` holds rows
    /// `rows[colp[k]..colp[k + 1]]` (all `< k`), values in `off`.
    colp: Vec<usize>,
    rows: Vec<usize>,
    off: Vec<B3>,
    /// Diagonal blocks, by permuted index.
    diag: Vec<B3>,
    /// For each pair given to [`NormalEquations::new`]: its two permuted vertices and the
    /// index of its block in `off`.
    pairs: Vec<(usize, usize, usize)>,
    /// Elimination tree and the factor's column structure: column `i` of `L` holds rows
    /// `li[lp[i]..lp[i + 1]]` (filled in row order during the factorization).
    parent: Vec<usize>,
    lp: Vec<usize>,
    li: Vec<usize>,
    lx: Vec<B3>,
    /// Inverses of the pivot blocks `D_k`.
    dinv: Vec<B3>,
    /// Work arrays of the factorization.
    y: Vec<B3>,
    flag: Vec<usize>,
    stack: Vec<usize>,
    lnz: Vec<usize>,
    /// Whether the last factorization succeeded (then `solve` may reuse it).
    factored: bool,
}

impl NormalEquations {
    /// The pattern for `n` vertices and the given pairs (`i != j`, each pair once): the
    /// ordering ([`vertex_order`]), the elimination tree and the factor's column counts.
    pub fn new(n: usize, pairs: &[(usize, usize)]) -> Self {
        let adj = Adjacency::new(n, pairs);
        let order = vertex_order(&adj).unwrap_or_else(|| (0..n).collect());
        Self::with_order(n, pairs, &adj, order)
    }

    /// [`NormalEquations::new`] for new pairs on the same vertices, keeping this pattern's
    /// ordering instead of running AMD again. A flip pass changes a few chords of the ~3n pairs,
    /// so the old ordering stays a good one (any ordering is exact; only fill depends on it), and
    /// AMD was ~10 % of a cold solve when every flip pass rebuilt the pattern from scratch.
    pub fn reordered_like(&self, pairs: &[(usize, usize)]) -> Self {
        Self::with_order(self.n, pairs, &Adjacency::new(self.n, pairs), self.order.clone())
    }

    /// [`NormalEquations::new`] in the natural order (the fallback when AMD refuses a graph).
    #[cfg(test)]
    fn natural(n: usize, pairs: &[(usize, usize)]) -> Self {
        Self::with_order(n, pairs, &Adjacency::new(n, pairs), (0..n).collect())
    }

    fn with_order(n: usize, pairs: &[(usize, usize)], adj: &Adjacency, order: Vec<usize>) -> Self {
        let mut pos = vec![0; n];
        for (k, &v) in order.iter().enumerate() {
            pos[v] = k;
        }
        // Column k of the strict upper part: the permuted neighbours of order[k] before k.
        let mut colp = Vec::with_capacity(n + 1);
        let mut rows = Vec::with_capacity(pairs.len());
        colp.push(0);
        for &v in &order {
            let k = pos[v];
            let start = rows.len();
            rows.extend(adj.row(v).iter().map(|&w| pos[w]).filter(|&i| i < k));
            sort_short(&mut rows[start..]);
            colp.push(rows.len());
        }
        let slot = |i: usize, k: usize| colp[k] + rows[colp[k]..colp[k + 1]].binary_search(&i).expect("pair in pattern");
        let pairs = pairs
            .iter()
            .map(|&(a, b)| {
                let (i, j) = (pos[a], pos[b]);
                (i, j, slot(i.min(j), i.max(j)))
            })
            .collect();
        // Elimination tree and column counts of L (the symbolic pass of Davis' LDL).
        let (mut parent, mut lnz, mut flag) = (vec![NONE; n], vec![0usize; n], vec![NONE; n]);
        for k in 0..n {
            flag[k] = k;
            for &r in &rows[colp[k]..colp[k + 1]] {
                let mut i = r;
                while flag[i] != k {
                    if parent[i] == NONE {
                        parent[i] = k;
                    }
                    lnz[i] += 1;
                    flag[i] = k;
                    i = parent[i];
                }
            }
        }
        let mut lp = Vec::with_capacity(n + 1);
        lp.push(0);
        for k in 0..n {
            lp.push(lp[k] + lnz[k]);
        }
        let nnz = lp[n];
        let off = vec![ZERO; rows.len()];
        NormalEquations {
            n,
            order,
            pos,
            colp,
            rows,
            off,
            diag: vec![ZERO; n],
            pairs,
            parent,
            lp,
            li: vec![0; nnz],
            lx: vec![ZERO; nnz],
            dinv: vec![ZERO; n],
            y: vec![ZERO; n],
            flag,
            stack: vec![0; n],
            lnz,
            factored: false,
        }
    }

    /// Solves `(Σ_p w_p u_p u_pᵀ-blocks + λ·μ I) Δ = −g` for pairs `p` (in the order given to
    /// [`NormalEquations::new`]) with 3×3 blocks `m[p] = w u uᵀ`, where μ is the mean diagonal.
    /// `None` when the factorization meets a pivot block that is not positive definite or a
    /// non-finite value.
    pub fn solve(&mut self, blocks: &[[[f64; 3]; 3]], g: &[f64], lambda: f64) -> Option<Vec<f64>> {
        self.assemble(blocks, lambda);
        self.factored = self.factor();
        if !self.factored {
            return None;
        }
        let d = self.substitute(g);
        d.iter().all(|v| v.is_finite()).then_some(d)
    }

    /// `−M⁻¹ g` with the matrix of the last successful [`NormalEquations::solve_blocks`] or
    /// [`NormalEquations::solve`] (a modified Newton step: new gradient, old factor); `None`
    /// when there is no factorization to reuse.
    pub fn resolve(&self, g: &[f64]) -> Option<Vec<f64>> {
        if !self.factored {
            return None;
        }
        let d = self.substitute(g);
        d.iter().all(|v| v.is_finite()).then_some(d)
    }

    /// Solves `(M + λ·μ I) Δ = −g` for a matrix given by its blocks: `diag[v]` the diagonal
    /// block of vertex `v`, `off[p]` the block (rows of `a`, columns of `b`) of pair `p = (a, b)`
    /// in the order given to [`NormalEquations::new`]. This is the general form of
    /// [`NormalEquations::solve`] for residuals of more than two vertices (a hinge's dihedral
    /// angle has four), whose `JᵀJ` blocks are not `±w u uᵀ`.
    pub fn solve_blocks(&mut self, diag: &[B3], off: &[B3], g: &[f64], lambda: f64) -> Option<Vec<f64>> {
        for (v, d) in diag.iter().enumerate() {
            self.diag[self.pos[v]] = *d;
        }
        self.off.iter_mut().for_each(|b| *b = ZERO);
        for (&(i, j, s), m) in self.pairs.iter().zip(off) {
            // The stored block is (row min, column max) of the permuted pair.
            let m = if i < j { *m } else { [0, 1, 2].map(|r| [0, 1, 2].map(|c| m[c][r])) };
            for r in 0..3 {
                for c in 0..3 {
                    self.off[s][r][c] += m[r][c];
                }
            }
        }
        self.damp(lambda);
        self.factored = self.factor();
        if !self.factored {
            return None;
        }
        let d = self.substitute(g);
        d.iter().all(|v| v.is_finite()).then_some(d)
    }

    /// The matrix's values: `m` on both diagonal blocks of its pair, `−m` off the diagonal,
    /// then `λ·μ` on the diagonal (μ the mean of the diagonal entries).
    fn assemble(&mut self, blocks: &[B3], lambda: f64) {
        self.diag.iter_mut().for_each(|b| *b = ZERO);
        self.off.iter_mut().for_each(|b| *b = ZERO);
        for (&(i, j, s), m) in self.pairs.iter().zip(blocks) {
            for r in 0..3 {
                for c in 0..3 {
                    self.diag[i][r][c] += m[r][c];
                    self.diag[j][r][c] += m[r][c];
                    // m is symmetric, so the block (i, j) and its transpose (j, i) are both −m.
                    self.off[s][r][c] -= m[r][c];
                }
            }
        }
        self.damp(lambda);
    }

    /// Adds `λ·μ` to the diagonal, μ the mean of the diagonal entries.
    fn damp(&mut self, lambda: f64) {
        let mu = self.diag.iter().map(|b| b[0][0] + b[1][1] + b[2][2]).sum::<f64>() / (3 * self.n).max(1) as f64;
        for b in &mut self.diag {
            for a in 0..3 {
                b[a][a] += lambda * mu;
            }
        }
    }

    /// The numeric block LDLᵀ (see the module docs); false on a pivot block that is not SPD.
    fn factor(&mut self) -> bool {
        let n = self.n;
        let Self { colp, rows, off, diag, parent, lp, li, lx, dinv, y, flag, stack, lnz, .. } = self;
        for k in 0..n {
            // The pattern of row k of L: the reach of column k's rows in the elimination tree,
            // in topological order (the stack's top is eliminated first).
            let mut top = n;
            flag[k] = k;
            lnz[k] = 0;
            for p in colp[k]..colp[k + 1] {
                let mut i = rows[p];
                y[i] = off[p];
                let mut len = 0;
                while flag[i] != k {
                    stack[len] = i;
                    len += 1;
                    flag[i] = k;
                    i = parent[i];
                }
                while len > 0 {
                    top -= 1;
                    len -= 1;
                    stack[top] = stack[len];
                }
            }
            let mut dk = diag[k];
            for &i in &stack[top..n] {
                let yi = std::mem::replace(&mut y[i], ZERO);
                for p in lp[i]..lp[i] + lnz[i] {
                    let d = mul(&lx[p], &yi);
                    sub_assign(&mut y[li[p]], &d);
                }
                let lki = mul_tn(&yi, &dinv[i]);
                sub_assign(&mut dk, &mul(&lki, &yi));
                let p = lp[i] + lnz[i];
                li[p] = k;
                lx[p] = lki;
                lnz[i] += 1;
            }
            // D_k is symmetric up to round-off; its lower triangle is what the inverse reads.
            match spd_inverse(&dk) {
                Some(inv) => dinv[k] = inv,
                None => return false,
            }
        }
        true
    }

    /// `−(L D Lᵀ)⁻¹ g` in the vertex numbering of the caller.
    fn substitute(&self, g: &[f64]) -> Vec<f64> {
        let n = self.n;
        let mut z: Vec<[f64; 3]> = self.order.iter().map(|&v| [-g[3 * v], -g[3 * v + 1], -g[3 * v + 2]]).collect();
        let apply = |m: &B3, v: &[f64; 3]| [0, 1, 2].map(|r| m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2]);
        // L z' = z (unit block lower triangular, by columns).
        for i in 0..n {
            let zi = z[i];
            for p in self.lp[i]..self.lp[i + 1] {
                let d = apply(&self.lx[p], &zi);
                let r = &mut z[self.li[p]];
                for a in 0..3 {
                    r[a] -= d[a];
                }
            }
        }
        for (zi, dinv) in z.iter_mut().zip(&self.dinv) {
            *zi = apply(dinv, zi);
        }
        // Lᵀ z'' = z'.
        for i in (0..n).rev() {
            let mut zi = z[i];
            for p in self.lp[i]..self.lp[i + 1] {
                let (m, r) = (&self.lx[p], z[self.li[p]]);
                for a in 0..3 {
                    zi[a] -= m[0][a] * r[0] + m[1][a] * r[1] + m[2][a] * r[2];
                }
            }
            z[i] = zi;
        }
        let mut out = vec![0.0; 3 * n];
        for (v, &k) in self.pos.iter().enumerate() {
            out[3 * v..3 * v + 3].copy_from_slice(&z[k]);
        }
        out
    }
}

/// Sorts a short slice in place (insertion sort): the rows here hold a vertex's few neighbours,
/// and a std sort of `usize` would be one more instantiation in the .wasm (see [`crate::order`]).
fn sort_short(v: &mut [usize]) {
    for k in 1..v.len() {
        let x = v[k];
        let mut m = k;
        while m > 0 && v[m - 1] > x {
            v[m] = v[m - 1];
            m -= 1;
        }
        v[m] = x;
    }
}

/// The vertex graph in compressed rows: row `v` is `ai[ap[v]..ap[v + 1]]`, `v`'s sorted
/// neighbours, itself included (a pair given twice, a chord in both pieces, counts once).
struct Adjacency {
    ap: Vec<usize>,
    ai: Vec<usize>,
}

impl Adjacency {
    fn new(n: usize, pairs: &[(usize, usize)]) -> Self {
        let mut start = vec![0usize; n + 1];
        for &(i, j) in pairs {
            start[i + 1] += 1;
            start[j + 1] += 1;
        }
        for v in 0..n {
            start[v + 1] += start[v] + 1;
        }
        let mut fill: Vec<usize> = start[..n].to_vec();
        let mut ai = vec![0usize; start[n]];
        let mut put = |v: usize, w: usize, fill: &mut Vec<usize>| {
            ai[fill[v]] = w;
            fill[v] += 1;
        };
        for v in 0..n {
            put(v, v, &mut fill);
        }
        for &(i, j) in pairs {
            put(i, j, &mut fill);
            put(j, i, &mut fill);
        }
        // Sort each row and drop repeats, compacting in place.
        let mut ap = Vec::with_capacity(n + 1);
        ap.push(0);
        let mut out = 0;
        for v in 0..n {
            sort_short(&mut ai[start[v]..start[v + 1]]);
            for k in start[v]..start[v + 1] {
                if k == start[v] || ai[k] != ai[k - 1] {
                    ai[out] = ai[k];
                    out += 1;
                }
            }
            ap.push(out);
        }
        ai.truncate(out);
        Adjacency { ap, ai }
    }

    fn row(&self, v: usize) -> &[usize] {
        &self.ai[self.ap[v]..self.ap[v + 1]]
    }
}

/// A fill-reducing ordering of the vertices: approximate minimum degree (Amestoy, Davis & Duff,
/// SIAM J. Matrix Anal. Appl. 17(4), 1996; the `amd` crate) on the vertex graph (each vertex's
/// three unknowns are one block, so they stay together). The graph is the seam cycle plus the
/// chords of both pieces, two families of nearly parallel chords crossing at the offset's angle.
/// On the D-forms of `bench/simulate.bench.mjs` (256 seam vertices) AMD's factor needed 10–30 %
/// fewer nonzeros and multiplications than reverse Cuthill–McKee, and the factorization ran
/// about twice as fast at the same iteration counts. `adj`: each vertex's sorted neighbours, itself
/// included; `order[k]` is the vertex eliminated `k`-th. `None` if AMD refuses the graph or
/// returns anything but a permutation; AMD only refuses malformed input, which `adj` never is,
/// so the natural order used then is a safety net, not a tuned path.
fn vertex_order(adj: &Adjacency) -> Option<Vec<usize>> {
    let n = adj.ap.len() - 1;
    let (ap, ai) = (&adj.ap, &adj.ai);
    let (p, _, _) = amd::order(n, ap, ai, &amd::Control::default()).ok()?;
    let mut seen = vec![false; n];
    if p.len() != n || !p.iter().all(|&v| v < n && !std::mem::replace(&mut seen[v], true)) {
        return None;
    }
    Some(p)
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
        assert!(vertex_order(&Adjacency::new(24, &strips)).is_some(), "AMD gave no ordering for the crossing strips");
        check_against_dense(&mut ne, 24, &strips, "crossing strips, AMD");
        // The fallback ordering (the natural one), used if AMD ever refuses a graph.
        let mut ne = NormalEquations::natural(24, &strips);
        check_against_dense(&mut ne, 24, &strips, "crossing strips, natural order");
    }
    /// The general block form against a dense `JᵀJ + λμI` of made-up four-vertex residual rows
    /// (a hinge's support), pairs given in both orientations.
    #[test]
    fn solve_blocks_matches_a_dense_elimination() {
        let n = 10;
        let rows: Vec<([usize; 4], [[f64; 3]; 4])> = (0..14)
            .map(|r| {
                let v = [r % n, (r + 1) % n, (r + 3) % n, (r + 6) % n];
                let g = [0, 1, 2, 3].map(|k| [0, 1, 2].map(|a| ((r * 13 + k * 5 + a * 7) as f64 * 0.71).sin()));
                (v, g)
            })
            .collect();
        let mut pairs: Vec<(usize, usize)> = Vec::new();
        for (v, _) in &rows {
            for a in 0..4 {
                for b in a + 1..4 {
                    let (p, q) = (v[a], v[b]);
                    if !pairs.contains(&(p, q)) && !pairs.contains(&(q, p)) {
                        pairs.push((p, q));
                    }
                }
            }
        }
        let n3 = 3 * n;
        let mut h = vec![vec![0.0f64; n3]; n3];
        let mut diag = vec![ZERO; n];
        let mut off = vec![ZERO; pairs.len()];
        for (v, g) in &rows {
            for a in 0..4 {
                for b in 0..4 {
                    for r in 0..3 {
                        for c in 0..3 {
                            h[3 * v[a] + r][3 * v[b] + c] += g[a][r] * g[b][c];
                        }
                    }
                }
            }
            for a in 0..4 {
                for r in 0..3 {
                    for c in 0..3 {
                        diag[v[a]][r][c] += g[a][r] * g[a][c];
                    }
                }
                for b in 0..4 {
                    if let Some(s) = pairs.iter().position(|&p| p == (v[a], v[b])) {
                        for r in 0..3 {
                            for c in 0..3 {
                                off[s][r][c] += g[a][r] * g[b][c];
                            }
                        }
                    }
                }
            }
        }
        let lambda = 0.2;
        let mu = (0..n3).map(|k| h[k][k]).sum::<f64>() / n3 as f64;
        for (k, row) in h.iter_mut().enumerate() {
            row[k] += lambda * mu;
        }
        let g: Vec<f64> = (0..n3).map(|k| (k as f64 * 0.37).cos()).collect();
        let mut ne = NormalEquations::new(n, &pairs);
        let d = ne.solve_blocks(&diag, &off, &g, lambda).expect("SPD system");
        for k in 0..n3 {
            let r: f64 = (0..n3).map(|c| h[k][c] * d[c]).sum::<f64>() + g[k];
            assert!(r.abs() < 1e-10, "row {k}: residual wanted 0, got {r}");
        }
    }
}
