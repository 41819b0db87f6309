//! The path DTO of the contract, as JSON-shaped data:
//! `{ closed: true, points: [{ anchor: [x, y], left: [x, y], right: [x, y] }, …] }`.
//! `left` is the incoming handle (Illustrator `leftDirection`), `right` the outgoing one
//! (`rightDirection`); a missing or null handle means a corner (handle at the anchor).

use crate::contour::{Contour, Knot};
use crate::error::{Error, Result};
use kurbo::Point;
use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PointDto {
    pub anchor: [f64; 2],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub left: Option<[f64; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub right: Option<[f64; 2]>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PathDto {
    #[serde(default)]
    pub closed: bool,
    pub points: Vec<PointDto>,
}

pub(crate) fn pt(p: [f64; 2]) -> Point {
    Point::new(p[0], p[1])
}

pub(crate) fn arr(p: Point) -> [f64; 2] {
    [p.x, p.y]
}

impl PointDto {
    /// The knot of this point; a missing handle lies at the anchor (a corner).
    pub(crate) fn to_knot(&self) -> Knot {
        let a = pt(self.anchor);
        Knot { anchor: a, left: self.left.map(pt).unwrap_or(a), right: self.right.map(pt).unwrap_or(a) }
    }
}

impl From<&Knot> for PointDto {
    /// Always writes both handles, so a host can copy them straight into its points.
    fn from(k: &Knot) -> Self {
        PointDto { anchor: arr(k.anchor), left: Some(arr(k.left)), right: Some(arr(k.right)) }
    }
}

impl PathDto {
    /// Converts to a closed [`Contour`], refusing open paths; `piece` numbers the messages.
    pub fn to_contour(&self, piece: usize) -> Result<Contour> {
        if !self.closed {
            // Fewer than two points is the more basic problem; report it first.
            if self.points.len() < 2 {
                return Err(Error::TooFewPoints { piece, count: self.points.len() });
            }
            return Err(Error::OpenPath { piece });
        }
        Contour::new(self.points.iter().map(PointDto::to_knot).collect(), piece)
    }
}

impl From<&Contour> for PathDto {
    /// Always writes both handles, so a host can copy them straight into its points.
    fn from(c: &Contour) -> Self {
        PathDto { closed: true, points: c.knots().iter().map(PointDto::from).collect() }
    }
}
