//! Checks that turn into warnings: holes that overlap or cross the edge, outlines whose teeth or
//! leaves run into each other. Connectors are named by their label numbers (connector k is
//! labelled k + 1), so the user can find them on the drawing.

use kurbo::{CubicBez, ParamCurve, ParamCurveExtrema, ParamCurveNearest, PathEl, Point, Rect, Shape, Vec2};

/// At most this many connectors are listed in one warning; the rest are counted.
const MAX_LISTED: usize = 30;

/// "3, 4, 9 and 12 more".
pub fn list(items: &[String]) -> String {
    let shown = items.iter().take(MAX_LISTED).cloned().collect::<Vec<_>>().join(", ");
    if items.len() > MAX_LISTED {
        format!("{shown} and {} more", items.len() - MAX_LISTED)
    } else {
        shown
    }
}

/// The cut outline as cubic segments with their tight bounding boxes, bucketed in a uniform
/// grid (for distance queries) and in horizontal bands (for the inside test), so a query looks
/// at the few segments near the point instead of all of them.
pub struct Edge {
    segs: Vec<CubicBez>,
    boxes: Vec<Rect>,
    origin: Point,
    cell: f64,
    cols: usize,
    rows: usize,
    /// `grid[row * cols + col]`: segments whose box overlaps the cell.
    grid: Vec<Vec<u32>>,
    /// `bands[row]`: segments whose box overlaps the row's y-range.
    bands: Vec<Vec<u32>>,
}

/// `a.max(b)` for ordered (non-NaN) inputs, without the NaN handling of `f64::max` (which WASM
/// turns into a library call).
#[inline]
fn mx(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

impl Edge {
    pub fn new(segs: Vec<CubicBez>) -> Self {
        let boxes: Vec<Rect> = segs.iter().map(ParamCurveExtrema::bounding_box).collect();
        let all = boxes.iter().fold(Rect::new(f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY), |u, b| u.union(*b));
        // About four cells per segment over the outline's box.
        let (w, h) = (mx(all.width(), 0.0), mx(all.height(), 0.0));
        let n = segs.len().max(1) as f64;
        let mut cell = ((w * h) / (4.0 * n)).sqrt();
        if !(cell > 0.0 && cell.is_finite()) {
            cell = mx(mx(w, h), 1.0) / n;
        }
        let cols = ((w / cell).floor() as usize + 1).min(4096);
        let rows = ((h / cell).floor() as usize + 1).min(4096);
        let cell = mx(cell, mx(w / cols as f64, h / rows as f64) * (1.0 + 1e-12));
        let mut grid = vec![Vec::new(); cols * rows];
        let mut bands = vec![Vec::new(); rows];
        let origin = Point::new(all.x0, all.y0);
        let clamp = |v: f64, n: usize| (mx(v, 0.0) as usize).min(n - 1);
        for (i, b) in boxes.iter().enumerate() {
            let (c0, c1) = (clamp((b.x0 - origin.x) / cell, cols), clamp((b.x1 - origin.x) / cell, cols));
            let (r0, r1) = (clamp((b.y0 - origin.y) / cell, rows), clamp((b.y1 - origin.y) / cell, rows));
            for r in r0..=r1 {
                bands[r].push(i as u32);
                for c in c0..=c1 {
                    grid[r * cols + c].push(i as u32);
                }
            }
        }
        Edge { segs, boxes, origin, cell, cols, rows, grid, bands }
    }

    fn cell_range(&self, lo: f64, hi: f64, o: f64, n: usize) -> Option<(usize, usize)> {
        let (a, b) = ((lo - o) / self.cell, (hi - o) / self.cell);
        if b < 0.0 || a >= n as f64 {
            return None;
        }
        Some(((mx(a, 0.0)) as usize, (b as usize).min(n - 1)))
    }

    /// Indices of the segments bucketed in the cells that the square `p ± limit` touches, in
    /// `out` (cleared first; a segment spanning several cells is listed once per cell).
    fn near(&self, p: Point, limit: f64, out: &mut Vec<usize>) {
        out.clear();
        let (Some(cols), Some(rows)) = (
            self.cell_range(p.x - limit, p.x + limit, self.origin.x, self.cols),
            self.cell_range(p.y - limit, p.y + limit, self.origin.y, self.rows),
        ) else {
            return;
        };
        for r in rows.0..=rows.1 {
            for c in cols.0..=cols.1 {
                out.extend(self.grid[r * self.cols + c].iter().map(|&i| i as usize));
            }
        }
    }

    /// Distance from `p` to the outline if it is below `limit`, else `None`. Only segments
    /// that might come within `limit` are measured exactly (kurbo's `nearest` minimises
    /// |B(t) − p|² through the roots of its degree-5 derivative).
    pub fn distance_below(&self, p: Point, limit: f64) -> Option<f64> {
        let mut ids = Vec::new();
        self.near(p, limit, &mut ids);
        crate::order::sort_dedup(&mut ids);
        let mut best: Option<f64> = None;
        for i in ids {
            if let Some(d) = self.segment_distance_below(i, p, limit) {
                if best.is_none_or(|b| d < b) {
                    best = Some(d);
                }
            }
        }
        best
    }

    /// Whether the outline comes closer than `limit` to `p`: the same answer as
    /// `distance_below(p, limit).is_some()`, stopping at the first segment that does.
    /// `scratch` is reused between calls to save an allocation per query.
    pub fn comes_within(&self, p: Point, limit: f64, scratch: &mut Vec<usize>) -> bool {
        self.near(p, limit, scratch);
        scratch.iter().any(|&i| self.segment_distance_below(i, p, limit).is_some())
    }

    /// Exact distance from `p` to segment `i` when it is below `limit`. The exact (and costly)
    /// nearest-point search runs only when two cheap lower bounds on the distance, the
    /// segment's tight axis-aligned box and [`hull_distance_sq`], are both below `limit`.
    fn segment_distance_below(&self, i: usize, p: Point, limit: f64) -> Option<f64> {
        let (c, b) = (&self.segs[i], &self.boxes[i]);
        let dx = mx(mx(b.x0 - p.x, p.x - b.x1), 0.0);
        let dy = mx(mx(b.y0 - p.y, p.y - b.y1), 0.0);
        if dx * dx + dy * dy >= limit * limit || hull_distance_sq(c, p) >= limit * limit {
            return None;
        }
        let d = c.nearest(p, 1e-12 * limit).distance_sq.sqrt();
        (d < limit).then_some(d)
    }

    /// Whether `p` is enclosed (non-zero winding). Only segments whose box reaches the
    /// horizontal ray to the left of `p` can contribute, so only those (from `p`'s band) are
    /// counted. kurbo's winding count cuts a cubic into pieces monotone in x and y, and a piece
    /// whose ray crossing lies left of `p` adds `[start.y > p.y] − [end.y > p.y]` (its crossing
    /// sign, half-open in y). For a segment lying wholly to the left of `p` that holds for every
    /// piece, and the sum telescopes to the same expression for the segment's own ends, so only
    /// segments whose box straddles `p.x` go to kurbo (the same count, without solving cubics).
    /// The same holds when the crossings are only known to lie left of `p` through the convex
    /// hull of the control points ([`hull_span_at`]), and a segment whose hull meets the line
    /// only right of `p` adds nothing; kurbo is left with the segments whose hull contains the
    /// ray's start, which for a hole centre away from the edge is rare.
    pub fn contains(&self, p: Point) -> bool {
        let Some((r, _)) = self.cell_range(p.y, p.y, self.origin.y, self.rows) else {
            return false;
        };
        if p.y > self.origin.y + self.cell * self.rows as f64 {
            return false;
        }
        let above = |y: f64| (y > p.y) as i32;
        let mut winding = 0;
        for &i in &self.bands[r] {
            let (c, b) = (&self.segs[i as usize], &self.boxes[i as usize]);
            if !(b.y0 <= p.y && p.y <= b.y1 && b.x0 <= p.x) {
                continue;
            }
            // Margin for the rounding of points evaluated on the curve (a few ulps of the box).
            let slack = 1e-12 * (b.x1.abs() + b.x0.abs() + (b.y1 - b.y0));
            let (lo, hi) = hull_span_at(c, p.y);
            if b.x1 + slack < p.x || hi + slack < p.x {
                // Every crossing of the line y = p.y lies left of p: the crossings' signs.
                winding += above(c.p0.y) - above(c.p3.y);
            } else if lo > p.x + slack {
                // Every crossing lies right of p: none is on the ray.
            } else {
                let els = [PathEl::MoveTo(c.p0), PathEl::CurveTo(c.p1, c.p2, c.p3)];
                winding += (&els[..]).winding(p);
            }
        }
        winding != 0
    }
}

/// The x-range `[lo, hi]` where the horizontal line at height `y` meets the convex hull of the
/// control points of `c` (which contains every crossing of the curve with that line): the
/// extreme crossings of the line with the six segments between pairs of control points.
/// `(∞, −∞)` when the line misses the hull.
fn hull_span_at(c: &CubicBez, y: f64) -> (f64, f64) {
    let pts = [c.p0, c.p1, c.p2, c.p3];
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for i in 0..4 {
        let a = pts[i];
        if a.y == y {
            lo = if a.x < lo { a.x } else { lo };
            hi = if a.x > hi { a.x } else { hi };
        }
        for b in &pts[i + 1..] {
            if (a.y < y && y < b.y) || (b.y < y && y < a.y) {
                let x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
                lo = if x < lo { x } else { lo };
                hi = if x > hi { x } else { hi };
            }
        }
    }
    (lo, hi)
}

/// A lower bound on the squared distance from `p` to the cubic `c`: the squared distance to
/// the box around its control points aligned with its chord (the curve lies in the convex hull
/// of its control points, which lies in that box). Shrunk by a relative 1e-12 of the
/// coordinates so that rounding never makes it exceed the true distance. Returns 0 for a
/// (nearly) zero chord.
fn hull_distance_sq(c: &CubicBez, p: Point) -> f64 {
    let chord = c.p3 - c.p0;
    let len = chord.hypot();
    let scale = c.p0.x.abs() + c.p0.y.abs() + p.x.abs() + p.y.abs() + len;
    if !(len > 1e-9 * scale) {
        return 0.0;
    }
    let u = chord / len;
    let (q1, q2, q3, qp) = (c.p1 - c.p0, c.p2 - c.p0, c.p3 - c.p0, p - c.p0);
    let along = |v: Vec2| v.dot(u);
    let across = |v: Vec2| u.cross(v);
    let gap = |x: f64, a: [f64; 4]| {
        let lo = a.iter().fold(f64::INFINITY, |m, &v| if v < m { v } else { m });
        let hi = a.iter().fold(f64::NEG_INFINITY, |m, &v| if v > m { v } else { m });
        mx(mx(lo - x, x - hi) - 1e-12 * scale, 0.0)
    };
    let ga = gap(along(qp), [0.0, along(q1), along(q2), along(q3)]);
    let gc = gap(across(qp), [0.0, across(q1), across(q2), across(q3)]);
    ga * ga + gc * gc
}

/// Warnings about holes on one piece: pairs that overlap, holes that cross the cut edge, holes on
/// the wrong side of it. `centers[k]` is connector k's hole, `radius` the drawn radius,
/// `inside` whether holes belong inside the outline.
pub fn holes(piece: &str, centers: &[Point], radius: f64, edge: &Edge, inside: bool) -> Vec<String> {
    let mut out = Vec::new();
    // Overlaps: sweep over the holes sorted by x; only pairs closer than 2r in x can overlap.
    let order = crate::order::argsort(&centers.iter().map(|c| c.x).collect::<Vec<_>>());
    let mut pairs = Vec::new();
    for (i, &a) in order.iter().enumerate() {
        for &b in &order[i + 1..] {
            if centers[b].x - centers[a].x >= 2.0 * radius {
                break;
            }
            if (centers[b] - centers[a]).hypot() < 2.0 * radius {
                let (lo, hi) = (a.min(b), a.max(b));
                pairs.push((lo, hi));
            }
        }
    }
    crate::order::sort_dedup_pairs(&mut pairs);
    if !pairs.is_empty() {
        let names: Vec<String> = pairs.iter().map(|(a, b)| format!("{} and {}", a + 1, b + 1)).collect();
        out.push(format!(
            "On the {piece}, the holes of connectors {} overlap: use fewer connectors or smaller holes.",
            list(&names)
        ));
    }
    let mut crossing = Vec::new();
    let mut wrong_side = Vec::new();
    let mut scratch = Vec::new();
    // A centre on the wrong side went through a part of the piece narrower than the inset: that
    // is the more useful thing to say, even when its hole also crosses the edge. Every other
    // crossing is with another stretch of the edge (the hole clears its own stretch, as the inset
    // is at least the radius), i.e. a narrow part or a bend tighter than the inset: a larger
    // inset only pushes the hole further across.
    for (k, &c) in centers.iter().enumerate() {
        if edge.contains(c) != inside {
            wrong_side.push((k + 1).to_string());
        } else if edge.comes_within(c, radius, &mut scratch) {
            crossing.push((k + 1).to_string());
        }
    }
    if !crossing.is_empty() {
        out.push(format!(
            "On the {piece}, the holes of connectors {} cross the edge: use smaller holes or a smaller inset, or move the connectors away from tight curves and narrow parts.",
            list(&crossing)
        ));
    }
    if !wrong_side.is_empty() {
        out.push(format!(
            "On the {piece}, the holes of connectors {} lie {} the piece (the piece is narrower than the inset there): reduce the inset.",
            list(&wrong_side),
            if inside { "outside" } else { "inside" }
        ));
    }
    out
}

/// Pairs of connectors whose parts of an outline cross each other. `segs[i]` belongs to
/// connector `tags[i]`. The outline is flattened into short chords (sampled uniformly in t,
/// `per_seg` chords per segment) and every pair of non-adjacent chords is tested for a proper
/// crossing (orientation test) by a sweep over x; the result lists each pair of connectors once.
pub fn collisions(segs: &[CubicBez], tags: &[usize], per_seg: usize) -> Vec<(usize, usize)> {
    let per_seg = per_seg.max(1);
    let mut chords: Vec<(Point, Point, usize)> = Vec::with_capacity(segs.len() * per_seg);
    for (c, &tag) in segs.iter().zip(tags) {
        let mut prev = c.p0;
        for j in 1..=per_seg {
            let p = c.eval(j as f64 / per_seg as f64);
            if p != prev {
                chords.push((prev, p, tag));
            }
            prev = p;
        }
    }
    let m = chords.len();
    let min_x = |i: usize| chords[i].0.x.min(chords[i].1.x);
    let max_x = |i: usize| chords[i].0.x.max(chords[i].1.x);
    let order = crate::order::argsort(&(0..m).map(min_x).collect::<Vec<_>>());
    let mut found = Vec::new();
    for (oi, &i) in order.iter().enumerate() {
        for &j in &order[oi + 1..] {
            if min_x(j) > max_x(i) {
                break;
            }
            let gap = i.abs_diff(j);
            if gap <= 1 || gap == m - 1 {
                continue; // neighbours share an end point
            }
            if crosses(chords[i].0, chords[i].1, chords[j].0, chords[j].1) {
                let (a, b) = (chords[i].2.min(chords[j].2), chords[i].2.max(chords[j].2));
                found.push((a, b));
            }
        }
    }
    crate::order::sort_dedup_pairs(&mut found);
    found
}

/// Proper crossing of segments pq and rs: each one's end points lie strictly on opposite sides
/// of the other's line (signs of the 2D cross products).
fn crosses(p: Point, q: Point, r: Point, s: Point) -> bool {
    let o = |a: Point, b: Point, c: Point| (b - a).cross(c - a);
    let (d1, d2) = (o(p, q, r), o(p, q, s));
    let (d3, d4) = (o(r, s, p), o(r, s, q));
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn figure_eight_chords_cross_once() {
        let l = |a: (f64, f64), b: (f64, f64)| CubicBez::new(a, a, b, b);
        let segs = [l((0.0, 0.0), (2.0, 2.0)), l((2.0, 2.0), (2.0, 0.0)), l((2.0, 0.0), (0.0, 2.0)), l((0.0, 2.0), (0.0, 0.0))];
        let got = collisions(&segs, &[0, 1, 2, 3], 1);
        assert_eq!(got, vec![(0, 2)], "wanted the two diagonals (0, 2), got {got:?}");
    }

    /// A wavy closed outline of `n` smooth cubics (Catmull–Rom handles) with concave stretches,
    /// so that holes near it see both bulging and hollow segments.
    fn wavy(n: usize) -> Vec<CubicBez> {
        let pt = |i: usize| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            let r = 10.0 + 2.5 * (5.0 * a).sin();
            Point::new(r * a.cos(), r * a.sin())
        };
        (0..n)
            .map(|i| {
                let (o, p, q, r) = (pt(i + n - 1), pt(i), pt(i + 1), pt(i + 2));
                CubicBez::new(p, p + (q - o) / 6.0, q - (r - p) / 6.0, q)
            })
            .collect()
    }

    /// Regression guard for the cheap bounds in front of the exact nearest-point search and for
    /// the shortcut in the winding count: on a grid of points around a wavy outline, the fast
    /// queries must agree with a brute force over every segment (kurbo's `nearest` and kurbo's
    /// winding of the whole path).
    #[test]
    fn fast_edge_queries_agree_with_brute_force() {
        let segs = wavy(40);
        let mut path = kurbo::BezPath::new();
        path.move_to(segs[0].p0);
        for c in &segs {
            path.curve_to(c.p1, c.p2, c.p3);
        }
        path.close_path();
        let edge = Edge::new(segs.clone());
        let mut scratch = Vec::new();
        let mut near_count = 0;
        for i in 0..=120 {
            for j in 0..=120 {
                let p = Point::new(-14.0 + 28.0 * i as f64 / 120.0, -14.0 + 28.0 * j as f64 / 120.0);
                for limit in [0.05, 0.4, 2.0] {
                    let exact = segs.iter().map(|c| c.nearest(p, 1e-12 * limit).distance_sq.sqrt()).fold(f64::INFINITY, f64::min);
                    let want = exact < limit;
                    near_count += want as usize;
                    let got = edge.comes_within(p, limit, &mut scratch);
                    assert_eq!(got, want, "point {p:?}, limit {limit}: exact distance {exact}, wanted within = {want}, got {got}");
                    let below = edge.distance_below(p, limit);
                    assert_eq!(below.is_some(), want, "distance_below at {p:?}, limit {limit}: exact {exact}, got {below:?}");
                }
                let (want, got) = (path.winding(p) != 0, edge.contains(p));
                assert_eq!(got, want, "point {p:?}: wanted inside = {want}, got {got}");
            }
        }
        assert!(near_count > 1000, "the grid should put many points near the edge, got {near_count}");
    }
}
