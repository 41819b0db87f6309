//! Where a non-convex pair's seam starts: at a point of the outline's own choosing, not at the
//! knot the drawing happened to start at.
//!
//! The seam samples are equal steps from the seam's start (A's first anchor, [`Glue::new`]), so
//! the first anchor decides every sample, and with them the sheet path's meshes. A thin sheet
//! glued from a non-convex pair has several equilibria, and which one the path falls into is
//! decided by its mesh ([`super::sheet::level`]): until stop 49 the kidney with a circle, started
//! at each of eight of its knots, gave volumes 3.2 % apart at 256 seam vertices (244,657 to
//! 252,485 mm³, all converged, WASM), the five lobes 2.0 % and the smooth heart 21 %. Which knot
//! is first is bookkeeping of the drawing (the pen starts where the student clicked first;
//! reversing, joining or cutting a path moves it), no part of the shape. So the piece that sets
//! the samples is restarted at its canonical start ([`canonical_start`]), a function of its
//! knots alone, with the offset moved so that the gluing is the same ([`restarts`]); the frames
//! ([`super::frame`]) then place and turn the restarted outline. The other piece is restarted at
//! its own canonical start too: its samples are glued to the first's, but its first anchor is
//! its frame's origin, and so the bits of its meshes. Started anywhere or drawn the
//! other way round, each with a circle, the kidney, the heart and the Pebble now give one mesh
//! and form to the last bit, the five lobes (whose five tips the rule cannot tell apart) to
//! 7e-15 mm.
//!
//! *On a mirror axis.* A mirror-symmetric outline starts on its axis, through a knot or the
//! middle of a segment: the samples, equal steps either way from there, are then mirror images,
//! and the form of a symmetric pair can be symmetric (issue 14's requirement 3). A 1:2 ellipse
//! with a dent, symmetric about its long axis, started off the axis, was 1.9 % of its size from
//! its mirror image at 128 seam vertices; on it, within the test's 0.5 %; and with the pair's
//! meshes made mirror images of themselves ([`super::sheet::mirror`]), to round-off.
//!
//! *A second start.* The canonical start is one draw of the meshes, no luckier than the drawn
//! first anchor was. An answer that misses its promise by a little, or passes through itself
//! ([`retry`]), is solved again from the point half the perimeter round (on the same axis, for
//! a symmetric outline), and the better answer is kept ([`better`]). Measured at 256 seam
//! vertices, native, on 381 pairs (120 random pairs of two blobs; the Pebble, kidney, smooth
//! heart, five lobes, blob and heart drawn with corners each with its copy and with its mirror
//! image at k/16; nine drawings with a circle): 315 converged from the drawn first anchors, 321
//! from the canonical start alone, 325 with the second start. The second start costs a second
//! solve where it runs, mostly on the smooth heart's copies and mirror images (through
//! themselves at 4–6 % strain, and no better from the other start): on the 180 pairs with copies
//! and mirror images at 1–15/16, 122 s native in all, against 83 s from the canonical start
//! alone and 79 s from the drawn first anchors. And a new draw is a reshuffle as much as a gain:
//! the kidney with its copy at 13/16, converged from its drawn first anchor, ends 3.3 %
//! stretched (from the other start, 2.0 % through itself); the smooth heart with a circle,
//! converged from its drawn first anchor (one of eight first anchors did), is creased.
//!
//! An outline with a symmetry (the five lobes, a regular flower) has several starts the rule
//! cannot tell apart; it takes the first of them in the drawn order, a start the same up to the
//! symmetry, which the frames turn to the same place.
//!
//! [`Glue::new`]: super::seam::Glue::new

use crate::libm_ext::LibmExt;
use super::checks::faces_cross;
use super::seam::SAMPLE_ACCURACY;
use super::{round, Shortfall, Simulation};
use crate::arclen::ArcTable;
use crate::contour::Contour;
use kurbo::{ParamCurve, Point};

/// Relative resolution (of the largest) at which anchors' distances from the centre are
/// compared ([`canonical_start`]): coarse enough that two distances equal but for the rounding
/// of where the outline sits (a symmetric shape's lobes, ~1e-15 apart) are equal, fine enough
/// that any drawn difference is not.
pub const DISTANCE_BITS: i32 = 30;

/// How far (relative to the outline's size, its farthest anchor's distance from their mean) a
/// knot may lie from its mirror image's reflection for an outline to count as
/// mirror-symmetric ([`canonical_start`]): 0.01 mm on a piece of 100 mm, finer than any cutter
/// can tell. A drawing made symmetric (reflected in the editor, or drawn from a formula) is so
/// to the bit in Illustrator, but a file rounds it: Inkscape writes 8 significant digits, so a
/// dented ellipse placed at (350, 420) on its page came back 7e-6 mm off, and at 1e-9 it was no
/// longer symmetric (its form 1 % of its size off its mirror image).
pub const MIRROR_TOLERANCE: f64 = 1e-4;

/// Where an outline's seam starts: at a knot, or at parameter `t` of the segment from knot `k`
/// to the next (its middle, `t = ½`, where a mirror axis crosses it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Start {
    Knot(usize),
    At(usize, f64),
}

/// The anchors' mean, each coordinate summed sorted, so that it is the same to the bit
/// whichever knot the outline starts at.
pub(super) fn centre(anchors: &[Point]) -> Point {
    let mean = |f: fn(&Point) -> f64| {
        let mut v: Vec<f64> = anchors.iter().map(f).collect();
        crate::order::sort_f64(&mut v);
        v.iter().sum::<f64>() / anchors.len() as f64
    };
    Point::new(mean(|p| p.x), mean(|p| p.y))
}

/// Whether `c` is its own mirror image in the line through `centre` and `on` (a point of the
/// outline) with its knots paired `k − i` with `j + i` (`j = k` for an axis through knot `k`,
/// `j = k + 1` for one through the middle of the segment from `k`): each anchor within
/// `tolerance` of its partner's reflection, and each handle of its partner's other one's (the
/// mirror reverses the outline's sense).
fn mirrored_about(c: &Contour, centre: Point, on: Point, k: usize, j: usize, tolerance: f64) -> bool {
    let knots = c.knots();
    let m = knots.len();
    let axis = on - centre;
    let len = axis.hypot();
    if !(len > 0.0 && len.is_finite()) {
        return false;
    }
    let u = axis / len;
    let reflect = |p: Point| {
        let d = p - centre;
        let along = d.dot(u);
        centre + (2.0 * along * u - d)
    };
    (0..=m / 2 + 1).all(|i| {
        let (a, b) = (&knots[(k + m - i % m) % m], &knots[(j + i) % m]);
        reflect(a.anchor).distance(b.anchor) <= tolerance && reflect(a.left).distance(b.right) <= tolerance && reflect(a.right).distance(b.left) <= tolerance
    })
}

/// Where `c`'s seam starts, a function of its knots alone whichever knot is first:
///
/// - on a mirror axis when it has one ([`MIRROR_TOLERANCE`]), through a knot or the middle of a
///   segment: the seam samples, equal steps either way from there, are then mirror images of
///   each other, and so can the meshes be (a symmetric pair's form must be symmetric, issue 14's
///   requirement 3); of several axes, the end farthest from the anchors' mean;
/// - else at the anchor farthest from that mean (compared to [`DISTANCE_BITS`]) whose sequence
///   of distances read forward round the outline is the greatest.
///
/// Among starts the rule cannot tell apart (a turn-symmetric outline's), the first in `c`'s
/// order. `Knot(0)` for an outline with fewer than two anchors or non-finite ones.
pub fn canonical_start(c: &Contour) -> Start {
    let knots = c.knots();
    let m = knots.len();
    let anchors: Vec<Point> = knots.iter().map(|k| k.anchor).collect();
    if m < 2 {
        return Start::Knot(0);
    }
    let centre = centre(&anchors);
    let d: Vec<f64> = anchors.iter().map(|p| p.distance_squared(centre)).collect();
    let far = d.iter().copied().fold(0.0, f64::max);
    if !(far.is_finite() && far > 0.0) {
        return Start::Knot(0);
    }
    let quantum = |x: f64| quantum(x, far);
    let tolerance = MIRROR_TOLERANCE * far.sqrt();
    let mut axis: Option<(i64, Start)> = None;
    for k in 0..m {
        let middle = c.segment(k).eval(0.5);
        for (start, on, j) in [(Start::Knot(k), anchors[k], k), (Start::At(k, 0.5), middle, k + 1)] {
            let q = quantum(on.distance_squared(centre));
            if axis.is_some_and(|(best, _)| best >= q) || !mirrored_about(c, centre, on, k, j, tolerance) {
                continue;
            }
            axis = Some((q, start));
        }
    }
    if let Some((_, start)) = axis {
        return start;
    }
    let q: Vec<i64> = d.iter().map(|&x| quantum(x)).collect();
    Start::Knot(greatest_rotation(&q))
}

/// `x` as a multiple of `far`'s 2^-[`DISTANCE_BITS`]: distances compared so are equal whichever
/// knot an outline starts at, where their last bits are not.
pub(super) fn quantum(x: f64, far: f64) -> i64 {
    (x / far * 2f64.powi(DISTANCE_BITS)).round() as i64
}

/// The first `k` from which `q` read forward round the outline (`q[k], q[k + 1], …`) is the
/// greatest sequence; 0 for an empty `q`. Only an index of `q`'s largest value can start it.
pub(super) fn greatest_rotation(q: &[i64]) -> usize {
    let m = q.len();
    let top = q.iter().copied().max().unwrap_or(0);
    let mut best: Option<usize> = None;
    for k in (0..m).filter(|&k| q[k] == top) {
        best = match best {
            Some(b) if (0..m).map(|i| q[(b + i) % m]).ge((0..m).map(|i| q[(k + i) % m])) => Some(b),
            _ => Some(k),
        };
    }
    best.unwrap_or(0)
}

/// `c` started at `start`: its knots turned to begin at that knot, or with the segment split
/// there (de Casteljau: the same curve) and begun at the new knot; with the arc length from
/// `c`'s first anchor to the new start. `None` when that is no valid contour.
fn started(c: &Contour, start: Start, piece: usize) -> Option<(Contour, f64)> {
    let mut knots = c.knots().to_vec();
    let k = match start {
        Start::Knot(k) => k,
        Start::At(k, t) => {
            let m = knots.len();
            let seg = c.segment(k);
            let (first, second) = (seg.subsegment(0.0..t), seg.subsegment(t..1.0));
            knots[k].right = first.p1;
            knots[(k + 1) % m].left = second.p2;
            knots.insert(k + 1, crate::contour::Knot { anchor: first.p3, left: first.p2, right: second.p1 });
            k + 1
        }
    };
    let split = Contour::new(knots, piece).ok()?;
    let s = ArcTable::new(&split, SAMPLE_ACCURACY).segment_start(k);
    Some((split.started_at(k), s))
}

/// A pair restarted: A, B and the offset that keeps the drawn gluing.
pub type Restart = (Contour, Contour, f64);

/// Nearer than this (of the segment's parameter) to a knot, the second start is that knot
/// ([`restarts`]).
const AT_KNOT: f64 = 1e-9;

/// The pair (`a`, `b`, glued at `offset`) restarted, first at the canonical start
/// ([`canonical_start`]) of the piece that sets the seam samples, then at the point half the
/// perimeter round from it (on the same axis, for a mirror-symmetric outline), the other piece
/// (unless it is a circle) at its own canonical start both times, each with the offset that
/// keeps the same gluing; `None` for a restart that moves neither piece's first knot. The piece
/// that sets the samples is A, or B when A is a circle and B is not (a circle is solved as one
/// canonical circle whatever its start, [`round::Canonical`], and its partner's first anchor is
/// then what is glued to that circle's). Each is oriented as the gluing takes it first (A
/// counter-clockwise, B clockwise, [`super::seam::Glue::new`]), so the offset moves by each
/// restart's arc length along the seam: A at `s` is glued to B at `offset + s` (B's arc length
/// scaled to its own perimeter), and B restarted `d` on is glued at `offset − d`. The other
/// piece is restarted too because its first anchor is its frame's origin ([`super::frame`]):
/// the five lobes with the kidney second at 3/10 of the perimeter gave 241,864 mm³ with the
/// kidney drawn from its first knot, 243,155 from its 17th and 242,250 from its 50th (256 seam
/// vertices, native).
pub fn restarts(a: &Contour, b: &Contour, offset: f64) -> [Option<Restart>; 2] {
    let (circle_a, circle_b) = (round::circle(a).is_some(), round::circle(b).is_some());
    let piece = if circle_a && !circle_b { 1 } else { 0 };
    let oriented = |p: usize| {
        let c = if p == 0 { a } else { b };
        let flip = if p == 0 { c.signed_area() < 0.0 } else { c.signed_area() > 0.0 };
        if flip { c.reversed() } else { c.clone() }
    };
    let c = oriented(piece);
    let (ta, tb) = (ArcTable::new(a, SAMPLE_ACCURACY), ArcTable::new(b, SAMPLE_ACCURACY));
    // B at its canonical start when A sets the samples and B is no circle, with the arc length
    // the offset moves back by.
    let other = if piece == 0 && !circle_b {
        let ob = oriented(1);
        match canonical_start(&ob) {
            Start::Knot(0) => None,
            start => started(&ob, start, 1),
        }
    } else {
        None
    };
    let at = |start: Start| -> Option<Restart> {
        let first = if start == Start::Knot(0) { None } else { Some(started(&c, start, piece)?) };
        if first.is_none() && other.is_none() {
            return None;
        }
        let s = first.as_ref().map_or(0.0, |f| f.1);
        let moved = if piece == 0 { offset + s * tb.total() / ta.total() - other.as_ref().map_or(0.0, |o| o.1) } else { offset - s };
        let restarted = first.map_or_else(|| c.clone(), |f| f.0);
        let pair = if piece == 0 { (restarted, other.as_ref().map_or_else(|| b.clone(), |o| o.0.clone()), moved) } else { (a.clone(), restarted, moved) };
        moved.is_finite().then_some(pair)
    };
    let first = canonical_start(&c);
    let table = ArcTable::new(&c, SAMPLE_ACCURACY);
    let from = match first {
        Start::Knot(k) => table.segment_start(k),
        Start::At(k, t) => table.segment_start(k) + crate::arclen::segment_len(&table.segment(k).subsegment(0.0..t), SAMPLE_ACCURACY),
    };
    let (k, t) = table.locate(from + table.total() / 2.0);
    let m = c.knots().len();
    let second = if t < AT_KNOT { Start::Knot(k) } else if t > 1.0 - AT_KNOT { Start::Knot((k + 1) % m) } else { Start::At(k, t) };
    [at(first), at(second)]
}

/// Whether an answer is worth solving again from the second start ([`restarts`]): it misses
/// its promise (stretched, through itself or unsettled; a creased or converged answer keeps its
/// flat lengths), and either by little, no edge strained beyond `near`, or through itself
/// ([`faces_cross`]) and strained by at most `crossing_below`. Another start is another mesh of
/// the pieces, and so another draw of the thin sheet's equilibria ([`super::sheet::level`]).
/// The caller passes the sheet path's own bounds: `near`, its `FAR_ABOVE` times the strain
/// target (beyond it an answer is far off and has been followed again on other paths already,
/// `sheet::retry`); `crossing_below`, its `TOUCH_BELOW` (a sheet strained by tens of percent
/// is crumpled, and another mesh of the same path does not unfold it). An answer stretched by
/// percents without crossing is left as it is: the kidney with its copy at 13/16, 3.3e-2
/// strained, took 7.3 s in WASM with a second start that ended through itself, instead of 2.2.
pub fn retry(sim: &Simulation, near: f64, crossing_below: f64) -> bool {
    let missed = matches!(sim.stats.shortfall, Some(Shortfall::Stretch | Shortfall::Crossing | Shortfall::Unsettled));
    let strain = sim.stats.max_strain;
    missed && (strain <= near || (strain <= crossing_below && faces_cross(&sim.vertices, &sim.triangles)))
}

/// The better of two answers of one pair from two starts, as the sheet path grades its own
/// attempts ([`super::sheet::retry::Attempt::grade`]): converged; isometric and uncrossed
/// (creased, or held by its samples); uncrossed but stretched; through itself (read from the
/// mesh, [`faces_cross`]: a stretched answer's shortfall says only that it stretches); within
/// the last two the lesser strain. `first` when they tie. Its `iterations` count both solves'.
pub fn better(first: Simulation, second: Simulation) -> Simulation {
    let grade = |s: &Simulation| match s.stats.shortfall {
        None => (0, 0.0),
        Some(Shortfall::Fold | Shortfall::Sampling) => (1, 0.0),
        _ if faces_cross(&s.vertices, &s.triangles) => (3, s.stats.max_strain),
        _ => (2, s.stats.max_strain),
    };
    let steps = first.stats.iterations + second.stats.iterations;
    let mut out = if grade(&second) < grade(&first) { second } else { first };
    out.stats.iterations = steps;
    out
}

/// Turns `sim.seam` to start at the seam vertex whose corner on A is nearest `at` (A's drawn
/// first anchor, in the coordinates of `sim.flat`): the seam still starts where the drawing does
/// when it was solved from another start ([`restart`], [`round::Turn::turn`]).
pub fn start_seam_at(sim: &mut Simulation, at: Point) {
    let mut on_a: Vec<Option<[f64; 2]>> = vec![None; sim.vertices.len()];
    for ((t, corners), &p) in sim.triangles.iter().zip(&sim.flat).zip(&sim.piece) {
        if p == 0 {
            for (&v, &q) in t.iter().zip(corners) {
                on_a[v] = Some(q);
            }
        }
    }
    let d = |v: usize| on_a[v].map_or(f64::INFINITY, |q| (q[0] - at.x).hypot_m(q[1] - at.y));
    let first = (0..sim.seam.len()).fold(0, |best, k| if d(sim.seam[k]) < d(sim.seam[best]) { k } else { best });
    sim.seam.rotate_left(first);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::Knot;
    use std::f64::consts::TAU;

    /// A smooth closed outline through `r(θ)` at `m` equal steps of θ from 0 (Catmull–Rom
    /// handles), first anchor at θ = 0.
    fn polar(m: usize, r: impl Fn(f64) -> f64) -> Contour {
        let p: Vec<Point> = (0..m).map(|k| k as f64 * TAU / m as f64).map(|t| Point::new(r(t) * t.cos_m(), r(t) * t.sin_m())).collect();
        let knots = (0..m).map(|i| {
            let (a, prev, next) = (p[i], p[(i + m - 1) % m], p[(i + 1) % m]);
            let t = (next - prev) / 6.0;
            Knot { anchor: a, left: a - t, right: a + t }
        }).collect();
        Contour::new(knots, 0).unwrap()
    }

    /// The anchor the start is at (a knot's, or the middle of its segment).
    fn point(c: &Contour, s: Start) -> Point {
        match s {
            Start::Knot(k) => c.knots()[k].anchor,
            Start::At(k, t) => c.segment(k).eval(t),
        }
    }

    /// A `w` × `h` rectangle at the origin with corners rounded by `r` (one cubic per arc),
    /// counter-clockwise, first anchor where the bottom side meets the arc at the origin.
    fn rounded_rect(w: f64, h: f64, r: f64) -> Contour {
        let k = 4.0 / 3.0 * (TAU / 16.0).tan_m() * r;
        // Each corner: the tangent point coming in, then the one going out, with the arc's
        // handles along the sides.
        let corners = [((w - r, 0.0), (1.0, 0.0), (w, r), (0.0, 1.0)), ((w, h - r), (0.0, 1.0), (w - r, h), (-1.0, 0.0)), ((r, h), (-1.0, 0.0), (0.0, h - r), (0.0, -1.0)), ((0.0, r), (0.0, -1.0), (r, 0.0), (1.0, 0.0))];
        let mut knots = Vec::new();
        for (a, u, b, v) in corners {
            let (a, b) = (Point::new(a.0, a.1), Point::new(b.0, b.1));
            knots.push(Knot { anchor: a, left: a, right: Point::new(a.x + k * u.0, a.y + k * u.1) });
            knots.push(Knot { anchor: b, left: Point::new(b.x - k * v.0, b.y - k * v.1), right: b });
        }
        let last = knots.pop().unwrap();
        knots.insert(0, last);
        Contour::new(knots, 0).unwrap()
    }

    /// Started at any of its knots, an outline starts its seam at one point: the kidney (no
    /// symmetry) at its anchor farthest from the anchors' mean; a 1:2 ellipse with a dent
    /// (symmetric about the x axis) on that axis at its far end (−30, 0); the five lobes
    /// r = 55(1 + 0.12 sin 5θ) at a lobe's tip (sin 5θ = 1, on a mirror axis); an 80 × 50
    /// rectangle with rounded corners (axes through the middles of its sides, no knot on them)
    /// at the middle of a short side, (0, 25) or (80, 25).
    #[test]
    fn every_first_knot_gives_one_start_on_a_mirror_axis_where_there_is_one() {
        let kidney = polar(72, |t| 60.0 * (1.0 + 0.35 * (2.0 * t).cos_m() - 0.25 * t.cos_m() + 0.2 * (3.0 * t).sin_m()));
        let lobes = polar(80, |t| 55.0 * (1.0 + 0.12 * (5.0 * t).sin_m()));
        let dented = polar(96, |t| {
            let r = 1.0 / ((t.cos_m() / 30.0).powi(2) + (t.sin_m() / 60.0).powi(2)).sqrt();
            let d = if t > std::f64::consts::PI { t - TAU } else { t };
            r - 0.005 * 120.0 * (-(d / 0.25).powi(2)).exp_m()
        });
        let mean = |c: &Contour| {
            let m = c.knots().len() as f64;
            c.knots().iter().fold(Point::ZERO, |s, k| s + k.anchor.to_vec2() / m)
        };
        let farthest = |c: &Contour| {
            let o = mean(c);
            c.knots().iter().map(|k| k.anchor).fold(o, |best, p| if p.distance(o) > best.distance(o) { p } else { best })
        };
        let close = |p: Point, q: Point| p.distance(q) <= 1e-9;
        let cases: [(&str, Contour, Box<dyn Fn(Point) -> bool>); 4] = [
            ("kidney", kidney.clone(), Box::new(move |p| close(p, farthest(&kidney)))),
            ("dented ellipse", dented, Box::new(|p| close(p, Point::new(-30.0, 0.0)))),
            ("five lobes", lobes, Box::new(|p| ((5.0 * p.y.atan2_m(p.x)).sin_m() - 1.0).abs() < 1e-12)),
            ("rounded rectangle", rounded_rect(80.0, 50.0, 10.0), Box::new(|p| close(p, Point::new(0.0, 25.0)) || close(p, Point::new(80.0, 25.0)))),
        ];
        for (what, c, wanted) in cases {
            for first in 0..c.knots().len() {
                let d = c.started_at(first);
                let s = canonical_start(&d);
                let got = point(&d, s);
                assert!(wanted(got), "{what} started at knot {first}: the seam starts at {got:?} ({s:?})");
            }
        }
    }
}
