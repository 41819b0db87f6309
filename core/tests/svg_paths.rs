//! SVG path data: exact conversions and the regressions the fuzzer found.

use dformer::api::{self, path::PathDto};

fn read(d: &str) -> Vec<PathDto> {
    api::path_from_svg(d).unwrap_or_else(|e| panic!("{d:?} should read, got: {e}"))
}

#[test]
fn arc_with_a_huge_chord_and_small_radii_stays_small() {
    // Fuzzer: radii 4×2 to a point 5e52 away once produced billions of cubics (out of memory).
    // The SVG rules scale the radii up to reach the end point: a half ellipse, a few cubics.
    let p = read("M0 0 A 4 2 0 1 1 0 5.5e52 Z");
    let n = p[0].points.len();
    assert!((2..=40).contains(&n), "wanted a handful of points, got {n}");
}

#[test]
fn quadratic_elevation_is_exact_and_lines_are_corners() {
    let p = read("M0 0 Q 3 3 6 0 L 6 -2 Z");
    let q = &p[0].points;
    assert_eq!(q[0].right, Some([2.0, 2.0]), "c1 = p0 + ⅔(q − p0)");
    assert_eq!(q[1].left, Some([4.0, 2.0]), "c2 = p3 + ⅔(q − p3)");
    assert_eq!(q[2].left, Some([6.0, -2.0]), "line end: corner");
    assert!(p[0].closed);
}

#[test]
fn write_then_read_is_bit_identical() {
    let d = "M0.1 0.2 C0.30000000000000004 1e-7 -5e20 3 1 1 L2 2 C3 3 4 4 0.1 0.2 Z";
    let p = read(d);
    let out = api::path_to_svg(&p[0]).expect("writes");
    assert_eq!(out, d, "wanted the same data back");
}

#[test]
fn explicit_closing_segment_merges_into_the_first_point() {
    let p = read("M0 0 C 1 0 1 1 0 1 C -1 1 -1 0 0 0 Z");
    assert_eq!(p[0].points.len(), 2, "the closing curve returns to point 1: wanted 2 points");
    assert_eq!(p[0].points[0].left, Some([-1.0, 0.0]), "its incoming handle moves to point 1");
}
