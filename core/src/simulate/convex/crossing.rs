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
//! 1. the two pieces' Delaunay chord triangulations become one intrinsic triangulation of the
//!    glued metric ([`super::intrinsic::Mesh`]);
//! 2. Bobenko & Izmestiev's method finds the polyhedron's triangulation and vertex positions
//!    ([`super::alexandrov::embed`]), flipping edges across the seam where it must;
//! 3. Levenberg–Marquardt on that fixed triangulation polishes the positions to the length
//!    equations' tolerance ([`Frozen`]);
//! 4. the triangles are cut along the seam ([`super::overlay::cut`]), with a seam vertex where a
//!    crease crosses it, into a chord mesh of the two flat pieces like any other answer, held to
//!    the same checks.

use super::super::checks::convex_as_a_whole;
use super::super::isometry::{max_strain, Bar, STEP_TOL, STRAIN_TOL};
use super::super::metric::{KeyMap, Triangulation};
use super::super::seam::SeamPieces;
use super::super::vec3::V3;
use super::intrinsic::Mesh;
use super::relax::{relax_with, Flips, Orientation, WARM};
use super::{exact_if_polyhedral, is_good, triangulate};

/// Newton steps allowed to [`super::alexandrov::embed`]: the survey's answers take 60–250.
pub(crate) const NEWTON: usize = 400;

/// Levenberg–Marquardt steps of each polish: from the embedding (strain ~1e-6) it takes 2–60.
pub(crate) const POLISH: usize = 200;

/// The D-form of the sample polygons `pieces` (both convex) by the steps of the module docs:
/// the pieces with a seam vertex added where a crease crosses the seam, the positions and the
/// triangulations, when the answer is isometric to the length equations ([`STRAIN_TOL`]) and
/// good ([`is_good`], [`exact_if_polyhedral`], [`convex_as_a_whole`]); else `None`. The Newton
/// and LM steps are added to `steps`.
pub(crate) fn solve(pieces: &SeamPieces, steps: &mut (usize, usize)) -> Option<(SeamPieces, Vec<V3>, [Triangulation; 2])> {
    let mut mesh = Mesh::from_chords(pieces, &[triangulate(pieces, 0).ok()?, triangulate(pieces, 1).ok()?])?;
    let mut newton = 0;
    let embedded = super::alexandrov::embed(&mut mesh, NEWTON, &mut newton);
    steps.0 += newton;
    let mut x = embedded?;
    let r = relax_with(&mut Frozen { n: mesh.n, bars: mesh.bars() }, &mut x, POLISH, STEP_TOL, Orientation::Kept, WARM).tally(steps);
    let isometric = r.converged || max_strain(&x, &mesh.bars()) <= STRAIN_TOL;
    mesh.flip_straight_angles();
    let (cut, xs, tri) = super::overlay::cut(&mesh, pieces, &x)?;
    (isometric && is_good(&xs, &tri, true) && exact_if_polyhedral(&cut, &xs, &tri) && convex_as_a_whole(&xs, &tri)).then_some((cut, xs, tri))
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
