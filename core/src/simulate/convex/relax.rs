//! Levenberg–Marquardt on a fixed triangulation with flips of reflex chords between solves
//! (Lawson-style, towards the convex realization; see the module docs of [`crate::simulate`]).

use super::super::checks::{reflex_sine, REFLEX_SINE};
use super::super::isometry::{bars, cost, max_strain, pattern, repattern, step, Bar, STRAIN_TOL};
use super::super::normal::NormalEquations;
use super::super::mesh::make_outward;
use super::super::metric::{self, KeyMap, Triangulation};
use super::super::seam::SeamPieces;
use super::super::vec3::{size, V3};
use std::f64::consts::PI;

/// How often a chord may be flipped away before it is frozen: a chord that keeps coming back
/// sits between two nearly coplanar triangles (or a non-convex piece), where flipping it again
/// would only cycle.
pub(crate) const MAX_FLIPS_PER_EDGE: usize = 2;

/// Whether a relaxation may mirror the positions to make the volume positive.
///
/// A start whose orientation is not known (a lifted flat layout) must be allowed to; a start
/// that is already outward-oriented (a coarser level's solution or a warm start from a previous
/// result, whose A faces are outward by construction) must not. Mirroring such a start while its
/// triangulation is still the flat ear-clipping strip (whose realization has no meaningful
/// volume sign) reverses what "outward" means half way through the flips, and the flips then
/// drive A's chords onto B's cap: both sheets end up on the same cap and the shape collapses to
/// volume ≈ 0 (the warm-start bug; see `warm_start_keeps_its_orientation` in the tests).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Orientation {
    Free,
    Kept,
}

/// Makes the mesh outward-oriented (positive volume) by mirroring, an isometry, when the
/// orientation is [`Orientation::Free`], then flips every reflex chord whose flat quad allows
/// it and whose new flat triangles have no angle above `largest` (π: any). Returns the number
/// of flips.
pub(crate) fn flip_pass(
    x: &mut [V3],
    tri: &mut [Triangulation; 2],
    pieces: &SeamPieces,
    // Keyed by `order::pair_key(i, j)`: [`KeyMap`] is the map type the triangulations use too,
    // so the .wasm holds one instantiation of the hash table, not two.
    count: &mut [KeyMap; 2],
    orientation: Orientation,
    largest: f64,
) -> usize {
    if orientation == Orientation::Free {
        make_outward(x, tri);
    }
    let mut flips = 0;
    for p in 0..2 {
        let pts = &pieces.flat[p].pts;
        let s2 = metric::size2(pts);
        for (i, j) in tri[p].chords() {
            let key = crate::order::pair_key(i, j);
            if count[p].get(&key).is_some_and(|&c| c >= MAX_FLIPS_PER_EDGE) {
                continue;
            }
            let Some(s) = reflex_sine(x, &tri[p], p, i, j) else { continue };
            if s <= REFLEX_SINE {
                continue;
            }
            // The new chord must be able to be an edge (see [`shortest_flips`]): a flip that
            // would put in a chord longer than the path through the other piece is refused,
            // unless the chord it replaces is as bad.
            let (Some(k), Some(l)) = (tri[p].opposite(i, j), tri[p].opposite(j, i)) else { continue };
            if excess(pieces, p, k, l) > SHORTEST_TOL.max(excess(pieces, p, i, j)) {
                continue;
            }
            if largest < PI && largest_angle(pts[k], pts[i], pts[l]).max(largest_angle(pts[l], pts[j], pts[k])) > largest {
                continue;
            }
            if tri[p].flip(i, j, pts, s2) {
                *count[p].entry(key).or_insert(0) += 1;
                flips += 1;
            }
        }
    }
    flips
}

/// The largest angle of the flat triangle `a`, `b`, `c`.
fn largest_angle(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    metric::angle(a, b, c).max(metric::angle(b, c, a)).max(metric::angle(c, a, b))
}

/// Largest angle a flip of [`Chords::without_caps`] may make in a new flat triangle. A cap (an
/// angle near π, three nearly collinear seam samples) has a 3D plane that tilts freely with
/// its middle vertex; the chord flips of the intrinsic path's last relax made 26 of them, at
/// 179.99°, on two congruent 120 × 80 rectangles with 1 mm corners, and the convexity tests then
/// read vertices 72 mm outside them.
pub(crate) const CAP_ANGLE: f64 = PI - 1e-3;

/// Relative excess `d_p(i, j) / d_q(i, j) − 1` of chord i–j of piece `p` over the same chord of
/// the other piece `q`. An isometric realization has `|X_i − X_j| = d_p(i, j)` for every edge of
/// `p` and `|X_i − X_j| ≤ d_q(i, j)` (the straight segment is no longer than the path across the
/// other piece, a curve on the surface), so a chord with positive excess cannot be an edge of any
/// realization, convex or not. (For a convex polyhedron this is the fact that every edge is a
/// shortest path between its ends.)
pub(crate) fn excess(pieces: &SeamPieces, p: usize, i: usize, j: usize) -> f64 {
    pieces.chord(p, i, j) / pieces.chord(1 - p, i, j).max(f64::MIN_POSITIVE) - 1.0
}

/// Excess (see [`excess`]) tolerated in a chord put in by a flip: the seam edges' lengths are
/// the mean of A's and B's chords, which makes the metric's distances differ from either flat
/// piece's at `O(h²)` relative, so only a clear excess is ruled out.
pub(crate) const SHORTEST_TOL: f64 = 1e-6;

/// Flips every chord of piece `p` that cannot be an edge (positive [`excess`]) to the other
/// diagonal of its quad, when that one's excess is smaller, until none can be. Purely intrinsic
/// (no positions): it turns the ear-clipping strip, which on a rectangle glued to a circle holds
/// rectangle chords up to 8 % longer than the circle's between the same seam vertices (and circle
/// chords up to 59 % longer than the rectangle's), into a start the isometry equations can meet.
/// Each flip lowers the sum of the chords' excess ratios, so it ends.
pub(crate) fn shortest_flips(t: &mut Triangulation, pieces: &SeamPieces, p: usize) {
    let pts = &pieces.flat[p].pts;
    let s2 = metric::size2(pts);
    loop {
        let mut any = false;
        for (i, j) in t.chords() {
            let e = excess(pieces, p, i, j);
            if e <= 0.0 {
                continue;
            }
            let (Some(k), Some(l)) = (t.opposite(i, j), t.opposite(j, i)) else { continue };
            if excess(pieces, p, k, l) < e && t.flip(i, j, pts, s2) {
                any = true;
            }
        }
        if !any {
            break;
        }
    }
}

/// Steps after which [`relax`] folds reflex chords if the cost has not halved (see there).
pub(crate) const PLATEAU: usize = 10;

/// Flips after which the pattern's ordering is computed afresh rather than kept
/// ([`super::super::normal::NormalEquations::reordered_like`]), per seam vertex: a few flips
/// leave a good ordering good, but after the hundreds of flips of a warm start (a slider step of
/// 1 % of the perimeter moves B's chords by a few samples each) the kept ordering's factor made
/// the warm re-solve of the bench's crossed ellipses about three times slower.
pub(crate) const REORDER_FLIPS: f64 = 1.0 / 16.0;

/// The normal equations' pattern for `bars` after `since` flips: `ne`'s ordering kept while
/// `since` stays under [`REORDER_FLIPS`] per vertex, else a fresh one (then `since` restarts).
fn renew(ne: NormalEquations, since: usize, n: usize, bars: &[Bar]) -> (NormalEquations, usize) {
    if (since as f64) <= REORDER_FLIPS * n as f64 {
        (repattern(&ne, bars), since)
    } else {
        (pattern(n, bars), 0)
    }
}

/// Result of relaxing one level.
pub(crate) struct Relaxed {
    pub(crate) iterations: usize,
    pub(crate) flips: usize,
    pub(crate) converged: bool,
}

impl Relaxed {
    /// Adds this relaxation's steps and flips to a cold solve's running `(steps, flips)`.
    pub(crate) fn tally(self, steps: &mut (usize, usize)) -> Self {
        steps.0 += self.iterations;
        steps.1 += self.flips;
        self
    }
}

/// The Levenberg–Marquardt damping schedule of a [`relax`]: `λ` (relative to the mean diagonal of
/// `JᵀJ`) at the start and after every flip pass, and the factor it shrinks by after an accepted
/// step (it grows ×4 after a rejected one).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Damping {
    pub(crate) start: f64,
    pub(crate) shrink: f64,
}

/// The cold solve's damping: strong at first, shrinking by 3 (Marquardt's schedule). The starts
/// of the multistart are far from any realization, and the flat doubly covered D-form (congruent
/// pieces) is a singular point of the length equations, flat to first order in every
/// out-of-plane flex: with λ starting at 1e-10 or shrinking by 10, Gauss–Newton's steps left it
/// for a bent branch (two congruent 16-arc circles at a fifth of the perimeter ended at volume
/// 8e-5 instead of 0), and the ladder's flip decisions, taken at its levels' loose 1e-6 stall,
/// changed (a rectangle with a circle ended 5e-6 off in volume).
pub(crate) const COLD: Damping = Damping { start: 1e-4, shrink: 3.0 };

/// A warm start's damping: a previous result at a nearby offset is close to an isometric
/// realization, where undamped Gauss–Newton converges quadratically (a zero-residual problem:
/// Dennis & Schnabel, *Numerical Methods for Unconstrained Optimization and Nonlinear
/// Equations*, 1983, ch. 10; λ only regularizes the six rigid motions here). With the
/// cold schedule each flip pass restarted at λ = 1e-4 and took ~10 steps of linear convergence
/// (the soft modes of nearly flat regions damped by λ): 62–82 steps for a slider step of 1 % on
/// the bench's crossed ellipses, 21–33 with this one, to the same volumes (1e-9).
pub(crate) const WARM: Damping = Damping { start: 1e-10, shrink: 10.0 };

/// Levenberg–Marquardt on a fixed triangulation until the step is negligible, then one pass of
/// flips; repeated until nothing flips. `step_tol` is relative to the shape's size. With the
/// cold [`Damping`] ([`relax_damped`] for another).
pub(crate) fn relax(
    pieces: &SeamPieces,
    x: &mut Vec<V3>,
    tri: &mut [Triangulation; 2],
    budget: usize,
    step_tol: f64,
    orientation: Orientation,
) -> Relaxed {
    relax_damped(pieces, x, tri, budget, step_tol, orientation, COLD)
}

/// [`relax`] with the damping schedule `damping`.
pub(crate) fn relax_damped(
    pieces: &SeamPieces,
    x: &mut Vec<V3>,
    tri: &mut [Triangulation; 2],
    budget: usize,
    step_tol: f64,
    orientation: Orientation,
    damping: Damping,
) -> Relaxed {
    relax_with(&mut Chords { pieces, tri, largest: PI }, x, budget, step_tol, orientation, damping)
}

/// A triangulation whose edges carry the length equations and whose reflex edges can be
/// flipped: the chord meshes of the two pieces ([`Chords`]), or an intrinsic triangulation of
/// the glued metric ([`super::intrinsic::Mesh`]).
pub(crate) trait Flips {
    /// Number of vertices.
    fn vertices(&self) -> usize;
    /// The length equations of the edges.
    fn bars(&self) -> Vec<Bar>;
    /// Makes `x` outward when `orientation` is [`Orientation::Free`], then flips every reflex
    /// edge that can be flipped (at most [`MAX_FLIPS_PER_EDGE`] times each, counted in `count`).
    /// Returns the number of flips.
    fn flip_pass(&mut self, x: &mut [V3], count: &mut [KeyMap; 2], orientation: Orientation) -> usize;
}

/// The two pieces' chord triangulations as one mesh to relax ([`Flips`]), whose flips make no
/// flat angle above `largest`.
pub(crate) struct Chords<'a> {
    pub(crate) pieces: &'a SeamPieces,
    pub(crate) tri: &'a mut [Triangulation; 2],
    pub(crate) largest: f64,
}

impl<'a> Chords<'a> {
    /// Chord meshes whose flips make no cap ([`CAP_ANGLE`]).
    pub(crate) fn without_caps(pieces: &'a SeamPieces, tri: &'a mut [Triangulation; 2]) -> Chords<'a> {
        Chords { pieces, tri, largest: CAP_ANGLE }
    }
}

impl Flips for Chords<'_> {
    fn vertices(&self) -> usize {
        self.pieces.n
    }

    fn bars(&self) -> Vec<Bar> {
        bars(self.pieces, self.tri)
    }

    fn flip_pass(&mut self, x: &mut [V3], count: &mut [KeyMap; 2], orientation: Orientation) -> usize {
        flip_pass(x, self.tri, self.pieces, count, orientation, self.largest)
    }
}

/// Levenberg–Marquardt on the fixed triangulation of `mesh` with the damping schedule
/// `damping` until the step is negligible (`step_tol`, relative to the shape's size), then one
/// pass of flips; repeated until nothing flips.
pub(crate) fn relax_with(
    mesh: &mut impl Flips,
    x: &mut Vec<V3>,
    budget: usize,
    step_tol: f64,
    orientation: Orientation,
    damping: Damping,
) -> Relaxed {
    let n = mesh.vertices();
    let mut count = [KeyMap::default(), KeyMap::default()];
    let mut flips = 0;
    for _ in 0..n {
        let f = mesh.flip_pass(x, &mut count, orientation);
        flips += f;
        if f == 0 {
            break;
        }
    }
    let scale = size(x).max(f64::MIN_POSITIVE);
    let mut bars = mesh.bars();
    let mut ne = pattern(n, &bars);
    // Flips since `ne`'s ordering was computed (see [`renew`]).
    let mut since = 0;
    let mut c = cost(x, &bars);
    let mut lambda = damping.start;
    let mut iterations = 0;
    let mut converged = false;
    let mut window = (0usize, c);
    while iterations < budget {
        // A triangulation with no isometric realization makes the least-squares cost plateau long
        // before the step gets negligible (hundreds of steps on a rectangle with a circle): when
        // the cost has not halved in PLATEAU steps, fold the reflex chords now.
        if iterations - window.0 >= PLATEAU {
            let slow = c > 0.5 * window.1;
            window = (iterations, c);
            if slow {
                let f = mesh.flip_pass(x, &mut count, orientation);
                if f > 0 {
                    flips += f;
                    bars = mesh.bars();
                    (ne, since) = renew(ne, since + f, n, &bars);
                    c = cost(x, &bars);
                    lambda = damping.start;
                    window = (iterations, c);
                }
            }
        }
        iterations += 1;
        let Some(d) = step(x, &bars, lambda, &mut ne) else {
            lambda *= 10.0;
            if lambda > 1e12 {
                break;
            }
            continue;
        };
        let trial: Vec<V3> = (0..n).map(|k| [x[k][0] + d[3 * k], x[k][1] + d[3 * k + 1], x[k][2] + d[3 * k + 2]]).collect();
        let ct = cost(&trial, &bars);
        let dmax = d.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let stalled = dmax <= step_tol * scale || c == 0.0;
        if ct <= c {
            *x = trial;
            c = ct;
            lambda = (lambda / damping.shrink).max(1e-12);
        } else if !stalled {
            lambda *= 4.0;
            if lambda > 1e12 {
                break;
            }
            continue;
        }
        if !stalled {
            continue;
        }
        // The realization of this triangulation is found: fold the reflex chords the other way.
        let f = mesh.flip_pass(x, &mut count, orientation);
        flips += f;
        if f > 0 {
            bars = mesh.bars();
            (ne, since) = renew(ne, since + f, n, &bars);
            c = cost(x, &bars);
            lambda = damping.start;
            continue;
        }
        let worst = max_strain(x, &bars);
        converged = worst <= STRAIN_TOL;
        break;
    }
    Relaxed { iterations, flips, converged }
}
