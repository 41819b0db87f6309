//! Connector positions along a piece, and the inverse of arc length for many positions at once.
//!
//! Connector k sits at arc length `s_k = start + (k + slide)·pitch` (wrapped into `[0, P)`).
//! Inverting arc length one position at a time (bracket, then a root find of `s(t) = s_k` from
//! `t = 0` of the segment) costs a full quadrature per iteration. Here the positions are sorted
//! once and the outline is walked segment by segment: each solve starts from the previous
//! solution, so every quadrature runs over a short stretch `[t_prev, t]`, and safeguarded Newton
//! iteration on `f(t) = ∫_{t_prev}^{t} |B'(τ)| dτ − Δs` (with `f'(t) = |B'(t)|`) from a
//! second-order first guess converges in two quadratures, the last Newton step being accepted
//! by an error bound instead of a third (see [`solve`]; quadratic convergence; bisection takes
//! over where `|B'|` vanishes).

use crate::arclen::{control_polygon_len, segment_len, unit_tangent, ArcTable};
use kurbo::{CubicBez, ParamCurve, ParamCurveDeriv, Point, Vec2};

/// A located position on the outline.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Station {
    /// Arc length from knot 0, wrapped into `[0, perimeter)`.
    pub s: f64,
    pub seg: usize,
    pub t: f64,
    pub point: Point,
    /// Unit tangent in the walking direction.
    pub tangent: Vec2,
}

/// Arc lengths of the `count` connectors on a piece of `perimeter`, in connector order (not
/// wrapped): `start + (k + slide)·pitch`.
pub fn connector_positions(start: f64, slide: f64, perimeter: f64, count: usize) -> Vec<f64> {
    let pitch = perimeter / count as f64;
    (0..count).map(|k| start + (k as f64 + slide) * pitch).collect()
}

/// Locates every arc length in `targets` (any order, any real value; wrapped by the perimeter)
/// and returns the stations in the same order. Cost: one sort plus a few short quadratures per
/// target (see the module comment).
pub fn locate_many(table: &ArcTable, targets: &[f64]) -> Vec<Station> {
    let wrapped: Vec<f64> = targets.iter().map(|&s| table.wrap(s)).collect();
    let order = crate::order::argsort(&wrapped);
    let n = table.segment_count();
    let mut out = vec![
        Station { s: 0.0, seg: 0, t: 0.0, point: Point::ZERO, tangent: Vec2::new(1.0, 0.0) };
        targets.len()
    ];
    let mut seg = 0;
    let (mut t_ref, mut a_ref) = (0.0, 0.0);
    for idx in order {
        let s = wrapped[idx];
        while seg + 1 < n && table.segment_start(seg + 1) <= s {
            seg += 1;
            t_ref = 0.0;
            a_ref = 0.0;
        }
        let c = table.segment(seg);
        let seg_len = table.segment_start(seg + 1) - table.segment_start(seg);
        let local = s - table.segment_start(seg);
        let (t, a) = solve(c, t_ref, a_ref, local, seg_len, table.accuracy());
        t_ref = t;
        a_ref = a;
        out[idx] = Station { s, seg, t, point: c.eval(t), tangent: unit_tangent(c, t) };
    }
    out
}

/// Arc length of a stretch of a segment to the absolute accuracy `abs`: the crate's
/// [`segment_len`] (kurbo's adaptive Gauss–Legendre rules and error estimate, with plain square
/// roots instead of libm's costly `hypot` in WASM), whose relative accuracy is per unit of the
/// stretch's control-polygon length, hence `abs / polygon`.
fn stretch_len(q: &CubicBez, abs: f64) -> f64 {
    let poly = control_polygon_len(q);
    if poly == 0.0 { 0.0 } else { segment_len(q, abs / poly) }
}

/// Finds `t ≥ t_ref` on `c` with arc length `target` from `t = 0`, given that the arc length to
/// `t_ref` is `a_ref` and the whole segment measures `seg_len`. Returns `t` and its arc length:
/// as accumulated by the quadratures, or `target` when the last Newton step was accepted
/// without a quadrature (below).
///
/// - First guess: the second-order Taylor step `Δs = v·h + ½·v'·h²` from `t_ref`, with speed
///   `v = |B'|` and `v' = B'·B''/|B'|`, solved for `h` in the cancellation-free form
///   `h = 2Δs / (v + √(v² + 2·v'·Δs))`; the chord-proportional point if that leaves the bracket.
/// - Each Newton step from a measured residual `f` lands at a residual of at most
///   `½·max|B''|·(f/v)²` (Taylor with remainder, `|d²s/dt²| = |v'| ≤ |B''|`; `max|B''|` is
///   6× the larger second difference of the control points, since `B''` is linear in `t`).
///   When that bound is below 1 % of the tolerance, the step is taken without measuring again:
///   the carried-forward error stays a hundredth of the tolerance per connector.
fn solve(c: &CubicBez, t_ref: f64, a_ref: f64, target: f64, seg_len: f64, accuracy: f64) -> (f64, f64) {
    let poly = control_polygon_len(c);
    if poly == 0.0 || target <= a_ref {
        return (t_ref, a_ref);
    }
    if target >= seg_len {
        return (1.0, seg_len);
    }
    let tol = accuracy * poly;
    let piece_acc = 0.1 * tol;
    let d = c.deriv();
    let dd = d.deriv();
    let bend = 6.0 * mx((c.p2 - 2.0 * c.p1.to_vec2() + c.p0.to_vec2()).to_vec2().hypot(), (c.p3 - 2.0 * c.p2.to_vec2() + c.p1.to_vec2()).to_vec2().hypot());
    let (mut lo, mut hi) = (t_ref, 1.0);
    let (mut t, mut a) = (t_ref, a_ref);
    let v0 = d.eval(t).to_vec2();
    let speed = v0.hypot();
    let mut next = f64::NAN;
    if speed > 0.0 {
        let ds = target - a;
        let accel = v0.dot(dd.eval(t).to_vec2()) / speed;
        let disc = speed * speed + 2.0 * accel * ds;
        next = if disc >= 0.0 { t + 2.0 * ds / (speed + disc.sqrt()) } else { t + ds / speed };
    }
    if !(next > lo && next < hi) {
        next = lo + (hi - lo) * (target - a_ref) / (seg_len - a_ref).max(f64::MIN_POSITIVE);
    }
    for _ in 0..100 {
        let piece = if next >= t {
            stretch_len(&c.subsegment(t..next), piece_acc)
        } else {
            -stretch_len(&c.subsegment(next..t), piece_acc)
        };
        a += piece;
        t = next;
        let f = a - target;
        if f.abs() <= tol {
            break;
        }
        if f < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        if hi - lo <= 4.0 * f64::EPSILON {
            break;
        }
        let speed = d.eval(t).to_vec2().hypot();
        next = t - f / speed;
        if !(speed > 0.0 && next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        } else if 0.5 * bend * (f / speed) * (f / speed) <= 0.01 * tol {
            return (next, target);
        }
    }
    (t, a)
}

/// `a.max(b)` for non-NaN inputs without the NaN handling of `f64::max` (a library call in WASM).
#[inline]
fn mx(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arclen::DEFAULT_ACCURACY;
    use kurbo::ParamCurveArclen;
    use crate::contour::{Contour, Knot};

    /// A circle of radius 10 from four cubics (not a true circle: exact lengths come from the
    /// module-independent `inv_arclen` of kurbo below).
    fn blob() -> Contour {
        let k = 5.522_847_498_307_936;
        let pts = [((10.0, 0.0), (10.0, -k), (10.0, k)), ((0.0, 10.0), (k, 10.0), (-k, 10.0)),
            ((-10.0, 0.0), (-10.0, k), (-10.0, -k)), ((0.0, -10.0), (-k, -10.0), (k, -10.0))];
        Contour::new(pts.iter().map(|&(a, l, r)| Knot { anchor: a.into(), left: l.into(), right: r.into() }).collect(), 0).unwrap()
    }

    #[test]
    fn walker_agrees_with_a_fresh_inverse_per_position() {
        let c = blob();
        let table = ArcTable::new(&c, DEFAULT_ACCURACY);
        let p = table.total();
        let targets: Vec<f64> = (0..97).map(|k| 3.3 + k as f64 * p / 97.0).collect();
        let got = locate_many(&table, &targets);
        for (k, st) in got.iter().enumerate() {
            let s = table.wrap(targets[k]);
            let seg = (0..4).rev().find(|&i| table.segment_start(i) <= s).unwrap();
            let local = s - table.segment_start(seg);
            let t = table.segment(seg).inv_arclen(local, 1e-14);
            let want = table.segment(seg).eval(t);
            assert!((want - st.point).hypot() < 1e-11, "connector {k}: wanted {want:?}, got {:?}", st.point);
        }
    }
}
