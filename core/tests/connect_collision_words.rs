//! The warning for teeth that collide names each connector once per kind of collision. Before,
//! teeth at an equilateral triangle's 60° corners (glued to a circle, default options) were
//! reported as "the teeth of connectors 1, 1 and 24, 8 and 9, 9, … run into each other (a concave
//! stretch …)": a tooth crossing itself was listed like a pair, and the convex triangle was said
//! to have a concave stretch.

mod common;
use common::*;
use dformer::api::connect::{connect, ConnectOptionsDto};
use dformer::api::normalize::{normalize, NormalizeOptionsDto};
use dformer::api::value::Value;

/// The connector numbers in "connectors 1 and 24, 8 and 9" up to the next word that is no number.
fn numbers_after(text: &str, from: &str) -> Vec<usize> {
    let Some(at) = text.find(from) else { return Vec::new() };
    text[at + from.len()..]
        .split(' ')
        .map(|w| w.trim_end_matches(','))
        .take_while(|w| w.parse::<usize>().is_ok() || *w == "and")
        .filter_map(|w| w.parse().ok())
        .collect()
}

#[test]
fn test_teeth_at_a_triangles_corners_are_named_once_and_near_a_corner() {
    let h = 50.0 * 3f64.sqrt() / 2.0;
    let corners = [[0.0, 0.0], [50.0, 0.0], [25.0, h]];
    let circle = moved(&ellipse([0.0, 0.0], 1.0, 1.0, 4, true), 30.0, [200.0, 0.0]);
    let n = normalize(&[polygon(&corners), circle], &NormalizeOptionsDto { target: Some(Value::Text("mean".into())), ..Default::default() }).unwrap();
    // Normalized about its bounding-box centre: the corners scale with the triangle.
    let k = n.scales[0];
    let c = [25.0, h / 2.0];
    let corners: Vec<[f64; 2]> = corners.iter().map(|p| [c[0] + k * (p[0] - c[0]), c[1] + k * (p[1] - c[1])]).collect();
    // The count every host starts with (defaults()); the rest left to the core.
    let count = dformer::api::defaults().options.iter().find(|o| o.name == "count").and_then(|o| match &o.value {
        Some(dformer::api::defaults::serde_json_value::Value::Number(x)) => Some(*x),
        _ => None,
    });
    let r = connect(&n.paths, &ConnectOptionsDto { kind: Some("teeth".into()), count, ..Default::default() }).unwrap();
    let w = r.warnings.iter().find(|w| w.starts_with("On the first piece, the teeth")).expect("teeth collide at the 60° corners");
    assert!(w.contains("(a corner or a concave stretch tighter than the teeth)"), "got {w}");
    assert!(!r.warnings.iter().any(|w| w.starts_with("On the second piece")), "the circle has no corner: {:?}", r.warnings);
    let pairs = numbers_after(w, "the teeth of connectors ");
    let pairs = if w.contains("run into each other") { pairs } else { Vec::new() };
    let own = if w.contains("cross themselves") {
        numbers_after(w, if pairs.is_empty() { "the teeth of connectors " } else { "those of connectors " })
    } else {
        Vec::new()
    };
    assert!(!pairs.is_empty() || !own.is_empty(), "no connector named in {w}");
    assert_eq!(pairs.len() % 2, 0, "pairs come in twos: {w}");
    let mut seen = own.clone();
    seen.sort_unstable();
    seen.dedup();
    assert_eq!(seen.len(), own.len(), "a connector named twice as crossing itself: {w}");
    let mut listed: Vec<(usize, usize)> = pairs.chunks(2).map(|p| (p[0], p[1])).collect();
    let before = listed.len();
    listed.sort_unstable();
    listed.dedup();
    assert_eq!(listed.len(), before, "a pair named twice: {w}");
    // Each named connector is within a pitch and a half of one of the triangle's corners (its
    // number, engraved beside its tooth, locates it).
    for &num in pairs.iter().chain(&own) {
        let at = r.pieces[0].labels[num - 1].at;
        let near = corners.iter().map(|q| (q[0] - at[0]).hypot(q[1] - at[1])).fold(f64::INFINITY, f64::min);
        assert!(near < 1.5 * r.pitch, "connector {num} is {near} from the nearest corner (pitch {}): {w}", r.pitch);
    }
}
