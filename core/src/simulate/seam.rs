//! The two pieces sampled at the seam: `N` points at equal arc-length steps, A walked
//! counter-clockwise from its first anchor, B walked clockwise from its first anchor + `offset`
//! (the `start` convention of `connect`). B is then mirrored (x → −x), an isometry of the plane,
//! so that both sample polygons run counter-clockwise: vertex k of A and vertex k of B are the
//! same seam vertex.
//!
//! Corners (a turn of the tangent at an anchor, of either piece) are seam vertices: the nearest
//! sample moves onto each one. A seam edge straddling a corner would cut it on that piece only,
//! so its two flat lengths (the chords of A and B) would differ by `O(h·θ²)` for a turn θ instead
//! of `O(h³κ²)`: a rectangle's corner sampled between vertices gives ~10 % strain that no
//! realization can remove. So are kinks, turns too tight for the seam's steps at smooth anchors
//! or inside a segment ([`super::kink`]): each piece is walked along the seam by arc length with
//! its kinks taken as corners ([`Walk`]), which moves the gluing by at most
//! [`super::kink::KINK_SHIFT`] of the perimeter per kink, and by nothing on a piece without.

use crate::libm_ext::LibmExt;
use crate::arclen::{unit_tangent, ArcTable};
use crate::contour::Contour;
use crate::error::{Error, Result};
use crate::validate;
use super::density::{Density, KINK_WINDOW, REFERENCE};
use super::kink::{kinks_within, Limits, Walk};
use super::metric::KeyMap;
use std::cell::RefCell;

/// Relative accuracy of the arc lengths used to place seam samples: far below any visible or
/// measurable effect (the seam gap target is 1e-4 of the perimeter) and cheap to invert.
pub const SAMPLE_ACCURACY: f64 = 1e-11;

/// Largest relative perimeter difference that can be stitched (the same rule as `connect`).
pub const PERIMETER_TOLERANCE: f64 = 1e-6;

/// Smallest turn of the tangent at an anchor (radians) that makes it a corner the seam samples
/// are placed on: below it the two chords of a straddling seam edge differ by < 1e-4·h.
pub const CORNER_TURN: f64 = 0.02;

/// Coarsest level of the multilevel start: below this the seam chords of A and B differ too
/// much for the polyhedral metric to mean anything.
pub const COARSEST: usize = 32;

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

impl FlatPiece {
    /// A piece on the samples `pts` whose seam stretches between samples are straight (a polygon
    /// pair's sides, or samples placed on a straight stretch): each `arc_mid` is the midpoint of
    /// its chord. `area` and `perimeter` are the true outline's.
    pub fn on_chords(pts: Vec<[f64; 2]>, area: f64, perimeter: f64) -> FlatPiece {
        let q = pts.len();
        let arc_mid = (0..q).map(|m| [0.5 * (pts[m][0] + pts[(m + 1) % q][0]), 0.5 * (pts[m][1] + pts[(m + 1) % q][1])]).collect();
        FlatPiece { pts, arc_mid, area, perimeter }
    }
}

/// Both pieces, with the same number of samples.
#[derive(Debug, Clone)]
pub struct SeamPieces {
    pub n: usize,
    pub flat: [FlatPiece; 2],
}

impl SeamPieces {
    /// Every `stride`-th sample (`stride` divides `n`): the sample polygons of a coarser level
    /// with the same first vertex. Each coarse edge's arc midpoint is the sample halfway along
    /// it (its own midpoint when `stride` is 1). Areas and perimeters are the outlines'.
    pub fn every(&self, stride: usize) -> SeamPieces {
        let m = self.n / stride;
        let flat = [0, 1].map(|p| {
            let f = &self.flat[p];
            let pts: Vec<[f64; 2]> = (0..m).map(|k| f.pts[k * stride]).collect();
            let arc_mid = (0..m).map(|k| if stride == 1 { f.arc_mid[k] } else { f.pts[k * stride + stride / 2] }).collect();
            FlatPiece { pts, arc_mid, area: f.area, perimeter: f.perimeter }
        });
        SeamPieces { n: m, flat }
    }
}

/// The two outlines oriented for gluing, measured once and sampled at any resolution.
#[derive(Debug, Clone)]
pub struct Glue {
    ta: ArcTable,
    tb: ArcTable,
    area: [f64; 2],
    /// Seam positions (arc length along A's walk, in `[0, L)`) of both pieces' corners, sorted.
    corners: Vec<f64>,
    /// The curvature-graded spacing ([`Density`]), `None` where the even step serves.
    density: Option<Density>,
    /// Each piece walked along the seam, its kinks taken as corners ([`Walk`]).
    walk: [Walk; 2],
    /// The limits its kinks were found within, and their number on both pieces.
    limits: Limits,
    kinks: usize,
    /// The points sampled so far, shared by every call of [`Glue::sample`] and
    /// [`Glue::sample_levels`] (see [`Glue::sample_cached`]).
    points: RefCell<[(KeyMap, Vec<[f64; 2]>); 2]>,
}

impl Glue {
    /// Checks both outlines and their perimeters (the 1e-6 rule of `connect`).
    pub fn new(a: &Contour, b: &Contour, offset: f64) -> Result<Self> {
        Self::with_kinks(a, b, offset, Limits::EXACT)
    }

    /// [`Glue::new`] with the tight turns within `limits` taken as kinks ([`super::kink`]).
    pub fn with_kinks(a: &Contour, b: &Contour, offset: f64, limits: Limits) -> Result<Self> {
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
        // B's arc lengths run over its own perimeter, which may differ from A's by the tolerance
        // (each walk is scaled to A's).
        let anchors = [anchor_corners(&ta), anchor_corners(&tb)];
        let kinks = [kinks_within(&ta, &anchors[0], limits), kinks_within(&tb, &anchors[1], limits)];
        // The seam starts at A's first anchor, or at a kink whose window (its tight stretch and
        // what the density leaves out beside it) holds that anchor: a sample there would cut
        // the kink's turn, and the samples nested between it and the kink would all lie in it
        // (a rectangle whose corners are rounded at 0.05 mm and whose first anchor starts a
        // corner had seam edges of 0.009 mm across that corner, 18 % apart on A and B).
        // The offset is periodic: taken as given, 1e12 mm and more lost B's samples to round-off
        // (a circle with its copy came back crossing, then stretched, and from 1e16 "too thin or
        // too detailed for 32 seam vertices").
        let offset = offset.rem_euclid(pb);
        let starts = [0.0, offset];
        let window = KINK_WINDOW * pa / REFERENCE;
        let origin = (0..2)
            .flat_map(|p| kinks[p].iter().map(move |k| (p, k)))
            .find_map(|(p, k)| {
                // In seam positions (B's arc lengths run over its own perimeter), any turn round.
                let scale = if p == 0 { 1.0 } else { pa / pb };
                let (from, to, at) = ((k.from - starts[p]) * scale - window, (k.to - starts[p]) * scale + window, (k.at - starts[p]) * scale);
                [-pa, 0.0, pa].into_iter().find(|&w| from + w <= 0.0 && to + w >= 0.0).map(|w| at + w)
            })
            .unwrap_or(0.0);
        let starts = [origin, offset + origin * (pb / pa)];
        let walk = [Walk::new(&ta, starts[0], pa, &kinks[0]), Walk::new(&tb, starts[1], pa, &kinks[1])];
        let mut corners: Vec<f64> = Vec::new();
        for (p, t) in [&ta, &tb].into_iter().enumerate() {
            corners.extend(anchors[p].iter().map(|&x| walk[p].seam_of(t, x)).chain(walk[p].kink_positions()).map(|s| ta.wrap(s)));
        }
        crate::order::sort_f64(&mut corners);
        let density = Density::new(&ta, &tb, starts, [&kinks[0], &kinks[1]]);
        let kinks = kinks[0].len() + kinks[1].len();
        Ok(Glue { ta, tb, area: [a.signed_area().abs(), b.signed_area().abs()], corners, density, walk, limits, kinks, points: Default::default() })
    }

    /// The limits within which the seam takes tight turns as kinks ([`Glue::with_kinks`]).
    pub fn limits(&self) -> Limits {
        self.limits
    }

    /// How many turns of the two pieces the seam takes as kinks.
    pub fn kinks(&self) -> usize {
        self.kinks
    }

    /// Seam positions of `n` samples: equal steps `h = L/n` from 0, with the nearest free sample
    /// moved onto each corner (see the module docs), or failing that a free neighbour. A sample
    /// moves by at most one step and the positions stay strictly increasing; sample 0 stays at
    /// the seam's start (A's first anchor, or a kink beside it: see [`Glue::new`]). A corner
    /// with no free sample near it (several corners within one step) keeps the step.
    ///
    /// Nested: for even `n` with `n/2` a level of the ladder ([`Glue::nests`]), the samples are those
    /// of `n/2` and the midpoints between them, so a corner is sample `2m` when it is sample `m`
    /// one level down (samples then move by up to a step of the coarsest such level). The
    /// solver's coarse-to-fine ladder needs this: when a corner fell on sample 2m + 1 at the finer
    /// level (its own nearest), the coarse solution laid the corner's position onto a sample of a
    /// straight side, whose chords cannot flip away from the resulting dent (their quads have
    /// three collinear samples): a 57×43 rectangle with a circle converged at 128 seam vertices
    /// and ended dented at 256.
    pub fn positions(&self, n: usize) -> Vec<f64> {
        if n % 2 == 0 && self.nests(n / 2) {
            // Nested (see the docs above): the coarser level's samples and their midpoints.
            let total = self.ta.total();
            let c = self.positions(n / 2);
            let next = |m: usize| if m + 1 < c.len() { c[m + 1] } else { total };
            let mid = |a: f64, b: f64| match &self.density {
                None => 0.5 * (a + b),
                Some(d) => d.inverse(0.5 * (d.forward(a) + d.forward(b))),
            };
            let mut u: Vec<f64> = (0..n).map(|k| if k % 2 == 0 { c[k / 2] } else { mid(c[k / 2], next(k / 2)) }).collect();
            // A corner the coarser level had no free sample for (several corners within one of
            // its steps) takes the new midpoint sample of its interval, if still free: every
            // corner becomes a seam vertex once the level is fine enough, as without nesting.
            let same = 1e-3 * total / n as f64;
            let mut taken = vec![false; n];
            for &corner in &self.corners {
                let m = c.partition_point(|&x| x <= corner).saturating_sub(1);
                let (lo, hi) = (c[m], next(m));
                if corner - lo <= same || hi - corner <= same || taken[2 * m + 1] {
                    continue;
                }
                u[2 * m + 1] = corner;
                taken[2 * m + 1] = true;
            }
            return u;
        }
        let total = self.ta.total();
        let h = total / n as f64;
        // Even steps of F (the arc length itself where no density is needed, bit for bit).
        let (f, step) = match &self.density {
            None => (None, h),
            Some(d) => (Some(d), d.weight() / n as f64),
        };
        let at = |x: f64| f.map_or(x, |d| d.inverse(x));
        let of = |s: f64| f.map_or(s, |d| d.forward(s));
        let mut u: Vec<f64> = (0..n).map(|k| at(k as f64 * step)).collect();
        let mut snapped = vec![false; n];
        snapped[0] = true;
        // Both pieces' corners at one seam point (a square's corner glued to a rectangle's) come
        // out apart by round-off and by the perimeters' difference (up to 1e-6 relative): the
        // same corner, which must not take two samples and leave a seam edge of almost nothing.
        let same = 1e-3 * h;
        for &c in &self.corners {
            if (0..n).any(|k| snapped[k] && (u[k] - c).abs() <= same) || total - c <= same {
                continue;
            }
            let near = (of(c) / step).round() as usize;
            for k in [near, near + 1, near.wrapping_sub(1)] {
                if k == 0 || k >= n || snapped[k] {
                    continue;
                }
                let before = u[k - 1];
                let after = if k + 1 < n { u[k + 1] } else { total };
                if c - before > same && after - c > same && (of(c) - k as f64 * step).abs() <= step {
                    u[k] = c;
                    snapped[k] = true;
                    break;
                }
            }
        }
        u
    }

    /// Whether `m` seam samples can be a level of the coarse-to-fine ladder, and so the coarser
    /// half of a nested sampling ([`Glue::positions`]): at least the solver's coarsest level, and
    /// at least 3/2 samples per distinct corner.
    ///
    /// A level with fewer samples than that cannot give every corner its own sample at an even
    /// spacing. Outlines flattened into polylines (CAD and laser-cutter SVGs, Inkscape's
    /// "Flatten Beziers") have dozens of corners of small turn; with 72 of them on 32 samples,
    /// each snapped corner moved its sample by up to a step, and the next level's midpoints (or
    /// the corners left over, on the midpoint of their interval) made seam edges from almost
    /// nothing to two steps long. The ladder from such a level ended in a wrong branch (a
    /// 72-point polyline ellipse with a circle: strain 0.27 from 64 seam vertices up, while a
    /// single level of 48 or 64, corners snapped to their nearest sample, converged in 17–44
    /// steps). So the ladder starts at the first level with room for the corners, which snaps
    /// them at nearly even steps, and the finer levels nest on it as before. The room of 3/2,
    /// measured: at one sample per corner a 64-gon with a circle still started at 64 with 64
    /// corners (up to 2.5 times slower, and a 24-gon at 32 with 24 ended at strain 3e-3 as before);
    /// at two the 72-point ellipse had to start at 256 and ran out of steps there; at 3/2 it
    /// starts at 128 and converges at 128 and 256. Outlines with at most 21 corners (every
    /// polygon test and the bench) keep the ladder from 32, unchanged.
    pub fn nests(&self, m: usize) -> bool {
        // Both pieces' corners at one seam point take one sample (see `positions`).
        let same = 1e-3 * self.ta.total() / m as f64;
        let distinct = self.corners.iter().enumerate().filter(|&(i, &c)| i == 0 || c - self.corners[i - 1] > same).count();
        m >= COARSEST && 2 * m >= 3 * distinct
    }

    pub fn perimeter(&self) -> f64 {
        self.ta.total()
    }

    /// Both pieces sampled at `n` seam vertices ([`Glue::positions`]).
    pub fn sample(&self, n: usize) -> SeamPieces {
        self.sample_cached(n, &mut self.points.borrow_mut())
    }

    /// [`Glue::sample`] at each of `ns`, the same values. Every seam point is computed once per
    /// glue, whichever call asks for it first: the levels of the coarse-to-fine ladder nest
    /// ([`Glue::positions`]): a level's samples are every other sample of the next, and its arc
    /// midpoints that level's odd samples, the same arc lengths bit for bit. Inverting the arc
    /// length is the costly part (kurbo's `inv_arclen`; the four levels 32…256 were 13 % of a
    /// cold solve), and the ladder then needs the finest level's points only; the convexity test
    /// of `simulate` samples the finest level before the ladder does, at no extra cost.
    pub fn sample_levels(&self, ns: &[usize]) -> Vec<SeamPieces> {
        ns.iter().map(|&n| self.sample(n)).collect()
    }

    /// [`Glue::sample`] with the points already computed, per piece, keyed by the bits of their
    /// seam arc length ([`KeyMap`], the map type of the triangulations, so the .wasm
    /// holds one instantiation) into a list of points.
    fn sample_cached(&self, n: usize, cache: &mut [(KeyMap, Vec<[f64; 2]>); 2]) -> SeamPieces {
        let u = self.positions(n);
        let total = self.ta.total();
        let sample = |t: &ArcTable, walk: &Walk, mirror: f64, (index, points): &mut (KeyMap, Vec<[f64; 2]>)| -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
            let mut at = |s: f64| {
                let m = *index.entry(s.to_bits()).or_insert_with(|| {
                    let p = t.point_at(walk.arc(s));
                    points.push([mirror * p.x, p.y]);
                    points.len() - 1
                });
                points[m]
            };
            let pts = u.iter().map(|&s| at(s)).collect();
            let mid = (0..n).map(|i| at(0.5 * (u[i] + if i + 1 < n { u[i + 1] } else { total }))).collect();
            (pts, mid)
        };
        let [ca, cb] = cache;
        let (pts_a, mid_a) = sample(&self.ta, &self.walk[0], 1.0, ca);
        let (pts_b, mid_b) = sample(&self.tb, &self.walk[1], -1.0, cb);
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
        (a[0] - b[0]).hypot_m(a[1] - b[1])
    }
}

/// Arc lengths (from knot 0) of the anchors where the tangent turns by more than
/// [`CORNER_TURN`]; zero-length segments are looked through.
fn anchor_corners(t: &ArcTable) -> Vec<f64> {
    let n = t.segment_count();
    let live: Vec<usize> = (0..n).filter(|&i| t.segment_start(i + 1) > t.segment_start(i)).collect();
    let mut out = Vec::new();
    for (j, &i) in live.iter().enumerate() {
        let prev = live[(j + live.len() - 1) % live.len()];
        let (a, b) = (unit_tangent(t.segment(prev), 1.0), unit_tangent(t.segment(i), 0.0));
        if a.cross(b).atan2_m(a.dot(b)).abs() > CORNER_TURN {
            out.push(t.segment_start(i));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::Knot;
    use kurbo::Point;

    /// A circle of perimeter `p` as 16 cubic arcs (no corners), counter-clockwise.
    fn circle(p: f64) -> Contour {
        let r = p / std::f64::consts::TAU;
        let th = std::f64::consts::TAU / 16.0;
        let k = 4.0 / 3.0 * (th / 4.0).tan_m() * r;
        let knots = (0..16)
            .map(|i| {
                let (s, c) = (th * i as f64).sin_cos_m();
                let a = Point::new(r * c, r * s);
                Knot { anchor: a, left: Point::new(a.x + k * s, a.y - k * c), right: Point::new(a.x - k * s, a.y + k * c) }
            })
            .collect();
        Contour::new(knots, 1).unwrap()
    }

    fn rectangle(w: f64, h: f64) -> Contour {
        let pts = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)];
        Contour::new(pts.iter().map(|&(x, y)| Knot::corner(Point::new(x, y))).collect(), 0).unwrap()
    }

    #[test]
    fn corners_are_seam_vertices_and_smooth_pieces_keep_equal_steps() {
        // Rectangle 80 × 20 (corners at arc lengths 0, 80, 100, 180 of 200) with a circle.
        let rect = rectangle(80.0, 20.0);
        let disc = circle(200.0);
        // The perimeters equal to far better than the 1e-6 rule.
        let rescaled = disc.transformed(kurbo::Affine::scale(200.0 / ArcTable::new(&disc, 1e-13).total()));
        for n in [32, 37, 64, 100] {
            let glue = Glue::new(&rect, &rescaled, 0.0).unwrap();
            let u = glue.positions(n);
            let h = 200.0 / n as f64;
            assert_eq!(u.len(), n);
            assert!(u.windows(2).all(|w| w[0] < w[1]) && u[n - 1] < 200.0, "n = {n}: positions not increasing: {u:?}");
            for c in [0.0, 80.0, 100.0, 180.0] {
                assert!(u.iter().any(|&x| (x - c).abs() < 1e-9), "n = {n}: corner at {c} is not a seam vertex: {u:?}");
            }
            for (k, &x) in u.iter().enumerate() {
                assert!((x - k as f64 * h).abs() <= h, "n = {n}: sample {k} moved from {} to {x}", k as f64 * h);
            }
            // The circle alone (glued to itself) has no corners: exactly equal steps.
            let g = Glue::new(&rescaled, &rescaled, 17.0).unwrap();
            let step = g.perimeter() / n as f64;
            let smooth = g.positions(n);
            // Nested levels take midpoints, equal to k·step up to round-off.
            assert!(smooth.iter().enumerate().all(|(k, &x)| (x - k as f64 * step).abs() <= 1e-12 * g.perimeter()), "n = {n}: a smooth gluing moved samples");
        }
    }

    /// Regression (nested levels): a 48-gon has more corners than the coarsest level has samples;
    /// the corners left over there must still become seam vertices at the finer levels.
    #[test]
    fn corners_beyond_the_coarsest_level_become_seam_vertices_at_finer_levels() {
        let m = 48;
        let r = 100.0 / (2.0 * m as f64 * (std::f64::consts::PI / m as f64).sin_m());
        let poly = Contour::new(
            (0..m).map(|i| Knot::corner(Point::new(r * (std::f64::consts::TAU * i as f64 / m as f64).cos_m(), r * (std::f64::consts::TAU * i as f64 / m as f64).sin_m()))).collect(),
            0,
        )
        .unwrap();
        let disc = circle(100.0);
        let disc = disc.transformed(kurbo::Affine::scale(100.0 / ArcTable::new(&disc, 1e-13).total()));
        let glue = Glue::new(&poly, &disc, 0.0).unwrap();
        let step = 100.0 / m as f64;
        for n in [128, 256] {
            let u = glue.positions(n);
            assert!(u.windows(2).all(|w| w[0] < w[1]) && u[n - 1] < glue.perimeter(), "n = {n}: positions not increasing");
            for i in 0..m {
                let c = i as f64 * step;
                assert!(u.iter().any(|&x| (x - c).abs() < 1e-9), "n = {n}: corner {i} at {c} is not a seam vertex");
            }
        }
    }

    /// Regression (Inkscape's 3D export at 16 seam vertices): a 40 × 20 rectangle, turned by 10°,
    /// glued to a 30 × 30 square meets it corner to corner at a quarter of the seam; the two
    /// corners came out 1e-14 apart, took two samples, and the zero-length seam edge made the
    /// sample polygon impossible to triangulate.
    #[test]
    fn coinciding_corners_of_both_pieces_take_one_sample() {
        let corners = |pts: &[(f64, f64)], piece| Contour::new(pts.iter().map(|&(x, y)| Knot::corner(Point::new(x, y))).collect(), piece).unwrap();
        let rect = corners(&[(0.0, 0.0), (40.0, 0.0), (40.0, 20.0), (0.0, 20.0)], 0)
            .transformed(kurbo::Affine::rotate(10f64.to_radians()).then_translate(kurbo::Vec2::new(22.04, 36.68)));
        let square = corners(&[(110.0, 30.0), (110.0, 60.0), (140.0, 60.0), (140.0, 30.0)], 1);
        // Also with the square's perimeter 5e-7 longer, as the stitching tolerance allows.
        let longer = square.transformed(kurbo::Affine::scale(1.0 + 5e-7));
        for (glue, n) in [&square, &longer].into_iter().flat_map(|b| [16, 24, 32].map(|n| (Glue::new(&rect, b, 0.0).unwrap(), n))) {
            let u = glue.positions(n);
            let h = glue.perimeter() / n as f64;
            let gap = (0..n).map(|k| if k + 1 < n { u[k + 1] - u[k] } else { glue.perimeter() - u[k] }).fold(f64::INFINITY, f64::min);
            assert!(gap > 0.1 * h, "n = {n}: two samples {gap} apart: {u:?}");
            let pieces = glue.sample(n);
            for p in 0..2 {
                assert!(crate::simulate::metric::ear_clip(&pieces.flat[p].pts).is_some(), "n = {n}: piece {p} cannot be triangulated");
            }
        }
    }
}
