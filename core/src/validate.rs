//! Input checks shared by every operation: an outline must have length and must not cross itself.
//!
//! ## Self-intersection
//! The outline is first mapped into the unit box `[-1, 1]²` (translate to the centre of the
//! control bounds, divide by half the larger side), so every tolerance below is *relative to
//! the shape's size* and lyon_geom's absolute epsilons (tuned for coordinates of order 1) apply.
//! Then:
//! - segments whose control polygon is shorter than [`DEGENERATE`] are dropped: zero-length
//!   segments are normal input, and their neighbours become adjacent;
//! - every remaining cubic is checked for a loop of its own (closed form, [`cubic_loop`]) and
//!   for a straight segment that doubles back on itself;
//! - candidate pairs come from a uniform grid of about one cell per segment over the
//!   control-point bounding boxes, so a 1,000-segment outline costs about `n` plus the pairs
//!   whose boxes really overlap;
//! - each candidate pair goes to lyon_geom's Bézier clipping (`cubic_intersections_t`).
//!   Adjacent segments meet at their shared anchor by construction: a pair whose control points
//!   lie in disjoint angular cones around that anchor cannot meet anywhere else (convex-hull
//!   property) and is skipped; otherwise hits within [`JOIN`] of the shared anchor are ignored.
//!   Non-adjacent segments that merely touch at an anchor, and collinear straight segments
//!   that overlap (lyon reports none for parallel lines), count as intersections.

use crate::libm_ext::LibmExt;
use crate::arclen::control_polygon_len;
use crate::contour::Contour;
use crate::error::{Error, Result};
use kurbo::{CubicBez, Point, Vec2};
use lyon_geom::{point as lpoint, CubicBezierSegment};

/// Control polygons shorter than this (relative to the half-size of the shape) are zero-length.
const DEGENERATE: f64 = 1e-12;
/// Intersections closer than this to the anchor shared by adjacent segments are that anchor.
const JOIN: f64 = 1e-7;
/// Two anchors of non-adjacent segments closer than this touch.
const TOUCH: f64 = 1e-10;
/// Collinearity / overlap tolerance for straight segments.
const LINEAR: f64 = 1e-10;
/// Parameter separation that makes a single-cubic self-intersection a real loop.
const LOOP_DT: f64 = 1e-7;

/// Checks a closed outline: non-zero length, no self-intersection.
pub fn check_outline(contour: &Contour, piece: usize) -> Result<()> {
    if contour.segments().all(|c| control_polygon_len(&c) == 0.0) {
        return Err(Error::ZeroLength { piece });
    }
    match find_self_intersection(contour) {
        Some((first, second)) => Err(Error::SelfIntersection { piece, first, second }),
        None => Ok(()),
    }
}

/// A segment of the normalized outline, with its index in the contour.
struct Seg {
    index: usize,
    c: CubicBez,
    min: Point,
    max: Point,
}

/// The first pair `(i, j)`, `i ≤ j`, of contour segments that intersect (`i == j`: segment i
/// loops over itself), or `None` for a simple outline. Pairs are ordered lexicographically,
/// so the answer does not depend on the search order.
pub fn find_self_intersection(contour: &Contour) -> Option<(usize, usize)> {
    let (lo, hi) = contour.control_bounds();
    let centre = lo.midpoint(hi);
    // Half-size computed by halves so that ±1e308 coordinates do not overflow.
    let half = (hi.x / 2.0 - lo.x / 2.0).max(hi.y / 2.0 - lo.y / 2.0);
    if !(half > 0.0 && half.is_finite()) {
        return None;
    }
    let norm = |p: Point| Point::new((p.x - centre.x) / half, (p.y - centre.y) / half);
    let segs: Vec<Seg> = contour
        .segments()
        .map(|c| CubicBez::new(norm(c.p0), norm(c.p1), norm(c.p2), norm(c.p3)))
        .enumerate()
        .filter(|(_, c)| control_polygon_len(c) > DEGENERATE)
        .map(|(index, c)| {
            let (min, max) = control_box(&c);
            Seg { index, c, min, max }
        })
        .collect();
    let n = segs.len();
    let mut best: Option<(usize, usize)> = None;
    let mut found = |i: usize, j: usize| {
        let pair = (i.min(j), i.max(j));
        if best.is_none_or(|b| pair < b) {
            best = Some(pair);
        }
    };

    for s in &segs {
        if cubic_loop(&s.c, n == 1) || doubles_back(&s.c) {
            found(s.index, s.index);
        }
    }

    // Candidate pairs from a uniform grid over the unit box (about one segment per cell): a pair
    // is tested once, in the first cell its two boxes share.
    let g = ((n as f64).sqrt().ceil() as usize).clamp(1, 256);
    let cell = |x: f64| (((x + 1.0) * 0.5 * g as f64).floor().max(0.0) as usize).min(g - 1);
    let span = |s: &Seg| (cell(s.min.x - LINEAR), cell(s.max.x + LINEAR), cell(s.min.y - LINEAR), cell(s.max.y + LINEAR));
    let spans: Vec<_> = segs.iter().map(span).collect();
    let mut grid: Vec<Vec<usize>> = vec![Vec::new(); g * g];
    // Segments whose box covers many cells are paired with everything directly instead, so
    // memory stays O(n) however the handles are drawn.
    let mut big: Vec<usize> = Vec::new();
    for (k, &(x0, x1, y0, y1)) in spans.iter().enumerate() {
        if (x1 - x0 + 1) * (y1 - y0 + 1) > 64 {
            big.push(k);
            continue;
        }
        for cy in y0..=y1 {
            for cx in x0..=x1 {
                if let Some(c) = grid.get_mut(cy * g + cx) {
                    c.push(k);
                }
            }
        }
    }
    let mut test_pair = |i: usize, j: usize| {
        let (i, j) = (i.min(j), i.max(j));
        let (Some(a), Some(b)) = (segs.get(i), segs.get(j)) else { return };
        if a.min.x > b.max.x + LINEAR || b.min.x > a.max.x + LINEAR || a.min.y > b.max.y + LINEAR || b.min.y > a.max.y + LINEAR {
            return;
        }
        if pair_intersects(a, b, j == i + 1, n > 1 && i == 0 && j == n - 1) {
            found(a.index, b.index);
        }
    };
    let mut is_big = vec![false; n];
    for &i in &big {
        for j in 0..n {
            // A pair of big segments is tested once, from the one listed first.
            if j != i && !is_big.get(j).copied().unwrap_or(false) {
                test_pair(i, j);
            }
        }
        if let Some(f) = is_big.get_mut(i) {
            *f = true;
        }
    }
    for (ci, members) in grid.iter().enumerate() {
        let (cx, cy) = (ci % g, ci / g);
        for (m, &i) in members.iter().enumerate() {
            for &j in members.iter().skip(m + 1) {
                let (Some(si), Some(sj)) = (spans.get(i), spans.get(j)) else { continue };
                if cx != si.0.max(sj.0) || cy != si.2.max(sj.2) {
                    continue; // tested in an earlier shared cell
                }
                test_pair(i, j);
            }
        }
    }
    best
}

fn control_box(c: &CubicBez) -> (Point, Point) {
    let xs = [c.p0.x, c.p1.x, c.p2.x, c.p3.x];
    let ys = [c.p0.y, c.p1.y, c.p2.y, c.p3.y];
    let min = Point::new(xs.iter().copied().fold(f64::INFINITY, f64::min), ys.iter().copied().fold(f64::INFINITY, f64::min));
    let max = Point::new(xs.iter().copied().fold(f64::NEG_INFINITY, f64::max), ys.iter().copied().fold(f64::NEG_INFINITY, f64::max));
    (min, max)
}

fn lyon(c: &CubicBez) -> CubicBezierSegment<f64> {
    CubicBezierSegment {
        from: lpoint(c.p0.x, c.p0.y),
        ctrl1: lpoint(c.p1.x, c.p1.y),
        ctrl2: lpoint(c.p2.x, c.p2.y),
        to: lpoint(c.p3.x, c.p3.y),
    }
}

/// Does segment `a` (earlier in the outline) meet segment `b`? `next`: `b` follows `a` (they
/// share `a.p3 = b.p0`); `wrap`: `a` follows `b` (they share `b.p3 = a.p0`).
fn pair_intersects(a: &Seg, b: &Seg, next: bool, wrap: bool) -> bool {
    let mut joins: Vec<Point> = Vec::with_capacity(2);
    if next {
        joins.push(a.c.p3);
    }
    if wrap {
        joins.push(a.c.p0);
    }
    // Adjacent segments separated by their tangent cones at every shared anchor meet only there.
    let separated = |j: Point| {
        half_plane_split(&a.c, &b.c, j)
            || match (cone(&a.c, j), cone(&b.c, j)) {
        (Some(ca), Some(cb)) => {
            let gap = ca.0.cross(cb.0).atan2_m(ca.0.dot(cb.0)).abs();
            gap > ca.1 + cb.1 + 1e-9
        }
        _ => false,
    }
    };
    if !joins.is_empty() && joins.iter().all(|&j| separated(j)) {
        return false;
    }
    // Straight, collinear, overlapping segments (lyon finds no point for parallel lines).
    if collinear_overlap(&a.c, &b.c) {
        return true;
    }
    // Non-adjacent segments touching at an anchor (lyon drops endpoint/endpoint hits), or an
    // anchor of one within TOUCH of the other (lyon drops hits at t = 0 or 1 too: a figure of eight
    // through an anchor of 11 straight sides, glued to itself, passed and then failed with
    // "too thin or too detailed for 32 seam vertices").
    if joins.is_empty() {
        for p in [a.c.p0, a.c.p3] {
            for q in [b.c.p0, b.c.p3] {
                if (p - q).hypot() < TOUCH {
                    return true;
                }
            }
        }
        let on = |p: Point, c: &CubicBez| kurbo::ParamCurveNearest::nearest(c, p, 1e-3 * TOUCH).distance_sq < TOUCH * TOUCH;
        if [a.c.p0, a.c.p3].into_iter().any(|p| on(p, &b.c)) || [b.c.p0, b.c.p3].into_iter().any(|p| on(p, &a.c)) {
            return true;
        }
    }
    let la = lyon(&a.c);
    let lb = lyon(&b.c);
    la.cubic_intersections_t(&lb).iter().any(|&(t, _)| {
        let p = la.sample(t);
        let p = Point::new(p.x, p.y);
        p.x.is_finite() && p.y.is_finite() && joins.iter().all(|&j| (p - j).hypot() > JOIN)
    })
}

/// Cheap sufficient test (no trigonometry) that the control points of `a` and `b` other than
/// the shared anchor `j` lie strictly on opposite sides of a line through `j`: the line
/// perpendicular to `w = dir(b) − dir(a)`, where `dir` is the unit direction from `j` to the
/// farthest control point. True for every ordinary join (a smooth join or a corner < 180°).
fn half_plane_split(a: &CubicBez, b: &CubicBez, j: Point) -> bool {
    let far = |c: &CubicBez| {
        [c.p0, c.p1, c.p2, c.p3].iter().map(|&p| p - j).fold(Vec2::ZERO, |m, v| if v.hypot2() > m.hypot2() { v } else { m })
    };
    let (fa, fb) = (far(a), far(b));
    if fa.hypot2() == 0.0 || fb.hypot2() == 0.0 {
        return false;
    }
    let w = fb / fb.hypot2().sqrt() - fa / fa.hypot2().sqrt();
    let side = |c: &CubicBez, sign: f64| {
        [c.p0, c.p1, c.p2, c.p3].iter().all(|&p| {
            let v = p - j;
            v.hypot2() <= DEGENERATE * DEGENERATE || sign * w.dot(v) > 1e-12 * v.hypot2().sqrt()
        })
    };
    side(a, -1.0) && side(b, 1.0)
}

/// The convex cone at anchor `j` containing the control points of `c` (other than those at
/// `j`): `(unit centre direction, half-angle)`, or `None` when it is not convex (wider than π).
fn cone(c: &CubicBez, j: Point) -> Option<(Vec2, f64)> {
    let mut angles: Vec<f64> = [c.p0, c.p1, c.p2, c.p3]
        .iter()
        .map(|&p| p - j)
        .filter(|v| v.hypot() > DEGENERATE)
        .map(|v| v.y.atan2_m(v.x))
        .collect();
    if angles.is_empty() {
        return None;
    }
    crate::order::sort_f64(&mut angles);
    // The widest gap between consecutive directions (cyclically) is where the cone is not.
    let tau = std::f64::consts::TAU;
    let (first, last) = (*angles.first()?, *angles.last()?);
    let mut gap = (first + tau - last, last, first + tau);
    for w in angles.windows(2) {
        if let [x, y] = w {
            if y - x > gap.0 {
                gap = (y - x, *x, *y);
            }
        }
    }
    let span = tau - gap.0;
    if span >= std::f64::consts::PI {
        return None;
    }
    // The cone runs from the gap's end to its start (counter-clockwise).
    let mid = gap.2 + span / 2.0;
    Some((Vec2::new(mid.cos_m(), mid.sin_m()), span / 2.0))
}

/// Distance of `p` from the line through `a` with unit direction `u`.
fn line_dist(p: Point, a: Point, u: Vec2) -> f64 {
    u.cross(p - a).abs()
}

/// Unit direction of a straight cubic, if all four control points lie on one line.
fn straight(c: &CubicBez) -> Option<(Point, Vec2)> {
    // Quick rejection (the common case): a handle clearly off the chord. Valid when the handles
    // are no farther from p0 than p3 is: then the chord is within 2·LINEAR/len of any line
    // that all points are within LINEAR of, so a straight cubic stays within 3·LINEAR of it.
    let v = c.p3 - c.p0;
    let len2 = v.hypot2();
    if len2 > 0.0
        && (c.p1 - c.p0).hypot2() <= len2
        && (c.p2 - c.p0).hypot2() <= len2
        && [c.p1, c.p2].iter().any(|&p| v.cross(p - c.p0).abs() > 4.0 * LINEAR * len2.sqrt())
    {
        return None;
    }
    let pts = [c.p0, c.p1, c.p2, c.p3];
    // Direction from the two farthest-apart control points.
    let mut far = (0.0, c.p0, c.p3);
    for (i, &p) in pts.iter().enumerate() {
        for &q in &pts[i + 1..] {
            let d = (q - p).hypot();
            if d > far.0 {
                far = (d, p, q);
            }
        }
    }
    if far.0 <= DEGENERATE {
        return None;
    }
    let u = (far.2 - far.1) / far.0;
    pts.iter().all(|&p| line_dist(p, far.1, u) <= LINEAR).then_some((far.1, u))
}

/// A straight cubic whose motion along its line reverses inside (0, 1): it retraces itself.
fn doubles_back(c: &CubicBez) -> bool {
    let Some((_, u)) = straight(c) else { return false };
    // x'(t)/3 along u is the quadratic Bernstein polynomial with coefficients d0, d1, d2.
    let (d0, d1, d2) = (u.dot(c.p1 - c.p0), u.dot(c.p2 - c.p1), u.dot(c.p3 - c.p2));
    let (qa, qb, qc) = (d0 - 2.0 * d1 + d2, 2.0 * (d1 - d0), d0);
    let scale = d0.abs() + d1.abs() + d2.abs();
    let roots: Vec<f64> = if qa.abs() <= 1e-12 * scale {
        if qb.abs() <= 1e-12 * scale { vec![] } else { vec![-qc / qb] }
    } else {
        let disc = qb * qb - 4.0 * qa * qc;
        if disc <= (1e-9 * scale).powi(2) {
            vec![]
        } else {
            let r = disc.sqrt();
            vec![(-qb - r) / (2.0 * qa), (-qb + r) / (2.0 * qa)]
        }
    };
    roots.iter().any(|&t| t > LOOP_DT && t < 1.0 - LOOP_DT)
}

/// Both straight, on one line, and sharing a stretch longer than the tolerance.
fn collinear_overlap(a: &CubicBez, b: &CubicBez) -> bool {
    let (Some((o, u)), Some(_)) = (straight(a), straight(b)) else { return false };
    if [b.p0, b.p1, b.p2, b.p3].iter().any(|&p| line_dist(p, o, u) > LINEAR) {
        return false;
    }
    let range = |c: &CubicBez| {
        let xs = [c.p0, c.p1, c.p2, c.p3].map(|p| u.dot(p - o));
        (xs.iter().copied().fold(f64::INFINITY, f64::min), xs.iter().copied().fold(f64::NEG_INFINITY, f64::max))
    };
    let (ra, rb) = (range(a), range(b));
    ra.1.min(rb.1) - ra.0.max(rb.0) > LINEAR
}

/// Does the cubic cross itself (a loop)? Closed form: with `B(t) = a t³ + b t² + c t + d`,
/// `(B(s) − B(t)) / (s − t) = a(σ² − π) + bσ + c = 0` where `σ = s + t`, `π = s t`.
/// Crossing with `a` gives `σ = −(a × c)/(a × b)`; projecting on `a` gives `π`;
/// `s, t` are the roots of `x² − σx + π`, a loop when both are real, distinct and in [0, 1].
/// `closed_alone`: the cubic is the whole outline, so `B(0) = B(1)` is its closure, not a loop.
pub fn cubic_loop(cb: &CubicBez, closed_alone: bool) -> bool {
    let (p0, p1, p2, p3) = (cb.p0.to_vec2(), cb.p1.to_vec2(), cb.p2.to_vec2(), cb.p3.to_vec2());
    let a = -p0 + 3.0 * p1 - 3.0 * p2 + p3;
    let b = 3.0 * p0 - 6.0 * p1 + 3.0 * p2;
    let c = 3.0 * (p1 - p0);
    let axb = a.cross(b);
    let aa = a.dot(a);
    if aa <= 1e-24 || axb.abs() <= 1e-14 * (aa.sqrt() * b.hypot()).max(f64::MIN_POSITIVE) {
        return false;
    }
    let sigma = -a.cross(c) / axb;
    let pi = sigma * sigma + (b * sigma + c).dot(a) / aa;
    let disc = sigma * sigma - 4.0 * pi;
    if !(disc > 0.0 && disc.is_finite()) {
        return false;
    }
    let r = disc.sqrt();
    let (s, t) = ((sigma - r) / 2.0, (sigma + r) / 2.0);
    let inside = s >= -1e-12 && t <= 1.0 + 1e-12 && t - s > LOOP_DT;
    let closure = closed_alone && s < LOOP_DT && t > 1.0 - LOOP_DT;
    inside && !closure
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::Knot;

    fn poly(pts: &[(f64, f64)]) -> Contour {
        Contour::new(pts.iter().map(|&p| Knot::corner(p.into())).collect(), 0).unwrap()
    }

    #[test]
    fn square_is_simple_and_bowtie_is_not() {
        assert_eq!(find_self_intersection(&poly(&[(0., 0.), (1., 0.), (1., 1.), (0., 1.)])), None);
        assert_eq!(find_self_intersection(&poly(&[(0., 0.), (1., 1.), (1., 0.), (0., 1.)])), Some((0, 2)));
    }

    #[test]
    fn loop_inside_one_cubic() {
        let c = CubicBez::new((0., 0.), (2., 1.), (-1., 1.), (1., 0.));
        assert!(cubic_loop(&c, false));
        let arch = CubicBez::new((0., 0.), (0., 1.), (1., 1.), (1., 0.));
        assert!(!cubic_loop(&arch, false));
    }
}
