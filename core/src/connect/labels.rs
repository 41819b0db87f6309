//! Connector numbers that never overlap each other, holes, slots or the cut line.
//!
//! A label of text height `h` and `c` characters is read as the box `h` high and
//! `(0.6·c + 0.2)·h` wide, centred on `at` and turned by `angle` (sans-serif digits are about
//! 0.55 em wide; the box is what hosts draw into with `font-size = h`, text centred on `at`).
//! Each label starts at its nominal depth and size ([`super::label_layout`]); when its box meets
//! something already there, it is tried a little deeper into the piece, between the edge and its
//! hole, then farther along the edge (up to 2.4 text heights either way, which clears the narrow
//! inside of a sharp corner), and then smaller, down to 0.4 of the nominal size, and the first placement that is clear is kept. A label that fits
//! nowhere keeps the smallest size at its nominal depth and the caller warns.
//!
//! Tests: box against box is the separating-axis test (two rectangles are disjoint iff their
//! projections on one of the four edge normals are), box against circle clamps the circle's
//! centre into the box's frame, box against the cut line covers the box by square cells and asks
//! [`Edge::comes_within`] for each cell's circumscribed circle (a sufficient condition).

use crate::libm_ext::LibmExt;
use super::warnings::Edge;
use kurbo::{Point, Vec2};

/// Width of a label's box per character and its margin, in text heights.
pub const CHAR_WIDTH: f64 = 0.6;
pub const MARGIN: f64 = 0.2;

/// An oriented box: centre, unit axis along the text, half extents.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LabelBox {
    pub center: Point,
    pub axis: Vec2,
    pub half: (f64, f64),
}

impl LabelBox {
    pub fn new(center: Point, angle_deg: f64, size: f64, chars: usize) -> Self {
        let a = angle_deg.to_radians();
        LabelBox { center, axis: Vec2::new(a.cos_m(), a.sin_m()), half: (0.5 * (CHAR_WIDTH * chars as f64 + MARGIN) * size, 0.5 * size) }
    }

    /// A box from a centre, a unit axis and full extents (slots).
    pub fn oriented(center: Point, axis: Vec2, length: f64, width: f64) -> Self {
        LabelBox { center, axis, half: (0.5 * length, 0.5 * width) }
    }

    fn corners(&self) -> [Point; 4] {
        let (u, v) = (self.axis * self.half.0, self.axis.turn_90() * self.half.1);
        [self.center - u - v, self.center + u - v, self.center + u + v, self.center - u + v]
    }

    /// Whether two boxes overlap (separating-axis test).
    pub fn overlaps(&self, other: &LabelBox) -> bool {
        let (ca, cb) = (self.corners(), other.corners());
        for axis in [self.axis, self.axis.turn_90(), other.axis, other.axis.turn_90()] {
            let span = |c: &[Point; 4]| {
                c.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                    let x = p.to_vec2().dot(axis);
                    (lo.min(x), hi.max(x))
                })
            };
            let ((a0, a1), (b0, b1)) = (span(&ca), span(&cb));
            if a1 <= b0 || b1 <= a0 {
                return false;
            }
        }
        true
    }

    /// Whether the box overlaps the disc of radius `r` around `c`.
    pub fn meets_circle(&self, c: Point, r: f64) -> bool {
        let d = c - self.center;
        let (x, y) = (d.dot(self.axis), d.dot(self.axis.turn_90()));
        let (qx, qy) = (x.clamp(-self.half.0, self.half.0), y.clamp(-self.half.1, self.half.1));
        (x - qx).hypot_m(y - qy) < r
    }

    /// Whether the cut line comes into the box (see the module comment): one row of cells as
    /// tall as the box, each at most as wide as tall.
    pub fn meets_edge(&self, edge: &Edge, scratch: &mut Vec<usize>) -> bool {
        let cols = ((self.half.0 / self.half.1).ceil() as usize).max(1);
        let half_w = self.half.0 / cols as f64;
        let r = half_w.hypot_m(self.half.1);
        (0..cols).any(|i| {
            let x = -self.half.0 + (2 * i + 1) as f64 * half_w;
            edge.comes_within(self.center + self.axis * x, r, scratch)
        })
    }
}

/// What a label must keep clear of.
pub struct Obstacles<'a> {
    pub holes: &'a [(Point, f64)],
    pub slots: &'a [LabelBox],
    pub edge: &'a Edge,
    /// Whether labels belong inside the cut line.
    pub inside: bool,
}

/// Places one label: from its station point `base`, along the unit direction `dir` (into the
/// piece, or out with inverted holes), at nominal `depth` and `size`; `placed` are the boxes of
/// labels already placed. With `before`, the depth of the near side of the connector's hole, a
/// label may also go between the edge and its hole when it fits there; with `own`, its hole's
/// index, it must stay nearer that hole than any other. Returns the centre,
/// size and whether it is clear.
#[allow(clippy::too_many_arguments)]
pub fn place(
    base: Point,
    dir: Vec2,
    angle: f64,
    chars: usize,
    depth: f64,
    size: f64,
    before: Option<f64>,
    own: Option<usize>,
    placed: &[LabelBox],
    obstacles: &Obstacles,
    scratch: &mut Vec<usize>,
) -> (Point, f64, bool) {
    let along = dir.turn_90().normalize();
    for scale in [1.0, 0.8, 0.64, 0.5, 0.4] {
        let h = size * scale;
        let inner = before.map(|b| b - 0.6 * h).filter(|&d| d > 0.6 * h);
        let tries = [(0.0, 0.0), (0.5, 0.0), (1.0, 0.0), (0.0, 0.6), (0.0, -0.6), (0.5, 0.6), (0.5, -0.6), (1.5, 0.0), (1.0, 1.0), (1.0, -1.0)]
            .map(|(extra, slide)| (depth + extra * h, slide));
        let inside = inner.map(|d| [(d, 0.0), (d, 0.6), (d, -0.6)]).unwrap_or_default();
        // Farther along the edge: out of the narrow inside of a sharp corner.
        let along_edge = [(0.5, 1.6), (0.5, -1.6), (1.0, 2.4), (1.0, -2.4)].map(|(extra, slide)| (depth + extra * h, slide));
        for (d, slide) in tries.into_iter().chain(inside).chain(along_edge) {
            let at = base + dir * d + along * (slide * h);
            let b = LabelBox::new(at, angle, h, chars);
            // A label stays nearest its own hole, so the numbers still say which hole is which.
            let by_own = own.is_none_or(|k| {
                let mine = (at - obstacles.holes[k].0).hypot();
                obstacles.holes.iter().enumerate().all(|(j, &(c, _))| j == k || (at - c).hypot() > mine)
            });
            let clear = by_own
                && obstacles.edge.contains(at) == obstacles.inside
                && !b.meets_edge(obstacles.edge, scratch)
                && !obstacles.holes.iter().any(|&(c, r)| b.meets_circle(c, r))
                && !obstacles.slots.iter().any(|s| b.overlaps(s))
                && !placed.iter().any(|p| b.overlaps(p));
            if clear {
                return (at, h, true);
            }
        }
    }
    (base + dir * depth, 0.4 * size, false)
}
