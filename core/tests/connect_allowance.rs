//! Seam allowance: the cut line is at the asked distance from the seam line everywhere, corners
//! stay sharp, holes stay where they were, and an allowance that makes the cut line cross
//! itself is refused. Distances are measured here: in closed form to a rectangle, and to a dense
//! polyline of the circle's cubics.

mod common;
use common::*;
use dformer::api::connect::{connect, ConnectOptionsDto};
use std::f64::consts::PI;

/// Distance from q to the rectangle's boundary [x0, x1] × [y0, y1], for q outside it.
fn rect_dist(q: P, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
    let dx = (x0 - q[0]).max(q[0] - x1).max(0.0);
    let dy = (y0 - q[1]).max(q[1] - y1).max(0.0);
    dx.hypot(dy)
}

#[test]
fn the_cut_line_is_the_allowance_away_from_the_seam_line_everywhere() {
    // A 40 × 30 rectangle and a circle of the same perimeter (140 = 2πR).
    let a = polygon(&[[0.0, 0.0], [40.0, 0.0], [40.0, 30.0], [0.0, 30.0]]);
    let r0 = 140.0 / (2.0 * PI);
    let circle = ellipse([100.0, 0.0], r0, r0, 8, false);
    let p_circle = perimeter_truth(&circle);
    let b = moved(&circle, 140.0 / p_circle, [0.0, 0.0]);
    let centre = [100.0 * 140.0 / p_circle, 0.0];
    let seam_b = flatten(&b, 400);
    for kind in ["stitch", "leaves"] {
        for allowance in [0.5, 3.0] {
            let o = ConnectOptionsDto { kind: Some(kind.into()), count: Some(14.0), allowance: Some(allowance), ..Default::default() };
            let r = connect(&[a.clone(), b.clone()], &o).unwrap();
            // The seam line is handed back as drawn.
            assert_eq!(r.pieces[0].seam.as_ref(), Some(&a), "{kind}: A's seam line");
            assert_eq!(r.pieces[1].seam.as_ref(), Some(&b), "{kind}: B's seam line");
            if kind == "stitch" {
                let cut = flatten(&r.pieces[0].outline, 50);
                let mut worst = 0.0f64;
                for q in &cut {
                    let d = rect_dist(*q, 0.0, 0.0, 40.0, 30.0);
                    // Beside the sides exactly `allowance`; in the corner squares (mitres) at
                    // least that and at most √2 times it.
                    let corner = (q[0] < 0.0 || q[0] > 40.0) && (q[1] < 0.0 || q[1] > 30.0);
                    let err = if corner { if d >= allowance - 1e-9 && d <= allowance * 2f64.sqrt() + 1e-9 { 0.0 } else { (d - allowance).abs() } } else { (d - allowance).abs() };
                    worst = worst.max(err);
                }
                assert!(worst < 1e-9, "allowance {allowance}: cut line off the offset by {worst}");
                // Sharp corners: the mitre points are on the cut line.
                let pts: Vec<P> = r.pieces[0].outline.points.iter().map(|p| p.anchor).collect();
                for want in [[-allowance, -allowance], [40.0 + allowance, -allowance], [40.0 + allowance, 30.0 + allowance], [-allowance, 30.0 + allowance]] {
                    let best = pts.iter().map(|p| (p[0] - want[0]).hypot(p[1] - want[1])).fold(f64::INFINITY, f64::min);
                    assert!(best < 1e-9, "allowance {allowance}: no sharp corner at {want:?} (nearest anchor {best} away)");
                }
                // The circle's cut line: `allowance` from its seam line, sampled.
                let cut_b = flatten(&r.pieces[1].outline, 50);
                let worst_b = cut_b.iter().map(|q| (dist_poly(&seam_b, *q) - allowance).abs()).fold(0.0, f64::max);
                assert!(worst_b < 2e-3 * allowance, "allowance {allowance}: circle's cut line off by {worst_b}");
                let radius_err = cut_b.iter().map(|q| ((q[0] - centre[0]).hypot(q[1] - centre[1]) - (140.0 / (2.0 * PI) + allowance)).abs()).fold(0.0, f64::max);
                assert!(radius_err < 1e-3 * r0, "circle cut line radius off by {radius_err}");
                // Holes are placed from the seam line, as without an allowance.
                let plain = connect(&[a.clone(), b.clone()], &ConnectOptionsDto { allowance: None, ..o.clone() }).unwrap();
                for i in 0..2 {
                    for (h, g) in r.pieces[i].holes.iter().zip(&plain.pieces[i].holes) {
                        assert!((h.center[0] - g.center[0]).hypot(h.center[1] - g.center[1]) < 1e-12, "hole moved by the allowance");
                    }
                }
            } else {
                // Leaves stand on the cut line: every point of A's new outline is at least the
                // allowance outside the rectangle.
                let cut = flatten(&r.pieces[0].outline, 50);
                let min = cut.iter().map(|q| rect_dist(*q, 0.0, 0.0, 40.0, 30.0)).fold(f64::INFINITY, f64::min);
                assert!(min > allowance - 1e-9, "allowance {allowance}: leaves' outline comes {min} from the seam line");
            }
        }
    }
}

#[test]
fn test_allowance_that_makes_the_cut_line_cross_itself_is_refused() {
    // A U with a slot 2 wide: an allowance over 1 closes the slot, and the offsets of its two
    // sides cross.
    let u = polygon(&[[0.0, 0.0], [20.0, 0.0], [20.0, 20.0], [11.0, 20.0], [11.0, 5.0], [9.0, 5.0], [9.0, 20.0], [0.0, 20.0]]);
    let p = 20.0 * 4.0 + 2.0 * 15.0 + 2.0 - 2.0;
    let side = p / 4.0;
    let sq = polygon(&[[50.0, 0.0], [50.0 + side, 0.0], [50.0 + side, side], [50.0, side]]);
    let o = |a: f64| ConnectOptionsDto { count: Some(20.0), allowance: Some(a), ..Default::default() };
    assert!(connect(&[u.clone(), sq.clone()], &o(0.5)).is_ok(), "0.5 leaves the slot open");
    let e = connect(&[u, sq], &o(1.5)).unwrap_err().to_string();
    assert!(e.contains("A seam allowance of 1.5 makes the cut line of the first piece cross itself") && e.contains("use a smaller allowance"), "got {e}");
}

#[test]
fn test_teeth_take_no_allowance_and_negative_ones_are_refused() {
    let a = polygon(&[[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]);
    let b = polygon(&[[20.0, 0.0], [30.0, 0.0], [30.0, 10.0], [20.0, 10.0]]);
    let e = connect(&[a.clone(), b.clone()], &ConnectOptionsDto { kind: Some("teeth".into()), count: Some(8.0), allowance: Some(1.0), ..Default::default() }).unwrap_err().to_string();
    assert!(e.contains("teeth interlock on the seam line itself"), "got {e}");
    let e = connect(&[a, b], &ConnectOptionsDto { count: Some(8.0), allowance: Some(-1.0), ..Default::default() }).unwrap_err().to_string();
    assert!(e.contains("Option `allowance`: must be zero or a positive distance"), "got {e}");
}
