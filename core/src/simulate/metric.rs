//! Chord triangulations of a flat, counter-clockwise sample polygon: the combinatorics of the
//! polyhedral metric. Every edge is a chord inside the polygon, so its flat length is the
//! piece's intrinsic distance. Built by ear clipping (valid for non-convex pieces, no zero-area
//! triangles where avoidable) and changed only by legal flips (the new chord must cut a strictly
//! convex flat quad, so it stays inside the piece).

use crate::libm_ext::LibmExt;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// The simulation's one hash map: `u64` keys (a vertex pair's [`crate::order::pair_key`], a
/// directed edge, the bits of an arc length) to indices. One type for all of them keeps one
/// instantiation of the hash table in the .wasm.
pub type KeyMap = HashMap<u64, usize, BuildHasherDefault<KeyHasher>>;

/// The hasher of [`KeyMap`]: SplitMix64's finalizer (Steele, Lea & Flood, "Fast splittable
/// pseudorandom number generators", OOPSLA 2014) on the key, a bijection of `u64` that spreads
/// every key bit over the high and the low bits the table reads. The keys are the solver's own,
/// never an attacker's, so the standard library's SipHash (whose keyed hashing guards against
/// chosen collisions) only cost time: its edge look-ups were ~8 % of a cold solve.
#[derive(Debug, Clone, Copy, Default)]
pub struct KeyHasher(u64);

impl Hasher for KeyHasher {
    fn finish(&self) -> u64 {
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0.rotate_left(8) ^ b as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15);
        }
    }

    fn write_u64(&mut self, v: u64) {
        self.0 = (self.0.rotate_left(32) ^ v).wrapping_add(0x9e37_79b9_7f4a_7c15);
    }
}

/// Twice the signed area of triangle (a, b, c); positive when counter-clockwise.
pub fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// The angle at `a` between `a` → `b` and `a` → `c`, in [0, π].
pub fn angle(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
    (u[0] * v[1] - u[1] * v[0]).abs().atan2_m(u[0] * v[0] + u[1] * v[1])
}

/// Relative margin for "strictly" positive areas: a triangle counts as degenerate when its
/// doubled area is below this times the squared polygon size.
const AREA_EPS: f64 = 1e-12;

/// How far (relative to a polygon's size) a sample may lie off the line through its two
/// neighbours and still count as on it ([`straight_margin`]): twice what the snap of each
/// piece's frame moves a point ([`super::frame::SNAP_MOVE`]), for the vertex and its
/// neighbours, doubled again because the frame measures its size on the control points and
/// this on the samples. An anchor added on a straight side (as Illustrator's "Add Anchor
/// Points" leaves one) is moved off the line by up to that, and round-off alone was then the
/// tolerance: a convex 21-gon with such anchors counted as non-convex (its sampled sides bent
/// inward by 7e-8 mm) and went the sheet path: with its copy, volumes 3 % apart at offsets
/// 1e-9 mm apart, all 12–16 % above its polyhedron's (61,507 mm³, now at each of them); a
/// trapezoid with such anchors could not be ear-clipped at 4 of 80 offsets.
pub const STRAIGHT: f64 = 4.0 * super::frame::SNAP_MOVE;

/// The margin within which `orient(a, b, c)` counts as zero for a vertex `b` between `a` and
/// `c` of a polygon of squared size `s2` ([`size2`]): round-off (a relative 1e-12 of `s2`) plus
/// `b` lying [`STRAIGHT`] of the size off the line a–c.
pub fn straight_margin(a: [f64; 2], c: [f64; 2], s2: f64) -> f64 {
    AREA_EPS * s2 + STRAIGHT * s2.sqrt() * (c[0] - a[0]).hypot_m(c[1] - a[1])
}

/// A triangulation of polygon 0..n with counter-clockwise triangles, and the map from each
/// directed edge to the triangle that contains it.
#[derive(Debug, Clone)]
pub struct Triangulation {
    pub tris: Vec<[usize; 3]>,
    n: usize,
    edge: KeyMap,
}

impl Triangulation {
    fn key(&self, a: usize, b: usize) -> u64 {
        (a as u64) * (self.n as u64) + b as u64
    }

    /// Number of polygon vertices.
    pub fn len(&self) -> usize {
        self.n
    }

    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The triangulation of the polygon with twice the samples (coarse vertex m = fine vertex
    /// 2m): every coarse triangle kept, plus the ear (2m, 2m+1, 2m+2) at each seam edge.
    ///
    /// On a straight stretch of the outline (a polygon's side) that ear has no area: the new
    /// sample lies on the coarse seam edge. The coarse triangle on that edge is then split at the
    /// new sample instead (its sub-polygon, the triangle with the new samples on its seam edges,
    /// ear-clipped), so the coarse solution's chords, which name the convex shape, stay edges.
    /// (A fresh ear clipping would throw them away; from its strip the flips can end in a fan of
    /// chords from one sample to consecutive samples of a straight side, whose reflex chords can
    /// never flip: each one's quad has three collinear samples. A triangle glued to a circle
    /// converged at 32 seam vertices and stalled at 64 in such fans at its corners.)
    ///
    /// `None` when an ear is clockwise (a concave stretch where the new sample falls inside), or
    /// when a coarse triangle would hold another sample.
    pub fn doubled(&self, fine: &[[f64; 2]]) -> Option<Triangulation> {
        let (n, nf) = (self.n, 2 * self.n);
        if fine.len() != nf {
            return None;
        }
        let eps = AREA_EPS * size2(fine);
        let mut tris: Vec<[usize; 3]> = Vec::with_capacity(nf - 2);
        // Seam edges whose new sample lies on the coarse seam edge (no ear).
        let mut straight = vec![false; n];
        for m in 0..n {
            let o = orient(fine[2 * m], fine[2 * m + 1], fine[(2 * m + 2) % nf]);
            if o < -eps {
                return None;
            }
            straight[m] = o <= eps;
        }
        // The coarse triangles must stay proper triangles at the fine positions (a sample moved
        // onto a corner at one level need not sit there at the other) and must not swallow a new
        // sample either.
        for t in &self.tris {
            let [a, b, c] = t.map(|v| fine[2 * v]);
            if orient(a, b, c) <= eps {
                return None;
            }
            for m in 0..n {
                let p = fine[2 * m + 1];
                if orient(a, b, p) > eps && orient(b, c, p) > eps && orient(c, a, p) > eps {
                    return None;
                }
            }
            let mut poly = Vec::with_capacity(6);
            for e in 0..3 {
                let (u, v) = (t[e], t[(e + 1) % 3]);
                poly.push(2 * u);
                if v == (u + 1) % n && straight[u] {
                    poly.push(2 * u + 1);
                }
            }
            if poly.len() == 3 {
                tris.push([poly[0], poly[1], poly[2]]);
                continue;
            }
            let sub: Vec<[f64; 2]> = poly.iter().map(|&v| fine[v]).collect();
            tris.extend(ear_clip(&sub)?.tris.into_iter().map(|t| t.map(|v| poly[v])));
        }
        tris.extend((0..n).filter(|&m| !straight[m]).map(|m| [2 * m, 2 * m + 1, (2 * m + 2) % nf]));
        Some(Triangulation::from_tris(nf, tris))
    }

    /// A triangulation from its triangles (counter-clockwise; the caller checks they tile the polygon).
    pub fn from_tris(n: usize, tris: Vec<[usize; 3]>) -> Self {
        let mut t = Triangulation { tris, n, edge: KeyMap::default() };
        t.edge.reserve(3 * t.tris.len());
        for ti in 0..t.tris.len() {
            t.index(ti);
        }
        t
    }

    fn index(&mut self, ti: usize) {
        let [a, b, c] = self.tris[ti];
        for (p, q) in [(a, b), (b, c), (c, a)] {
            let k = self.key(p, q);
            self.edge.insert(k, ti);
        }
    }

    fn unindex(&mut self, ti: usize) {
        let [a, b, c] = self.tris[ti];
        for (p, q) in [(a, b), (b, c), (c, a)] {
            let k = self.key(p, q);
            self.edge.remove(&k);
        }
    }

    /// Third vertex of the triangle containing the directed edge a → b.
    pub fn opposite(&self, a: usize, b: usize) -> Option<usize> {
        let ti = *self.edge.get(&self.key(a, b))?;
        let t = self.tris[ti];
        (0..3).find(|&m| t[m] == a && t[(m + 1) % 3] == b).map(|m| t[(m + 2) % 3])
    }

    /// Undirected edges `(i, j)`, `i < j`, each once: the n seam edges and the n − 3 chords.
    pub fn edges(&self) -> Vec<(usize, usize)> {
        let mut out = Vec::with_capacity(3 * self.tris.len());
        for t in &self.tris {
            for m in 0..3 {
                let (a, b) = (t[m], t[(m + 1) % 3]);
                // Boundary edges appear once (as k → k+1); interior ones twice: keep a < b there.
                // A chord never joins neighbours along the outline (it would be the seam edge
                // itself), so an edge is a boundary edge exactly when it is a seam edge: no
                // look-up in the edge map (this loop was 7 % of a cold solve).
                let interior = !is_seam(self.n, a, b);
                if !interior || a < b {
                    out.push((a.min(b), a.max(b)));
                }
            }
        }
        out
    }

    /// Interior edges (chords) as `(i, j)` with `i < j`.
    pub fn chords(&self) -> Vec<(usize, usize)> {
        // [`Triangulation::edges`] without its seam edges, in the same order, in one pass.
        let mut out = Vec::with_capacity(self.n.saturating_sub(3));
        for t in &self.tris {
            for m in 0..3 {
                let (a, b) = (t[m], t[(m + 1) % 3]);
                if a < b && !is_seam(self.n, a, b) {
                    out.push((a, b));
                }
            }
        }
        out
    }

    /// Replaces chord i–j by the other diagonal of its quad when that quad is strictly convex
    /// in the flat piece `pts`. Returns whether it flipped.
    pub fn flip(&mut self, i: usize, j: usize, pts: &[[f64; 2]], size2: f64) -> bool {
        let (Some(&t1), Some(&t2)) = (self.edge.get(&self.key(i, j)), self.edge.get(&self.key(j, i))) else {
            return false;
        };
        let (Some(k), Some(l)) = (self.opposite(i, j), self.opposite(j, i)) else { return false };
        if k == l {
            return false;
        }
        let eps = AREA_EPS * size2;
        if orient(pts[k], pts[i], pts[l]) <= eps || orient(pts[l], pts[j], pts[k]) <= eps {
            return false;
        }
        self.unindex(t1);
        self.unindex(t2);
        self.tris[t1] = [k, i, l];
        self.tris[t2] = [l, j, k];
        self.index(t1);
        self.index(t2);
        true
    }
}

/// Whether i–j is a seam (boundary) edge of the n-gon.
pub fn is_seam(n: usize, i: usize, j: usize) -> bool {
    let d = i.abs_diff(j);
    d == 1 || d == n - 1
}

/// Squared size of the polygon (bounding-box diagonal²), the scale for area margins.
pub fn size2(pts: &[[f64; 2]]) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in pts {
        for a in 0..2 {
            lo[a] = lo[a].min(p[a]);
            hi[a] = hi[a].max(p[a]);
        }
    }
    (hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2)
}

/// Ear-clipping triangulation of the counter-clockwise simple polygon `pts`. Prefers strictly
/// convex ears (turning by more than [`straight_margin`]) with no other vertex inside or on
/// them; if none is left (a degenerate polygon from very coarse sampling of a thin piece) it
/// returns `None`.
pub fn ear_clip(pts: &[[f64; 2]]) -> Option<Triangulation> {
    let n = pts.len();
    let s2 = size2(pts);
    let eps = AREA_EPS * s2;
    let mut prev: Vec<usize> = (0..n).map(|i| (i + n - 1) % n).collect();
    let mut next: Vec<usize> = (0..n).map(|i| (i + 1) % n).collect();
    let mut alive = n;
    let mut tris = Vec::with_capacity(n.saturating_sub(2));
    let is_ear = |prev: &[usize], next: &[usize], v: usize| -> bool {
        let (a, b, c) = (prev[v], v, next[v]);
        if orient(pts[a], pts[b], pts[c]) <= straight_margin(pts[a], pts[c], s2) {
            return false;
        }
        // No other remaining vertex inside or on the triangle.
        let mut w = next[c];
        while w != a {
            let p = pts[w];
            if orient(pts[a], pts[b], p) >= -eps && orient(pts[b], pts[c], p) >= -eps && orient(pts[c], pts[a], p) >= -eps {
                return false;
            }
            w = next[w];
        }
        true
    };
    let mut v = 0;
    let mut misses = 0;
    while alive > 3 {
        if is_ear(&prev, &next, v) {
            let (a, c) = (prev[v], next[v]);
            tris.push([a, v, c]);
            next[a] = c;
            prev[c] = a;
            alive -= 1;
            misses = 0;
            // Alternate sides so the result is a strip rather than a fan.
            v = next[c];
        } else {
            v = next[v];
            misses += 1;
            if misses > alive {
                return None;
            }
        }
    }
    let (a, c) = (prev[v], next[v]);
    if orient(pts[a], pts[v], pts[c]) <= 0.0 {
        return None;
    }
    tris.push([a, v, c]);
    Some(Triangulation::from_tris(n, tris))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn circle(n: usize) -> Vec<[f64; 2]> {
        (0..n).map(|k| {
            let t = std::f64::consts::TAU * k as f64 / n as f64;
            [t.cos_m(), t.sin_m()]
        }).collect()
    }

    #[test]
    fn ear_clip_gives_n_minus_2_ccw_triangles_and_3n_minus_3_edges() {
        let pts = circle(17);
        let t = ear_clip(&pts).expect("convex polygon triangulates");
        assert_eq!(t.tris.len(), 15);
        assert_eq!(t.edges().len(), 2 * 17 - 3, "wanted n seam edges + n-3 chords");
        assert!(t.tris.iter().all(|&[a, b, c]| orient(pts[a], pts[b], pts[c]) > 0.0));
    }

    #[test]
    fn ear_clip_handles_a_non_convex_polygon_with_collinear_samples() {
        // An L-shape sampled with several points per side.
        let corners = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]];
        let mut pts = vec![];
        for k in 0..6 {
            let (a, b) = (corners[k], corners[(k + 1) % 6]);
            for s in 0..4 {
                let t = s as f64 / 4.0;
                pts.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
            }
        }
        let t = ear_clip(&pts).expect("L-shape triangulates");
        assert_eq!(t.tris.len(), pts.len() - 2);
        let area: f64 = t.tris.iter().map(|&[a, b, c]| orient(pts[a], pts[b], pts[c]) / 2.0).sum();
        assert!((area - 3.0).abs() < 1e-12, "wanted area 3, got {area}");
        assert!(t.tris.iter().all(|&[a, b, c]| orient(pts[a], pts[b], pts[c]) > 0.0), "a zero-area triangle");
    }

    #[test]
    fn flip_replaces_the_diagonal_and_refuses_a_non_convex_quad() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let mut t = Triangulation::from_tris(4, vec![[0, 1, 2], [0, 2, 3]]);
        assert!(t.flip(0, 2, &pts, 2.0));
        assert_eq!(t.chords(), vec![(1, 3)]);
        let dart = [[0.0, 0.0], [1.0, 0.0], [0.2, 0.2], [0.0, 1.0]];
        let mut t = Triangulation::from_tris(4, vec![[0, 1, 2], [0, 2, 3]]);
        assert!(!t.flip(0, 2, &dart, 2.0), "the chord 1-3 would leave the dart");
    }
}
