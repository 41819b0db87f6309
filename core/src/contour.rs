//! A closed outline as a list of knots, mirroring Illustrator's `PathPoint`
//! (anchor, `leftDirection` = incoming handle, `rightDirection` = outgoing handle).
//! Segment i is the cubic `anchor[i] → right[i] → left[i+1] → anchor[i+1]`, wrapping at the end.

use crate::error::{Error, Result};
use kurbo::{Affine, BezPath, CubicBez, ParamCurveArea, Point};

/// One anchor with its two handles. A handle equal to the anchor is a corner.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Knot {
    pub anchor: Point,
    /// Incoming handle (Illustrator `leftDirection`).
    pub left: Point,
    /// Outgoing handle (Illustrator `rightDirection`).
    pub right: Point,
}

impl Knot {
    /// A corner knot: both handles at the anchor.
    pub fn corner(anchor: Point) -> Self {
        Knot { anchor, left: anchor, right: anchor }
    }
}

/// A closed outline with at least two knots and finite coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct Contour {
    knots: Vec<Knot>,
}

impl Contour {
    /// Checks what every operation needs: at least two knots, every coordinate finite.
    /// `piece` is the index used in error messages. (Self-intersection is checked separately:
    /// see [`crate::validate`].)
    pub fn new(knots: Vec<Knot>, piece: usize) -> Result<Self> {
        if knots.len() < 2 {
            return Err(Error::TooFewPoints { piece, count: knots.len() });
        }
        for (i, k) in knots.iter().enumerate() {
            for (field, p) in [("anchor", k.anchor), ("left", k.left), ("right", k.right)] {
                if !(p.x.is_finite() && p.y.is_finite()) {
                    return Err(Error::NonFinite { piece, point: i, field });
                }
            }
        }
        Ok(Contour { knots })
    }

    pub fn knots(&self) -> &[Knot] {
        &self.knots
    }

    /// Number of segments (= number of knots, since the outline is closed).
    pub fn len(&self) -> usize {
        self.knots.len()
    }

    pub fn is_empty(&self) -> bool {
        self.knots.is_empty()
    }

    /// Segment i: `anchor[i] → right[i] → left[i+1] → anchor[i+1]`.
    pub fn segment(&self, i: usize) -> CubicBez {
        let a = &self.knots[i % self.knots.len()];
        let b = &self.knots[(i + 1) % self.knots.len()];
        CubicBez::new(a.anchor, a.right, b.left, b.anchor)
    }

    pub fn segments(&self) -> impl Iterator<Item = CubicBez> + '_ {
        (0..self.knots.len()).map(move |i| self.segment(i))
    }

    /// Signed area, positive when the outline runs counter-clockwise in a y-up system
    /// (Green's theorem summed over the cubic segments). Computed relative to the first anchor
    /// (the sum is translation-invariant for a closed outline), so a small shape far from the
    /// origin does not lose its digits to products of large coordinates.
    pub fn signed_area(&self) -> f64 {
        let o = self.knots.first().map_or(kurbo::Vec2::ZERO, |k| k.anchor.to_vec2());
        self.segments().map(|c| CubicBez::new(c.p0 - o, c.p1 - o, c.p2 - o, c.p3 - o).signed_area()).sum()
    }

    /// Applies an affine map to every anchor and handle (Bézier curves are affine-invariant,
    /// so this maps the curve exactly).
    pub fn transformed(&self, m: Affine) -> Contour {
        Contour {
            knots: self
                .knots
                .iter()
                .map(|k| Knot { anchor: m * k.anchor, left: m * k.left, right: m * k.right })
                .collect(),
        }
    }

    /// The same outline walked the other way, still starting at knot 0
    /// (knot order 0, n-1, …, 1 with the handles swapped).
    pub fn reversed(&self) -> Contour {
        let n = self.knots.len();
        let knots = (0..n)
            .map(|i| {
                let k = self.knots[(n - i) % n];
                Knot { anchor: k.anchor, left: k.right, right: k.left }
            })
            .collect();
        Contour { knots }
    }

    /// The same outline drawn from knot `k` (taken modulo the knot count): its knots turned to
    /// begin there, every segment unchanged.
    pub fn started_at(&self, k: usize) -> Contour {
        let mut knots = self.knots.clone();
        let n = knots.len().max(1);
        knots.rotate_left(k % n);
        Contour { knots }
    }

    /// Control-point bounding box `(min, max)`; contains the curve.
    pub fn control_bounds(&self) -> (Point, Point) {
        let mut min = Point::new(f64::INFINITY, f64::INFINITY);
        let mut max = Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
        for k in &self.knots {
            for p in [k.anchor, k.left, k.right] {
                min.x = min.x.min(p.x);
                min.y = min.y.min(p.y);
                max.x = max.x.max(p.x);
                max.y = max.y.max(p.y);
            }
        }
        (min, max)
    }

    /// As a kurbo path (closed), for kurbo's shape algorithms.
    pub fn to_bezpath(&self) -> BezPath {
        let mut p = BezPath::new();
        p.move_to(self.knots[0].anchor);
        for c in self.segments() {
            p.curve_to(c.p1, c.p2, c.p3);
        }
        p.close_path();
        p
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Contour {
        let pts = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        Contour::new(pts.iter().map(|&p| Knot::corner(p.into())).collect(), 0).unwrap()
    }

    #[test]
    fn ccw_square_has_positive_area() {
        let a = square().signed_area();
        assert!((a - 1.0).abs() < 1e-15, "wanted 1, got {a}");
    }

    #[test]
    fn reversed_flips_area_and_keeps_first_anchor() {
        let s = square();
        let r = s.reversed();
        assert_eq!(r.knots()[0].anchor, s.knots()[0].anchor);
        assert_eq!(r.knots()[1].anchor, s.knots()[3].anchor);
        assert!((r.signed_area() + 1.0).abs() < 1e-15);
    }

    #[test]
    fn started_at_keeps_every_segment_and_begins_at_the_knot() {
        let s = square();
        for k in 0..6 {
            let t = s.started_at(k);
            assert_eq!(t.knots()[0], s.knots()[k % 4], "from knot {k}");
            for i in 0..4 {
                assert_eq!(t.segment(i), s.segment(i + k), "from knot {k}: segment {i}");
            }
        }
    }

    #[test]
    fn rejects_nan_and_too_few_points() {
        let e = Contour::new(vec![Knot::corner(Point::new(0.0, 0.0))], 1).unwrap_err();
        assert_eq!(e, Error::TooFewPoints { piece: 1, count: 1 });
        let mut k = vec![Knot::corner(Point::new(0.0, 0.0)), Knot::corner(Point::new(1.0, 0.0))];
        k[1].left.y = f64::NAN;
        let e = Contour::new(k, 0).unwrap_err();
        assert_eq!(e, Error::NonFinite { piece: 0, point: 1, field: "left" });
    }
}
