//! Leaves: flaps standing out of the edge, alternating between the pieces, and (for locking
//! leaves) the slots on the other piece that hold them.
//!
//! Connector k's leaf belongs to A when k is even and to B when k is odd (swapped by `invert`);
//! on the other piece connector k is the spot the leaf lands on, marked by its label. The count
//! is even (see [`super::options`]), so neighbours are never on the same piece, also where the
//! seam closes. A leaf is a rigid shape in the frame of the connector (point `P`, unit tangent
//! `T`, outward normal `N`; at a corner `N` is the mitre direction, so the leaf splits the angle),
//! standing on the cut line `v = a` (`a` the seam allowance, 0 by default):
//!
//! - `tab` (glued): straight sides from the edge at `s_k ∓ w/2` up to `v = a + ℓ − r_y`, closed by
//!   a half ellipse with radii `w/2` along T and `r_y = min(w/2, ℓ)` along N, drawn as two quarter
//!   arcs with the handle factor [`CIRCLE_K`]. Width `w = 0.8·p`.
//! - `lock` (the 2016 scripts' bulb): a neck of width `n = 0.4·p` and a round head of diameter
//!   `w = 0.8·p` whose top is at `v = a + ℓ`. The head's circle (centre `c = a + ℓ − w/2`) meets
//!   the neck's sides at the shoulders `v_s = c − √((w/2)² − (n/2)²)`, drawn as kurbo's
//!   [`Arc`](kurbo::Arc) (cubic fit within 1e-6 of the pitch). Joined face to face, a point `v`
//!   out of one piece's seam line lies `v` into the other's, so the leaf folds over the seam
//!   onto the other piece and its head goes through a slot there: a slit centred at depth `v_s`
//!   on the other piece, as long as the neck is wide (along the edge) and `t = p/20` across,
//!   which the head is pushed through and whose ends catch the shoulders.
//!
//! Kerf (κ = kerf/2): a leaf grows by κ on every side (`w + kerf`, `n + kerf`, `ℓ + κ`), a slot
//! shrinks by κ on every side (`n − kerf` by `t − kerf`), so after cutting both have their
//! nominal sizes and the neck fills the slot exactly.

use crate::libm_ext::LibmExt;
use super::circle::CIRCLE_K;
use super::edge::Builder;
use super::options::{Leaf, Settings};
use super::piece::Walked;
use super::spacing::{locate_many, Station};
use crate::contour::{Contour, Knot};
use crate::error::{len, Error, Result};
use kurbo::{Affine, CubicBez, PathEl, Point, Vec2};

/// Leaf (and head) width as a fraction of the pitch.
pub const WIDTH: f64 = 0.8;
/// Neck width of a locking leaf as a fraction of the pitch.
pub const NECK: f64 = 0.4;
/// Slot width across the edge as a fraction of the pitch (a slit the material slides through).
pub const SLOT: f64 = 0.05;

/// Whether connector k's leaf belongs to piece `index` (0 = A).
pub fn owns(index: usize, k: usize, invert: bool) -> bool {
    (k.is_multiple_of(2) != invert) == (index == 0)
}

/// Heights of a locking leaf above its root, nominal (no kerf): shoulder and head centre.
pub fn lock_heights(set: &Settings) -> (f64, f64) {
    let (r, hn) = (0.5 * WIDTH * set.pitch, 0.5 * NECK * set.pitch);
    let c = set.length - r;
    (c - (r * r - hn * hn).sqrt(), c)
}

/// Checks that a leaf (with kerf) is narrower than the pitch, so neighbours never touch on a
/// straight edge; for locking leaves also that the neck has a length and the slot a width.
pub fn check(set: &Settings) -> Result<()> {
    if WIDTH * set.pitch + set.kerf >= set.pitch {
        return Err(Error::Infeasible {
            reason: format!(
                "A kerf of {} makes the leaves ({} wide) as wide as the pitch {}: use fewer connectors or a smaller kerf.",
                len(set.kerf),
                len(WIDTH * set.pitch),
                len(set.pitch)
            ),
        });
    }
    if set.leaf == Leaf::Lock {
        let (shoulder, _) = lock_heights(set);
        if shoulder <= 0.0 {
            let r = 0.5 * WIDTH * set.pitch;
            let hn = 0.5 * NECK * set.pitch;
            return Err(Error::Infeasible {
                reason: format!(
                    "Locking leaves {} long leave no neck under their head ({} wide) at a pitch of {}: make them longer than {} or use fewer connectors.",
                    len(set.length),
                    len(2.0 * r),
                    len(set.pitch),
                    len(r + (r * r - hn * hn).sqrt())
                ),
            });
        }
        if set.kerf >= SLOT * set.pitch {
            return Err(Error::Infeasible {
                reason: format!(
                    "A kerf of {} is as wide as the slots for the locking leaves ({} across): the slots would vanish. Use a smaller kerf or fewer connectors.",
                    len(set.kerf),
                    len(SLOT * set.pitch)
                ),
            });
        }
    }
    Ok(())
}

/// The frame of connector `st` on `piece`: point, unit tangent along the walk, unit outward
/// normal (the mitre direction at a corner).
fn frame(piece: &Walked, st: &Station) -> (Point, Vec2, Vec2) {
    let inward = piece.inward_at(st);
    (st.point, piece.along(inward), -inward.normalize())
}

/// The map from leaf coordinates `(x along T, y along N)` to the drawing.
fn to_world(p: Point, t: Vec2, n: Vec2) -> Affine {
    Affine::new([t.x, t.y, n.x, n.y, p.x, p.y])
}

/// The outline of `piece` with its leaves (walking direction), segments and their connectors;
/// `None` when the piece owns no leaf (one connector, on the other piece).
pub fn outline(piece: &Walked, connectors: &[f64], set: &Settings) -> Option<(Contour, Vec<CubicBez>, Vec<usize>)> {
    let pitch = piece.perimeter() / connectors.len() as f64;
    let own: Vec<usize> = (0..connectors.len()).filter(|&k| owns(piece.index, k, set.invert)).collect();
    let a = set.allowance;
    if own.is_empty() {
        return None;
    }
    let kappa = 0.5 * set.kerf;
    let h = 0.5 * WIDTH * pitch + kappa;
    let hn = 0.5 * NECK * pitch + kappa;
    let root = if set.leaf == Leaf::Lock { hn } else { h };
    let len = set.length + kappa;
    let ry = h.min(len);
    // Per leaf: the root before it, its centre, the root after it.
    let us: Vec<f64> = own.iter().flat_map(|&k| [connectors[k] - root, connectors[k], connectors[k] + root]).collect();
    let st = locate_many(&piece.table, &us);
    let mut b = Builder::new(piece, pitch);
    // Roots on the cut line: the seam line moved out by the allowance (the mitre at a corner).
    let on_cut = |s: &Station| s.point - piece.inward_at(s) * a;
    for (i, &k) in own.iter().enumerate() {
        let (root0, centre, root1) = (&st[3 * i], &st[3 * i + 1], &st[3 * i + 2]);
        let (p, t, n) = frame(piece, centre);
        let m = to_world(p, t, n);
        match set.leaf {
            Leaf::Tab => {
                let q1 = p - t * h + n * (a + len - ry);
                let q2 = p + n * (a + len);
                let q3 = p + t * h + n * (a + len - ry);
                b.line_to(on_cut(root0), q1, k);
                b.cubic_to(q1 + n * (CIRCLE_K * ry), q2 - t * (CIRCLE_K * h), q2, k);
                b.cubic_to(q2 + t * (CIRCLE_K * h), q3 + n * (CIRCLE_K * ry), q3, k);
                b.line_to(q3, on_cut(root1), k);
            }
            Leaf::Lock => {
                let c = a + len - h;
                let shoulder = c - (h * h - hn * hn).sqrt();
                b.line_to(on_cut(root0), m * Point::new(-hn, shoulder), k);
                // From the left shoulder over the top to the right one: clockwise in (T, N).
                let start = (shoulder - c).atan2_m(-hn);
                let end = (shoulder - c).atan2_m(hn);
                let sweep = -(std::f64::consts::TAU - (end - start).rem_euclid(std::f64::consts::TAU));
                let arc = kurbo::Arc::new(Point::new(0.0, c), (h, h), start, sweep, 0.0);
                for el in arc.append_iter(1e-6 * pitch) {
                    if let PathEl::CurveTo(p1, p2, p3) = el {
                        b.cubic_to(m * p1, m * p2, m * p3, k);
                    }
                }
                b.line_to(m * Point::new(hn, shoulder), on_cut(root1), k);
            }
        }
        // The cut line up to the next leaf's root (around to the first one after the last).
        let next = (i + 1) % own.len();
        let next_root = us[3 * next] + if next == 0 { piece.perimeter() } else { 0.0 };
        b.run(root1, &st[3 * next], next_root - us[3 * i + 2], a, k);
    }
    Some(b.finish())
}

/// A slot of a locking leaf, as drawn (kerf taken off every side).
#[derive(Debug, Clone, PartialEq)]
pub struct Slot {
    pub center: Point,
    /// Unit direction along the edge (the slot's long side).
    pub axis: Vec2,
    /// Drawn length (along the edge) and width (across it).
    pub length: f64,
    pub width: f64,
    pub path: Contour,
}

impl Slot {
    /// The slot's rectangle, for keeping labels off it.
    pub fn bounds(&self) -> super::labels::LabelBox {
        super::labels::LabelBox::oriented(self.center, self.axis, self.length, self.width)
    }
}

/// The slots on `piece` for the other piece's locking leaves, in connector order: at connector
/// k's station, `a + v_s` into the piece (see the module comment), running against the piece's
/// drawing direction like holes (`piece_ccw`).
pub fn slots(piece: &Walked, stations: &[Station], set: &Settings, piece_ccw: bool) -> Vec<Slot> {
    if set.leaf != Leaf::Lock {
        return Vec::new();
    }
    let (shoulder, _) = lock_heights(set);
    let half_len = 0.5 * (NECK * set.pitch - set.kerf);
    let half_w = 0.5 * (SLOT * set.pitch - set.kerf);
    stations
        .iter()
        .enumerate()
        .filter(|&(k, _)| !owns(piece.index, k, set.invert))
        .map(|(_, st)| {
            let (p, t, n) = frame(piece, st);
            let center = p - n * (set.allowance + shoulder);
            let m = to_world(center, t, n);
            let mut corners = vec![(-half_len, -half_w), (half_len, -half_w), (half_len, half_w), (-half_len, half_w)];
            // (T, N) is left-handed against the walk's turn; draw against the piece's direction.
            let ccw_in_world = t.cross(n) > 0.0;
            if ccw_in_world == piece_ccw {
                corners.reverse();
            }
            let knots = corners.into_iter().map(|(x, y)| Knot::corner(m * Point::new(x, y))).collect();
            // Not `expect`: see `circle::circle`.
            let path = Contour::new(knots, piece.index).unwrap_or_else(|_| panic!("four finite knots"));
            Slot { center, axis: t, length: 2.0 * half_len, width: 2.0 * half_w, path }
        })
        .collect()
}
