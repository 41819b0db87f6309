//! Which path solves a gluing: the convex (Alexandrov) path for two convex pieces, the sheet path
//! for a pair with a non-convex piece.

use super::checks::{is_convex_polygon, max_bend, self_intersecting, triangulates_polygon, FOLD_BEND};
use super::convex;
use super::mesh::{flatten_near_planar, unshare_planar, Solution};
use super::metric::Triangulation;
use super::options::SimulateOptions;
use super::seam::{Glue, SeamPieces};
use super::vec3::V3;
use crate::error::Result;

/// Finds the seam positions at `options.resolution` seam vertices. Never panics; an input that
/// cannot even be triangulated is an error.
///
/// The answer is then judged on the mesh it returns ([`sound`]): converged only when, besides
/// the length equations the path met, the mesh is a closed 2-manifold, no chord is folded beyond
/// 90° inside a piece and no two triangles cross.
pub fn solve(glue: &Glue, options: &SimulateOptions) -> Result<(SeamPieces, Solution)> {
    let (pieces, mut sol) = convex::solve(glue, options)?;
    flatten_near_planar(&pieces, &mut sol);
    sol.flips += unshare_planar(&pieces, &sol.x, &mut sol.tri);
    let convex = pieces.flat.iter().all(|f| is_convex_polygon(&f.pts));
    sol.converged = sol.converged && sound(&sol.x, &sol.tri, !convex);
    Ok((pieces, sol))
}

/// Whether a mesh is what a sheet can be: a closed 2-manifold (each piece's triangles
/// triangulate its polygon, [`triangulates_polygon`]; a chord in both pieces is split in B when
/// the mesh is written out, [`super::mesh::split_shared_chords`]), no self-intersection
/// ([`self_intersecting`]) and, when `folds` is set (a pair with a non-convex piece), no fold
/// inside a piece (a bend above [`FOLD_BEND`], [`max_bend`]). A convex pair's answer has been
/// checked convex, and a sharp chord of it is an edge of its Alexandrov polyhedron (a triangle
/// with a square bends by 90–99° along the creases between corners), not a fold the sheet would
/// not take; a non-convex pair's answer often is a fold: the kidney of issue 14 with a circle
/// ended isometric to 2e-2 with chords bent by 175° through the other sheet.
pub fn sound(x: &[V3], tri: &[Triangulation; 2], folds: bool) -> bool {
    tri.iter().all(triangulates_polygon) && !(folds && max_bend(x, tri) > FOLD_BEND) && !self_intersecting(x, tri)
}
