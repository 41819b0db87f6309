//! Levenberg–Marquardt on the isometry equations of the seam-vertex polyhedron, with flips of
//! reflex chords towards the convex realization (see the module docs of [`super`]).

use super::metric::{self, Triangulation};
use super::options::SimulateOptions;
use super::seam::SeamPieces;
use crate::error::{Error, Result};
use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, Triplet};
use faer::{Mat, Side};

/// Out-of-plane sine above which a chord counts as reflex and is flipped. Below it the two
/// triangles are coplanar to round-off and either diagonal is right.
pub const REFLEX_SINE: f64 = 1e-9;

/// A step shorter than this (relative to the shape's size) ends the iteration.
const STEP_TOL: f64 = 1e-11;

/// Largest strain accepted as "converged" on top of the seam's own A/B chord mismatch.
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

type V3 = [f64; 3];

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// One length equation: |x_i − x_j| = d.
#[derive(Debug, Clone, Copy)]
struct Bar {
    i: usize,
    j: usize,
    d: f64,
}

fn bars(pieces: &SeamPieces, tri: &[Triangulation; 2]) -> Vec<Bar> {
    let mut out = Vec::with_capacity(4 * pieces.n);
    for (p, t) in tri.iter().enumerate() {
        for (i, j) in t.edges() {
            let d = pieces.chord(p, i, j);
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

/// Size scale of a point set (RMS distance to the centroid).
fn size(x: &[V3]) -> f64 {
    let n = x.len() as f64;
    let c = x.iter().fold([0.0; 3], |s, p| [s[0] + p[0] / n, s[1] + p[1] / n, s[2] + p[2] / n]);
    (x.iter().map(|p| dot(sub(*p, c), sub(*p, c))).sum::<f64>() / n).sqrt()
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

/// Makes the mesh outward-oriented (positive volume) by mirroring, an isometry, then flips every
/// reflex chord whose flat quad allows it. Returns the number of flips.
fn flip_pass(x: &mut [V3], tri: &mut [Triangulation; 2], pieces: &SeamPieces) -> usize {
    if signed_volume(x, tri) < 0.0 {
        for p in x.iter_mut() {
            p[2] = -p[2];
        }
    }
    let mut flips = 0;
    for p in 0..2 {
        let pts = &pieces.flat[p].pts;
        let s2 = metric::size2(pts);
        for (i, j) in tri[p].chords() {
            if let Some(s) = reflex_sine(x, &tri[p], p, i, j) {
                if s > REFLEX_SINE && tri[p].flip(i, j, pts, s2) {
                    flips += 1;
                }
            }
        }
    }
    flips
}

/// Initial positions: the two flat polygons rigidly aligned (Procrustes) and averaged, lifted
/// into the saddle that the chord mismatch asks for. Where A's chords are longer than B's, A
/// (the top sheet, outward normal +z) must bulge across them, which puts the seam low at their
/// ends: z = −s·(ĉᵀ M̃ ĉ) with M̃ the trace-free part of Σ (d_A² − d_B²) û ûᵀ.
/// Congruent pieces glued congruently give M̃ = 0: the flat, doubly covered start, which is
/// already the solution.
fn initial_guess(pieces: &SeamPieces) -> Vec<V3> {
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
    flat.iter()
        .map(|p| {
            let q = (hx * (p[0] * p[0] - p[1] * p[1]) + 2.0 * hxy * p[0] * p[1]) / lam.max(f64::MIN_POSITIVE);
            [p[0], p[1], -amp * q]
        })
        .collect()
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

/// Solves one damped Gauss–Newton step `(JᵀJ + λ·μ I) Δ = −Jᵀr`; `None` if the factorization
/// fails (then the caller raises λ).
fn step(x: &[V3], bars: &[Bar], lambda: f64) -> Option<Vec<f64>> {
    let n3 = 3 * x.len();
    let mut trip: Vec<Triplet<usize, usize, f64>> = Vec::with_capacity(bars.len() * 21 + n3);
    let mut g = vec![0.0; n3];
    let mut diag = vec![0.0; n3];
    for b in bars {
        let e = sub(x[b.j], x[b.i]);
        let l = norm(e);
        let u = if l > 0.0 { [e[0] / l, e[1] / l, e[2] / l] } else { [1.0, 0.0, 0.0] };
        let r = l / b.d - 1.0;
        let w = 1.0 / (b.d * b.d);
        for a in 0..3 {
            g[3 * b.j + a] += u[a] * r / b.d;
            g[3 * b.i + a] -= u[a] * r / b.d;
            diag[3 * b.i + a] += w * u[a] * u[a];
            diag[3 * b.j + a] += w * u[a] * u[a];
        }
        let (lo, hi) = (b.i.min(b.j), b.i.max(b.j));
        for a in 0..3 {
            for c in 0..3 {
                let v = w * u[a] * u[c];
                // Diagonal blocks: lower triangle only (the diagonal itself comes from `diag`).
                if a > c {
                    trip.push(Triplet::new(3 * b.i + a, 3 * b.i + c, v));
                    trip.push(Triplet::new(3 * b.j + a, 3 * b.j + c, v));
                }
                // Off-diagonal block, rows of the larger vertex.
                trip.push(Triplet::new(3 * hi + a, 3 * lo + c, -v));
            }
        }
    }
    let mu = diag.iter().sum::<f64>() / n3 as f64;
    for (k, d) in diag.iter().enumerate() {
        trip.push(Triplet::new(k, k, d + lambda * mu));
    }
    let h = SparseColMat::<usize, f64>::try_new_from_triplets(n3, n3, &trip).ok()?;
    let llt = h.sp_cholesky(Side::Lower).ok()?;
    let mut rhs = Mat::<f64>::from_fn(n3, 1, |k, _| -g[k]);
    llt.solve_in_place(rhs.as_mut());
    let d: Vec<f64> = (0..n3).map(|k| rhs[(k, 0)]).collect();
    d.iter().all(|v| v.is_finite()).then_some(d)
}

/// Finds the seam positions. Never panics; an input that cannot even be triangulated is an error.
pub fn solve(pieces: &SeamPieces, options: &SimulateOptions) -> Result<Solution> {
    let n = pieces.n;
    let triangulate = |p: usize| {
        metric::ear_clip(&pieces.flat[p].pts).ok_or_else(|| Error::Infeasible {
            reason: format!(
                "The {} piece is too thin or too detailed for {n} seam vertices: its sampled outline cannot be triangulated. Raise the resolution or simplify the outline.",
                if p == 0 { "first" } else { "second" }
            ),
        })
    };
    let mut tri = [triangulate(0)?, triangulate(1)?];
    let mut x = match &options.warm {
        Some(w) => resample(w, n),
        None => initial_guess(pieces),
    };
    // Bring the start's triangulation to the convex one of the start positions.
    let mut flips = 0;
    for _ in 0..n {
        let f = flip_pass(&mut x, &mut tri, pieces);
        flips += f;
        if f == 0 {
            break;
        }
    }
    // Seam chords of A and B differ by the discretization; that part of the residual stays.
    let seam_mismatch = (0..n)
        .map(|k| {
            let (a, b) = (pieces.chord(0, k, (k + 1) % n), pieces.chord(1, k, (k + 1) % n));
            (a - b).abs() / a.min(b).max(f64::MIN_POSITIVE)
        })
        .fold(0.0, f64::max);
    let scale = size(&x).max(f64::MIN_POSITIVE);
    let mut bars = bars(pieces, &tri);
    let mut c = cost(&x, &bars);
    let mut lambda = 1e-4;
    let mut iterations = 0;
    let mut converged = false;
    while iterations < options.max_iterations {
        iterations += 1;
        let Some(d) = step(&x, &bars, lambda) else {
            lambda *= 10.0;
            if lambda > 1e12 {
                break;
            }
            continue;
        };
        let trial: Vec<V3> = (0..n).map(|k| [x[k][0] + d[3 * k], x[k][1] + d[3 * k + 1], x[k][2] + d[3 * k + 2]]).collect();
        let ct = cost(&trial, &bars);
        if !(ct <= c) {
            lambda *= 4.0;
            if lambda > 1e12 {
                break;
            }
            continue;
        }
        let dmax = d.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        x = trial;
        c = ct;
        lambda = (lambda / 3.0).max(1e-12);
        let f = flip_pass(&mut x, &mut tri, pieces);
        flips += f;
        if std::env::var("SIMDBG").is_ok() { eprintln!("it {iterations} cost {c:.3e} lambda {lambda:.1e} dmax {dmax:.2e} flips {f} vol {:.4}", signed_volume(&x, &tri)); }
        if f > 0 {
            bars = self::bars(pieces, &tri);
            c = cost(&x, &bars);
            continue;
        }
        if dmax <= STEP_TOL * scale || c == 0.0 {
            let worst = bars.iter().map(|b| (norm(sub(x[b.j], x[b.i])) / b.d - 1.0).abs()).fold(0.0, f64::max);
            converged = worst <= seam_mismatch + STRAIN_TOL;
            break;
        }
    }
    Ok(Solution { x, tri, iterations, flips, converged })
}
