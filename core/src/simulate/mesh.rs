//! The closed mesh of two triangulated pieces glued along their seam: the solver's result, its
//! signed volume and its orientation. A's triangles face outward as they are (counter-clockwise
//! in the flat piece), B's reversed.

use super::metric::Triangulation;
use super::vec3::{cross, dot, V3};

/// The solver's result: positions, the two triangulations, and how it went.
#[derive(Debug, Clone)]
pub struct Solution {
    pub x: Vec<[f64; 3]>,
    pub tri: [Triangulation; 2],
    pub iterations: usize,
    pub flips: usize,
    pub converged: bool,
}

/// Signed volume of the closed mesh (A's triangles as they are, B's reversed).
pub fn signed_volume(x: &[V3], tri: &[Triangulation; 2]) -> f64 {
    let mut v = 0.0;
    for (p, t) in tri.iter().enumerate() {
        for &[a, b, c] in &t.tris {
            let (b, c) = if p == 0 { (b, c) } else { (c, b) };
            v += dot(x[a], cross(x[b], x[c]));
        }
    }
    v / 6.0
}

/// Mirrors the positions (z → −z, an isometry) when the mesh is inside out, so that A's triangles
/// as they are and B's reversed face outward.
pub(crate) fn make_outward(x: &mut [V3], tri: &[Triangulation; 2]) {
    if signed_volume(x, tri) < 0.0 {
        for p in x.iter_mut() {
            p[2] = -p[2];
        }
    }
}
