//! Perimeter, area, orientation, bounds and centroid of a closed outline.

use crate::arclen::ArcTable;
use crate::contour::Contour;
use kurbo::{CubicBez, ParamCurve, ParamCurveDeriv, Point, Shape};

/// Which way the outline runs, in a y-up coordinate system (Illustrator's).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Orientation {
    Ccw,
    Cw,
}

/// Everything `measure` reports.
#[derive(Debug, Clone, PartialEq)]
pub struct Measurement {
    pub perimeter: f64,
    /// Unsigned enclosed area.
    pub area: f64,
    pub orientation: Orientation,
    /// Tight bounds of the curve (not of the handles).
    pub bounds: (Point, Point),
    /// Centroid of the enclosed region.
    pub centroid: Point,
}

/// Measures a closed outline; `accuracy` is the relative accuracy of the perimeter
/// (see [`crate::arclen::DEFAULT_ACCURACY`]).
pub fn measure(contour: &Contour, accuracy: f64) -> Measurement {
    let perimeter = ArcTable::new(contour, accuracy).total();
    let signed = contour.signed_area();
    let rect = contour.to_bezpath().bounding_box();
    Measurement {
        perimeter,
        area: signed.abs(),
        orientation: if signed >= 0.0 { Orientation::Ccw } else { Orientation::Cw },
        bounds: (Point::new(rect.x0, rect.y0), Point::new(rect.x1, rect.y1)),
        centroid: centroid(contour, signed),
    }
}

/// 5-point Gauss–Legendre nodes and weights on [0, 1]; exact for polynomials of degree ≤ 9.
const GL5: [(f64, f64); 5] = [
    (0.046_910_077_030_668, 0.118_463_442_528_094_5),
    (0.230_765_344_947_158_5, 0.239_314_335_249_683_2),
    (0.5, 0.284_444_444_444_444_4),
    (0.769_234_655_052_841_5, 0.239_314_335_249_683_2),
    (0.953_089_922_969_332, 0.118_463_442_528_094_5),
];

/// Region centroid by Green's theorem: `Cx = (1/A)∮ x²/2 dy`, `Cy = −(1/A)∮ y²/2 dx`.
/// On a cubic the integrands are polynomials of degree 8 in t, so 5-point Gauss–Legendre is exact.
/// The outline is shifted to its first anchor first, so shapes far from the origin keep their digits.
/// A region of zero area has no centroid; the midpoint of the control bounds stands in.
fn centroid(contour: &Contour, signed_area: f64) -> Point {
    let o = contour.knots()[0].anchor.to_vec2();
    let (mut mx, mut my) = (0.0, 0.0);
    for c in contour.segments() {
        let c = CubicBez::new(c.p0 - o, c.p1 - o, c.p2 - o, c.p3 - o);
        let d = c.deriv();
        for (t, w) in GL5 {
            let p = c.eval(t);
            let v = d.eval(t);
            mx += w * 0.5 * p.x * p.x * v.y;
            my -= w * 0.5 * p.y * p.y * v.x;
        }
    }
    if signed_area.abs() > 0.0 && (mx / signed_area).is_finite() && (my / signed_area).is_finite() {
        Point::new(mx / signed_area, my / signed_area) + o
    } else {
        let (a, b) = contour.control_bounds();
        a.midpoint(b)
    }
}
