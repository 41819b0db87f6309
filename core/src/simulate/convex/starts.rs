//! Starting shapes of the multistart: saddles, the fourfold start, the chord-mismatch start, a
//! warm start resampled, a coarser level laid onto a finer one, points pushed onto a sphere.

use crate::libm_ext::LibmExt;
use super::super::metric::Triangulation;
use super::super::seam::SeamPieces;
use super::super::vec3::{centroid, map_affine, norm, size, sub, V3};

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
pub(crate) fn initial_guess(pieces: &SeamPieces, start: Start) -> Vec<V3> {
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
    let th = ss.atan2_m(sc);
    let (c, s) = (th.cos_m(), th.sin_m());
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
            let l = u[0].hypot_m(u[1]);
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
    let lam = hx.hypot_m(hxy);
    let r2 = flat.iter().map(|p| p[0] * p[0] + p[1] * p[1]).sum::<f64>() / n as f64;
    let r = r2.sqrt();
    let delta = if total > 0.0 { lam / (total / 2.0) } else { 0.0 };
    let amp = if lam > 0.0 && r > 0.0 { 0.5 * delta.sqrt() / r } else { 0.0 };
    let amp = amp * lift;
    if lift < 0.0 {
        // The fourfold start: z = |lift|·r/10 · (ρ/r) cos 4θ.
        return flat
            .iter()
            .map(|p| [p[0], p[1], -0.1 * lift * p[0].hypot_m(p[1]) * (4.0 * p[1].atan2_m(p[0])).cos_m()])
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
pub(crate) fn mismatch_start(pieces: &SeamPieces, h: f64) -> Vec<V3> {
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
pub(crate) enum Start {
    Saddle(f64),
    Fourfold(f64),
    Mismatch(f64),
}

/// Starts tried by the multistart, most likely first (see [`initial_guess`]). The mismatch start
/// comes third so that the shapes the first two already solve take no longer.
pub(crate) const LIFTS: [Start; 11] = [
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

/// A warm start resampled to `n` seam vertices (linear along the previous seam polygon).
pub(crate) fn resample(w: &[V3], n: usize) -> Vec<V3> {
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

/// Lays the finer level's seam vertices onto the coarser solution: each fine sample is mapped
/// by the affine map of the coarse triangle at its seam edge (flat piece → 3D), for A and for B,
/// and the two images are averaged. The start is then isometric up to the coarse level's error.
pub(crate) fn upsample(pc: &SeamPieces, xc: &[V3], tc: &[Triangulation; 2], pf: &SeamPieces) -> Vec<V3> {
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

/// `x` pushed radially onto the sphere about its centroid of its RMS radius: points in convex
/// position. The gluing of two equilateral triangles at a quarter offset on its corners and
/// seam crossings ([`seam_crossings`]), relaxed with flips from each of the 196 pairs of
/// triangulations with no chord longer than the other piece's, reached the convex polyhedron
/// from the mismatch start pushed onto the sphere every time (in ~15 steps), from the plain
/// mismatch start never, and from the saddle and fourfold starts in 3–11 of 196.
pub(crate) fn on_sphere(mut x: Vec<V3>) -> Vec<V3> {
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
