//! Levenberg–Marquardt on the isometry equations of the seam-vertex polyhedron, with flips of
//! reflex chords towards the convex realization (see the module docs of [`super`]).

use super::metric::{self, Triangulation};
use super::options::SimulateOptions;
use super::seam::SeamPieces;
use crate::error::{Error, Result};
use super::normal::NormalEquations;
use std::collections::HashMap;
use super::seam::Glue;

/// Out-of-plane sine above which a chord counts as reflex and is flipped. Below it the two
/// triangles are coplanar to round-off and either diagonal is right.
pub const REFLEX_SINE: f64 = 1e-6;

/// A step shorter than this (relative to the shape's size) ends the iteration.
const STEP_TOL: f64 = 1e-11;

/// Largest residual strain of the length equations accepted as "converged".
pub const STRAIN_TOL: f64 = 1e-7;

/// The solver's result: positions, the two triangulations, and how it went.
#[derive(Debug, Clone)]
pub struct Solution {
    pub x: Vec<[f64; 3]>,
    pub tri: [Triangulation; 2],
    pub iterations: usize,
    pub flips: usize,
    pub converged: bool,
}

pub(super) type V3 = [f64; 3];

pub(super) fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub(super) fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub(super) fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
pub(super) fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// One length equation: |x_i − x_j| = d.
#[derive(Debug, Clone, Copy)]
struct Bar {
    i: usize,
    j: usize,
    d: f64,
}

/// The length equations: every chord of each piece at its flat length, and each seam edge once,
/// at the mean of A's and B's chord. (The two chords differ by `O(h³)`; one length per seam edge
/// makes the polyhedral metric consistent, so the square system has an exact solution and the
/// convexity of each chord is decided by geometry, not by least-squares noise.)
fn bars(pieces: &SeamPieces, tri: &[Triangulation; 2]) -> Vec<Bar> {
    let n = pieces.n;
    let mut out = Vec::with_capacity(3 * n);
    for (p, t) in tri.iter().enumerate() {
        for (i, j) in t.edges() {
            let seam = metric::is_seam(n, i, j);
            if seam && p == 1 {
                continue;
            }
            let d = if seam { 0.5 * (pieces.chord(0, i, j) + pieces.chord(1, i, j)) } else { pieces.chord(p, i, j) };
            if d > 0.0 {
                out.push(Bar { i, j, d });
            }
        }
    }
    out
}

/// Sum of squared relative residuals `(|x_i − x_j| / d − 1)²`.
fn cost(x: &[V3], bars: &[Bar]) -> f64 {
    bars.iter().map(|b| (norm(sub(x[b.j], x[b.i])) / b.d - 1.0).powi(2)).sum()
}

/// Mirrors the positions (z → −z, an isometry) when the mesh is inside out, so that A's triangles
/// as they are and B's reversed face outward.
pub(super) fn make_outward(x: &mut [V3], tri: &[Triangulation; 2]) {
    if signed_volume(x, tri) < 0.0 {
        for p in x.iter_mut() {
            p[2] = -p[2];
        }
    }
}

/// Signed volume of the closed mesh (A's triangles as they are, B's reversed).
pub fn signed_volume(x: &[V3], tri: &[Triangulation; 2]) -> f64 {
    let mut v = 0.0;
    for (p, t) in tri.iter().enumerate() {
        for &[a, b, c] in &t.tris {
            let (b, c) = if p == 0 { (b, c) } else { (c, b) };
            v += dot(x[a], cross(x[b], x[c]));
        }
    }
    v / 6.0
}

/// Centroid of a point set (the mean of its points).
pub(super) fn centroid(x: &[V3]) -> V3 {
    let n = x.len() as f64;
    x.iter().fold([0.0; 3], |s, p| [s[0] + p[0] / n, s[1] + p[1] / n, s[2] + p[2] / n])
}

/// The centroid of a point set and the largest distance of a point from it.
pub(super) fn centroid_and_radius(x: &[V3]) -> (V3, f64) {
    let c = centroid(x);
    (c, x.iter().map(|p| norm(sub(*p, c))).fold(0.0, f64::max))
}

/// Size scale of a point set (RMS distance to the centroid).
fn size(x: &[V3]) -> f64 {
    let c = centroid(x);
    (x.iter().map(|p| dot(sub(*p, c), sub(*p, c))).sum::<f64>() / x.len() as f64).sqrt()
}

/// Out-of-plane sine of chord i–j in piece `p`: positive when reflex (the far vertex of the
/// neighbouring triangle lies outside the plane of the outward face).
pub fn reflex_sine(x: &[V3], t: &Triangulation, p: usize, i: usize, j: usize) -> Option<f64> {
    let k = t.opposite(i, j)?;
    let l = t.opposite(j, i)?;
    let n = cross(sub(x[j], x[i]), sub(x[k], x[i]));
    let (nn, dl) = (norm(n), sub(x[l], x[i]));
    let ndl = norm(dl);
    if nn == 0.0 || ndl == 0.0 {
        return Some(0.0);
    }
    // A's faces are outward as ccw in the flat piece; B's are reversed.
    let s = if p == 0 { 1.0 } else { -1.0 };
    Some(s * dot(n, dl) / (nn * ndl))
}

/// How often a chord may be flipped away before it is frozen: a chord that keeps coming back
/// sits between two nearly coplanar triangles (or a non-convex piece), where flipping it again
/// would only cycle.
const MAX_FLIPS_PER_EDGE: usize = 2;

/// Whether a relaxation may mirror the positions to make the volume positive.
///
/// A start whose orientation is not known (a lifted flat layout) must be allowed to; a start
/// that is already outward-oriented (a coarser level's solution or a warm start from a previous
/// result, whose A faces are outward by construction) must not. Mirroring such a start while its
/// triangulation is still the flat ear-clipping strip (whose realization has no meaningful
/// volume sign) reverses what "outward" means half way through the flips, and the flips then
/// drive A's chords onto B's cap: both sheets end up on the same cap and the shape collapses to
/// volume ≈ 0 (the warm-start bug; see `warm_start_keeps_its_orientation` in the tests).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Orientation {
    Free,
    Kept,
}

/// Makes the mesh outward-oriented (positive volume) by mirroring, an isometry, when the
/// orientation is [`Orientation::Free`], then flips every reflex chord whose flat quad allows
/// it. Returns the number of flips.
fn flip_pass(
    x: &mut [V3],
    tri: &mut [Triangulation; 2],
    pieces: &SeamPieces,
    // Keyed by `order::pair_key(i, j)`: `HashMap<u64, usize>` is the map type the triangulations
    // use too, so the .wasm holds one instantiation of the hash table, not two.
    count: &mut [HashMap<u64, usize>; 2],
    orientation: Orientation,
) -> usize {
    if orientation == Orientation::Free {
        make_outward(x, tri);
    }
    let mut flips = 0;
    for p in 0..2 {
        let pts = &pieces.flat[p].pts;
        let s2 = metric::size2(pts);
        for (i, j) in tri[p].chords() {
            let key = crate::order::pair_key(i, j);
            if count[p].get(&key).is_some_and(|&c| c >= MAX_FLIPS_PER_EDGE) {
                continue;
            }
            let Some(s) = reflex_sine(x, &tri[p], p, i, j) else { continue };
            if s <= REFLEX_SINE {
                continue;
            }
            // The new chord must be able to be an edge (see [`shortest_flips`]): a flip that
            // would put in a chord longer than the path through the other piece is refused,
            // unless the chord it replaces is as bad.
            let (Some(k), Some(l)) = (tri[p].opposite(i, j), tri[p].opposite(j, i)) else { continue };
            if excess(pieces, p, k, l) > SHORTEST_TOL.max(excess(pieces, p, i, j)) {
                continue;
            }
            if tri[p].flip(i, j, pts, s2) {
                *count[p].entry(key).or_insert(0) += 1;
                flips += 1;
            }
        }
    }
    flips
}

/// Relative excess `d_p(i, j) / d_q(i, j) − 1` of chord i–j of piece `p` over the same chord of
/// the other piece `q`. An isometric realization has `|X_i − X_j| = d_p(i, j)` for every edge of
/// `p` and `|X_i − X_j| ≤ d_q(i, j)` (the straight segment is no longer than the path across the
/// other piece, a curve on the surface), so a chord with positive excess cannot be an edge of any
/// realization, convex or not. (For a convex polyhedron this is the fact that every edge is a
/// shortest path between its ends.)
fn excess(pieces: &SeamPieces, p: usize, i: usize, j: usize) -> f64 {
    pieces.chord(p, i, j) / pieces.chord(1 - p, i, j).max(f64::MIN_POSITIVE) - 1.0
}

/// Excess (see [`excess`]) tolerated in a chord put in by a flip: the seam edges' lengths are
/// the mean of A's and B's chords, which makes the metric's distances differ from either flat
/// piece's at `O(h²)` relative, so only a clear excess is ruled out.
const SHORTEST_TOL: f64 = 1e-6;

/// Flips every chord of piece `p` that cannot be an edge (positive [`excess`]) to the other
/// diagonal of its quad, when that one's excess is smaller, until none can be. Purely intrinsic
/// (no positions): it turns the ear-clipping strip, which on a rectangle glued to a circle holds
/// rectangle chords up to 8 % longer than the circle's between the same seam vertices (and circle
/// chords up to 59 % longer than the rectangle's), into a start the isometry equations can meet.
/// Each flip lowers the sum of the chords' excess ratios, so it ends.
fn shortest_flips(t: &mut Triangulation, pieces: &SeamPieces, p: usize) {
    let pts = &pieces.flat[p].pts;
    let s2 = metric::size2(pts);
    loop {
        let mut any = false;
        for (i, j) in t.chords() {
            let e = excess(pieces, p, i, j);
            if e <= 0.0 {
                continue;
            }
            let (Some(k), Some(l)) = (t.opposite(i, j), t.opposite(j, i)) else { continue };
            if excess(pieces, p, k, l) < e && t.flip(i, j, pts, s2) {
                any = true;
            }
        }
        if !any {
            break;
        }
    }
}

/// Initial positions: the two flat polygons rigidly aligned (Procrustes) and averaged, lifted
/// into the saddle that the chord mismatch asks for. Where A's chords are longer than B's, A
/// (the top sheet, outward normal +z) must bulge across them, which puts the seam low at their
/// ends: z = −s·(ĉᵀ M̃ ĉ) with M̃ the trace-free part of Σ (d_A² − d_B²) û ûᵀ.
/// `lift` scales the saddle's height (the multistart tries several; see [`Start`]).
/// Congruent pieces glued congruently give M̃ = 0: the flat, doubly covered start, which is
/// already the solution.
///
/// A negative `lift` ([`Start::Fourfold`]) gives the fourfold start instead, z = (|lift|/10)·ρ cos 4θ in polar
/// coordinates about the centroid. Pieces with a fourfold (or nearly fourfold) symmetry, a
/// square or a near-square rectangle glued to a circle, give M̃ ≈ 0 too, yet their D-form is not
/// flat: by Alexandrov–Pogorelov uniqueness it has the symmetries of the gluing, so a 90° turn
/// that maps each piece onto itself maps the shape onto itself, and its seam's height can only
/// hold the Fourier modes cos 4kθ, sin 4kθ — none of which the saddle (cos 2θ) has. From the
/// saddle, every height ends on a wrong branch for 52×48 and 50×50 rectangles with a circle;
/// from the fourfold start they converge in ~50–150 steps (so do 60×40 and 57×43).
fn initial_guess(pieces: &SeamPieces, start: Start) -> Vec<V3> {
    let lift = match start {
        Start::Saddle(h) => h,
        Start::Fourfold(h) => -h,
        Start::Mismatch(h) => return mismatch_start(pieces, h),
    };
    let n = pieces.n;
    let (a, b) = (&pieces.flat[0].pts, &pieces.flat[1].pts);
    let centroid = |p: &[[f64; 2]]| {
        let s = p.iter().fold([0.0, 0.0], |s, q| [s[0] + q[0], s[1] + q[1]]);
        [s[0] / n as f64, s[1] / n as f64]
    };
    let (ca, cb) = (centroid(a), centroid(b));
    let (mut sc, mut ss) = (0.0, 0.0);
    for k in 0..n {
        let (u, v) = ([a[k][0] - ca[0], a[k][1] - ca[1]], [b[k][0] - cb[0], b[k][1] - cb[1]]);
        sc += u[0] * v[0] + u[1] * v[1];
        ss += v[0] * u[1] - v[1] * u[0];
    }
    let th = ss.atan2(sc);
    let (c, s) = (th.cos(), th.sin());
    let flat: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let v = [b[k][0] - cb[0], b[k][1] - cb[1]];
            let rb = [c * v[0] - s * v[1], c * v[1] + s * v[0]];
            [(a[k][0] - ca[0] + rb[0]) / 2.0, (a[k][1] - ca[1] + rb[1]) / 2.0]
        })
        .collect();
    // Mismatch tensor over pairs k, k+m for a few spans m.
    let (mut mxx, mut mxy, mut myy, mut total) = (0.0, 0.0, 0.0, 0.0);
    for m in [n / 8, n / 4, 3 * n / 8, n / 2] {
        if m == 0 {
            continue;
        }
        for i in 0..n {
            let j = (i + m) % n;
            let (da, db) = (pieces.chord(0, i, j), pieces.chord(1, i, j));
            let u = [flat[j][0] - flat[i][0], flat[j][1] - flat[i][1]];
            let l = u[0].hypot(u[1]);
            if l == 0.0 {
                continue;
            }
            let u = [u[0] / l, u[1] / l];
            let w = da * da - db * db;
            mxx += w * u[0] * u[0];
            mxy += w * u[0] * u[1];
            myy += w * u[1] * u[1];
            total += (da * da + db * db) / 2.0;
        }
    }
    let (hx, hxy) = ((mxx - myy) / 2.0, mxy); // trace-free part [[hx, hxy], [hxy, -hx]]
    let lam = hx.hypot(hxy);
    let r2 = flat.iter().map(|p| p[0] * p[0] + p[1] * p[1]).sum::<f64>() / n as f64;
    let r = r2.sqrt();
    let delta = if total > 0.0 { lam / (total / 2.0) } else { 0.0 };
    let amp = if lam > 0.0 && r > 0.0 { 0.5 * delta.sqrt() / r } else { 0.0 };
    let amp = amp * lift;
    if lift < 0.0 {
        // The fourfold start: z = |lift|·r/10 · (ρ/r) cos 4θ.
        return flat
            .iter()
            .map(|p| [p[0], p[1], -0.1 * lift * p[0].hypot(p[1]) * (4.0 * p[1].atan2(p[0])).cos()])
            .collect();
    }
    flat.iter()
        .map(|p| {
            let q = (hx * (p[0] * p[0] - p[1] * p[1]) + 2.0 * hxy * p[0] * p[1]) / lam.max(f64::MIN_POSITIVE);
            [p[0], p[1], -amp * q]
        })
        .collect()
}

/// The mismatch start: the flat layout of [`initial_guess`] with seam vertex k at height
/// `z_k = −(h/10)·r·(μ_k − μ̄) / max|μ − μ̄|`, where `μ_k = Σ_j (d_A(k, j)² − d_B(k, j)²)` sums the
/// chord mismatch over every other seam vertex and `r` is the layout's RMS radius.
///
/// The saddle is the quadratic (cos 2θ) part of the same rule: where A's chords are longer than
/// B's, A bulges across them and the seam sits low at their ends. Here every vertex gets its own
/// height, so the start holds every angular mode the mismatch has, not only cos 2θ (and cos 4θ,
/// the fourfold start). A regular m-gon glued to a circle has the m-fold symmetry of the gluing
/// (Alexandrov–Pogorelov uniqueness, as for the fourfold start), so its seam height holds only the
/// modes cos mkθ: μ has them (A's chords from a corner are the longest, its sides' midpoints the
/// shortest), while the saddle and the fourfold start have none for m = 3 or m ≥ 5. A triangle,
/// an octagon and a 12-gon with a circle ended unconverged from every other start (strain
/// 1–38 %); from this one they converge in ~100–200 steps.
fn mismatch_start(pieces: &SeamPieces, h: f64) -> Vec<V3> {
    let n = pieces.n;
    let flat = initial_guess(pieces, Start::Saddle(0.0));
    let mu: Vec<f64> = (0..n).map(|k| (0..n).map(|j| pieces.chord(0, k, j).powi(2) - pieces.chord(1, k, j).powi(2)).sum()).collect();
    let mean = mu.iter().sum::<f64>() / n as f64;
    let top = mu.iter().map(|m| (m - mean).abs()).fold(0.0, f64::max);
    let r = (flat.iter().map(|p| p[0] * p[0] + p[1] * p[1]).sum::<f64>() / n as f64).sqrt();
    let s = if top > 0.0 { -0.1 * h * r / top } else { 0.0 };
    flat.iter().zip(&mu).map(|(p, m)| [p[0], p[1], s * (m - mean)]).collect()
}

/// A start of the multistart (see [`initial_guess`]): the saddle, the fourfold start, or the
/// mismatch start ([`mismatch_start`]), each with its relative height.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Start {
    Saddle(f64),
    Fourfold(f64),
    Mismatch(f64),
}

/// A warm start resampled to `n` seam vertices (linear along the previous seam polygon).
fn resample(w: &[V3], n: usize) -> Vec<V3> {
    if w.len() == n {
        return w.to_vec();
    }
    let m = w.len();
    (0..n)
        .map(|k| {
            let t = k as f64 * m as f64 / n as f64;
            let i = (t.floor() as usize).min(m - 1);
            let f = t - i as f64;
            let (a, b) = (w[i], w[(i + 1) % m]);
            [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])]
        })
        .collect()
}

/// Solves one damped Gauss–Newton step `(JᵀJ + λ·μ I) Δ = −Jᵀr` with the normal equations
/// pattern of `bars`; `None` if the factorization fails (then the caller raises λ).
fn step(x: &[V3], bars: &[Bar], lambda: f64, ne: &mut NormalEquations) -> Option<Vec<f64>> {
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
fn pattern(n: usize, bars: &[Bar]) -> NormalEquations {
    let pairs: Vec<(usize, usize)> = bars.iter().map(|b| (b.i, b.j)).collect();
    NormalEquations::new(n, &pairs)
}

/// Coarsest level of the multilevel start: below this the seam chords of A and B differ too
/// much for the polyhedral metric to mean anything.
pub const COARSEST: usize = 32;

/// Lays the finer level's seam vertices onto the coarser solution: each fine sample is mapped
/// by the affine map of the coarse triangle at its seam edge (flat piece → 3D), for A and for B,
/// and the two images are averaged. The start is then isometric up to the coarse level's error.
fn upsample(pc: &SeamPieces, xc: &[V3], tc: &[Triangulation; 2], pf: &SeamPieces) -> Vec<V3> {
    let (nc, nf) = (pc.n, pf.n);
    (0..nf)
        .map(|k| {
            let m = (k * nc / nf).min(nc - 1);
            let m1 = (m + 1) % nc;
            let mut acc = [0.0; 3];
            let mut w = 0.0;
            for p in 0..2 {
                let Some(r) = tc[p].opposite(m, m1) else { continue };
                let f = &pc.flat[p].pts;
                if let Some(q) = map_affine([f[m], f[m1], f[r]], [xc[m], xc[m1], xc[r]], pf.flat[p].pts[k]) {
                    acc = [acc[0] + q[0], acc[1] + q[1], acc[2] + q[2]];
                    w += 1.0;
                }
            }
            if w > 0.0 {
                acc.map(|v| v / w)
            } else {
                let t = k as f64 * nc as f64 / nf as f64 - m as f64;
                [0, 1, 2].map(|a| xc[m][a] + t * (xc[m1][a] - xc[m][a]))
            }
        })
        .collect()
}

/// Maps flat point `q` into 3D by the affine map that takes flat triangle `f` to `t`.
pub fn map_affine(f: [[f64; 2]; 3], t: [V3; 3], q: [f64; 2]) -> Option<V3> {
    let det = (f[1][0] - f[0][0]) * (f[2][1] - f[0][1]) - (f[1][1] - f[0][1]) * (f[2][0] - f[0][0]);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let (dx, dy) = (q[0] - f[0][0], q[1] - f[0][1]);
    let b1 = (dx * (f[2][1] - f[0][1]) - dy * (f[2][0] - f[0][0])) / det;
    let b2 = ((f[1][0] - f[0][0]) * dy - (f[1][1] - f[0][1]) * dx) / det;
    let b0 = 1.0 - b1 - b2;
    Some([0, 1, 2].map(|a| b0 * t[0][a] + b1 * t[1][a] + b2 * t[2][a]))
}

/// A cold start's triangulation of piece `p`: ear clipping, then [`shortest_flips`].
fn triangulate(pieces: &SeamPieces, p: usize) -> Result<Triangulation> {
    let mut t = ear_clip(pieces, p)?;
    shortest_flips(&mut t, pieces, p);
    Ok(t)
}

fn ear_clip(pieces: &SeamPieces, p: usize) -> Result<Triangulation> {
    metric::ear_clip(&pieces.flat[p].pts).ok_or_else(|| Error::Infeasible {
        reason: format!(
            "The {} piece is too thin or too detailed for {} seam vertices: its sampled outline cannot be triangulated. Raise the resolution or simplify the outline.",
            if p == 0 { "first" } else { "second" },
            pieces.n
        ),
    })
}

/// Steps after which [`relax`] folds reflex chords if the cost has not halved (see there).
const PLATEAU: usize = 10;

/// Result of relaxing one level.
struct Relaxed {
    iterations: usize,
    flips: usize,
    converged: bool,
}

impl Relaxed {
    /// Adds this relaxation's steps and flips to a cold solve's running `(steps, flips)`.
    fn tally(self, steps: &mut (usize, usize)) -> Self {
        steps.0 += self.iterations;
        steps.1 += self.flips;
        self
    }
}

/// Levenberg–Marquardt on a fixed triangulation until the step is negligible, then one pass of
/// flips; repeated until nothing flips. `step_tol` is relative to the shape's size.
fn relax(
    pieces: &SeamPieces,
    x: &mut Vec<V3>,
    tri: &mut [Triangulation; 2],
    budget: usize,
    step_tol: f64,
    orientation: Orientation,
) -> Relaxed {
    let n = pieces.n;
    let mut count = [HashMap::new(), HashMap::new()];
    let mut flips = 0;
    for _ in 0..n {
        let f = flip_pass(x, tri, pieces, &mut count, orientation);
        flips += f;
        if f == 0 {
            break;
        }
    }
    let scale = size(x).max(f64::MIN_POSITIVE);
    let mut bars = bars(pieces, tri);
    let mut ne = pattern(n, &bars);
    let mut c = cost(x, &bars);
    let mut lambda = 1e-4;
    let mut iterations = 0;
    let mut converged = false;
    let mut window = (0usize, c);
    while iterations < budget {
        // A triangulation with no isometric realization makes the least-squares cost plateau long
        // before the step gets negligible (hundreds of steps on a rectangle with a circle): when
        // the cost has not halved in PLATEAU steps, fold the reflex chords now.
        if iterations - window.0 >= PLATEAU {
            let slow = c > 0.5 * window.1;
            window = (iterations, c);
            if slow {
                let f = flip_pass(x, tri, pieces, &mut count, orientation);
                if f > 0 {
                    flips += f;
                    bars = self::bars(pieces, tri);
                    ne = pattern(n, &bars);
                    c = cost(x, &bars);
                    lambda = 1e-4;
                    window = (iterations, c);
                }
            }
        }
        iterations += 1;
        let Some(d) = step(x, &bars, lambda, &mut ne) else {
            lambda *= 10.0;
            if lambda > 1e12 {
                break;
            }
            continue;
        };
        let trial: Vec<V3> = (0..n).map(|k| [x[k][0] + d[3 * k], x[k][1] + d[3 * k + 1], x[k][2] + d[3 * k + 2]]).collect();
        let ct = cost(&trial, &bars);
        let dmax = d.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let stalled = dmax <= step_tol * scale || c == 0.0;
        if ct <= c {
            *x = trial;
            c = ct;
            lambda = (lambda / 3.0).max(1e-12);
        } else if !stalled {
            lambda *= 4.0;
            if lambda > 1e12 {
                break;
            }
            continue;
        }
        if !stalled {
            continue;
        }
        // The realization of this triangulation is found: fold the reflex chords the other way.
        let f = flip_pass(x, tri, pieces, &mut count, orientation);
        flips += f;
        if f > 0 {
            bars = self::bars(pieces, tri);
            ne = pattern(n, &bars);
            c = cost(x, &bars);
            lambda = 1e-4;
            continue;
        }
        let worst = max_strain(x, &bars);
        converged = worst <= STRAIN_TOL;
        break;
    }
    Relaxed { iterations, flips, converged }
}

/// Step budgets of one pass of the cold solve: per multistart attempt on the coarsest level, per
/// refinement level while other starts remain, and in all (`cap`, counted with the steps of
/// earlier passes).
#[derive(Debug, Clone, Copy)]
struct Patience {
    attempt: usize,
    level: usize,
    cap: usize,
    /// Whether a failed multistart attempt restarts from the convex hull of where it ended
    /// ([`super::hull`]).
    hull: bool,
}

/// The first pass: a healthy start needs a few dozen steps per level (the whole 32→256 solve of
/// two ellipses takes ~100–400), so a start that needs more is dropped for the next one.
const QUICK: Patience = Patience { attempt: 60, level: 150, cap: 1000, hull: false };

/// The second pass, run only when the first found no convex isometric branch: pieces with
/// straight stretches (rectangles, rounded rectangles, polygons) give D-forms with nearly flat
/// regions, whose chords sit between nearly coplanar triangles and take many steps and flips to
/// settle (a rounded 60×40 rectangle glued to a circle: ~2,300 steps in all, ~70 ms native at
/// 256 seam vertices) — longer than the quick budgets allow, but the branch is right.
const PATIENT: Patience = Patience { attempt: 2000, level: 2000, cap: usize::MAX, hull: true };

/// Steps allowed to a warm start before it is dropped for a cold solve. A slider step of 1 % of
/// the perimeter takes 25–105 steps from the previous result (two 2:1 ellipses, an ellipse with
/// a circle); a warm start that needs more is heading for a shape the solver cannot realize, and
/// grinding it longer only delays the cold solve the slider then waits for.
const WARM_BUDGET: usize = 300;

/// Starts tried by the multistart, most likely first (see [`initial_guess`]). The mismatch start
/// comes third so that the shapes the first two already solve take no longer.
const LIFTS: [Start; 11] = [
    Start::Saddle(1.0),
    Start::Fourfold(1.0),
    Start::Mismatch(1.0),
    Start::Saddle(3.0),
    Start::Saddle(2.0),
    Start::Saddle(0.5),
    Start::Mismatch(2.0),
    Start::Saddle(5.0),
    Start::Saddle(1.5),
    Start::Saddle(8.0),
    Start::Saddle(0.25),
];

fn max_strain(x: &[V3], bars: &[Bar]) -> f64 {
    bars.iter().map(|b| (norm(sub(x[b.j], x[b.i])) / b.d - 1.0).abs()).fold(0.0, f64::max)
}

/// Out-of-plane sine of a reflex chord above which a solution counts as dented (a wrong
/// isometric branch) rather than convex up to the tiny folds that coarse levels keep.
const DENT_SINE: f64 = 1e-2;

/// Largest out-of-plane sine of a reflex chord (0 when the mesh is convex).
fn worst_reflex(x: &[V3], tri: &[Triangulation; 2]) -> f64 {
    (0..2)
        .flat_map(|p| tri[p].chords().into_iter().filter_map(move |(i, j)| reflex_sine(x, &tri[p], p, i, j)))
        .fold(0.0, f64::max)
}

/// Strain below which a coarser level (relaxed only to a step of 1e-6 of the size) counts as
/// solved: its solution is only a start for the next level, which polishes it.
const LEVEL_STRAIN_TOL: f64 = 1e-5;

/// The finer level's triangulation: the coarse one plus one ear per seam edge where it can be,
/// else a fresh ear clipping.
fn refine(tc: &[Triangulation; 2], pieces: &SeamPieces, p: usize) -> Result<Triangulation> {
    if tc[p].len() * 2 == pieces.n {
        if let Some(mut t) = tc[p].doubled(&pieces.flat[p].pts) {
            shortest_flips(&mut t, pieces, p);
            return Ok(t);
        }
    }
    triangulate(pieces, p)
}

/// Whether a solution is the convex isometric one: converged, without a dent, and convex as a
/// whole ([`outside`] within [`OUTSIDE_TOL`]).
fn is_good(x: &[V3], tri: &[Triangulation; 2], converged: bool) -> bool {
    converged && worst_reflex(x, tri) <= DENT_SINE && outside_sampled(x, tri) <= OUTSIDE_TOL && !folded_flat(x, tri)
}

/// For a polyhedral gluing (two convex polygons, [`super::hull::cone_vertices`]): whether the
/// mesh is convex — no chord reflex beyond round-off (out-of-plane sine above
/// [`super::stats::REFLEX_REPORT`], what the stats count as a reflex edge), convex as a whole
/// ([`outside`]) and not a flat fold ([`folded_flat`]); always true for a curved seam, whose
/// "converged" keeps meaning that the isometry equations are met.
///
/// The tolerance of [`DENT_SINE`] is for the folds a polygonal seam keeps where the true seam is
/// curved, which vanish as the samples get finer. The seam of two polygons is exactly polygonal
/// and the polyhedron exact at any sampling that holds the corners, so a fold there is a wrong
/// shape, not a discretization error: two triangles at a quarter offset "converged" at 40–61
/// seam vertices with 4–21 reflex chords and volumes from 5,500 to 6,700, and a 90×10
/// rectangle with a square at 48 with 3 (volume 7,961; the polyhedron's is 7,978.128 at 128, 160
/// and 256). Where a crease of the polyhedron crosses the seam between samples no chord mesh
/// realizes it and the honest answer is "not converged" ([`solve_polyhedral`] puts a sample at
/// each such crossing it can find, see [`seam_crossings`]).
fn exact_if_polyhedral(pieces: &SeamPieces, x: &[V3], tri: &[Triangulation; 2]) -> bool {
    super::hull::cone_vertices(pieces).is_none()
        || (worst_reflex(x, tri) <= super::stats::REFLEX_REPORT && outside_sampled(x, tri) <= OUTSIDE_TOL && !folded_flat(x, tri))
}

/// Whether the mesh lies in a plane (to 1e-5 of its size) without being a doubly covered convex
/// polygon: its area is more than twice the area of its points' convex hull in that plane.
///
/// The dihedral and plane tests cannot see such a state: a fold of 180° has out-of-plane sine
/// 0, and no vertex lies above the plane of any face. Yet a flat-folded sheet (flaps folded onto
/// a face, covering parts of the plane four times) is an isometric realization that is not
/// convex; the only flat convex one (Alexandrov's degenerate case) is a doubly covered convex
/// polygon, whose area is exactly twice its hull's. Two equilateral triangles glued at a
/// quarter-perimeter offset ended in such a flat fold, "converged" at volume 0.
fn folded_flat(x: &[V3], tri: &[Triangulation; 2]) -> bool {
    let (c, size) = centroid_and_radius(x);
    // Normal of the largest triangle; flat when every vertex is within 1e-5·size of its plane
    // (a convex body that thin has an area within O(1e-10) of twice its shadow's, far inside the
    // 1e-6 allowed below, so a thin convex shape is never taken for a fold).
    let mut best = ([0.0; 3], 0.0);
    let mut area = 0.0;
    for t in tri {
        for &[a, b, d] in &t.tris {
            let m = cross(sub(x[b], x[a]), sub(x[d], x[a]));
            let l = norm(m);
            area += 0.5 * l;
            if l > best.1 {
                best = (m, l);
            }
        }
    }
    if best.1 == 0.0 || size == 0.0 {
        return false;
    }
    let u = best.0.map(|v| v / best.1);
    if x.iter().any(|p| dot(u, sub(*p, c)).abs() > 1e-5 * size) {
        return false;
    }
    // In-plane coordinates, then the hull's area (Andrew's monotone chain).
    let e1 = if u[0].abs() < 0.9 { [1.0, 0.0, 0.0] } else { [0.0, 1.0, 0.0] };
    let e1 = { let w = cross(u, e1); let l = norm(w); w.map(|v| v / l) };
    let e2 = cross(u, e1);
    let q: Vec<[f64; 2]> = x.iter().map(|p| [dot(sub(*p, c), e1), dot(sub(*p, c), e2)]).collect();
    // Lexicographic (x, then y) order by two stable argsorts, y first (the crate's one f64 sort,
    // see crate::order).
    let by_y: Vec<[f64; 2]> = crate::order::argsort(&q.iter().map(|p| p[1]).collect::<Vec<_>>()).into_iter().map(|i| q[i]).collect();
    let q: Vec<[f64; 2]> = crate::order::argsort(&by_y.iter().map(|p| p[0]).collect::<Vec<_>>()).into_iter().map(|i| by_y[i]).collect();
    let mut hull: Vec<[f64; 2]> = Vec::with_capacity(2 * q.len());
    for pass in 0..2 {
        let start = hull.len();
        let it: Box<dyn Iterator<Item = &[f64; 2]>> = if pass == 0 { Box::new(q.iter()) } else { Box::new(q.iter().rev()) };
        for &p in it {
            while hull.len() >= start + 2 && metric::orient(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0 {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    let h2: f64 = (0..hull.len()).map(|m| metric::orient([0.0, 0.0], hull[m], hull[(m + 1) % hull.len()])).sum();
    area > (1.0 + 1e-6) * h2.abs()
}

/// Largest height of a vertex above the plane of a face (outward), relative to the largest
/// distance of a vertex from the centroid: 0 for a convex mesh. Every `stride`-th vertex is
/// tested against every face.
///
/// No reflex chord is not enough: every chord can fold outward while the surface as a whole is
/// not convex (a locally convex but not embedded realization). A triangle glued to a circle ended
/// there, converged and with no reflex chord, 2 % below the convex shape's volume and with
/// vertices a whole size outside some face's plane. A closed surface that is convex at every
/// edge and embedded is convex (Hadamard), so the two tests together rule out such branches.
fn outside(x: &[V3], tri: &[Triangulation; 2], stride: usize) -> f64 {
    let (_, size) = centroid_and_radius(x);
    let mut worst = 0.0f64;
    for (p, t) in tri.iter().enumerate() {
        for &[a, b, c] in &t.tris {
            let (b, c) = if p == 0 { (b, c) } else { (c, b) };
            let m = cross(sub(x[b], x[a]), sub(x[c], x[a]));
            let l = norm(m);
            if l == 0.0 {
                continue;
            }
            let top = x.iter().step_by(stride.max(1)).map(|q| dot(m, sub(*q, x[a]))).fold(0.0, f64::max);
            worst = worst.max(top / l);
        }
    }
    if size > 0.0 { worst / size } else { 0.0 }
}

/// [`outside`] for the solver's loops: against every face, 32 vertices spread along the seam.
/// The test is for whole-shape failures (a vertex a sizeable fraction of the size outside), which
/// no 32 of them all miss, and it keeps the cost at 32·(2n − 4) plane tests, nothing next to a
/// solver step.
fn outside_sampled(x: &[V3], tri: &[Triangulation; 2]) -> f64 {
    outside(x, tri, x.len() / 32)
}

/// Whether every vertex (not only [`outside_sampled`]'s 32) is within [`OUTSIDE_TOL`] of every
/// face: the test of a finest-level answer before it is called converged, run once per answer
/// (2n² plane tests). A nearly flat form (a 24-gon or a 48-gon glued to a circle, nearly
/// congruent pieces) can fold a rim face up so that a few vertices stand a whole size above its
/// plane while the 32 sampled ones do not: such shapes "converged" at 64 and 128 seam vertices
/// with 32–40 reflex chords and a vertex 1.8 sizes outside a face.
fn convex_as_a_whole(x: &[V3], tri: &[Triangulation; 2]) -> bool {
    outside(x, tri, 1) <= OUTSIDE_TOL
}

/// Relative height above a face (see [`outside`]) that makes a solution non-convex: far above the
/// tiny folds that coarse levels keep (see [`DENT_SINE`]).
const OUTSIDE_TOL: f64 = 1e-2;

/// Steps allowed to a [`cone_restart`], on top of the level's own (it runs only after a level
/// failed, and from a start that is exact up to the cone points' error it needs a few dozen).
const CONE_BUDGET: usize = 300;

/// Places every seam sample between two neighbouring cone points on the straight segment
/// between their positions, by arc length (see [`cone_restart`]).
fn reseat(pieces: &SeamPieces, cones: &[usize], x: &mut [V3]) {
    let n = pieces.n;
    for (m, &c0) in cones.iter().enumerate() {
        let c1 = cones[(m + 1) % cones.len()];
        let span = pieces.chord(0, c0, c1);
        let mut k = (c0 + 1) % n;
        while k != c1 && span > 0.0 {
            let t = pieces.chord(0, c0, k) / span;
            x[k] = [0, 1, 2].map(|a| x[c0][a] + t * (x[c1][a] - x[c0][a]));
            k = (k + 1) % n;
        }
    }
}

/// Largest strain of the cone triangulation at the positions a [`cone_restart`] starts from:
/// it restarts a shape that is isometric but for its folds, not a wrong branch.
const CONE_NEAR: f64 = 1e-3;

/// The restart of a polyhedral gluing (two polygons) from the creases of the convex hull of its
/// cone points ([`super::hull::cone_triangulations`]), relaxed from `x`: the positions, the
/// triangulations and whether it converged, when it is good ([`is_good`]); else `None`.
fn cone_restart(pieces: &SeamPieces, x: &[V3], budget: usize, step_tol: f64, steps: &mut (usize, usize)) -> Option<(Vec<V3>, [Triangulation; 2], bool)> {
    let cones = super::hull::cone_vertices(pieces)?;
    let pre = max_strain(x, &bars(pieces, &super::hull::cone_triangulations(x, pieces)?));
    if pre > CONE_NEAR {
        return None;
    }
    // Between two cone points that are neighbours along the seam both pieces are straight. When
    // every crease of the polyhedron is a chord of one piece between cone points (the case
    // [`super::hull::cone_triangulations`] builds for), no crease meets that stretch inside, so
    // it lies on the boundary of one face of each piece: a straight segment in 3D, its samples
    // evenly spread by arc length. Re-seating them there takes out the folds across flat faces
    // ("popped" strips between a cone and two samples of a straight side, continued across the
    // seam) that the fans from a cone to collinear samples keep: their chords cannot be flipped
    // (the quad has three collinear vertices) and the folded strip is itself isometric, so
    // Gauss–Newton stays in it (a 90×10 rectangle with a square: strain 1.2e-7 and two reflex
    // chords after 5000 steps). Where a crease does cross the seam this is only a start, and
    // [`is_good`] judges the result like any other.
    let mut xc = x.to_vec();
    reseat(pieces, &cones, &mut xc);
    let mut t = super::hull::cone_triangulations(&xc, pieces)?;
    let r = relax(pieces, &mut xc, &mut t, budget, step_tol, Orientation::Kept).tally(steps);
    is_good(&xc, &t, r.converged).then_some((xc, t, r.converged))
}

/// Step budgets of the multistart on the cone points alone ([`solve_polyhedral`]): a handful of
/// vertices, so every start and its hull restart are cheap.
const CONES: Patience = Patience { attempt: 300, level: 300, cap: 3000, hull: true };

/// A polyhedral gluing (two polygons, see [`super::hull::cone_vertices`]) solved on its cone
/// points alone, then laid onto the seam samples.
///
/// By Alexandrov's gluing theorem the D-form of two convex polygons is the convex polyhedron
/// whose vertices are the cone points of the glued metric (the corners; every other seam point
/// has total angle 2π), unique up to isometry (Pogorelov). The seam between two neighbouring
/// cone points is straight in both pieces, so the metric is already the polyhedral metric of the
/// *cone points* as seam vertices: the same isometry equations with a few vertices instead of
/// `n`, where no sample sits on a flat face or a straight crease. There the multistart and the
/// hull restarts ([`super::hull::triangulations`]) work as for a smooth seam, while at `n`
/// samples the flat faces make every dihedral sign between coplanar triangles round-off and the
/// starts end on folded, isometric but non-convex branches (two equilateral triangles at an
/// offset: 14 reflex chords at strain 3e-10; a triangle with a square: strain 9 %). Its solution
/// then places every sample ([`cone_restart`], which keeps only a good result). A cold solve of a
/// polygon pair tries this first: a handful of vertices take a few dozen steps in all (two
/// 80×20 and 60×40 rectangles at a quarter offset took ~1,500 steps on the samples), and when it
/// finds nothing convex the ladder runs as for any other gluing.
///
/// A crease of the polyhedron (a shortest path between two cone points) need not be a chord of
/// either piece: it can run from a corner across one piece, cross the seam at a flat point and
/// go on across the other (straight in the unfolding of the two pieces along the seam). Then no
/// realization on the cone points alone is convex (two equilateral triangles at a quarter
/// offset: every start, and every one of the 196 pairs of triangulations of the six corners,
/// ended locally convex but not convex), and no sampling that misses the crossing holds the
/// polyhedron. Those crossings ([`seam_crossings`]) are then added as seam vertices: the gluing
/// on corners and crossings is solved (from the mismatch starts in convex position,
/// [`on_sphere`]), and laid onto the samples with the nearest sample moved onto each crossing
/// ([`lay_on`]). The returned pieces are then `pieces` with those samples moved (each the
/// nearest free sample of its stretch, along a side that is straight in both pieces), so the
/// mesh is exact.
fn solve_polyhedral(pieces: &SeamPieces, cap: usize, steps: &mut (usize, usize)) -> Option<(SeamPieces, Vec<V3>, [Triangulation; 2], bool)> {
    let cones = super::hull::cone_vertices(pieces)?;
    let k = cones.len();
    let seat = |idx: &[(usize, f64)]| -> SeamPieces {
        let piece = |p: usize| {
            let f = &pieces.flat[p];
            let pts: Vec<[f64; 2]> = idx.iter().map(|&(m, t)| on_side(f, &cones, m, t)).collect();
            let q = pts.len();
            let arc_mid = (0..q).map(|m| [0.5 * (pts[m][0] + pts[(m + 1) % q][0]), 0.5 * (pts[m][1] + pts[(m + 1) % q][1])]).collect();
            super::seam::FlatPiece { pts, arc_mid, area: f.area, perimeter: f.perimeter }
        };
        SeamPieces { n: idx.len(), flat: [piece(0), piece(1)] }
    };
    let corners: Vec<(usize, f64)> = (0..k).map(|m| (m, 0.0)).collect();
    let small = seat(&corners);
    let tri = [triangulate(&small, 0).ok()?, triangulate(&small, 1).ok()?];
    let patience = Patience { cap: CONES.cap.min(cap.saturating_sub(steps.0)) + steps.0, ..CONES };
    // (The third field is "good" for a good start, else only "converged": judge it here.)
    let (xs, ts, converged, _) = multistart(&small, &tri, 0, STEP_TOL, patience, steps)?;
    if is_good(&xs, &ts, converged) {
        return lay_on(pieces, &corners, &cones, &xs, &ts, cap, steps);
    }
    // No convex polyhedron with every crease a chord of one piece: add the seam points where the
    // shortest paths between cone points cross the seam ([`seam_crossings`]) as vertices.
    let crossings = seam_crossings(&small);
    if crossings.is_empty() {
        return None;
    }
    let mut idx = corners;
    idx.extend(crossings.iter().map(|c| (c.0, c.1)));
    // In seam order (stretch, then fraction; through [`crate::order`], one sort instantiation).
    let keys: Vec<f64> = idx.iter().map(|&(m, t)| m as f64 + t).collect();
    let mut idx: Vec<(usize, f64)> = crate::order::argsort(&keys).into_iter().map(|i| idx[i]).collect();
    idx.dedup();
    let big = seat(&idx);
    // The start's triangulations hold each crossing path as two chords, i–X of p and X–j of q.
    let at = |m: usize, t: f64| idx.iter().position(|&(a, b)| a == m && b == t);
    let mut chords: [Vec<(usize, usize)>; 2] = [Vec::new(), Vec::new()];
    for &(m, t, i, j, p) in &crossings {
        let x = at(m, t)?;
        for (q, a) in [(p, at(i, 0.0)?), (1 - p, at(j, 0.0)?)] {
            let e = (a.min(x), a.max(x));
            let crossing = chords[q].iter().any(|&(u, v)| (e.0 < u && u < e.1 && e.1 < v) || (u < e.0 && e.0 < v && v < e.1));
            if !metric::is_seam(big.n, e.0, e.1) && !chords[q].contains(&e) && !crossing {
                chords[q].push(e);
            }
        }
    }
    let tri = super::hull::cut_along(&big, &chords)?;
    // From the mismatch starts pushed onto a sphere (see [`on_sphere`]).
    for start in [Start::Mismatch(1.0), Start::Mismatch(2.0)] {
        let budget = CONES.attempt.min(cap.saturating_sub(steps.0));
        if budget == 0 {
            return None;
        }
        let (mut x, mut t) = (on_sphere(initial_guess(&big, start)), tri.clone());
        let r = relax(&big, &mut x, &mut t, budget, STEP_TOL, Orientation::Free).tally(steps);
        if is_good(&x, &t, r.converged) {
            return lay_on(pieces, &idx, &cones, &x, &t, cap, steps);
        }
    }
    None
}

/// Lays the solution `xs`, `ts` on the seam points `idx` of `pieces` (cone point `m` and the
/// fraction along the stretch after it, see [`solve_polyhedral`]) onto `pieces`, and relaxes it
/// there: on the cone points alone by [`cone_restart`]; with seam crossings, with the nearest
/// sample of each crossing's stretch moved onto it, every sample on the straight segment
/// between its neighbouring seam points ([`reseat`]) and each piece cut along the chords of
/// `ts`, so that every triangle lies in one face of the polyhedron and the start is exact up to
/// round-off. The pieces with the moved samples, the positions, the triangulations and whether
/// it converged, when it is good ([`is_good`]); else `None`.
fn lay_on(
    pieces: &SeamPieces,
    idx: &[(usize, f64)],
    cones: &[usize],
    xs: &[V3],
    ts: &[Triangulation; 2],
    cap: usize,
    steps: &mut (usize, usize),
) -> Option<(SeamPieces, Vec<V3>, [Triangulation; 2], bool)> {
    let n = pieces.n;
    if idx.len() == cones.len() {
        let mut x = vec![[0.0; 3]; n];
        for (m, &c) in cones.iter().enumerate() {
            x[c] = xs[m];
        }
        reseat(pieces, cones, &mut x);
        let budget = CONE_BUDGET.min(cap.saturating_sub(steps.0));
        return cone_restart(pieces, &x, budget, STEP_TOL, steps).map(|(x, t, c)| (pieces.clone(), x, t, c));
    }
    // Each extra seam point takes the nearest free sample of its stretch (in order), moved onto
    // it in both pieces (both straight there, so the sample polygons stay convex).
    let mut moved = pieces.clone();
    let mut at = Vec::with_capacity(idx.len());
    let mut last = None::<usize>;
    for &(m, t) in idx {
        if t == 0.0 {
            at.push(cones[m]);
            last = Some(cones[m]);
            continue;
        }
        let (c0, c1) = (cones[m], cones[(m + 1) % cones.len()]);
        let span = pieces.chord(0, c0, c1);
        let mut best: Option<(usize, f64)> = None;
        let mut s = (c0 + 1) % n;
        while s != c1 {
            let free = last.is_none_or(|l| l == c0 || (s + n - c0) % n > (l + n - c0) % n);
            let d = (pieces.chord(0, c0, s) / span - t).abs();
            if free && best.is_none_or(|b| d < b.1) {
                best = Some((s, d));
            }
            s = (s + 1) % n;
        }
        let (s, _) = best?;
        for p in 0..2 {
            moved.flat[p].pts[s] = on_side(&pieces.flat[p], cones, m, t);
        }
        at.push(s);
        last = Some(s);
    }
    for p in 0..2 {
        let f = &mut moved.flat[p];
        f.arc_mid = (0..n).map(|m| [0.5 * (f.pts[m][0] + f.pts[(m + 1) % n][0]), 0.5 * (f.pts[m][1] + f.pts[(m + 1) % n][1])]).collect();
    }
    // Every sample on the straight segment between its neighbouring seam points of `small`, and
    // each piece cut along `small`'s chords: every triangle then lies in a face.
    let mut sorted = at.clone();
    crate::order::sort_dedup(&mut sorted);
    let mut x = vec![[0.0; 3]; n];
    for (m, &s) in at.iter().enumerate() {
        x[s] = xs[m];
    }
    reseat(&moved, &sorted, &mut x);
    let chords = [0, 1].map(|p| ts[p].chords().into_iter().map(|(u, v)| (at[u], at[v])).collect::<Vec<_>>());
    let mut t = super::hull::cut_along(&moved, &chords)?;
    let budget = CONE_BUDGET.min(cap.saturating_sub(steps.0));
    let r = relax(&moved, &mut x, &mut t, budget, STEP_TOL, Orientation::Kept).tally(steps);
    is_good(&x, &t, r.converged).then_some((moved, x, t, r.converged))
}

/// The point of piece `f` a fraction `t` along the straight seam stretch from cone point `m` to
/// the next one (`cones` are sample indices of `f`).
fn on_side(f: &super::seam::FlatPiece, cones: &[usize], m: usize, t: f64) -> [f64; 2] {
    let (a, b) = (f.pts[cones[m]], f.pts[cones[(m + 1) % cones.len()]]);
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
}

/// The seam points, as (stretch, fraction) with the stretches between neighbouring cone points
/// of `small` (the gluing on its cone points alone), where a shortest path between two cone
/// points crosses the seam once.
///
/// The edges of Alexandrov's polyhedron are shortest paths between cone points. Such a path is
/// straight in each piece, and across the seam it is straight in the *unfolding*: the other
/// piece laid along the common stretch, on the far side. A path from cone point i in piece p
/// to cone point j in piece q = 1 − p crossing stretch S once is therefore the segment from i
/// to the image of j under the isometry that lays q's copy of S onto p's with q's interior on
/// the other side; it crosses S inside when the segment does, and (both pieces convex) it then
/// lies in p up to S and in q beyond. When for some pair that path is shorter than both
/// pieces' chords from i to j, no chord can be the crease between them (see [`excess`]), and
/// a crease there crosses the seam at a flat point no cone-point mesh holds: two triangles at
/// a quarter offset and a triangle with a square at 0.41 have no convex realization on their
/// corners alone. With such a crossing as an extra (flat) seam vertex the crease is the
/// chords i–X of p and X–j of q, and the polyhedron is exact again.
fn seam_crossings(small: &SeamPieces) -> Vec<(usize, f64, usize, usize, usize)> {
    let k = small.n;
    let mut out: Vec<(usize, f64, usize, usize, usize)> = Vec::new();
    for i in 0..k {
        for j in i + 2..k {
            if (j + 1) % k == i {
                continue;
            }
            let mut best = small.chord(0, i, j).min(small.chord(1, i, j)) * (1.0 - 1e-9);
            let mut at = None;
            for p in 0..2 {
                for m in 0..k {
                    if let Some((len, t)) = crossing(small, i, j, p, m) {
                        if len < best {
                            best = len;
                            at = Some((m, t, i, j, p));
                        }
                    }
                }
            }
            if let Some(c) = at {
                if let Some(o) = out.iter().find(|o| o.0 == c.0 && (o.1 - c.1).abs() < 1e-9) {
                    let t = o.1;
                    out.push((c.0, t, c.2, c.3, c.4));
                } else {
                    out.push(c);
                }
            }
        }
    }
    out
}

/// The path from seam vertex `i` in piece `p` to `j` in the other piece that crosses the seam
/// once, inside stretch `m` (from vertex m to m + 1), straight in the unfolding (see
/// [`seam_crossings`]): its length and the fraction along the stretch where it crosses.
fn crossing(small: &SeamPieces, i: usize, j: usize, p: usize, m: usize) -> Option<(f64, f64)> {
    let k = small.n;
    let (fp, fq) = (&small.flat[p].pts, &small.flat[1 - p].pts);
    let m1 = (m + 1) % k;
    if [m, m1].contains(&i) || [m, m1].contains(&j) {
        return None;
    }
    let (s0, s1, r0, r1) = (fp[m], fp[m1], fq[m], fq[m1]);
    let (ls, lr) = ((s1[0] - s0[0]).hypot(s1[1] - s0[1]), (r1[0] - r0[0]).hypot(r1[1] - r0[1]));
    if ls == 0.0 || lr == 0.0 {
        return None;
    }
    let es = [(s1[0] - s0[0]) / ls, (s1[1] - s0[1]) / ls];
    let er = [(r1[0] - r0[0]) / lr, (r1[1] - r0[1]) / lr];
    let y = [fq[j][0] - r0[0], fq[j][1] - r0[1]];
    let (al, be) = (y[0] * er[0] + y[1] * er[1], er[0] * y[1] - er[1] * y[0]);
    // q's interior (left of r0→r1) goes to the right of s0→s1.
    let qj = [s0[0] + al * es[0] + be * es[1], s0[1] + al * es[1] - be * es[0]];
    let pi = fp[i];
    let len = (qj[0] - pi[0]).hypot(qj[1] - pi[1]);
    // Where segment pi→qj meets the line s0→s1 (fraction t along it).
    let (o1, o2) = (metric::orient(s0, s1, pi), metric::orient(s0, s1, qj));
    if !(o1 > 0.0 && o2 < 0.0) {
        return None;
    }
    let u = o1 / (o1 - o2);
    let x = [pi[0] + u * (qj[0] - pi[0]), pi[1] + u * (qj[1] - pi[1])];
    let t = ((x[0] - s0[0]) * es[0] + (x[1] - s0[1]) * es[1]) / ls;
    (t > 1e-6 && t < 1.0 - 1e-6).then_some((len, t))
}

/// Finds the seam positions at `options.resolution` seam vertices, from the warm start or cold
/// (see [`solve_cold`]). Never panics; an input that cannot even be triangulated is an error.
pub fn solve(glue: &Glue, options: &SimulateOptions) -> Result<(SeamPieces, Solution)> {
    let Some(w) = &options.warm else { return solve_cold(glue, options) };
    // A warm start: a previous result's vertices, already outward (never mirrored).
    let pieces = glue.sample(options.resolution);
    // Plain ear clipping, not [`triangulate`]: the warm positions decide the flips.
    let mut tri = [ear_clip(&pieces, 0)?, ear_clip(&pieces, 1)?];
    let mut x = resample(w, pieces.n);
    let r = relax(&pieces, &mut x, &mut tri, options.max_iterations.min(WARM_BUDGET).max(1), STEP_TOL, Orientation::Kept);
    if is_good(&x, &tri, r.converged) && exact_if_polyhedral(&pieces, &x, &tri) && convex_as_a_whole(&x, &tri) {
        let solution = Solution { x, tri, iterations: r.iterations, flips: r.flips, converged: true };
        return Ok((pieces, solution));
    }
    // A warm start that leads nowhere convex (e.g. the vertices of another shape, which can pull
    // the solver into an isometric but dented branch) is dropped for a cold solve rather than
    // returned. "Convex" allows the tiny reflex folds that coarse resolutions keep (the cold
    // solve keeps them too), not a dent.
    // The cold solve gets what is left of the user's `max_iterations`.
    let left = options.max_iterations.saturating_sub(r.iterations);
    if left == 0 {
        let converged = r.converged && exact_if_polyhedral(&pieces, &x, &tri) && convex_as_a_whole(&x, &tri);
        return Ok((pieces, Solution { x, tri, iterations: r.iterations, flips: r.flips, converged }));
    }
    let cold = SimulateOptions { warm: None, max_iterations: left, ..options.clone() };
    let (p, mut sol) = solve_cold(glue, &cold)?;
    sol.iterations += r.iterations;
    sol.flips += r.flips;
    Ok((p, sol))
}

/// Multistart on the coarsest level (cheap), trying the starts `LIFTS[from..]`: the
/// start decides which isometric branch Gauss–Newton falls into; the first converged one
/// without a dent is kept (coarse levels keep tiny reflex folds, see DENT_SINE, which the finer
/// levels flip away), else the one of least strain. Returns it, whether it is good, and the
/// index of the next height to try (`LIFTS.len()` once a start failed to be good: all were tried).
fn multistart(
    pieces: &SeamPieces,
    tri: &[Triangulation; 2],
    from: usize,
    step_tol: f64,
    patience: Patience,
    steps: &mut (usize, usize),
) -> Option<(Vec<V3>, [Triangulation; 2], bool, usize)> {
    let mut best: Option<(Vec<V3>, [Triangulation; 2], bool, usize, f64)> = None;
    for (k, &lift) in LIFTS.iter().enumerate().skip(from) {
        let (mut x, mut t) = (initial_guess(pieces, lift), tri.clone());
        let budget = patience.cap.saturating_sub(steps.0).min(patience.attempt);
        let r = relax(pieces, &mut x, &mut t, budget, step_tol, Orientation::Free).tally(steps);
        let mut strain = max_strain(&x, &bars(pieces, &t));
        let mut good = is_good(&x, &t, r.converged || (step_tol > STEP_TOL && strain <= LEVEL_STRAIN_TOL));
        let mut converged = r.converged;
        // A failed start: restart it from the convex hull of where it ended, whose chords the
        // local flips could not reach ([`super::hull`]).
        if !good && patience.hull && steps.0 < patience.cap {
            if let Some(mut th) = super::hull::triangulations(&x, pieces) {
                let mut xh = x.clone();
                let budget = patience.cap.saturating_sub(steps.0).min(patience.attempt);
                let rh = relax(pieces, &mut xh, &mut th, budget, step_tol, Orientation::Kept).tally(steps);
                let sh = max_strain(&xh, &bars(pieces, &th));
                if sh < strain {
                    (x, t, strain, converged) = (xh, th, sh, rh.converged);
                    good = is_good(&x, &t, converged || (step_tol > STEP_TOL && strain <= LEVEL_STRAIN_TOL));
                }
            }
        }
        if good {
            return Some((x, t, true, k + 1));
        }
        if best.as_ref().is_none_or(|b| strain < b.4) {
            best = Some((x, t, converged, k, strain));
        }
        if steps.0 >= patience.cap {
            break;
        }
    }
    best.map(|(x, t, converged, _, _)| (x, t, converged, LIFTS.len()))
}

/// A cold solve: multistart on the coarsest level (32 seam vertices), then each finer level
/// (64, 128, …) laid onto the last ([`upsample`]) and relaxed. Near-ties in the flips (chords
/// between nearly coplanar triangles) can tip a level into a wrong isometric branch that does
/// not converge; which way a tie tips depends on the last bits of libm (WASM and native
/// differ). So a branch whose level needs more than its budget of steps ([`QUICK`]), or ends unconverged
/// or dented, is abandoned and the whole coarse-to-fine path is retried from the next saddle
/// height. When no height gives a good start on the coarsest level (at some offsets the 32-gon's
/// only reachable branch is a collapsed one, strain ≈ 0.1), the ladder starts one level finer
/// (64, …). The last height of the last rung (or the last of the step budget) runs to the end.
/// The answer is the first good branch, else the best one that reached the finest level
/// (converged first, then least strain). Deterministic: heights and rungs in a fixed order.
/// All of this runs first with the [`QUICK`] budgets; only when that finds no good branch does
/// it run again with the [`PATIENT`] ones, up to `max_iterations` steps in all.
fn solve_cold(glue: &Glue, options: &SimulateOptions) -> Result<(SeamPieces, Solution)> {
    let n = options.resolution;
    let mut levels = vec![n];
    while levels[levels.len() - 1] % 2 == 0 && glue.nests(levels[levels.len() - 1] / 2) {
        levels.push(levels[levels.len() - 1] / 2);
    }
    levels.reverse();
    let mut samples: Vec<SeamPieces> = levels.iter().map(|&m| glue.sample(m)).collect();
    let mut steps = (0usize, 0usize);
    let cap = options.max_iterations;
    let quick = Patience { cap: QUICK.cap.min(cap), ..QUICK };
    // A polygon pair is solved on its corners first (see [`solve_polyhedral`]); a solution with
    // seam crossings comes with the finest level's samples moved onto them.
    let mut best = None;
    let mut polyhedral = false;
    if let Some((moved, x, tri, converged)) = solve_polyhedral(&samples[samples.len() - 1], cap, &mut steps) {
        let pieces = samples.last_mut().expect("a level");
        *pieces = moved;
        best = Some((x, tri, converged, true));
        polyhedral = true;
    }
    if best.is_none() {
        best = ladder(&samples, &levels, quick, &mut steps)?;
    }
    if !best.as_ref().is_some_and(|b| b.3) && steps.0 < cap {
        let patient = ladder(&samples, &levels, Patience { cap, ..PATIENT }, &mut steps)?;
        if let Some(p) = patient {
            // Good first, then without a dent (a converged but dented shape is a wrong isometric
            // branch, further from the truth than an unconverged convex one), then converged,
            // then least strain.
            let rank = |b: &Branch| {
                let undented = worst_reflex(&b.0, &b.1) <= DENT_SINE;
                (b.3, undented, b.2, -max_strain(&b.0, &bars(&samples[samples.len() - 1], &b.1)))
            };
            if best.as_ref().is_none_or(|b| rank(&p) > rank(b)) {
                best = Some(p);
            }
        }
    }
    let (Some((x, tri, converged, good)), Some(pieces)) = (best, samples.into_iter().last()) else {
        return Err(Error::Infeasible { reason: "No start could be tried.".into() });
    };
    // Only the exact polyhedron is a converged polyhedral gluing (see [`exact_if_polyhedral`]),
    // and only a shape convex as a whole is converged (a good branch of the ladder was tested).
    let checked = good && !polyhedral;
    let converged = converged && exact_if_polyhedral(&pieces, &x, &tri) && (checked || convex_as_a_whole(&x, &tri));
    Ok((pieces, Solution { x, tri, iterations: steps.0, flips: steps.1, converged }))
}

/// A finest-level branch: positions, triangulations, converged, good (converged without a dent).
type Branch = (Vec<V3>, [Triangulation; 2], bool, bool);

/// One pass of the coarse-to-fine ladder with the step budgets of `patience` (see [`solve_cold`]):
/// the first good branch, else the best one that reached the finest level.
fn ladder(samples: &[SeamPieces], levels: &[usize], patience: Patience, steps: &mut (usize, usize)) -> Result<Option<Branch>> {
    let mut best: Option<(Vec<V3>, [Triangulation; 2], bool, f64)> = None;
    // Coarsest level of the ladder: 32 first; when no height gives a good start there (a
    // polygon that coarse can make a wrong branch the only one within reach), 64, and so on.
    'ladder: for first in 0..levels.len() {
        let coarse_tri = [triangulate(&samples[first], 0)?, triangulate(&samples[first], 1)?];
        let coarse_tol = if first + 1 == levels.len() { STEP_TOL } else { 1e-6 };
        let final_rung = first + 1 == levels.len();
        let mut from = 0;
        while from < LIFTS.len() {
            let Some((mut x, mut tri, mut converged, next)) =
                multistart(&samples[first], &coarse_tri, from, coarse_tol, patience, steps)
            else {
                break;
            };
            from = next;
            let out_of_steps = steps.0 >= patience.cap;
            if from >= LIFTS.len() && !final_rung && !out_of_steps {
                // No good start on this rung: climb to the next one.
                continue 'ladder;
            }
            let mut abandoned = false;
            for li in first + 1..levels.len() {
                let (pc, pf) = (&samples[li - 1], &samples[li]);
                let mut tf = [refine(&tri, pf, 0)?, refine(&tri, pf, 1)?];
                let mut xf = upsample(pc, &x, &tri, pf);
                let remaining = patience.cap.saturating_sub(steps.0);
                let retry = (from < LIFTS.len() || !final_rung) && remaining > 0;
                let full = if retry { remaining.min(patience.level) } else { remaining };
                // A polyhedral gluing gets the cone restart ([`cone_restart`]) after at most a
                // level's budget, then (on the last try) the rest of the steps.
                let polyhedral = super::hull::cone_vertices(pf).is_some();
                let budget = if polyhedral { full.min(patience.level) } else { full };
                let last = li + 1 == levels.len();
                let tol = if last { STEP_TOL } else { 1e-6 };
                let r = relax(pf, &mut xf, &mut tf, budget, tol, Orientation::Kept).tally(steps);
                (x, tri, converged) = (xf, tf, r.converged);
                let mut loose = !last && max_strain(&x, &bars(pf, &tri)) <= LEVEL_STRAIN_TOL;
                if polyhedral && !is_good(&x, &tri, converged || loose) {
                    // Within the cap, like every other step (`max_iterations` is the user's).
                    let left = CONE_BUDGET.min(patience.level).min(patience.cap.saturating_sub(steps.0));
                    if let Some(c) = (left > 0).then(|| cone_restart(pf, &x, left, tol, steps)).flatten() {
                        (x, tri, converged) = c;
                        loose = false;
                    } else if full > r.iterations {
                        let r = relax(pf, &mut x, &mut tri, full - r.iterations, tol, Orientation::Kept).tally(steps);
                        converged = r.converged;
                        loose = !last && max_strain(&x, &bars(pf, &tri)) <= LEVEL_STRAIN_TOL;
                    }
                }
                if retry && !is_good(&x, &tri, converged || loose) {
                    abandoned = true;
                    break;
                }
            }
            if abandoned {
                continue;
            }
            let pieces = &samples[levels.len() - 1];
            if is_good(&x, &tri, converged) && exact_if_polyhedral(pieces, &x, &tri) && convex_as_a_whole(&x, &tri) {
                return Ok(Some((x, tri, true, true)));
            }
            let strain = max_strain(&x, &bars(pieces, &tri));
            if best.as_ref().is_none_or(|b| (converged, -strain) > (b.2, -b.3)) {
                best = Some((x, tri, converged, strain));
            }
            if steps.0 >= patience.cap {
                break 'ladder;
            }
        }
    }
    Ok(best.map(|(x, tri, converged, _)| (x, tri, converged, false)))
}

/// `x` pushed radially onto the sphere about its centroid of its RMS radius: points in convex
/// position. The gluing of two equilateral triangles at a quarter offset on its corners and
/// seam crossings ([`seam_crossings`]), relaxed with flips from each of the 196 pairs of
/// triangulations with no chord longer than the other piece's, reached the convex polyhedron
/// from the mismatch start pushed onto the sphere every time (in ~15 steps), from the plain
/// mismatch start never, and from the saddle and fourfold starts in 3–11 of 196.
fn on_sphere(mut x: Vec<V3>) -> Vec<V3> {
    let c = centroid(&x);
    let r = size(&x);
    for p in x.iter_mut() {
        let d = sub(*p, c);
        let l = norm(d);
        if l > 0.0 {
            *p = [0, 1, 2].map(|a| c[a] + d[a] * r / l);
        }
    }
    x
}
