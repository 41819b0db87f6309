//! Building a new cut outline (teeth, leaves) along a walked piece: stretches of the original
//! edge, the same stretches offset along the normal, and straight or curved pieces in between.
//! Every segment carries the connector it belongs to, for the collision warnings.

use super::piece::Walked;
use super::spacing::Station;
use crate::arclen::control_polygon_len;
use crate::contour::{Contour, Knot};
use kurbo::{offset::offset_cubic, BezPath, CubicBez, ParamCurve, ParamCurveNearest, PathEl, Point, Vec2};
use lyon_geom::{point as lpt, CubicBezierSegment};

/// Accumulates cubic segments head to tail in the walking direction.
pub struct Builder<'a> {
    piece: &'a Walked,
    segs: Vec<CubicBez>,
    tags: Vec<usize>,
    /// Absolute tolerance for offset fitting and for snapping nearly coincident ends.
    tol: f64,
}

/// Are the control points of `c` within `tol` of its chord (then it is drawn as a line)?
fn is_straight(c: &CubicBez, tol: f64) -> bool {
    let chord = c.p3 - c.p0;
    let len = chord.hypot();
    if len == 0.0 {
        return (c.p1 - c.p0).hypot() <= tol && (c.p2 - c.p0).hypot() <= tol;
    }
    let off = |p: Point| chord.cross(p - c.p0).abs() / len;
    let along = |p: Point| chord.dot(p - c.p0) / len;
    off(c.p1) <= tol && off(c.p2) <= tol && (-tol..=len + tol).contains(&along(c.p1)) && (-tol..=len + tol).contains(&along(c.p2))
}

fn line(a: Point, b: Point) -> CubicBez {
    CubicBez::new(a, a.lerp(b, 1.0 / 3.0), a.lerp(b, 2.0 / 3.0), b)
}

fn to_lyon(c: &CubicBez) -> CubicBezierSegment<f64> {
    CubicBezierSegment {
        from: lpt(c.p0.x, c.p0.y),
        ctrl1: lpt(c.p1.x, c.p1.y),
        ctrl2: lpt(c.p2.x, c.p2.y),
        to: lpt(c.p3.x, c.p3.y),
    }
}

impl<'a> Builder<'a> {
    /// `scale` sets the tolerances (1e-6 of it): pass the pitch.
    pub fn new(piece: &'a Walked, scale: f64) -> Self {
        Builder { piece, segs: Vec::new(), tags: Vec::new(), tol: 1e-6 * scale }
    }

    fn end(&self) -> Option<Point> {
        self.segs.last().map(|c| c.p3)
    }

    /// Appends `c`, joining it to the previous end: snapped when within tolerance, else bridged
    /// by a straight line. Degenerate (point) segments are dropped.
    fn push(&mut self, mut c: CubicBez, tag: usize) {
        if let Some(e) = self.end() {
            let gap = (c.p0 - e).hypot();
            if gap <= self.tol {
                c.p0 = e;
            } else {
                self.segs.push(line(e, c.p0));
                self.tags.push(tag);
            }
        }
        if c.p0 == c.p1 && c.p1 == c.p2 && c.p2 == c.p3 {
            return;
        }
        self.segs.push(c);
        self.tags.push(tag);
    }

    /// A straight line from the current end (or `from`, at the start) to `to`.
    pub fn line_to(&mut self, from: Point, to: Point, tag: usize) {
        let start = self.end().unwrap_or(from);
        if (to - start).hypot() > 0.0 {
            self.push(line(start, to), tag);
        }
    }

    /// A cubic from the current end.
    pub fn cubic_to(&mut self, p1: Point, p2: Point, p3: Point, tag: usize) {
        let p0 = self.end().unwrap_or(p1);
        self.push(CubicBez::new(p0, p1, p2, p3), tag);
    }

    /// The original edge from station `a` to station `b` (an arc length `run` further on),
    /// moved `v` along the outward normal. The offset of each cubic is kurbo's `offset_cubic`
    /// (curve fitting of the parallel curve, Levien 2022, "Parallel curves of cubic Béziers");
    /// where the edge has a corner, the two offsets are trimmed at their crossing (the inner side
    /// of the corner) or joined by a straight bevel (the outer side).
    pub fn run(&mut self, a: &Station, b: &Station, run: f64, v: f64, tag: usize) {
        let table = &self.piece.table;
        let n = table.segment_count();
        let seg_len = |i: usize| table.segment_start(i + 1) - table.segment_start(i);
        let mut pieces = Vec::new();
        if a.seg == b.seg && b.t >= a.t && run <= seg_len(a.seg) + 1e-9 * table.total() {
            pieces.push(table.segment(a.seg).subsegment(a.t..b.t));
        } else {
            pieces.push(table.segment(a.seg).subsegment(a.t..1.0));
            let mut i = (a.seg + 1) % n;
            while i != b.seg {
                pieces.push(*table.segment(i));
                i = (i + 1) % n;
            }
            pieces.push(table.segment(b.seg).subsegment(0.0..b.t));
        }
        // Outward offset v is kurbo's offset d along the left normal (tangent turned +90°),
        // which points inward on a counter-clockwise walk: d = −turn·v.
        let d = -self.piece.turn * v;
        let mut buf = BezPath::new();
        for q in pieces {
            if q.p0 == q.p1 && q.p1 == q.p2 && q.p2 == q.p3 {
                continue;
            }
            let offset: Vec<CubicBez> = if v == 0.0 {
                vec![q]
            } else if is_straight(&q, self.tol) {
                let chord = q.p3 - q.p0;
                if chord.hypot() == 0.0 {
                    continue;
                }
                let nrm = chord.normalize().turn_90() * d;
                vec![line(q.p0 + nrm, q.p3 + nrm)]
            } else {
                offset_cubic(q, d, self.tol, &mut buf);
                cubics(&buf)
            };
            self.join(offset, v, tag);
        }
    }

    /// Appends one offset piece. Where it does not start at the previous end (a corner of the
    /// edge), the two tangent lines at the gap meet at the mitre point `M`. On the outer side of
    /// the corner (`M` ahead of the previous end and behind the new start) the gap is closed
    /// through `M`, a sharp corner like the edge's own, unless the mitre is longer than four
    /// times the offset (then a straight bevel). On the inner side the two offsets cross: both
    /// are cut at their intersection (lyon_geom's cubic–cubic intersection), or at `M` when the
    /// crossing falls exactly on their ends.
    fn join(&mut self, mut piece: Vec<CubicBez>, v: f64, tag: usize) {
        if piece.is_empty() {
            return;
        }
        if let Some(last) = self.segs.last().copied() {
            let (e, s) = (last.p3, piece[0].p0);
            if (s - e).hypot() > self.tol {
                let t1 = end_tangent(&last);
                let t2 = start_tangent(&piece[0]);
                let mitre = meet(e, t1, s, t2);
                let outer = mitre.is_some_and(|m| (m - e).dot(t1) > 0.0 && (s - m).dot(t2) > 0.0);
                if outer {
                    let m = mitre.expect("outer implies a mitre");
                    if (m - e).hypot() <= 4.0 * v.abs() {
                        self.push(line(e, m), tag);
                    }
                } else {
                    let hits = to_lyon(&last).cubic_intersections_t(&to_lyon(&piece[0]));
                    let cut_at = hits
                        .iter()
                        .max_by(|x, y| x.0.total_cmp(&y.0))
                        .map(|&(a, b)| (a, b, last.eval(a)))
                        .or_else(|| {
                            mitre.filter(|m| (*m - e).hypot() <= 4.0 * v.abs() && (*m - s).hypot() <= 4.0 * v.abs()).map(|m| {
                                (last.nearest(m, 1e-12).t, piece[0].nearest(m, 1e-12).t, m)
                            })
                        });
                    if let Some((a, b, m)) = cut_at {
                        let mut cut = last.subsegment(0.0..a);
                        cut.p3 = m;
                        self.segs.pop();
                        let last_tag = self.tags.pop().unwrap_or(tag);
                        if control_polygon_len(&cut) > self.tol {
                            self.segs.push(cut);
                            self.tags.push(last_tag);
                        }
                        piece[0] = piece[0].subsegment(b..1.0);
                        piece[0].p0 = m;
                    }
                }
            }
        }
        for c in piece {
            self.push(c, tag);
        }
    }

    /// Closes the outline and returns it (walking direction) with its segments and their tags.
    pub fn finish(mut self) -> (Contour, Vec<CubicBez>, Vec<usize>) {
        if let (Some(first), Some(e)) = (self.segs.first().map(|c| c.p0), self.end()) {
            let gap = (first - e).hypot();
            if gap <= self.tol {
                self.segs.last_mut().expect("non-empty").p3 = first;
            } else {
                let tag = *self.tags.last().expect("non-empty");
                self.segs.push(line(e, first));
                self.tags.push(tag);
            }
        }
        let n = self.segs.len();
        let knots = (0..n)
            .map(|i| {
                let c = &self.segs[i];
                Knot { anchor: c.p0, right: c.p1, left: self.segs[(i + n - 1) % n].p2 }
            })
            .collect();
        let contour = Contour::new(knots, self.piece.index).unwrap_or_else(|_| self.piece.contour.clone());
        (contour, self.segs, self.tags)
    }
}

/// Direction in which a cubic leaves its start (first non-coincident control point).
fn start_tangent(c: &CubicBez) -> Vec2 {
    [c.p1, c.p2, c.p3].iter().map(|&p| p - c.p0).find(|d| d.hypot() > 0.0).map(|d| d.normalize()).unwrap_or(Vec2::ZERO)
}

/// Direction in which a cubic arrives at its end.
fn end_tangent(c: &CubicBez) -> Vec2 {
    [c.p2, c.p1, c.p0].iter().map(|&p| c.p3 - p).find(|d| d.hypot() > 0.0).map(|d| d.normalize()).unwrap_or(Vec2::ZERO)
}

/// Where the lines `a + x·u` and `b + y·w` meet (Cramer's rule), if they are not parallel.
fn meet(a: Point, u: Vec2, b: Point, w: Vec2) -> Option<Point> {
    let den = u.cross(w);
    if den.abs() < 1e-12 {
        return None;
    }
    let x = (b - a).cross(w) / den;
    Some(a + u * x)
}

/// The cubic segments of a single-subpath BezPath (lines and quadratics raised to cubics).
fn cubics(path: &BezPath) -> Vec<CubicBez> {
    let mut out = Vec::new();
    let mut cur = Point::ZERO;
    for el in path.elements() {
        match *el {
            PathEl::MoveTo(p) => cur = p,
            PathEl::LineTo(p) => {
                out.push(line(cur, p));
                cur = p;
            }
            PathEl::QuadTo(p1, p2) => {
                out.push(kurbo::QuadBez::new(cur, p1, p2).raise());
                cur = p2;
            }
            PathEl::CurveTo(p1, p2, p3) => {
                out.push(CubicBez::new(cur, p1, p2, p3));
                cur = p3;
            }
            PathEl::ClosePath => {}
        }
    }
    out
}
