//! A piece that is a circle, where the seam offset does not change the form.
//!
//! Glued at offset `s`, A's point at arc length `t` (counter-clockwise) meets B's point at
//! `t + s` (clockwise, [`super::seam::Glue`]). When B is a circle of perimeter `P` about `c`,
//! turning it about `c` by `−2πs/P` takes its point at `t` to its point at `t + s`, and the disc
//! onto itself: every offset glues the same two flat pieces with the same seam lengths, one
//! metric, hence one D-form, only B's flat coordinates turned. Likewise when A is the circle
//! (its point at `t − s` is its point at `t` turned by `−2πs/P`).
//!
//! The solver's forms were not so: the sheet path meshes each piece by Delaunay refinement,
//! which decides by exact in-circle tests, and a circle's samples are all but cocircular, so
//! each offset drew another mesh of the circle, and another equilibrium ([`super::sheet`], "the
//! mesh decides among nearby answers"). Over 16 offsets at 256 seam vertices (native) the
//! kidney with a circle spread by 2.8 % in volume, the five lobes by 3.6 %, the blob by 1.9 %,
//! the rounded star by 5.8 %, the L by 15 %, and the smooth heart took two forms, converged
//! (70,427 mm³, bent by 88°) at even sixteenths and creased (62,221 mm³, 133°) at odd ones. The
//! panel's sweep of volume and height against the offset (the 3D form as a design tool) drew
//! that noise as a design choice, and its "Largest" button chose among meshes. So a pair with a
//! non-convex piece and a circle is solved at offset 0, and the circle's `flat` is turned by the
//! offset ([`Turn::turn`]): every offset gives the same form to the last bit, and
//! `stats.offset_free` says so. A convex pair is left alone: its exact Alexandrov polyhedron
//! has no mesh to draw, and agrees across offsets within its sampling (1e-3, the triangle with a
//! circle of `tests/simulate_shapes.rs`).
//!
//! A circle here is an outline within [`TOLERANCE`] of its radius from a circle of the same
//! perimeter, traversed at the circle's speed (checked at [`SAMPLES`] points equally spaced in
//! arc length, each against the circle's point at the same arc length). A circle drawn with
//! Illustrator's or Inkscape's ellipse tool (four Bézier quarter arcs, 2.7e-4 of the radius off
//! the circle) is one; its turned `flat` lies within that of its outline (0.015 mm on a
//! circle of 55 mm), less than a seam chord's sag (0.004 mm at 256 seam vertices) times four.

use crate::arclen::ArcTable;
use super::Simulation;
use crate::contour::Contour;
use kurbo::Point;
use std::f64::consts::TAU;

/// Largest distance, relative to the radius, of a circle's points from the true circle's at the
/// same arc length.
pub const TOLERANCE: f64 = 5e-4;

/// Points of an outline checked against the circle, equally spaced in arc length.
pub const SAMPLES: usize = 256;

/// Relative accuracy of the arc lengths the check walks.
const ACCURACY: f64 = 1e-12;

/// The circle `c` is within [`TOLERANCE`]: its centre and perimeter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    pub centre: Point,
    pub perimeter: f64,
}

/// `c` as a circle, or `None` when it is none (see the module docs). Never panics: a degenerate
/// or non-finite outline is no circle.
pub fn circle(c: &Contour) -> Option<Circle> {
    let table = ArcTable::new(c, ACCURACY);
    let p = table.total();
    if !(p.is_finite() && p > 0.0) {
        return None;
    }
    let pts: Vec<Point> = (0..SAMPLES).map(|k| table.point_at(p * k as f64 / SAMPLES as f64)).collect();
    // Equally spaced in arc length on a circle, the samples' mean is its centre.
    let n = SAMPLES as f64;
    let centre = Point::new(pts.iter().map(|q| q.x).sum::<f64>() / n, pts.iter().map(|q| q.y).sum::<f64>() / n);
    let r = p / TAU;
    let sense = if c.signed_area() >= 0.0 { 1.0 } else { -1.0 };
    let start = (pts[0] - centre).atan2();
    let round = pts.iter().enumerate().all(|(k, q)| {
        let a = start + sense * TAU * k as f64 / n;
        let want = Point::new(centre.x + r * a.cos(), centre.y + r * a.sin());
        q.distance(want) <= TOLERANCE * r
    });
    (round && centre.x.is_finite() && centre.y.is_finite()).then_some(Circle { centre, perimeter: p })
}

/// A pair solved at offset 0 in place of `offset` because one piece is a circle: that piece's
/// flat coordinates are turned by `angle` about `centre`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Turn {
    /// 0 when A is the circle, 1 when B is.
    pub piece: u8,
    pub centre: Point,
    /// Radians, counter-clockwise.
    pub angle: f64,
}

impl Turn {
    /// The turn that carries the offset-0 form to the form at `offset` (arc length along B,
    /// reduced to `[0, B's perimeter)`) when piece `piece` (0 = A, 1 = B) is the circle `c`;
    /// `None` when `offset` is 0 (or not finite): the form is then solved as it is.
    pub fn new(piece: u8, c: Circle, offset: f64) -> Option<Turn> {
        (offset != 0.0 && offset.is_finite()).then(|| Turn { piece, centre: c.centre, angle: -TAU * offset / c.perimeter })
    }

    /// `q` turned about the centre.
    pub fn apply(&self, q: [f64; 2]) -> [f64; 2] {
        let (s, c) = self.angle.sin_cos();
        let (x, y) = (q[0] - self.centre.x, q[1] - self.centre.y);
        [self.centre.x + c * x - s * y, self.centre.y + s * x + c * y]
    }

    /// Turns the circle's flat corners of the offset-0 answer `sim` (each piece's frame
    /// coordinates). When A is the circle its seam then starts elsewhere on A, so `seam` is
    /// rotated to start at the seam vertex nearest `a_start`, A's first anchor, as it does on
    /// every other answer.
    pub fn turn(&self, sim: &mut Simulation, a_start: Point) {
        for (corners, &p) in sim.flat.iter_mut().zip(&sim.piece) {
            if p == self.piece {
                *corners = corners.map(|q| self.apply(q));
            }
        }
        if self.piece != 0 {
            return;
        }
        let mut on_a: Vec<Option<[f64; 2]>> = vec![None; sim.vertices.len()];
        for ((t, corners), &p) in sim.triangles.iter().zip(&sim.flat).zip(&sim.piece) {
            if p == 0 {
                for (&v, &q) in t.iter().zip(corners) {
                    on_a[v] = Some(q);
                }
            }
        }
        let d = |v: usize| on_a[v].map_or(f64::INFINITY, |q| (q[0] - a_start.x).hypot(q[1] - a_start.y));
        let first = (0..sim.seam.len()).fold(0, |best, k| if d(sim.seam[k]) < d(sim.seam[best]) { k } else { best });
        sim.seam.rotate_left(first);
    }
}

/// The piece of the pair that is a circle, B's first, with its circle.
pub fn round_piece(a: &Contour, b: &Contour) -> Option<(u8, Circle)> {
    circle(b).map(|c| (1, c)).or_else(|| circle(a).map(|c| (0, c)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::Knot;
    use kurbo::Affine;

    /// An ellipse with semi-axes `rx`, `ry` by `m` Bézier arcs (handles of the circle's
    /// 4/3·tan(θ/4) rule, stretched), first anchor at (rx, 0), counter-clockwise.
    fn ellipse(rx: f64, ry: f64, m: usize) -> Contour {
        let h = 4.0 / 3.0 * (TAU / (4.0 * m as f64)).tan();
        let knots = (0..m)
            .map(|k| {
                let t = TAU * k as f64 / m as f64;
                let (c, s) = (t.cos(), t.sin());
                let a = Point::new(rx * c, ry * s);
                Knot { anchor: a, left: Point::new(a.x + h * rx * s, a.y - h * ry * c), right: Point::new(a.x - h * rx * s, a.y + h * ry * c) }
            })
            .collect();
        Contour::new(knots, 1).unwrap()
    }

    /// Circles drawn as an ellipse tool draws them (four arcs, 2.7e-4 of the radius off), with
    /// eight arcs, moved, reversed and scaled to points, are circles with their own centre and
    /// perimeter; ellipses 0.2 % out of round, a circle with one handle pulled by 1 % of the
    /// radius and a square are not.
    #[test]
    fn circles_drawn_with_bezier_arcs_are_circles_and_near_circles_are_not() {
        let four = ellipse(50.0, 50.0, 4);
        for (what, c, centre) in [
            ("four arcs", four.clone(), Point::ZERO),
            ("eight arcs", ellipse(50.0, 50.0, 8), Point::ZERO),
            ("moved", four.transformed(Affine::translate((120.5, -33.25))), Point::new(120.5, -33.25)),
            ("reversed", four.reversed(), Point::ZERO),
            ("in points", four.transformed(Affine::scale(72.0 / 25.4)), Point::ZERO),
        ] {
            let got = circle(&c).unwrap_or_else(|| panic!("{what}: wanted a circle, got none"));
            let r = crate::arclen::perimeter(&c, 1e-12) / TAU;
            assert!(got.centre.distance(centre) <= 1e-9 * r, "{what}: wanted the centre {centre:?}, got {:?}", got.centre);
            assert!((got.perimeter / (TAU * r) - 1.0).abs() < 1e-12, "{what}: perimeter {}", got.perimeter);
        }
        let mut pulled = four.knots().to_vec();
        pulled[1].right = pulled[1].right + kurbo::Vec2::new(0.5, 0.0);
        let square = Contour::new([(0.0, 0.0), (5.0, 0.0), (5.0, 5.0), (0.0, 5.0)].map(|(x, y)| Knot::corner(Point::new(x, y))).to_vec(), 1).unwrap();
        for (what, c) in [("ellipse 1.002:1", ellipse(50.1, 50.0, 4)), ("ellipse 1:1.002", ellipse(50.0, 50.1, 8)), ("pulled handle", Contour::new(pulled, 1).unwrap()), ("square", square)] {
            assert_eq!(circle(&c), None, "{what}: wanted no circle");
        }
    }

    /// A point, a segment traced back and forth and coordinates past f64's range are no circle,
    /// and asking does not panic.
    #[test]
    fn degenerate_outlines_are_no_circle() {
        let dot = Contour::new(vec![Knot::corner(Point::new(1.0, 2.0)), Knot::corner(Point::new(1.0, 2.0))], 0).unwrap();
        let line = Contour::new(vec![Knot::corner(Point::new(0.0, 0.0)), Knot::corner(Point::new(10.0, 0.0))], 0).unwrap();
        let huge = Contour::new(vec![Knot::corner(Point::new(-1e308, 0.0)), Knot::corner(Point::new(1e308, 1.0)), Knot::corner(Point::new(0.0, 1e308))], 0).unwrap();
        for c in [dot, line, huge] {
            assert_eq!(circle(&c), None);
        }
    }

    /// The turn takes the circle's point at arc length `t` (clockwise from its first anchor, as
    /// the seam walks B) to its point at `t + s`: wanted the point the circle's own arc-length
    /// table gives, within the tolerance.
    #[test]
    fn the_turn_moves_a_circle_along_itself_by_the_offset() {
        let b = ellipse(40.0, 40.0, 4).reversed();
        let p = crate::arclen::perimeter(&b, 1e-12);
        let table = ArcTable::new(&b, 1e-12);
        let a = ellipse(60.0, 25.0, 8);
        let (piece, c) = round_piece(&a, &b).expect("B is a circle");
        assert_eq!(piece, 1);
        for s in [0.1 * p, 0.37 * p, 0.9 * p] {
            let turn = Turn::new(piece, c, s).expect("a turn");
            for t in [0.0, 0.2 * p, 0.55 * p] {
                let q = table.point_at(t);
                let got = turn.apply([q.x, q.y]);
                let want = table.point_at(t + s);
                let d = Point::new(got[0], got[1]).distance(want);
                assert!(d <= 2.0 * TOLERANCE * 40.0, "offset {s:.3}, t {t:.3}: wanted {want:?}, got {got:?} ({d:.2e} off)");
            }
        }
        assert_eq!(Turn::new(piece, c, 0.0), None, "offset 0 needs no turn");
        assert_eq!(round_piece(&a, &a), None, "no circle");
        assert_eq!(round_piece(&b, &a).map(|(p, _)| p), Some(0), "A the circle");
    }
}
