//! The closed mesh of two triangulated pieces glued along their seam: the solver's result, its
//! signed volume and its orientation. A's triangles face outward as they are (counter-clockwise
//! in the flat piece), B's reversed.

use super::metric::Triangulation;
use super::seam::SeamPieces;
use super::vec3::{cross, dot, norm, sub, V3};

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

/// Relative length error under which a flipped chord still has its flat length in 3D.
const COPLANAR_TOL: f64 = 1e-9;

/// Flips each chord of B that A has too (an edge of four triangles: the mesh would not be a
/// 2-manifold) to the other diagonal of its flat quad, when that diagonal is not A's and has its
/// flat length in 3D already (the quad is planar, as everywhere in the flat doubly covered
/// D-form of two congruent pieces, where both ear clippings are the same): the shape is
/// unchanged and stays isometric. Returns the number of flips.
pub fn unshare_planar(pieces: &SeamPieces, x: &[V3], tri: &mut [Triangulation; 2]) -> usize {
    let mut flips = 0;
    let pts = &pieces.flat[1].pts;
    let s2 = super::metric::size2(pts);
    for _ in 0..4 {
        let a = super::checks::chord_keys(&tri[0]);
        let mut any = false;
        for (i, j) in tri[1].chords() {
            if !a.contains_key(&crate::order::pair_key(i, j)) {
                continue;
            }
            let (Some(k), Some(l)) = (tri[1].opposite(i, j), tri[1].opposite(j, i)) else { continue };
            let d = pieces.chord(1, k, l);
            let ok = d > 0.0 && (norm(sub(x[k], x[l])) / d - 1.0).abs() <= COPLANAR_TOL && !a.contains_key(&crate::order::pair_key(k.min(l), k.max(l)));
            if ok && tri[1].flip(i, j, pts, s2) {
                flips += 1;
                any = true;
            }
        }
        if !any {
            break;
        }
    }
    flips
}
