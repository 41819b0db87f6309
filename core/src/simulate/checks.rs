//! Checks of a solved mesh shared by both paths: dihedral signs (reflex chords), convexity as a
//! whole, flat folds, folds inside a piece, self-intersection, chords shared by both pieces.

use crate::libm_ext::LibmExt;
use super::metric::{self, Triangulation};
use super::vec3::{centroid_and_radius, cross, dot, norm, sub, V3};

/// Out-of-plane sine above which a chord counts as reflex and is flipped. Below it the two
/// triangles are coplanar to round-off and either diagonal is right.
pub const REFLEX_SINE: f64 = 1e-6;

/// Out-of-plane sine of chord i–j in piece `p`: positive when reflex (the far vertex of the
/// neighbouring triangle lies outside the plane of the outward face).
pub fn reflex_sine(x: &[V3], t: &Triangulation, p: usize, i: usize, j: usize) -> Option<f64> {
    let k = t.opposite(i, j)?;
    let l = t.opposite(j, i)?;
    let n = cross(sub(x[j], x[i]), sub(x[k], x[i]));
    let (nn, dl) = (norm(n), sub(x[l], x[i]));
    let ndl = norm(dl);
    if nn == 0.0 || ndl == 0.0 {
        return Some(0.0);
    }
    // A's faces are outward as ccw in the flat piece; B's are reversed.
    let s = if p == 0 { 1.0 } else { -1.0 };
    Some(s * dot(n, dl) / (nn * ndl))
}

/// Largest out-of-plane sine of a reflex chord (0 when the mesh is convex).
pub(crate) fn worst_reflex(x: &[V3], tri: &[Triangulation; 2]) -> f64 {
    (0..2)
        .flat_map(|p| tri[p].chords().into_iter().filter_map(move |(i, j)| reflex_sine(x, &tri[p], p, i, j)))
        .fold(0.0, f64::max)
}

/// Whether the mesh lies in a plane (to 1e-5 of its size) without being a doubly covered convex
/// polygon: its area is more than twice the area of its points' convex hull in that plane.
///
/// The dihedral and plane tests cannot see such a state: a fold of 180° has out-of-plane sine
/// 0, and no vertex lies above the plane of any face. Yet a flat-folded sheet (flaps folded onto
/// a face, covering parts of the plane four times) is an isometric realization that is not
/// convex; the only flat convex one (Alexandrov's degenerate case) is a doubly covered convex
/// polygon, whose area is exactly twice its hull's. Two equilateral triangles glued at a
/// quarter-perimeter offset ended in such a flat fold, "converged" at volume 0.
pub(crate) fn folded_flat(x: &[V3], tri: &[Triangulation; 2]) -> bool {
    let (c, size) = centroid_and_radius(x);
    // Normal of the largest triangle; flat when every vertex is within 1e-5·size of its plane
    // (a convex body that thin has an area within O(1e-10) of twice its shadow's, far inside the
    // 1e-6 allowed below, so a thin convex shape is never taken for a fold).
    let mut best = ([0.0; 3], 0.0);
    let mut area = 0.0;
    for t in tri {
        for &[a, b, d] in &t.tris {
            let m = cross(sub(x[b], x[a]), sub(x[d], x[a]));
            let l = norm(m);
            area += 0.5 * l;
            if l > best.1 {
                best = (m, l);
            }
        }
    }
    if best.1 == 0.0 || size == 0.0 {
        return false;
    }
    let u = best.0.map(|v| v / best.1);
    if x.iter().any(|p| dot(u, sub(*p, c)).abs() > 1e-5 * size) {
        return false;
    }
    // In-plane coordinates, then the hull's area (Andrew's monotone chain).
    let e1 = if u[0].abs() < 0.9 { [1.0, 0.0, 0.0] } else { [0.0, 1.0, 0.0] };
    let e1 = { let w = cross(u, e1); let l = norm(w); w.map(|v| v / l) };
    let e2 = cross(u, e1);
    let q: Vec<[f64; 2]> = x.iter().map(|p| [dot(sub(*p, c), e1), dot(sub(*p, c), e2)]).collect();
    // Lexicographic (x, then y) order by two stable argsorts, y first (the crate's one f64 sort,
    // see crate::order).
    let by_y: Vec<[f64; 2]> = crate::order::argsort(&q.iter().map(|p| p[1]).collect::<Vec<_>>()).into_iter().map(|i| q[i]).collect();
    let q: Vec<[f64; 2]> = crate::order::argsort(&by_y.iter().map(|p| p[0]).collect::<Vec<_>>()).into_iter().map(|i| by_y[i]).collect();
    let mut hull: Vec<[f64; 2]> = Vec::with_capacity(2 * q.len());
    for pass in 0..2 {
        let start = hull.len();
        let it: Box<dyn Iterator<Item = &[f64; 2]>> = if pass == 0 { Box::new(q.iter()) } else { Box::new(q.iter().rev()) };
        for &p in it {
            while hull.len() >= start + 2 && metric::orient(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0 {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    let h2: f64 = (0..hull.len()).map(|m| metric::orient([0.0, 0.0], hull[m], hull[(m + 1) % hull.len()])).sum();
    area > (1.0 + 1e-6) * h2.abs()
}

/// Thickness of a closed mesh across the plane of its seam (vertices `0..seam`, in order),
/// relative to its size: the largest distance of a vertex from the plane through the centroid
/// normal to the seam loop's vector area, over the largest distance from the centroid.
pub fn thickness(x: &[V3], seam: usize) -> f64 {
    let (c, size) = centroid_and_radius(x);
    let mut n = [0.0; 3];
    for k in 0..seam {
        let m = cross(sub(x[k], c), sub(x[(k + 1) % seam], c));
        n = [n[0] + m[0], n[1] + m[1], n[2] + m[2]];
    }
    let l = norm(n);
    if l == 0.0 || size == 0.0 {
        return 0.0;
    }
    x.iter().map(|p| dot(n, sub(*p, c)).abs() / l).fold(0.0, f64::max) / size
}

/// Largest height of a vertex above the plane of a face (outward), relative to the largest
/// distance of a vertex from the centroid: 0 for a convex mesh. Every `stride`-th vertex is
/// tested against every face.
///
/// No reflex chord is not enough: every chord can fold outward while the surface as a whole is
/// not convex (a locally convex but not embedded realization). A triangle glued to a circle ended
/// there, converged and with no reflex chord, 2 % below the convex shape's volume and with
/// vertices a whole size outside some face's plane. A closed surface that is convex at every
/// edge and embedded is convex (Hadamard), so the two tests together rule out such branches.
pub(crate) fn outside(x: &[V3], tri: &[Triangulation; 2], stride: usize) -> f64 {
    outside_of(x, tri, stride, |_, _| true)
}

/// [`outside`] against the faces `face(piece, triangle)` keeps.
fn outside_of(x: &[V3], tri: &[Triangulation; 2], stride: usize, face: impl Fn(usize, [usize; 3]) -> bool) -> f64 {
    let (_, size) = centroid_and_radius(x);
    let mut worst = 0.0f64;
    for (p, t) in tri.iter().enumerate() {
        for &[a, b, c] in t.tris.iter().filter(|&&t| face(p, t)) {
            let (b, c) = if p == 0 { (b, c) } else { (c, b) };
            let m = cross(sub(x[b], x[a]), sub(x[c], x[a]));
            let l = norm(m);
            if l == 0.0 {
                continue;
            }
            let top = x.iter().step_by(stride.max(1)).map(|q| dot(m, sub(*q, x[a]))).fold(0.0, f64::max);
            worst = worst.max(top / l);
        }
    }
    if size > 0.0 { worst / size } else { 0.0 }
}

/// Smallest `2·area / longest²` (the sine of a needle's sharp angle, or of a cap's blunt one) of
/// a flat triangle whose plane [`sound_outside`] trusts.
pub(crate) const SOUND_FACE: f64 = 2e-2;

/// [`outside`] (every vertex) against the faces that are not slivers in their flat piece
/// `flat[p]` ([`SOUND_FACE`]).
///
/// A sliver's plane in 3D is set by a side far shorter than the others, so it tilts with
/// movements that change no length noticeably: on two congruent 120 × 80 rectangles with 1 mm
/// corners at 7/16, a triangle of three nearly collinear seam samples (angle 179.2°) tilted
/// until a vertex stood 72 mm "above" it, on a shape convex to 1e-9 of its size by every other
/// face. A whole-shape failure, which this test is for, puts vertices outside sound faces too.
pub(crate) fn sound_outside(x: &[V3], tri: &[Triangulation; 2], flat: [&[[f64; 2]]; 2]) -> f64 {
    outside_of(x, tri, 1, |p, [a, b, c]| {
        let q = flat[p];
        let d2 = |u: [f64; 2], v: [f64; 2]| (u[0] - v[0]).powi(2) + (u[1] - v[1]).powi(2);
        let longest = d2(q[a], q[b]).max(d2(q[b], q[c])).max(d2(q[c], q[a]));
        metric::orient(q[a], q[b], q[c]).abs() >= SOUND_FACE * longest
    })
}

/// Depth of the worst dent relative to the shape's size: over the reflex chords, how far the
/// far vertex of the neighbouring triangle stands outside the outward face's plane. Unlike
/// [`worst_reflex`]'s sine it stays small where a needle triangle (a long chord to two seam
/// samples 0.1 mm apart) tilts: there a sine of 0.08 is a dent of 8 µm.
pub(crate) fn dent_depth(x: &[V3], tri: &[Triangulation; 2]) -> f64 {
    let (_, size) = centroid_and_radius(x);
    let mut worst = 0.0f64;
    for (p, t) in tri.iter().enumerate() {
        for (i, j) in t.chords() {
            if let (Some(s), Some(l)) = (reflex_sine(x, t, p, i, j), t.opposite(j, i)) {
                worst = worst.max(s * norm(sub(x[l], x[i])));
            }
        }
    }
    if size > 0.0 { worst / size } else { 0.0 }
}

/// [`outside`] for the solver's loops: against every face, 32 vertices spread along the seam.
/// The test is for whole-shape failures (a vertex a sizeable fraction of the size outside), which
/// no 32 of them all miss, and it keeps the cost at 32·(2n − 4) plane tests, nothing next to a
/// solver step.
pub(crate) fn outside_sampled(x: &[V3], tri: &[Triangulation; 2]) -> f64 {
    outside(x, tri, x.len() / 32)
}

/// Whether every vertex (not only [`outside_sampled`]'s 32) is within [`OUTSIDE_TOL`] of every
/// face: the test of a finest-level answer before it is called converged, run once per answer
/// (2n² plane tests). A nearly flat form (a 24-gon or a 48-gon glued to a circle, nearly
/// congruent pieces) can fold a rim face up so that a few vertices stand a whole size above its
/// plane while the 32 sampled ones do not: such shapes "converged" at 64 and 128 seam vertices
/// with 32–40 reflex chords and a vertex 1.8 sizes outside a face.
pub(crate) fn convex_as_a_whole(x: &[V3], tri: &[Triangulation; 2]) -> bool {
    outside(x, tri, 1) <= OUTSIDE_TOL
}

/// Relative height above a face (see [`outside`]) that makes a solution non-convex: far above the
/// tiny folds that coarse levels keep (see [`DENT_SINE`]).
pub(crate) const OUTSIDE_TOL: f64 = 1e-2;

/// Whether the flat sample polygon `pts` (counter-clockwise) is convex: no vertex turns
/// clockwise by more than [`metric::straight_margin`] (round-off, and the snap of the piece's
/// frame off a straight side).
pub fn is_convex_polygon(pts: &[[f64; 2]]) -> bool {
    let n = pts.len();
    let s2 = metric::size2(pts);
    (0..n).all(|k| {
        let (a, c) = (pts[(k + n - 1) % n], pts[(k + 1) % n]);
        metric::orient(a, pts[k], c) >= -metric::straight_margin(a, c, s2)
    })
}

/// The bend across chord i–j of piece `p` (the angle between the two triangles' normals: 0 when
/// flat, π when folded back onto itself), or `None` for a seam edge or a missing triangle.
pub fn bend(x: &[V3], t: &Triangulation, i: usize, j: usize) -> Option<f64> {
    let k = t.opposite(i, j)?;
    let l = t.opposite(j, i)?;
    let n1 = cross(sub(x[j], x[i]), sub(x[k], x[i]));
    let n2 = cross(sub(x[i], x[j]), sub(x[l], x[j]));
    if norm(n1) == 0.0 || norm(n2) == 0.0 {
        return Some(0.0);
    }
    Some(norm(cross(n1, n2)).atan2_m(dot(n1, n2)))
}

/// A bend above this inside a piece is a fold (a crease the sheet cannot take without damage).
pub const FOLD_BEND: f64 = std::f64::consts::FRAC_PI_2;

/// Largest bend ([`bend`]) across a chord of either piece.
pub fn max_bend(x: &[V3], tri: &[Triangulation; 2]) -> f64 {
    tri.iter().flat_map(|t| t.chords().into_iter().filter_map(move |(i, j)| bend(x, t, i, j))).fold(0.0, f64::max)
}

/// Whether segment p–q passes through the inside of triangle (a, b, c), both strictly (by a
/// relative margin `eps`, barycentric and along the segment): Möller & Trumbore 1997. A segment
/// parallel to the triangle's plane, or within `flat` of it at both ends, does not count (two
/// sheets lying on each other, as in the flat doubly covered D-form, touch but do not cross).
fn segment_crosses(p: V3, q: V3, a: V3, b: V3, c: V3, eps: f64, flat: f64) -> bool {
    let d = sub(q, p);
    let (e1, e2) = (sub(b, a), sub(c, a));
    // A segment within `flat` of the triangle's plane at both ends lies on it: sheets touching
    // up to round-off (the flat doubly covered D-form ends ~1e-8 of its size apart).
    let m = cross(e1, e2);
    let lm = norm(m);
    if lm > 0.0 && (dot(m, sub(p, a)) / lm).abs() <= flat && (dot(m, sub(q, a)) / lm).abs() <= flat {
        return false;
    }
    let h = cross(d, e2);
    let det = dot(e1, h);
    if det.abs() <= 1e-9 * norm(e1) * norm(e2) * norm(d) {
        return false;
    }
    let s = sub(p, a);
    let u = dot(s, h) / det;
    let w = cross(s, e1);
    let v = dot(d, w) / det;
    let t = dot(e2, w) / det;
    u > eps && v > eps && u + v < 1.0 - eps && t > eps && t < 1.0 - eps
}

/// Whether two triangles of the closed mesh cross each other away from what they share: a side
/// of one (not touching a shared vertex) through the inside of the other. Triangles sharing a
/// side meet only along it unless folded, which [`max_bend`] sees. Bounding boxes first, swept
/// along x (sort and sweep: the boxes sorted by their low x, each compared only with the later
/// ones that start before it ends), so the pairs tested are those whose boxes overlap, as
/// before, without the `F²/2` box tests (130,000 at 256 seam vertices) of every pair; then each
/// face's plane, then Möller–Trumbore. A convex D-form's chords run across the whole form, so
/// many pairs of boxes overlap there (the crossed 2:1 ellipses at 0.3 of the perimeter, 256
/// seam vertices: 28,000 pairs of 129,000); on a convex answer every face lies on one side of
/// every other's plane, so the planes settle them (4.5 → 0.6 ms of an 11 ms solve, native).
pub fn self_intersecting(x: &[V3], tri: &[Triangulation; 2]) -> bool {
    let faces: Vec<[usize; 3]> = tri.iter().flat_map(|t| t.tris.iter().copied()).collect();
    faces_cross(x, &faces)
}

/// [`self_intersecting`] for any closed triangle mesh (`faces` index `x`).
pub fn faces_cross(x: &[V3], faces: &[[usize; 3]]) -> bool {
    let flat = 1e-6 * centroid_and_radius(x).1;
    let boxes: Vec<(V3, V3)> = faces
        .iter()
        .map(|f| {
            let lo = [0, 1, 2].map(|a| f.iter().map(|&v| x[v][a]).fold(f64::INFINITY, f64::min));
            let hi = [0, 1, 2].map(|a| f.iter().map(|&v| x[v][a]).fold(f64::NEG_INFINITY, f64::max));
            (lo, hi)
        })
        .collect();
    // Each face's plane (a normal, not unit, and a point on it): a side of one face can only
    // pass through another if its ends lie strictly on either side of that face's plane, so a
    // face all on one side of the other's plane is skipped before the Möller–Trumbore tests
    // (on a convex answer that is every pair).
    let planes: Vec<(V3, V3)> = faces.iter().map(|f| (cross(sub(x[f[1]], x[f[0]]), sub(x[f[2]], x[f[0]])), x[f[0]])).collect();
    let straddles = |f: [usize; 3], (m, a): (V3, V3)| {
        let d = f.map(|v| dot(m, sub(x[v], a)));
        d.iter().any(|&v| v > 0.0) && d.iter().any(|&v| v < 0.0)
    };
    const EPS: f64 = 1e-9;
    let by_x = crate::order::argsort(&boxes.iter().map(|b| b.0[0]).collect::<Vec<_>>());
    for (r, &i) in by_x.iter().enumerate() {
        for &j in &by_x[r + 1..] {
            let (bi, bj) = (boxes[i], boxes[j]);
            if bj.0[0] > bi.1[0] {
                break;
            }
            if (0..3).any(|a| bi.1[a] < bj.0[a] || bj.1[a] < bi.0[a]) {
                continue;
            }
            let (fi, fj) = (faces[i], faces[j]);
            let shared = fi.iter().filter(|v| fj.contains(v)).count();
            if shared >= 2 {
                continue;
            }
            let crosses = |f: [usize; 3], g: [usize; 3]| {
                (0..3).any(|m| {
                    let (p, q) = (f[m], f[(m + 1) % 3]);
                    !g.contains(&p) && !g.contains(&q) && segment_crosses(x[p], x[q], x[g[0]], x[g[1]], x[g[2]], EPS, flat)
                })
            };
            if (straddles(fi, planes[j]) && crosses(fi, fj)) || (straddles(fj, planes[i]) && crosses(fj, fi)) {
                return true;
            }
        }
    }
    false
}

/// Whether `t` triangulates its polygon: `n − 2` triangles, each seam edge `k → k+1` on exactly
/// one of them, every other edge on exactly two, once each way. A triangulation that fails it
/// has overlapping triangles or a hole, and the glued mesh is no closed 2-manifold whatever its
/// lengths: a thin triangle glued to its copy 29.7 mm along its 200 mm perimeter was called
/// converged with an edge of three triangles and an open one (the intrinsic path had put its
/// straight sides' samples back by splitting one triangle twice, [`super::convex::flat`]).
pub fn triangulates_polygon(t: &Triangulation) -> bool {
    let n = t.len();
    if n < 3 || t.tris.len() != n - 2 {
        return false;
    }
    // Directed edges keyed by [`crate::order::pair_key`] in a [`metric::KeyMap`] (see
    // [`chord_keys`]).
    let key = crate::order::pair_key;
    let mut seen = metric::KeyMap::default();
    for tri in &t.tris {
        for m in 0..3 {
            let (a, b) = (tri[m], tri[(m + 1) % 3]);
            if a >= n || b >= n || a == b || seen.insert(key(a, b), 0).is_some() {
                return false;
            }
        }
    }
    let has = |a: usize, b: usize| seen.contains_key(&key(a, b));
    t.tris.iter().flat_map(|tri| (0..3).map(move |m| (tri[m], tri[(m + 1) % 3]))).all(|(a, b)| has(b, a) != ((a + 1) % n == b))
        && (0..n).all(|k| has(k, (k + 1) % n))
}

/// The chords of `t` keyed by [`crate::order::pair_key`] ([`metric::KeyMap`], the map type
/// the triangulations use, so the .wasm holds one instantiation of the hash table).
pub fn chord_keys(t: &Triangulation) -> metric::KeyMap {
    t.chords().into_iter().map(|(i, j)| (crate::order::pair_key(i, j), 0)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every pair of faces through Möller–Trumbore, with no boxes, sweep or planes.
    fn brute(x: &[V3], faces: &[[usize; 3]]) -> bool {
        let flat = 1e-6 * centroid_and_radius(x).1;
        let crosses = |f: [usize; 3], g: [usize; 3]| {
            (0..3).any(|m| {
                let (p, q) = (f[m], f[(m + 1) % 3]);
                !g.contains(&p) && !g.contains(&q) && segment_crosses(x[p], x[q], x[g[0]], x[g[1]], x[g[2]], 1e-9, flat)
            })
        };
        (0..faces.len()).any(|i| {
            (i + 1..faces.len()).any(|j| {
                let shared = faces[i].iter().filter(|v| faces[j].contains(v)).count();
                shared < 2 && (crosses(faces[i], faces[j]) || crosses(faces[j], faces[i]))
            })
        })
    }

    /// The broad phase (boxes swept along x, then each face's plane) never changes the answer of
    /// the pairwise test: random soups of 2–12 triangles on 12 points, many of them crossing,
    /// and the faces of a convex polyhedron (an octahedron's, none crossing; with a fin from
    /// its inside out through a face, crossing).
    #[test]
    fn broad_phase_keeps_the_pairwise_answer() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut rand = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut crossing, mut clear) = (0, 0);
        for case in 0..2000 {
            let x: Vec<V3> = (0..12).map(|_| [rand(), rand(), rand()]).collect();
            let nf = 2 + case % 11;
            let faces: Vec<[usize; 3]> = (0..nf)
                .filter_map(|_| {
                    let f = [0, 1, 2].map(|_| ((rand() * 12.0) as usize).min(11));
                    (f[0] != f[1] && f[1] != f[2] && f[0] != f[2]).then_some(f)
                })
                .collect();
            let (want, got) = (brute(&x, &faces), faces_cross(&x, &faces));
            assert_eq!(got, want, "case {case}: faces {faces:?} on {x:?}: wanted {want}, got {got}");
            if want { crossing += 1 } else { clear += 1 }
        }
        assert!(crossing > 200 && clear > 200, "the soups should test both answers: {crossing} crossing, {clear} clear");
        let mut x: Vec<V3> = vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]];
        let mut faces: Vec<[usize; 3]> = (0..4).flat_map(|k| [[k, (k + 1) % 4, 4], [(k + 1) % 4, k, 5]]).collect();
        assert!(!faces_cross(&x, &faces) && !brute(&x, &faces), "the octahedron does not cross itself");
        // A fin from inside to outside through the face (0, 1, 4).
        x.extend([[0.1, 0.1, 0.1], [0.1, 0.1, 0.2], [0.9, 0.9, 0.9]]);
        faces.push([6, 7, 8]);
        assert!(faces_cross(&x, &faces) && brute(&x, &faces), "a fin through a face crosses it");
    }
}
