//! Each piece in a frame of its own: moved so that its first anchor is the origin, and every
//! control point snapped to a binary grid of about 2⁻³⁰ of the piece's size.
//!
//! Why: the sheet path's answer is a deterministic function of the input's bits, and it turns
//! on them. Its meshes come from Delaunay refinement, whose exact in-circle tests decide on a
//! circle's all but cocircular samples by their last bits, and another mesh ends in another
//! equilibrium of the thin sheet (see [`super::sheet`]). So the same drawing moved on the
//! artboard gave another form: moved by (250.1, 400.9) mm the L with a circle had a volume of
//! 73,438 mm³ against 77,548, the heart drawn with corners 118,459 against 116,432 (256 seam
//! vertices, native). In a piece's own frame the drawing and its moved copy differ only by the
//! rounding of `p − origin`, about `ulp(|p| + |move|)` (2e-13 mm for a move of a metre), and the
//! snap takes both to the same grid point unless one lies within that of a grid point's midway
//! line: the odds are ~1e-6 per coordinate. The snap moves a point by at most half a cell,
//! ~5e-10 of the piece's size (5e-8 mm on a 100 mm piece), far below the 1e-6 perimeter rule
//! and below anything a cutter resolves.
//!
//! The grid is a power of two, so the snap is exact arithmetic, chosen by `ceil(log₂ size + ½)`:
//! its steps fall at sizes `2ᵏ/√2`, which no drawing in round millimetres or inches has, so a
//! moved copy (whose size differs in its last bits) gets the same grid. What the host reads
//! back, `flat`, is moved back by the origin ([`Frame::to_input`]): the input's coordinates.

use crate::contour::{Contour, Knot};
use kurbo::Point;

/// The grid cell as a power of two below the piece's size.
pub const GRID_BITS: i32 = 30;

/// Farthest the snap moves a point, relative to the piece's size: half a cell's diagonal, the
/// cell being at most `2^(1.5 − GRID_BITS)` of the size (`ceil(log₂ size + ½)` exceeds
/// `log₂ size` by at most 1.5), so `2^(1 − GRID_BITS)`, 1.9e-9.
pub const SNAP_MOVE: f64 = 2.0 / (1u64 << GRID_BITS) as f64;

/// Where a piece's frame sits in the input's coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    pub origin: Point,
}

impl Frame {
    /// A point of the piece's frame in the input's coordinates.
    pub fn to_input(&self, p: [f64; 2]) -> [f64; 2] {
        [p[0] + self.origin.x, p[1] + self.origin.y]
    }
}

/// `c` in its own frame (see the module docs), and the frame. An outline whose size is not a
/// positive finite number, or whose snapped copy is not a valid contour, is kept as it is, in
/// the frame at the origin: the checks that follow give their own messages on it.
pub fn local(c: &Contour, piece: usize) -> (Contour, Frame) {
    let keep = (c.clone(), Frame { origin: Point::ZERO });
    let Some(first) = c.knots().first() else { return keep };
    let origin = first.anchor;
    let (lo, hi) = c.control_bounds();
    // By halves, so that ±1e308 coordinates do not overflow.
    let size = 2.0 * (hi.x / 2.0 - lo.x / 2.0).max(hi.y / 2.0 - lo.y / 2.0);
    if !(size.is_finite() && size > 0.0) {
        return keep;
    }
    let cell = 2f64.powi((size.log2() + 0.5).ceil() as i32 - GRID_BITS);
    if !cell.is_normal() {
        return keep;
    }
    let snap = |p: Point| Point::new(((p.x - origin.x) / cell).round() * cell, ((p.y - origin.y) / cell).round() * cell);
    let knots: Vec<Knot> = c.knots().iter().map(|k| Knot { anchor: snap(k.anchor), left: snap(k.left), right: snap(k.right) }).collect();
    match Contour::new(knots, piece) {
        Ok(moved) => (moved, Frame { origin }),
        Err(_) => keep,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kurbo::Affine;

    fn wavy(m: usize) -> Contour {
        let knots = (0..m)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / m as f64;
                let r = 50.0 * (1.0 + 0.2 * (3.0 * t).sin());
                let a = Point::new(r * t.cos() + 3.3, r * t.sin() - 7.1);
                Knot { anchor: a, left: Point::new(a.x + 4.0 * t.sin(), a.y - 4.0 * t.cos()), right: Point::new(a.x - 4.0 * t.sin(), a.y + 4.0 * t.cos()) }
            })
            .collect();
        Contour::new(knots, 0).unwrap()
    }

    /// A drawing and its copies moved across the artboard get the very same bits in their own
    /// frames, each frame's origin is the copy's first anchor, and no point moved by more than
    /// half a cell.
    #[test]
    fn moved_copies_get_the_same_bits_in_their_own_frames() {
        let c = wavy(24);
        let (base, frame) = local(&c, 0);
        assert_eq!(frame.origin, c.knots()[0].anchor);
        let (lo, hi) = c.control_bounds();
        let half_cell = 0.5 * 2f64.powi(((hi.x - lo.x).max(hi.y - lo.y).log2() + 0.5).ceil() as i32 - GRID_BITS);
        for (k, q) in c.knots().iter().zip(base.knots()) {
            let back = frame.to_input([q.anchor.x, q.anchor.y]);
            let d = (back[0] - k.anchor.x).abs().max((back[1] - k.anchor.y).abs());
            assert!(d <= half_cell * (1.0 + 1e-9), "snap moved an anchor by {d:e}, wanted ≤ {half_cell:e}");
        }
        for (dx, dy) in [(37.3, -11.7), (250.1, 400.9), (-1000.3, 3.3), (1e-7, 0.0), (25_400.0, -25_400.0)] {
            let (moved, f) = local(&c.transformed(Affine::translate((dx, dy))), 0);
            let diff = base.knots().iter().zip(moved.knots()).filter(|(a, b)| a != b).count();
            assert_eq!(diff, 0, "moved by ({dx}, {dy}): {diff} of {} knots got other bits", c.len());
            assert!((f.origin.x - (c.knots()[0].anchor.x + dx)).abs() < 1e-9);
        }
    }

    /// Outlines the snap cannot take stay as they are (their checks follow).
    #[test]
    fn outlines_without_a_size_are_kept() {
        let dot = Contour::new(vec![Knot::corner(Point::new(1.0, 2.0)), Knot::corner(Point::new(1.0, 2.0))], 0).unwrap();
        let (same, f) = local(&dot, 0);
        assert_eq!(same.knots(), dot.knots());
        assert_eq!(f.origin, Point::ZERO);
        let huge = Contour::new(vec![Knot::corner(Point::new(-1e308, 0.0)), Knot::corner(Point::new(1e308, 1.0)), Knot::corner(Point::new(0.0, 1e308))], 0).unwrap();
        assert_eq!(local(&huge, 0).0.knots(), huge.knots());
    }
}
