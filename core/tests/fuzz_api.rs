//! The binding layer never panics: arbitrary JSON-shaped values (as a host could send) and
//! arbitrary numbers (NaN, ±∞, huge, zero, duplicates) go into every api function, which must
//! return Ok or Err. (The cargo-fuzz target in core/fuzz does the same with coverage guidance.)

use dformer::api::{self, normalize::NormalizeOptionsDto, path::{PathDto, PointDto}};
use proptest::prelude::*;
use serde_json::{json, Value as Json};

fn num() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN), Just(f64::INFINITY), Just(f64::NEG_INFINITY), Just(0.0), Just(-0.0),
        Just(1e308), Just(-1e308), Just(f64::MIN_POSITIVE), Just(5e-324), Just(1.0),
        -10.0f64..10.0, any::<f64>(),
    ]
}

fn point() -> impl Strategy<Value = PointDto> {
    let xy = || (num(), num()).prop_map(|(x, y)| [x, y]);
    (xy(), prop::option::of(xy()), prop::option::of(xy())).prop_map(|(anchor, left, right)| PointDto { anchor, left, right })
}

fn path() -> impl Strategy<Value = PathDto> {
    // Few distinct points, repeated, so duplicates and degenerate segments are common.
    (prop::collection::vec(point(), 0..5), prop::collection::vec(0usize..5, 0..12), any::<bool>()).prop_map(|(pool, idx, closed)| {
        let points = if pool.is_empty() { vec![] } else { idx.iter().map(|&i| pool[i % pool.len()].clone()).collect() };
        PathDto { closed, points }
    })
}

fn json() -> impl Strategy<Value = Json> {
    let leaf = prop_oneof![
        Just(Json::Null), any::<bool>().prop_map(Json::Bool), any::<f64>().prop_map(|x| json!(x)),
        (-5i64..5).prop_map(|x| json!(x)), Just(json!(1e300)),
        prop_oneof![Just("largest"), Just("mean"), Just("center"), Just("centroid"), Just("M0 0 L1 1Z"), Just("")].prop_map(|s| json!(s)),
    ];
    leaf.prop_recursive(4, 64, 6, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..6).prop_map(Json::Array),
            prop::collection::vec((prop_oneof![Just("closed"), Just("points"), Just("anchor"), Just("left"), Just("right"), Just("target"), Just("pivot"), Just("accuracy")], inner), 0..5)
                .prop_map(|kv| Json::Object(kv.into_iter().map(|(k, v)| (k.to_string(), v)).collect())),
        ]
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, .. ProptestConfig::default() })]

    #[test]
    fn dto_values_never_panic(p in path(), q in path(), acc in prop::option::of(num()), t in num(), pv in (num(), num())) {
        let _ = api::measure(&p, acc);
        let _ = api::svg::path_to_svg(&p);
        let opts: NormalizeOptionsDto = serde_json::from_value(json!({ "target": t, "pivot": [pv.0, pv.1] })).unwrap_or_default();
        let _ = api::normalize(&[p.clone(), q.clone()], &opts);
        let _ = api::normalize(&[p, q], &NormalizeOptionsDto::default());
    }

    #[test]
    fn json_values_never_panic(a in json(), b in json(), c in json()) {
        if let Ok(p) = serde_json::from_value::<PathDto>(a.clone()) {
            let _ = api::measure(&p, None);
            let _ = api::svg::path_to_svg(&p);
        }
        let paths: Vec<PathDto> = serde_json::from_value(b).unwrap_or_default();
        if let Ok(o) = serde_json::from_value::<NormalizeOptionsDto>(c) {
            let _ = api::normalize(&paths, &o);
        }
        if let Json::String(d) = a {
            let _ = api::svg::path_from_svg(&d);
        }
    }

    #[test]
    fn svg_text_never_panics(d in "[MmLlHhVvCcSsQqTtAaZz0-9 ,.eE+-]{0,80}", any_text in ".{0,40}") {
        for s in [&d, &any_text] {
            if let Ok(paths) = api::svg::path_from_svg(s) {
                for p in &paths {
                    // What was read must write and read back to the same points.
                    if let Ok(out) = api::svg::path_to_svg(p) {
                        let back = api::svg::path_from_svg(&out).map_err(|e| TestCaseError::fail(format!("{out}: {e}")))?;
                        if p.closed {
                            prop_assert!(back.len() == 1, "{s:?} → {out:?} read back as {} paths", back.len());
                        }
                    }
                }
            }
        }
    }
}
