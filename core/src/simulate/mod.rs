//! # 3D form-finding of a D-form
//!
//! Two flat pieces A and B with equal perimeter L are stitched edge to edge: the point at arc
//! length `s` on A (walked counter-clockwise from its first anchor) meets the point at arc length
//! `offset + s` on B (walked clockwise from its first anchor) — the `start` convention of
//! `connect`, so what the user previews is what the connectors assemble. (Up to
//! [`kink::KINK_SHIFT`] of `L` per kink, a turn rounded too tightly for the seam, taken as a
//! corner: see [`seam`].)
//!
//! ## Method (why this one)
//!
//! *Geometry.* For convex pieces the glued surface is the unique convex body of Alexandrov's
//! theorem (Alexandrov 1950, uniqueness by Pogorelov); it is the convex hull of its seam and its
//! flat parts carry no creases, so all curvature lives on the seam (Demaine & Price 2010,
//! "Generalized D-forms have no spurious creases"). Sampling the seam at `N` equal arc-length
//! steps (with every corner of either piece moved onto a sample, see [`seam`]) therefore gives a
//! *polyhedral metric whose only vertices are seam vertices*: each piece
//! becomes the flat polygon of its `N` samples, and the surface is a convex polyhedron whose
//! faces are triangles spanned by chords of those polygons. In a chord triangulation of a convex
//! polygon every edge's flat length is the Euclidean chord (the geodesic of a convex piece), so
//! the unknown surface is fully described by
//!
//! * the `N` seam positions `X_k ∈ R³` (3N unknowns), and
//! * one chord triangulation `T_A`, `T_B` of each polygon (N−3 interior edges each).
//!
//! Together with the `N` seam edges that is `3N − 6` edges: exactly the count of a triangulated
//! sphere, which is infinitesimally rigid when convex (Cauchy–Dehn). So for the right
//! triangulations the isometry equations `|X_i − X_j| = d_ij` form a square, well-posed system.
//!
//! *Solver.* Levenberg–Marquardt on the relative edge residuals `|X_i − X_j| / d_ij − 1`
//! (Gauss–Newton with Levenberg damping `λ·I`, which also absorbs the six rigid motions and the
//! out-of-plane flexes of a flat configuration). Each step solves `(JᵀJ + λI) Δ = −Jᵀr`, a sparse
//! SPD system with the planar graph's sparsity, with a sparse LDLᵀ on 3×3 blocks (approximate-minimum-degree
//! ordering; the symbolic factorization is kept until a flip changes the pattern, see [`normal`]).
//! Between steps every interior edge whose dihedral is reflex is *flipped* (Lawson-style) to the
//! other diagonal of its flat quad, which is always legal in a convex piece; the flips drive the
//! triangulation to the one whose realization is convex — the Alexandrov polyhedron, i.e. the
//! convex hull of the seam (Huang et al. 2023 use the same two ingredients, isometry + convex
//! hull, as penalty terms; here convexity is enforced exactly through the combinatorics).
//! Quadratic convergence of Gauss–Newton on a square system gives 1e-12 strain in a handful of
//! steps, and a warm start (a previous result's vertices) keeps the slider interactive. Which
//! isometric branch the solver lands on depends on the start, so a cold solve is a multistart
//! over starts (saddles, a fourfold start, the chord-mismatch start) on a coarse-to-fine ladder,
//! first with tight step budgets, then (only if that found no convex branch) with patient ones:
//! nearly flat regions (pieces with straight stretches) settle slowly but correctly. Each finer
//! level starts from the coarser answer, isometric up to O(h²), and is relaxed undamped first
//! (with the cold damping only if that fails: the flat doubly covered sheet is a singular point);
//! a warm start climbs the same ladder from a quarter of the resolution. Congruent pieces glued
//! congruently skip all of it: their answer, the flat doubly covered form, is laid out directly
//! ([`convex::congruent`]).
//!
//! *Creases across the seam.* A chord triangulation keeps every edge inside one piece, but where
//! both pieces are straight the seam is flat and a crease of the polyhedron can run straight
//! across it (two congruent rectangles with rounded corners glued at an offset). No chord mesh on
//! the samples holds such a crease, so when the quick ladder finds no convex branch the convex
//! path turns to an *intrinsic* triangulation of the glued metric, whose edges may cross the
//! seam, and embeds it by Bobenko & Izmestiev's variational method (2008; as geometry-central's
//! `embedConvex`), which is proved to reach the polyhedron for a convex metric; the triangles
//! are then cut along the seam, with a seam vertex where a crease crosses it
//! ([`convex::crossing`]). It is not the first path: it cannot give the flat doubly covered form
//! (congruent pieces at zero offset, no interior point for its apex), and at 256 seam vertices its
//! dense Newton steps take ~0.1–0.5 s where the chord ladder takes ~10 ms. Mass–spring /
//! position-based dynamics meshes with interior vertices converge slowly (≈1 % strain) and smear
//! the seam curvature into the interior; the seam-vertex polyhedron has no interior vertices at
//! all, so the flat parts are exactly flat by construction.
//!
//! *Seam edges.* A seam edge has two flat lengths, A's chord and B's chord (they differ by
//! `O(h³ (κ_A² − κ_B²))` for step `h`); both are residuals, so the solver takes the least-squares
//! compromise and the stats report the strain against each piece honestly.
//!
//! *Non-convex pieces.* The convex path still runs first (a constrained triangulation: ear
//! clipping, a flip only where the new chord stays inside the flat piece), and its answer is
//! kept when it meets every promise — e.g. two congruent pieces at offset 0, the flat doubly
//! covered sheet. Otherwise the [`sheet`] path solves the pair as two inextensible elastic
//! sheets with interior vertices (discrete shells, Grinspun et al. 2003), followed by a homotopy
//! from convex twins of the pieces and thinned until every edge is within 1e-3 of its flat
//! length; `converged` then also says the mesh is unfolded (no bend above 90° inside a piece)
//! and free of self-intersections. Its vertices are the seam's first, then the interior ones.
//!
//! ## Files
//! - [`options`]: user options and their checks; [`seam`]: the two sampled pieces;
//!   [`metric`]: chord triangulations of a flat polygon and flips;
//! - [`vec3`]: 3D vector helpers; [`mesh`]: the solver's result (positions and the two
//!   triangulations), its volume and orientation; [`isometry`]: the length equations and one
//!   Levenberg–Marquardt step ([`normal`]: its sparse LDLᵀ);
//! - [`solve`]: which path solves a gluing; [`convex`]: the Alexandrov path (LM with flips
//!   towards convexity, the multistart ladder, hull restarts, polygon pairs on their cone points,
//!   and the intrinsic triangulation for creases across the seam);
//!   [`sheet`]: the elastic-sheet path of non-convex pairs (meshes with interior vertices, the
//!   shell energy, the homotopy from convex twins);
//! - [`frame`]: each piece moved to its first anchor, scaled and snapped (and, in a pair with a
//!   non-convex piece, turned), so that where, in what units and (there) how turned a pair is
//!   drawn does not change its form; [`anchor`]: a pair with a non-convex piece restarted at
//!   its outline's canonical start (on a mirror axis when it has one), so that where the drawing
//!   starts does not either, and solved from a second start when that answer misses a little
//!   or crosses itself; [`picked`]: such a pair solved in an order of its own and read back in
//!   the order its pieces were picked, so that which was picked first does not either;
//!   [`round`]: a circle, whose seam
//!   offset does not change the form either (solved at offset 0, the circle turned), and a B
//!   that a turn of 2π/k carries onto itself (solved within the first k-th of the perimeter);
//!   [`fit`]: the least-squares turn and shift of one planar point set onto another;
//! - [`density`]: seam samples spaced by the curvature mismatch of the two pieces; [`kink`]:
//!   turns too tight for the seam, taken as corners; [`corners`]: roundings below the seam's
//!   resolution previewed as corners when the sheet cannot follow them;
//! - [`checks`]: dihedral signs, convexity as a whole, flat folds; [`stats`]: strain, seam gap,
//!   area, angle defects, volume; [`clock`]: a timer that works natively and in wasm32.
//!
//! Imports run one way: `vec3`, `metric`, `fit` ← `seam`, `mesh`, `checks`, `isometry` ← `convex` ←
//! `solve` ← this module; `stats` reads `mesh` and `checks`; `sheet` reads `convex` (the twins'
//! polyhedron), `checks`, `stats` and `normal`, and only this module reads `sheet`; `frame`
//! reads only `contour` and `arclen`, `round` those and this module's `Simulation`, `anchor`
//! those, `round`, `checks` and `seam`; `picked` reads `anchor` and `round`.

pub mod anchor;
pub mod checks;
pub mod clock;
pub mod convex;
pub mod corners;
pub mod density;
pub mod fit;
pub mod frame;
pub mod isometry;
pub mod mesh;
pub mod metric;
pub mod normal;
pub mod options;
pub mod picked;
pub mod progress;
pub mod round;
pub mod kink;
pub mod seam;
pub mod sheet;
pub mod solve;
pub mod stats;
pub mod vec3;

use crate::arclen::ArcTable;
use crate::contour::Contour;
use mesh::Solution;
use crate::error::{Error, Result};
pub use options::SimulateOptions;
pub use stats::{Crease, Shortfall, Stats};

/// A solved D-form: a closed triangle mesh. Its first vertices are the seam vertices; a
/// non-convex pair's answer from the sheet path has interior vertices after them.
#[derive(Debug, Clone)]
pub struct Simulation {
    /// Vertex positions (input units), centred on their centroid: the seam vertices, then (sheet
    /// path) the interior vertices of A and of B.
    pub vertices: Vec<[f64; 3]>,
    /// Outward-oriented triangles (counter-clockwise seen from outside).
    pub triangles: Vec<[usize; 3]>,
    /// 0 for a triangle of piece A, 1 for piece B.
    pub piece: Vec<u8>,
    /// Seam vertex indices in order (A counter-clockwise from its start).
    pub seam: Vec<usize>,
    /// For every triangle, its three corners' positions on its own flat piece, in the input's
    /// coordinates and in the corner order of `triangles`: `|vertices[i] − vertices[j]|` against
    /// `|flat[t][a] − flat[t][b]|` is the isometry check, and a point given by barycentric
    /// coordinates in `flat[t]` maps to the same coordinates in the 3D triangle.
    pub flat: Vec<[[f64; 2]; 3]>,
    /// A non-convex pair's interior edges bent by more than [`checks::FOLD_BEND`] inside a
    /// piece ([`stats::Crease`]): empty unless `stats.shortfall` is a fold (or a worse
    /// shortfall hides one); always empty for a convex pair.
    pub creases: Vec<stats::Crease>,
    pub stats: Stats,
}

/// Glues `a` and `b` (closed, equal perimeters) and finds the 3D D-form.
pub fn simulate(a: &Contour, b: &Contour, options: &SimulateOptions) -> Result<Simulation> {
    run(a, b, options, &mut |_| {}, false)
}

/// [`simulate`], telling `observe` each time a stage of a non-convex pair's solve ends, and once
/// of the interim form when there is one ([`progress`]): the same result, for a host that shows
/// progress.
pub fn simulate_observed(a: &Contour, b: &Contour, options: &SimulateOptions, observe: &mut dyn FnMut(progress::Progress)) -> Result<Simulation> {
    run(a, b, options, observe, true)
}

/// [`simulate_observed`], building the interim form only when `interims` is set.
fn run(a: &Contour, b: &Contour, options: &SimulateOptions, observe: &mut dyn FnMut(progress::Progress), interims: bool) -> Result<Simulation> {
    let timer = clock::Timer::start();
    // Each piece in its own frame, so that where the pair sits on the artboard and the units it
    // is drawn in cannot change its form ([`frame`]); the answer goes back to the input's units
    // and place at the end.
    // A pair with a non-convex piece is framed turned too ([`frame::turn_of`]), so that how its
    // pieces are turned cannot change its form either; a convex pair, whose exact polyhedron has
    // no mesh to draw, keeps the frames square to the input (a rectangle drawn square is solved
    // square: turned, its sides were no longer straight to the bit, and the convex path took 1.7
    // times the steps).
    let framed = |a: &Contour, b: &Contour, offset: f64, turned: bool, limits: kink::Limits| -> Result<Framed> {
        let ((framed_a, fa), (framed_b, fb)) = frame::pair(a, b, turned);
        let options = SimulateOptions {
            offset: frame::offset(offset, b, &fb),
            warm: options.warm.as_ref().map(|w| w.iter().map(|p| p.map(|c| c / fa.unit)).collect()),
            ..options.clone()
        };
        let glue = seam::Glue::with_kinks(&framed_a, &framed_b, options.offset, limits).map_err(|e| match e {
            Error::PerimeterMismatch { a, b } => Error::PerimeterMismatch { a: fa.length_out(a), b: fa.length_out(b) },
            e => e,
        })?;
        Ok((framed_a, fa, framed_b, fb, options, glue))
    };
    let drawn = (a, b, options.offset);
    let plain = framed(a, b, options.offset, false, kink::Limits::EXACT)?;
    // Convex at the coarsest samples and at the resolution's: an outline that bends inward by
    // a hair between coarse samples (a 200 × 40 ellipse through 64 smooth points) is no convex
    // metric at the resolution, and the convex path would spend the whole budget on it.
    let convex = [seam::COARSEST, plain.4.resolution].iter().all(|&n| plain.5.sample(n).flat.iter().all(|f| checks::is_convex_polygon(&f.pts)));
    let per_start = options.max_iterations.min(options::START_MAX_ITERATIONS);
    let with_cap = |f: Framed, cap: usize| (f.0, f.1, f.2, f.3, SimulateOptions { max_iterations: cap, ..f.4 }, f.5);
    if convex {
        let mut sim = in_frames(with_cap(plain, per_start), true, None, observe, false)?;
        sim.stats.ms = timer.elapsed_ms();
        return Ok(sim);
    }
    // A pair with a non-convex piece is solved in an order of its own ([`picked`]), so that
    // which piece was picked first cannot change its form; from its first piece's canonical
    // start ([`anchor`]), so that where the drawing starts cannot either; when that answer misses
    // its promise by a little or passes through itself, from the point half the perimeter round
    // too ([`anchor::retry`]), and the better is kept ([`anchor::better`]).
    let swap = picked::second_first(a, b);
    let drawn = if swap {
        let (pa, pb) = (ArcTable::new(a, seam::SAMPLE_ACCURACY).total(), ArcTable::new(b, seam::SAMPLE_ACCURACY).total());
        (b, a, options.offset * (pa / pb))
    } else {
        drawn
    };
    let starts = anchor::restarts(drawn.0, drawn.1, drawn.2);
    let framed_from = |k: usize, limits: kink::Limits| -> Result<Framed> {
        let (ra, rb, offset) = starts[k].as_ref().map_or((drawn.0, drawn.1, drawn.2), |(ra, rb, offset)| (ra, rb, *offset));
        framed(ra, rb, offset, true, limits)
    };
    let solve_in = |k: usize, f: Framed, cap: usize, observe: &mut dyn FnMut(progress::Progress), interims: bool| -> Result<Simulation> {
        let at = starts[k].as_ref().map(|_| drawn.0.knots()[0].anchor);
        in_frames(with_cap(f, cap), false, at, observe, interims)
    };
    // An interim form is in the order the pieces were picked, and timed from the request.
    let first_anchor = a.knots()[0].anchor;
    let shown = std::cell::Cell::new(0);
    let mut picked_order = |mut p: progress::Progress| {
        shown.set(p.done);
        if let Some(sim) = p.interim.take() {
            let mut sim = if swap { picked::swap_back(*sim, first_anchor) } else { *sim };
            sim.stats.ms = timer.elapsed_ms();
            p.interim = Some(Box::new(sim));
        }
        observe(p)
    };
    let mut told = false;
    let first = framed_from(0, kink::Limits::EXACT)?;
    let exact_kinks = first.5.kinks();
    let mut sim = solve_in(0, first, per_start, &mut |p: progress::Progress| {
        told |= p.interim.is_some();
        picked_order(p)
    }, interims)?;
    // Not converged, on a pair with roundings below the seam's resolution: those previewed as
    // corners from the first start ([`corners`]), the better answer kept, before a second start,
    // which then runs only if that still misses. Each fills what the solves before it left of
    // the progress bar.
    let left = options.max_iterations.saturating_sub(sim.stats.iterations);
    if left > 0 && !sim.stats.converged {
        let with_corners = framed_from(0, kink::Limits::CORNERS)?;
        if with_corners.5.kinks() > exact_kinks {
            let done = shown.get();
            let mut after = |p: progress::Progress| picked_order(progress::Progress { done: done + p.done * (p.total - done) / p.total.max(1), ..p });
            let preview = solve_in(0, with_corners, left.min(options::START_MAX_ITERATIONS), &mut after, false)?;
            sim = corners::better(sim, preview);
        }
    }
    let left = options.max_iterations.saturating_sub(sim.stats.iterations);
    if left > 0 && anchor::retry(&sim, sheet::FAR_ABOVE * sheet::STRAIN_TARGET, sheet::retry::TOUCH_BELOW) {
        let done = shown.get();
        let mut after = |p: progress::Progress| picked_order(progress::Progress { done: done + p.done * (p.total - done) / p.total.max(1), ..p });
        let other = solve_in(1, framed_from(1, kink::Limits::EXACT)?, left.min(options::START_MAX_ITERATIONS), &mut after, interims && !told)?;
        sim = anchor::better(sim, other);
    }
    if swap {
        sim = picked::swap_back(sim, first_anchor);
    }
    sim.stats.ms = timer.elapsed_ms();
    Ok(sim)
}

/// A pair in its frames: each piece and its frame, the options in the frame and the gluing.
type Framed = (Contour, frame::Frame, Contour, frame::Frame, SimulateOptions, seam::Glue);

/// One pair in its frames solved: the convex path for a `convex` pair, else the sheet path
/// after it; the answer in the input's units and place, its `seam` started at the seam vertex
/// nearest `seam_start` (A's drawn first anchor, for a pair solved from another start) when
/// given. An interim form (`interims`, [`progress`]) is told to `observe` in the same units and
/// place. A gluing rebuilt here (a circle's canonical one, a turned one) keeps the kink limits of
/// the framed one ([`seam::Glue::limits`]).
fn in_frames(framed: Framed, convex: bool, seam_start: Option<kurbo::Point>, observe: &mut dyn FnMut(progress::Progress), interims: bool) -> Result<Simulation> {
    let (a, fa, b, fb, options, glue) = framed;
    let limits = glue.limits();
    let options = &options;
    // A non-convex piece with a circle: every offset is the offset-0 form with the circle turned
    // ([`round`]), so it is solved at offset 0, on one mesh of the circle.
    // Likewise B (or else A) turned onto itself by 2π/k: an offset past the first k-th of the
    // perimeter is solved at its remainder (on the frame's cell, the bits of that offset given
    // directly).
    let symmetry = if convex { None } else { round::round_piece(&a, &b) };
    // Both pieces turn-symmetric: their periods combine ([`round::Turn::both`]).
    let turn = match symmetry {
        Some((1, sb)) if sb.order > 0 => match round::order(&a) {
            Some(sa) => round::Turn::both(sa, sb, options.offset),
            None => round::Turn::new(1, sb, options.offset).map(|(t, at)| (vec![t], at)),
        },
        Some((piece, s)) => round::Turn::new(piece, s, options.offset).map(|(t, at)| (vec![t], at)),
        None => None,
    };
    // A circle is solved as one canonical circle of the other piece's perimeter, however it was
    // drawn (its arcs, first anchor, sense), and placed back on the drawn one ([`round::Canonical`]).
    let canonical = match symmetry {
        Some((0, s)) if s.order == 0 => round::Canonical::new(0, s, &a, &b),
        Some((1, s)) if s.order == 0 => round::Canonical::new(1, s, &b, &a),
        _ => None,
    };
    let glue = match (&canonical, &turn) {
        (Some((c, circle)), _) => {
            let (ga, gb) = if c.piece == 0 { (circle, &b) } else { (&a, circle) };
            seam::Glue::with_kinks(ga, gb, 0.0, limits)?
        }
        (None, Some((_, at))) => seam::Glue::with_kinks(&a, &b, fb.snap(*at), limits)?,
        (None, None) => glue,
    };
    // A pair with a non-convex piece: the convex path gives the sheet path its start (or, when
    // it meets every promise, e.g. the flat doubly covered sheet, the answer) on a short budget.
    // A previous result's vertices are no warm start here: a sheet's answer has interior vertices.
    let first = if convex { options.clone() } else { SimulateOptions { max_iterations: options.max_iterations.min(sheet::START_BUDGET), warm: None, ..options.clone() } };
    let (pieces, solution) = solve::solve(&glue, &first)?;
    let convex = pieces.flat.iter().all(|f| checks::is_convex_polygon(&f.pts));
    let left = options.max_iterations.saturating_sub(solution.iterations);
    // The answer (and an interim form) judged, and taken back to the input's place and units.
    let output = |sim: &mut Simulation| {
        stats::judge(sim, !convex);
        if let Some((c, _)) = &canonical {
            c.place(sim);
        }
        for t in turn.iter().flat_map(|(turns, _)| turns) {
            t.turn(sim, a.knots()[0].anchor);
        }
        sim.stats.offset_free = matches!(symmetry, Some((_, s)) if s.order == 0);
        for (corners, &p) in sim.flat.iter_mut().zip(&sim.piece) {
            let f = if p == 0 { fa } else { fb };
            *corners = corners.map(|q| f.to_input(q));
        }
        if let Some(at) = seam_start {
            anchor::start_seam_at(sim, at);
        }
        let u = fa.unit;
        for v in &mut sim.vertices {
            *v = v.map(|c| c * u);
        }
        sim.stats.seam_gap *= u;
        sim.stats.area *= u * u;
        sim.stats.volume *= u * u * u;
    };
    let mut sim = stats::finish(&pieces, solution.clone());
    if !convex && !solution.converged && left > 0 {
        let mut framed_observe = |mut p: progress::Progress| {
            if let Some(sim) = p.interim.as_deref_mut() {
                output(sim);
            }
            observe(p)
        };
        let mut report = progress::Reporter::new(&mut framed_observe, sheet::STAGES, interims);
        report.stage(sim.stats.max_strain);
        // A sheet that converged, or is not crumpled, is the answer: the convex path on a pair
        // with a non-convex piece ends strained by percents ([`sheet::CRUMPLED`]).
        let unsettled = match sheet::simulate(&pieces, solution.iterations, left, &mut report) {
            sheet::Outcome::Sheet(s, strain) if s.stats.converged || strain <= sheet::CRUMPLED => {
                sim = s;
                None
            }
            other => Some(other),
        };
        if let Some(outcome) = unsettled {
            // No such sheet: the convex path's patient answer is the answer when it meets
            // every promise, else the sheet's start when no twin could be solved, and the answer
            // when the sheet ends more strained (a start folded through itself is not a better
            // approximation of the form). Within the caller's cap on steps.
            let used = match &outcome {
                sheet::Outcome::Sheet(s, _) => s.stats.iterations,
                _ => solution.iterations,
            };
            let cap = options.max_iterations.saturating_sub(used).min(sheet::FALLBACK_BUDGET);
            let mut sheet = match outcome {
                sheet::Outcome::Sheet(s, strain) => Some((s, strain)),
                _ => None,
            };
            if cap > 0 {
                let (pieces, patient) = solve::solve(&glue, &SimulateOptions { max_iterations: cap, ..first })?;
                let spent = patient.iterations;
                let patient = Solution { iterations: used + spent, ..patient };
                sim = stats::finish(&pieces, patient.clone());
                let left = options.max_iterations.saturating_sub(used + spent);
                sheet = match sheet {
                    _ if patient.converged => None,
                    Some((mut s, strain)) => {
                        s.stats.iterations += spent;
                        Some((s, strain))
                    }
                    None if left > 0 => sheet::from_start(&pieces, &patient, left, &mut report),
                    None => None,
                };
            }
            if let Some((s, strain)) = sheet {
                if s.stats.converged || strain <= sim.stats.max_strain {
                    sim = s;
                }
            }
        }
    }
    output(&mut sim);
    Ok(sim)
}
