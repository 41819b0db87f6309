//! Arc length along a closed outline: a table of cumulative segment lengths, and the inverse
//! (arc length → segment and curve parameter), built on kurbo's `ParamCurveArclen`
//! (adaptive Gauss–Legendre quadrature of |B'(t)|). Gently curved segments — most of a
//! finely drawn outline — skip kurbo's error estimate: an a-priori bound ([`Quadrature`]) proves a
//! fixed 4-, 6- or 8-point rule accurate enough.
//!
//! `accuracy` here is **relative**: the perimeter is within `accuracy × perimeter` of the truth.
//! kurbo's own accuracy is absolute; units are the host's (points, px, mm), so a relative
//! tolerance is the only one that means the same thing for a 0.01-unit shape and a 1e5-unit one.
//! Each segment gets the absolute budget `accuracy × (its control-polygon length)`; the control
//! polygon is never shorter than the curve, so the budgets add up to at most
//! `accuracy × polygon ≤ accuracy × perimeter × (polygon / perimeter)`, a ratio near 1.

use crate::libm_ext::LibmExt;
use crate::contour::Contour;
use kurbo::{CubicBez, ParamCurve, ParamCurveArclen, ParamCurveDeriv, Point, Vec2};

/// Default relative accuracy of every arc length in the crate: perimeters are exact to 1e-12
/// relative with margin to spare (kurbo's per-segment error estimate is conservative).
pub const DEFAULT_ACCURACY: f64 = 1e-13;

/// Smallest accepted relative accuracy (below this, round-off dominates and time explodes).
pub const MIN_ACCURACY: f64 = 1e-15;

/// Largest accepted relative accuracy.
pub const MAX_ACCURACY: f64 = 0.1;

/// |v|: a plain square root where `x² + y²` is a normal number (libm's `hypot` costs about
/// ten times more in WASM), `hypot` where squaring would overflow or underflow.
#[inline]
pub fn norm(v: Vec2) -> f64 {
    let s = v.x * v.x + v.y * v.y;
    if s.is_normal() { s.sqrt() } else { v.x.hypot_m(v.y) }
}

/// Length of the control polygon p0→p1→p2→p3, an upper bound on the arc length. `#[inline]`:
/// it is on the per-segment hot path, and the WASM build's lower inline threshold
/// (.cargo/config.toml) would otherwise leave it a call.
#[inline]
pub fn control_polygon_len(c: &CubicBez) -> f64 {
    norm(c.p1 - c.p0) + norm(c.p2 - c.p1) + norm(c.p3 - c.p2)
}

/// The cubic translated so that it starts at the origin. Arc length is translation-invariant,
/// but kurbo subdivides in absolute coordinates: a 0.01-unit curve 1e5 units from the origin
/// would lose ~9 digits to the rounding of the subdivision points. Differences of nearby
/// coordinates are exact (Sterbenz), so the translated curve is the same curve.
pub fn at_origin(c: &CubicBez) -> CubicBez {
    let o = c.p0.to_vec2();
    CubicBez::new(Point::ORIGIN, c.p1 - o, c.p2 - o, c.p3 - o)
}

/// Arc length of one cubic to relative accuracy `accuracy` (absolute error ≤ `accuracy ×`
/// control-polygon length). Zero-length segments (all four points equal) are normal input and
/// have length 0.
///
/// The curve is moved to the origin and scaled to unit control-polygon length (exact up to one
/// rounding per coordinate), then measured by [`arclen_unit`]; at unit scale no square can
/// overflow, so speeds are plain square roots.
pub fn segment_len(c: &CubicBez, accuracy: f64) -> f64 {
    segment_len_with(c, accuracy, None)
}

/// [`segment_len`] with the fixed-rule shortcut of [`Quadrature`], for loops over many segments
/// at one accuracy.
pub fn segment_len_q(c: &CubicBez, q: &Quadrature) -> f64 {
    segment_len_with(c, q.accuracy, Some(q))
}

fn segment_len_with(c: &CubicBez, accuracy: f64, q: Option<&Quadrature>) -> f64 {
    let poly = control_polygon_len(c);
    if poly == 0.0 {
        return 0.0;
    }
    if !poly.is_finite() {
        return at_origin(c).arclen(accuracy * poly);
    }
    // Control polygon no longer than the chord: a straight segment traversed once (a corner-to-
    // corner line, or handles along it in order), whose length is the chord, exactly.
    let chord = norm(c.p3 - c.p0);
    if poly <= chord {
        return chord;
    }
    let k = 1.0 / poly;
    let o = c.p0;
    let u = CubicBez::new(Point::ORIGIN, ((c.p1 - o) * k).to_point(), ((c.p2 - o) * k).to_point(), ((c.p3 - o) * k).to_point());
    if let Some((_, len)) = q.and_then(|q| q.fixed_rule(&u)) {
        return poly * len;
    }
    poly * arclen_unit(&u, accuracy, 0, Some(1.0))
}

/// Perimeter of a closed outline to relative `accuracy` (the sum of [`segment_len`]).
pub fn perimeter(contour: &Contour, accuracy: f64) -> f64 {
    let q = Quadrature::new(accuracy);
    contour.segments().map(|c| segment_len_q(&c, &q)).sum()
}

/// An a-priori error bound that lets a well-behaved segment skip the adaptive error estimate and
/// go straight to a 4-, 6- or 8-point Gauss–Legendre rule.
///
/// With `B'/3 = q(x) = dm + dm1·x + dm2·x²` on `x ∈ [−1, 1]` (see [`gl_core`]) the length is
/// `1.5 ∫ |q(x)| dx`. Every point of the Bernstein ellipse `E_ρ` has `|z| ≤ R = (ρ + 1/ρ)/2`,
/// so `|q(z) − dm| ≤ e·|dm|` with `e·|dm| = |dm1|·R + |dm2|·R²`. If `e ≤ E = √1.5 − 1` then
/// `q·q / |dm|²` stays in the disc `|w − 1| ≤ ½`, where the principal square root is analytic and
/// at most `√1.5`: `|q|` continues analytically to `E_ρ` with `|f| ≤ M = √1.5·|dm| ≤ √1.5` (at
/// unit control-polygon length `|dm| ≤ 1`, `dm` being a convex combination of the legs).
/// Gauss quadrature with `n` points then errs by at most `(64/15)·M·ρ^{−2(n−1)}/(ρ² − 1)`
/// (Trefethen, *Approximation Theory and Approximation Practice*, Thm 19.3, read with `n − 1`
/// for `n` to stay on the safe side of its indexing), so the length errs by at most `K·ρ^{−2n}`
/// with `K = 1.5·(64/15)·√1.5·ρ²/(ρ² − 1) < 16` for `ρ ≥ √2`. A rule is used when that is below
/// `accuracy`. The test `2(|dm1|²R² + |dm2|²R⁴) ≤ E²|dm|²` implies `e ≤ E` (as
/// `(a + b)² ≤ 2(a² + b²)`) and needs no square root. Anything else takes the adaptive path.
#[derive(Debug, Clone, Copy)]
pub struct Quadrature {
    accuracy: f64,
    /// `(R², R⁴)` for the 4-, 6- and 8-point rules.
    radii: [(f64, f64); 3],
}

impl Quadrature {
    const K: f64 = 16.0;
    /// `E² = (√1.5 − 1)²`.
    const E2: f64 = 0.050_510_257_216_821_9;

    pub fn new(accuracy: f64) -> Self {
        let radius = |n: i32| {
            let rho = (Self::K / accuracy).powf_m(0.5 / n as f64).max(std::f64::consts::SQRT_2);
            let r = 0.5 * (rho + 1.0 / rho);
            (r * r, r * r * r * r)
        };
        Quadrature { accuracy, radii: [radius(4), radius(6), radius(8)] }
    }

    /// The number of points of the smallest fixed rule whose a-priori bound meets the accuracy
    /// for a unit-scale cubic (control polygon of length 1), and the length by that rule; or
    /// `None`.
    fn fixed_rule(&self, u: &CubicBez) -> Option<(usize, f64)> {
        use kurbo::common::{GAUSS_LEGENDRE_COEFFS_4, GAUSS_LEGENDRE_COEFFS_6, GAUSS_LEGENDRE_COEFFS_8_HALF};
        let (dm, dm1, dm2) = midpoint_form(u);
        let sq = |v: Vec2| v.x * v.x + v.y * v.y;
        let (a, b, d) = (sq(dm1), sq(dm2), Self::E2 * sq(dm));
        let fits = |(r2, r4): (f64, f64)| 2.0 * (a * r2 + b * r4) <= d;
        if !fits(self.radii[2]) {
            return None;
        }
        if fits(self.radii[0]) {
            return Some((4, gl_full(GAUSS_LEGENDRE_COEFFS_4, dm, dm1, dm2)));
        }
        if fits(self.radii[1]) {
            return Some((6, gl_full(GAUSS_LEGENDRE_COEFFS_6, dm, dm1, dm2)));
        }
        Some((8, gl_core(GAUSS_LEGENDRE_COEFFS_8_HALF, dm, dm1, dm2)))
    }
}

/// `B'(t)/3` of a cubic as `dm + dm1·x + dm2·x²` with `t = (1 + x)/2` (kurbo's arclen form).
#[inline]
fn midpoint_form(c: &CubicBez) -> (Vec2, Vec2, Vec2) {
    let d01 = c.p1 - c.p0;
    let d12 = c.p2 - c.p1;
    let d23 = c.p3 - c.p2;
    let dd1 = d12 - d01;
    let dd2 = d23 - d12;
    (0.25 * (d01 + d23) + 0.5 * d12, 0.5 * (dd2 + dd1), 0.25 * (dd2 - dd1))
}

/// `1.5 Σ wᵢ |q(xᵢ)|` over a full Gauss–Legendre table on `[−1, 1]`.
#[inline]
fn gl_full(coeffs: &[(f64, f64)], dm: Vec2, dm1: Vec2, dm2: Vec2) -> f64 {
    let mut sum = 0.0;
    for &(wi, xi) in coeffs {
        let p = dm + dm1 * xi + dm2 * (xi * xi);
        sum += wi * (p.x * p.x + p.y * p.y).sqrt();
    }
    1.5 * sum
}

/// ∫₀¹ |B'(t)| dt by Gauss–Legendre on node pairs symmetric about t = ½, with
/// `B'/3 = dm ± dm1·x + dm2·x²` at `t = ½ ± x/2` (kurbo's `arclen_quadrature_core`, with plain
/// square roots).
#[inline]
fn gl_core(coeffs: &[(f64, f64)], dm: Vec2, dm1: Vec2, dm2: Vec2) -> f64 {
    let mut sum = 0.0;
    for &(wi, xi) in coeffs {
        let d = dm + dm2 * (xi * xi);
        let p = d + dm1 * xi;
        let m = d - dm1 * xi;
        sum += wi * ((p.x * p.x + p.y * p.y).sqrt() + (m.x * m.x + m.y * m.y).sqrt());
    }
    1.5 * sum
}

/// kurbo 0.13's adaptive arc length (`arclen_rec`): the same error estimate (∫|B''|²/|B'|² by
/// 8-point Gauss–Legendre, then the a-priori error bounds of the 8-, 16- and 24-point rules
/// times the polygon-minus-chord length), the same rules and the same subdivision, hence the
/// same accuracy semantics; only the speeds use `sqrt` (valid at the unit scale of
/// [`segment_len`]) instead of `hypot`.
///
/// `poly`: the control-polygon length when already known (1 at the top level, by construction).
fn arclen_unit(c: &CubicBez, accuracy: f64, depth: usize, poly: Option<f64>) -> f64 {
    use kurbo::common::{
        GAUSS_LEGENDRE_COEFFS_16_HALF, GAUSS_LEGENDRE_COEFFS_24_HALF, GAUSS_LEGENDRE_COEFFS_8,
        GAUSS_LEGENDRE_COEFFS_8_HALF,
    };
    let sq = |v: Vec2| (v.x * v.x + v.y * v.y).sqrt();
    let lp_lc = poly.unwrap_or_else(|| sq(c.p1 - c.p0) + sq(c.p2 - c.p1) + sq(c.p3 - c.p2)) - sq(c.p3 - c.p0);
    let (dm, dm1, dm2) = midpoint_form(c);
    let est: f64 = GAUSS_LEGENDRE_COEFFS_8
        .iter()
        .map(|&(wi, xi)| {
            let d = dm + dm1 * xi + dm2 * (xi * xi);
            let dd = dm1 + dm2 * (2.0 * xi);
            wi * (dd.x * dd.x + dd.y * dd.y) / (d.x * d.x + d.y * d.y)
        })
        .sum();
    if (est.powi(3) * 2.5e-6).min(3e-2) * lp_lc < accuracy {
        return gl_core(GAUSS_LEGENDRE_COEFFS_8_HALF, dm, dm1, dm2);
    }
    if (est.powi(6) * 1.5e-11).min(9e-3) * lp_lc < accuracy {
        return gl_core(GAUSS_LEGENDRE_COEFFS_16_HALF, dm, dm1, dm2);
    }
    if (est.powi(9) * 3.5e-16).min(3.5e-3) * lp_lc < accuracy || depth >= 20 {
        return gl_core(GAUSS_LEGENDRE_COEFFS_24_HALF, dm, dm1, dm2);
    }
    let (c0, c1) = c.subdivide();
    arclen_unit(&c0, accuracy * 0.5, depth + 1, None) + arclen_unit(&c1, accuracy * 0.5, depth + 1, None)
}

/// Cumulative arc lengths of a closed outline, and point/tangent lookup by arc length.
#[derive(Debug, Clone)]
pub struct ArcTable {
    segs: Vec<CubicBez>,
    /// `cum[i]` is the arc length from knot 0 to knot i; `cum[n]` is the perimeter.
    cum: Vec<f64>,
    accuracy: f64,
}

impl ArcTable {
    /// Measures every segment of `contour` to relative `accuracy`.
    pub fn new(contour: &Contour, accuracy: f64) -> Self {
        let segs: Vec<CubicBez> = contour.segments().collect();
        let mut cum = Vec::with_capacity(segs.len() + 1);
        let mut total = 0.0;
        cum.push(0.0);
        let q = Quadrature::new(accuracy);
        for c in &segs {
            total += segment_len_q(c, &q);
            cum.push(total);
        }
        ArcTable { segs, cum, accuracy }
    }

    /// The perimeter.
    pub fn total(&self) -> f64 {
        *self.cum.last().unwrap_or(&0.0)
    }

    pub fn accuracy(&self) -> f64 {
        self.accuracy
    }

    /// Arc length from knot 0 to the start of segment `i`.
    pub fn segment_start(&self, i: usize) -> f64 {
        self.cum[i.min(self.segs.len())]
    }

    pub fn segment(&self, i: usize) -> &CubicBez {
        &self.segs[i]
    }

    pub fn segment_count(&self) -> usize {
        self.segs.len()
    }

    /// Wraps any arc length into `[0, perimeter)`.
    pub fn wrap(&self, s: f64) -> f64 {
        let p = self.total();
        if p <= 0.0 || !s.is_finite() {
            return 0.0;
        }
        let w = s.rem_euclid(p);
        if w >= p { 0.0 } else { w }
    }

    /// Segment index and curve parameter `t` at arc length `s` (wrapped) from knot 0.
    pub fn locate(&self, s: f64) -> (usize, f64) {
        let s = self.wrap(s);
        let n = self.segs.len();
        // Last i with cum[i] <= s, skipping zero-length segments.
        let mut i = match self.cum[..n].binary_search_by(|c| c.partial_cmp(&s).unwrap_or(std::cmp::Ordering::Less)) {
            Ok(mut k) => {
                while k + 1 < n && self.cum[k + 1] <= s {
                    k += 1;
                }
                k
            }
            Err(k) => k.saturating_sub(1),
        };
        while i + 1 < n && self.cum[i + 1] - self.cum[i] == 0.0 {
            i += 1;
        }
        let seg = &self.segs[i];
        let local = s - self.cum[i];
        let poly = control_polygon_len(seg);
        if poly == 0.0 {
            return (i, 0.0);
        }
        let t = at_origin(seg).inv_arclen(local, self.accuracy * poly);
        (i, t.clamp(0.0, 1.0))
    }

    /// Point at arc length `s` (wrapped).
    pub fn point_at(&self, s: f64) -> Point {
        let (i, t) = self.locate(s);
        self.segs[i].eval(t)
    }

    /// Point and unit tangent (direction of travel) at arc length `s` (wrapped).
    pub fn frame_at(&self, s: f64) -> (Point, Vec2) {
        let (i, t) = self.locate(s);
        (self.segs[i].eval(t), unit_tangent(&self.segs[i], t))
    }
}

/// Unit tangent of a cubic at `t`, well defined where the derivative vanishes (a handle that
/// coincides with its anchor): then the direction is the limit of B'(t)/|B'(t)|, which is the
/// second derivative's direction, or failing that the chord's.
pub fn unit_tangent(c: &CubicBez, t: f64) -> Vec2 {
    let d = c.deriv().eval(t).to_vec2();
    let scale = control_polygon_len(c);
    if d.hypot() > 1e-12 * scale.max(f64::MIN_POSITIVE) {
        return d.normalize();
    }
    // Near an end with a collapsed handle: step inwards along the curve.
    let dd = c.deriv().deriv().eval(t).to_vec2();
    if dd.hypot() > 1e-12 * scale.max(f64::MIN_POSITIVE) {
        // Leaving t=0: B'(h) ≈ h·B''(0). Arriving at t=1: B'(1−h) ≈ −h·B''(1).
        let v = if t < 0.5 { dd } else { -dd };
        return v.normalize();
    }
    let chord = c.p3 - c.p0;
    if chord.hypot() > 0.0 {
        chord.normalize()
    } else {
        Vec2::new(1.0, 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::Knot;

    fn polygon(pts: &[(f64, f64)]) -> Contour {
        Contour::new(pts.iter().map(|&p| Knot::corner(p.into())).collect(), 0).unwrap()
    }

    #[test]
    fn polygon_perimeter_is_exact() {
        let c = polygon(&[(0.0, 0.0), (3.0, 0.0), (3.0, 4.0)]);
        let t = ArcTable::new(&c, DEFAULT_ACCURACY);
        assert!((t.total() - 12.0).abs() < 1e-13, "wanted 12, got {}", t.total());
    }

    #[test]
    fn point_at_walks_the_edges() {
        let c = polygon(&[(0.0, 0.0), (3.0, 0.0), (3.0, 4.0)]);
        let t = ArcTable::new(&c, DEFAULT_ACCURACY);
        let p = t.point_at(5.0);
        assert!((p - Point::new(3.0, 2.0)).hypot() < 1e-12, "got {p:?}");
        let p = t.point_at(12.0 + 1.5);
        assert!((p - Point::new(1.5, 0.0)).hypot() < 1e-12, "wrapped: got {p:?}");
    }

    /// Each fixed rule of the shortcut is reachable at the default accuracy: a nearly straight arc
    /// takes 4 points, gentle bends 6 or 8, a sharp one goes to the adaptive path.
    #[test]
    fn every_fixed_rule_is_taken_somewhere() {
        let q = Quadrature::new(DEFAULT_ACCURACY);
        let arc = |phi: f64| {
            let h = 4.0 / 3.0 * (phi / 4.0).tan_m();
            let p3 = Point::new(phi.cos_m(), phi.sin_m());
            let c = CubicBez::new(Point::new(1.0, 0.0), Point::new(1.0, h), p3 + Vec2::new(h * phi.sin_m(), -h * phi.cos_m()), p3);
            let k = 1.0 / control_polygon_len(&c);
            CubicBez::new(Point::ORIGIN, ((c.p1 - c.p0) * k).to_point(), ((c.p2 - c.p0) * k).to_point(), ((c.p3 - c.p0) * k).to_point())
        };
        let rule = |phi: f64| q.fixed_rule(&arc(phi)).map(|(points, _)| points);
        let got: Vec<_> = [1e-3, 2e-2, 5e-2, 0.5].into_iter().map(rule).collect();
        assert_eq!(got, vec![Some(4), Some(6), Some(8), None], "rule by turning angle 1e-3, 2e-2, 5e-2, 0.5 rad");
    }

    #[test]
    fn zero_length_segment_is_normal_input() {
        let c = polygon(&[(0.0, 0.0), (0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]);
        let t = ArcTable::new(&c, DEFAULT_ACCURACY);
        assert!((t.total() - (2.0 + 2f64.sqrt())).abs() < 1e-13);
        let (_, tan) = t.frame_at(0.5);
        assert!((tan - Vec2::new(1.0, 0.0)).hypot() < 1e-12, "got {tan:?}");
    }
}
