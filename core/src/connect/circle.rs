//! Small shapes the connectors are drawn with: circles (holes) and the start mark.

use crate::libm_ext::LibmExt;
use crate::contour::{Contour, Knot};
use kurbo::{Point, Vec2};

/// Handle length of the four-cubic circle, as a fraction of the radius:
/// `k = 4/3·tan(π/8)`, which puts each quarter's midpoint exactly on the circle
/// (radial error at most 2.7e-4·r elsewhere; Riškus, "Approximation of a cubic Bézier curve by
/// circular arcs and vice versa", 2006).
pub const CIRCLE_K: f64 = 0.552_284_749_830_793_4;

/// A circle of radius `r` around `c` as four cubic segments, starting at angle 0 and running
/// counter-clockwise (y-up) when `ccw`, clockwise otherwise.
pub fn circle(c: Point, r: f64, ccw: bool) -> Contour {
    let dirs: [(f64, f64); 4] = if ccw {
        [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)]
    } else {
        [(1.0, 0.0), (0.0, -1.0), (-1.0, 0.0), (0.0, 1.0)]
    };
    let knots = dirs
        .iter()
        .map(|&(x, y)| {
            let radial = Vec2::new(x, y);
            // Direction of travel at this anchor: the radial direction turned ±90°.
            let along = if ccw { Vec2::new(-y, x) } else { Vec2::new(y, -x) };
            let anchor = c + radial * r;
            Knot { anchor, left: anchor - along * (CIRCLE_K * r), right: anchor + along * (CIRCLE_K * r) }
        })
        .collect();
    // Not `expect`: that would format the error with `Debug`, whose code (the crate's only use of
    // `Error`'s derived `Debug`) costs ~3 KB of the .wasm for a message nobody sees there.
    Contour::new(knots, 0).unwrap_or_else(|_| panic!("four finite knots"))
}

/// The start mark: an isosceles triangle whose apex points at the connector, `apex` being the
/// tip, `toward` the unit direction from the base to the tip, `size` its height (base width
/// `size`).
pub fn triangle(apex: Point, toward: Vec2, size: f64) -> Contour {
    let base = apex - toward * size;
    let side = Vec2::new(-toward.y, toward.x) * (0.5 * size);
    // Not `expect`: see `circle`.
    Contour::new(vec![Knot::corner(apex), Knot::corner(base + side), Knot::corner(base - side)], 0)
        .unwrap_or_else(|_| panic!("three finite knots"))
}

/// Text angle in degrees for a label running along the unit tangent `t`, turned by 180° when
/// needed so the text never reads upside down: the result lies in (−90°, 90°].
pub fn readable_angle(t: Vec2) -> f64 {
    let mut a = t.y.atan2_m(t.x).to_degrees();
    if a > 90.0 {
        a -= 180.0;
    } else if a <= -90.0 {
        a += 180.0;
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;
    use kurbo::ParamCurve;

    #[test]
    fn circle_midpoints_lie_on_the_circle() {
        let c = circle(Point::new(3.0, -2.0), 2.0, false);
        assert!(c.signed_area() < 0.0, "clockwise circle has area {}", c.signed_area());
        for seg in c.segments() {
            let r = (seg.eval(0.5) - Point::new(3.0, -2.0)).hypot();
            assert!((r - 2.0).abs() < 1e-12, "wanted radius 2, got {r}");
        }
    }

    #[test]
    fn label_angles_are_never_upside_down() {
        for (t, want) in [((1.0, 0.0), 0.0), ((-1.0, 0.0), 0.0), ((0.0, -1.0), 90.0), ((-1.0, -1.0), 45.0)] {
            let got = readable_angle(Vec2::new(t.0, t.1).normalize());
            assert!((got - want).abs() < 1e-12, "tangent {t:?}: wanted {want}, got {got}");
        }
    }
}
