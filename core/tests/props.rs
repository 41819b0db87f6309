//! Property tests: random valid outlines never panic, and measure/normalize keep their promises
//! (isoperimetric inequality, direction and translation invariance, equal normalized perimeters
//! re-measured independently).

mod common;
use common::*;
use dformer::api::{self, normalize::NormalizeOptionsDto, value::Value};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, .. ProptestConfig::default() })]

    #[test]
    fn measure_keeps_its_promises(p in star()) {
        let m = match api::measure(&p, None) {
            Ok(m) => m,
            Err(dformer::Error::SelfIntersection { .. }) => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(format!("valid star rejected: {e}"))),
        };
        let want = perimeter_truth(&p);
        prop_assert!(rel(m.perimeter, want) <= 1e-12, "perimeter: wanted {want:.17e}, got {:.17e}", m.perimeter);
        // Isoperimetric inequality: 4πA ≤ L².
        prop_assert!(4.0 * std::f64::consts::PI * m.area <= m.perimeter * m.perimeter * (1.0 + 1e-12),
            "isoperimetric: 4πA = {}, L² = {}", 4.0 * std::f64::consts::PI * m.area, m.perimeter * m.perimeter);
        for k in 0..2 {
            prop_assert!(m.bounds.min[k] <= m.centroid[k] && m.centroid[k] <= m.bounds.max[k],
                "centroid {:?} outside bounds {:?}", m.centroid, m.bounds);
        }
        let r = api::measure(&reversed(&p), None).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(rel(r.perimeter, m.perimeter) <= 1e-13, "reversed perimeter: wanted {}, got {}", m.perimeter, r.perimeter);
        prop_assert_ne!(r.orientation, m.orientation);
        prop_assert!(rel(r.area, m.area) <= 1e-9, "reversed area: wanted {}, got {}", m.area, r.area);
    }

    #[test]
    fn normalized_perimeters_are_equal(a in star(), b in star(), which in 0usize..5, t in 1.0f64..1e3) {
        let target = match which {
            0 => Value::Text("largest".into()),
            1 => Value::Text("smallest".into()),
            2 => Value::Text("mean".into()),
            3 => Value::Text("first".into()),
            _ => Value::Number(t),
        };
        let opts = NormalizeOptionsDto { target: Some(target), ..Default::default() };
        let r = match api::normalize(&[a.clone(), b.clone()], &opts) {
            Ok(r) => r,
            Err(dformer::Error::SelfIntersection { .. }) => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(format!("valid stars rejected: {e}"))),
        };
        let before = [perimeter_truth(&a), perimeter_truth(&b)];
        for (i, p) in r.paths.iter().enumerate() {
            prop_assert_eq!(p.points.len(), [&a, &b][i].points.len());
            let got = perimeter_truth(p);
            // 1e-12 plus the representability of the result (see tests/core/normalize.test.mjs).
            let maxc = p.points.iter().flat_map(|q| [q.anchor, q.left.unwrap_or(q.anchor), q.right.unwrap_or(q.anchor)])
                .flat_map(|q| q.map(f64::abs)).fold(0.0, f64::max);
            let tol = 1e-12 + 8.0 * p.points.len() as f64 * f64::EPSILON * maxc / r.perimeter;
            prop_assert!(rel(got, r.perimeter) <= tol, "path {i}: wanted {:.17e}, got {got:.17e}", r.perimeter);
            prop_assert!(rel(r.scales[i] * before[i], r.perimeter) <= 1e-12, "scale {i}: {} × {} ≠ {}", r.scales[i], before[i], r.perimeter);
        }
    }
}
