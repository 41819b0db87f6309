//! A discrete elastic shell: membrane and bending energies of a triangle mesh whose rest shape is
//! flat, minimized by Levenberg–Marquardt.
//!
//! Energy (Grinspun, Hirani, Desbrun & Schröder, "Discrete shells", SCA 2003), as a sum of
//! squared residuals so that Gauss–Newton applies:
//!
//! * membrane, one residual per edge and piece: `r = |x_i − x_j| − L` (`L` the edge's flat
//!   length in that piece), i.e. `L²·ε²` for the strain ε — a seam edge has one residual per
//!   piece, with its own flat length in each;
//! * bending, one residual per interior edge of a piece: `r = √(kb · 3L²/(A₁ + A₂)) · θ`, with θ
//!   the hinge's dihedral angle ([`super::hinge`]), `A₁, A₂` the flat areas of its triangles.
//!   The rest angle is 0 (the pieces are cut flat); the seam has no bending term (it is a free
//!   hinge: the two pieces meet there at whatever angle the equilibrium gives);
//! * contact, when set ([`super::contact`]): one residual per vertex closer to a face than the
//!   gap, or on the wrong side of it.
//!
//! Both terms scale like an area, so `kb` is a squared length, independent of the mesh: the
//! bending of a curvature κ costs about `kb·κ²` per unit area against `ε²` for a strain ε, so
//! `√kb` plays the sheet's thickness (up to a constant). Lowering `kb` from a thick to a thin
//! sheet is the continuation towards zero stretch of Surface Evolver's elastic-sheet runs.
//!
//! Each Gauss–Newton step solves `(JᵀJ + λ·μ I) Δ = −Jᵀr` with the block LDLᵀ of
//! [`crate::simulate::normal`]; its pattern holds the mesh edges and the two tips of every
//! hinge (the only pair of a hinge's four vertices that is not an edge). A thin sheet can
//! leave the tips out ([`Shell::set_tip_blocks`]): the matrix is then a sparser majorant of
//! `JᵀJ`, with the same gradient, hence the same equilibria.
//!
//! *Gauss–Newton, not Newton (stop 52).* `JᵀJ` leaves out the hinges' `θ·∇²θ`, which is not
//! small where the sheet bends by tens of degrees. But that is not what makes a stage take its
//! 20–60 steps: through the thin stages λ sits at its floor (1e-12) and each fresh step lowers
//! the energy by 1–2 %, the sheet moving a long way along its soft modes. With `θ·∇²θ` added
//! (by differences of the analytic gradient, the tips kept at every stage) the kidney with its
//! mirror image, 256 seam vertices, took 818, 597, 847 and 554 iterations at 1, 3, 9 and 12/16
//! of its perimeter against 900, 639, 592 and 539, and ended creased at 6/16 where it
//! converges. Extrapolating each accepted full step (×2, ×4 while the energy falls) did not help
//! either: 0.87, 1.76 and 2.52 s at 1, 6 and 15/16 against 0.93, 1.41 and 1.94 s native, with
//! the volumes moved by 0.1–0.4 %.

use crate::libm_ext::LibmExt;
use super::hinge::angle_and_gradient;
use crate::simulate::normal::NormalEquations;
use crate::simulate::vec3::{norm, sub, V3};
use crate::order::pair_key;
use crate::simulate::metric::KeyMap;

type B3 = [[f64; 3]; 3];

/// One membrane term: vertices and flat length.
#[derive(Debug, Clone, Copy)]
pub struct Edge {
    pub i: usize,
    pub j: usize,
    pub rest: f64,
    /// The piece whose flat length `rest` is.
    pub piece: u8,
}

/// One bending term: hinge `(i, j, k, l)` (edge i→j, tips k and l) and its weight `3L²/(A₁+A₂)`.
#[derive(Debug, Clone, Copy)]
pub struct Hinge {
    pub v: [usize; 4],
    pub weight: f64,
}

/// The shell's terms and the reusable sparse pattern of its normal equations.
pub struct Shell {
    pub n: usize,
    pub edges: Vec<Edge>,
    pub hinges: Vec<Hinge>,
    ne: NormalEquations,
    /// The pattern's pairs, and for each term the pair slots of its vertex pairs
    /// ([`TIPS_LEFT_OUT`] for a hinge's tips when the pattern has none).
    pairs: Vec<(usize, usize)>,
    edge_slot: Vec<usize>,
    hinge_slots: Vec<[usize; 6]>,
    tips: bool,
    /// Self-contact ([`super::contact`]), off unless set.
    pub contact: Option<super::contact::Contact>,
}

/// The pairs of a hinge's four vertices, in the order of [`Shell::hinge_slots`]; the last one
/// is its two tips, the pair that is no mesh edge.
const HINGE_PAIRS: [(usize, usize); 6] = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];

/// The slot of a hinge's tip pair in a pattern without tip blocks.
const TIPS_LEFT_OUT: usize = usize::MAX;

/// The thinning's bending weights (`kb/R²`, see [`super::SCHEDULE`]) at and below which its
/// normal equations leave the hinges' tip blocks out ([`Shell::set_tip_blocks`]).
///
/// Without them the pattern is the mesh's edges, a planar graph: at 256 seam vertices the
/// factor of the drawn heart with a circle holds 20,431 blocks instead of 48,502 and takes
/// 311,564 block updates instead of 1,556,849 (the rounded star's: 256,957 against
/// 1,210,255). The majorant is a cruder model of the energy, so a stage takes more steps and
/// factorizations (1.1–2 times), but each fresh one costs about a fifth: the thinning's
/// stages at and below 1e-7 are where a thin sheet spends most of its steps.
///
/// The thicker stages keep the tips, because there the path still chooses its equilibrium,
/// and the cruder model chose others. Dropped from the homotopy's thick sheet
/// ([`super::HOMOTOPY_KB`]) on, the rounded star's first homotopy step went from 13 % to 166 %
/// strain. Dropped from 1e-5, the bench's kidney with a circle (WASM) ended folded by 98.5°
/// instead of converged at 73°. From 1e-6, the kidney with a 2:1 ellipse at 128 seam
/// vertices ended strained by 1.4e-3 instead of converged, and the blob with a circle was
/// 1.08 % apart at 128 and 256. From 1e-7, every pair of the tests and the bench ends in the
/// same equilibrium (volumes within 0.13 %, the same sharpest bends).
pub const TIPLESS_KB: f64 = 1e-7;

/// Accepted steps on one factorization.
pub const REUSE: usize = 4;

/// Halvings of a freshly factored step that raised the energy, tried before the step is
/// thrown away and refactored with more damping (a backtracking line search along the
/// Levenberg–Marquardt direction, Nocedal & Wright §3.1). Raising λ costs a new factorization,
/// most of a step's time; trying `d/2, d/4, d/8` costs three energy evaluations. At 256 seam
/// vertices the sheet paths' fresh factorizations fell by up to 55 % (each with a circle:
/// Pebble 45 → 45, five lobes 90 → 79, kidney 112 → 87, rounded star 226 → 110, L 164 → 73),
/// to the same equilibria (volumes within 0.3 %). One halving saved as much on all but the
/// star and the five lobes; six no more than three.
pub const HALVINGS: usize = 3;

impl Shell {
    pub fn new(n: usize, edges: Vec<Edge>, hinges: Vec<Hinge>) -> Self {
        let (pairs, edge_slot, hinge_slots) = pattern(&edges, &hinges, true);
        let ne = NormalEquations::new(n, &pairs);
        Shell { n, edges, hinges, ne, pairs, edge_slot, hinge_slots, tips: true, contact: None }
    }

    /// Whether the normal equations hold each hinge's tip block (they do from
    /// [`Shell::new`]). Left out, each hinge's tip pair `(k, l)` with gradient rows `g_k`,
    /// `g_l` gets the matrix `JᵀJ + Σ [g_k; −g_l][g_k; −g_l]ᵀ` instead of `JᵀJ`: the added term
    /// cancels the block `g_k g_lᵀ` and adds `g_k g_kᵀ`, `g_l g_lᵀ` to the two diagonal blocks
    /// (diagonal compensation of a dropped entry, as in Gustafsson's modified incomplete
    /// factorization, BIT 18, 1978), so the matrix stays positive semidefinite and above
    /// `JᵀJ`: each step is still a descent direction of the same energy, only shorter along
    /// the bending's modes, and the equilibria are the same. A change rebuilds the pattern
    /// and its ordering. See [`TIPLESS_KB`].
    pub fn set_tip_blocks(&mut self, tips: bool) {
        if tips == self.tips {
            return;
        }
        let (pairs, edge_slot, hinge_slots) = pattern(&self.edges, &self.hinges, tips);
        self.ne = NormalEquations::new(self.n, &pairs);
        (self.pairs, self.edge_slot, self.hinge_slots, self.tips) = (pairs, edge_slot, hinge_slots, tips);
    }

    /// Sets every edge's rest length to the blend `(1 − t)·L⁰ + t·L¹` of its lengths in the flat
    /// positions `from` and `to`: a homotopy of the metric that never needs an intermediate flat
    /// layout (a blend of two layouts can fold over where the two differ much).
    pub fn set_rest_blend(&mut self, from: &[Vec<[f64; 2]>; 2], to: &[Vec<[f64; 2]>; 2], t: f64) {
        for e in &mut self.edges {
            let len = |f: &[Vec<[f64; 2]>; 2]| {
                let f = &f[e.piece as usize];
                (f[e.i][0] - f[e.j][0]).hypot_m(f[e.i][1] - f[e.j][1])
            };
            e.rest = (1.0 - t) * len(from) + t * len(to);
        }
    }

    /// The energy at `x` for bending weight `kb`.
    pub fn cost(&self, x: &[V3], kb: f64) -> f64 {
        let m: f64 = self.edges.iter().map(|e| (norm(sub(x[e.j], x[e.i])) - e.rest).powi(2)).sum::<f64>() + self.contact.as_ref().map_or(0.0, |c| c.cost(x));
        if kb == 0.0 {
            return m;
        }
        let b: f64 = self
            .hinges
            .iter()
            .map(|h| {
                let t = super::hinge::angle(x[h.v[0]], x[h.v[1]], x[h.v[2]], x[h.v[3]]);
                kb * h.weight * t * t
            })
            .sum();
        m + b
    }

    /// Largest relative strain `| |x_i − x_j| / L − 1 |` over the membrane terms.
    pub fn max_strain(&self, x: &[V3]) -> f64 {
        self.edges.iter().map(|e| (norm(sub(x[e.j], x[e.i])) / e.rest - 1.0).abs()).fold(0.0, f64::max)
    }

    /// The least [`Shell::max_strain`] of any shape: an edge with two membrane terms (a seam
    /// edge, one flat length per piece, `L₁ < L₂`) is strained by at least
    /// `(L₂ − L₁)/(L₁ + L₂)` against one of them, whatever its length (the least is at the
    /// harmonic mean `2L₁L₂/(L₁ + L₂)`). The seam samples' floor ([`crate::simulate::density`]).
    pub fn strain_floor(&self) -> f64 {
        let mut first = KeyMap::default();
        let mut floor: f64 = 0.0;
        for (k, e) in self.edges.iter().enumerate() {
            let key = pair_key(e.i.min(e.j), e.i.max(e.j));
            match first.get(&key) {
                Some(&m) => {
                    let (a, b) = (self.edges[m].rest, e.rest);
                    floor = floor.max((a - b).abs() / (a + b));
                }
                None => {
                    first.insert(key, k);
                }
            }
        }
        floor
    }

    /// `Jᵀr` at `x`, and `JᵀJ`'s diagonal and pair blocks when `blocks` is given.
    fn assemble(&self, x: &[V3], kb: f64, mut blocks: Option<(&mut [B3], &mut [B3])>) -> Vec<f64> {
        let mut g = vec![0.0; 3 * self.n];
        let pairs = &self.pairs;
        let mut add = |vs: &[usize], rows: &[V3], slots: &[usize], pair_of: &[(usize, usize)], r: f64| {
            for (&v, row) in vs.iter().zip(rows) {
                for a in 0..3 {
                    g[3 * v + a] += row[a] * r;
                }
            }
            let Some((diag, off)) = blocks.as_mut() else { return };
            for (&v, row) in vs.iter().zip(rows) {
                for a in 0..3 {
                    for c in 0..3 {
                        diag[v][a][c] += row[a] * row[c];
                    }
                }
            }
            for (&s, &(p, q)) in slots.iter().zip(pair_of) {
                if s == TIPS_LEFT_OUT {
                    // Diagonal compensation of the left-out block (see `set_tip_blocks`).
                    for w in [p, q] {
                        for a in 0..3 {
                            for c in 0..3 {
                                diag[vs[w]][a][c] += rows[w][a] * rows[w][c];
                            }
                        }
                    }
                    continue;
                }
                // The stored pair is (min, max), its block has the rows of its first vertex.
                let (ra, rb) = if pairs[s].0 == vs[p] { (rows[p], rows[q]) } else { (rows[q], rows[p]) };
                for a in 0..3 {
                    for c in 0..3 {
                        off[s][a][c] += ra[a] * rb[c];
                    }
                }
            }
        };
        for (e, &s) in self.edges.iter().zip(&self.edge_slot) {
            let d = sub(x[e.j], x[e.i]);
            let l = norm(d);
            let u = if l > 0.0 { d.map(|v| v / l) } else { [1.0, 0.0, 0.0] };
            add(&[e.i, e.j], &[u.map(|v| -v), u], &[s], &[(0, 1)], l - e.rest);
        }
        if kb > 0.0 {
            for (h, slots) in self.hinges.iter().zip(&self.hinge_slots) {
                let [i, j, k, l] = h.v;
                let Some((theta, grad)) = angle_and_gradient(x[i], x[j], x[k], x[l]) else { continue };
                let w = (kb * h.weight).sqrt();
                add(&h.v, &grad.map(|row| row.map(|v| w * v)), slots, &HINGE_PAIRS, w * theta);
            }
        }
        if let Some(c) = &self.contact {
            for t in c.terms(x) {
                for (&v, row) in t.v.iter().zip(&t.rows) {
                    for a in 0..3 {
                        g[3 * v + a] += row[a] * t.r;
                    }
                }
                if let Some((diag, _)) = blocks.as_mut() {
                    // A majorant of the term's JᵀJ on the diagonal blocks (pattern unchanged).
                    for ((&v, row), m) in t.v.iter().zip(&t.rows).zip(t.major) {
                        for a in 0..3 {
                            for c in 0..3 {
                                diag[v][a][c] += m * row[a] * row[c];
                            }
                        }
                    }
                }
            }
        }
        g
    }

    /// A damped Gauss–Newton step `−(JᵀJ + λμI)⁻¹ Jᵀr`, freshly factored or (`reuse`) with the
    /// last factorization and the new gradient; `None` if the factorization fails.
    fn step(&mut self, x: &[V3], kb: f64, lambda: f64, reuse: bool) -> Option<Vec<f64>> {
        if reuse {
            let g = self.assemble(x, kb, None);
            return self.ne.resolve(&g);
        }
        let mut diag = vec![[[0.0; 3]; 3]; self.n];
        let mut off = vec![[[0.0; 3]; 3]; self.pairs.len()];
        let g = self.assemble(x, kb, Some((&mut diag, &mut off)));
        self.ne.solve_blocks(&diag, &off, &g, lambda)
    }

    /// Minimizes the energy for bending weight `kb` from `x` by Levenberg–Marquardt (Nocedal &
    /// Wright, "Numerical Optimization", §10.3), at most `budget` steps. A factorization is
    /// reused for up to [`REUSE`] accepted steps (the matrix changes slowly near an
    /// equilibrium, and a back-substitution costs a small fraction of a factorization); a step
    /// that fails on an old factor is retried on a fresh one, and one that fails on a fresh
    /// factor is shortened ([`HALVINGS`]) before λ is raised. Ends when a
    /// freshly factored, lightly damped step lowers the energy by less than `rtol` of it.
    /// `lambda` carries the damping from one call to the next. Returns the steps taken.
    pub fn minimize(&mut self, x: &mut [V3], kb: f64, budget: usize, rtol: f64, lambda: &mut f64) -> usize {
        let mut cost = self.cost(x, kb);
        let (mut steps, mut age) = (0, usize::MAX);
        while steps < budget {
            steps += 1;
            let reuse = age < REUSE;
            if !reuse {
                if let Some(c) = &mut self.contact {
                    c.refresh(x);
                    cost = self.cost(x, kb);
                }
            }
            let Some(d) = self.step(x, kb, *lambda, reuse) else {
                if reuse {
                    age = usize::MAX;
                    continue;
                }
                *lambda *= 10.0;
                if *lambda > 1e12 {
                    break;
                }
                continue;
            };
            let along = |alpha: f64| -> Vec<V3> { x.iter().enumerate().map(|(v, p)| [0, 1, 2].map(|a| p[a] + alpha * d[3 * v + a])).collect() };
            let mut trial = along(1.0);
            let mut c = self.cost(&trial, kb);
            // On a fresh factor, a step that overshoots is shortened before λ is raised.
            let mut shortened = false;
            let mut alpha = 1.0;
            for _ in 0..if reuse { 0 } else { HALVINGS } {
                if c.is_finite() && c < cost {
                    break;
                }
                alpha *= 0.5;
                trial = along(alpha);
                c = self.cost(&trial, kb);
                shortened = true;
            }
            if c.is_finite() && c < cost {
                let drop = cost - c;
                x.copy_from_slice(&trial);
                cost = c;
                // A small drop under heavy damping, or on an old factor, is a short step, not an
                // equilibrium. (One along a shortened step may end it: requiring a full step
                // there took the five lobes' last stage from 11 to 60 fresh factorizations, GN's
                // model overshooting near the equilibrium where the hinges' residuals are not 0,
                // for a volume 1e-5 apart.)
                if !reuse && *lambda <= 1e-2 && drop <= rtol * cost {
                    break;
                }
                if reuse {
                    age += 1;
                } else if shortened {
                    // The model was trusted too far: damp a little more, keep the factor.
                    *lambda *= 2.0;
                    age = 1;
                } else {
                    *lambda = (*lambda / 3.0).max(1e-12);
                    age = 1;
                }
            } else if reuse {
                age = usize::MAX;
            } else {
                *lambda *= 4.0;
                if *lambda > 1e12 {
                    break;
                }
            }
        }
        steps
    }
}

/// The vertex pairs of the normal equations' pattern, the slot of each edge's pair, and the
/// slots of each hinge's six pairs.
type Pattern = (Vec<(usize, usize)>, Vec<usize>, Vec<[usize; 6]>);

/// The [`Pattern`] of the terms: every edge's pair, then every hinge's, its tips'
/// [`TIPS_LEFT_OUT`] unless `tips`.
fn pattern(edges: &[Edge], hinges: &[Hinge], tips: bool) -> Pattern {
    let mut slot = KeyMap::default();
    let mut pairs = Vec::new();
    let mut key = |a: usize, b: usize, pairs: &mut Vec<(usize, usize)>| {
        let k = (a.min(b), a.max(b));
        *slot.entry(pair_key(k.0, k.1)).or_insert_with(|| {
            pairs.push(k);
            pairs.len() - 1
        })
    };
    let edge_slot = edges.iter().map(|e| key(e.i, e.j, &mut pairs)).collect();
    let hinge_slots = hinges
        .iter()
        .map(|h| {
            HINGE_PAIRS.map(|(a, b)| if tips || (a, b) != (2, 3) { key(h.v[a], h.v[b], &mut pairs) } else { TIPS_LEFT_OUT })
        })
        .collect();
    (pairs, edge_slot, hinge_slots)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A triangle whose edge 0–1 is a seam edge with flat lengths 10 and 10.5 (one per piece).
    fn seam_triangle() -> Shell {
        let e = |i, j, rest, piece| Edge { i, j, rest, piece };
        Shell::new(3, vec![e(0, 1, 10.0, 0), e(1, 2, 10.0, 0), e(2, 0, 10.0, 0), e(1, 0, 10.5, 1)], Vec::new())
    }

    /// A 3×3 grid of vertices (spacing 10) cut into 8 triangles as piece A of a
    /// [`super::super::glued::SheetMesh`] (piece B empty), with the shell's terms it gives: its
    /// 16 edges and a hinge on each of its 8 interior edges. Bent out of its plane by `z`.
    fn grid_sheet(z: impl Fn(usize) -> f64) -> (Shell, Vec<V3>) {
        let flat: Vec<[f64; 2]> = (0..9).map(|v| [10.0 * (v % 3) as f64, 10.0 * (v / 3) as f64]).collect();
        let faces = (0..4).flat_map(|q| {
            let v = 3 * (q / 2) + q % 2;
            [[v, v + 1, v + 4], [v, v + 4, v + 3]]
        });
        let mesh = super::super::glued::SheetMesh { n: 8, faces: [faces.collect(), Vec::new()], flat: [flat.clone(), flat.clone()] };
        let shell = mesh.shell();
        assert_eq!((shell.edges.len(), shell.hinges.len()), (16, 8), "the grid's edges and hinges");
        let x = flat.iter().enumerate().map(|(v, p)| [p[0], p[1], z(v)]).collect();
        (shell, x)
    }

    /// The dense `3n × 3n` matrix of the blocks [`Shell::assemble`] fills, and the gradient.
    fn dense(shell: &Shell, x: &[V3], kb: f64) -> (Vec<Vec<f64>>, Vec<f64>) {
        let mut diag = vec![[[0.0; 3]; 3]; shell.n];
        let mut off = vec![[[0.0; 3]; 3]; shell.pairs.len()];
        let g = shell.assemble(x, kb, Some((&mut diag, &mut off)));
        let mut m = vec![vec![0.0; 3 * shell.n]; 3 * shell.n];
        for (v, b) in diag.iter().enumerate() {
            for a in 0..3 {
                for c in 0..3 {
                    m[3 * v + a][3 * v + c] += b[a][c];
                }
            }
        }
        for (&(p, q), b) in shell.pairs.iter().zip(&off) {
            for a in 0..3 {
                for c in 0..3 {
                    m[3 * p + a][3 * q + c] += b[a][c];
                    m[3 * q + c][3 * p + a] += b[a][c];
                }
            }
        }
        (m, g)
    }

    /// Leaving the tips out adds `c cᵀ` per hinge, `c = w·(g_k on tip k, −g_l on tip l)` from
    /// the hinge's own gradient (so the matrix stays above `JᵀJ`), keeps the gradient, and
    /// drops every tip pair that is no edge from the pattern.
    #[test]
    fn leaving_the_tips_out_adds_a_square_per_hinge_and_keeps_the_gradient() {
        let (mut shell, x) = grid_sheet(|v| [0.0, 1.5, -0.7, 2.0, 0.3, -1.1, 0.9, -2.2, 1.4][v]);
        let kb = 0.8;
        let (m, g) = dense(&shell, &x, kb);
        shell.set_tip_blocks(false);
        let (m2, g2) = dense(&shell, &x, kb);
        assert_eq!(g, g2, "the gradient must not change");
        let mut want = m.clone();
        for h in &shell.hinges {
            let [i, j, k, l] = h.v;
            let (_, grad) = angle_and_gradient(x[i], x[j], x[k], x[l]).expect("a proper hinge");
            let w2 = kb * h.weight;
            let mut c = vec![0.0; 3 * shell.n];
            for a in 0..3 {
                c[3 * k + a] += grad[2][a];
                c[3 * l + a] -= grad[3][a];
            }
            for (r, row) in want.iter_mut().enumerate() {
                for (col, e) in row.iter_mut().enumerate() {
                    *e += w2 * c[r] * c[col];
                }
            }
        }
        let scale = m.iter().flatten().fold(0.0f64, |s, v| s.max(v.abs()));
        for r in 0..3 * shell.n {
            for c in 0..3 * shell.n {
                assert!((m2[r][c] - want[r][c]).abs() <= 1e-12 * scale, "entry ({r}, {c}): wanted {}, got {}", want[r][c], m2[r][c]);
            }
        }
        let edge = |a: usize, b: usize| shell.edges.iter().any(|e| (e.i.min(e.j), e.i.max(e.j)) == (a.min(b), a.max(b)));
        for &(a, b) in &shell.pairs {
            assert!(edge(a, b), "pair ({a}, {b}) of the tipless pattern is no edge");
        }
        shell.set_tip_blocks(true);
        let (m3, _) = dense(&shell, &x, kb);
        assert_eq!(m, m3, "putting the tips back must give the matrix of Shell::new");
    }

    /// With the sparser majorant the minimization still ends at the equilibrium: a bent grid
    /// relaxes to its flat rest shape (zero energy) with the tips left out, as with them.
    #[test]
    fn a_tipless_minimization_still_relaxes_a_bent_sheet_flat() {
        for tips in [true, false] {
            let (mut shell, mut x) = grid_sheet(|v| [0.0, 0.8, -0.4, 1.0, 0.2, -0.6, 0.5, -1.2, 0.7][v]);
            shell.set_tip_blocks(tips);
            let kb = 1e-2;
            let start = shell.cost(&x, kb);
            let mut lambda = 1e-3;
            let steps = shell.minimize(&mut x, kb, 500, 1e-14, &mut lambda);
            let end = shell.cost(&x, kb);
            let strain = shell.max_strain(&x);
            println!("tips {tips}: energy {start:.3e} → {end:.3e} in {steps} steps, strain {strain:.1e}");
            assert!(end <= 1e-12 * start, "tips {tips}: wanted the flat sheet's zero energy, got {end:e} from {start:e}");
            assert!(strain <= 1e-6, "tips {tips}: wanted the rest lengths, got strain {strain:e}");
        }
    }

    #[test]
    fn the_strain_floor_is_the_least_strain_of_a_seam_edge_with_two_flat_lengths() {
        let shell = seam_triangle();
        let want = 0.5 / 20.5;
        let got = shell.strain_floor();
        assert!((got - want).abs() < 1e-15, "wanted the floor (L₂ − L₁)/(L₁ + L₂) = {want:e}, got {got:e}");
        // Against the strain of shapes: edge 0–1 at lengths around the harmonic mean, the other
        // two edges at their flat lengths (the apex on the perpendicular bisector).
        let at = |d: f64| {
            let h = (100.0 - d * d / 4.0).sqrt();
            shell.max_strain(&[[0.0, 0.0, 0.0], [d, 0.0, 0.0], [d / 2.0, h, 0.0]])
        };
        let harmonic = 2.0 * 10.0 * 10.5 / 20.5;
        assert!((at(harmonic) - want).abs() < 1e-12, "at the harmonic mean: wanted {want:e}, got {:e}", at(harmonic));
        for d in [9.9, 10.0, 10.2, 10.3, 10.5, 10.6] {
            assert!(at(d) >= want, "length {d}: strain {:e} below the floor {want:e}", at(d));
        }
        let single = Shell::new(2, vec![Edge { i: 0, j: 1, rest: 3.0, piece: 0 }], Vec::new());
        assert_eq!(single.strain_floor(), 0.0, "an edge with one flat length can be unstrained");
    }
}
