//! `connect` on polygons, where every position has a closed form: on a rectangle walked from a
//! corner, arc length s lands on a known edge at a known offset.

use dformer::api::connect::{connect, ConnectOptionsDto};
use dformer::api::path::{PathDto, PointDto};

fn rect(x: f64, y: f64, w: f64, h: f64, ccw: bool) -> PathDto {
    let mut pts = vec![[x, y], [x + w, y], [x + w, y + h], [x, y + h]];
    if !ccw {
        pts[1..].reverse();
    }
    PathDto { closed: true, points: pts.into_iter().map(|a| PointDto { anchor: a, left: None, right: None }).collect() }
}

/// Point at arc length s along the rectangle's boundary from its first corner, walking
/// counter-clockwise (ccw) or clockwise, and the inward unit normal there.
fn on_rect(x: f64, y: f64, w: f64, h: f64, ccw: bool, s: f64) -> ([f64; 2], [f64; 2]) {
    let p = 2.0 * (w + h);
    let s = s.rem_euclid(p);
    if ccw {
        if s < w { ([x + s, y], [0.0, 1.0]) }
        else if s < w + h { ([x + w, y + s - w], [-1.0, 0.0]) }
        else if s < 2.0 * w + h { ([x + w - (s - w - h), y + h], [0.0, -1.0]) }
        else { ([x, y + h - (s - 2.0 * w - h)], [1.0, 0.0]) }
    } else if s < h { ([x, y + s], [1.0, 0.0]) }
    else if s < h + w { ([x + s - h, y + h], [0.0, -1.0]) }
    else if s < 2.0 * h + w { ([x + w, y + h - (s - h - w)], [-1.0, 0.0]) }
    else { ([x + w - (s - 2.0 * h - w), y], [0.0, 1.0]) }
}

fn opts(count: f64) -> ConnectOptionsDto {
    ConnectOptionsDto { count: Some(count), ..Default::default() }
}

#[test]
fn rectangle_holes_match_the_closed_form_on_both_pieces() {
    // A: 40 × 10 drawn clockwise (walked ccw anyway); B: 20 × 30 drawn ccw (walked cw anyway).
    let a = rect(0.0, 0.0, 40.0, 10.0, false);
    let b = rect(100.0, 0.0, 20.0, 30.0, true);
    // Starts chosen so that no connector falls on a corner (corners get the mitre; see below).
    let o = ConnectOptionsDto { inset: Some(1.5), diameter: Some(0.5), start: Some([4.6, 6.6]), slide: Some(0.25), ..opts(25.0) };
    let r = connect(&[a, b], &o).unwrap();
    assert_eq!(r.count, 25);
    assert!((r.pitch - 100.0 / 25.0).abs() < 1e-14, "wanted pitch 4, got {}", r.pitch);
    for (i, (x, w, h, start)) in [(0.0, 40.0, 10.0, 4.6), (100.0, 20.0, 30.0, 6.6)].into_iter().enumerate() {
        for (k, hole) in r.pieces[i].holes.iter().enumerate() {
            let s = start + (k as f64 + 0.25) * 4.0;
            let (p, n) = on_rect(x, 0.0, w, h, i == 0, s);
            let want = [p[0] + 1.5 * n[0], p[1] + 1.5 * n[1]];
            let err = (hole.center[0] - want[0]).hypot(hole.center[1] - want[1]);
            // Positions are exact to the relative accuracy (1e-13) times the perimeter (100).
            assert!(err < 1e-11, "piece {i} connector {}: wanted {want:?}, got {:?}", k + 1, hole.center);
            assert_eq!(r.pieces[i].labels[k].text, (k + 1).to_string());
        }
    }
    assert!(r.warnings.is_empty(), "no warnings wanted, got {:?}", r.warnings);
}

#[test]
fn a_hole_on_a_corner_keeps_the_inset_from_both_sides() {
    let a = rect(0.0, 0.0, 10.0, 10.0, true);
    let b = rect(50.0, 0.0, 10.0, 10.0, true);
    let o = ConnectOptionsDto { inset: Some(1.0), diameter: Some(0.5), ..opts(4.0) };
    let r = connect(&[a, b], &o).unwrap();
    for (k, want) in [[1.0, 1.0], [9.0, 1.0], [9.0, 9.0], [1.0, 9.0]].iter().enumerate() {
        let got = r.pieces[0].holes[k].center;
        assert!((got[0] - want[0]).hypot(got[1] - want[1]) < 1e-12, "corner {}: wanted {want:?}, got {got:?}", k + 1);
    }
}

#[test]
fn teeth_on_a_square_follow_the_crenellation_closed_form() {
    // 4 connectors on a 40 × 40 square: pitch 40, teeth p/2 = 20 wide; start 20 centres them on
    // the edge midpoints.
    let a = rect(0.0, 0.0, 40.0, 40.0, true);
    let b = rect(100.0, 0.0, 40.0, 40.0, true);
    let o = ConnectOptionsDto { kind: Some("teeth".into()), length: Some(4.0), start: Some([20.0, 20.0]), ..opts(4.0) };
    let r = connect(&[a, b], &o).unwrap();
    // A's bottom edge: tooth from x = 10 to 30 standing 2 below y = 0; gaps 2 above it elsewhere.
    let pts: Vec<[f64; 2]> = r.pieces[0].outline.points.iter().map(|p| p.anchor).collect();
    for want in [[10.0, 2.0], [10.0, -2.0], [30.0, -2.0], [30.0, 2.0]] {
        assert!(
            pts.iter().any(|p| (p[0] - want[0]).hypot(p[1] - want[1]) < 1e-9),
            "A should have a corner at {want:?}; corners: {pts:?}"
        );
    }
    // B walked clockwise from (100, 0) up its left edge: a gap (2 inside, x = 102) at y 10..30.
    let pts: Vec<[f64; 2]> = r.pieces[1].outline.points.iter().map(|p| p.anchor).collect();
    for want in [[98.0, 10.0], [102.0, 10.0], [102.0, 30.0], [98.0, 30.0]] {
        assert!(
            pts.iter().any(|p| (p[0] - want[0]).hypot(p[1] - want[1]) < 1e-9),
            "B should have a corner at {want:?}; corners: {pts:?}"
        );
    }
}

#[test]
fn stitch_returns_the_outline_point_for_point() {
    let a = rect(0.0, 0.0, 40.0, 10.0, false);
    let b = rect(100.0, 0.0, 20.0, 30.0, true);
    let r = connect(&[a.clone(), b.clone()], &opts(10.0)).unwrap();
    assert_eq!(r.pieces[0].outline, a);
    assert_eq!(r.pieces[1].outline, b);
}

#[test]
fn mismatched_perimeters_name_both() {
    let a = rect(0.0, 0.0, 40.0, 10.0, true);
    let b = rect(100.0, 0.0, 20.0, 31.0, true);
    let e = connect(&[a, b], &opts(10.0)).unwrap_err().to_string();
    assert!(e.contains("100") && e.contains("102") && e.contains("Normalize"), "got {e}");
}

#[test]
fn wrong_piece_counts_are_refused() {
    let a = rect(0.0, 0.0, 40.0, 10.0, true);
    for n in [0, 1, 3] {
        let e = connect(&vec![a.clone(); n], &opts(10.0)).unwrap_err().to_string();
        assert_eq!(e, format!("Expected exactly two pieces to connect, got {n}."));
    }
}

/// Regression: two holes on a 60 × 40 rectangle with the default inset (half the 100 pitch) go
/// straight through it and out of the far side; the warning said "cross the edge: increase the
/// inset", the opposite of the fix. They are named as outside the piece, with "reduce the inset".
#[test]
fn holes_through_a_narrow_piece_are_called_outside_and_told_to_reduce_the_inset() {
    let a = rect(0.0, 0.0, 60.0, 40.0, true);
    let b = rect(100.0, 0.0, 50.0, 50.0, true);
    let r = connect(&[a, b], &ConnectOptionsDto { count: Some(2.0), slide: Some(0.5), ..Default::default() }).unwrap();
    for (k, h) in r.pieces[0].holes.iter().enumerate() {
        let (at, n) = on_rect(0.0, 0.0, 60.0, 40.0, true, (k as f64 + 0.5) * 100.0);
        let want = [at[0] + 50.0 * n[0], at[1] + 50.0 * n[1]];
        assert!((h.center[0] - want[0]).hypot(h.center[1] - want[1]) < 1e-9, "hole {}: wanted {want:?}, got {:?}", k + 1, h.center);
        assert!(!(0.0..=40.0).contains(&h.center[1]), "hole {} should lie outside the 40-high piece: {:?}", k + 1, h.center);
    }
    let first: Vec<&String> = r.warnings.iter().filter(|w| w.starts_with("On the first piece")).collect();
    assert!(first.iter().any(|w| w.contains("connectors 1, 2 lie outside") && w.contains("reduce the inset")), "warnings: {:?}", r.warnings);
    assert!(r.warnings.iter().all(|w| !w.contains("increase the inset")), "warnings: {:?}", r.warnings);
}
