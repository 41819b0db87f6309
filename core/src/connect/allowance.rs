//! Seam allowance: the cut line is the seam line (the drawn outline) moved out by the allowance
//! `a`, a true offset of the curve: every cubic's parallel curve fitted by kurbo's
//! `offset_cubic` (Levien 2022, "Parallel curves of cubic Béziers", within 1e-6 of the pitch),
//! stitched by [`Builder::run`](super::edge::Builder::run). Corners stay sharp: at a convex
//! corner the two offsets are extended to their mitre point (a point `a` from both edge lines),
//! bevelled only when the mitre is longer than `4a` (corners sharper than about 29°); at a
//! concave corner they are cut where they cross. Holes, teeth, leaves and slots are placed from
//! the seam line, which is returned as `seam` so hosts can score it.
//!
//! An allowance wider than the tightest concave bend (or half a narrow gap) would make the cut
//! line loop over itself (the offset of a curve of radius `r` has a cusp at `a = r`): that is
//! refused, found as a crossing of the cut line with itself or as a point of it closer than the
//! allowance to the seam line (sampled at 9 points per segment).

use super::edge::Builder;
use super::options::Settings;
use super::piece::Walked;
use super::spacing::locate_many;
use super::warnings;
use crate::contour::Contour;
use crate::error::{len, Error, Result};
use kurbo::{CubicBez, ParamCurve};

/// The seam line of `piece` moved out by the allowance (walking direction), and its segments.
pub fn outline(piece: &Walked, set: &Settings) -> (Contour, Vec<CubicBez>, Vec<usize>) {
    // Start and end in the middle of the longest segment, so that every corner (anchor 0's too)
    // is joined by the builder's mitre, and the loop closes on a smooth stretch.
    let table = &piece.table;
    let seg_len = |i: usize| table.segment_start(i + 1) - table.segment_start(i);
    let longest = (0..table.segment_count()).max_by(|&i, &j| seg_len(i).total_cmp(&seg_len(j))).unwrap_or(0);
    let st = locate_many(table, &[table.segment_start(longest) + 0.5 * seg_len(longest)]);
    let mut b = Builder::new(piece, set.pitch);
    b.run(&st[0], &st[0], piece.perimeter(), set.allowance, 0);
    b.finish()
}

/// Refuses an allowance whose cut line crosses itself (checked on any new outline built from
/// the cut line, so leaves count too).
pub fn check(piece: &Walked, set: &Settings, segs: &[CubicBez]) -> Result<()> {
    if set.allowance == 0.0 {
        return Ok(());
    }
    // A cut line that folds over itself either crosses itself or (where the folds lie on top of
    // each other) comes back closer to the seam line than the allowance: both are caught.
    let tags = vec![0; segs.len()];
    let seam = warnings::Edge::new(piece.contour.segments().collect());
    let near = 0.999 * set.allowance;
    let folds = segs.iter().any(|c| (0..=8).any(|j| seam.distance_below(c.eval(j as f64 / 8.0), near).is_some()));
    if folds || !warnings::collisions(segs, &tags, 8).is_empty() {
        return Err(Error::Infeasible {
            reason: format!(
                "A seam allowance of {} makes the cut line of the {} cross itself (the outline bends tighter than that somewhere, or has a narrow neck): use a smaller allowance.",
                len(set.allowance),
                piece.name()
            ),
        });
    }
    Ok(())
}
