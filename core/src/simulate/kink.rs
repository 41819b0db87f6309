//! Kinks: turns so tight inside a smooth outline that the seam takes them as corners.
//!
//! A smooth anchor can still hide a corner. A heart fitted through the points of
//! x = 16 sin³t, y = 13 cos t − 5 cos 2t − 2 cos 3t − cos 4t turns by 157° at its tip and 162°
//! at its dip, each within 0.01 mm (radius 2 µm), on a perimeter of 306 mm. The graded seam
//! step ([`super::density`]) shrinks only to `L/(n·W_MAX)`, so one seam edge cut most of such a
//! turn on that piece only, and its two chords differed by 9 % (the pair's strain floor).
//!
//! So a kink is a seam vertex, as a corner is ([`super::seam::Glue::positions`]), its
//! curvature is left out of the seam's weight within an even step of it
//! ([`super::density::KINK_WINDOW`]), and the seam starts at a kink when A's first anchor lies
//! that close to one ([`super::seam::Glue::new`]). That is not enough alone: the chord of a seam
//! edge from the kink's middle falls short of its arc by what the turn itself takes,
//! `r(φ − sin φ)` for a turn `φ` on that side at radius `r` (the arc `rφ` against the chord's
//! projection `r sin φ` onto the outgoing tangent), however long the edge is. At the heart's tip
//! that is 1.4e-3 mm, 1.7 % of a 0.08 mm edge. A cutter resolves no 2 µm rounding: the piece
//! has a corner there, and a corner's sides meet at its point. So the seam walks each piece by
//! arc length with every kink taken as a corner ([`Walk`]): the walk jumps over what each side
//! of the turn loses (its *deficit*, measured on the outline as the arc minus the chord's
//! projection onto the far tangent), and the rest of the walk is scaled to the perimeter. A
//! piece with no kinks is walked by its arc length, bit for bit as before.
//!
//! *Between kinks and roundings (stop 55).* Star polygons (5–7 points, valleys at 0.45 or 0.6 of
//! the tips' radius) with a circle, 256 seam vertices, native: with sharp corners each ends sound
//! (converged or creased) in 150–290 ms; with every corner rounded by 0.1–0.5 mm, 17 of 18 end
//! stretched by 1e-3 to 500 % in 1–6 s; by 1–2 mm, 8 of 12 are sound. Such a rounding is no kink
//! ([`KINK_SHIFT`], [`KINK_OFFSET`]) and the graded steps follow it, and the sheet path does not
//! find its form. With both limits twice as wide the stars rounded by 0.1 mm are kinks and end
//! creased, strained by at most 1.06e-3, in 0.3–0.4 s (the five-pointed one at 84,494 mm³, its
//! sharp twin 82,618), those rounded by 0.25 mm not; the limits were not moved, because the rounded
//! rectangle with a circle above, a convex pair, ended strained at 256 seam vertices with its
//! 0.06 mm corners taken as kinks. Since stop 56 such stars are solved a second time with every
//! tight turn taken as a kink ([`Limits::CORNERS`]) when the first answer is not converged, and
//! the better answer is kept ([`super::corners`]).

use crate::libm_ext::LibmExt;
use crate::arclen::{unit_tangent, ArcTable};
use super::seam::CORNER_TURN;

/// Curvature (times the perimeter) above which a turn is a kink: `2·K·16`, twice the tightest
/// the seam density resolved when kinks came in (its largest weight was 16). Left there when
/// that weight went to 64 ([`super::density::W_MAX`]): kinks also need [`KINK_SHIFT`] and
/// [`KINK_OFFSET`], and the rounded corners between the two thresholds are now resolved by the
/// density instead of ending stretched.
pub const KINK_KAPPA_L: f64 = 2.0 * super::density::K * 16.0;

/// Largest deficit of a kink (both sides, relative to the perimeter): the seam's gluing moves
/// by a kink's deficit ([`Walk`]), so a turn that would move it more is no kink but a rounding
/// the seam's graded steps follow ([`super::density`]), as before kinks. 1e-4 is 0.1 mm on a
/// metre of seam, a laser's kerf. The fitted heart's tip loses 2.7e-3 mm of 306 (8.9e-6), its
/// dip 2.2e-3 (7.3e-6); a 90° corner rounded at 0.05 mm on a 200 mm rectangle 7.8e-3 (3.9e-5),
/// where the graded steps, then at most 16 times shorter than the even ones,
/// left 2 % between the chords beside it. A hairpin at the kinks' curvature (radius `L/768`)
/// would lose 4e-3 of `L`.
pub const KINK_SHIFT: f64 = 1e-4;

/// Largest distance of a kink's middle from the tangent lines at the ends of its tight stretch
/// (relative to the perimeter). The walk makes up what a chord from the middle loses to the
/// turn as seen from far off; a seam edge of length `h` from it also sits off that tangent by
/// this distance `d`, which lengthens its chord by about `d²/2h` more, and the convex path is
/// sensitive to it. A 60×40 rectangle with its corners rounded at radius r, glued to a circle
/// (measured at 128 and 256 seam vertices): up to r = 0.05 mm (d = 7.3e-5 of the perimeter; the
/// chords beside a corner 1.7e-4 apart) it converges at both; at 0.06 and 0.065 mm (8.8e-5 and
/// 9.5e-5) at 128 only, at 256 ending 1.5e-2 strained (the chords 2.6e-4 and 3.1e-4 apart),
/// where by the graded steps alone, as from 0.07 mm (1.0e-4) on, every one of these ended
/// 2–180 % strained and most through themselves. The fitted heart's turns are 1.2e-5 off.
pub const KINK_OFFSET: f64 = 1e-4;

/// Tangent samples per segment when looking for kinks.
const KINK_PER_SEGMENT: usize = 48;

/// Tight stretches closer than this (relative to the perimeter) are one, and a stretch this
/// close to a corner is the corner's.
const KINK_NEAR: f64 = 1e-6;

/// A kink of an outline ([`kinks`]): arc lengths along it of its middle and of the tight
/// stretch around it (`from` may be negative and `to` beyond the perimeter when the stretch
/// runs across the first anchor), and the deficit of each side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kink {
    pub at: f64,
    pub from: f64,
    pub to: f64,
    /// The arc from `from` to `at`, less the chord's projection onto the tangent at `from`.
    pub before: f64,
    /// The arc from `at` to `to`, less the chord's projection onto the tangent at `to`.
    pub after: f64,
    /// The larger distance of the middle from the tangent line at `from` or at `to`.
    pub offset: f64,
}

/// Which tight turns are kinks: those whose deficit (both sides) and offset, relative to the
/// perimeter, are at most `shift` and `offset` ([`kinks_within`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    pub shift: f64,
    pub offset: f64,
}

impl Limits {
    /// The seam's own: [`KINK_SHIFT`] and [`KINK_OFFSET`], turns the walk takes as corners
    /// without moving the gluing or the chords beside them by more than a kerf.
    pub const EXACT: Limits = Limits { shift: KINK_SHIFT, offset: KINK_OFFSET };

    /// Every turn tighter than [`KINK_KAPPA_L`] (a rounding of radius below `L/768`, below what
    /// the seam's graded steps resolve at 256 samples), whatever its deficit and offset: the
    /// preview of such roundings as corners ([`crate::simulate::corners`]). Its seam edges
    /// beside a kink are off their arcs by the deficit, spread over the seam, and by `d²/2h`
    /// (module docs, [`KINK_OFFSET`]), which the answer's strain then shows.
    pub const CORNERS: Limits = Limits { shift: f64::INFINITY, offset: f64::INFINITY };
}

/// The kinks of `t` within [`Limits::EXACT`] ([`kinks_within`]).
pub fn kinks(t: &ArcTable, corners: &[f64]) -> Vec<Kink> {
    kinks_within(t, corners, Limits::EXACT)
}

/// The kinks of `t`: stretches inside segments, or across a smooth anchor, where the tangent
/// turns by more than [`CORNER_TURN`] at a mean curvature above [`KINK_KAPPA_L`]` / L`, within
/// `limits`. The middle is where the tangent has made half the stretch's turn. A stretch that
/// reaches one of `corners` (arc lengths of the anchors that are corners) is that corner's, not
/// a kink.
pub fn kinks_within(t: &ArcTable, corners: &[f64], limits: Limits) -> Vec<Kink> {
    let total = t.total();
    if !(total > 0.0) {
        return Vec::new();
    }
    let tight = KINK_KAPPA_L / total;
    // Tight stretches as (start, end, turn), in arc-length order.
    let mut runs: Vec<(f64, f64, f64)> = Vec::new();
    for i in 0..t.segment_count() {
        let (s0, s1) = (t.segment_start(i), t.segment_start(i + 1));
        if !(s1 > s0) {
            continue;
        }
        let seg = t.segment(i);
        let mut prev = unit_tangent(seg, 0.0);
        for m in 1..=KINK_PER_SEGMENT {
            let (u0, u1) = ((m - 1) as f64 / KINK_PER_SEGMENT as f64, m as f64 / KINK_PER_SEGMENT as f64);
            let next = unit_tangent(seg, u1);
            let turn = prev.cross(next).atan2_m(prev.dot(next));
            prev = next;
            if turn.abs() <= CORNER_TURN {
                continue;
            }
            // The chord is at most the arc: a turn that is not tight over the chord is not over
            // the arc either, and the arc is only measured for the few that are.
            let chord = (kurbo::ParamCurve::eval(seg, u1) - kurbo::ParamCurve::eval(seg, u0)).hypot();
            if turn.abs() <= tight * chord {
                continue;
            }
            let ds = crate::arclen::segment_len(&kurbo::ParamCurve::subsegment(seg, u0..u1), 1e-9);
            if turn.abs() <= tight * ds {
                continue;
            }
            let a = s0 + crate::arclen::segment_len(&kurbo::ParamCurve::subsegment(seg, 0.0..u0), 1e-9);
            let b = a + ds;
            match runs.last_mut() {
                Some(r) if a - r.1 <= KINK_NEAR * total && r.2 * turn > 0.0 => {
                    r.1 = b;
                    r.2 += turn;
                }
                _ => runs.push((a, b, turn)),
            }
        }
    }
    // A run that ends the outline and one that starts it are one stretch across the first anchor.
    if runs.len() > 1 {
        let (first, last) = (runs[0], runs[runs.len() - 1]);
        if total - last.1 + first.0 <= KINK_NEAR * total && first.2 * last.2 > 0.0 {
            runs[0] = (last.0 - total, first.1, first.2 + last.2);
            runs.pop();
        }
    }
    let near = KINK_NEAR * total;
    let at_corner = |a: f64, b: f64| corners.iter().any(|&c| [c - total, c, c + total].iter().any(|&c| c >= a - near && c <= b + near));
    runs.into_iter()
        .filter(|r| r.2.abs() > CORNER_TURN && !at_corner(r.0, r.1))
        .map(|(a, b, turn)| {
            // Bisect for the tangent at half the turn (the sign of its cross product with the
            // start's tangent turned by half the turn changes there; turns below 2π).
            let (pa, ta) = t.frame_at(t.wrap(a));
            let half = kurbo::Vec2::new(ta.x * (0.5 * turn).cos_m() - ta.y * (0.5 * turn).sin_m(), ta.x * (0.5 * turn).sin_m() + ta.y * (0.5 * turn).cos_m());
            let side = |s: f64| half.cross(t.frame_at(t.wrap(s)).1) * turn.signum();
            let (mut lo, mut hi) = (a, b);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if side(mid) < 0.0 { lo = mid } else { hi = mid }
            }
            let at = 0.5 * (lo + hi);
            let (pm, _) = t.frame_at(t.wrap(at));
            let (pb, tb) = t.frame_at(t.wrap(b));
            let before = ((at - a) - (pm - pa).dot(ta)).max(0.0);
            let after = ((b - at) - (pb - pm).dot(tb)).max(0.0);
            let offset = (pm - pa).cross(ta).abs().max((pb - pm).cross(tb).abs());
            Kink { at: t.wrap(at), from: a, to: b, before, after, offset }
        })
        .filter(|k| k.before + k.after <= limits.shift * total && k.offset <= limits.offset * total)
        .collect()
}

/// A piece walked along the seam: the arc length along its outline of seam position `s`, with
/// each kink taken as a corner (see the module docs).
#[derive(Debug, Clone)]
pub struct Walk {
    start: f64,
    scale: f64,
    /// Per kink, in seam order: its seam position, and the deficits before and after it.
    kinks: Vec<(f64, f64, f64)>,
    /// Seam positions closer than this to a kink's are the kink's.
    same: f64,
    /// The seam's length.
    seam: f64,
}

impl Walk {
    /// The walk of the outline `t` from arc length `start`, over a seam of length `seam` (the
    /// first piece's perimeter), past `kinks` (of `t`).
    pub fn new(t: &ArcTable, start: f64, seam: f64, kinks: &[Kink]) -> Walk {
        // A kink on the walk's start is seam position 0: what its first side loses closes the
        // seam's last edge, into the start.
        let near = 1e-9 * t.total();
        let rel: Vec<(f64, f64, f64)> = kinks
            .iter()
            .map(|k| match t.wrap(k.at - start) {
                r if r <= near || r >= t.total() - near => (0.0, k.before, k.after),
                r => (r, k.before, k.after),
            })
            .collect();
        let rel: Vec<(f64, f64, f64)> = crate::order::argsort(&rel.iter().map(|k| k.0).collect::<Vec<_>>()).into_iter().map(|i| rel[i]).collect();
        let lost: f64 = rel.iter().map(|k| k.1 + k.2).sum();
        let scale = (t.total() - lost) / seam;
        let mut passed = 0.0;
        let kinks = rel
            .into_iter()
            .map(|(r, before, after)| {
                if r == 0.0 {
                    passed += after;
                    return (0.0, 0.0, after);
                }
                let s = ((r - passed - before) / scale).max(0.0);
                passed += before + after;
                (s, before, after)
            })
            .collect();
        Walk { start, scale, kinks, same: 1e-9 * seam, seam }
    }

    /// Arc length along the outline (from its first anchor, not wrapped) of seam position `s`.
    pub fn arc(&self, s: f64) -> f64 {
        let mut x = self.start + self.scale * s;
        for &(c, before, after) in &self.kinks {
            if s > c + self.same {
                x += before + after;
            } else {
                if s >= c - self.same {
                    x += before;
                }
                break;
            }
        }
        x
    }

    /// Seam position of arc length `x` along the outline (wrapped from the walk's start); a
    /// kink's own arc length gives its seam position.
    pub fn seam_of(&self, t: &ArcTable, x: f64) -> f64 {
        if self.kinks.is_empty() {
            // Unwrapped, and by the inverse ratio, as the seam has always placed corners.
            return (x - self.start) * (self.seam / t.total());
        }
        let r = t.wrap(x - self.start);
        let mut passed = 0.0;
        for &(c, before, after) in &self.kinks {
            let at = self.scale * c + passed + before;
            if r < at - self.same * self.scale.max(1.0) {
                break;
            }
            if r <= at + self.same * self.scale.max(1.0) {
                return c;
            }
            passed += before + after;
        }
        (r - passed) / self.scale
    }

    /// Seam positions of the kinks.
    pub fn kink_positions(&self) -> impl Iterator<Item = f64> + '_ {
        self.kinks.iter().map(|k| k.0)
    }
}

