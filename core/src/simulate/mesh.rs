//! The closed mesh of two triangulated pieces glued along their seam: the solver's result, its
//! signed volume and its orientation. A's triangles face outward as they are (counter-clockwise
//! in the flat piece), B's reversed.

use super::isometry::{bars, max_strain};
use super::metric::{KeyMap, Triangulation};
use super::seam::SeamPieces;
use super::vec3::{centroid, cross, dot, norm, sub, V3};

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
/// unchanged and stays isometric. Returns the number of flips. A shared chord it cannot flip
/// is split when the mesh is written out ([`split_shared_chords`]).
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

/// Where along a shared chord `i → j` ([`split_shared_chords`]) the new vertex goes: not at the
/// midpoint, which is a seam sample when the chord spans an even number of evenly spaced samples
/// on a straight side (a convex 11-gon with its mirror image at offset 0, 128 seam vertices: a
/// zero-length edge whose "strain" of 5.8e-2 was round-off), but at the golden section, which
/// no such even spacing hits.
const SPLIT_AT: f64 = 0.618_033_988_749_894_8;

/// Splits each chord that both pieces' triangles have (an edge of four triangles: no
/// 2-manifold) of an isometric answer in piece B: B's two triangles on it become four around a
/// new vertex on the chord ([`SPLIT_AT`]), in 3D and on B's flat piece. A triangle is planar, so
/// the split keeps every length and the shape. Such chords are where the two sheets lie on each
/// other: the flat doubly covered D-form of two congruent polygons, whose triangulations are
/// each other's mirror image (two 80 × 50 mm rectangles at 50 mm: every chord shared where
/// flipping one is no help, its quad being degenerate on the straight sides).
pub(crate) fn split_shared_chords(x: &mut Vec<V3>, triangles: &mut Vec<[usize; 3]>, flat: &mut Vec<[[f64; 2]; 3]>, piece: &mut Vec<u8>) {
    // Keyed by [`crate::order::pair_key`] in [`KeyMap`]s, the triangulations' map type: each
    // undirected edge's number of triangles per piece, and the triangle that holds each directed
    // edge of B (one per directed edge in a piece), kept up to date as B's triangles are split.
    let key = crate::order::pair_key;
    let undirected = |a: usize, b: usize| key(a.min(b), a.max(b));
    let mut count = [KeyMap::default(), KeyMap::default()];
    let mut owner = KeyMap::default();
    for (t, tri) in triangles.iter().enumerate() {
        for m in 0..3 {
            let (a, b) = (tri[m], tri[(m + 1) % 3]);
            *count[piece[t] as usize].entry(undirected(a, b)).or_insert(0) += 1;
            if piece[t] == 1 {
                owner.insert(key(a, b), t);
            }
        }
    }
    let mut shared: Vec<u64> = count[0].iter().filter(|&(k, &c)| c == 2 && count[1].get(k) == Some(&2)).map(|(&k, _)| k).collect();
    shared.sort_unstable();
    for k in shared {
        let (i, j) = crate::order::unpair(k);
        let v = x.len();
        x.push([0, 1, 2].map(|a| x[i][a] + SPLIT_AT * (x[j][a] - x[i][a])));
        let mut on: Vec<usize> = [key(i, j), key(j, i)].iter().filter_map(|e| owner.get(e).copied()).collect();
        on.sort_unstable();
        for t in on {
            // Triangle (p, q, r) with the chord as p → q: (p, v, r) in its place, (v, q, r) new.
            let (tri, f) = (triangles[t], flat[t]);
            let Some(m) = (0..3).find(|&m| undirected(tri[m], tri[(m + 1) % 3]) == k) else { continue };
            let (p, q, r) = (tri[m], tri[(m + 1) % 3], tri[(m + 2) % 3]);
            // The same point of the chord i → j on the flat piece (p → q may run either way).
            let (fi, fj) = if p == i { (f[m], f[(m + 1) % 3]) } else { (f[(m + 1) % 3], f[m]) };
            let mid = [fi[0] + SPLIT_AT * (fj[0] - fi[0]), fi[1] + SPLIT_AT * (fj[1] - fi[1])];
            let u = triangles.len();
            let (mut first, mut second) = (tri, tri);
            first[(m + 1) % 3] = v;
            second[m] = v;
            let (mut f1, mut f2) = (f, f);
            f1[(m + 1) % 3] = mid;
            f2[m] = mid;
            triangles[t] = first;
            flat[t] = f1;
            triangles.push(second);
            flat.push(f2);
            piece.push(1);
            owner.remove(&key(p, q));
            for (a, b, holder) in [(p, v, t), (v, r, t), (v, q, u), (q, r, u), (r, v, u)] {
                owner.insert(key(a, b), holder);
            }
        }
    }
}

/// Largest distance from its plane, over its size, of a shape that [`flatten_near_planar`]
/// lays flat.
pub const NEAR_PLANAR: f64 = 1e-4;

/// Largest edge strain a flattened shape may end with (when the shape had less).
const FLATTENED_STRAIN: f64 = 1e-7;

/// Lays a shape within [`NEAR_PLANAR`] of a plane onto that plane, when that keeps every edge
/// within [`FLATTENED_STRAIN`] (or the strain it had) of its flat length. Returns whether it did.
///
/// Why: the flat doubly covered D-form (congruent pieces glued congruently: at offset 0, or an
/// ellipse with itself at half its perimeter) is where a flat sheet is infinitesimally flexible,
/// so a solve that starts a hair off flat ends isometric to 1e-10 but wavy by about the square
/// root of that, with the two sheets crossing each other at that scale. Two 2:1 ellipses at half
/// their perimeter, their control points snapped to grids of 2⁻²⁶…2⁻⁴⁴ of their size
/// ([`super::frame`]), ended so for four of seven grids (sheets crossing at a volume of 1e-5 of
/// area × size, or a vertex 2.7e-5 off a face plane); the plane through the centroid, normal to
/// the sum of A's area normals, is the flat answer those waves are round. (Congruent gluings
/// other than the identity, whose waves the projection strained past that bound, are laid out
/// flat before any solve: [`super::convex::congruent`].)
pub fn flatten_near_planar(pieces: &SeamPieces, sol: &mut Solution) -> bool {
    let x = &sol.x;
    if x.is_empty() {
        return false;
    }
    let c = centroid(x);
    let size = x.iter().map(|p| norm(sub(*p, c))).fold(0.0, f64::max);
    let mut n = [0.0; 3];
    for &[a, b, k] in &sol.tri[0].tris {
        let m = cross(sub(x[b], x[a]), sub(x[k], x[a]));
        n = [n[0] + m[0], n[1] + m[1], n[2] + m[2]];
    }
    let l = norm(n);
    if !(l > 0.0 && size > 0.0) {
        return false;
    }
    let n = [n[0] / l, n[1] / l, n[2] / l];
    let off = |p: &V3| dot(sub(*p, c), n);
    if x.iter().map(|p| off(p).abs()).fold(0.0, f64::max) > NEAR_PLANAR * size {
        return false;
    }
    let flat: Vec<V3> = x.iter().map(|p| {
        let h = off(p);
        [p[0] - h * n[0], p[1] - h * n[1], p[2] - h * n[2]]
    }).collect();
    let bars = bars(pieces, &sol.tri);
    if max_strain(&flat, &bars) > max_strain(x, &bars).max(FLATTENED_STRAIN) {
        return false;
    }
    sol.x = flat;
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::{Contour, Knot};
    use crate::simulate::metric::ear_clip;
    use crate::simulate::seam::Glue;
    use kurbo::Point;

    /// A 2:1 ellipse glued to itself at half its perimeter (the flat doubly covered D-form), its
    /// seam laid in z = 0 and waved out of that plane by `wave` of its size.
    fn waved(wave: f64) -> (SeamPieces, Solution) {
        let k = 0.552_284_749_830_793_4;
        let knots = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)]
            .map(|(x, y): (f64, f64)| {
                let a = Point::new(2.0 * x, y);
                let t = (-2.0 * y * k, x * k);
                Knot { anchor: a, left: Point::new(a.x - t.0, a.y - t.1), right: Point::new(a.x + t.0, a.y + t.1) }
            })
            .to_vec();
        let e = Contour::new(knots, 0).unwrap();
        let glue = Glue::new(&e, &e, crate::arclen::ArcTable::new(&e, 1e-13).total() / 2.0).unwrap();
        let pieces = glue.sample(32);
        let x: Vec<V3> = pieces.flat[0].pts.iter().map(|p| [p[0], p[1], wave * 4.0 * (3.0 * p[1].atan2(p[0])).sin()]).collect();
        let tri = [ear_clip(&pieces.flat[0].pts).unwrap(), ear_clip(&pieces.flat[1].pts).unwrap()];
        (pieces, Solution { x, tri, iterations: 0, flips: 0, converged: true })
    }

    /// Waves of 1e-6 of the size on the flat answer are laid flat: every vertex in one plane,
    /// and no edge further from its flat length than before (or than 1e-7).
    #[test]
    fn a_flat_answer_waved_by_round_off_is_laid_flat() {
        let (pieces, mut sol) = waved(1e-6);
        assert!(flatten_near_planar(&pieces, &mut sol), "wanted the waved sheet laid flat");
        // The plane through three seam vertices a quarter of the seam apart.
        let x = &sol.x;
        let n = cross(sub(x[8], x[0]), sub(x[16], x[0]));
        let n = [n[0] / norm(n), n[1] / norm(n), n[2] / norm(n)];
        let off = x.iter().map(|p| dot(sub(*p, x[0]), n).abs()).fold(0.0, f64::max);
        assert!(off <= 1e-12, "wanted every vertex in one plane, got one {off:e} off it");
        for (p, t) in sol.tri.iter().enumerate() {
            for (i, j) in t.edges() {
                let d = pieces.chord(p, i, j);
                let strain = (norm(sub(sol.x[i], sol.x[j])) / d - 1.0).abs();
                assert!(strain <= 1e-7, "edge {i}–{j} of piece {p}: wanted strain ≤ 1e-7, got {strain:e}");
            }
        }
    }

    /// A shape that is really curved (waves of 1e-2 of the size) is left as it is.
    #[test]
    fn a_curved_shape_is_not_laid_flat() {
        let (pieces, mut sol) = waved(1e-2);
        let before = sol.x.clone();
        assert!(!flatten_near_planar(&pieces, &mut sol));
        assert_eq!(sol.x, before);
    }
}
