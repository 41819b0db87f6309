//! Dovetail teeth and locking leaves fit, checked with geometry written here (polylines of the
//! outlines, point-in-polygon), not with the crate's.
//!
//! The set-up makes "joined face to face along the seam" literal: A is the rectangle
//! [0, 100] × [0, 30] and B its mirror image [0, 100] × [−30, 0]. A is walked counter-clockwise
//! and B clockwise from (0, 0), so along the shared side y = 0 both walks are at (s, 0) at arc
//! length s, A's inside is y > 0 and B's is y < 0: a point v out of A's seam line is v into B's,
//! exactly where it lies in the drawing.

mod common;
use common::*;
use dformer::api::connect::{connect, ConnectDto, ConnectOptionsDto};

fn pair() -> [dformer::api::path::PathDto; 2] {
    [polygon(&[[0.0, 0.0], [100.0, 0.0], [100.0, 30.0], [0.0, 30.0]]), polygon(&[[0.0, 0.0], [0.0, -30.0], [100.0, -30.0], [100.0, 0.0]])]
}

/// Sorted x where the closed polyline crosses the line at height y, within [lo, hi].
fn crossings(poly: &[P], y: f64, lo: f64, hi: f64) -> Vec<f64> {
    let mut xs: Vec<f64> = (0..poly.len())
        .filter_map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
            ((a[1] > y) != (b[1] > y)).then(|| a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
        })
        .filter(|&x| (lo..=hi).contains(&x))
        .collect();
    xs.sort_by(f64::total_cmp);
    xs
}

fn run(o: ConnectOptionsDto) -> ConnectDto {
    let r = connect(&pair(), &ConnectOptionsDto { count: Some(26.0), slide: Some(0.0), ..o }).unwrap();
    assert!((r.pitch - 10.0).abs() < 1e-12, "pitch: wanted 10, got {}", r.pitch);
    r
}

/// Dovetails at 90° < angle < 180° and tapers below 90°: in the band the teeth occupy, every
/// point away from the flanks is inside exactly one of the two toothed outlines (no overlap, no
/// gap), and a dovetail is wider at its tip than at its root.
#[test]
fn dovetails_tile_the_seam_band_with_no_overlap_and_no_gap() {
    for angle in [60.0, 90.0, 110.0, 125.0] {
        let length = 4.0;
        let r = run(ConnectOptionsDto { kind: Some("teeth".into()), length: Some(length), angle: Some(angle), ..Default::default() });
        // (Teeth folded round the rectangles' corners may warn; the band checked is x ∈ [15, 85].)
        let (a, b) = (flatten(&r.pieces[0].outline, 8), flatten(&r.pieces[1].outline, 8));
        let cot = angle.to_radians().cos() / angle.to_radians().sin();
        let mut bad = Vec::new();
        for i in 0..=700 {
            for j in 1..20 {
                let (x, y) = (15.0 + 70.0 * i as f64 / 700.0, -0.5 * length + length * j as f64 / 20.0);
                // Skip points within 1e-3 of a flank: at height v above A's tooth root the flank
                // is at ±(p/4 − v·cot) from the connector (A's teeth stand out into y < 0).
                let v = -y;
                let u = (x + 5.0).rem_euclid(10.0) - 5.0; // from the nearest connector (multiples of 10)
                let flank = 2.5 - v * cot;
                let near = [flank, 10.0 - flank].iter().any(|f| (u.abs() - f).abs() < 1e-3 * (1.0 + cot.abs()));
                if near || y.abs() < 1e-9 {
                    continue;
                }
                let (ia, ib) = (inside_poly(&a, [x, y]), inside_poly(&b, [x, y]));
                if ia == ib {
                    bad.push(format!("({x:.3}, {y:.3}): in A {ia}, in B {ib}"));
                }
            }
        }
        assert!(bad.is_empty(), "angle {angle}: {} points not covered exactly once, e.g. {:?}", bad.len(), &bad[..bad.len().min(5)]);
        // Width of A's tooth at connector 5 (x = 50) just below the tip and just above the root.
        let width = |y: f64| {
            let xs = crossings(&a, y, 45.0, 55.0);
            xs[xs.len() - 1] - xs[0]
        };
        let (tip, root) = (width(-0.5 * length + 0.01), width(0.5 * length - 0.01));
        let want_tip = 5.0 + 2.0 * (0.5 * length - 0.01) * (-cot);
        assert!((tip - want_tip).abs() < 1e-9, "angle {angle}: tooth tip width wanted {want_tip}, got {tip}");
        if angle > 90.0 {
            assert!(tip > root, "angle {angle}: a dovetail must widen toward its tip, tip {tip} root {root}");
        }
    }
}

#[test]
fn test_dovetail_too_steep_for_the_pitch_names_the_angles_that_fit() {
    let e = connect(&pair(), &ConnectOptionsDto { kind: Some("teeth".into()), count: Some(26.0), length: Some(8.0), angle: Some(150.0), ..Default::default() })
        .unwrap_err()
        .to_string();
    // Fits while L·|cot θ| < p/2 (the tips of neighbouring dovetails meet beyond): atan(2L/p) = 58.0° to 122.0°.
    assert!(e.contains("dovetails' corners collide") && e.contains("between 58° and 122°"), "got {e}");
    assert!(e.contains("Teeth of length 8 with 150° flanks do not fit a pitch of 10"), "got {e}");
}

/// A host that sends its pieces in the user's unit names it: every length in the message is
/// followed by it, and a later call without a unit prints bare numbers again.
#[test]
fn lengths_in_messages_carry_the_unit_the_host_names() {
    let steep = |unit: Option<&str>| {
        let o = ConnectOptionsDto { kind: Some("teeth".into()), count: Some(26.0), length: Some(8.0), angle: Some(10.0), unit: unit.map(Into::into), ..Default::default() };
        connect(&pair(), &o).unwrap_err().to_string()
    };
    let e = steep(Some("mm"));
    assert!(e.contains("Teeth of length 8 mm with 10° flanks do not fit a pitch of 10 mm: the flanks meet"), "got {e}");
    let e = steep(None);
    assert!(e.contains("Teeth of length 8 with 10° flanks do not fit a pitch of 10: the flanks meet"), "got {e}");
    let e = steep(Some("in; rm"));
    assert!(e.contains("Option `unit`") && e.contains("1 to 8 letters"), "got {e}");
}

/// Locking leaves: A's leaf k (even k) stands into y < 0, which is B's face; B has a slot there
/// whose centre is the leaf's shoulder (where the head widens out of the neck) and whose length
/// along the edge is the neck's drawn width minus twice the kerf (both nominal after cutting).
/// With a seam allowance `a` the leaf stands on A's cut line y = −a and the shoulder is measured
/// from the seam line y = 0, as far into B as it lies out of A.
fn check_slots(kerf: f64, allowance: f64) {
    let r = run(ConnectOptionsDto { kind: Some("leaves".into()), leaf: Some("lock".into()), kerf: Some(kerf), allowance: Some(allowance), ..Default::default() });
    let what = format!("kerf {kerf}, allowance {allowance}");
    assert!(r.warnings.is_empty(), "{what}: {:?}", r.warnings);
    let a = flatten(&r.pieces[0].outline, 64);
    let slots_b = &r.pieces[1].slots;
    assert_eq!(slots_b.len(), 13, "{what}: B receives A's 13 leaves (even connectors)");
    assert_eq!(r.pieces[0].slots.len(), 13, "{what}: A receives B's 13 leaves");
    for k in (2..9).step_by(2) {
        let x0 = 10.0 * k as f64;
        // Width of A below y = −allowance around x0 at depth v: between the outline's crossings
        // of the line y = −v within half a pitch of x0.
        let width = |v: f64| {
            let xs = crossings(&a, -v, x0 - 5.0, x0 + 5.0);
            if xs.len() >= 2 { xs[xs.len() - 1] - xs[0] } else { 0.0 }
        };
        let neck = width(allowance + 0.3);
        assert!((neck - (4.0 + kerf)).abs() < 0.02, "{what}, leaf {}: neck wanted {}, got {neck}", k + 1, 4.0 + kerf);
        // The shoulder: the first depth beyond the cut line where the leaf is wider than its neck.
        let shoulder = (1..6000).map(|i| allowance + 6.0 * i as f64 / 6000.0).find(|&v| width(v) > neck + 0.05).unwrap();
        let slot = slots_b.iter().find(|s| (s.points[0].anchor[0] - x0).abs() < 5.0).expect("a slot at the leaf");
        let xs: Vec<f64> = slot.points.iter().map(|p| p.anchor[0]).collect();
        let ys: Vec<f64> = slot.points.iter().map(|p| p.anchor[1]).collect();
        let (lo, hi) = (xs.iter().cloned().fold(f64::INFINITY, f64::min), xs.iter().cloned().fold(f64::NEG_INFINITY, f64::max));
        let cy = ys.iter().sum::<f64>() / 4.0;
        let cx = 0.5 * (lo + hi);
        assert!((cx - x0).abs() < 1e-9, "{what}, slot {}: centred at x {cx}, wanted {x0}", k + 1);
        assert!((-cy - shoulder).abs() < 0.05, "{what}, slot {}: at depth {}, the leaf's shoulder at {shoulder}", k + 1, -cy);
        assert!(((hi - lo) - (neck - 2.0 * kerf)).abs() < 0.02, "{what}, slot {}: length {}, neck {neck} − 2 kerf", k + 1, hi - lo);
        // The head is wider than the slot, so it holds once pushed through.
        assert!(width(shoulder + 1.5) > (hi - lo) + 2.0, "{what}, leaf {}: head not wider than its slot", k + 1);
    }
}

#[test]
fn every_slot_is_where_its_leaf_lands_and_fits_the_neck() {
    for kerf in [0.0, 0.1] {
        check_slots(kerf, 0.0);
    }
}

#[test]
fn with_a_seam_allowance_every_slot_is_still_where_its_leaf_lands() {
    for kerf in [0.0, 0.1] {
        check_slots(kerf, 2.0);
    }
}

#[test]
fn test_odd_leaf_count_is_refused_naming_the_nearest_even_counts() {
    let o = ConnectOptionsDto { kind: Some("leaves".into()), count: Some(25.0), ..Default::default() };
    let e = connect(&pair(), &o).unwrap_err().to_string();
    assert!(e.contains("must be even, got 25: use 24 or 26"), "got {e}");
    // With a pitch the nearest even count is taken: 260 / 9.6 ≈ 27.1 → 28 (27 is odd).
    let r = connect(&pair(), &ConnectOptionsDto { kind: Some("leaves".into()), pitch: Some(9.6), ..Default::default() }).unwrap();
    assert_eq!(r.count, 28);
    let r = connect(&pair(), &ConnectOptionsDto { kind: Some("leaves".into()), pitch: Some(10.5), ..Default::default() }).unwrap();
    assert!(r.count % 2 == 0, "pitch 10.5: count {} is odd", r.count);
}
