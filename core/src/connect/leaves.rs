//! Leaves: rounded tabs standing out of the edge, alternating between the pieces.
//!
//! Connector k's leaf belongs to A when k is even and to B when k is odd (swapped by `invert`);
//! on the other piece connector k is the spot the leaf lands on, marked by its label. A leaf is
//! a rigid shape in the frame of the connector (point `P`, unit tangent `T`, outward normal `N`):
//! straight sides from the edge at `s_k ∓ w/2` up to `P ∓ (w/2)·T + (ℓ − r_y)·N`, closed by a
//! half ellipse with radii `w/2` along T and `r_y = min(w/2, ℓ)` along N (a semicircle whenever
//! the leaf is longer than half its width), drawn as two quarter arcs with the handle factor
//! [`CIRCLE_K`]. Width `w = 0.8·pitch`, length `ℓ` = option `length`.
//!
//! Kerf: the leaf grows by κ = kerf/2 on every side (`w + kerf`, `ℓ + κ`), so it comes out at its
//! nominal size after the laser has burnt κ away.

use super::circle::CIRCLE_K;
use super::edge::Builder;
use super::options::Settings;
use super::piece::Walked;
use super::spacing::locate_many;
use crate::contour::Contour;
use crate::error::{Error, Result};
use kurbo::CubicBez;

/// Leaf width as a fraction of the pitch.
pub const WIDTH: f64 = 0.8;

/// Whether connector k's leaf belongs to piece `index` (0 = A).
pub fn owns(index: usize, k: usize, invert: bool) -> bool {
    (k.is_multiple_of(2) != invert) == (index == 0)
}

/// Checks that a leaf (with kerf) is narrower than the pitch, so neighbours never touch on a
/// straight edge.
pub fn check(set: &Settings) -> Result<()> {
    if WIDTH * set.pitch + set.kerf >= set.pitch {
        return Err(Error::Infeasible {
            reason: format!(
                "A kerf of {} makes the leaves ({} wide) as wide as the pitch {}: use fewer connectors or a smaller kerf.",
                set.kerf,
                WIDTH * set.pitch,
                set.pitch
            ),
        });
    }
    Ok(())
}

/// The outline of `piece` with its leaves (walking direction), segments and their connectors;
/// `None` when the piece owns no leaf (one connector, on the other piece).
pub fn outline(piece: &Walked, connectors: &[f64], set: &Settings) -> Option<(Contour, Vec<CubicBez>, Vec<usize>)> {
    let pitch = piece.perimeter() / connectors.len() as f64;
    let own: Vec<usize> = (0..connectors.len()).filter(|&k| owns(piece.index, k, set.invert)).collect();
    if own.is_empty() {
        return None;
    }
    let kappa = 0.5 * set.kerf;
    let h = 0.5 * WIDTH * pitch + kappa;
    let len = set.length + kappa;
    let ry = h.min(len);
    // Per leaf: the root before it, its centre, the root after it.
    let us: Vec<f64> = own.iter().flat_map(|&k| [connectors[k] - h, connectors[k], connectors[k] + h]).collect();
    let st = locate_many(&piece.table, &us);
    let mut b = Builder::new(piece, pitch);
    for (i, &k) in own.iter().enumerate() {
        let (root0, centre, root1) = (&st[3 * i], &st[3 * i + 1], &st[3 * i + 2]);
        // The connector's frame; at a corner the mitre direction, so the leaf splits the angle.
        let inward = piece.inward_at(centre);
        let n = -inward.normalize();
        let t = piece.along(inward);
        let q1 = centre.point - t * h + n * (len - ry);
        let q2 = centre.point + n * len;
        let q3 = centre.point + t * h + n * (len - ry);
        b.line_to(root0.point, q1, k);
        b.cubic_to(q1 + n * (CIRCLE_K * ry), q2 - t * (CIRCLE_K * h), q2, k);
        b.cubic_to(q2 + t * (CIRCLE_K * h), q3 + n * (CIRCLE_K * ry), q3, k);
        b.line_to(q3, root1.point, k);
        // The plain edge up to the next leaf's root (around to the first one after the last).
        let next = (i + 1) % own.len();
        let next_root = us[3 * next] + if next == 0 { piece.perimeter() } else { 0.0 };
        b.run(root1, &st[3 * next], next_root - us[3 * i + 2], 0.0, k);
    }
    Some(b.finish())
}
