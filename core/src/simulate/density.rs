//! Seam spacing graded by curvature: where either piece bends tightly, seam samples come closer.
//!
//! A seam edge is one mesh edge with two flat lengths, A's chord and B's chord of the same arc of
//! length `h`; they differ by `h³(κ_A² − κ_B²)/24` (a chord of an arc of curvature `κ` is
//! `h − h³κ²/24 + O(h⁵)`), so no realization of the polyhedron has a relative edge strain below
//! about `(hκ)²/48` on that edge. At equal steps a 60×40 rectangle with 2 mm rounded corners,
//! glued to a circle at 256 seam vertices, ended "converged" with 3.1e-3 strain on its corner
//! edges, and with 1 mm corners not at all (strain 0.12); the issue's kidney, heart and rounded
//! star cannot get below 3.4e-3, 0.85 and 3.4e-2 there.
//!
//! So the samples are spaced evenly in `F(s) = ∫₀ˢ w`, with the weight
//! `w = clamp(κ·L / K, 1, W_MAX)`, `κ = √|κ_A² − κ_B²|` (both pieces' curvatures at seam point
//! `s`, `L` the perimeter): the step is `W̄·L/(n·w)`, `W̄ = F(L)/L` the mean weight, so the
//! even one times `W̄` wherever `κL ≤ K` (a 2:1 ellipse has `κL ≤ 19.4` against anything, a
//! circle 2π; congruent pieces glued edge to edge have `κ = 0`), shrinking in proportion to
//! `1/κ` beyond, to `hκ = W̄·K/n`. The floor `(hκ)²/48` is so `W̄²` times `(K/n)²/48`. `W̄` is
//! 1 where no stretch is tight and near 1 where few are; where tight turns take much of the
//! seam, the `n` samples they draw lengthen every other step: the rounded star with a circle has
//! `W̄ ≈ 2.4`, steps of 0.25–4.1 mm against an even 1.73 at 256 seam vertices, and a floor of
//! 1.06e-3 (5.8 times 1.8e-4; 4.2e-3 at 128, 2.6e-4 at 512). `w` is graded (its
//! logarithm changes by at most [`GRADING`] per local seam step at 256 samples) so neighbouring
//! seam edges never differ abruptly. The weight does not depend on `n`, so every level of the
//! solver's ladder samples the same `F` and the levels nest. A pair whose weight is 1 everywhere
//! gets no table at all, and its samples are the even steps bit for bit.

use crate::libm_ext::LibmExt;
use crate::arclen::ArcTable;
use kurbo::ParamCurveCurvature;

/// `κL` up to which the seam step stays the even one (times the mean weight, see the module
/// docs): at 256 seam vertices the chords of A and B then differ by at most
/// `(K/256)²/24 ≈ 3.7e-4` relative, times the mean weight squared.
pub const K: f64 = 24.0;

/// Largest weight: a step at most this many times shorter than the even one (a cusp, whose
/// curvature is unbounded, gets this much and no more). A corner rounded at radius `r` on a
/// seam of length `L` needs `w ≈ 6.5·L/(n·r)` for its chords to differ by under 1e-3 (the floor
/// `(hκ)²/24` of a step `h = L/(n·w)`, `κ = 1/r`). At 16, 60 × 40 rectangles with corners rounded
/// below 0.3 mm, glued to a circle at 256 seam vertices, were 1.8e-3 (r 0.2) to 2.6e-2 (r 0.05)
/// off, or ended 10–180 % stretched; at 64 they converge from 0.08 mm up, and from 0.03 mm to
/// 0.07 mm end within 5e-3 ("sampling"). The weight table's bins (`L/4096`) hold such a corner's
/// few bins at the full weight, and the grading keeps the steps beside it gradual. Curvature
/// that high is rare enough that the rest of the seam keeps its steps: of the survey's 768
/// convex gluings 708 converge at 64, 707 at 16.
pub const W_MAX: f64 = 64.0;

/// Largest change of `ln w` per local seam step (at [`REFERENCE`] samples).
pub const GRADING: f64 = 0.5;

/// The resolution the grading is measured at (the default resolution).
pub const REFERENCE: f64 = 256.0;

/// How far beyond a kink's tight stretch ([`super::kink`]) its curvature is left out of the
/// weight, in even seam steps at [`REFERENCE`] samples: the seam takes a kink as a corner, and
/// beside a corner the steps are the even ones. A drawn smooth cusp is rounded beyond its
/// tight stretch: the heart of the tests has a 2 µm turn at its tip inside 0.45 mm either side
/// at 0.45–0.55 /mm. Graded for that rounding (left out only within half the stretch's length
/// beyond it) the seam edges beside its 342° reflex dip were 0.08 mm long, and the thick
/// homotopy from its convex twins blew up to 1,500 % strain at 128 and 256 seam vertices. Left
/// out within half a step, one of the four (two first anchors, 128 and 256) still ended
/// through itself; within one step, none.
pub const KINK_WINDOW: f64 = 1.0;

/// Bins of the weight table over the perimeter.
const BINS: usize = 4096;

/// Curvature samples per cubic segment.
const PER_SEGMENT: usize = 48;

/// The cumulative weight `F` of a seam, as a table over `BINS` equal bins of arc length.
#[derive(Debug, Clone)]
pub struct Density {
    total: f64,
    /// `cum[b]` is `F` at the start of bin `b`; `cum[BINS]` is `W = F(L)`.
    cum: Vec<f64>,
}

impl Density {
    /// The density of the seam of `ta` (A's arc length `starts[0] + s` at seam position `s`) and
    /// `tb` (B's, `starts[1] + k·s`), or `None` when the weight is 1 everywhere.
    ///
    /// `kinks` are each piece's kinks (arc lengths along its own outline, see
    /// [`super::kink::kinks`]): the seam has a vertex on each, and the curvature within
    /// [`KINK_WINDOW`] even steps of one is left out, so the seam edges beside a kink are not
    /// shortened by it.
    pub fn new(ta: &ArcTable, tb: &ArcTable, starts: [f64; 2], kinks: [&[super::kink::Kink]; 2]) -> Option<Density> {
        let total = ta.total();
        if !(total > 0.0) {
            return None;
        }
        let bin = total / BINS as f64;
        // Each piece's largest curvature in each bin: of the curvature linear between the
        // samples along each segment, over the part of the bin each stretch between two samples
        // covers ([`spread`]).
        let mut kappa_in = [vec![0.0f64; BINS], vec![0.0f64; BINS]];
        let k = tb.total() / total;
        for (p, (table, map)) in [(ta, (starts[0], 1.0)), (tb, (starts[1], k))].into_iter().enumerate() {
            let margin = KINK_WINDOW * table.total() / REFERENCE;
            let near_kink = |sigma: f64| kinks[p].iter().any(|c| {
                (sigma - (c.from - margin)).rem_euclid(table.total()) <= c.to - c.from + 2.0 * margin
            });
            for i in 0..table.segment_count() {
                let seg = table.segment(i);
                let (s0, s1) = (table.segment_start(i), table.segment_start(i + 1));
                let mut last = None;
                for m in 0..=PER_SEGMENT {
                    let t = m as f64 / PER_SEGMENT as f64;
                    let kappa = seg.curvature(t).abs();
                    // Arc length along the segment, near enough for a weight: linear in t.
                    let sigma = s0 + t * (s1 - s0);
                    if !kappa.is_finite() || near_kink(sigma) {
                        last = None;
                        continue;
                    }
                    let s = ta.wrap((sigma - map.0) / map.1);
                    spread(&mut kappa_in[p], total, last.unwrap_or((s, kappa)), (s, kappa));
                    last = Some((s, kappa));
                }
            }
        }
        // The chords differ by the difference of the squared curvatures: congruent pieces glued
        // edge to edge (the flat doubly covered D-form) need no finer steps anywhere.
        let mut w: Vec<f64> = (0..BINS)
            .map(|b| ((kappa_in[0][b].powi(2) - kappa_in[1][b].powi(2)).abs().sqrt() * total / K).clamp(1.0, W_MAX))
            .collect();
        if w.iter().all(|&v| v <= 1.0) {
            return None;
        }
        // Grading, both ways round the closed seam (two rounds reach across the start).
        let per_bin = |v: f64| (-GRADING * REFERENCE * v / BINS as f64).exp_m();
        for _ in 0..2 {
            for b in 1..=BINS {
                let (p, c) = ((b - 1) % BINS, b % BINS);
                w[c] = w[c].max(w[p] * per_bin(w[p]));
            }
            for b in (0..BINS).rev() {
                let (n, c) = ((b + 1) % BINS, b);
                w[c] = w[c].max(w[n] * per_bin(w[n]));
            }
        }
        let mut cum = Vec::with_capacity(BINS + 1);
        let mut f = 0.0;
        cum.push(0.0);
        for v in &w {
            f += v * bin;
            cum.push(f);
        }
        Some(Density { total, cum })
    }

    /// `W = F(L)`.
    pub fn weight(&self) -> f64 {
        self.cum[BINS]
    }

    /// `F(s)` for `s` in `[0, L]`.
    pub fn forward(&self, s: f64) -> f64 {
        let bin = self.total / BINS as f64;
        let x = (s / bin).clamp(0.0, BINS as f64);
        let b = (x as usize).min(BINS - 1);
        self.cum[b] + (x - b as f64) * (self.cum[b + 1] - self.cum[b])
    }

    /// `F⁻¹(f)` for `f` in `[0, W]`.
    pub fn inverse(&self, f: f64) -> f64 {
        let f = f.clamp(0.0, self.weight());
        let b = self.cum.partition_point(|&c| c <= f).saturating_sub(1).min(BINS - 1);
        let bin = self.total / BINS as f64;
        let span = self.cum[b + 1] - self.cum[b];
        let frac = if span > 0.0 { (f - self.cum[b]) / span } else { 0.0 };
        (b as f64 + frac) * bin
    }
}

/// Raises `kappa_in`'s bins (of a seam of length `total`) to the curvature that is `a.1` at
/// seam point `a.0` and `b.1` at `b.0` and linear between them (the shorter way round), over
/// the part of each bin the stretch covers. Unlike the largest sample in each bin, this moves
/// with the samples continuously: a sample within round-off of a bin's end, which one side of
/// a symmetric outline puts in one bin and the other side in the next, changes the weight by
/// round-off. With each sample in one bin, a circle's 392 samples left 3,712 of 4,096 bins at
/// no curvature, and the weight of a mirror-symmetric pair was 0.16 off symmetric (the rounded
/// star with a circle): its seam samples were no mirror images ([`crate::simulate::sheet::mirror`]).
fn spread(kappa_in: &mut [f64], total: f64, a: (f64, f64), b: (f64, f64)) {
    let bins = kappa_in.len();
    let bin = total / bins as f64;
    let (mut a, mut b) = (a, b);
    let mut len = (b.0 - a.0).rem_euclid(total);
    if len > total / 2.0 {
        std::mem::swap(&mut a, &mut b);
        len = total - len;
    }
    if !(len.is_finite() && bin > 0.0) {
        return;
    }
    let at = |x: f64| if len > 0.0 { a.1 + (b.1 - a.1) * ((x - a.0) / len).clamp(0.0, 1.0) } else { a.1.max(b.1) };
    // The bins from the one holding `a.0` to the one holding its end (past the seam's end they
    // wrap round), at most once round.
    let first = ((a.0 / bin).max(0.0) as usize).min(bins - 1);
    let last = (((a.0 + len) / bin) as usize).clamp(first, first + bins);
    for j in first..=last {
        let (lo, hi) = ((j as f64 * bin).max(a.0), ((j + 1) as f64 * bin).min(a.0 + len));
        let slot = &mut kappa_in[j % bins];
        *slot = slot.max(at(lo)).max(at(hi.max(lo)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::{Contour, Knot};
    use kurbo::Point;

    /// A circle of radius `r` by `m` cubic arcs.
    fn circle(r: f64, m: usize) -> Contour {
        let h = 4.0 / 3.0 * (std::f64::consts::TAU / (4.0 * m as f64)).tan_m() * r;
        let knots = (0..m)
            .map(|k| {
                let (s, c) = (std::f64::consts::TAU * k as f64 / m as f64).sin_cos_m();
                let a = Point::new(r * c, r * s);
                Knot { anchor: a, left: Point::new(a.x + h * s, a.y - h * c), right: Point::new(a.x - h * s, a.y + h * c) }
            })
            .collect();
        Contour::new(knots, 0).unwrap()
    }

    #[test]
    fn congruent_or_gently_curved_pairs_keep_even_steps() {
        let a = ArcTable::new(&circle(10.0, 8), 1e-12);
        assert!(Density::new(&a, &a, [0.0, 3.0], [&[], &[]]).is_none(), "a circle with itself needs no grading");
        let big = ArcTable::new(&circle(10.0, 8), 1e-12);
        let small = ArcTable::new(&circle(10.0, 8).transformed(kurbo::Affine::scale(1.0 + 1e-7)), 1e-12);
        assert!(Density::new(&big, &small, [0.0, 0.0], [&[], &[]]).is_none());
    }

    /// A square with corners rounded at radius `r`, first anchor where its first corner's arc
    /// begins (each corner one arc, then a straight side).
    fn rounded_square(side: f64, r: f64) -> Contour {
        let k = 0.5522847498307936 * r;
        let mut knots = Vec::new();
        for (cx, cy, a0) in [(side - r, r, -1.0), (side - r, side - r, 0.0), (r, side - r, 1.0), (r, r, 2.0)] {
            let a0 = a0 * std::f64::consts::FRAC_PI_2;
            let (c0, s0, c1, s1) = (a0.cos_m(), a0.sin_m(), (a0 + std::f64::consts::FRAC_PI_2).cos_m(), (a0 + std::f64::consts::FRAC_PI_2).sin_m());
            let (p0, p1) = (Point::new(cx + r * c0, cy + r * s0), Point::new(cx + r * c1, cy + r * s1));
            knots.push(Knot { anchor: p0, left: p0, right: Point::new(p0.x - k * s0, p0.y + k * c0) });
            knots.push(Knot { anchor: p1, left: Point::new(p1.x + k * s1, p1.y - k * c1), right: p1 });
        }
        Contour::new(knots, 0).unwrap()
    }

    /// A seam that starts on a mirror axis of both pieces has a weight symmetric about its start,
    /// `F(L − s) = W − F(s)`, so its samples are mirror images (`sheet::mirror` meshes such a
    /// pair symmetrically). With each curvature sample counted in one bin, a circle's few
    /// samples left most bins at no curvature, where they fell: the rounded star with a circle
    /// had a weight 0.16 off symmetric and samples 0.04 mm off.
    #[test]
    fn test_issue_14_a_seam_started_on_both_axes_has_a_symmetric_weight() {
        let square = ArcTable::new(&rounded_square(20.0, 1.0), 1e-12);
        let p = square.total();
        let disc = ArcTable::new(&circle(p / std::f64::consts::TAU, 8), 1e-12);
        // The middle of the first corner's arc: an axis of the square; the circle's first anchor
        // is on one of its own.
        let middle = square.segment_start(1) / 2.0;
        let d = Density::new(&square, &disc, [middle, 0.0], [&[], &[]]).expect("tight corners need grading");
        let w = d.weight();
        let mut worst = (0.0f64, 0.0);
        for m in 1..1000 {
            let s = p * m as f64 / 1000.0;
            let gap = (d.forward(p - s) - (w - d.forward(s))).abs();
            if gap > worst.0 {
                worst = (gap, s);
            }
        }
        assert!(worst.0 <= 1e-9 * w, "wanted F(L − s) = W − F(s) within 1e-9 of W = {w}, got {:.3e} at s = {}", worst.0, worst.1);
    }

    #[test]
    fn forward_and_inverse_agree_and_tight_bends_get_short_steps() {
        // A rounded square (corner radius 1 of side 20) against a circle of its perimeter: κL ≈ 80 at
        // the corners, so the weight there is about 80/K.
        let (side, r) = (20.0, 1.0);
        let square = ArcTable::new(&rounded_square(side, r), 1e-12);
        let p = square.total();
        let disc = ArcTable::new(&circle(p / std::f64::consts::TAU, 8), 1e-12);
        let d = Density::new(&square, &disc, [0.0, 0.0], [&[], &[]]).expect("tight corners need grading");
        let mut last = -1.0;
        for m in 0..=400 {
            let s = p * m as f64 / 400.0;
            let f = d.forward(s);
            assert!(f >= last, "F must not decrease: F({s}) = {f} after {last}");
            last = f;
            let back = d.inverse(f);
            assert!((back - s).abs() <= 1e-9 * p, "F⁻¹(F({s})) = {back}");
        }
        // Weight at a corner's middle (arc length ≈ side − 2r + πr/4 from the first anchor, which
        // starts the first corner) against a straight side's middle.
        let slope = |s: f64| (d.forward(s + 1e-3) - d.forward(s - 1e-3)) / 2e-3;
        let corner = 0.25 * std::f64::consts::PI * r;
        let straight = 0.5 * std::f64::consts::PI * r + 0.5 * (side - 2.0 * r);
        let want = (p / r / K).min(W_MAX);
        assert!((slope(corner) / want - 1.0).abs() < 0.1, "weight at a corner: wanted ≈ {want}, got {}", slope(corner));
        assert!(slope(straight) < slope(corner) / 2.0, "a straight side is sampled coarser than a corner");
    }
}
