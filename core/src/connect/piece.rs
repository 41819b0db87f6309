//! A piece as `connect` walks it: the outline in its walking direction (A counter-clockwise,
//! B clockwise, y-up), its arc-length table and which side is inside.

use super::spacing::Station;
use crate::arclen::{control_polygon_len, unit_tangent, ArcTable};
use crate::contour::Contour;
use crate::error::{Error, Result};
use kurbo::Vec2;

/// One of the two pieces, oriented for walking.
#[derive(Debug, Clone)]
pub struct Walked {
    /// 0 for A, 1 for B (used in messages).
    pub index: usize,
    /// The outline in walking direction, starting at the input's first anchor.
    pub contour: Contour,
    /// Whether `contour` is the input walked backwards (outputs are turned back).
    pub reversed: bool,
    /// +1 when the walk runs counter-clockwise (inside on the left), −1 when clockwise.
    pub turn: f64,
    pub table: ArcTable,
}

impl Walked {
    /// Orients `input` to run counter-clockwise (`ccw`) or clockwise, by the sign of its area
    /// (Green's theorem, [`Contour::signed_area`]).
    pub fn new(input: &Contour, index: usize, ccw: bool, accuracy: f64) -> Result<Self> {
        let area = input.signed_area();
        if area == 0.0 || area.is_nan() {
            return Err(Error::Infeasible {
                reason: format!(
                    "The {} piece encloses no area, so it has no inside for the connectors.",
                    if index == 0 { "first" } else { "second" }
                ),
            });
        }
        let reversed = (area > 0.0) != ccw;
        let contour = if reversed { input.reversed() } else { input.clone() };
        let table = ArcTable::new(&contour, accuracy);
        Ok(Walked { index, contour, reversed, turn: if ccw { 1.0 } else { -1.0 }, table })
    }

    /// Unit normal pointing into the piece, for the unit tangent `t` of the walk: the tangent
    /// turned by +90° on a counter-clockwise walk, −90° on a clockwise one.
    pub fn inward(&self, t: Vec2) -> Vec2 {
        Vec2::new(-t.y, t.x) * self.turn
    }

    /// Inward offset direction at a station, scaled for unit distance from the edge. Inside a
    /// segment it is the unit normal. At an anchor where the outline turns (a corner) it is the
    /// mitre vector `(n₁ + n₂)/|n₁ + n₂| / cos(φ/2)` of the normals before and after (φ the angle
    /// between them): a point `d` along it is `d` away from both edge lines, so a hole at a corner
    /// keeps its inset from both sides. The factor is capped at 4 (corners sharper than ~29°).
    pub fn inward_at(&self, st: &Station) -> Vec2 {
        let n = self.table.segment_count();
        let live = |i: usize| control_polygon_len(self.table.segment(i)) > 0.0;
        let (before, after) = if st.t <= 1e-9 {
            let prev = (1..=n).map(|d| (st.seg + n - d) % n).find(|&i| live(i));
            match prev {
                Some(i) => (unit_tangent(self.table.segment(i), 1.0), st.tangent),
                None => return self.inward(st.tangent),
            }
        } else if st.t >= 1.0 - 1e-9 {
            let next = (1..=n).map(|d| (st.seg + d) % n).find(|&i| live(i));
            match next {
                Some(i) => (st.tangent, unit_tangent(self.table.segment(i), 0.0)),
                None => return self.inward(st.tangent),
            }
        } else {
            return self.inward(st.tangent);
        };
        let (n1, n2) = (self.inward(before), self.inward(after));
        let cos = n1.dot(n2);
        let sum = n1 + n2;
        if cos > 1.0 - 1e-12 || sum.hypot() < 1e-9 {
            return n2;
        }
        let half_cos = (0.5 * (1.0 + cos)).sqrt().max(0.25);
        sum.normalize() / half_cos
    }

    /// The walking direction matching an inward direction `n` (the tangent it is the normal of).
    pub fn along(&self, n: Vec2) -> Vec2 {
        let t = Vec2::new(n.y, -n.x) * self.turn;
        if t.hypot() > 0.0 { t.normalize() } else { Vec2::new(1.0, 0.0) }
    }

    pub fn perimeter(&self) -> f64 {
        self.table.total()
    }

    /// "first piece" / "second piece", for messages.
    pub fn name(&self) -> &'static str {
        if self.index == 0 { "first piece" } else { "second piece" }
    }
}
