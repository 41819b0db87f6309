//! Pieces that a turn carries onto themselves: a circle, where the seam offset does not change
//! the form, and a second piece that a turn of 2π/k carries onto itself, where offsets a k-th
//! of the perimeter apart give one form.
//!
//! Glued at offset `s`, A's point at arc length `t` (counter-clockwise) meets B's point at
//! `t + s` (clockwise, [`super::seam::Glue`]). When B is a circle of perimeter `P` about `c`,
//! turning it about `c` by `−2πs/P` takes its point at `t` to its point at `t + s`, and the disc
//! onto itself: every offset glues the same two flat pieces with the same seam lengths, one
//! metric, hence one D-form, only B's flat coordinates turned. Likewise when A is the circle
//! (its point at `t − s` is its point at `t` turned by `−2πs/P`).
//!
//! The solver's forms were not so: the sheet path meshes each piece by Delaunay refinement,
//! which decides by exact in-circle tests, and a circle's samples are all but cocircular, so
//! each offset drew another mesh of the circle, and another equilibrium ([`super::sheet`], "the
//! mesh decides among nearby answers"). Over 16 offsets at 256 seam vertices (native) the
//! kidney with a circle spread by 2.8 % in volume, the five lobes by 3.6 %, the blob by 1.9 %,
//! the rounded star by 5.8 %, the L by 15 %, and the smooth heart took two forms, converged
//! (70,427 mm³, bent by 88°) at even sixteenths and creased (62,221 mm³, 133°) at odd ones. The
//! panel's sweep of volume and height against the offset (the 3D form as a design tool) drew
//! that noise as a design choice, and its "Largest" button chose among meshes. So a pair with a
//! non-convex piece and a circle is solved at offset 0, and the circle's `flat` is turned by the
//! offset ([`Turn::turn`]): every offset gives the same form to the last bit, and
//! `stats.offset_free` says so. A convex pair is left alone: its exact Alexandrov polyhedron
//! has no mesh to draw, and agrees across offsets within its sampling (1e-3, the triangle with a
//! circle of `tests/simulate_shapes.rs`).
//!
//! *Turn symmetry.* Likewise when B is carried onto itself by a turn of `2π/k` about `c`, each
//! point moving `P/k` along it (an ellipse or a rounded rectangle, k = 2; the five-lobed
//! flower, 5): offsets `P/k` apart glue one metric. A kidney with the five lobes, a fifth of the
//! perimeter apart, gave forms 1.5–2.2 % apart, converged at one and not at the other (the
//! flower's samples fell elsewhere on it). So an offset past the first period is solved at its
//! remainder and B's `flat` turned by the whole periods ([`Turn::new`]). The symmetry must hold
//! to round-off ([`EXACT`]), so that the turned flat keeps every promise of an unturned one
//! (on the outline, the gluing). The offset still changes the form within a period:
//! `stats.offset_free` stays false. (A kidney with a 2:1 ellipse of 96 points already gave the
//! same form half a perimeter on: its samples fell on the same places.)
//!
//! The same holds with A turn-symmetric: its point at `t − jP/k` is its point at `t` turned by
//! `−2πj/k` (counter-clockwise, the way the seam walks A), so the form at offset `s + jP/k` is
//! the form at `s` with A's `flat` turned by that, its seam starting at the seam vertex nearest
//! A's first anchor (the one at `jP/k` before the turn; [`Turn::turn`]). The same pair picked
//! in the other order, the five lobes first and a kidney second, went from 248,368 to 260,671
//! mm³ over five offsets a fifth apart (256 seam vertices, native), unconverged at one; now it
//! is one form. When both pieces are turn-symmetric, of orders `k_A` and `k_B`, their periods
//! add up to `P/lcm(k_A, k_B)` and both may be turned ([`Turn::both`]): a 2:1 ellipse with the
//! five lobes is one form every tenth of the perimeter, not every half.
//!
//! *One circle.* A circle is solved as the same canonical circle however it was drawn (its
//! arcs, first anchor, place), and its answer placed back on the drawn one ([`Canonical`]): a
//! circle of four Bézier arcs and one of eight gave the kidney forms 3.1 % apart.
//!
//! A circle here is an outline within [`TOLERANCE`] of its radius from a circle of the same
//! perimeter, traversed at the circle's speed (checked at [`SAMPLES`] points equally spaced in
//! arc length, each against the circle's point at the same arc length). A circle drawn with
//! Illustrator's or Inkscape's ellipse tool (four Bézier quarter arcs, 2.7e-4 of the radius off
//! the circle) is one; its turned `flat` lies within that of its outline (0.015 mm on a
//! circle of 55 mm), less than a seam chord's sag (0.004 mm at 256 seam vertices) times four.

use crate::libm_ext::LibmExt;
use crate::arclen::ArcTable;
use super::Simulation;
use crate::contour::Contour;
use kurbo::Point;
use std::f64::consts::TAU;

/// Largest distance, relative to the radius, of a circle's points from the true circle's at the
/// same arc length.
pub const TOLERANCE: f64 = 5e-4;

/// Points of an outline checked against the circle, equally spaced in arc length.
pub const SAMPLES: usize = 256;

/// Relative accuracy of the arc lengths the check walks.
const ACCURACY: f64 = 1e-12;

/// Largest order of turn symmetry looked for ([`order`]): a flower of up to twelve petals.
pub const MAX_ORDER: usize = 12;

/// How closely, relative to `P/2π`, a piece must map onto itself for a turn symmetry of finite
/// order ([`order`]): round-off and the frame's snap (2⁻³⁰ of the size), not drawing. Its
/// turned flat then lies on its outline and keeps every promise of an unturned one; an ellipse
/// of five or seven Bézier arcs, which is symmetric only to about 1e-4, is left as it is.
pub const EXACT: f64 = 1e-7;

/// How a piece is carried onto itself by turns about `centre`, each point moving along it by the
/// turn's share of the `perimeter`: by every turn (a circle, `order` 0), or by the multiples of
/// `2π/order` (an ellipse or a rounded rectangle: 2; the five-lobed flower: 5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Symmetry {
    pub centre: Point,
    pub perimeter: f64,
    pub order: usize,
}

/// [`SAMPLES`] points of `c` equally spaced in arc length from its first anchor, with the arc
/// length table, the perimeter and the sense `c` runs (1 counter-clockwise, −1 clockwise);
/// `None` for an outline without a positive finite perimeter.
fn samples(c: &Contour) -> Option<(ArcTable, f64, Vec<Point>, f64)> {
    let table = ArcTable::new(c, ACCURACY);
    let p = table.total();
    if !(p.is_finite() && p > 0.0) {
        return None;
    }
    let pts = (0..SAMPLES).map(|k| table.point_at(p * k as f64 / SAMPLES as f64)).collect();
    Some((table, p, pts, if c.signed_area() >= 0.0 { 1.0 } else { -1.0 }))
}

/// `c` as a circle (a [`Symmetry`] of `order` 0), or `None` when it is none (see the module
/// docs). Never panics: a degenerate or non-finite outline is no circle.
pub fn circle(c: &Contour) -> Option<Symmetry> {
    let (_, p, pts, sense) = samples(c)?;
    // Equally spaced in arc length on a circle, the samples' mean is its centre.
    let n = SAMPLES as f64;
    let centre = Point::new(pts.iter().map(|q| q.x).sum::<f64>() / n, pts.iter().map(|q| q.y).sum::<f64>() / n);
    let r = p / TAU;
    let start = (pts[0] - centre).atan2();
    let round = pts.iter().enumerate().all(|(k, q)| {
        let a = start + sense * TAU * k as f64 / n;
        let want = Point::new(centre.x + r * a.cos_m(), centre.y + r * a.sin_m());
        q.distance(want) <= TOLERANCE * r
    });
    (round && centre.x.is_finite() && centre.y.is_finite()).then_some(Symmetry { centre, perimeter: p, order: 0 })
}

/// The finite turn symmetry of `c` ([`Symmetry`]): the largest order `k` up to [`MAX_ORDER`]
/// for which the point `P/k` further along `c` from each of [`SAMPLES`] points equally spaced
/// in arc length is that point turned by `2π/k` (the sense `c` runs) about one centre, within
/// [`EXACT`] of `P/2π`. The centre is the least-squares one, `(I − R)⁻¹ · mean(q − R p)` for
/// the turn `R`, exact for a symmetric outline. `None` when `c` has none (a circle is asked
/// of [`circle`]). Never panics.
pub fn order(c: &Contour) -> Option<Symmetry> {
    let (table, p, pts, sense) = samples(c)?;
    let tolerance = EXACT * p / TAU;
    (2..=MAX_ORDER).rev().find_map(|k| {
        let step = p / k as f64;
        let (sn, cs) = (sense * TAU / k as f64).sin_cos_m();
        let turn = |x: f64, y: f64| (cs * x - sn * y, sn * x + cs * y);
        let ahead = |j: usize| table.point_at(p * j as f64 / SAMPLES as f64 + step);
        let centre_of = |idx: &[usize]| {
            let (mut mx, mut my) = (0.0, 0.0);
            for &j in idx {
                let (q, r) = (ahead(j), turn(pts[j].x, pts[j].y));
                mx += q.x - r.0;
                my += q.y - r.1;
            }
            let (mx, my) = (mx / idx.len() as f64, my / idx.len() as f64);
            // (I − R) c = m for the turn R: determinant 2 − 2 cos(2π/k) > 0.
            let (a, b) = (1.0 - cs, sn);
            let det = a * a + b * b;
            Point::new((a * mx - b * my) / det, (b * mx + a * my) / det)
        };
        let fits = |idx: &[usize], centre: Point| {
            idx.iter().all(|&j| {
                let r = turn(pts[j].x - centre.x, pts[j].y - centre.y);
                ahead(j).distance(Point::new(centre.x + r.0, centre.y + r.1)) <= tolerance
            })
        };
        // A few points first: most outlines have no such symmetry.
        let few: Vec<usize> = (0..SAMPLES).step_by(SAMPLES / 8).collect();
        if !fits(&few, centre_of(&few)) {
            return None;
        }
        let all: Vec<usize> = (0..SAMPLES).collect();
        let centre = centre_of(&all);
        (centre.x.is_finite() && centre.y.is_finite() && fits(&all, centre)).then_some(Symmetry { centre, perimeter: p, order: k })
    })
}

/// A pair solved at another offset than the one asked for because one piece is turn-symmetric
/// ([`Symmetry`]): that piece's flat coordinates are turned by `angle` about `centre`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Turn {
    /// The piece turned: 0 for A, 1 for B.
    pub piece: u8,
    pub centre: Point,
    /// Radians, counter-clockwise.
    pub angle: f64,
}

impl Turn {
    /// The turn that carries the form at the returned offset to the form at `offset` (arc
    /// length along B, reduced to `[0, B's perimeter)`) when piece `piece` (0 = A, 1 = B) has
    /// the symmetry `s`: offset 0 and a turn by `−2π·offset/P` for a circle; for order `k`, the
    /// offset less its whole periods `P/k`, and a turn by `−2π` times their number over `k`.
    /// `None` when no turn is needed (offset 0, or within the first period).
    pub fn new(piece: u8, s: Symmetry, offset: f64) -> Option<(Turn, f64)> {
        if offset == 0.0 || !offset.is_finite() {
            return None;
        }
        if s.order == 0 {
            return Some((Turn { piece, centre: s.centre, angle: -TAU * offset / s.perimeter }, 0.0));
        }
        let (turns, rest) = whole_periods(offset, s.perimeter / s.order as f64, s.order);
        (turns != 0).then(|| (Turn { piece, centre: s.centre, angle: -TAU * turns as f64 / s.order as f64 }, rest))
    }

    /// The turns that carry the form at the returned offset to the form at `offset` when both
    /// pieces have finite orders, `sa` of A and `sb` of B: offsets `P/lcm(k_A, k_B)` apart glue
    /// one metric, since A's whole periods `P/k_A` and B's `P/k_B` add up to every multiple of
    /// it (`i·l/k_A + j·l/k_B` runs through every residue mod `l = lcm` as `l/k_A` and `l/k_B`
    /// are coprime). The offset less its whole such periods, and A turned by `−2πi/k_A`, B by
    /// `−2πj/k_B` (either turn left out when it is none). `None` when no turn is needed.
    pub fn both(sa: Symmetry, sb: Symmetry, offset: f64) -> Option<(Vec<Turn>, f64)> {
        let (ka, kb) = (sa.order, sb.order);
        if offset == 0.0 || !offset.is_finite() || ka == 0 || kb == 0 {
            return None;
        }
        let gcd = (1..=ka.min(kb)).rev().find(|d| ka % d == 0 && kb % d == 0).unwrap_or(1);
        let l = ka / gcd * kb;
        let (w, rest) = whole_periods(offset, sb.perimeter / l as f64, l);
        let (i, j) = (0..ka).flat_map(|i| (0..kb).map(move |j| (i, j))).find(|&(i, j)| (i * (l / ka) + j * (l / kb)) % l == w)?;
        let turns: Vec<Turn> = [(0u8, sa, i), (1u8, sb, j)]
            .into_iter()
            .filter(|&(_, _, n)| n != 0)
            .map(|(piece, s, n)| Turn { piece, centre: s.centre, angle: -TAU * n as f64 / s.order as f64 })
            .collect();
        (!turns.is_empty()).then_some((turns, rest))
    }

    /// `q` turned about the centre.
    pub fn apply(&self, q: [f64; 2]) -> [f64; 2] {
        let (s, c) = self.angle.sin_cos_m();
        let (x, y) = (q[0] - self.centre.x, q[1] - self.centre.y);
        [self.centre.x + c * x - s * y, self.centre.y + s * x + c * y]
    }

    /// Turns the flat corners of piece `self.piece` in `sim`, the answer at the offset
    /// [`Turn::new`] or [`Turn::both`] returned (each piece's frame coordinates). When A is turned its seam then
    /// starts elsewhere on A, so `seam` is rotated to start at the seam vertex nearest
    /// `a_start`, A's first anchor, as it does on every other answer.
    pub fn turn(&self, sim: &mut Simulation, a_start: Point) {
        for (corners, &p) in sim.flat.iter_mut().zip(&sim.piece) {
            if p == self.piece {
                *corners = corners.map(|q| self.apply(q));
            }
        }
        if self.piece == 0 {
            super::anchor::start_seam_at(sim, a_start);
        }
    }
}

/// `offset` as whole periods of `period` (taken mod `count`, the periods in the perimeter) and
/// what is left, in `[0, period)`. An offset a hair short of a whole period is that period
/// (round-off of `j·P/n`).
fn whole_periods(offset: f64, period: f64, count: usize) -> (usize, f64) {
    let mut whole = (offset / period).floor();
    let mut rest = offset - whole * period;
    if rest >= period * (1.0 - 1e-12) {
        whole += 1.0;
        rest = 0.0;
    }
    ((whole as i64).rem_euclid(count as i64) as usize, rest.max(0.0))
}

/// Bézier arcs of the circle a round piece is solved as ([`Canonical`]): 4.2e-6 of the radius
/// off a true circle, so a hundred times closer than any drawn circle this module accepts.
pub const CANONICAL_ARCS: usize = 8;

/// A round piece solved as one circle whatever way it was drawn.
///
/// The sheet path's mesh of a circle turns on its samples' last bits ([`super::sheet`], "the
/// mesh decides among nearby answers"), and so did the form: the kidney with a circle of four
/// Bézier arcs (Illustrator's and Inkscape's ellipse tools) and with one of eight, the same
/// circle within 2.7e-4 of its radius, were 3.1 % apart in volume (243,597 and 251,312 mm³, 256
/// seam vertices), and a circle drawn from another start point or the other way round drew yet
/// another mesh. So the piece is solved as [`canonical`]: [`CANONICAL_ARCS`] arcs, its first
/// anchor at the origin of its frame, its centre at `(−r, 0)`, the sense it was drawn in, and
/// the other piece's perimeter (which the pair's must equal): a function of the other piece
/// alone. Its flat corners are then placed on the drawn circle by the rigid motion that takes
/// the canonical centre to the drawn one and its first anchor to the drawn first anchor's
/// direction ([`Canonical::place`]); they lie within the drawn circle's roundness of its outline,
/// as a turned circle's do ([`Turn`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Canonical {
    /// The round piece: 0 for A, 1 for B.
    pub piece: u8,
    /// The canonical circle's centre, and the drawn one's, in the piece's frame.
    pub from: Point,
    pub to: Point,
    /// Radians, counter-clockwise: the drawn first anchor's direction from the drawn centre.
    pub angle: f64,
}

/// The circle of perimeter `perimeter` by [`CANONICAL_ARCS`] Bézier arcs, first anchor at the
/// origin, centre at `(−r, 0)`, counter-clockwise unless `clockwise`, with its radius `r`; `None`
/// for a perimeter that is not positive and finite. Its perimeter is `perimeter` to the
/// arc-length table's accuracy.
pub fn canonical(perimeter: f64, clockwise: bool, piece: usize) -> Option<(Contour, f64)> {
    if !(perimeter.is_finite() && perimeter > 0.0) {
        return None;
    }
    let m = CANONICAL_ARCS;
    let h = 4.0 / 3.0 * (TAU / (4.0 * m as f64)).tan_m();
    let knots = |r: f64| -> Vec<crate::contour::Knot> {
        (0..m)
            .map(|k| {
                let t = TAU * k as f64 / m as f64;
                let (c, s) = (t.cos_m(), t.sin_m());
                let y = if clockwise { -1.0 } else { 1.0 };
                let at = |x: f64, v: f64| Point::new(r * x - r, y * r * v);
                crate::contour::Knot { anchor: at(c, s), left: at(c + h * s, s - h * c), right: at(c - h * s, s + h * c) }
            })
            .collect()
    };
    let unit = Contour::new(knots(1.0), piece).ok()?;
    let r = perimeter / ArcTable::new(&unit, ACCURACY).total();
    if !(r.is_finite() && r > 0.0) {
        return None;
    }
    Contour::new(knots(r), piece).ok().map(|c| (c, r))
}

impl Canonical {
    /// For the round piece `piece` of the pair (`drawn`, in its frame, with its circle `s`) and
    /// the other piece `other`: the canonical circle to solve it as ([`canonical`]) and how its
    /// answer goes back onto the drawn circle. `None` when either cannot be built.
    pub fn new(piece: u8, s: Symmetry, drawn: &Contour, other: &Contour) -> Option<(Canonical, Contour)> {
        let perimeter = ArcTable::new(other, ACCURACY).total();
        let (circle, r) = canonical(perimeter, drawn.signed_area() < 0.0, piece as usize)?;
        let start = drawn.knots().first()?.anchor;
        let angle = (start - s.centre).atan2();
        angle.is_finite().then_some((Canonical { piece, from: Point::new(-r, 0.0), to: s.centre, angle }, circle))
    }

    /// `q` on the canonical circle's flat piece, placed on the drawn one's.
    pub fn apply(&self, q: [f64; 2]) -> [f64; 2] {
        let (s, c) = self.angle.sin_cos_m();
        let (x, y) = (q[0] - self.from.x, q[1] - self.from.y);
        [self.to.x + c * x - s * y, self.to.y + s * x + c * y]
    }

    /// Places the round piece's flat corners of `sim` (solved on the canonical circle) on the
    /// drawn circle.
    pub fn place(&self, sim: &mut Simulation) {
        for (corners, &p) in sim.flat.iter_mut().zip(&sim.piece) {
            if p == self.piece {
                *corners = corners.map(|q| self.apply(q));
            }
        }
    }
}

/// The piece of the pair to turn, with its symmetry: a circle ([`circle`]), B's first; else B
/// when a turn of finite order carries it onto itself ([`order`]); else A when one carries A
/// onto itself. Turning A moves the seam's start off A's first anchor, to the seam vertex
/// nearest it ([`Turn::turn`]), as a circle A does; B is preferred, which keeps it there.
pub fn round_piece(a: &Contour, b: &Contour) -> Option<(u8, Symmetry)> {
    circle(b)
        .map(|s| (1, s))
        .or_else(|| circle(a).map(|s| (0, s)))
        .or_else(|| order(b).map(|s| (1, s)))
        .or_else(|| order(a).map(|s| (0, s)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::Knot;
    use kurbo::Affine;

    /// An ellipse with semi-axes `rx`, `ry` by `m` Bézier arcs (handles of the circle's
    /// 4/3·tan(θ/4) rule, stretched), first anchor at (rx, 0), counter-clockwise.
    fn ellipse(rx: f64, ry: f64, m: usize) -> Contour {
        let h = 4.0 / 3.0 * (TAU / (4.0 * m as f64)).tan_m();
        let knots = (0..m)
            .map(|k| {
                let t = TAU * k as f64 / m as f64;
                let (c, s) = (t.cos_m(), t.sin_m());
                let a = Point::new(rx * c, ry * s);
                Knot { anchor: a, left: Point::new(a.x + h * rx * s, a.y - h * ry * c), right: Point::new(a.x - h * rx * s, a.y + h * ry * c) }
            })
            .collect();
        Contour::new(knots, 1).unwrap()
    }

    /// Circles drawn as an ellipse tool draws them (four arcs, 2.7e-4 of the radius off), with
    /// eight arcs, moved, reversed and scaled to points, are circles with their own centre and
    /// perimeter; ellipses 0.2 % out of round, a circle with one handle pulled by 1 % of the
    /// radius and a square are not.
    #[test]
    fn circles_drawn_with_bezier_arcs_are_circles_and_near_circles_are_not() {
        let four = ellipse(50.0, 50.0, 4);
        for (what, c, centre) in [
            ("four arcs", four.clone(), Point::ZERO),
            ("eight arcs", ellipse(50.0, 50.0, 8), Point::ZERO),
            ("moved", four.transformed(Affine::translate((120.5, -33.25))), Point::new(120.5, -33.25)),
            ("reversed", four.reversed(), Point::ZERO),
            ("in points", four.transformed(Affine::scale(72.0 / 25.4)), Point::ZERO),
        ] {
            let got = circle(&c).unwrap_or_else(|| panic!("{what}: wanted a circle, got none"));
            let r = crate::arclen::perimeter(&c, 1e-12) / TAU;
            assert!(got.centre.distance(centre) <= 1e-9 * r, "{what}: wanted the centre {centre:?}, got {:?}", got.centre);
            assert!((got.perimeter / (TAU * r) - 1.0).abs() < 1e-12, "{what}: perimeter {}", got.perimeter);
        }
        let mut pulled = four.knots().to_vec();
        pulled[1].right += kurbo::Vec2::new(0.5, 0.0);
        let square = Contour::new([(0.0, 0.0), (5.0, 0.0), (5.0, 5.0), (0.0, 5.0)].map(|(x, y)| Knot::corner(Point::new(x, y))).to_vec(), 1).unwrap();
        for (what, c) in [("ellipse 1.002:1", ellipse(50.1, 50.0, 4)), ("ellipse 1:1.002", ellipse(50.0, 50.1, 8)), ("pulled handle", Contour::new(pulled, 1).unwrap()), ("square", square)] {
            assert_eq!(circle(&c), None, "{what}: wanted no circle");
        }
    }

    /// An ellipse of eight arcs has order 2 about its centre, a hexagon 6, a five-lobed flower 5
    /// (each moved, so the centre is found); an ellipse of five arcs (symmetric to 1e-4), a
    /// flower with one lobe 1 % larger, a scalene triangle and an egg have none. An offset past
    /// the first period is reduced to it, and the turn takes the point at `t` to the point
    /// the whole periods further on.
    #[test]
    fn exactly_turn_symmetric_outlines_have_their_order_and_centre() {
        let moved = Affine::translate((31.0, -17.5));
        let flower = |bump: f64| {
            let m = 80;
            let pts: Vec<Point> = (0..m)
                .map(|k| {
                    let t = TAU * k as f64 / m as f64;
                    let r = 55.0 * (1.0 + 0.12 * (5.0 * t).sin_m()) * (1.0 + bump * (-((t - 1.0) * 8.0).powi(2)).exp_m());
                    Point::new(r * t.cos_m(), r * t.sin_m())
                })
                .collect();
            let knots = (0..m)
                .map(|i| {
                    let (a, prev, next) = (pts[i], pts[(i + m - 1) % m], pts[(i + 1) % m]);
                    let h = (next - prev) / 6.0;
                    Knot { anchor: a, left: a - h, right: a + h }
                })
                .collect();
            Contour::new(knots, 0).unwrap()
        };
        let hexagon = Contour::new((0..6).map(|k| { let t = TAU * k as f64 / 6.0; Knot::corner(Point::new(40.0 * t.cos_m(), 40.0 * t.sin_m())) }).collect(), 0).unwrap();
        for (what, c, order) in [("ellipse", ellipse(60.0, 25.0, 8), 2), ("hexagon", hexagon, 6), ("five lobes", flower(0.0), 5)] {
            let c = c.transformed(moved);
            let s = super::order(&c).unwrap_or_else(|| panic!("{what}: wanted order {order}, got none"));
            assert_eq!(s.order, order, "{what}");
            assert!(s.centre.distance(Point::new(31.0, -17.5)) < 1e-6, "{what}: centre {:?}", s.centre);
            assert_eq!(circle(&c), None, "{what}: no circle");
            let table = ArcTable::new(&c, 1e-12);
            let p = table.total();
            let offset = (order as f64 - 0.7) * p / order as f64;
            let (turn, at) = Turn::new(1, s, offset).expect("past the first period");
            assert!((at - 0.3 * p / order as f64).abs() < 1e-9 * p, "{what}: reduced to {at}");
            for t in [0.1 * p, 0.6 * p] {
                let q = table.point_at(t);
                let got = turn.apply([q.x, q.y]);
                let want = table.point_at(t - (offset - at));
                assert!(Point::new(got[0], got[1]).distance(want) < 1e-8 * p, "{what}: turned {got:?}, wanted {want:?}");
            }
        }
        let egg = Contour::new((0..40).map(|k| { let t = TAU * k as f64 / 40.0; Knot::corner(Point::new(50.0 * t.cos_m() * (1.0 + 0.1 * t.cos_m()), 40.0 * t.sin_m())) }).collect(), 0).unwrap();
        for (what, c) in [("ellipse of five arcs", ellipse(60.0, 25.0, 5)), ("flower with one lobe larger", flower(0.01)), ("egg", egg)] {
            assert_eq!(order(&c), None, "{what}: wanted no symmetry");
        }
    }

    /// Two turn-symmetric pieces: every offset is reduced below `P/lcm(k_A, k_B)` and the two
    /// turns account for the rest, i.e. A's whole periods and B's add up to what was taken off
    /// (mod P); within the first such period nothing is turned.
    #[test]
    fn two_orders_reduce_offsets_by_their_least_common_period() {
        let at = |order| Symmetry { centre: Point::ZERO, perimeter: 60.0, order };
        for (ka, kb, l) in [(5, 2, 10), (3, 4, 12), (6, 4, 12), (2, 2, 2)] {
            let period = 60.0 / l as f64;
            for k in 0..3 * l {
                let offset = (k as f64 + 0.3) * period;
                let Some((turns, rest)) = Turn::both(at(ka), at(kb), offset) else {
                    assert!(k % l == 0, "orders {ka}, {kb}: offset {offset} wanted turns");
                    continue;
                };
                assert!((rest - 0.3 * period).abs() < 1e-9, "orders {ka}, {kb}: offset {offset} reduced to {rest}");
                // A turn by −2πn/k is n of that piece's periods P/k, in either piece.
                let taken: f64 = turns.iter().map(|t| {
                    let k = if t.piece == 0 { ka } else { kb };
                    (-t.angle / TAU * k as f64).round() * 60.0 / k as f64
                }).sum();
                let d = (offset - rest - taken).rem_euclid(60.0);
                assert!(d < 1e-9 || 60.0 - d < 1e-9, "orders {ka}, {kb}: offset {offset}: turns take {taken}, wanted {} mod 60", offset - rest);
            }
        }
    }

    /// A point, a segment traced back and forth and coordinates past f64's range are no circle,
    /// and asking does not panic.
    #[test]
    fn degenerate_outlines_are_no_circle() {
        let dot = Contour::new(vec![Knot::corner(Point::new(1.0, 2.0)), Knot::corner(Point::new(1.0, 2.0))], 0).unwrap();
        let line = Contour::new(vec![Knot::corner(Point::new(0.0, 0.0)), Knot::corner(Point::new(10.0, 0.0))], 0).unwrap();
        let huge = Contour::new(vec![Knot::corner(Point::new(-1e308, 0.0)), Knot::corner(Point::new(1e308, 1.0)), Knot::corner(Point::new(0.0, 1e308))], 0).unwrap();
        for c in [dot, line, huge] {
            assert_eq!(circle(&c), None);
        }
    }

    /// The turn takes the circle's point at arc length `t` (clockwise from its first anchor, as
    /// the seam walks B) to its point at `t + s`: wanted the point the circle's own arc-length
    /// table gives, within the tolerance.
    #[test]
    fn the_turn_moves_a_circle_along_itself_by_the_offset() {
        let b = ellipse(40.0, 40.0, 4).reversed();
        let p = crate::arclen::perimeter(&b, 1e-12);
        let table = ArcTable::new(&b, 1e-12);
        let a = ellipse(60.0, 25.0, 8);
        let (piece, c) = round_piece(&a, &b).expect("B is a circle");
        assert_eq!((piece, c.order), (1, 0));
        for s in [0.1 * p, 0.37 * p, 0.9 * p] {
            let (turn, at) = Turn::new(piece, c, s).expect("a turn");
            assert_eq!(at, 0.0, "a circle is solved at offset 0");
            for t in [0.0, 0.2 * p, 0.55 * p] {
                let q = table.point_at(t);
                let got = turn.apply([q.x, q.y]);
                let want = table.point_at(t + s);
                let d = Point::new(got[0], got[1]).distance(want);
                assert!(d <= 2.0 * TOLERANCE * 40.0, "offset {s:.3}, t {t:.3}: wanted {want:?}, got {got:?} ({d:.2e} off)");
            }
        }
        assert_eq!(Turn::new(piece, c, 0.0), None, "offset 0 needs no turn");
        assert_eq!(round_piece(&b, &a).map(|(p, s)| (p, s.order)), Some((0, 0)), "A the circle");
        assert_eq!(round_piece(&b.reversed(), &a).map(|(p, s)| (p, s.order)), Some((0, 0)), "A the circle, B an ellipse");
        assert_eq!(round_piece(&a, &a).map(|(p, s)| (p, s.order)), Some((1, 2)), "two ellipses: B's order 2, not A's");
        let scalene = Contour::new([(0.0, 0.0), (7.0, 0.0), (2.0, 5.0)].map(|(x, y)| Knot::corner(Point::new(x, y))).to_vec(), 0).unwrap();
        assert_eq!(round_piece(&a, &scalene).map(|(p, s)| (p, s.order)), Some((0, 2)), "an ellipse A with a scalene B: A's order 2");
        assert_eq!(round_piece(&scalene, &scalene.reversed()), None, "neither piece symmetric");
    }

    /// The canonical circle has the perimeter asked for (to 1e-12), its first anchor at the
    /// origin and its centre at (−r, 0), in either sense; placed on a drawn circle of four arcs
    /// (moved, started at another angle, either sense), its point at arc length `t` from its
    /// start lands on the drawn circle's point at `t` (the same way round) within the drawn
    /// circle's roundness. Non-finite or zero perimeters give none.
    #[test]
    fn the_canonical_circle_is_placed_on_the_drawn_one() {
        for clockwise in [false, true] {
            let (c, r) = canonical(123.0, clockwise, 1).expect("a circle");
            let table = ArcTable::new(&c, 1e-12);
            assert!((table.total() - 123.0).abs() <= 1e-12 * 123.0, "perimeter {}", table.total());
            assert_eq!(c.knots()[0].anchor, Point::ZERO, "first anchor at the origin");
            assert_eq!(c.signed_area() < 0.0, clockwise, "the sense asked for");
            for k in 0..16 {
                let q = table.point_at(123.0 * k as f64 / 16.0);
                let off = (q.distance(Point::new(-r, 0.0)) - r).abs();
                assert!(off <= 5e-6 * r, "clockwise {clockwise}: point {k} off the circle about (−r, 0) by {off:.2e}");
            }
        }
        let moved = Affine::translate((30.0, -7.0)) * Affine::rotate(2.0);
        for drawn in [ellipse(20.0, 20.0, 4).transformed(moved), ellipse(20.0, 20.0, 4).reversed().transformed(moved)] {
            let e = ellipse(40.0, 10.0, 8);
            let other = e.transformed(Affine::scale(ArcTable::new(&drawn, 1e-12).total() / ArcTable::new(&e, 1e-12).total()));
            let s = circle(&drawn).expect("a circle");
            let (place, c) = Canonical::new(1, s, &drawn, &other).expect("canonical");
            let (ct, dt) = (ArcTable::new(&c, 1e-12), ArcTable::new(&drawn, 1e-12));
            assert!((ct.total() - ArcTable::new(&other, 1e-12).total()).abs() <= 1e-9, "the other piece's perimeter");
            for k in 0..8 {
                let t = dt.total() * k as f64 / 8.0;
                let q = ct.point_at(t);
                let got = place.apply([q.x, q.y]);
                let d = Point::new(got[0], got[1]).distance(dt.point_at(t));
                assert!(d <= 2.0 * TOLERANCE * 20.0, "t {t:.3}: placed {got:?}, drawn {:?} ({d:.2e} off)", dt.point_at(t));
            }
        }
        assert_eq!(canonical(f64::NAN, false, 0).map(|c| c.1), None);
        assert_eq!(canonical(0.0, false, 0).map(|c| c.1), None);
        assert_eq!(canonical(f64::INFINITY, false, 0).map(|c| c.1), None);
    }
}
