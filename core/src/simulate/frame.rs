//! Both pieces in frames of their own: each moved so that its first anchor is the origin and
//! turned so that a direction of its own lies along the x axis ([`turn_of`]),
//! both scaled by one unit so that the first piece, so turned, measures [`SIZE`] across, and
//! every control point snapped to a binary grid of about 2⁻³⁰ of its piece's size.
//!
//! Why: the sheet path's answer is a deterministic function of the input's bits, and it turns
//! on them. Its meshes come from Delaunay refinement, whose exact in-circle tests decide on a
//! circle's all but cocircular samples by their last bits, and another mesh ends in another
//! equilibrium of the thin sheet (see [`super::sheet`]). So the same drawing moved on the
//! artboard gave another form: moved by (250.1, 400.9) mm the L with a circle had a volume of
//! 73,438 mm³ against 77,548, the heart drawn with corners 118,459 against 116,432 (256 seam
//! vertices, native). And the same drawing in other units: over seven scales (millimetres,
//! points, inches, CSS pixels, ×0.01, ×100, ×0.3) the kidney with a circle spread by 1.7 % in
//! volume, the five lobes by 2.0 %, the heart drawn with corners by 6.2 % and the L by 6.6 %,
//! so a drawing read in points (the panel) and in millimetres (an Inkscape document) gave forms
//! a few percent apart. And the same drawing turned on the artboard (both pieces by 0.3, 1 and
//! 2.5 radians; stop 45): the L with a circle spread by 13 % (76,473–86,538 mm³), the heart
//! drawn with corners with its copy at 3/16 by 11 %, the rounded star with its copy at 3/16 by
//! 37 %, the five lobes with a circle by 1.9 %; each piece is a flat sheet, and how it lies on
//! the artboard is no part of the form.
//!
//! In the frames the drawing and its moved, turned or scaled copy differ only by the rounding of
//! `R(−φ)(p − origin) / unit`, a few units in the last place of [`SIZE`], and the snap takes both to
//! the same grid point unless one lies within that of a grid point's midway line: the odds are
//! ~1e-6 per coordinate. The offset along the seam is reduced by the input's perimeter and
//! scaled and snapped the same way ([`offset`]). The snap moves a point by at most half a
//! cell, ~5e-10 of the piece's size (5e-8 mm on a 100 mm piece), far below the 1e-6 perimeter
//! rule and below anything a cutter resolves.
//!
//! The grid is a power of two, so the snap is exact arithmetic, chosen by `ceil(log₂ size + ½)`:
//! its steps fall at sizes `2ᵏ/√2`; the first piece's size in its frame is [`SIZE`], far from
//! any step, and a second piece of equal perimeter is seldom within rounding of one. What the
//! host reads back goes back to the input's units and place ([`Frame::to_input`],
//! [`Frame::length_out`]).

use crate::libm_ext::LibmExt;
use crate::contour::{Contour, Knot};
use kurbo::Point;

/// The grid cell as a power of two below the piece's size.
pub const GRID_BITS: i32 = 30;

/// The first piece's size (the larger side of its control points' bounding box) in its frame.
/// Any positive number would do; this one is a power of two and the size of a typical drawing
/// in millimetres.
///
/// Another value is another draw of every sheet path's meshes, as another unit was before the
/// frames were scaled, so it is also how to measure what a claim about the sheet path owes to
/// one draw: over eight values (90–150) the five lobes with a circle spread by 0.1–4.2 % in
/// volume between 128, 192 and 256 seam vertices, the Pebble with a circle by at most 0.3 %
/// (see the tests of requirement 3 in `core/tests/simulate_nonconvex.rs`).
pub const SIZE: f64 = 128.0;

/// Farthest the snap moves a point, relative to the piece's size: half a cell's diagonal, the
/// cell being at most `2^(1.5 − GRID_BITS)` of the size (`ceil(log₂ size + ½)` exceeds
/// `log₂ size` by at most 1.5), so `2^(1 − GRID_BITS)`, 1.9e-9.
pub const SNAP_MOVE: f64 = 2.0 / (1u64 << GRID_BITS) as f64;

/// Where a piece's frame sits in the input's coordinates: its origin, the input length of one
/// frame unit, and the frame's grid cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    pub origin: Point,
    pub unit: f64,
    pub cell: f64,
    /// The frame's turn against the input: `(cos, sin)` of the angle by which a frame point is
    /// turned back into the input ([`Frame::to_input`], [`turn_of`]).
    pub turn: (f64, f64),
}

impl Frame {
    /// The frame of an outline kept as it is.
    const INPUT: Frame = Frame { origin: Point::ZERO, unit: 1.0, cell: 0.0, turn: (1.0, 0.0) };

    /// A point of the piece's frame in the input's coordinates.
    pub fn to_input(&self, p: [f64; 2]) -> [f64; 2] {
        let (c, s) = self.turn;
        let (x, y) = (c * p[0] - s * p[1], s * p[0] + c * p[1]);
        [x * self.unit + self.origin.x, y * self.unit + self.origin.y]
    }

    /// A length of the frame (an arc length, a distance) in the input's units.
    pub fn length_out(&self, l: f64) -> f64 {
        l * self.unit
    }

    /// A length of the input (the offset along the seam) in the frame, snapped to the frame's
    /// grid like the control points, so that a scaled drawing's offset gets the same bits.
    pub fn length_in(&self, l: f64) -> f64 {
        self.snap(l / self.unit)
    }

    /// A length of the frame on its cell, as [`Frame::length_in`] leaves every length: an offset
    /// reduced by a period in the frame ([`super::round`]) then has the bits of the same offset
    /// given within the period.
    pub fn snap(&self, f: f64) -> f64 {
        if self.cell > 0.0 && (f / self.cell).is_finite() {
            (f / self.cell).round() * self.cell
        } else {
            f
        }
    }
}

/// Relative accuracy of the perimeter an offset is reduced by ([`offset`]).
pub const PERIOD_ACCURACY: f64 = 1e-13;

/// `offset` along `b` (the second piece as the input has it) in `b`'s frame `f`: reduced
/// modulo `b`'s perimeter, then [`Frame::length_in`].
///
/// Why here: the offset is periodic, and an offset of many perimeters is the gluing of its
/// remainder. Reduced in the frame (as [`super::seam::Glue`] also does), the period would be
/// the snapped outline's perimeter, which differs from the input's in about the tenth digit,
/// and `k` perimeters on carry `k` times that into the remainder: the rounded rectangle with an
/// octagon a million perimeters on had a volume 1.4e-6 from its own at the remainder. Reduced
/// by the input's perimeter (to [`PERIOD_ACCURACY`]) the remainder is off by `k · 1e-13` of it.
pub fn offset(offset: f64, b: &Contour, f: &Frame) -> f64 {
    let period = crate::arclen::ArcTable::new(b, PERIOD_ACCURACY).total();
    let reduced = if period.is_finite() && period > 0.0 && offset.is_finite() { offset.rem_euclid(period) } else { offset };
    f.length_in(reduced)
}

/// The larger side of `c`'s control points' bounding box, by halves so that ±1e308
/// coordinates do not overflow.
fn size(c: &Contour) -> f64 {
    let (lo, hi) = c.control_bounds();
    2.0 * (hi.x / 2.0 - lo.x / 2.0).max(hi.y / 2.0 - lo.y / 2.0)
}

/// `c` moved so that its first anchor is the origin and turned back by `turn` (`(cos φ, sin φ)`,
/// [`turn_of`]), unscaled, with that anchor; `None` when that is no valid contour.
fn moved(c: &Contour, turn: (f64, f64), piece: usize) -> Option<(Contour, Point)> {
    let origin = c.knots().first()?.anchor;
    let (tc, ts) = turn;
    let at = |p: Point| {
        let (x, y) = (p.x - origin.x, p.y - origin.y);
        Point::new(tc * x + ts * y, tc * y - ts * x)
    };
    let knots = c.knots().iter().map(|k| Knot { anchor: at(k.anchor), left: at(k.left), right: at(k.right) }).collect();
    Some((Contour::new(knots, piece).ok()?, origin))
}

/// A piece `moved` from its first anchor `origin` and turned back by `turn` ([`moved`]), scaled
/// by `1 / unit` and snapped, with its frame; `None` when that is no valid contour or has no
/// size.
fn local(moved: &Contour, origin: Point, turn: (f64, f64), unit: f64, piece: usize) -> Option<(Contour, Frame)> {
    // `R(−φ)(p − origin) / unit` by hand rather than `Contour::transformed`, whose affine map
    // would round `p · (1/unit) + (−origin · (1/unit))` instead: here one subtraction, one turn
    // and one division, the rounding the module docs count.
    let scale = |p: Point| Point::new(p.x / unit, p.y / unit);
    let scaled = Contour::new(moved.knots().iter().map(|k| Knot { anchor: scale(k.anchor), left: scale(k.left), right: scale(k.right) }).collect(), piece).ok()?;
    let size = size(&scaled);
    if !(size.is_finite() && size > 0.0) {
        return None;
    }
    let cell = 2f64.powi((size.log2_m() + 0.5).ceil() as i32 - GRID_BITS);
    if !cell.is_normal() {
        return None;
    }
    let snap = |p: Point| Point::new((p.x / cell).round() * cell, (p.y / cell).round() * cell);
    let knots = scaled.knots().iter().map(|k| Knot { anchor: snap(k.anchor), left: snap(k.left), right: snap(k.right) }).collect();
    Some((Contour::new(knots, piece).ok()?, Frame { origin, unit, cell, turn }))
}

/// Anisotropy of a piece's control points (the difference of their covariance's eigenvalues
/// over its trace) above which their major axis gives the piece's direction ([`turn_of`]).
pub const ANISOTROPY: f64 = 1e-3;

/// How far `c` is turned: `(cos φ, sin φ)` of a direction `φ` that turns with the outline, so
/// that its frame, turning it back by `φ`, holds the outline drawn turned with the same
/// coordinates (to the snap):
///
/// - the major axis of its control points (anchors and handles), pointing to the side of their
///   mean from the first anchor (or, when the mean lies on the axis through the first anchor,
///   with the mean on its left), when they are anisotropic beyond [`ANISOTROPY`] (an ellipse,
///   a rectangle, most drawings);
/// - else the first of its longest anchor-to-anchor chords (a square, a regular polygon).
///
/// Both keep a piece drawn square to the axes square to them: the convex path solves a
/// rectangle with rounded corners at 1,520 steps square to the axes and 2,607 turned by 11°
/// (the direction to its control points' mean, tried first). `(1, 0)` when neither is defined.
pub fn turn_of(c: &Contour) -> (f64, f64) {
    let Some(first) = c.knots().first() else { return (1.0, 0.0) };
    let o = first.anchor;
    let pts: Vec<Point> = c.knots().iter().flat_map(|k| [k.anchor, k.left, k.right]).map(|p| Point::new(p.x - o.x, p.y - o.y)).collect();
    let n = pts.len() as f64;
    let (mx, my) = (pts.iter().map(|p| p.x / n).sum::<f64>(), pts.iter().map(|p| p.y / n).sum::<f64>());
    let (mut xx, mut yy, mut xy) = (0.0, 0.0, 0.0);
    for p in &pts {
        let (x, y) = (p.x - mx, p.y - my);
        xx += x * x / n;
        yy += y * y / n;
        xy += x * y / n;
    }
    let spread = ((xx - yy) * (xx - yy) + 4.0 * xy * xy).sqrt();
    let unit = |x: f64, y: f64| {
        let len = x.hypot_m(y);
        (len.is_finite() && len > 0.0).then(|| (x / len, y / len))
    };
    if spread > ANISOTROPY * (xx + yy) && spread.is_finite() {
        let phi = 0.5 * (2.0 * xy).atan2_m(xx - yy);
        let (dc, ds) = (phi.cos_m(), phi.sin_m());
        let scale = 1e-6 * size(c);
        let along = mx * dc + my * ds;
        let across = -mx * ds + my * dc;
        let sign = if along.abs() > scale { along.signum() } else if across.abs() > scale { across.signum() } else { 1.0 };
        return (sign * dc, sign * ds);
    }
    let k = c.knots();
    let chords: Vec<(f64, f64)> = (0..k.len()).map(|i| {
        let (a, b) = (k[i].anchor, k[(i + 1) % k.len()].anchor);
        (b.x - a.x, b.y - a.y)
    }).collect();
    let longest = chords.iter().map(|&(x, y)| x.hypot_m(y)).fold(0.0, f64::max);
    chords
        .iter()
        .find(|&&(x, y)| x.hypot_m(y) >= longest * (1.0 - 1e-9))
        .and_then(|&(x, y)| unit(x, y))
        .unwrap_or((1.0, 0.0))
}

/// `a` and `b` in their frames (see the module docs), with the frames; turned ([`turn_of`]) when
/// `turned`, else only moved and scaled (a convex pair: see [`super::simulate_observed`]). When either cannot be
/// framed (an outline whose size is not a positive finite number, or a second piece too large
/// for the first's unit) both are kept as they are, in the input's frame: the checks that follow
/// give their own messages on them.
pub fn pair(a: &Contour, b: &Contour, turned: bool) -> ((Contour, Frame), (Contour, Frame)) {
    let keep = ((a.clone(), Frame::INPUT), (b.clone(), Frame::INPUT));
    let (ta, tb) = if turned { (turn_of(a), turn_of(b)) } else { ((1.0, 0.0), (1.0, 0.0)) };
    let (Some((ma, oa)), Some((mb, ob))) = (moved(a, ta, 0), moved(b, tb, 1)) else { return keep };
    // The unit from the first piece's size as its frame holds it, the same for it drawn turned.
    let unit = if turned { size(&ma) } else { size(a) } / SIZE;
    if !(unit.is_normal() && unit.is_finite()) {
        return keep;
    }
    match (local(&ma, oa, ta, unit, 0), local(&mb, ob, tb, unit, 1)) {
        (Some(fa), Some(fb)) => (fa, fb),
        _ => keep,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kurbo::Affine;

    fn wavy(m: usize, r0: f64) -> Contour {
        let knots = (0..m)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / m as f64;
                let r = r0 * (1.0 + 0.2 * (3.0 * t).sin_m());
                let a = Point::new(r * t.cos_m() + 3.3, r * t.sin_m() - 7.1);
                let h = 0.08 * r0;
                Knot { anchor: a, left: Point::new(a.x + h * t.sin_m(), a.y - h * t.cos_m()), right: Point::new(a.x - h * t.sin_m(), a.y + h * t.cos_m()) }
            })
            .collect();
        Contour::new(knots, 0).unwrap()
    }

    /// A drawing and its copies moved across the artboard, turned, or drawn in other units
    /// (points, inches, metres) get the very same bits in their frames, each frame's origin is the copy's
    /// first anchor, its unit scales with the copy, and no point moved by more than half a cell.
    #[test]
    fn moved_and_scaled_copies_get_the_same_bits_in_their_frames() {
        let (a, b) = (wavy(24, 50.0), wavy(17, 43.0));
        let ((base_a, fa), (base_b, fb)) = pair(&a, &b, true);
        assert_eq!(fa.origin, a.knots()[0].anchor);
        assert_eq!(fb.origin, b.knots()[0].anchor);
        assert_eq!(fa.unit, fb.unit);
        let (lo, hi) = base_a.control_bounds();
        let got = (hi.x - lo.x).max(hi.y - lo.y);
        assert!((got - SIZE).abs() < 1e-6, "the first piece measures {got} in its frame, wanted {SIZE}");
        for (c, base, f) in [(&a, &base_a, fa), (&b, &base_b, fb)] {
            for (k, q) in c.knots().iter().zip(base.knots()) {
                let back = f.to_input([q.anchor.x, q.anchor.y]);
                let d = (back[0] - k.anchor.x).abs().max((back[1] - k.anchor.y).abs());
                // Half a cell's diagonal: the snap rounds each axis of the turned frame.
                let half_cell = 0.5 * std::f64::consts::SQRT_2 * f.cell * f.unit;
                assert!(d <= half_cell * (1.0 + 1e-9), "snap moved an anchor by {d:e}, wanted ≤ {half_cell:e} (half a cell's diagonal)");
            }
        }
        let offset = 37.123_456_789;
        for (dx, dy, k, turn) in [(37.3, -11.7, 1.0, 0.0), (250.1, 400.9, 1.0, 0.0), (-1000.3, 3.3, 1.0, 0.0), (1e-7, 0.0, 1.0, 0.0), (0.0, 0.0, 72.0 / 25.4, 0.0), (12.5, -3.0, 1.0 / 25.4, 0.0), (0.0, 0.0, 0.001, 0.0), (-7.0, 2.0, 96.0 / 25.4, 0.0), (0.0, 0.0, 100.0, 0.0), (0.0, 0.0, 1.0, 0.3), (40.0, -3.0, 1.0, 2.5), (0.0, 0.0, 72.0 / 25.4, -1.0), (5.5, 1.5, 1.0, std::f64::consts::PI)] {
            let m = Affine::translate((dx, dy)) * Affine::rotate(turn) * Affine::scale(k);
            let ((ma, ga), (mb, gb)) = pair(&a.transformed(m), &b.transformed(m), true);
            for (base, moved) in [(&base_a, &ma), (&base_b, &mb)] {
                let diff = base.knots().iter().zip(moved.knots()).filter(|(p, q)| p != q).count();
                assert_eq!(diff, 0, "moved by ({dx}, {dy}), turned by {turn} and scaled by {k}: {diff} of {} knots got other bits", base.len());
            }
            assert!(ga.origin.distance(m * a.knots()[0].anchor) < 1e-9);
            assert!((gb.unit / fb.unit - k).abs() < 1e-12 * k, "unit {} against {} × {k}", gb.unit, fb.unit);
            assert_eq!(ga.length_in(k * offset).to_bits(), fa.length_in(offset).to_bits(), "the offset scaled by {k} got other bits");
        }
    }

    /// Outlines the frames cannot take stay as they are, both of them (their checks follow).
    #[test]
    fn outlines_without_a_size_are_kept() {
        let dot = Contour::new(vec![Knot::corner(Point::new(1.0, 2.0)), Knot::corner(Point::new(1.0, 2.0))], 0).unwrap();
        let square = Contour::new([(0.0, 0.0), (5.0, 0.0), (5.0, 5.0), (0.0, 5.0)].map(|(x, y)| Knot::corner(Point::new(x, y))).to_vec(), 1).unwrap();
        for (a, b) in [(&dot, &square), (&square, &dot)] {
            let ((ka, fa), (kb, fb)) = pair(a, b, true);
            assert_eq!((ka.knots(), kb.knots()), (a.knots(), b.knots()));
            assert_eq!((fa.origin, fa.unit, fb.unit), (Point::ZERO, 1.0, 1.0));
        }
        let huge = Contour::new(vec![Knot::corner(Point::new(-1e308, 0.0)), Knot::corner(Point::new(1e308, 1.0)), Knot::corner(Point::new(0.0, 1e308))], 0).unwrap();
        assert_eq!(pair(&huge, &square, true).0 .0.knots(), huge.knots());
        // A second piece too large for the first's unit.
        let tiny = square.transformed(Affine::scale(1e-300));
        assert_eq!(pair(&tiny, &huge, true).1 .0.knots(), huge.knots());
    }
}
