//! Ground truth for `measure`'s perimeter: the relative error stays within the requested
//! relative accuracy for circles, ellipses, polygons and free cubics, at any size and position,
//! drawn either way round. The reference lengths come from an independent composite
//! Gauss–Legendre quadrature with compensated summation (tests/common), not from kurbo.

mod common;
use common::*;
use dformer::api::{self, path::PathDto};

fn perimeter(p: &PathDto, accuracy: Option<f64>) -> f64 {
    match api::measure(p, accuracy) {
        Ok(m) => m.perimeter,
        Err(e) => panic!("measure failed on a valid shape: {e}"),
    }
}

/// Free-form closed shapes: smooth blobs with uneven handles, a shape with corners and
/// collapsed handles, a long thin lens.
fn shapes() -> Vec<(&'static str, PathDto)> {
    vec![
        ("circle, 4 arcs", ellipse([0.0, 0.0], 1.0, 1.0, 4, false)),
        ("circle, 3 arcs", ellipse([0.0, 0.0], 1.0, 1.0, 3, false)),
        ("ellipse 5:1, 8 arcs", ellipse([0.0, 0.0], 5.0, 1.0, 8, false)),
        (
            "blob",
            path(&[
                ([0.0, 0.0], [-0.3, 0.5], [0.4, -0.6]),
                ([2.0, -0.2], [1.1, -0.9], [2.9, 0.4]),
                ([2.5, 2.0], [3.0, 1.2], [2.0, 2.7]),
                ([0.5, 1.8], [1.4, 2.6], [-0.2, 1.2]),
            ]),
        ),
        (
            "corners and collapsed handles",
            path(&[
                ([0.0, 0.0], [0.0, 0.0], [1.0, 0.0]),
                ([2.0, 0.0], [2.0, 0.0], [2.0, 0.0]),
                ([2.0, 2.0], [3.0, 1.0], [2.0, 2.0]),
                ([0.0, 2.0], [0.0, 2.0], [-1.0, 1.0]),
            ]),
        ),
        (
            "thin lens",
            path(&[([0.0, 0.0], [3.0, -0.05], [3.0, 0.05]), ([10.0, 0.0], [7.0, 0.05], [7.0, -0.05])]),
        ),
        (
            "sharp bend",
            path(&[
                ([0.0, 0.0], [0.0, 0.0], [4.0, 3.0]),
                ([0.2, 0.5], [4.0, 3.4], [0.2, 0.5]),
                ([-1.0, -1.0], [-1.0, -1.0], [-1.0, -1.0]),
            ]),
        ),
    ]
}

#[test]
fn default_accuracy_is_within_1e_12_for_any_size_position_and_direction() {
    for (name, shape) in shapes() {
        for scale in [0.01, 1.0, 7.3, 1e4] {
            for offset in [[0.0, 0.0], [1e5, -1e5], [-3.0e3, 2.5e4]] {
                for cw in [false, true] {
                    let s = moved(&shape, scale, offset);
                    let s = if cw { reversed(&s) } else { s };
                    let want = perimeter_truth(&s);
                    let got = perimeter(&s, None);
                    assert!(
                        rel(got, want) <= 1e-12,
                        "{name} ×{scale} at {offset:?} {}: wanted {want:.17e}, got {got:.17e} (relative error {:.2e})",
                        if cw { "cw" } else { "ccw" },
                        rel(got, want)
                    );
                }
            }
        }
    }
}

#[test]
fn every_requested_accuracy_is_met() {
    for (name, shape) in shapes() {
        let want = perimeter_truth(&shape);
        for e in 3..=13 {
            let acc = 10f64.powi(-e);
            let got = perimeter(&shape, Some(acc));
            assert!(
                rel(got, want) <= acc,
                "{name} at accuracy {acc:e}: wanted {want:.17e}, got {got:.17e} (relative error {:.2e})",
                rel(got, want)
            );
        }
    }
}

#[test]
fn circle_from_four_arcs_matches_quadrature() {
    // The 4-arc Bézier circle is not a circle: its length exceeds 2πr by about 1e-4 relative,
    // which the reference must see and the module must reproduce.
    for r in [0.01, 1.0, 250.0] {
        let c = ellipse([1e5, 1e5], r, r, 4, false);
        let want = perimeter_truth(&c);
        let got = perimeter(&c, None);
        assert!(rel(got, want) <= 1e-12, "r = {r}: wanted {want:.17e}, got {got:.17e}");
        let excess = want / (std::f64::consts::TAU * r) - 1.0;
        assert!(excess > 1e-5 && excess < 1e-3, "Bézier circle excess over 2πr: got {excess:e}");
    }
}

/// Largest relative radial deviation of the n-arc Bézier circle from the unit circle, sampled.
fn circle_deviation(n: usize) -> f64 {
    let c = ellipse([0.0, 0.0], 1.0, 1.0, n, false);
    let (a, b) = (&c.points[0], &c.points[1]);
    let p = [a.anchor, a.right.unwrap(), b.left.unwrap(), b.anchor];
    (0..=1000)
        .map(|i| {
            let t = i as f64 / 1000.0;
            let u = 1.0 - t;
            let w = [u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t];
            let x: f64 = (0..4).map(|k| w[k] * p[k][0]).sum();
            let y: f64 = (0..4).map(|k| w[k] * p[k][1]).sum();
            (x.hypot(y) - 1.0).abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn many_arc_ellipse_matches_the_elliptic_integral() {
    // The Bézier ellipse is diag(a, b) applied to the Bézier circle, whose radius is off by at
    // most δ (relative, sampled). Its points are off the true ellipse by at most a·δ along a
    // path of slope ≤ 1 relative to the true one in the mapped frame, and the length error of
    // such a perturbation is first-order bounded by (a/b)·δ relative (curvature ≤ a/b², normal
    // offset ≤ a·δ, ΔL ≤ ∫κ·|Δn| ds). So the tolerance is (a/b)·δ + 1e-12.
    for (a, b) in [(3.0, 1.0), (1.0, 1.0), (10.0, 9.0), (2.0, 0.5)] {
        for n in [64, 256, 1024] {
            let delta = circle_deviation(n);
            let tol = (a / b) * delta + 1e-12;
            for cw in [false, true] {
                let e = ellipse([-40.0, 1e5], a, b, n, cw);
                let want = ellipse_perimeter(a, b);
                let got = perimeter(&e, None);
                assert!(
                    rel(got, want) <= tol,
                    "ellipse {a}×{b}, {n} arcs: wanted {want:.17e}, got {got:.17e}, relative error {:.2e} > tolerance {tol:.2e}",
                    rel(got, want)
                );
            }
        }
    }
}

#[test]
fn ellipse_closed_form_is_right() {
    // Checks the AGM helper itself against known values.
    let circle = ellipse_perimeter(1.0, 1.0);
    assert!((circle - std::f64::consts::TAU).abs() < 1e-15, "wanted 2π, got {circle}");
    // Flat ellipse degenerates to 4a.
    let flat = ellipse_perimeter(1.0, 1e-12);
    assert!((flat - 4.0).abs() < 1e-9, "wanted 4, got {flat}");
    // a = 2, b = 1: 9.688448220547676 (Abramowitz & Stegun 17.3; widely tabulated).
    let e = ellipse_perimeter(2.0, 1.0);
    assert!((e - 9.688_448_220_547_676).abs() < 1e-13, "wanted 9.688448220547676, got {e:.16}");
}

#[test]
fn polygons_are_exact() {
    let star: Vec<P> = (0..10)
        .map(|i| {
            let t = i as f64 * std::f64::consts::TAU / 10.0;
            let r = if i % 2 == 0 { 3.0 } else { 1.2 };
            [1e5 + r * t.cos(), -2e4 + r * t.sin()]
        })
        .collect();
    for pts in [vec![[0.0, 0.0], [3.0, 0.0], [3.0, 4.0]], vec![[0.0, 0.0], [0.01, 0.0], [0.01, 0.02], [0.0, 0.02]], star] {
        let want = ksum((0..pts.len()).map(|i| {
            let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
            (b[0] - a[0]).hypot(b[1] - a[1])
        }));
        for cw in [false, true] {
            let p = polygon(&pts);
            let p = if cw { reversed(&p) } else { p };
            let got = perimeter(&p, None);
            assert!(rel(got, want) <= 1e-14, "polygon {pts:?}: wanted {want:.17e}, got {got:.17e}");
        }
    }
}

#[test]
fn reference_quadrature_is_converged() {
    // The helpers must agree with each other and with 4× the panels, far below the 1e-12 tested.
    for (name, s) in shapes() {
        let n = s.points.len();
        for i in 0..n {
            let (a, b) = (&s.points[i], &s.points[(i + 1) % n]);
            let p = [a.anchor, a.right.unwrap_or(a.anchor), b.left.unwrap_or(b.anchor), b.anchor];
            let (l1, l4, ad) = (cubic_len_truth(p, 64), cubic_len_truth(p, 256), cubic_len_adaptive(p));
            assert!(rel(l1, l4) < 1e-15 || (l1 - l4).abs() < 1e-15, "{name} segment {i}: 64 panels {l1:e}, 256 panels {l4:e}");
            assert!(rel(ad, l4) < 1e-15 || (ad - l4).abs() < 1e-15, "{name} segment {i}: adaptive {ad:e}, 256 panels {l4:e}");
        }
    }
}

/// The fixed-rule shortcut (`arclen::Quadrature`) skips the adaptive error estimate on gently
/// curved segments. Sweep its whole range — arcs turning from 1e-4 rad to 1 rad, with even and
/// uneven handles and an S-bend, and near-cusps — at every accuracy from 1e-4 to 1e-15: each segment must stay
/// within `accuracy ×` its control-polygon length of the independent reference.
#[test]
fn fixed_rule_shortcut_meets_its_bound_per_segment() {
    use dformer::arclen::{control_polygon_len, segment_len_q, Quadrature};
    use kurbo::{CubicBez, Point};
    let mut cubics = Vec::new();
    for k in 0..=40 {
        let phi = 1e-4 * 10f64.powf(k as f64 / 10.0); // 1e-4 … 1 rad
        let h = 4.0 / 3.0 * (phi / 4.0).tan();
        for (ha, hb, bend) in [(1.0, 1.0, 1.0), (0.3, 1.7, 1.0), (1.0, 1.0, -1.0)] {
            let p0 = [1.0, 0.0];
            let p3 = [phi.cos(), phi.sin()];
            let p1 = [1.0, h * ha];
            let p2 = [p3[0] + h * hb * phi.sin() * bend, p3[1] - h * hb * phi.cos() * bend];
            cubics.push([p0, p1, p2, p3]);
        }
    }
    // Near-cusps: B'/3 = (1 + (1 − c)x, ε) on x ∈ [−1, 1] nearly vanishes just beyond t = 0, the
    // singularity that makes fixed rules slow to converge; the shortcut must decline these.
    for c in [0.05, 0.2, 0.5, 0.8] {
        for eps in [1e-1, 1e-2, 1e-4] {
            let (d01, d12, d23) = ([c, eps], [1.0, eps], [2.0 - c, eps]);
            let p1 = d01;
            let p2 = [p1[0] + d12[0], p1[1] + d12[1]];
            cubics.push([[0.0, 0.0], p1, p2, [p2[0] + d23[0], p2[1] + d23[1]]]);
        }
    }
    for e in 4..=15 {
        let acc = 10f64.powi(-e);
        let q = Quadrature::new(acc);
        for p in &cubics {
            let pt = |i: usize| Point::new(p[i][0], p[i][1]);
            let c = CubicBez::new(pt(0), pt(1), pt(2), pt(3));
            let (got, want) = (segment_len_q(&c, &q), cubic_len_adaptive(*p));
            let allowed = acc * control_polygon_len(&c) + 4.0 * f64::EPSILON * want;
            assert!(
                (got - want).abs() <= allowed,
                "cubic {p:?} at accuracy {acc:e}: wanted {want:.17e}, got {got:.17e} (error {:.2e} > {allowed:.2e})",
                (got - want).abs()
            );
        }
    }
}
