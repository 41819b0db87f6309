//! Clean corners: squares, rectangles and triangles glued to circles, at the default sizes and
//! at the sizes of the issue's report (a 41.6 × 40.1 mm square with a circle, 24 holes of 2 mm at
//! 4 mm inset). Checked with geometry written here: distances to the polygon's sides in closed
//! form, to the circle by its radius, label boxes (`size` high, `(0.6·chars + 0.2)·size` wide,
//! the box hosts draw into) by the separating-axis test. Stitch holes must come out with no
//! warning at all: on squares and rectangles a hole on every corner, on triangles (60°, 37°, 21°
//! and 17° corners) holes along the inset line clear of the tips; so must locking leaves.

mod common;
use common::*;
use dformer::api::connect::{connect, ConnectDto, ConnectOptionsDto};
use dformer::api::path::PathDto;
use std::f64::consts::PI;

/// A label's box as its four corners.
fn label_box(at: P, angle: f64, size: f64, chars: usize) -> [P; 4] {
    let (c, s) = (angle.to_radians().cos(), angle.to_radians().sin());
    let (hw, hh) = (0.5 * (0.6 * chars as f64 + 0.2) * size, 0.5 * size);
    [(-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh)].map(|(x, y)| [at[0] + x * c - y * s, at[1] + x * s + y * c])
}

/// Separating-axis test for two convex quadrilaterals.
fn boxes_overlap(a: &[P; 4], b: &[P; 4]) -> bool {
    for poly in [a, b] {
        for i in 0..4 {
            let (p, q) = (poly[i], poly[(i + 1) % 4]);
            let n = [q[1] - p[1], p[0] - q[0]];
            let proj = |r: &[P; 4]| r.iter().map(|v| v[0] * n[0] + v[1] * n[1]).fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)));
            let ((a0, a1), (b0, b1)) = (proj(a), proj(b));
            if a1 <= b0 || b1 <= a0 {
                return false;
            }
        }
    }
    true
}

/// Whether segments ab and cd cross (orientation test, touching counts).
fn segments_cross(a: P, b: P, c: P, d: P) -> bool {
    let o = |p: P, q: P, r: P| (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    o(a, b, c) * o(a, b, d) <= 0.0 && o(c, d, a) * o(c, d, b) <= 0.0
}

/// Distance from q to the box (0 inside).
fn box_dist(bx: &[P; 4], q: P) -> f64 {
    if inside_poly(&bx[..], q) { 0.0 } else { dist_poly(&bx[..], q) }
}

/// An outline as a polygon (the circle as a dense polyline of its cubics).
enum Shape {
    Poly(Vec<P>),
}

impl Shape {
    fn dist(&self, q: P) -> f64 {
        match self {
            Shape::Poly(p) => dist_poly(p, q),
        }
    }
    fn inside(&self, q: P) -> bool {
        match self {
            Shape::Poly(p) => inside_poly(p, q),
        }
    }
    /// Whether the outline comes into the box: a box corner outside, or a polygon vertex
    /// inside it, or a side crossing one of the box's sides.
    fn meets_box(&self, bx: &[P; 4]) -> bool {
        match self {
            Shape::Poly(p) => {
                bx.iter().any(|&c| !inside_poly(p, c))
                    || p.iter().any(|&v| box_dist(bx, v) == 0.0)
                    || (0..p.len()).any(|i| (0..4).any(|j| segments_cross(p[i], p[(i + 1) % p.len()], bx[j], bx[(j + 1) % 4])))
            }
        }
    }
}

/// A polygon and a circle of the same perimeter, circle drawn clockwise far to the right.
fn with_circle(pts: &[P]) -> (Vec<PathDto>, [Shape; 2]) {
    let per: f64 = (0..pts.len()).map(|i| { let (a, b) = (pts[i], pts[(i + 1) % pts.len()]); (b[0] - a[0]).hypot(b[1] - a[1]) }).sum();
    let c = ellipse([0.0, 0.0], 1.0, 1.0, 4, true);
    let scale = per / perimeter_truth(&c);
    let centre = [200.0, 0.0];
    let circle = moved(&c, scale, centre);
    // The 4-cubic circle is within 2.7e-4 of its radius: measured as its own polyline.
    let _ = (centre, PI);
    (vec![polygon(pts), circle.clone()], [Shape::Poly(pts.to_vec()), Shape::Poly(flatten(&circle, 400))])
}

/// Whether a warning about `what` on piece `i` names connector `k` (1-based).
fn warned(r: &ConnectDto, i: usize, what: &str, k: usize) -> bool {
    let piece = ["On the first piece", "On the second piece"][i];
    r.warnings.iter().any(|w| {
        w.starts_with(piece) && w.contains(what) && {
            let list = &w[w.find("connectors").map_or(0, |x| x + 10)..];
            let list = &list[..list.find(|c: char| c.is_alphabetic()).unwrap_or(list.len())];
            list.split(|c: char| !c.is_ascii_digit()).any(|t| t == k.to_string())
        }
    })
}

/// Every hole clear of the edge and inside, every label box clear of the other labels, holes,
/// slots and cut line, unless a warning names it; `strict`: no such warning at all.
fn check(name: &str, r: &ConnectDto, shapes: &[Shape; 2], strict: bool) {
    for (i, piece) in r.pieces.iter().enumerate() {
        let shape = &shapes[i];
        for (k, h) in piece.holes.iter().enumerate() {
            let d = shape.dist(h.center);
            let ok = shape.inside(h.center) && d > 0.5 * h.diameter;
            assert!(ok || warned(r, i, "holes of", k + 1), "{name} piece {i} hole {}: {d} from the edge, radius {}, unwarned: {:?}", k + 1, 0.5 * h.diameter, r.warnings);
        }
        let boxes: Vec<[P; 4]> = piece.labels.iter().map(|l| label_box(l.at, l.angle, l.size, l.text.len())).collect();
        for (k, b) in boxes.iter().enumerate() {
            let excused = |m: usize| warned(r, i, "numbers of", k + 1) || warned(r, i, "numbers of", m + 1);
            for (m, c) in boxes.iter().enumerate().skip(k + 1) {
                assert!(!boxes_overlap(b, c) || excused(m), "{name} piece {i}: labels {} and {} overlap", k + 1, m + 1);
            }
            for (m, h) in piece.holes.iter().enumerate() {
                assert!(box_dist(b, h.center) >= 0.5 * h.diameter || excused(k), "{name} piece {i}: label {} on hole {}", k + 1, m + 1);
            }
            for (m, s) in piece.slots.iter().enumerate() {
                let sq: [P; 4] = [0, 1, 2, 3].map(|j| s.points[j].anchor);
                assert!(!boxes_overlap(b, &sq) || excused(k), "{name} piece {i}: label {} on slot {}", k + 1, m + 1);
            }
            assert!(!shape.meets_box(b) || excused(k), "{name} piece {i}: label {} crosses the cut line", k + 1);
            assert!(piece.labels[k].size > 0.0);
        }
    }
    if strict {
        assert!(!r.warnings.iter().any(|w| w.contains("cross the edge") || w.contains("overlap") || w.contains("do not fit")), "{name}: {:?}", r.warnings);
    }
}

fn shapes() -> Vec<(&'static str, Vec<P>)> {
    let tri_h = 50.0 * (3f64).sqrt() / 2.0;
    vec![
        ("square 41.6 × 40.1", vec![[0.0, 0.0], [41.6, 0.0], [41.6, 40.1], [0.0, 40.1]]),
        ("rectangle 80 × 25", vec![[0.0, 0.0], [80.0, 0.0], [80.0, 25.0], [0.0, 25.0]]),
        ("equilateral triangle 50", vec![[0.0, 0.0], [50.0, 0.0], [25.0, tri_h]]),
        ("right triangle 60 × 45", vec![[0.0, 0.0], [60.0, 0.0], [0.0, 45.0]]),
    ]
}

#[test]
fn holes_and_labels_keep_clear_of_corners_at_the_default_sizes() {
    for (name, pts) in shapes() {
        let (pieces, sh) = with_circle(&pts);
        let r = connect(&pieces, &ConnectOptionsDto { count: Some(24.0), ..Default::default() }).unwrap();
        check(&format!("{name}, stitch defaults"), &r, &sh, true);
    }
}

#[test]
fn test_issue_square_with_circle_24_holes_of_2mm_at_4mm_inset() {
    // Before: holes bunched at the corners, labels 24, 1 and 2 overlapped, two holes crossed the edge.
    for (name, pts) in shapes() {
        let (pieces, sh) = with_circle(&pts);
        let r = connect(&pieces, &ConnectOptionsDto { count: Some(24.0), diameter: Some(2.0), inset: Some(4.0), ..Default::default() }).unwrap();
        check(&format!("{name}, 2 mm holes at 4 mm"), &r, &sh, true);
    }
}

#[test]
fn locking_leaves_labels_keep_clear_of_slots_and_edges() {
    for (name, pts) in shapes() {
        let (pieces, _) = with_circle(&pts);
        let r = connect(&pieces, &ConnectOptionsDto { kind: Some("leaves".into()), leaf: Some("lock".into()), count: Some(16.0), ..Default::default() }).unwrap();
        // Leaves change the outline: labels are checked against the leafy cut line.
        let sh = [Shape::Poly(flatten(&r.pieces[0].outline, 32)), Shape::Poly(flatten(&r.pieces[1].outline, 32))];
        check(&format!("{name}, locking leaves"), &r, &sh, true);
    }
}

/// The stitch options every host starts with, read from `defaults()` for a seam of `pitch`: the
/// fixed values as they are, the derived sizes as their fraction of the pitch. `slide` is left
/// unset, as hosts leave it ("left unset, connectors are shifted clear of the corners").
fn default_stitch_options(pitch: f64) -> ConnectOptionsDto {
    use dformer::api::defaults::serde_json_value::Value;
    let d = dformer::api::defaults();
    let of = |name: &str| d.options.iter().find(|o| o.name == name && o.kinds.iter().any(|k| k == "stitch")).unwrap_or_else(|| panic!("no default {name}"));
    let number = |name: &str| match (&of(name).value, of(name).pitch) {
        (Some(Value::Number(x)), _) => *x,
        (None, Some(f)) => f * pitch,
        other => panic!("{name}: {other:?}"),
    };
    let Some(Value::Text(kind)) = of("kind").value.clone() else { panic!("kind") };
    ConnectOptionsDto {
        kind: Some(kind),
        count: Some(number("count")),
        diameter: Some(number("diameter")),
        inset: Some(number("inset")),
        kerf: Some(number("kerf")),
        ..Default::default()
    }
}

/// Before: at the default sizes, triangles glued to circles had labels that fit nowhere (the
/// equilateral one: numbers 17 and 24; the right one: holes 18, 19 and 20 overlapping at its
/// 37° corner) and a thin one holes across the edge and outside the piece at its 21° tip. Each
/// triangle is normalized against a circle (to their mean perimeter), connected with the options
/// of `defaults()`, and checked here with no excuse: no warning at all, every hole wholly inside
/// its piece and clear of every other hole, every label box inside its piece, off the cut line,
/// off every hole and every other label, and nearest its own hole.
#[test]
fn triangles_glued_to_circles_get_no_warning_at_the_defaults() {
    use dformer::api::normalize::{normalize, NormalizeOptionsDto};
    use dformer::api::value::Value;
    let tri_h = 50.0 * (3f64).sqrt() / 2.0;
    let triangles: Vec<(&str, Vec<P>)> = vec![
        ("equilateral triangle 50", vec![[0.0, 0.0], [50.0, 0.0], [25.0, tri_h]]),
        ("right triangle 60 × 45", vec![[0.0, 0.0], [60.0, 0.0], [0.0, 45.0]]),
        ("thin triangle 30 × 80 (21° tip)", vec![[0.0, 0.0], [30.0, 0.0], [15.0, 80.0]]),
        ("thin right triangle 100 × 30 (17° corner)", vec![[0.0, 0.0], [100.0, 0.0], [0.0, 30.0]]),
    ];
    for (name, pts) in triangles {
        let circle = moved(&ellipse([0.0, 0.0], 1.0, 1.0, 4, true), 30.0, [200.0, 0.0]);
        let n = normalize(&[polygon(&pts), circle], &NormalizeOptionsDto { target: Some(Value::Text("mean".into())), ..Default::default() }).unwrap();
        let (tri, circ) = (&n.paths[0], &n.paths[1]);
        let shapes = [Shape::Poly(tri.points.iter().map(|p| p.anchor).collect()), Shape::Poly(flatten(circ, 400))];
        let options = default_stitch_options(n.perimeter / 24.0);
        assert_eq!(options.count, Some(24.0), "{name}: the default count");
        let r = connect(&n.paths, &options).unwrap();
        assert!(r.warnings.is_empty(), "{name}: {:?}", r.warnings);
        check(name, &r, &shapes, true);
        for (i, piece) in r.pieces.iter().enumerate() {
            assert_eq!((piece.holes.len(), piece.labels.len()), (24, 24), "{name} piece {i}: one hole and one number per connector");
            for (k, h) in piece.holes.iter().enumerate() {
                for (m, g) in piece.holes.iter().enumerate().skip(k + 1) {
                    let gap = (h.center[0] - g.center[0]).hypot(h.center[1] - g.center[1]);
                    assert!(gap > 0.5 * (h.diameter + g.diameter), "{name} piece {i}: holes {} and {} overlap ({gap} apart)", k + 1, m + 1);
                }
            }
            for (k, l) in piece.labels.iter().enumerate() {
                assert_eq!(l.text, (k + 1).to_string());
                let bx = label_box(l.at, l.angle, l.size, l.text.len());
                assert!(!shapes[i].meets_box(&bx), "{name} piece {i}: label {} is not wholly inside the piece", k + 1);
                let dist = |h: &dformer::api::connect::HoleDto| (h.center[0] - l.at[0]).hypot(h.center[1] - l.at[1]);
                let nearest = (0..24).min_by(|&a, &b| dist(&piece.holes[a]).total_cmp(&dist(&piece.holes[b]))).unwrap();
                assert_eq!(nearest, k, "{name} piece {i}: label {} is nearest hole {}", k + 1, nearest + 1);
            }
        }
    }
}
