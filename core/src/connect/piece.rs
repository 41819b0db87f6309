//! A piece as `connect` walks it: the outline in its walking direction (A counter-clockwise,
//! B clockwise, y-up), its arc-length table and which side is inside.

use crate::arclen::ArcTable;
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
        if !(area.abs() > 0.0) {
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

    pub fn perimeter(&self) -> f64 {
        self.table.total()
    }

    /// "first piece" / "second piece", for messages.
    pub fn name(&self) -> &'static str {
        if self.index == 0 { "first piece" } else { "second piece" }
    }
}
