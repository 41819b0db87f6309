//! A flat sample polygon's convex twin and the homotopy from it to the polygon itself, keeping every
//! seam edge's length: the polygon is written by its edge lengths `ℓ_k` and turning angles `τ_k`
//! (the exterior angle at vertex k, `Σ τ_k = 2π` for a simple counter-clockwise polygon), and
//! the turning angles are blended, `τ(t) = (1 − t)·τ⁰ + t·τ`, from a convex `τ⁰ ≥ 0`.
//!
//! The blend keeps the lengths (so the seam metric, which reads only lengths, stays the one of
//! the real pieces along the seam) but not closure: `Σ ℓ_k e^{iφ_k} = 0` for the headings
//! `φ_k = φ_0 + Σ_{m ≤ k} τ_m` holds at `t = 0` and `t = 1` only in general. The gap is closed by
//! the least change of the turning angles in the span of `w_m·(a cos φ_m + b sin φ_m + c)`,
//! with weights `w_m` proportional to `|τ_m|` (so straight stretches stay straight and a convex
//! polygon stays convex under a small correction), solved for `(a, b, c)` by Gauss–Newton on the
//! two closure equations and `Σ Δτ = 0` (three equations, three unknowns; the Jacobian of the
//! closure in `τ_m` is `i·Σ_{k ≥ m} ℓ_k e^{iφ_k}`, a suffix sum).

use crate::libm_ext::LibmExt;
use crate::simulate::checks::is_convex_polygon;
use std::f64::consts::TAU;

/// Closure gap (relative to the perimeter) the correction drives the polygon below.
pub const CLOSURE_TOL: f64 = 1e-13;

/// A flat polygon's turning-angle homotopy from a convex polygon to itself.
#[derive(Debug, Clone)]
pub struct Morph {
    len: Vec<f64>,
    tau: Vec<f64>,
    tau0: Vec<f64>,
    heading0: f64,
    start: [f64; 2],
    pts: Vec<[f64; 2]>,
}

impl Morph {
    /// The homotopy of the counter-clockwise polygon `pts`; `None` when its turning angles do
    /// not sum to 2π (not a simple counter-clockwise polygon) or no convex start closes.
    ///
    /// The convex start keeps the positive turning of the piece, scaled to 2π, mixed with a
    /// quarter of the circle's (`τ⁰_k = ¾·max(τ_k, 0)·2π / Σ max(τ, 0) + ¼·τᶜ_k`): a concave
    /// stretch becomes a gentle arc, every bulge keeps its place on the seam. When that cannot be closed, the circle's turning
    /// (`τ⁰_k` proportional to the mean length of the edges at vertex k) is the start.
    pub fn new(pts: &[[f64; 2]]) -> Option<Morph> {
        Self::with_circle_share(pts, 0.25)
    }

    /// [`Morph::new`] with `share` of the circle's turning mixed into the convex start instead
    /// of a quarter (more makes a rounder twin, for pieces whose own positive turning makes a
    /// twin too pointed to solve, e.g. a heart's tip).
    pub fn with_circle_share(pts: &[[f64; 2]], share: f64) -> Option<Morph> {
        let n = pts.len();
        if n < 3 {
            return None;
        }
        let len: Vec<f64> = (0..n).map(|k| dist(pts[k], pts[(k + 1) % n])).collect();
        let heading: Vec<f64> = (0..n).map(|k| (pts[(k + 1) % n][1] - pts[k][1]).atan2_m(pts[(k + 1) % n][0] - pts[k][0])).collect();
        let tau: Vec<f64> = (0..n).map(|k| wrap(heading[k] - heading[(k + n - 1) % n])).collect();
        let total: f64 = tau.iter().sum();
        if (total - TAU).abs() > 1e-6 || len.iter().any(|&l| !(l > 0.0)) {
            return None;
        }
        let mut m = Morph { len, tau, tau0: vec![], heading0: heading[0], start: pts[0], pts: pts.to_vec() };
        let positive: f64 = m.tau.iter().map(|t| t.max(0.0)).sum();
        let perimeter: f64 = m.len.iter().sum();
        let circle: Vec<f64> = (0..n).map(|k| 0.5 * (m.len[k] + m.len[(k + n - 1) % n]) * TAU / perimeter).collect();
        // Strictly convex: a quarter of the circle's turning mixed in, so no stretch of the start
        // is straight (nearly flat regions make the convex solve slow, see `convex::PATIENT`).
        let scaled: Vec<f64> = (0..n).map(|k| (1.0 - share) * m.tau[k].max(0.0) * TAU / positive + share * circle[k]).collect();
        if is_convex_polygon(pts) {
            // A convex piece is its own start: the homotopy is the identity.
            m.tau0 = m.tau.clone();
            return Some(m);
        }
        for start in [scaled, circle] {
            m.tau0 = start;
            if m.at(0.0).is_some_and(|p| is_convex_polygon(&p)) {
                return Some(m);
            }
        }
        None
    }

    /// The polygon at `t` ∈ [0, 1] (the piece itself at 1), closed; `None` if the closure
    /// correction does not converge.
    pub fn at(&self, t: f64) -> Option<Vec<[f64; 2]>> {
        if t >= 1.0 || self.tau0 == self.tau {
            return Some(self.pts.clone());
        }
        let n = self.len.len();
        let mut tau: Vec<f64> = (0..n).map(|k| (1.0 - t) * self.tau0[k] + t * self.tau[k]).collect();
        let scale: f64 = tau.iter().map(|v| v.abs()).sum::<f64>() / n as f64;
        let w: Vec<f64> = tau.iter().map(|v| v.abs() + 1e-3 * scale).collect();
        let perimeter: f64 = self.len.iter().sum();
        for _ in 0..30 {
            let phi = self.headings(&tau);
            // Suffix sums S_m = Σ_{k ≥ m} ℓ_k e^{iφ_k}; the gap is S_0.
            let mut suffix = vec![[0.0; 2]; n + 1];
            for k in (0..n).rev() {
                suffix[k] = [suffix[k + 1][0] + self.len[k] * phi[k].cos_m(), suffix[k + 1][1] + self.len[k] * phi[k].sin_m()];
            }
            let gap = suffix[0];
            if gap[0].hypot_m(gap[1]) <= CLOSURE_TOL * perimeter {
                return Some(self.polygon(&phi));
            }
            // d gap / d τ_m = i·S_m (m ≥ 1; τ_0 is the closing turn and moves no heading).
            // Unknowns (a, b, c): Δτ_m = w_m (a cos φ_m + b sin φ_m + c), rows: gap x, gap y, ΣΔτ.
            let mut j = [[0.0; 3]; 3];
            for m in 1..n {
                let basis = [phi[m].cos_m(), phi[m].sin_m(), 1.0];
                let d = [-suffix[m][1], suffix[m][0]];
                for c in 0..3 {
                    j[0][c] += d[0] * w[m] * basis[c];
                    j[1][c] += d[1] * w[m] * basis[c];
                    j[2][c] += w[m] * basis[c];
                }
            }
            let sum_err = tau.iter().sum::<f64>() - TAU;
            let coef = solve3(j, [-gap[0], -gap[1], -sum_err])?;
            for m in 1..n {
                tau[m] += w[m] * (coef[0] * phi[m].cos_m() + coef[1] * phi[m].sin_m() + coef[2]);
            }
            tau[0] = TAU - tau[1..].iter().sum::<f64>();
        }
        None
    }

    fn headings(&self, tau: &[f64]) -> Vec<f64> {
        let mut phi = Vec::with_capacity(tau.len());
        let mut h = self.heading0;
        phi.push(h);
        for t in &tau[1..] {
            h += t;
            phi.push(h);
        }
        phi
    }

    fn polygon(&self, phi: &[f64]) -> Vec<[f64; 2]> {
        let mut p = self.start;
        let mut out = Vec::with_capacity(phi.len());
        for (k, f) in phi.iter().enumerate() {
            out.push(p);
            p = [p[0] + self.len[k] * f.cos_m(), p[1] + self.len[k] * f.sin_m()];
        }
        out
    }
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot_m(a[1] - b[1])
}

/// An angle wrapped into (−π, π].
fn wrap(a: f64) -> f64 {
    let mut a = a % TAU;
    if a > std::f64::consts::PI {
        a -= TAU;
    } else if a <= -std::f64::consts::PI {
        a += TAU;
    }
    a
}

/// Solves the 3×3 system `m·x = r` by Cramer's rule; `None` when it is singular.
fn solve3(m: [[f64; 3]; 3], r: [f64; 3]) -> Option<[f64; 3]> {
    let det3 = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let d = det3(m);
    if !(d.abs() > 0.0) || !d.is_finite() {
        return None;
    }
    let mut x = [0.0; 3];
    for c in 0..3 {
        let mut a = m;
        for row in 0..3 {
            a[row][c] = r[row];
        }
        x[c] = det3(a) / d;
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A kidney-like polygon: r = 1 + 0.35 cos 2θ − 0.25 cos θ (a concave waist).
    fn kidney(n: usize) -> Vec<[f64; 2]> {
        (0..n)
            .map(|k| {
                let th = TAU * k as f64 / n as f64;
                let r = 1.0 + 0.35 * (2.0 * th).cos_m() - 0.25 * th.cos_m();
                [r * th.cos_m(), r * th.sin_m()]
            })
            .collect()
    }

    #[test]
    fn the_homotopy_keeps_every_edge_length_and_closes() {
        let pts = kidney(128);
        assert!(!is_convex_polygon(&pts), "the test shape must be non-convex");
        let m = Morph::new(&pts).expect("a simple ccw polygon");
        for t in [0.0, 0.2, 0.5, 0.8, 0.99] {
            let q = m.at(t).expect("closes");
            for k in 0..q.len() {
                let (want, got) = (dist(pts[k], pts[(k + 1) % 128]), dist(q[k], q[(k + 1) % 128]));
                assert!((want - got).abs() <= 1e-12 * want.max(1.0), "t = {t}, edge {k}: wanted {want}, got {got}");
            }
            let gap = dist(q[127], q[0]) - dist(pts[127], pts[0]);
            assert!(gap.abs() < 1e-10, "t = {t}: the polygon does not close ({gap})");
        }
        assert!(is_convex_polygon(&m.at(0.0).unwrap()), "the twin (t = 0) is convex");
        assert_eq!(m.at(1.0).unwrap(), pts, "the piece itself at t = 1");
    }

    #[test]
    fn a_convex_polygon_is_its_own_twin() {
        let pts: Vec<[f64; 2]> = (0..64).map(|k| {
            let th = TAU * k as f64 / 64.0;
            [2.0 * th.cos_m(), th.sin_m()]
        }).collect();
        let m = Morph::new(&pts).unwrap();
        assert_eq!(m.at(0.0).unwrap(), pts, "a convex polygon is its own twin");
    }
}
