//! Kinks (`simulate::kink`): turns of a smooth outline too tight for the seam's steps, which the
//! seam takes as corners. Checked on the tests' fitted heart against the heart curve's own
//! points and against chords measured here.

#[path = "simulate_common/shapes.rs"]
#[allow(dead_code)]
mod shapes;

use dformer::arclen::ArcTable;
use dformer::simulate::kink::{kinks, Walk, KINK_SHIFT};

fn table(c: &dformer::contour::Contour) -> ArcTable {
    ArcTable::new(c, 1e-11)
}

#[test]
fn smooth_outlines_have_no_kinks_and_are_walked_by_arc_length() {
    for (name, c) in [("circle", shapes::circle_for(&shapes::kidney())), ("kidney", shapes::kidney()), ("pebble", shapes::pebble()), ("rounded star", shapes::rounded_star())] {
        let t = table(&c);
        assert_eq!(kinks(&t, &[]), vec![], "{name}");
        let (start, seam) = (7.25, t.total() * (1.0 + 1e-7));
        let walk = Walk::new(&t, start, seam, &[]);
        for s in [0.0, 1.0 / 3.0, 10.0, 0.5 * seam] {
            assert_eq!(walk.arc(s), start + (t.total() / seam) * s, "{name}: the walk at {s} is the arc length, bit for bit");
        }
    }
}

/// The fitted heart's tip (t = π) is its anchor at (0, −51) and its dip (t = 0) the one at
/// (0, 15).
#[test]
fn a_fitted_heart_has_kinks_at_its_tip_and_dip() {
    let t = table(&shapes::heart());
    let found = kinks(&t, &[]);
    assert_eq!(found.len(), 2, "wanted the tip and the dip, got {found:?}");
    for (k, want) in found.iter().zip([(0.0, -51.0), (0.0, 15.0)]) {
        let p = t.frame_at(k.at).0;
        let off = (p.x - want.0).hypot(p.y - want.1);
        assert!(off <= 1e-6, "wanted a kink at {want:?}, got ({}, {}), {off:.1e} away", p.x, p.y);
        for d in [k.before, k.after] {
            assert!(d > 0.0 && d <= KINK_SHIFT * t.total(), "deficit {d:e} of a side");
        }
    }
}

/// The point of the walk: past a kink, a chord is as long as its stretch of the seam (up to the
/// smooth curvature's `(hκ)²/24`), where by plain arc length it falls short by the turn.
#[test]
fn a_chord_from_a_kink_keeps_its_seam_length_on_the_walk() {
    let t = table(&shapes::heart());
    let found = kinks(&t, &[]);
    let walk = Walk::new(&t, 0.0, t.total(), &found);
    for (i, c) in walk.kink_positions().collect::<Vec<_>>().into_iter().enumerate() {
        let at = t.point_at(walk.arc(c));
        assert!((walk.arc(c) - found[i].at).abs() <= 1e-9 * t.total(), "kink {i}'s seam position walks to it");
        assert!((walk.seam_of(&t, found[i].at) - c).abs() <= 1e-12 * t.total(), "and back");
        for h in [0.05, 0.1, 0.2, -0.05, -0.1, -0.2] {
            let walked = (t.point_at(walk.arc(c + h)) - at).hypot() / h.abs() - 1.0;
            let by_arc = (t.point_at(found[i].at + h) - at).hypot() / h.abs() - 1.0;
            println!("kink {i}, {h:+} mm: walked {walked:+.2e}, by arc length {by_arc:+.2e}");
            assert!(walked.abs() <= 2e-3, "kink {i}, {h:+} mm: wanted the chord within 2e-3 of its seam length, got {walked:+.2e}");
            assert!(walked.abs() <= 0.2 * by_arc.abs(), "kink {i}, {h:+} mm: walked {walked:+.2e} against {by_arc:+.2e} by arc length");
        }
    }
}

#[test]
fn the_walk_is_monotone_and_closes_on_itself() {
    let t = table(&shapes::heart());
    let found = kinks(&t, &[]);
    for start in [0.0, 100.0, found[1].at] {
        let walk = Walk::new(&t, start, t.total(), &found);
        let mut last = walk.arc(0.0);
        assert!((last - start).abs() <= 1e-9 * t.total(), "seam position 0 is the walk's start");
        for m in 1..=4000 {
            let s = t.total() * m as f64 / 4000.0;
            let x = walk.arc(s);
            assert!(x > last, "the walk goes back at {s}: {x} after {last}");
            assert!((walk.seam_of(&t, x) - s).abs() <= 1e-9 * t.total() || m == 4000, "seam_of inverts the walk at {s}");
            last = x;
        }
        // Seam position L is 0 again; when a kink is the start, the last edge ends at it short
        // of what the kink's first side loses.
        let closing = if start == found[1].at { found[1].before } else { 0.0 };
        assert!((last + closing - (start + t.total())).abs() <= 1e-9 * t.total(), "the walk ends where it starts, one perimeter on: {last} from {start}");
    }
}
