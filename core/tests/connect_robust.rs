//! `connect` never panics: random options (in and out of range) on curved and cornered pieces
//! give either a result whose pieces have the asked-for count, or an error with a message.

use dformer::api::connect::{connect, ConnectOptionsDto};
use dformer::api::path::{PathDto, PointDto};
use proptest::prelude::*;

fn blob(scale: f64, dx: f64) -> PathDto {
    let k = 0.552_284_749_830_793_4 * scale;
    let p = |a: [f64; 2], l: [f64; 2], r: [f64; 2]| PointDto { anchor: a, left: Some(l), right: Some(r) };
    let s = scale;
    PathDto {
        closed: true,
        points: vec![
            p([dx + s, 0.0], [dx + s, -k], [dx + s, k]),
            p([dx, s], [dx + k, s], [dx - k, s]),
            p([dx - s, 0.0], [dx - s, k], [dx - s, -k]),
            p([dx, -s], [dx - k, -s], [dx + k, -s]),
        ],
    }
}

/// A square with a V notch, scaled to the blob's perimeter by the caller's choice of side.
fn notched() -> PathDto {
    let pts = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [5.2, 10.0], [5.0, 4.0], [4.8, 10.0], [0.0, 10.0]];
    PathDto { closed: true, points: pts.iter().map(|&a| PointDto { anchor: a, left: None, right: None }).collect() }
}

fn kinds() -> impl Strategy<Value = Option<String>> {
    prop_oneof![Just(None), Just(Some("stitch".into())), Just(Some("teeth".into())), Just(Some("leaves".into())), Just(Some("hybrid".into())), Just(Some("bogus".into()))]
}

fn num() -> impl Strategy<Value = Option<f64>> {
    prop_oneof![Just(None), (-1.0f64..30.0).prop_map(Some), Just(Some(f64::NAN)), Just(Some(0.0))]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]
    #[test]
    fn never_panics(kind in kinds(), count in prop_oneof![Just(None), (0u32..200).prop_map(|c| Some(c as f64))],
                    pitch in num(), slide in num(), inset in num(), diameter in num(), length in num(),
                    angle in prop_oneof![Just(None), (0.0f64..200.0).prop_map(Some)], kerf in num(),
                    leaf in prop_oneof![Just(None), Just(Some("tab".to_string())), Just(Some("lock".to_string())), Just(Some("knot".to_string()))],
                    allowance in num(),
                    invert in any::<bool>(), sa in -50.0f64..50.0, sb in -50.0f64..50.0, notch in any::<bool>()) {
        let (a, b) = if notch {
            // Perimeter of the notched square: 40 − 0.4 + 2·√(0.2² + 6²); match it with a square.
            let pn = 40.0 - 0.4 + 2.0 * (0.04f64 + 36.0).sqrt();
            let s = pn / 4.0;
            let sq = PathDto { closed: true, points: [[20.0, 0.0], [20.0 + s, 0.0], [20.0 + s, s], [20.0, s]]
                .iter().map(|&a| PointDto { anchor: a, left: None, right: None }).collect() };
            (notched(), sq)
        } else {
            (blob(10.0, 0.0), blob(10.0, 40.0))
        };
        let o = ConnectOptionsDto { kind, count, pitch, slide, start: Some([sa, sb]), inset, diameter, length, angle,
                                    leaf, allowance, invert: Some(invert), kerf, accuracy: None, labels: None, unit: None };
        match connect(&[a, b], &o) {
            Ok(r) => {
                for p in &r.pieces {
                    prop_assert_eq!(p.labels.len(), r.count);
                    prop_assert!(p.outline.points.len() >= 2);
                    for pt in &p.outline.points {
                        prop_assert!(pt.anchor[0].is_finite() && pt.anchor[1].is_finite(), "non-finite outline point");
                    }
                }
            }
            Err(e) => prop_assert!(!e.to_string().is_empty()),
        }
    }
}
