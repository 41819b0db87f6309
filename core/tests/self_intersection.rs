//! The self-intersection check: real crossings are named by their segments; what designers
//! legitimately draw (zero-length segments, handles on anchors, smooth joins, tiny or far-away
//! shapes, 1,000 segments) passes.

mod common;
use common::*;
use dformer::api::{self, path::PathDto};
use dformer::Error;

fn crossing(p: &PathDto) -> Option<(usize, usize)> {
    match api::measure(p, None) {
        Ok(_) => None,
        Err(Error::SelfIntersection { first, second, .. }) => Some((first, second)),
        Err(e) => panic!("wanted Ok or a self-intersection, got: {e}"),
    }
}

/// r(θ) = 1 + 0.3 sin 5θ with Hermite handles: simple, smooth, n segments.
fn blob(n: usize) -> PathDto {
    let h = std::f64::consts::TAU / n as f64;
    let pts: Vec<(P, P, P)> = (0..n)
        .map(|i| {
            let t = i as f64 * h;
            let (r, dr) = (1.0 + 0.3 * (5.0 * t).sin(), 1.5 * (5.0 * t).cos());
            let a = [r * t.cos(), r * t.sin()];
            let d = [dr * t.cos() - r * t.sin(), dr * t.sin() + r * t.cos()];
            (a, [a[0] - d[0] * h / 3.0, a[1] - d[1] * h / 3.0], [a[0] + d[0] * h / 3.0, a[1] + d[1] * h / 3.0])
        })
        .collect();
    path(&pts)
}

#[test]
fn bow_tie_names_its_crossing_segments() {
    let bow = polygon(&[[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]]);
    assert_eq!(crossing(&bow), Some((0, 2)), "wanted segments 0 and 2");
    let msg = api::measure(&bow, None).unwrap_err().to_string();
    assert!(msg.contains("segment 1 (the one leaving point 1) intersects segment 3"), "got message: {msg}");
    for (s, o) in [(1e-6, [1e5, 1e5]), (1e4, [-3e5, 0.0])] {
        assert_eq!(crossing(&moved(&bow, s, o)), Some((0, 2)), "bow tie ×{s} at {o:?}");
    }
}

#[test]
fn smooth_and_degenerate_outlines_pass() {
    let shapes = [
        ("circle", ellipse([0.0, 0.0], 1.0, 1.0, 4, false)),
        ("thin ellipse", ellipse([0.0, 0.0], 100.0, 0.01, 16, true)),
        ("blob 1000", blob(1000)),
        ("blob 7", blob(7)),
        ("square with repeated points and zero handles", path(&[
            ([0.0, 0.0], [0.0, 0.0], [0.0, 0.0]),
            ([0.0, 0.0], [0.0, 0.0], [0.0, 0.0]),
            ([1.0, 0.0], [1.0, 0.0], [1.0, 0.0]),
            ([1.0, 1.0], [1.0, 1.0], [1.0, 1.0]),
            ([1.0, 1.0], [1.0, 1.0], [1.0, 1.0]),
            ([0.0, 1.0], [0.0, 1.0], [0.0, 1.0]),
        ])),
        ("teardrop: one cubic closing on itself", path(&[([0.0, 0.0], [0.0, 0.0], [-1.0, 2.0]), ([0.0, 0.0], [1.0, 2.0], [0.0, 0.0])])),
        ("lens of two cubics", path(&[([0.0, 0.0], [1.0, -1.0], [1.0, 1.0]), ([3.0, 0.0], [2.0, 1.0], [2.0, -1.0])])),
        ("heart cusp", path(&[
            ([0.0, -1.0], [-0.2, -0.5], [0.2, -0.5]),
            ([1.0, 1.0], [1.0, 0.0], [1.0, 2.0]),
            ([0.0, 1.0], [0.0, 1.8], [0.0, 1.8]),
            ([-1.0, 1.0], [-1.0, 2.0], [-1.0, 0.0]),
        ])),
    ];
    for (name, s) in shapes {
        for (k, o) in [(1.0, [0.0, 0.0]), (0.01, [1e5, -1e5]), (1e4, [0.0, 3e5])] {
            assert_eq!(crossing(&moved(&s, k, o)), None, "{name} ×{k} at {o:?}: wanted no crossing");
        }
    }
}

#[test]
fn loop_inside_one_cubic_is_named() {
    let p = path(&[([0.0, 0.0], [0.0, 0.0], [2.0, 1.0]), ([1.0, 0.0], [-1.0, 1.0], [1.0, 0.0]), ([0.5, -1.0], [0.5, -1.0], [0.5, -1.0])]);
    assert_eq!(crossing(&p), Some((0, 0)));
    let msg = api::measure(&p, None).unwrap_err().to_string();
    assert!(msg.contains("segment 1 (the one leaving point 1) loops over itself"), "got message: {msg}");
}

#[test]
fn touching_anchors_and_overlapping_edges_count() {
    // Figure of eight through (2, 1) twice.
    let eight = polygon(&[[0.0, 0.0], [2.0, 1.0], [4.0, 0.0], [4.0, 2.0], [2.0, 1.0], [0.0, 2.0]]);
    assert_eq!(crossing(&eight), Some((0, 3)));
    // A spike: the second edge runs back along the first.
    // A cubic that leaves its anchor and comes straight back along the same line.
    let back = path(&[([0.0, 0.0], [0.0, 0.0], [1.0, 2.0]), ([0.0, 0.0], [0.0, 0.0], [3.0, 0.0]), ([3.0, 3.0], [3.0, 3.0], [3.0, 3.0])]);
    assert_eq!(crossing(&back), Some((0, 0)));
    let spike = polygon(&[[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 1.0]]);
    assert_eq!(crossing(&spike), Some((0, 1)));
    // An edge lying on a non-adjacent edge.
    let overlap = polygon(&[[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [3.0, 1.0], [3.0, 0.0], [1.0, 0.0], [1.0, 2.0], [0.0, 2.0]]);
    assert!(crossing(&overlap).is_some(), "wanted a crossing for edges lying on each other");
}

/// Regression (stop 40's fuzz campaign of `simulate`): a figure of eight of 11 straight sides
/// whose crossing is an anchor lying on a side that is not its own passed `measure`, and
/// `simulate` then said the piece was "too thin or too detailed for 32 seam vertices". The
/// anchor is (0, 0); the side from point 5 to point 6 passes through it.
#[test]
fn test_an_anchor_lying_on_another_side_is_a_crossing() {
    let eight = polygon(&[
        [0.0, 0.0], [16.86508585320746, 14.187813055511953], [28.3756261110239, 11.787661089847662], [30.877105571183677, -4.394270285710152],
        [23.575322179695323, -15.438552785591835], [8.788540571420311, -8.432542926603729], [-8.788540571420302, 8.432542926603722],
        [-23.57532217969532, 15.438552785591838], [-30.877105571183673, 4.394270285710158], [-28.37562611102391, -11.787661089847655],
        [-16.865085853207457, -14.187813055511949],
    ]);
    // Independently: the anchor is within round-off of the line through points 5 and 6.
    let (p, q): (P, P) = ([8.788540571420311, -8.432542926603729], [-8.788540571420302, 8.432542926603722]);
    let off_line = (p[0] * q[1] - p[1] * q[0]).abs() / ((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1])).sqrt();
    assert!(off_line < 1e-13, "precondition: (0, 0) on side 5, got {off_line:e} off it");
    let got = crossing(&eight);
    assert!(matches!(got, Some((_, 5))) || matches!(got, Some((5, _))), "wanted side 5 named in a crossing, got {got:?}");
}

#[test]
fn one_moved_anchor_in_a_thousand_segments_is_found() {
    let mut b = blob(1000);
    // Pull anchor 500 across to the far side of the shape.
    let q = &mut b.points[500];
    q.anchor = [1.2, 0.05];
    q.left = Some(q.anchor);
    q.right = Some(q.anchor);
    let c = crossing(&b);
    assert!(matches!(c, Some((a, b)) if (a == 499 || a == 500 || b == 499 || b == 500)), "wanted a crossing involving segment 499 or 500, got {c:?}");
}

#[test]
fn segments_with_far_handles_are_checked_too() {
    // Boxes spanning the whole shape go to the direct pairing, not the grid: a crossing made by
    // such wide curves is still found, and a simple shape made of them still passes.
    let wide_ok = path(&[
        ([0.0, 0.0], [-3.0, -3.0], [3.0, -3.0]),
        ([1.0, 0.0], [1.0, 0.0], [1.0, 0.0]),
        ([1.0, 1.0], [1.0, 1.0], [1.0, 1.0]),
        ([0.0, 1.0], [0.0, 1.0], [0.0, 1.0]),
    ]);
    let mut pts: Vec<(P, P, P)> = (0..40).map(|i| {
        let t = i as f64 * std::f64::consts::TAU / 40.0;
        let a = [t.cos(), t.sin()];
        (a, a, a)
    }).collect();
    pts[0].2 = [-2.0, 3.0]; // a handle thrown across the shape: segment 0 leaves it through other edges
    let wide_bad = path(&pts);
    assert_eq!(crossing(&wide_ok), None, "wide handles, simple outline");
    assert!(matches!(crossing(&wide_bad), Some((0, _))), "wanted a crossing of segment 0, got {:?}", crossing(&wide_bad));
}
