//! Stitch holes on random pieces keep the promises a maker relies on, checked with geometry
//! written here (nearest points by Newton on the cubics, arc lengths by the independent
//! quadrature of `common`), not with the crate's own arc-length code:
//! - both pieces get the same count, labelled 1…n in connector order;
//! - connector k sits at arc length `start + (k + slide)·pitch`, walking A counter-clockwise and
//!   B clockwise, wherever its hole is `inset` from the edge (straight and convex stretches);
//! - a hole that crosses the edge, lies outside its piece or overlaps another is named in a
//!   warning; every other hole is inside its piece, clear of the edge and of the other holes.

mod common;
use common::*;
use dformer::api::{self, connect::ConnectOptionsDto};
use proptest::prelude::*;

fn dist(a: P, b: P) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Nearest point of the outline to `q`: (distance, segment, parameter). The nearest of a dense
/// sampling brackets it to one sample step; a golden-section search on the distance then finds it
/// in that bracket and at the ends of the two neighbouring segments (a foot just past an anchor,
/// or one where the curve bends sharply, is missed by a search confined to one segment or by
/// Newton's method alone, while its distance is right to second order), and Newton's method
/// polishes it.
fn nearest(segs: &[Cubic], q: P) -> (f64, usize, f64) {
    const SAMPLES: usize = 64;
    let step = 1.0 / SAMPLES as f64;
    let mut best = (f64::INFINITY, 0, 0.0);
    for (i, c) in segs.iter().enumerate() {
        for s in 0..=SAMPLES {
            let t = s as f64 * step;
            let d = dist(eval(c, t), q);
            if d < best.0 {
                best = (d, i, t);
            }
        }
    }
    let golden = |i: usize, lo: f64, hi: f64| {
        let c = &segs[i];
        let r = 0.5 * (5f64.sqrt() - 1.0);
        let (mut a, mut b) = (lo.max(0.0), hi.min(1.0));
        for _ in 0..200 {
            let (x1, x2) = (b - r * (b - a), a + r * (b - a));
            if dist(eval(c, x1), q) <= dist(eval(c, x2), q) {
                b = x2;
            } else {
                a = x1;
            }
        }
        // The distance is flat at its minimum, so the search finds t only to ~1e-8; the root of
        // (B(t) − q)·B'(t), which crosses zero there, is polished by Newton's method.
        let mut t = 0.5 * (a + b);
        for _ in 0..20 {
            let (p, d, d2) = (eval(c, t), deriv(c, t), deriv2(c, t));
            let g = (p[0] - q[0]) * d[0] + (p[1] - q[1]) * d[1];
            let gp = d[0] * d[0] + d[1] * d[1] + (p[0] - q[0]) * d2[0] + (p[1] - q[1]) * d2[1];
            let next = t - g / gp;
            if !(gp > 0.0) || !(lo.max(0.0)..=hi.min(1.0)).contains(&next) {
                break;
            }
            t = next;
        }
        (dist(eval(c, t), q), i, t)
    };
    let n = segs.len();
    let (_, i, t) = best;
    [golden(i, t - step, t + step), golden((i + n - 1) % n, 1.0 - step, 1.0), golden((i + 1) % n, 0.0, step)]
        .into_iter()
        .fold((f64::INFINITY, 0, 0.0), |m, r| if r.0 < m.0 { r } else { m })
}

/// Even–odd inside test against a dense polygon of the outline (for points well off the edge).
fn inside(segs: &[Cubic], q: P) -> bool {
    let pts: Vec<P> = segs.iter().flat_map(|c| (0..64).map(move |s| eval(c, s as f64 / 64.0))).collect();
    let mut inside = false;
    for i in 0..pts.len() {
        let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
        if (a[1] > q[1]) != (b[1] > q[1]) && q[0] < a[0] + (q[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
            inside = !inside;
        }
    }
    inside
}

/// Signed area (y up) of the dense polygon: > 0 for a counter-clockwise outline.
fn signed_area(segs: &[Cubic]) -> f64 {
    let pts: Vec<P> = segs.iter().flat_map(|c| (0..64).map(move |s| eval(c, s as f64 / 64.0))).collect();
    (0..pts.len()).map(|i| {
        let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
        a[0] * b[1] - b[0] * a[1]
    }).sum::<f64>() / 2.0
}

/// Connector numbers (1-based) named by the warnings about `piece` that contain `what`; `None`
/// when a list was cut short ("… and 3 more"), so every connector may be meant.
fn named(warnings: &[String], piece: &str, what: &str) -> Option<Vec<usize>> {
    let mut out = Vec::new();
    for w in warnings.iter().filter(|w| w.contains(piece) && w.contains(what)) {
        if w.contains(" more") {
            return None;
        }
        let list = &w[w.find("connectors").map_or(0, |i| i + "connectors".len())..w.find(what).unwrap_or(w.len())];
        out.extend(list.split(|c: char| !c.is_ascii_digit()).filter_map(|s| s.parse::<usize>().ok()));
    }
    Some(out)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn stitch_holes_on_random_pieces_are_paired_spaced_and_inside(
        a in star(), b in star(), count in 3usize..48, slide in 0.0f64..1.0, start in (0.0f64..1.0, 0.0f64..1.0),
        inset in 0.1f64..0.6, diameter in 0.1f64..0.5,
    ) {
        let Some(pieces) = normalized_pair(a, b)? else { return Ok(()) };
        let (segs, lens, perimeter) = segments_and_lengths(&pieces);
        let pitch = perimeter / count as f64;
        let o = ConnectOptionsDto {
            count: Some(count as f64), slide: Some(slide), start: Some([start.0 * perimeter, start.1 * perimeter]),
            inset: Some(inset * pitch), diameter: Some(diameter * pitch), ..Default::default()
        };
        let (inset, radius) = (inset * pitch, 0.5 * diameter * pitch);
        let r = match api::connect::connect(&pieces, &o) {
            // Holes wider than twice the inset cross the edge everywhere: an error, not a warning.
            Err(e) if inset < radius => {
                prop_assert!(e.to_string().contains("across the edge"), "inset {inset} < radius {radius}: {e}");
                return Ok(());
            }
            r => r.map_err(|e| TestCaseError::fail(format!("connect: {e}")))?,
        };
        prop_assert!(inset >= radius, "inset {inset} < radius {radius} was accepted");
        prop_assert_eq!(r.count, count);
        prop_assert!(rel(r.pitch, pitch) <= 1e-12, "pitch: wanted {pitch}, got {}", r.pitch);
        for (j, piece) in r.pieces.iter().enumerate() {
            let name = ["first piece", "second piece"][j];
            let labels: Vec<&str> = piece.labels.iter().map(|l| l.text.as_str()).collect();
            let want: Vec<String> = (1..=count).map(|k| k.to_string()).collect();
            prop_assert_eq!(labels, want.iter().map(String::as_str).collect::<Vec<_>>(), "{} labels", name);
            prop_assert_eq!(piece.holes.len(), count, "{} holes", name);
            // A walks counter-clockwise, B clockwise; against the drawing direction, arc length
            // from the first anchor runs backwards.
            let ccw = signed_area(&segs[j]) > 0.0;
            let forward = if j == 0 { ccw } else { !ccw };
            let s0 = [start.0, start.1][j] * perimeter;
            let crossing = named(&r.warnings, name, "cross the edge");
            let outside = named(&r.warnings, name, "lie outside");
            let overlap = named(&r.warnings, name, "overlap");
            for (k, h) in piece.holes.iter().enumerate() {
                let (d, i, t) = nearest(&segs[j], h.center);
                let drawn = ksum(lens[j][..i].iter().copied()) + cubic_len_adaptive(head(&segs[j][i], t));
                let walked = if forward { drawn } else { perimeter - drawn };
                if (d - inset).abs() <= 1e-9 * perimeter {
                    // The hole's nearest edge point is its own station: check the spacing there.
                    let want = s0 + (k as f64 + slide) * pitch;
                    let off = (walked - want).rem_euclid(perimeter);
                    let off = off.min(perimeter - off);
                    prop_assert!(off <= 1e-8 * perimeter, "{name} hole {}: at arc length {walked}, wanted {want} (mod {perimeter})", k + 1);
                }
                let n = k + 1;
                let excused = |list: &Option<Vec<usize>>| list.as_ref().is_none_or(|l| l.contains(&n));
                if d < radius * (1.0 - 1e-6) {
                    // Named as crossing, or as outside when its centre went through the piece.
                    prop_assert!(excused(&crossing) || excused(&outside), "{name} hole {n} crosses the edge (distance {d} < radius {radius}) unwarned: {:?}", r.warnings);
                } else if d > radius * (1.0 + 1e-6) && !inside(&segs[j], h.center) {
                    prop_assert!(excused(&outside), "{name} hole {n} is outside its piece unwarned: {:?}", r.warnings);
                }
                for (m, g) in piece.holes.iter().enumerate().skip(k + 1) {
                    if dist(h.center, g.center) < 2.0 * radius * (1.0 - 1e-9) {
                        prop_assert!(excused(&overlap) && overlap.as_ref().is_none_or(|l| l.contains(&(m + 1))),
                            "{name} holes {n} and {} overlap unwarned: {:?}", m + 1, r.warnings);
                    }
                }
            }
        }
    }
}
