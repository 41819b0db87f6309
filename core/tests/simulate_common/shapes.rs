//! Outlines for the simulate tests and the native bench: smooth closed curves through sample
//! points (Catmull–Rom handles), polar shapes, polylines, the browser app's bundled "Pebble"
//! and scaling to a given perimeter. Shared by `core/tests/simulate_sheet.rs` and
//! `core/examples/simulate_bench.rs` (included there by `#[path]`).
#![allow(dead_code)]

use dformer::arclen::ArcTable;
use dformer::contour::{Contour, Knot};
use kurbo::{Affine, Point};
use std::f64::consts::TAU;

/// A smooth closed outline through `pts` (in order), tangents by Catmull–Rom (handle = 1/6 of
/// the neighbours' difference), first anchor at `pts[0]`.
pub fn smooth(pts: &[(f64, f64)]) -> Contour {
    let m = pts.len();
    let knots = (0..m)
        .map(|i| {
            let (a, prev, next) = (pts[i], pts[(i + m - 1) % m], pts[(i + 1) % m]);
            let t = ((next.0 - prev.0) / 6.0, (next.1 - prev.1) / 6.0);
            Knot { anchor: Point::new(a.0, a.1), left: Point::new(a.0 - t.0, a.1 - t.1), right: Point::new(a.0 + t.0, a.1 + t.1) }
        })
        .collect();
    Contour::new(knots, 0).unwrap()
}

/// A polar shape `r(θ)` through `m` points, smooth.
pub fn polar(m: usize, r: impl Fn(f64) -> f64) -> Contour {
    let pts: Vec<(f64, f64)> = (0..m).map(|k| k as f64 * TAU / m as f64).map(|t| (r(t) * t.cos(), r(t) * t.sin())).collect();
    smooth(&pts)
}

/// A closed polyline (every knot a corner).
pub fn polyline(pts: &[(f64, f64)]) -> Contour {
    Contour::new(pts.iter().map(|&(x, y)| Knot::corner(Point::new(x, y))).collect(), 0).unwrap()
}

pub fn perimeter(c: &Contour) -> f64 {
    ArcTable::new(c, 1e-13).total()
}

/// `c` scaled about the origin to perimeter `p`.
pub fn with_perimeter(c: &Contour, p: f64) -> Contour {
    c.transformed(Affine::scale(p / perimeter(c)))
}

/// A circle of the same perimeter as `c` (eight smooth arcs).
pub fn circle_for(c: &Contour) -> Contour {
    with_perimeter(&circle(1.0, 8), perimeter(c))
}

/// A circle of radius `r` by `m` cubic arcs, first anchor at (r, 0).
pub fn circle(r: f64, m: usize) -> Contour {
    let h = 4.0 / 3.0 * (TAU / (4.0 * m as f64)).tan() * r;
    let knots = (0..m)
        .map(|k| {
            let t = k as f64 * TAU / m as f64;
            let (c, s) = (t.cos(), t.sin());
            let a = Point::new(r * c, r * s);
            Knot { anchor: a, left: Point::new(a.x + h * s, a.y - h * c), right: Point::new(a.x - h * s, a.y + h * c) }
        })
        .collect();
    Contour::new(knots, 0).unwrap()
}

/// The kidney of issue 14: r = 60(1 + 0.35 cos 2θ − 0.25 cos θ + 0.2 sin 3θ).
pub fn kidney() -> Contour {
    polar(72, |t| 60.0 * (1.0 + 0.35 * (2.0 * t).cos() - 0.25 * t.cos() + 0.2 * (3.0 * t).sin()))
}

/// Five lobes: r = 55(1 + 0.12 sin 5θ).
pub fn five_lobed() -> Contour {
    polar(80, |t| 55.0 * (1.0 + 0.12 * (5.0 * t).sin()))
}

/// An organic blob: r = 50(1 + 0.18 cos 2θ + 0.12 sin 3θ − 0.08 cos 5θ).
pub fn blob() -> Contour {
    polar(72, |t| 50.0 * (1.0 + 0.18 * (2.0 * t).cos() + 0.12 * (3.0 * t).sin() - 0.08 * (5.0 * t).cos()))
}

/// A heart: x = 16 sin³t, y = 13 cos t − 5 cos 2t − 2 cos 3t − cos 4t (scaled by 3), smooth
/// (its dip at the top is a concave stretch; the tip at the bottom is rounded by the sampling).
pub fn heart() -> Contour {
    let m = 64;
    let pts: Vec<(f64, f64)> = (0..m)
        .map(|k| k as f64 * TAU / m as f64)
        .map(|t| (3.0 * 16.0 * t.sin().powi(3), 3.0 * (13.0 * t.cos() - 5.0 * (2.0 * t).cos() - 2.0 * (3.0 * t).cos() - (4.0 * t).cos())))
        .collect();
    // Counter-clockwise with its first anchor one point after the top dip (0.59 mm along it).
    let mut pts = pts;
    pts.reverse();
    smooth(&pts)
}

/// A heart as one draws it in Illustrator or Inkscape: six cubic arcs, smooth on its lobes and
/// sides, with a corner anchor at the top dip (reflex, an inside angle of about 260°) and one
/// at the bottom tip (about 78°); first anchor at the dip, counter-clockwise.
pub fn drawn_heart() -> Contour {
    let k = |a: (f64, f64), l: (f64, f64), r: (f64, f64)| Knot { anchor: Point::new(a.0, a.1), left: Point::new(l.0, l.1), right: Point::new(r.0, r.1) };
    let knots = vec![
        k((0.0, 40.0), (12.0, 50.0), (-12.0, 50.0)),
        k((-30.0, 60.0), (-18.0, 60.0), (-42.0, 60.0)),
        k((-55.0, 30.0), (-55.0, 45.0), (-55.0, 15.0)),
        k((0.0, -45.0), (-20.0, -20.0), (20.0, -20.0)),
        k((55.0, 30.0), (55.0, 15.0), (55.0, 45.0)),
        k((30.0, 60.0), (42.0, 60.0), (18.0, 60.0)),
    ];
    Contour::new(knots, 0).unwrap()
}

/// [`drawn_heart`] with its top dip, the corner between the lobes, at height `y` instead of 40
/// (the lobes' tops are at 60): a shallower bay for a larger `y`. The dip's handles keep their
/// share of the rise to the lobes.
pub fn drawn_heart_with_dip(y: f64) -> Contour {
    let mut knots = drawn_heart().knots().to_vec();
    let rise = y + 10.0 * (60.0 - y) / 20.0;
    knots[0] = Knot { anchor: Point::new(0.0, y), left: Point::new(12.0, rise), right: Point::new(-12.0, rise) };
    Contour::new(knots, 0).unwrap()
}

/// The polygon `pts` (counter-clockwise) with every corner rounded by a circular arc of radius
/// `r` (one cubic per arc, from the tangent point on one side to the other's), or the polygon
/// itself for `r = 0`.
pub fn rounded_polygon(pts: &[(f64, f64)], r: f64) -> Contour {
    if r == 0.0 {
        return polyline(pts);
    }
    let n = pts.len();
    let unit = |a: (f64, f64), b: (f64, f64)| {
        let l = (b.0 - a.0).hypot(b.1 - a.1);
        ((b.0 - a.0) / l, (b.1 - a.1) / l)
    };
    let mut knots = Vec::new();
    for k in 0..n {
        let b = pts[k];
        let (u, v) = (unit(b, pts[(k + n - 1) % n]), unit(b, pts[(k + 1) % n]));
        let inside = (u.0 * v.0 + u.1 * v.1).clamp(-1.0, 1.0).acos();
        let t = r / (inside / 2.0).tan();
        let h = 4.0 / 3.0 * ((std::f64::consts::PI - inside) / 4.0).tan() * r;
        let (a, c) = (Point::new(b.0 + u.0 * t, b.1 + u.1 * t), Point::new(b.0 + v.0 * t, b.1 + v.1 * t));
        knots.push(Knot { anchor: a, left: a, right: Point::new(a.x - u.0 * h, a.y - u.1 * h) });
        knots.push(Knot { anchor: c, left: Point::new(c.x - v.0 * h, c.y - v.1 * h), right: c });
    }
    Contour::new(knots, 0).unwrap()
}

/// A `w` × `h` rectangle with its corners rounded by `r` ([`rounded_polygon`]), its first anchor
/// where the corner at the origin meets the left side.
pub fn rounded_rect(w: f64, h: f64, r: f64) -> Contour {
    rounded_polygon(&[(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)], r)
}

/// The survey's triangle (corners of 63°, 50° and 66°) with its corners rounded by `r`.
pub fn rounded_triangle(r: f64) -> Contour {
    rounded_polygon(&[(0.0, 0.0), (80.0, 0.0), (30.0, 60.0)], r)
}

/// A five-pointed star with rounded tips: [`polar_star`] with 5 tips, `a` = 0.28.
pub fn rounded_star() -> Contour {
    polar_star(5.0, 0.28)
}

/// A star of `tips` rounded tips, r = 50(1 + a·cos³(tips·θ)) mm, through 100 points.
pub fn polar_star(tips: f64, a: f64) -> Contour {
    polar(100, move |t| 50.0 * (1.0 + a * (tips * t).cos().powi(3)))
}

/// A star polygon of `points` tips on a radius of 50 mm, its valleys at `inner` times that,
/// every corner rounded by `r` ([`rounded_polygon`]).
pub fn star_polygon(points: usize, inner: f64, r: f64) -> Contour {
    let pts: Vec<(f64, f64)> = (0..2 * points)
        .map(|i| {
            let radius = if i % 2 == 0 { 50.0 } else { 50.0 * inner };
            let t = std::f64::consts::PI * i as f64 / points as f64;
            (radius * t.sin(), radius * t.cos())
        })
        .collect();
    rounded_polygon(&pts, r)
}

/// An L-shaped hexagon (one reflex corner): [`notched_l`] with a 40 mm notch, sharp.
pub fn l_shape() -> Contour {
    notched_l(40.0, 0.0)
}

/// An 80 mm square with a `depth` × `depth` notch cut from its top right corner (an L), every
/// corner rounded by `r` ([`rounded_polygon`]).
pub fn notched_l(depth: f64, r: f64) -> Contour {
    let w = 80.0 - depth;
    rounded_polygon(&[(0.0, 0.0), (80.0, 0.0), (80.0, w), (w, w), (w, 80.0), (0.0, 80.0)], r)
}

/// An arrow-head quadrilateral (a dart: one reflex corner).
pub fn dart() -> Contour {
    polyline(&[(0.0, 0.0), (60.0, 20.0), (0.0, 40.0), (15.0, 20.0)])
}

/// The browser app's bundled "Pebble" (uxp-panel/samples/samples.js), y flipped to y-up.
pub fn pebble() -> Contour {
    let seg = [
        [(20.0, 62.0), (18.0, 30.0), (52.0, 12.0), (88.0, 16.0)],
        [(88.0, 16.0), (122.0, 20.0), (152.0, 30.0), (150.0, 62.0)],
        [(150.0, 62.0), (148.0, 92.0), (126.0, 106.0), (96.0, 100.0)],
        [(96.0, 100.0), (76.0, 96.0), (62.0, 108.0), (44.0, 104.0)],
        [(44.0, 104.0), (26.0, 100.0), (21.0, 82.0), (20.0, 62.0)],
    ];
    let p = |q: (f64, f64)| Point::new(q.0, -q.1);
    let m = seg.len();
    let knots = (0..m).map(|i| Knot { anchor: p(seg[i][0]), left: p(seg[(i + m - 1) % m][2]), right: p(seg[i][1]) }).collect();
    Contour::new(knots, 0).unwrap()
}

/// A 1:2 ellipse (semi-axes 30 across, 60 up) through 96 points, first anchor at (30, 0) on its
/// flattest stretch, with a smooth dent there of depth `depth` relative to its height (120): the
/// radius drops by `depth · 120 · exp(−(θ/0.25)²)`, θ in (−π, π]. Symmetric about the x axis.
pub fn dented_ellipse(depth: f64) -> Contour {
    polar(96, |t| {
        let r = 1.0 / ((t.cos() / 30.0).powi(2) + (t.sin() / 60.0).powi(2)).sqrt();
        let d = if t > std::f64::consts::PI { t - TAU } else { t };
        r - depth * 120.0 * (-(d / 0.25).powi(2)).exp()
    })
}

/// Whether an outline turns clockwise somewhere (a concave stretch), from 64 points per segment.
pub fn has_concave_stretch(c: &Contour) -> bool {
    use kurbo::ParamCurve;
    let pts: Vec<Point> = c.segments().flat_map(|s| (0..64).map(move |k| s.eval(k as f64 / 64.0))).collect();
    let m = pts.len();
    let turn = |k: usize| {
        let (a, b, d) = (pts[(k + m - 1) % m], pts[k], pts[(k + 1) % m]);
        (b.x - a.x) * (d.y - b.y) - (b.y - a.y) * (d.x - b.x)
    };
    let ccw = c.signed_area() > 0.0;
    (0..m).any(|k| if ccw { turn(k) < 0.0 } else { turn(k) > 0.0 })
}

/// `c` mirrored in the y axis (x → −x): glued to `c` at offset 0 the two flat pieces coincide.
pub fn mirrored(c: &Contour) -> Contour {
    c.transformed(Affine::scale_non_uniform(-1.0, 1.0))
}
