//! Teeth: interlocking crenellations built into both outlines.
//!
//! The flank angle θ is measured inside the tooth, against the edge: 90° square, less a tooth
//! narrowing toward its tip, more a dovetail widening toward its tip, which holds the other
//! piece's tooth behind its corners (the other piece's gap is the same dovetail turned round).
//!
//! Picture the seam flattened: `u` is arc length along the walk, `v` the distance out of the
//! piece along the outward normal. The original edge is `v = 0`, the line the two pieces meet
//! on. A piece's new edge is a trapezoid wave: tooth tops at `v = +L/2`, gap bottoms at
//! `v = −L/2`, flanks at angle θ to the edge, every tooth and every gap `p/2` wide where it
//! crosses `v = 0`. Tooth centres are at the connectors `s_k` on A and half a pitch later on B
//! (swapped by `invert`). Since B is walked clockwise, B's outward normal is A's inward one once
//! the pieces are joined face to face, so B's wave is A's mirrored, `v_B(u) = −v_A(u)`: A's tooth
//! intervals are exactly B's gap intervals.
//!
//! Kerf: each piece's edge is moved out by `κ = kerf/2` (the laser removes that much on each
//! side of its path): tops and bottoms by κ, each flank by κ along its own normal, which moves
//! its crossing of `v = 0` by `κ / sin θ` along the edge. Teeth come out `L/2 + κ` high and
//! `p/2 + 2κ/sin θ` wide at the seam line before cutting, and exact after.

use crate::libm_ext::LibmExt;
use super::edge::Builder;
use super::options::Settings;
use super::piece::Walked;
use super::spacing::locate_many;
use crate::contour::Contour;
use crate::error::{deg, len, Error, Result};
use kurbo::{CubicBez, Point};

/// The profile of one tooth in `(u, v)`: rising flank bottom and top, falling flank top and
/// bottom, relative to the tooth centre.
fn tooth(set: &Settings, pitch: f64) -> [(f64, f64); 4] {
    let k = 0.5 * set.kerf;
    let (sin, cot) = (set.angle.sin_m(), set.angle.cos_m() / set.angle.sin_m());
    let half = 0.25 * pitch + k / sin;
    let (top, bottom) = (0.5 * set.length + k, -0.5 * set.length + k);
    [(-half + bottom * cot, bottom), (-half + top * cot, top), (half - top * cot, top), (half - bottom * cot, bottom)]
}

/// Whether every width of the wave stays positive: tooth top and base, gap top and bottom. A
/// tapered tooth (angle < 90°) fails when its top vanishes, a dovetail (angle > 90°) when its
/// base does or the tips of neighbouring dovetails meet (the top wider than the pitch).
fn fits(set: &Settings) -> bool {
    let t = tooth(set, set.pitch);
    let (top, base) = (t[2].0 - t[1].0, t[3].0 - t[0].0);
    top > 0.0 && base > 0.0 && set.pitch - top > 0.0 && set.pitch - base > 0.0
}

/// The range of flank angles (degrees) that fit these teeth and this pitch, found by bisection
/// from 90° outwards (`fits` is monotone in the distance from 90°), or `None` when not even
/// square teeth fit.
fn angle_range(set: &Settings) -> Option<(f64, f64)> {
    let at = |deg: f64| fits(&Settings { angle: deg.to_radians(), ..set.clone() });
    if !at(90.0) {
        return None;
    }
    let edge = |far: f64| {
        let (mut ok, mut bad) = (90.0, far);
        for _ in 0..60 {
            let mid = 0.5 * (ok + bad);
            if at(mid) { ok = mid } else { bad = mid }
        }
        ok
    };
    Some((edge(0.0), edge(180.0)))
}

/// Checks that the teeth keep a positive width everywhere (see [`fits`]); the message names the
/// flank angles that would fit.
pub fn check(set: &Settings) -> Result<()> {
    if fits(set) {
        return Ok(());
    }
    let fix = match angle_range(set) {
        Some((lo, hi)) => format!(
            "At this pitch the flank angle must be between {}° and {}° (90 is square, more than 90 a dovetail): use fewer connectors, shorter teeth or an angle in that range.",
            deg((lo * 10.0).ceil() / 10.0),
            deg((hi * 10.0).floor() / 10.0)
        ),
        None => "Even square teeth do not fit: use fewer connectors or a smaller kerf.".into(),
    };
    Err(Error::Infeasible {
        reason: format!(
            "Teeth of length {} with {}° flanks do not fit a pitch of {}: the {}. {fix}",
            len(set.length),
            deg(set.angle.to_degrees()),
            len(set.pitch),
            if set.angle > std::f64::consts::FRAC_PI_2 { "dovetails' corners collide" } else { "flanks meet" }
        ),
    })
}

/// Tooth centres (unwrapped arc lengths) of a piece: at the connectors when `own`, else half a
/// pitch later.
pub fn tooth_centres(connectors: &[f64], pitch: f64, own: bool) -> Vec<f64> {
    connectors.iter().map(|&s| if own { s } else { s + 0.5 * pitch }).collect()
}

/// The toothed outline of `piece` (walking direction), its segments and their connectors.
/// `own` says whether this piece's teeth sit at the connectors (else half a pitch later).
pub fn outline(piece: &Walked, connectors: &[f64], set: &Settings, own: bool) -> (Contour, Vec<CubicBez>, Vec<usize>) {
    let pitch = piece.perimeter() / connectors.len() as f64;
    let profile = tooth(set, pitch);
    let mut us = Vec::with_capacity(4 * connectors.len());
    let mut vs = Vec::with_capacity(us.capacity());
    for &c in &tooth_centres(connectors, pitch, own) {
        for (du, v) in profile {
            us.push(c + du);
            vs.push(v);
        }
    }
    let stations = locate_many(&piece.table, &us);
    let mapped: Vec<Point> = stations
        .iter()
        .zip(&vs)
        .map(|(st, &v)| st.point - piece.inward_at(st) * v)
        .collect();
    let m = us.len();
    let mut b = Builder::new(piece, pitch);
    for i in 0..m {
        let j = (i + 1) % m;
        let tag = i / 4;
        if vs[i] != vs[j] {
            b.line_to(mapped[i], mapped[j], tag);
        } else {
            let run = if j == 0 { us[0] + piece.perimeter() - us[i] } else { us[j] - us[i] };
            b.run(&stations[i], &stations[j], run, vs[i], tag);
        }
    }
    b.finish()
}
