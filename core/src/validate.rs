//! Input checks shared by every operation: an outline must have length and must not cross itself.

use crate::arclen::control_polygon_len;
use crate::contour::Contour;
use crate::error::{Error, Result};

/// Checks a closed outline: non-zero length, no self-intersection.
pub fn check_outline(contour: &Contour, piece: usize) -> Result<()> {
    if contour.segments().all(|c| control_polygon_len(&c) == 0.0) {
        return Err(Error::ZeroLength { piece });
    }
    // TODO(core helper): self-intersection with lyon_geom (name the segments).
    Ok(())
}
