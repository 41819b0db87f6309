//! Which path solves a gluing: the convex (Alexandrov) path for two convex pieces, the sheet path
//! for a pair with a non-convex piece.

use super::convex;
use super::mesh::Solution;
use super::options::SimulateOptions;
use super::seam::{Glue, SeamPieces};
use crate::error::Result;

/// Finds the seam positions at `options.resolution` seam vertices. Never panics; an input that
/// cannot even be triangulated is an error.
pub fn solve(glue: &Glue, options: &SimulateOptions) -> Result<(SeamPieces, Solution)> {
    convex::solve(glue, options)
}
