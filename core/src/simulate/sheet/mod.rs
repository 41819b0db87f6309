//! The sheet path: a pair with a non-convex piece, solved as two inextensible elastic sheets.
//!
//! For convex pieces the glued surface is Alexandrov's unique convex polyhedron, and the convex
//! path finds it exactly with seam vertices only. A non-convex piece has no such theorem: the
//! physical D-form is the equilibrium of two elastic sheets glued edge to edge that (almost) do
//! not stretch and bend as little as they can, and its bending is no longer all on the seam.
//!
//! *Why interior vertices.* The seam-vertex polyhedron of a developable surface has the quads
//! between consecutive rulings planar, so each of their diagonals is an infinitesimal flex:
//! the length equations are singular exactly where the sheet is developable, and only the
//! convexity that the convex path enforces picks the right shape there. (Solving the exact
//! seam-vertex equations on rulings fitted to a relaxed sheet, tried at stop 18 and again
//! here, ends folded through itself.) So each flat piece is meshed with interior vertices
//! ([`flatmesh`]) and the glued mesh ([`glued`]) is relaxed as a discrete elastic shell
//! ([`shell`]: membrane + dihedral bending, Grinspun, Hirani, Desbrun & Schröder, "Discrete
//! shells", SCA 2003), whose bending energy settles those flexes.
//!
//! *Path.* Started from a far-off shape, a thick sheet's equilibrium is strained by tens of
//! percent, and thinning it compresses the pieces into wrinkles; started thin, a sheet crumples
//! (Surface Evolver does the same). So the sheet follows a homotopy ([`homotopy`]) from convex
//! twins of the pieces (same seam edge lengths, so the same gluing), whose D-form the convex
//! path solves exactly ([`twin_start`]), to the real pieces, as a thick sheet
//! ([`HOMOTOPY_KB`]), on a coarser mesh ([`level::homotopy`]), carried onto the fine one
//! ([`refine`]); then it is thinned on the fine mesh through [`SCHEDULE`] (the continuation of
//! Surface Evolver's elastic-sheet runs) and the answer is the thickest stage within [`STRAIN_TARGET`]
//! and sound: the least-bending equilibrium the path finds that meets the promise. When no twin
//! can be solved, the start is the convex path's own approximation ([`start`]). Every stage is
//! reported to an observer ([`crate::simulate::progress`]). A request of 256 or more seam
//! samples is solved so on a level of 128 to 255 of them and refined at the seam ([`level`]):
//! the sheet has several equilibria, and which one a path falls into is decided by its mesh.
//!
//! *What it does not do yet.* It follows one path, so "least-bending" is among the stages of
//! that path, not a search over equilibria. Where the path meets a bifurcation it can end in a
//! more bent one: a probe's peanut r = 50(1 − 0.25 cos 2θ) with a circle (a convex glued metric,
//! so its Alexandrov polyhedron exists: 113,545 mm³, bends of 2–4°), numbered from its waist, had
//! the convex path fail and the sheet end at 160,115 mm³ with bends of 85°, from a discrete
//! bending energy 6.6 times the other's. The same peanut built as the tests build outlines
//! (`polar`, 24–200 points, 16 offsets) is solved by the convex path every time, so the failure
//! hangs on the input's last bits. And the thin limit of a pair with a reflex corner creases the
//! circle along a short line across its inside (the L and the dart, each with a circle, and the
//! rounded star between its arms; the heart drawn with corners did too until its meshes were
//! made mirror-symmetric, [`mirror`], and now bends by 85°): about 18 mm long on the L, 30–35 mm
//! from its reflex corner, bent by 110–123° between two triangles. It is the equilibrium's, not
//! the path's or the mesh's: thinning in four times smaller steps, every twin share, 128 and 256
//! seam vertices and interior edges of 6.3, 4.7 and 3.1 mm end in the same crease (104–123°);
//! mirroring the sheet within 7–30 mm of it and relaxing again ends at 1.6–16 times the energy
//! (and mostly through itself), and a finer fan around its sharpest vertex only moves the bend
//! to either side of 90° (the heart's at 384 and 512 seam vertices is 95° and 88°: the 90° test
//! is a coin toss on a crease, which the heart at 512 wins). Surface Evolver, set up as in the
//! bench, crumples this pair (100 % strain, crossing facets) and gives no reference. Such answers
//! keep every edge within 1e-3 and do not cross; they are `converged: false` with the
//! [`crate::simulate::Shortfall::Fold`] that hosts word as a crease.
//!
//! *The mesh decides among nearby answers (stops 27–28).* For a given mesh the path is
//! deterministic, but the meshes turn on the samples' last bits: Delaunay refinement decides by
//! exact in-circle tests, a circle's samples are all but cocircular, and the seam weights
//! ([`crate::simulate::density`]) count each curvature sample in one bin. Until stop 28 the same
//! pair moved on the artboard got other triangles and another form (moved by (250.1, 400.9) mm
//! the L with a circle had 73,438 mm³ against 77,548, 256 seam vertices, native); now each
//! piece is taken in a frame of its own ([`crate::simulate::frame`]), and a moved pair is the
//! same to the last bit; since stop 43 so is a pair drawn in other units (the frames share a
//! unit taken from the first piece's size), which gave forms up to 6.6 % apart. A real edit
//! still draws another mesh: with one knot moved by 0.01 mm (a change of ~1e-4 of the volume)
//! in four ways, the kidney with a circle spreads by 0.01 %, the
//! Pebble by 0.2 %, the five lobes by 2 %, and the unconverged pairs with a reflex corner by
//! more (the heart drawn with corners 5 %, the L 14 %). The meshes
//! have many equilibria there, not one each: the five lobes' answer on one mesh, carried onto
//! a nudged copy's mesh ([`refine::carry`]) and relaxed at the same bending weight, settles
//! (in 25–75 steps, to a relative drop of 1e-9) at a volume between its own and that mesh's
//! answer, at 4–17 % more energy than the answer that mesh's own path found. Likely the
//! triangles' membrane locking: linear triangles held to 1e-3 strain bend isometrically only
//! about their own edges, and a bend of curvature κ across a triangle of side h strains it by
//! about (κh)²/8, 0.01 for the five lobes' lobes (κ ≈ 1/50 mm) at the interior edge of 15 mm.
//! At 3.5 seam steps instead of 5 ([`INTERIOR_EDGE`]) the five lobes reach 1e-3 a decade
//! thicker (kb/R² = 1e-6, strain 2.4e-4, where at 5 steps they need 1e-7) and four nudged copies
//! spread by 0.8 % instead of 1.4 %; at 4 steps one of four took the thicker stage and they
//! spread by 3.3 %; the kidney spreads by 1 % at 3 steps and falls from converged at 3.5 and 4
//! (native, stop 28). So the way on is a membrane that does not lock at this mesh size (edges
//! along the rulings, or strain measured on a coarser set than the bending), not a finer mesh:
//! at 3 steps the five lobes' mesh has 2,261 vertices against 1,267.
//!
//! *Where the five lobes' answer is held (stop 45, 256 seam vertices, native).* Their piece is
//! ruled as a developable sheet must be: its chords of 3–5 interior edges between seam samples
//! are straight in 3D to 5e-5–4e-4 of their length, and it bends by at most 14° across an edge.
//! The circle is not: its middle is flat (bends of 0.1–0.4°), and its bending is packed into
//! five ridges, one per lobe (its edges bent by over 20° lie in five sectors of about 50°, with
//! none between), at 40–80 % of its radius: 7–10° across an edge on average there, up to 52–57°
//! (two draws). No chord of it longer than three interior edges is straighter than 2.8e-3 of its
//! length, three times the sheet's largest strain. Likely a thin sheet's ridge, which narrows
//! with the thickness (Lobkovsky, "Boundary layer analysis of the ridge singularity in a thin
//! plate", PRE 53, 1996): at the thin limit its width is the mesh's, and the volume follows how
//! each mesh resolves it. Over eight draws of the meshes ([`crate::simulate::frame`] sizes
//! 90–160) the volumes at 128, 192 and 256 seam vertices spread by 0.7–4.2 %; with the circle's
//! interior triangles half as long (four times as many) by 0.4–3.0 %; refined beside every edge
//! of the answer bent by more than 10° or 20° ([`adapt::bent_centroids`]) and thinned again from
//! 1e-5, by 0.9–3.6 % and 0.9–5.7 %; with 28 of the lobes' straight chords kept as lines of
//! vertices (a mesh along their rulings) and thinned again, by 0.3–4.1 %. None was kept.
//!
//! *Saddles.* Where a concave stretch of one piece meets the other, the seam carries negative
//! curvature, and each piece's fan at a seam sample must bend along an edge into the piece. The
//! thinning's mesh has short rows of vertices there ([`saddle`]); without them two organic
//! blobs locked strained at 9 of 120 random gluings (2 with them), and the five lobes with a
//! circle moved by 3.4 % between 128, 192 and 256 seam vertices (0.7 % with them).
//!
//! *Locks.* Where both pieces are concave at one place (two blobs whose bays meet, a piece with
//! its mirror image at a small offset) the rows do not free the sheet, and a few edges stay
//! stretched at every bending weight; and on a smooth pair a line of high curvature can bend by
//! just over 90° between two triangles, a fold of the mesh rather than a crease of the form.
//! Either sheet is refined where it is held and thinned again ([`adapt`]): of 240 random pairs
//! of two blobs 238 converge instead of 219, and so do the kidney and the blob with their mirror
//! images at 1/16 and the kidney with a circle at 128 seam vertices.
//!
//! *Far off.* A few pairs end strained by percents or through themselves from every twin share
//! (the kidney with a congruent copy at 1/16 collapses through itself at the homotopy's last
//! blend; the drawn heart with its copy at 3/16). Followed again as a thinner or thicker sheet
//! ([`retry`]), the kidney converges and the drawn heart ends isometric and uncrossed. The
//! smooth heart with its copy, through itself on every such path, is followed again with the
//! sheets pushing each other back where they touch ([`contact`]).
//!
//! - [`flatmesh`]: each piece meshed by constrained Delaunay refinement, seam samples kept;
//! - [`mirror`]: a mirror-symmetric pair's pieces meshed as a half and its reflection;
//! - [`saddle`]: the rows of vertices beside the seam where it is a saddle;
//! - [`adapt`]: the mesh refined where the thin sheet stays stretched or folds;
//! - [`retry`]: the homotopy followed again at other bending weights when the sheet ends far off;
//! - [`contact`]: the sheets pushed back where they touch, for the last of those paths;
//! - [`glued`]: the two meshes glued on the seam, and the shell's terms on them;
//! - [`hinge`]: the dihedral angle of two triangles and its gradient;
//! - [`shell`]: the energy and its Levenberg–Marquardt minimization;
//! - [`morph`], [`tutte`], [`homotopy`]: the convex twins, the meshes carried onto them, and the
//!   homotopy of the metric back to the pieces;
//! - [`start`]: a polyhedron's shape carried onto the finer mesh;
//! - [`level`]: the seam level a pair is solved on, whatever the resolution, and refined from;
//! - [`refine`]: a sheet's shape on a coarser mesh carried onto a finer one;
//! - [`finish`]: soundness (folds, crossings), the result as a [`crate::simulate::Simulation`]
//!   and its stats.

pub mod adapt;
pub mod contact;
pub mod finish;
pub mod flatmesh;
pub mod glued;
pub mod hinge;
pub mod homotopy;
pub mod level;
pub mod mirror;
pub mod morph;
pub mod refine;
pub mod retry;
pub mod saddle;
pub mod shell;
pub mod start;
pub mod tutte;

use super::checks::faces_cross;
use super::mesh::Solution;
use super::progress::Reporter;
use super::seam::SeamPieces;
use super::vec3::V3;
use super::Simulation;
pub use glued::SheetMesh;
use shell::Shell;

/// Interior edge length of the meshes as a share of the perimeter `L`: the triangles grow from
/// the seam step at the boundary to about this inside. It is a length of the form, not a
/// number of seam steps, so that the sheet is as stiff at every seam resolution: at 6 seam
/// steps whatever the resolution, the five-lobed shape with a circle had a volume 2.4 % lower
/// at 128 seam vertices than at 256 (its coarser interior stiffer); at one length for both,
/// 0.3 %. At 256 seam vertices this is 5 steps (the Pebble with a circle: 1,307 vertices). At 6
/// steps the blob with a circle bent by 92° across one hinge and the kidney by 109°, at 5 by
/// 59° and 87°; at 2.5 steps the Pebble has 3,078 vertices and takes 10 s native, and its
/// volume moves by 0.05 %.
pub const INTERIOR_EDGE: f64 = 5.0 / 256.0;

/// The thinning's bending weights, as `kb / R²` (`R = L/2π`, the radius of a circle of the
/// seam's length): `√kb / R` is about the sheet's relative thickness. The strain falls about
/// as `kb^0.4`; at 256 seam vertices the organic pairs reach 1e-3 between 1e-7 (Pebble, five
/// lobes) and 1e-8 (kidney, each with a circle), the kidney with a 2:1 ellipse at 1e-9. A
/// thinner stage only costs the pairs that reach it.
///
/// One stage per decade: with two (3e-5, 1e-5, 3e-6, …, down to 3e-10, until stop 21) the
/// answers were the same equilibria (volumes within 0.5 %, Pebble, kidney, kidney with an
/// ellipse, five lobes and blob with a circle) at 1.2–1.5 times the fresh factorizations
/// (kidney 87 → 57, five lobes 79 → 54), the waypoints in between being relaxed only loosely
/// anyway ([`WAYPOINT_RTOL`]).
pub const SCHEDULE: [f64; 6] = [1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10];

/// Homotopy steps from the convex twins, and the bending weight (`kb/R²`) the sheet follows
/// them at: a thick sheet, strained by a few percent, that stays smooth. Each intermediate
/// step gets [`HOMOTOPY_STAGE_STEPS`] steps and ends at a relative energy drop of
/// [`HOMOTOPY_RTOL`]. 8 fully converged steps end in the same equilibria (Pebble, kidney, blob
/// and L with a circle, 256 seam vertices) as 4 loose ones, in 2.3× the time. Followed at 1e-5
/// instead, the five-lobed shape with a circle ended in an equilibrium that bends more (discrete
/// bending energy 141 against 127, volume 136,011 against 144,293 mm³; Surface Evolver's is
/// 149,152), and 2.9 % apart at 128 and 256 seam vertices; from 1e-4 up to 1e-3 the same one.
pub const HOMOTOPY_STEPS: usize = 4;
pub const HOMOTOPY_KB: f64 = 1e-4;
pub const HOMOTOPY_STAGE_STEPS: usize = 20;
pub const HOMOTOPY_RTOL: f64 = 1e-3;

/// How a path from the twins is followed ([`follow`]): the homotopy's bending weight (`kb /
/// R²`), and whether and where the sheets push each other back ([`Touch`], [`contact`]).
#[derive(Debug, Clone, Copy)]
pub struct Path {
    pub kb: f64,
    pub touch: Touch,
}

/// The self-contact of a path's sheet ([`contact`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Touch {
    /// None: the sheets may pass through each other.
    Free,
    /// A vertex is kept off the faces that are not its neighbours.
    Faces,
    /// That, and the two pieces do not close through each other across the seam.
    FacesAndSeam,
}

impl Path {
    /// The homotopy at bending weight `kb`, without contact.
    pub fn plain(kb: f64) -> Self {
        Path { kb, touch: Touch::Free }
    }

    /// The shell of `mesh`, with the path's contact.
    pub fn shell(&self, pieces: &SeamPieces, mesh: &SheetMesh) -> Shell {
        let mut shell = mesh.shell();
        if self.touch != Touch::Free {
            shell.contact = Some(contact::Contact::on(pieces, mesh, self.touch == Touch::FacesAndSeam));
        }
        shell
    }
}

/// The first path's homotopy on the level ([`level::homotopy`] along
/// [`Path::plain`]`(`[`HOMOTOPY_KB`]`)`), computed once per request. The level's own solve
/// ([`level::solve`]) starts from it, and so does the requested samples' own path ([`own`]) when
/// the level's answer is not kept: the level's samples are the requested ones every
/// [`level::stride`]-th (a level's own level is itself), and the homotopy runs on them alone, so
/// both computed the same thing. Until stop 55 each did: the kidney with its copy at 13/16
/// reported the same four strains twice (2.58e-2 … 1.58e-1), 39 ms native (at 14/16, 44 ms).
#[derive(Default)]
pub struct FirstStart {
    /// The level's number of samples and its homotopy's end, once computed (`None` inside when
    /// no twin pair of the level could be solved).
    known: Option<(usize, Option<level::Start>)>,
}

impl FirstStart {
    /// The level's homotopy along the first path for `pieces` (a request or its level), from
    /// memory when it was computed for the same level (its stages then skipped in `report`).
    pub fn get(&mut self, pieces: &SeamPieces, report: &mut Reporter) -> Option<&level::Start> {
        let level = level::stride(pieces.n).map(|s| pieces.n / s);
        match &self.known {
            Some((n, start)) if Some(*n) == level => {
                if start.is_some() {
                    report.skip(HOMOTOPY_STEPS);
                }
            }
            _ => self.known = level.map(|n| (n, level::homotopy(pieces, Path::plain(HOMOTOPY_KB), report))),
        }
        self.known.as_ref()?.1.as_ref()
    }
}

/// Shares of a circle's turning in the convex twins, tried in order ([`morph::Morph`]).
pub const TWIN_CIRCLE_SHARES: [f64; 3] = [0.25, 0.5, 0.75];

/// Step budgets of the convex path on a pair with a non-convex piece: its first pass, which
/// keeps its answer only when that meets every promise (the flat doubly covered form of
/// congruent pieces), and the patient solve that gives the sheet its start when no twin can be
/// solved ([`Outcome::NeedsStart`], [`from_start`]) or the sheet ends crumpled ([`CRUMPLED`];
/// then the less strained of the two is the answer). The first pass ran 1,500
/// steps until stop 28; a pair whose twins start a converged sheet only needs 300 and ends the
/// same to the last bit: 24–34 ms native of 280–680 saved (Pebble, kidney, five lobes with a
/// circle, 256 seam vertices), three to four times that in WASM.
pub const START_BUDGET: usize = 300;
pub const FALLBACK_BUDGET: usize = 1500;

/// Strain (over [`STRAIN_TARGET`]) beyond which an unconverged sheet is far off: followed again
/// on other paths ([`retry::far_off`]), not refined as a lock ([`adapt::BELOW`]), and not solved
/// again from the second start ([`crate::simulate::anchor::retry`]).
pub const FAR_ABOVE: f64 = 10.0;

/// Strain up to which an unconverged sheet is the answer without the patient convex solve
/// ([`FALLBACK_BUDGET`]); beyond it the sheet is crumpled, not squeezed (which also ends the
/// touching paths, [`retry::TOUCH_BELOW`]), and the convex path's answer, when less strained, is
/// the better approximation.
///
/// On a pair with a non-convex piece the convex path ends strained by 1–46 % (issue 14's table;
/// the smooth-cusp heart's 1,500 steps: 11 %). Over the 309 pairs of the survey (256 seam
/// vertices, native: 120 random pairs of two blobs, six drawings with their copies and mirror
/// images at 1–15/16, nine drawings with a circle), 27 sheets ended beyond 1e-2, the bound
/// until stop 52. Their patient solves took 0.2–0.84 s each and ended strained by 10.5 % to
/// 272 %. The 26 sheets strained by 1.4–9.1 % were less strained every time, so the patient
/// solve only cost time: the kidney with its copy at 13/16 and 14/16 spent 0.54 and 0.68 s
/// there. The one it beat was crumpled: 42 % against a sheet's 96 % (the smooth heart with its
/// mirror image at 15/16, from its second start, where the first start's 5.6e-3 was the
/// answer either way).
pub const CRUMPLED: f64 = 0.2;

/// Step budget of one convex solve of the twins ([`twin_start`]), and the strides of the seam
/// samples it is tried on. At 256 seam vertices the twins that solve take 100–280 steps; the
/// five-lobed shape's twin with a circle does not solve on all 256 samples in 1,500 (a level
/// that ends 3.6e-5 strained and dented, while the same twin with the circle shrunk by 1e-4
/// solves in 44 steps), but does on every other one; the heart's on every fourth.
pub const TWIN_BUDGET: usize = 500;
pub const TWIN_STRIDES: [usize; 4] = [1, 2, 4, 8];

/// Largest edge strain of a twin polyhedron the convex path did not converge on that still
/// starts the homotopy ([`twin_start`]): the homotopy's thick sheet ([`HOMOTOPY_KB`]) is strained
/// by percents, so a start this close to isometric starts it as well as an exact one. The rounded
/// star's twins with a circle end within 3e-4 in 500 steps at every share on every fourth of 128
/// seam samples, and never converge, in 8,000 steps at any stride either: the convex path's
/// flips do not settle (up to twice as many flips as steps). At 128 seam vertices no
/// twin of it was solved, and from the fallback start it ended 28 % strained, folded back
/// (174°) at 1.57e5 mm³ against 2.13e5 at 256; with such a start it ends at 5.2e-3 (its seam
/// samples' floor there is 4e-3) and 2.08e5 mm³. At 256 the coarse level's twins now start it,
/// which its own shortcut ([`level::homotopy`]) had missed: 0.54–0.62 s native instead of
/// 0.96–1.2. Every other pair of the tests and the bench keeps its start, and its answer bit
/// for bit: its twins converge before any near one is met (the same from 3e-4 to 3e-3 here).
pub const TWIN_NEAR: f64 = 1e-3;

/// Step budget of the last try at the twins, on the coarsest of [`TWIN_STRIDES`] only, when
/// none was solved within [`TWIN_BUDGET`]. The rounded star's twins with a circle are solved,
/// dented, only at stride 8 and only near the budget: 500 steps were enough for the star but
/// not for the same star 5e-13 larger (nor for the WASM build's, whose libm differs in the last
/// bits), which then started from the fallback and ended 24 % strained and through itself.
/// At 2,000 steps every share's twin solves for both, in 16 ms native (32 seam vertices).
pub const TWIN_RESCUE_BUDGET: usize = 2000;

/// Largest edge strain of an answer that counts as inextensible (requirement 1 of issue 14).
pub const STRAIN_TARGET: f64 = 1e-3;

/// Levenberg–Marquardt steps per stage, and the relative energy drop that ends a stage that
/// may be the answer.
pub const STAGE_STEPS: usize = 60;
pub const STAGE_RTOL: f64 = 1e-7;

/// The relative energy drop that ends a stage on the way ([`thin`]), and the strain (over
/// [`STRAIN_TARGET`]) below which a loosely relaxed stage is relaxed on as a candidate answer.
/// Between the loose and the tight tolerance a waypoint's volume moves by less than 0.5 %
/// (Pebble, five lobes and kidney with a circle, 256 seam vertices), and loose waypoints take
/// about half the thinning's steps.
pub const WAYPOINT_RTOL: f64 = 1e-4;
pub const POLISH_NEAR: f64 = 1.5;

/// A thinning stage above `STALL_ABOVE` times [`STRAIN_TARGET`] whose sheets cross, or whose
/// strain fell by less than `STALL_DROP` of the stage before, ends the thinning ([`thin`]). A
/// sheet on its way to an answer loses 5–60 % of its strain per half decade of `kb` (five
/// lobes with a circle: 0.0185, 0.0175, 0.0085, …; kidney: 0.108, 0.066, 0.031, …), 65–80 % per
/// decade (kidney: 0.065, 0.015, 0.0038, …); the dart's, stuck in
/// the fallback start, kept 0.622 to three digits through every stage.
pub const STALL_ABOVE: f64 = 10.0;
pub const STALL_DROP: f64 = 0.01;

/// Stages of a non-convex pair's solve, for [`crate::simulate::progress`]: the convex path's
/// first pass, the homotopy's steps, the thinning's stages and the rounds of refinement where
/// the sheet locks ([`adapt`]), and the other paths a far-off sheet is followed on
/// ([`retry`]: one per weight of [`retry::KB`], and one per contact of [`retry::TOUCH`]).
pub const STAGES: usize = 1 + HOMOTOPY_STEPS + SCHEDULE.len() + adapt::ROUNDS + retry::KB.len() + retry::TOUCH.len();

/// What a relaxation did.
#[derive(Debug, Clone)]
pub struct Relaxed {
    pub x: Vec<V3>,
    pub steps: usize,
    pub max_strain: f64,
    /// Within [`STRAIN_TARGET`] and sound.
    pub converged: bool,
    /// The bending weight (`kb / R²`) of the last stage relaxed, `f64::INFINITY` before any.
    pub stage: f64,
}

/// Thins the sheet from `x` through the bending weights `schedule`, stopping at the first
/// (thickest) stage whose equilibrium is within [`STRAIN_TARGET`] and sound, within `budget`
/// steps in all. A stage is first relaxed loosely ([`WAYPOINT_RTOL`]): one still well above the
/// target is only a waypoint to the next. One near or within it ([`POLISH_NEAR`]) is relaxed on
/// to [`STAGE_RTOL`] and then judged.
///
/// A stage is polished only when the promise can be kept at all: when the seam samples' floor
/// ([`Shell::strain_floor`]) is above [`STRAIN_TARGET`], no stage is within it, and the polish
/// would only trade time for a strain that stays above it (the rounded star with a circle,
/// floor 1.07e-3 at 256 seam vertices: its last stage's polish took 270 of 960 ms native to go
/// from 1.4e-3 to 1.32e-3).
///
/// The stages at and below [`shell::TIPLESS_KB`] solve with the sparser normal equations of
/// [`Shell::set_tip_blocks`] (same energy, same equilibria, a fifth of the factorization).
///
/// It also stops, unconverged, where thinner stages cannot help: at a stage within the strain
/// target that is unsound (a fold or a crossing only gets sharper as the sheet gets thinner),
/// and at one still above [`STALL_ABOVE`] times the target whose sheets cross or whose strain
/// did not fall by [`STALL_DROP`] from the stage before. The heart, the rounded star and the
/// dart with a circle, each from the fallback start, ran all of the eleven stages the schedule
/// then had, at 12–600 % strain, in 1–3 s.
pub fn thin(shell: &mut Shell, mut x: Vec<V3>, radius: f64, budget: usize, schedule: &[f64], faces: &[[usize; 3]], report: &mut Reporter) -> Relaxed {
    let mut steps = 0;
    let mut lambda: f64 = 1e-3;
    let mut out = Relaxed { x: x.clone(), steps: 0, max_strain: shell.max_strain(&x), converged: false, stage: f64::INFINITY };
    let mut before = f64::INFINITY;
    let reachable = shell.strain_floor() <= STRAIN_TARGET;
    for &beta in schedule {
        let kb = beta * radius * radius;
        shell.set_tip_blocks(beta > shell::TIPLESS_KB);
        lambda = lambda.min(1e-3);
        steps += shell.minimize(&mut x, kb, STAGE_STEPS.min(budget.saturating_sub(steps)), WAYPOINT_RTOL, &mut lambda);
        let mut strain = shell.max_strain(&x);
        if reachable && strain <= POLISH_NEAR * STRAIN_TARGET {
            steps += shell.minimize(&mut x, kb, STAGE_STEPS.min(budget.saturating_sub(steps)), STAGE_RTOL, &mut lambda);
            strain = shell.max_strain(&x);
        }
        let within = strain <= STRAIN_TARGET;
        let converged = within && finish::sound(&x, shell, faces);
        out = Relaxed { x: x.clone(), steps, max_strain: strain, converged, stage: beta };
        report.stage(strain);
        let stalled = strain > STALL_ABOVE * STRAIN_TARGET && (strain > (1.0 - STALL_DROP) * before || faces_cross(&x, faces));
        if within || stalled || steps >= budget {
            break;
        }
        before = strain;
    }
    out
}

/// The convex twins ([`homotopy`]) and their polyhedron: each piece's own bulges with a quarter
/// of a circle's turning mixed in, or rounder ones ([`TWIN_CIRCLE_SHARES`]), solved on the seam
/// samples or, when those cannot be solved within [`TWIN_BUDGET`], on every other one, every
/// fourth, every eighth ([`TWIN_STRIDES`]), and last on the coarsest with a larger budget
/// ([`TWIN_RESCUE_BUDGET`]) when `rescue` is set. Returns the homotopy, the sample polygons solved and
/// their polyhedron: the first the convex path found convex, or isometric but dented, or within
/// [`TWIN_NEAR`] of isometric (the rounded star's twins with a circle have no other within reach
/// at any stride, and from such a twin the star's sheet ends within 1.5e-3 strain, no crossing,
/// where from the fallback start it ended 11–18 % strained and through itself).
///
/// The search ends at the first of any kind: a start near isometric starts the thick homotopy
/// as well as an exact one ([`TWIN_NEAR`]). Until stop 27 a dented or near twin only ended it
/// when no convex one followed, and across the core tests none ever did (every pair that met one
/// used it), so those tries only cost time: the rounded star's at 256 seam vertices tried 6 more
/// twins after its first near one, 25–40 ms native of its homotopy's first stage (~100 ms).
///
/// Starting from the convex path's approximation of twins it could not solve, at whatever
/// strain, did worse than the fallback start (the five-lobed shape with a circle ended with
/// crossing sheets; [`TWIN_NEAR`] admits only one within 1e-3 of isometric), and so
/// did smooth outlines through the twins solved as curves (other equilibria at 128 and 256
/// seam vertices, 2 % apart).
pub fn twin_start(pieces: &SeamPieces, mesh: &SheetMesh, rescue: bool) -> Option<(homotopy::Homotopy, SeamPieces, Solution)> {
    let strides: Vec<usize> = TWIN_STRIDES.iter().copied().filter(|&s| pieces.n % s == 0 && pieces.n / s >= super::seam::COARSEST).collect();
    // The twins tried so far (each an embedding of both meshes), for the last try below.
    let mut built = Vec::new();
    for &share in &TWIN_CIRCLE_SHARES {
        let Some(h) = homotopy::Homotopy::new(pieces, mesh, share) else { continue };
        let twin = h.twin_pieces(pieces);
        for &stride in &strides {
            let coarse = twin.every(stride);
            if let Some((sol, _)) = super::convex::solve_samples_isometric(&coarse, TWIN_BUDGET, TWIN_NEAR) {
                return Some((h, coarse, sol));
            }
        }
        built.push((h, twin));
    }
    if !rescue {
        return None;
    }
    // None within the budget: the coarsest samples, patiently, before the fallback start.
    let &stride = strides.last()?;
    built.into_iter().find_map(|(h, twin)| {
        let coarse = twin.every(stride);
        super::convex::solve_samples_isometric(&coarse, TWIN_RESCUE_BUDGET, TWIN_NEAR).map(|(sol, _)| (h, coarse, sol))
    })
}

/// The homotopy from convex twins ([`homotopy`]) on `mesh` itself (`rescue`: see
/// [`twin_start`]): the twins' polyhedron
/// carried onto it and relaxed through [`HOMOTOPY_STEPS`] blends of the rest lengths. Returns
/// the shell (its rest lengths the pieces' at the end), the shape at the last step and the
/// steps taken, the twins' solve included. `None` when no twin pair can be built and solved.
fn homotopy_on(pieces: &SeamPieces, mesh: &SheetMesh, rescue: bool, path: Path, report: &mut Reporter) -> Option<(Shell, Vec<V3>, usize)> {
    let (h, coarse, sol) = twin_start(pieces, mesh, rescue)?;
    let twin_flat = h.twin_flat();
    let mut x = start::lift_onto([&coarse.flat[0].pts, &coarse.flat[1].pts], &sol, mesh, &twin_flat);
    let mut shell = path.shell(pieces, mesh);
    let radius = pieces.flat[0].perimeter / std::f64::consts::TAU;
    let mut lambda: f64 = 1e-3;
    let mut steps = sol.iterations;
    for k in 1..=HOMOTOPY_STEPS {
        let t = k as f64 / HOMOTOPY_STEPS as f64;
        shell.set_rest_blend(&twin_flat, &mesh.flat, t);
        lambda = lambda.min(1e-3);
        // The way there is only followed; the last step's equilibrium is the one thinned.
        let (rt, st) = if k == HOMOTOPY_STEPS { (WAYPOINT_RTOL, STAGE_STEPS) } else { (HOMOTOPY_RTOL, HOMOTOPY_STAGE_STEPS) };
        steps += shell.minimize(&mut x, path.kb * radius * radius, st, rt, &mut lambda);
        report.stage(shell.max_strain(&x));
    }
    Some((shell, x, steps))
}

/// The homotopy from convex twins ([`homotopy`]) on the coarser mesh of the samples' level where
/// there is one ([`level::homotopy`]), else on `mesh` (on its plain version when `mesh` is
/// `layered` with rows beside saddles, [`saddle`]); then the thinning on `mesh` through the
/// stages of [`SCHEDULE`] thinner than the homotopy's bending
/// weight (`path.kb`, as `kb / R²`: [`HOMOTOPY_KB`] first, [`retry::KB`] when that ends far
/// off), with the path's self-contact ([`Touch`], [`retry::CONTACT_KB`]). On the first path
/// (plain, at [`HOMOTOPY_KB`]) the level's homotopy is taken from `first` when given
/// ([`FirstStart`]). `None` when no twin pair can be built and solved.
pub fn follow(pieces: &SeamPieces, mesh: &SheetMesh, layered: bool, path: Path, first: Option<&mut FirstStart>, budget: usize, report: &mut Reporter) -> Option<(Shell, Relaxed)> {
    let computed;
    let start = match first {
        Some(known) if path.kb == HOMOTOPY_KB && path.touch == Touch::Free => known.get(pieces, report),
        _ => {
            computed = level::homotopy(pieces, path, report);
            computed.as_ref()
        }
    };
    let (mut shell, x, steps) = match start {
        Some(start) => (path.shell(pieces, mesh), refine::carry(&start.mesh, &start.x, mesh)?, start.steps),
        None if layered => {
            // The homotopy on the plain mesh ([`saddle`]), carried onto the layered one.
            let plain = SheetMesh::new(pieces, INTERIOR_EDGE)?;
            let (_, x, steps) = homotopy_on(pieces, &plain, true, path, report)?;
            (path.shell(pieces, mesh), refine::carry(&plain, &x, mesh)?, steps)
        }
        None => homotopy_on(pieces, mesh, true, path, report)?,
    };
    let radius = pieces.flat[0].perimeter / std::f64::consts::TAU;
    let faces: Vec<[usize; 3]> = mesh.faces.iter().flatten().copied().collect();
    let thinner: Vec<f64> = SCHEDULE.iter().copied().filter(|&b| b < path.kb).collect();
    report.skip(SCHEDULE.len() - thinner.len());
    let mut relaxed = thin(&mut shell, x, radius, budget.saturating_sub(steps), &thinner, &faces, report);
    relaxed.steps += steps;
    Some((shell, relaxed))
}

/// What the sheet path made of a pair ([`simulate`]).
pub enum Outcome {
    /// The sheet's answer and its largest edge strain.
    Sheet(Simulation, f64),
    /// A piece could not be meshed.
    Unmeshed,
    /// No twin pair could be built and solved: the sheet starts from the convex path's patient
    /// answer ([`FALLBACK_BUDGET`], [`from_start`]).
    NeedsStart,
}

/// The sheet path for a pair with a non-convex piece, from its convex twins ([`follow`]),
/// refined where its mesh holds it ([`adapt`]), and followed again at other bending weights
/// when it ends far off ([`retry`]); `iterations` are the steps taken before. From 256 seam
/// samples on, the pair is solved so on its level and refined at the seam ([`level::solve`]),
/// and on its own samples ([`own`]) only when that fails.
pub fn simulate(pieces: &SeamPieces, iterations: usize, budget: usize, report: &mut Reporter) -> Outcome {
    let solved = match level::stride(pieces.n) {
        Some(s) if s > 1 => {
            let mut start = FirstStart::default();
            level::solve(pieces, s, iterations, budget, &mut start, report).map_or_else(|| own(pieces, &mut start, budget, report), Ok)
        }
        _ => own(pieces, &mut FirstStart::default(), budget, report),
    };
    match solved {
        Ok(a) => Outcome::Sheet(finish::simulation(pieces, &a.mesh, &a.shell, &a.relaxed.x, iterations + a.relaxed.steps, a.relaxed.converged), a.relaxed.max_strain),
        Err(outcome) => outcome,
    }
}

/// The sheet path on `pieces`' own samples: from its convex twins, refined where its mesh holds
/// it ([`adapt`]), and followed again at other bending weights when it ends far off
/// ([`retry`]); its first path's homotopy is `start`'s, when the level's solve computed it.
/// `Err` when a piece cannot be meshed or no twin pair can be solved.
pub fn own(pieces: &SeamPieces, start: &mut FirstStart, budget: usize, report: &mut Reporter) -> Result<retry::Attempt, Outcome> {
    let (mesh, saddles, first) = first(pieces, start, budget, report)?;
    Ok(retry::others(pieces, &mesh, &saddles, first, budget, report))
}

/// The first path of [`own`] (before any of [`retry`]): the mesh with its saddle rows, the
/// saddle samples and the attempt, its level's homotopy from `start` ([`FirstStart`]).
pub fn first(pieces: &SeamPieces, start: &mut FirstStart, budget: usize, report: &mut Reporter) -> Result<(SheetMesh, Vec<usize>, retry::Attempt), Outcome> {
    let saddles = saddle::samples(pieces);
    let mesh = SheetMesh::layered(pieces, INTERIOR_EDGE, &saddles).ok_or(Outcome::Unmeshed)?;
    let first = retry::attempt(pieces, &mesh, &saddles, Path::plain(HOMOTOPY_KB), Some(start), budget, report).ok_or(Outcome::NeedsStart)?;
    Ok((mesh, saddles, first))
}

/// The sheet path from the convex path's answer `seam` on the same samples, lifted onto the
/// mesh ([`start::lift`]) and thinned through the whole [`SCHEDULE`]: for a pair whose twins
/// cannot be solved. Returns the answer and its largest edge strain; `None` when a piece cannot
/// be meshed.
pub fn from_start(pieces: &SeamPieces, seam: &Solution, budget: usize, report: &mut Reporter) -> Option<(Simulation, f64)> {
    let mesh = SheetMesh::layered(pieces, INTERIOR_EDGE, &saddle::samples(pieces))?;
    let faces: Vec<[usize; 3]> = mesh.faces.iter().flatten().copied().collect();
    let mut shell = mesh.shell();
    let radius = pieces.flat[0].perimeter / std::f64::consts::TAU;
    report.skip(HOMOTOPY_STEPS);
    let r = thin(&mut shell, start::lift(pieces, seam, &mesh), radius, budget, &SCHEDULE, &faces, report);
    Some((finish::simulation(pieces, &mesh, &shell, &r.x, seam.iterations + r.steps, r.converged), r.max_strain))
}
