//! The convex (Alexandrov) path: Levenberg–Marquardt with flips towards the convex realization,
//! a multistart on a coarse-to-fine ladder, hull restarts, and the cone-point solve of polygon
//! pairs (see the module docs of [`crate::simulate`]).
//!
//! - [`congruent`]: congruent pieces glued congruently, laid out flat without a solve;
//! - [`relax`]: LM on a fixed triangulation, flips between solves;
//! - [`starts`]: the multistart's starting shapes;
//! - [`hull`]: triangulations read off a convex hull, to restart a failed start;
//! - [`polyhedral`]: polygon pairs solved on their cone points;
//! - [`crossing`]: the fallback when a crease crosses the seam, on an intrinsic triangulation
//!   ([`intrinsic`]) embedded by Bobenko & Izmestiev's method ([`alexandrov`]) and cut along the
//!   seam ([`overlay`]), without the samples where both pieces run straight ([`flat`]).

pub mod alexandrov;
pub mod congruent;
pub mod crossing;
pub mod flat;
pub mod hull;
pub mod intrinsic;
pub mod overlay;
pub mod polyhedral;
pub mod relax;
pub mod starts;

use super::checks::{convex_as_a_whole, folded_flat, outside_sampled, worst_reflex, OUTSIDE_TOL};
use super::isometry::{bars, max_strain, STEP_TOL};
use super::mesh::Solution;
use super::metric::Triangulation;
use super::options::SimulateOptions;
use super::seam::{Glue, SeamPieces};
use super::vec3::V3;
use crate::error::{Error, Result};
use polyhedral::{cone_restart, solve_polyhedral, CONE_BUDGET};
use relax::{relax, relax_damped, shortest_flips, Orientation, WARM};
use starts::{initial_guess, resample, upsample, LIFTS};

/// Finds the seam positions at `options.resolution` seam vertices, from the warm start or cold
/// (see [`solve_cold`]). Never panics; an input that cannot even be triangulated is an error.
pub fn solve(glue: &Glue, options: &SimulateOptions) -> Result<(SeamPieces, Solution)> {
    let pieces = glue.sample(options.resolution);
    if let Some((x, tri)) = congruent::flat_layout(&pieces) {
        return Ok((pieces, Solution { x, tri, iterations: 0, flips: 0, converged: true }));
    }
    let Some(w) = &options.warm else { return solve_cold(glue, options) };
    let (pieces, x, tri, r) = warm_ladder(glue, options, w)?;
    if r.converged {
        let solution = Solution { x, tri, iterations: r.iterations, flips: r.flips, converged: true };
        return Ok((pieces, solution));
    }
    // A warm start that leads nowhere convex (e.g. the vertices of another shape, which can pull
    // the solver into an isometric but dented branch) is dropped for a cold solve rather than
    // returned. "Convex" allows the tiny reflex folds that coarse resolutions keep (the cold
    // solve keeps them too), not a dent.
    // The cold solve gets what is left of the user's `max_iterations`.
    let left = options.max_iterations.saturating_sub(r.iterations);
    if left == 0 {
        return Ok((pieces, Solution { x, tri, iterations: r.iterations, flips: r.flips, converged: false }));
    }
    let cold = SimulateOptions { warm: None, max_iterations: left, ..options.clone() };
    let (p, mut sol) = solve_cold(glue, &cold)?;
    sol.iterations += r.iterations;
    sol.flips += r.flips;
    Ok((p, sol))
}

/// A warm start on the coarse-to-fine ladder: the previous result's vertices resampled to the
/// coarsest of [`WARM_RUNGS`] levels, relaxed there from the triangulations of their convex
/// hull with the [`WARM`] damping, then each finer level from the last ([`relax_level`]).
/// Returns the finest level's samples, shape and triangulations, and a relaxation whose
/// `converged` says the answer is good (convex, undented, isometric): otherwise the caller drops
/// it for a cold solve.
fn warm_ladder(glue: &Glue, options: &SimulateOptions, w: &[V3]) -> Result<(SeamPieces, Vec<V3>, [Triangulation; 2], relax::Relaxed)> {
    let n = options.resolution;
    let mut levels = vec![n];
    while levels.len() < WARM_RUNGS && levels[levels.len() - 1] % 2 == 0 && glue.nests(levels[levels.len() - 1] / 2) {
        levels.push(levels[levels.len() - 1] / 2);
    }
    levels.reverse();
    let mut samples: Vec<SeamPieces> = glue.sample_levels(&levels);
    let mut steps = (0usize, 0usize);
    let first = &samples[0];
    let mut x = resample(w, first.n);
    // The triangulations read off the convex hull of the warm positions ([`hull::triangulations`]):
    // a previous convex result is the hull of its vertices, so its own chords come back and only
    // the few that the new offset turns reflex are flipped. Else plain ear clipping, not
    // [`triangulate`]: the warm positions decide the flips.
    let mut tri = match hull::triangulations(&x, first) {
        Some(t) => t,
        None => [ear_clip(first, 0)?, ear_clip(first, 1)?],
    };
    let budget = options.max_iterations.min(WARM_BUDGET).max(1);
    let single = levels.len() == 1;
    let tol = level_tol(single);
    let r = relax_damped(first, &mut x, &mut tri, budget, tol, Orientation::Kept, WARM).tally(&mut steps);
    let loose = level_loose(first, &x, &tri, single);
    let mut good = is_good(&x, &tri, r.converged || loose);
    let mut converged = r.converged;
    for li in 1..levels.len() {
        let budget = options.max_iterations.saturating_sub(steps.0).min(WARM_BUDGET);
        if !good || budget == 0 {
            // Given up: the shape laid onto the finest level as it is, so that what is returned
            // has the resolution's seam vertices.
            (good, converged) = (false, false);
            (x, tri) = laid_onto(&samples[li - 1], &x, &tri, &samples[li])?;
            continue;
        }
        let last = li + 1 == levels.len();
        let (xf, tf, r, loose) = relax_level(&samples[li - 1], &x, &tri, &samples[li], budget, options.max_iterations, last, &mut steps)?;
        (x, tri, converged) = (xf, tf, r.converged);
        good = is_good(&x, &tri, converged || loose);
    }
    let pieces = samples.pop().expect("a level");
    let done = good && converged && exact_if_polyhedral(&pieces, &x, &tri) && convex_as_a_whole(&x, &tri);
    Ok((pieces, x, tri, relax::Relaxed { iterations: steps.0, flips: steps.1, converged: done }))
}

/// Levels of a warm start's ladder ([`warm_ladder`]): 3, so it begins at a quarter of the
/// resolution (64 seam vertices at 256) where the ladder nests that far.
///
/// A slider step of 1 % of the perimeter shifts every one of B's chords by a few samples, so
/// the warm shape's chords are all wrong for the new offset: relaxed at 256 seam vertices
/// directly (as until stop 29) the bench's crossed 2:1 ellipses took 21–33 steps and 640–850
/// flips at 256, 1.13–1.18 times a cold solve once the cold solve's finer levels took the warm
/// damping ([`relax_level`]). Begun at 64 they take 10–14 steps there, 9–10 at 128 and 12–15 at
/// 256, the last level costing what the cold solve's does; the warm start saves the cold
/// solve's multistart and coarse levels. Begun at 128 it was as fast (0.79–0.94 of the cold
/// solve against 0.79–0.95), at 32 no faster.
pub(crate) const WARM_RUNGS: usize = 3;

/// Step budgets of one pass of the cold solve: per multistart attempt on the coarsest level, per
/// refinement level while other starts remain, and in all (`cap`, counted with the steps of
/// earlier passes).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Patience {
    pub(crate) attempt: usize,
    pub(crate) level: usize,
    pub(crate) cap: usize,
    /// Whether a failed multistart attempt restarts from the convex hull of where it ended
    /// ([`super::hull`]).
    pub(crate) hull: bool,
}

/// The first pass: a healthy start needs a few dozen steps per level (the whole 32→256 solve of
/// two ellipses takes ~100–400), so a start that needs more is dropped for the next one.
pub(crate) const QUICK: Patience = Patience { attempt: 60, level: 150, cap: 1000, hull: false };

/// The second pass, run only when the first found no convex isometric branch: pieces with
/// straight stretches (rectangles, rounded rectangles, polygons) give D-forms with nearly flat
/// regions, whose chords sit between nearly coplanar triangles and take many steps and flips to
/// settle (a rounded 60×40 rectangle glued to a circle: ~2,300 steps in all, ~70 ms native at
/// 256 seam vertices) — longer than the quick budgets allow, but the branch is right.
pub(crate) const PATIENT: Patience = Patience { attempt: 2000, level: 2000, cap: usize::MAX, hull: true };

/// Steps allowed to each level of a warm start ([`warm_ladder`]) before it is dropped for a
/// cold solve. Climbing from 64 seam vertices, a slider step of 1 % of the perimeter takes
/// 10–14, 9–10 and 12–15 steps on the levels of 64, 128 and 256 (the bench's crossed 2:1
/// ellipses); a level that needs more is heading for a shape the solver cannot realize, and
/// grinding it longer only delays the cold solve the slider then waits for. (It was 300 when a
/// warm start was relaxed at the finest level from an ear clipping, in 25–105 steps; 50 there
/// from the previous result's hull, in 5–33, until stop 29.)
pub(crate) const WARM_BUDGET: usize = 50;

/// Strain below which a coarser level (relaxed only to a step of 1e-6 of the size) counts as
/// solved: its solution is only a start for the next level, which polishes it.
pub(crate) const LEVEL_STRAIN_TOL: f64 = 1e-5;

/// The step tolerance a level of the ladder is relaxed to: [`STEP_TOL`] on the `last` (finest)
/// level, 1e-6 of the size on a coarser one, which only starts the next.
fn level_tol(last: bool) -> f64 {
    if last { STEP_TOL } else { 1e-6 }
}

/// Whether a level before the `last` counts as solved by its strain alone
/// ([`LEVEL_STRAIN_TOL`]), though its loose relaxation did not converge.
fn level_loose(pf: &SeamPieces, x: &[V3], tri: &[Triangulation; 2], last: bool) -> bool {
    !last && max_strain(x, &bars(pf, tri)) <= LEVEL_STRAIN_TOL
}

/// Out-of-plane sine of a reflex chord above which a solution counts as dented (a wrong
/// isometric branch) rather than convex up to the tiny folds that coarse levels keep.
pub(crate) const DENT_SINE: f64 = 1e-2;

/// [`OUTSIDE_TOL`] for a start of the multistart on a rung before the last ([`multistart`]):
/// a coarse level only starts the finer ones, which lay it onto more samples and flip its folds
/// away, and the finest level's answer is still held to [`OUTSIDE_TOL`] and
/// [`convex_as_a_whole`]. The graded seam ([`crate::simulate::density`]) puts most of a coarse
/// level's samples on tight corners: a 60 × 40 rectangle with 2 mm rounded corners on a circle
/// (and the same shape at twice the size) has a 32-gon whose only converged, undented starts
/// stand 1.23e-2 of the size outside a face. With 1e-2 every rung was refused, both passes ran
/// out of steps, and the answer was 1.8e-2 strained (`converged: false`) at 10 of 16 offsets;
/// with 2e-2 it converges at all 16 (256 seam vertices), and the bench pairs take the same steps.
pub(crate) const COARSE_OUTSIDE_TOL: f64 = 2e-2;

/// A cold start's triangulation of piece `p`: ear clipping, then [`shortest_flips`].
pub(crate) fn triangulate(pieces: &SeamPieces, p: usize) -> Result<Triangulation> {
    let mut t = ear_clip(pieces, p)?;
    shortest_flips(&mut t, pieces, p);
    Ok(t)
}

pub(crate) fn ear_clip(pieces: &SeamPieces, p: usize) -> Result<Triangulation> {
    super::metric::ear_clip(&pieces.flat[p].pts).ok_or_else(|| Error::Infeasible {
        reason: format!(
            "The {} piece is too thin or too detailed for {} seam vertices: its sampled outline cannot be triangulated. Raise the resolution or simplify the outline.",
            if p == 0 { "first" } else { "second" },
            pieces.n
        ),
    })
}

/// The finer level's triangulation: the coarse one plus one ear per seam edge where it can be,
/// else a fresh ear clipping.
pub(crate) fn refine(tc: &[Triangulation; 2], pieces: &SeamPieces, p: usize) -> Result<Triangulation> {
    if tc[p].len() * 2 == pieces.n {
        if let Some(mut t) = tc[p].doubled(&pieces.flat[p].pts) {
            shortest_flips(&mut t, pieces, p);
            return Ok(t);
        }
    }
    triangulate(pieces, p)
}

/// Whether a solution is the convex isometric one: converged, without a dent, and convex as a
/// whole ([`super::checks::outside`] within [`OUTSIDE_TOL`]).
pub(crate) fn is_good(x: &[V3], tri: &[Triangulation; 2], converged: bool) -> bool {
    is_good_within(x, tri, converged, OUTSIDE_TOL)
}

/// [`is_good`] with `outside_tol` in place of [`OUTSIDE_TOL`].
pub(crate) fn is_good_within(x: &[V3], tri: &[Triangulation; 2], converged: bool, outside_tol: f64) -> bool {
    converged && worst_reflex(x, tri) <= DENT_SINE && outside_sampled(x, tri) <= outside_tol && !folded_flat(x, tri)
}

/// For a polyhedral gluing (two convex polygons, [`hull::cone_vertices`]): whether the
/// mesh is convex — no chord reflex beyond round-off (out-of-plane sine above
/// [`crate::simulate::stats::REFLEX_REPORT`], what the stats count as a reflex edge), convex as a whole
/// ([`super::checks::outside`]) and not a flat fold ([`super::checks::folded_flat`]); always true for a curved seam, whose
/// "converged" keeps meaning that the isometry equations are met.
///
/// The tolerance of [`DENT_SINE`] is for the folds a polygonal seam keeps where the true seam is
/// curved, which vanish as the samples get finer. The seam of two polygons is exactly polygonal
/// and the polyhedron exact at any sampling that holds the corners, so a fold there is a wrong
/// shape, not a discretization error: two triangles at a quarter offset "converged" at 40–61
/// seam vertices with 4–21 reflex chords and volumes from 5,500 to 6,700, and a 90×10
/// rectangle with a square at 48 with 3 (volume 7,961; the polyhedron's is 7,978.128 at 128, 160
/// and 256). Where a crease of the polyhedron crosses the seam between samples no chord mesh
/// realizes it and the honest answer is "not converged" ([`solve_polyhedral`] puts a sample at
/// each such crossing it can find, see [`seam_crossings`]).
pub(crate) fn exact_if_polyhedral(pieces: &SeamPieces, x: &[V3], tri: &[Triangulation; 2]) -> bool {
    hull::cone_vertices(pieces).is_none()
        || (worst_reflex(x, tri) <= super::stats::REFLEX_REPORT && outside_sampled(x, tri) <= OUTSIDE_TOL && !folded_flat(x, tri))
}

/// Multistart on the coarsest level (cheap), trying the starts `LIFTS[from..]`: the
/// start decides which isometric branch Gauss–Newton falls into; the first converged one
/// without a dent is kept (coarse levels keep tiny reflex folds, see DENT_SINE, which the finer
/// levels flip away), else the one of least strain. Returns it, whether it is good, and the
/// index of the next height to try (`LIFTS.len()` once a start failed to be good: all were tried).
pub(crate) fn multistart(
    pieces: &SeamPieces,
    tri: &[Triangulation; 2],
    from: usize,
    step_tol: f64,
    patience: Patience,
    steps: &mut (usize, usize),
) -> Option<(Vec<V3>, [Triangulation; 2], bool, usize)> {
    let mut best: Option<(Vec<V3>, [Triangulation; 2], bool, usize, f64)> = None;
    for (k, &lift) in LIFTS.iter().enumerate().skip(from) {
        let (mut x, mut t) = (initial_guess(pieces, lift), tri.clone());
        let budget = patience.cap.saturating_sub(steps.0).min(patience.attempt);
        let r = relax(pieces, &mut x, &mut t, budget, step_tol, Orientation::Free).tally(steps);
        let mut strain = max_strain(&x, &bars(pieces, &t));
        let otol = if step_tol > STEP_TOL { COARSE_OUTSIDE_TOL } else { OUTSIDE_TOL };
        let mut good = is_good_within(&x, &t, r.converged || (step_tol > STEP_TOL && strain <= LEVEL_STRAIN_TOL), otol);
        let mut converged = r.converged;
        // A failed start: restart it from the convex hull of where it ended, whose chords the
        // local flips could not reach ([`super::hull`]).
        if !good && patience.hull && steps.0 < patience.cap {
            if let Some(mut th) = hull::triangulations(&x, pieces) {
                let mut xh = x.clone();
                let budget = patience.cap.saturating_sub(steps.0).min(patience.attempt);
                let rh = relax(pieces, &mut xh, &mut th, budget, step_tol, Orientation::Kept).tally(steps);
                let sh = max_strain(&xh, &bars(pieces, &th));
                if sh < strain {
                    (x, t, strain, converged) = (xh, th, sh, rh.converged);
                    good = is_good_within(&x, &t, converged || (step_tol > STEP_TOL && strain <= LEVEL_STRAIN_TOL), otol);
                }
            }
        }
        if good {
            return Some((x, t, true, k + 1));
        }
        if best.as_ref().is_none_or(|b| strain < b.4) {
            best = Some((x, t, converged, k, strain));
        }
        if steps.0 >= patience.cap {
            break;
        }
    }
    best.map(|(x, t, converged, _, _)| (x, t, converged, LIFTS.len()))
}

/// A cold solve: multistart on the coarsest level (32 seam vertices), then each finer level
/// (64, 128, …) laid onto the last ([`upsample`]) and relaxed. Near-ties in the flips (chords
/// between nearly coplanar triangles) can tip a level into a wrong isometric branch that does
/// not converge; which way a tie tips depends on the last bits of libm (WASM and native
/// differ). So a branch whose level needs more than its budget of steps ([`QUICK`]), or ends unconverged
/// or dented, is abandoned and the whole coarse-to-fine path is retried from the next saddle
/// height. When no height gives a good start on the coarsest level (at some offsets the 32-gon's
/// only reachable branch is a collapsed one, strain ≈ 0.1), the ladder starts one level finer
/// (64, …). The last height of the last rung (or the last of the step budget) runs to the end.
/// The answer is the first good branch, else the best one that reached the finest level
/// (converged first, then least strain). Deterministic: heights and rungs in a fixed order.
/// All of this runs first with the [`QUICK`] budgets; only when that finds no good branch does
/// it run again with the [`PATIENT`] ones, up to `max_iterations` steps in all.
pub(crate) fn solve_cold(glue: &Glue, options: &SimulateOptions) -> Result<(SeamPieces, Solution)> {
    let n = options.resolution;
    let mut levels = vec![n];
    while levels[levels.len() - 1] % 2 == 0 && glue.nests(levels[levels.len() - 1] / 2) {
        levels.push(levels[levels.len() - 1] / 2);
    }
    levels.reverse();
    let mut samples: Vec<SeamPieces> = glue.sample_levels(&levels);
    let mut steps = (0usize, 0usize);
    let cap = options.max_iterations;
    let quick = Patience { cap: QUICK.cap.min(cap), ..QUICK };
    // A polygon pair is solved on its corners first (see [`solve_polyhedral`]); a solution with
    // seam crossings comes with the finest level's samples moved onto them.
    let mut best = None;
    let mut polyhedral = false;
    if let Some((moved, x, tri, converged)) = solve_polyhedral(&samples[samples.len() - 1], cap, &mut steps) {
        // Good only when exact: a polyhedral answer with a reflex chord has a crease crossing
        // the seam between samples that no chord mesh holds, and the intrinsic path below may
        // (two congruent 80 × 50 mm rectangles at 39, 40, 51, 60 and 62 mm, 256 seam vertices,
        // ended unsettled without it).
        let good = exact_if_polyhedral(&moved, &x, &tri);
        let pieces = samples.last_mut().expect("a level");
        *pieces = moved;
        best = Some((x, tri, converged, good));
        polyhedral = true;
    }
    if best.is_none() {
        best = ladder(&samples, &levels, quick, &mut steps)?;
    }
    // No good branch with the quick budgets: before grinding the chord meshes for the rest of
    // the steps, the intrinsic path ([`crossing`]), which also reaches creases across the seam.
    if !best.as_ref().is_some_and(|b| b.3) && steps.0 < cap {
        if let Some((pieces, x, tri)) = crossing::solve(&samples[samples.len() - 1], cap, &mut steps) {
            return Ok((pieces, Solution { x, tri, iterations: steps.0, flips: steps.1, converged: true }));
        }
    }
    if !best.as_ref().is_some_and(|b| b.3) && steps.0 < cap {
        let patient = ladder(&samples, &levels, Patience { cap, ..PATIENT }, &mut steps)?;
        if let Some(p) = patient {
            // Good first, then without a dent (a converged but dented shape is a wrong isometric
            // branch, further from the truth than an unconverged convex one), then converged,
            // then least strain.
            let rank = |b: &Branch| {
                let undented = worst_reflex(&b.0, &b.1) <= DENT_SINE;
                (b.3, undented, b.2, -max_strain(&b.0, &bars(&samples[samples.len() - 1], &b.1)))
            };
            if best.as_ref().is_none_or(|b| rank(&p) > rank(b)) {
                best = Some(p);
            }
        }
    }
    let (Some((x, tri, converged, good)), Some(pieces)) = (best, samples.into_iter().last()) else {
        return Err(Error::Infeasible { reason: "No start could be tried.".into() });
    };
    // Only the exact polyhedron is a converged polyhedral gluing (see [`exact_if_polyhedral`]),
    // and only a shape convex as a whole is converged (a good branch of the ladder was tested).
    let checked = good && !polyhedral;
    let converged = converged && exact_if_polyhedral(&pieces, &x, &tri) && (checked || convex_as_a_whole(&x, &tri));
    Ok((pieces, Solution { x, tri, iterations: steps.0, flips: steps.1, converged }))
}

/// A finest-level branch: positions, triangulations, converged, good (converged without a dent).
pub(crate) type Branch = (Vec<V3>, [Triangulation; 2], bool, bool);

/// One pass of the coarse-to-fine ladder with the step budgets of `patience` (see [`solve_cold`]):
/// the first good branch, else the best one that reached the finest level.
pub(crate) fn ladder(samples: &[SeamPieces], levels: &[usize], patience: Patience, steps: &mut (usize, usize)) -> Result<Option<Branch>> {
    let mut best: Option<(Vec<V3>, [Triangulation; 2], bool, f64)> = None;
    // Coarsest level of the ladder: 32 first; when no height gives a good start there (a
    // polygon that coarse can make a wrong branch the only one within reach), 64, and so on.
    'ladder: for first in 0..levels.len() {
        let coarse_tri = [triangulate(&samples[first], 0)?, triangulate(&samples[first], 1)?];
        let final_rung = first + 1 == levels.len();
        let coarse_tol = level_tol(final_rung);
        let mut from = 0;
        while from < LIFTS.len() {
            let Some((mut x, mut tri, mut converged, next)) =
                multistart(&samples[first], &coarse_tri, from, coarse_tol, patience, steps)
            else {
                break;
            };
            from = next;
            let out_of_steps = steps.0 >= patience.cap;
            if from >= LIFTS.len() && !final_rung && !out_of_steps {
                // No good start on this rung: climb to the next one.
                continue 'ladder;
            }
            let mut abandoned = false;
            for li in first + 1..levels.len() {
                let (pc, pf) = (&samples[li - 1], &samples[li]);
                let remaining = patience.cap.saturating_sub(steps.0);
                let retry = (from < LIFTS.len() || !final_rung) && remaining > 0;
                let full = if retry { remaining.min(patience.level) } else { remaining };
                // A polyhedral gluing gets the cone restart ([`cone_restart`]) after at most a
                // level's budget, then (on the last try) the rest of the steps.
                let polyhedral = hull::cone_vertices(pf).is_some();
                let budget = if polyhedral { full.min(patience.level) } else { full };
                let last = li + 1 == levels.len();
                let tol = level_tol(last);
                let (xf, tf, r, loose_level) = relax_level(pc, &x, &tri, pf, budget, patience.cap, last, steps)?;
                (x, tri, converged) = (xf, tf, r.converged);
                let mut loose = loose_level;
                if polyhedral && !is_good(&x, &tri, converged || loose) {
                    // Within the cap, like every other step (`max_iterations` is the user's).
                    let left = CONE_BUDGET.min(patience.level).min(patience.cap.saturating_sub(steps.0));
                    if let Some(c) = (left > 0).then(|| cone_restart(pf, &x, left, tol, steps)).flatten() {
                        (x, tri, converged) = c;
                        loose = false;
                    } else if full > r.iterations {
                        let r = relax(pf, &mut x, &mut tri, full - r.iterations, tol, Orientation::Kept).tally(steps);
                        converged = r.converged;
                        loose = level_loose(pf, &x, &tri, last);
                    }
                }
                if retry && !is_good(&x, &tri, converged || loose) {
                    abandoned = true;
                    break;
                }
            }
            if abandoned {
                continue;
            }
            let pieces = &samples[levels.len() - 1];
            if is_good(&x, &tri, converged) && exact_if_polyhedral(pieces, &x, &tri) && convex_as_a_whole(&x, &tri) {
                return Ok(Some((x, tri, true, true)));
            }
            let strain = max_strain(&x, &bars(pieces, &tri));
            if best.as_ref().is_none_or(|b| (converged, -strain) > (b.2, -b.3)) {
                best = Some((x, tri, converged, strain));
            }
            if steps.0 >= patience.cap {
                break 'ladder;
            }
        }
    }
    Ok(best.map(|(x, tri, converged, _)| (x, tri, converged, false)))
}

/// Steps a finer level of the ladder gets with the [`WARM`] damping before it falls back to the
/// cold one ([`relax_level`]): a level that starts from the coarser solution takes 7–21 steps
/// with it (the bench's crossed 2:1 ellipses and an ellipse with a circle, 64 to 256 seam
/// vertices), so one that needs more is not heading for the convex realization.
pub(crate) const LEVEL_WARM_BUDGET: usize = 50;

/// Relaxes a finer level `pf` of the ladder from the coarser solution `(xc, tc)` of `pc` laid
/// onto it ([`upsample`], [`refine`]): first with the [`WARM`] damping, within
/// [`LEVEL_WARM_BUDGET`] steps, and when that does not end good ([`is_good`]; on a level before
/// the last, within [`LEVEL_STRAIN_TOL`]) again from the same start with the cold damping and
/// the whole `budget` (within `cap` steps in all), as the level had before it tried the warm
/// damping: with only what the warm try left, two 2:1 ellipses at a quarter offset and 64 seam
/// vertices ran out at their first start and took 862 steps instead of 139. Relaxed to a step
/// of 1e-6 of the size, or of [`STEP_TOL`] on the `last` level. Returns the shape, its
/// triangulations, the relaxation kept (whose steps and flips are all the level took) and,
/// on a level before the last, whether its strain is within [`LEVEL_STRAIN_TOL`].
///
/// The upsampled start is isometric up to the coarse level's O(h²) error, the zero-residual
/// case in which undamped Gauss–Newton converges quadratically (see [`WARM`]). With the cold
/// schedule every flip pass restarted at λ = 1e-4 and shrank by 3 a step: the crossed ellipses
/// took 31 steps at 256 seam vertices where the warm damping takes 12 (131 → 98 steps in all,
/// native 9.7 → 7.6 ms; an ellipse with a circle 115 → 84, 8.3 → 6.5 ms), to the same
/// polyhedron (volume within 1e-8). The fallback is for the singular point of the length
/// equations, the flat doubly covered D-form (two 2:1 ellipses at half their perimeter), where
/// λ = 1e-10 amplifies round-off out of the plane and the level ends 8 % strained; the cold
/// damping keeps it flat. Alexandrov's uniqueness makes the good answers of both schedules the
/// same polyhedron, so trying the fast one first cannot pick another branch.
#[allow(clippy::too_many_arguments)]
fn relax_level(
    pc: &SeamPieces,
    xc: &[V3],
    tc: &[Triangulation; 2],
    pf: &SeamPieces,
    budget: usize,
    cap: usize,
    last: bool,
    steps: &mut (usize, usize),
) -> Result<(Vec<V3>, [Triangulation; 2], relax::Relaxed, bool)> {
    let tol = level_tol(last);
    let (mut x, mut tri) = laid_onto(pc, xc, tc, pf)?;
    let warm = relax_damped(pf, &mut x, &mut tri, budget.min(LEVEL_WARM_BUDGET), tol, Orientation::Kept, WARM).tally(steps);
    let warm_loose = level_loose(pf, &x, &tri, last);
    let left = budget.min(cap.saturating_sub(steps.0));
    if is_good(&x, &tri, warm.converged || warm_loose) || left == 0 {
        return Ok((x, tri, warm, warm_loose));
    }
    let (mut x, mut tri) = laid_onto(pc, xc, tc, pf)?;
    let mut cold = relax(pf, &mut x, &mut tri, left, tol, Orientation::Kept).tally(steps);
    cold.iterations += warm.iterations;
    cold.flips += warm.flips;
    let cold_loose = level_loose(pf, &x, &tri, last);
    Ok((x, tri, cold, cold_loose))
}

/// The coarser solution `(xc, tc)` of `pc` laid onto the finer level `pf`: its shape by
/// [`upsample`], its triangulations by [`refine`].
fn laid_onto(pc: &SeamPieces, xc: &[V3], tc: &[Triangulation; 2], pf: &SeamPieces) -> Result<(Vec<V3>, [Triangulation; 2])> {
    Ok((upsample(pc, xc, tc, pf), [refine(tc, pf, 0)?, refine(tc, pf, 1)?]))
}

/// The convex polyhedron of two convex sample polygons given as they are (no outlines behind
/// them: the sheet path's convex twins), on the ladder of their own every-other-vertex
/// subpolygons down to [`crate::simulate::seam::COARSEST`]; the quick pass, then the patient one.
/// `None` unless the finest level converged to a good (convex, undented) branch.
pub fn solve_samples(pieces: &SeamPieces, cap: usize) -> Option<Solution> {
    solve_samples_isometric(pieces, cap, 0.0).and_then(|(s, good)| good.then_some(s))
}

/// [`solve_samples`], also returning a converged branch that is not good (isometric but dented
/// or not convex as a whole), with whether it is good; and, when `near` is positive, the best
/// branch that did not converge but whose largest edge strain is within `near` (not good, its
/// `converged` false): a start for what relaxes it further, not an answer.
pub fn solve_samples_isometric(pieces: &SeamPieces, cap: usize, near: f64) -> Option<(Solution, bool)> {
    let mut levels = vec![pieces.n];
    while levels[levels.len() - 1] % 2 == 0 && levels[levels.len() - 1] / 2 >= super::seam::COARSEST {
        levels.push(levels[levels.len() - 1] / 2);
    }
    levels.reverse();
    let samples: Vec<SeamPieces> = levels.iter().map(|&m| pieces.every(pieces.n / m)).collect();
    let mut steps = (0usize, 0usize);
    let quick = Patience { cap: QUICK.cap.min(cap), ..QUICK };
    let mut best = ladder(&samples, &levels, quick, &mut steps).ok()?;
    if !best.as_ref().is_some_and(|b| b.3) && steps.0 < cap {
        best = ladder(&samples, &levels, Patience { cap, ..PATIENT }, &mut steps).ok()?;
    }
    let (x, tri, converged, good) = best?;
    let close = || near > 0.0 && max_strain(&x, &bars(&samples[samples.len() - 1], &tri)) <= near;
    (converged || close()).then_some((Solution { x, tri, iterations: steps.0, flips: steps.1, converged }, good && converged))
}
