//! The convex D-form when the chord meshes cannot hold it: embedded on an intrinsic
//! triangulation, whose creases may cross the seam.
//!
//! Every chord mesh of [`super::relax`] keeps its edges inside one piece, but a crease of
//! Alexandrov's polyhedron runs straight across the seam wherever both pieces are straight (two
//! congruent rectangles with rounded corners at an offset: from a corner of A across a side
//! both share into B). The chord flips then cannot reach the polyhedron at all: of the survey's
//! 384 gluings of a convex piece with a congruent copy of itself (`core/examples/
//! simulate_survey.rs`), 110 converged. This path gives up the restriction to chords:
//!
//! 0. the samples where both pieces run straight, points inside the polyhedron's faces rather
//!    than vertices of it, are left out ([`super::flat`]) and put back at the end;
//! 1. the two pieces' Delaunay chord triangulations become one intrinsic triangulation of the
//!    glued metric ([`super::intrinsic::Mesh`]);
//! 2. Bobenko & Izmestiev's method finds the polyhedron's triangulation and vertex positions
//!    ([`super::alexandrov::embed`]), flipping edges across the seam where it must, first with
//!    one edge per vertex pair and, where that stalls, with several ([`Mesh::multi`]);
//! 3. Levenberg–Marquardt on that fixed triangulation polishes the positions to its length
//!    equations ([`Frozen`]);
//! 4. the triangles are cut along the seam ([`super::overlay::cut`]), with a seam vertex where a
//!    crease crosses it, into a chord mesh of the two flat pieces like any other answer;
//! 5. that mesh is relaxed on the chord meshes' own length equations, with flips that make no
//!    cap ([`Chords::without_caps`]), and held to convexity as far as its sound faces can tell
//!    ([`sound`]).
//!
//! Of the survey's congruent gluings all 384 converge (74 of them with seam vertices added), all
//! 384 with a circle (the superellipses among them are solved as non-convex pairs: their
//! outlines bend inward between samples), and offsets that make one gluing give one volume.
//! Without the straight samples, an embedding that stalls within
//! [`NEWTON`] steps with one edge per vertex pair and [`MULTI_NEWTON`] with several, or an
//! answer whose step 5 does not settle within [`POLISHED_STRAIN`] (the chord meshes' length
//! equations, each seam edge at the mean of A's and B's chords, are not quite the metric that
//! was embedded), is the same search on every sample ([`solve`]).

use super::super::checks::{dent_depth, folded_flat, sound_outside, OUTSIDE_TOL};
use super::super::isometry::{bars, max_strain, Bar, STEP_TOL};
use super::super::metric::{KeyMap, Triangulation};
use super::super::seam::SeamPieces;
use super::super::vec3::V3;
use super::intrinsic::Mesh;
use super::relax::{relax_with, Chords, Flips, Orientation, WARM};
use super::{exact_if_polyhedral, triangulate};

/// Seam vertices up to which this path runs, counted without the straight ones
/// ([`super::flat`]). Its Newton systems are dense (`O(n³)` a step, ~2 ms native at 256, the
/// default resolution); at 512 a failed embedding would take ~10 s and at the largest
/// resolution (4,096) hours and 130 MB, so finer gluings keep the chord path alone. Rounded
/// rectangles keep few samples on their straight sides: two congruent 200 × 40 with 1 mm
/// corners at 4/16 keep under 256 of 512 and converge there in 50 ms native (they ended 36 %
/// stretched while the limit counted every sample).
pub(crate) const MAX_SEAM: usize = 256;

/// Newton steps allowed to [`super::alexandrov::embed`]: the survey's answers take 60–250.
pub(crate) const NEWTON: usize = 400;

/// Newton steps allowed to the embedding with several edges per vertex pair, after the one with
/// one edge per pair stalled: the survey's take 45–111.
pub(crate) const MULTI_NEWTON: usize = 200;

/// Levenberg–Marquardt steps of each polish: from the embedding (strain ~1e-6) it takes 2–60,
/// and from there to the chord mesh's own length equations up to a few hundred.
pub(crate) const POLISH: usize = 500;

/// Largest strain of the chord mesh's length equations ([`bars`]) accepted from the last polish.
/// The chord path asks [`super::super::isometry::STRAIN_TOL`] (1e-7). From the embedding, the
/// polish's flips restart the damping, and without caps ([`Chords::without_caps`]) some
/// realizations are out of reach: 500 steps end at 2–9e-7 on the two 200 × 40 rectangles with
/// 1 mm corners, and at 1.5–5e-6 on 200 × 40 with 8 mm corners, where 2,000 steps get no
/// further. 1e-5 (a micrometre on a 10 cm chord, a hundredth of what `converged` promises)
/// takes those: with 1e-6 the survey's congruent gluings found 315 of 384, with 1e-5 335.
pub(crate) const POLISHED_STRAIN: f64 = 1e-5;

/// The D-form of the sample polygons `pieces` (both convex) by the steps of the module docs:
/// the pieces with a seam vertex added where a crease crosses the seam, the positions and the
/// triangulations, when the answer is isometric to the length equations ([`POLISHED_STRAIN`]),
/// convex by its sound faces ([`sound`]) and [`exact_if_polyhedral`]; else `None`, also
/// beyond [`MAX_SEAM`] seam vertices. The Newton and LM steps are added to `steps`, and stop at
/// `cap` in all (the user's `max_iterations`). First without the straight samples
/// ([`super::flat`], when at least [`MIN_KEPT`] are left), then, if that finds nothing, on all:
/// without them two congruent 120 × 80 rectangles with 3 mm corners at 7/16 take 24 ms
/// instead of 146 (native, the same volume to 4e-6), the survey's congruent gluings solve 382
/// of 384 instead of 378, and none of its twins disagree (two 200 × 40 rectangles with 3 mm
/// corners at 0 and 8/16 gave 31,433 and 31,471 mm³ on all the samples, 31,121 and 31,120
/// without the straight ones). An answer dented beyond [`DENT_DEPTH`] (up to
/// [`NEAR_FLAT_DENT_DEPTH`]) is kept only when neither finds one within it.
pub(crate) fn solve(pieces: &SeamPieces, cap: usize, steps: &mut (usize, usize)) -> Option<Answer> {
    let mut dented: Option<(Answer, f64)> = None;
    let keep = super::flat::kept(pieces);
    if keep.len() < pieces.n && (MIN_KEPT..=MAX_SEAM).contains(&keep.len()) {
        let fewer = super::flat::only(pieces, &keep);
        let answer = solve_on(&fewer, cap, steps).and_then(|((cut, x, tri), dent)| Some((super::flat::put_back(pieces, &keep, &cut, &x, &tri)?, dent)));
        match answer {
            Some((a, dent)) if dent <= DENT_DEPTH => return Some(a),
            other => dented = other,
        }
    }
    if pieces.n > MAX_SEAM {
        return dented.map(|d| d.0);
    }
    match solve_on(pieces, cap, steps) {
        Some((a, dent)) if dent <= DENT_DEPTH || dented.as_ref().is_none_or(|d| dent < d.1) => Some(a),
        _ => dented.map(|d| d.0),
    }
}

/// What [`solve`] finds: the pieces with a seam vertex where a crease crosses the seam, the
/// positions and each piece's triangulation.
pub(crate) type Answer = (SeamPieces, Vec<V3>, [Triangulation; 2]);

/// Fewest samples left for [`super::flat`] to leave the straight ones out: four, the fewest
/// vertices of a polyhedron with volume (three cone points make a doubly covered triangle,
/// which the chord path gives). It was 8, and two triangles, which leave six, were solved on all
/// their samples, whose flat points stall the embedding: about 70 % of random triangles glued
/// to their copy, mirror image or a rotated copy ended stretched by 3–900 %. With six, 289 of
/// 300 converge (128 seam vertices), and random convex 3- to 10-gons with their copy, mirror
/// image, a rotated copy or another convex polygon 196 of 200 instead of 191.
pub(crate) const MIN_KEPT: usize = 4;

/// [`solve`] on the samples `pieces` as they are, with the answer's [`dent_depth`].
fn solve_on(pieces: &SeamPieces, cap: usize, steps: &mut (usize, usize)) -> Option<(Answer, f64)> {
    let left = |steps: &(usize, usize)| cap.saturating_sub(steps.0);
    let start = Mesh::from_chords(pieces, &[triangulate(pieces, 0).ok()?, triangulate(pieces, 1).ok()?])?;
    // One edge per vertex pair first; where that stalls after refusing a flip for want of a
    // second edge, again with several ([`Mesh::multi`]) on [`MULTI_NEWTON`] steps.
    let mut refused = 0;
    let (mut mesh, mut x) = [(false, NEWTON), (true, MULTI_NEWTON)].into_iter().find_map(|(multi, budget)| {
        if multi && refused == 0 {
            return None;
        }
        let mut mesh = start.clone().multi(multi);
        let mut newton = 0;
        let embedded = super::alexandrov::embed(&mut mesh, budget.min(left(steps)), &mut newton);
        steps.0 += newton;
        refused = mesh.refused();
        Some((mesh, embedded?))
    })?;
    relax_with(&mut Frozen { n: mesh.n, bars: mesh.bars() }, &mut x, POLISH.min(left(steps)), STEP_TOL, Orientation::Kept, WARM).tally(steps);
    mesh.flip_straight_angles();
    let (cut, mut xs, mut tri) = super::overlay::cut(&mesh, pieces, &x)?;
    // The intrinsic lengths of chords that flips put in come from layouts whose seam sides have
    // the mean of A's and B's chords, so they differ from the flat pieces' chords by about as
    // much as the two chords of a seam edge do (1 % at 16 seam vertices on a 3:1 ellipse). The
    // answer is held to the length equations every chord mesh is ([`bars`]: each chord at its
    // flat length), relaxed there from the embedding with the chord flips of [`super::relax`]
    // (which take out the folds of up to 5e-2 that this small change of metric leaves between
    // nearly coplanar triangles).
    relax_with(&mut Chords::without_caps(&cut, &mut tri), &mut xs, POLISH.min(left(steps)), STEP_TOL, Orientation::Kept, WARM).tally(steps);
    let isometric = max_strain(&xs, &bars(&cut, &tri)) <= POLISHED_STRAIN;
    let dent = sound(&cut, &xs, &tri).filter(|_| isometric && exact_if_polyhedral(&cut, &xs, &tri))?;
    Some(((cut, xs, tri), dent))
}

/// Largest [`dent_depth`] of an answer of this path, relative to its size. The chord meshes'
/// length equations differ from the embedded metric by up to the seam floor (~1e-3), and the
/// realization takes that up where it is softest: needle triangles between a long crease and
/// two seam samples a fraction of a step apart tilt, with out-of-plane sines up to 0.16 and dents
/// of 1e-4–7e-4 of the size on the survey's congruent rectangles. A wrong isometric branch
/// stands 0.3–1.8 sizes out ([`sound_outside`]).
pub(crate) const DENT_DEPTH: f64 = 2e-3;

/// Largest [`dent_depth`] of an answer taken when none is found within [`DENT_DEPTH`] ([`solve`]).
/// Near the offset where two congruent pieces fold flat the form is a thin pillow, and the
/// chord meshes' length equations dent it deeper: two 160 × 60 rectangles with 3 mm corners,
/// 0.36 mm from their flat gluing (2/16 and 10/16), came back dented by 5.3e-3 and were refused,
/// though the answer (25,658 mm³) is the pillow: 0.003 mm nearer the flat gluing it converges
/// within [`DENT_DEPTH`] to 25,535 mm³, and the offsets 1 and 4 mm either side give one volume
/// each (42,630 and 42,609; 83,120 and 83,141). Taken before an answer within [`DENT_DEPTH`],
/// such answers made two 200 × 40 rectangles with 1 mm corners at 4/16 and 12/16 (one gluing)
/// disagree by 0.11 %.
pub(crate) const NEAR_FLAT_DENT_DEPTH: f64 = 6e-3;

/// Whether the answer is convex, as far as its sound faces can tell: no dent deeper than
/// [`DENT_DEPTH`] (see [`NEAR_FLAT_DENT_DEPTH`]), no vertex beyond [`OUTSIDE_TOL`] above a face that is not a sliver
/// ([`sound_outside`]), and not folded flat. [`super::is_good`] and
/// [`super::super::checks::convex_as_a_whole`], which this path used before, read the sine of
/// every chord and the plane of every face, which needles and caps turn arbitrarily: they
/// refused 21 congruent gluings of the survey and 8 with a circle that this accepts. Those
/// answers are convex by their sound faces to about 2e-3 of their size; two congruent rectangles
/// give the same volume half a perimeter on (Alexandrov's uniqueness) to 1e-4 (one pair 1e-3),
/// and the triangle with 1 mm corners gives one volume at two offsets on a circle to 3e-10.
/// Returns the dent when the answer is sound with a dent up to [`NEAR_FLAT_DENT_DEPTH`].
fn sound(pieces: &SeamPieces, x: &[V3], tri: &[Triangulation; 2]) -> Option<f64> {
    let dent = dent_depth(x, tri);
    (dent <= NEAR_FLAT_DENT_DEPTH && sound_outside(x, tri, [&pieces.flat[0].pts, &pieces.flat[1].pts]) <= OUTSIDE_TOL && !folded_flat(x, tri)).then_some(dent)
}

/// Length equations on `n` vertices relaxed without flips: the polish of an embedding whose
/// triangulation is already the polyhedron's.
pub(crate) struct Frozen {
    pub(crate) n: usize,
    pub(crate) bars: Vec<Bar>,
}

impl Flips for Frozen {
    fn vertices(&self) -> usize {
        self.n
    }

    fn bars(&self) -> Vec<Bar> {
        self.bars.clone()
    }

    fn flip_pass(&mut self, _: &mut [V3], _: &mut [KeyMap; 2], _: Orientation) -> usize {
        0
    }
}
