//! The two pieces sampled at the seam: `N` points at equal arc-length steps, A walked
//! counter-clockwise from its first anchor, B walked clockwise from its first anchor + `offset`
//! (the `start` convention of `connect`). B is then mirrored (x → −x), an isometry of the plane,
//! so that both sample polygons run counter-clockwise: vertex k of A and vertex k of B are the
//! same seam vertex.

use crate::arclen::ArcTable;
use crate::contour::Contour;
use crate::error::{Error, Result};
use crate::validate;

/// Relative accuracy of the arc lengths used to place seam samples: far below any visible or
/// measurable effect (the seam gap target is 1e-4 of the perimeter) and cheap to invert.
pub const SAMPLE_ACCURACY: f64 = 1e-11;

/// Largest relative perimeter difference that can be stitched (the same rule as `connect`).
pub const PERIMETER_TOLERANCE: f64 = 1e-6;

/// One sampled piece, in its own flat coordinates.
#[derive(Debug, Clone)]
pub struct FlatPiece {
    /// Seam samples, counter-clockwise.
    pub pts: Vec<[f64; 2]>,
    /// For seam edge k (vertex k → k+1): the point of the true outline halfway along the arc.
    pub arc_mid: Vec<[f64; 2]>,
    /// The true (curved) outline's area and perimeter.
    pub area: f64,
    pub perimeter: f64,
}

/// Both pieces, with the same number of samples.
#[derive(Debug, Clone)]
pub struct SeamPieces {
    pub n: usize,
    pub flat: [FlatPiece; 2],
}

/// The two outlines oriented for gluing, measured once and sampled at any resolution.
#[derive(Debug, Clone)]
pub struct Glue {
    ta: ArcTable,
    tb: ArcTable,
    area: [f64; 2],
    offset: f64,
}

impl Glue {
    /// Checks both outlines and their perimeters (the 1e-6 rule of `connect`).
    pub fn new(a: &Contour, b: &Contour, offset: f64) -> Result<Self> {
        validate::check_outline(a, 0)?;
        validate::check_outline(b, 1)?;
        for (i, c) in [a, b].into_iter().enumerate() {
            if !(c.signed_area().abs() > 0.0) {
                return Err(Error::Infeasible {
                    reason: format!(
                        "The {} piece encloses no area, so there is no surface to fold.",
                        if i == 0 { "first" } else { "second" }
                    ),
                });
            }
        }
        // A counter-clockwise, B clockwise (y-up), both still starting at their first anchor
        // (the orientation rule of `connect`: by the sign of the area).
        let a = if a.signed_area() < 0.0 { a.reversed() } else { a.clone() };
        let b = if b.signed_area() > 0.0 { b.reversed() } else { b.clone() };
        let ta = ArcTable::new(&a, SAMPLE_ACCURACY);
        let tb = ArcTable::new(&b, SAMPLE_ACCURACY);
        let (pa, pb) = (ta.total(), tb.total());
        if (pa - pb).abs() > PERIMETER_TOLERANCE * pa.max(pb) {
            return Err(Error::PerimeterMismatch { a: pa, b: pb });
        }
        Ok(Glue { ta, tb, area: [a.signed_area().abs(), b.signed_area().abs()], offset })
    }

    pub fn perimeter(&self) -> f64 {
        self.ta.total()
    }

    /// Both pieces sampled at `n` seam vertices.
    pub fn sample(&self, n: usize) -> SeamPieces {
        let sample = |t: &ArcTable, start: f64, mirror: f64| -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
            let h = t.total() / n as f64;
            let at = |s: f64| {
                let p = t.point_at(s);
                [mirror * p.x, p.y]
            };
            let pts = (0..n).map(|k| at(start + k as f64 * h)).collect();
            let mid = (0..n).map(|k| at(start + (k as f64 + 0.5) * h)).collect();
            (pts, mid)
        };
        let (pts_a, mid_a) = sample(&self.ta, 0.0, 1.0);
        let (pts_b, mid_b) = sample(&self.tb, self.offset, -1.0);
        SeamPieces {
            n,
            flat: [
                FlatPiece { pts: pts_a, arc_mid: mid_a, area: self.area[0], perimeter: self.ta.total() },
                FlatPiece { pts: pts_b, arc_mid: mid_b, area: self.area[1], perimeter: self.tb.total() },
            ],
        }
    }
}

impl SeamPieces {
    /// Flat distance between seam vertices `i` and `j` in piece `p` (a chord of the sample
    /// polygon; the triangulations only use chords that lie inside the piece).
    pub fn chord(&self, p: usize, i: usize, j: usize) -> f64 {
        let (a, b) = (self.flat[p].pts[i], self.flat[p].pts[j]);
        (a[0] - b[0]).hypot(a[1] - b[1])
    }
}
