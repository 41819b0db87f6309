//! Intrinsic triangulations of the glued pieces, for D-forms whose creases cross the seam.
//!
//! The chord meshes of [`super::relax`] keep every edge inside one piece. A crease of
//! Alexandrov's polyhedron can cross the seam, though, wherever the seam is flat (both pieces
//! straight there, total angle 2π): two congruent rectangles with rounded corners glued at an
//! offset have creases running from a corner of one piece straight across a side both pieces
//! share into the other. No chord mesh on the seam samples holds such a crease, so the chord
//! flips cannot reach the polyhedron (the survey's congruent pairs: 110 of 384 found).
//!
//! Here the mesh is an *intrinsic* triangulation of the glued metric (Fisher, Springborn,
//! Bobenko & Schröder, "An algorithm for the construction of intrinsic Delaunay
//! triangulations", 2007; Sharp, Soliman & Crane, "Navigating intrinsic triangulations", 2019):
//! its vertices are the seam samples, each edge is a straight segment of the flat metric with a
//! length, and a flip lays its two triangles out in the plane and puts in the other diagonal with
//! the length of that layout, whether or not the new edge crosses the seam. Bobenko & Izmestiev's
//! method flips it to the polyhedron's triangulation ([`super::alexandrov`]). Each seam edge is
//! tracked through the flips as the list of mesh edges its straight segment crosses (its
//! *path*), so that [`super::overlay`] can cut the triangles along the seam into a mesh of the
//! two flat pieces. Two vertices may be joined by several edges (different straight segments of
//! the metric, e.g. a chord of A and a chord of B between the same two samples, or two edges on
//! either side of a seam point with little curvature): edges are slots, each triangle knows the
//! slot of each of its sides, and each slot its two sides. With at most one edge per vertex pair,
//! the Alexandrov flips were refused thousands of times on a triangle with 1 mm corners glued to
//! a circle and on congruent rectangles, and the embedding stalled; [`Mesh::multi`] says when a
//! flip may add a second edge.

use crate::libm_ext::LibmExt;
use super::super::isometry::{bar_length, Bar};
use super::super::metric::{self, orient, KeyMap, Triangulation};
use super::super::seam::SeamPieces;
use crate::order::pair_key;

/// Where a seam edge's path crosses edge slot `e` of the mesh, whose ends are `u` and `v`: at
/// fraction `f` from `u`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Crossing {
    pub(crate) e: usize,
    pub(crate) u: usize,
    pub(crate) v: usize,
    pub(crate) f: f64,
}

/// An intrinsic triangulation of the glued pieces on the seam samples `0..n`.
#[derive(Debug, Clone)]
pub(crate) struct Mesh {
    pub(crate) n: usize,
    /// Triangles, counter-clockwise seen from outside (A's as in its flat piece, B's reversed).
    pub(crate) tris: Vec<[usize; 3]>,
    /// `side[t][a]`: the edge slot of triangle t's side t[a] → t[a + 1].
    pub(crate) side: Vec<[usize; 3]>,
    /// Each edge slot's two sides, as (triangle, a).
    halves: Vec<[(usize, usize); 2]>,
    /// Each edge slot's ends and length.
    ends: Vec<(usize, usize)>,
    len: Vec<f64>,
    /// For each seam edge s → s + 1, its slot while it is an edge of the mesh.
    seam_slot: Vec<Option<usize>>,
    /// How many edges join each vertex pair (`undirected` key).
    pairs: KeyMap,
    /// Whether a flip may join two vertices that an edge joins already (see [`Mesh::multi`]), and
    /// how many flips were refused for that.
    multi: bool,
    refused: std::cell::Cell<usize>,
    /// For each seam edge s → s + 1, the mesh edges its straight segment crosses, in order from
    /// s; empty while the seam edge is itself an edge of the mesh.
    pub(crate) paths: Vec<Vec<Crossing>>,
}

/// Flips `t` to the Delaunay triangulation of its flat polygon `pts` (each chord's two opposite
/// angles sum to at most π): the triangle on each seam edge then has its apex where the edge
/// subtends the largest angle, a sample of the same curved stretch rather than a distant
/// straight one. See [`Mesh::from_chords`] for why that matters.
fn delaunay(t: &mut Triangulation, pts: &[[f64; 2]]) {
    let s2 = metric::size2(pts);
    for _ in 0..4 * t.len() {
        let mut any = false;
        for (i, j) in t.chords() {
            let (Some(k), Some(l)) = (t.opposite(i, j), t.opposite(j, i)) else { continue };
            if metric::angle(pts[k], pts[i], pts[j]) + metric::angle(pts[l], pts[i], pts[j]) > std::f64::consts::PI + 1e-12 && t.flip(i, j, pts, s2) {
                any = true;
            }
        }
        if !any {
            break;
        }
    }
}

/// A point of a seam path: a mesh vertex, or a crossing of a mesh edge.
#[derive(Debug, Clone, Copy)]
enum PathPoint {
    Vertex(usize),
    On(Crossing),
}

fn undirected(i: usize, j: usize) -> u64 {
    pair_key(i.min(j), i.max(j))
}

/// The flip of an edge as [`Mesh::flip_preview`] sees it: the edge's ends `i` and `j` (in the
/// order of its first side), the new diagonal's ends `k` (on the side of i → j) and `l` and its
/// length `d`, the lengths of the quad's sides k → i, i → l, l → j and j → k (the sides of the
/// new triangles k, i, l and l, j, k), and the quad laid out in the plane (i, j, k, l: i at the
/// origin, j on the positive x axis, k above, l below).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Preview {
    pub(crate) i: usize,
    pub(crate) j: usize,
    pub(crate) k: usize,
    pub(crate) l: usize,
    pub(crate) d: f64,
    pub(crate) sides: [f64; 4],
    layout: [[f64; 2]; 4],
}

/// The apex of a triangle on base (0, 0)–(`base`, 0) with sides `a` (from the origin) and `b`,
/// above the base when `side` is positive, below when negative.
fn apex(base: f64, a: f64, b: f64, side: f64) -> [f64; 2] {
    let x = (base * base + a * a - b * b) / (2.0 * base);
    [x, side * (a * a - x * x).max(0.0).sqrt()]
}

/// The cosine of the angle opposite side `a` in a triangle with sides a, b, c (law of cosines),
/// clamped to [−1, 1].
pub(crate) fn cos_opposite(a: f64, b: f64, c: f64) -> f64 {
    ((b * b + c * c - a * a) / (2.0 * b * c)).clamp(-1.0, 1.0)
}

/// The point a fraction `t` of the way from `a` to `b`.
pub(crate) fn lerp2(a: [f64; 2], b: [f64; 2], t: f64) -> [f64; 2] {
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
}

/// Where segment `p0`–`p1` crosses segment `k`–`l` strictly inside both: the fraction along
/// `k`–`l`, or `None`.
fn crossing_fraction(p0: [f64; 2], p1: [f64; 2], k: [f64; 2], l: [f64; 2]) -> Option<f64> {
    let (o0, o1) = (orient(k, l, p0), orient(k, l, p1));
    let (q0, q1) = (orient(p0, p1, k), orient(p0, p1, l));
    if !(o0 * o1 < 0.0 && q0 * q1 < 0.0) {
        return None;
    }
    Some(q0 / (q0 - q1))
}

impl Mesh {
    /// The mesh of the two pieces' chord triangulations `tri`, each first flipped to the Delaunay
    /// triangulation of its flat polygon ([`delaunay`]), with the chord meshes' lengths (a chord
    /// at its flat length, a seam edge at the mean of A's and B's chords). A chord of A and a
    /// chord of B between the same two samples are two edges.
    ///
    /// The two chords of a seam edge differ where the pieces curve differently (by ~1e-3 at a
    /// 1 mm corner against a straight side), and one length for both bends the angles of the
    /// triangles on that edge. In the thin ears of an ear clipping the apex across from such an
    /// edge turned by up to 8e-3 rad, and a seam point where both pieces are straight then had
    /// more than 2π around it: no convex polyhedron has that metric, and the embedding never
    /// converged. In the Delaunay triangulations that apex is a sample of the same curved stretch,
    /// and the worst vertex has −1e-9 rad to spare.
    ///
    /// `None` when an edge has no positive length or the triangulations do not close up.
    pub(crate) fn from_chords(pieces: &SeamPieces, tri: &[Triangulation; 2]) -> Option<Mesh> {
        let n = pieces.n;
        let mut m = Mesh { n, tris: Vec::new(), side: Vec::new(), halves: Vec::new(), ends: Vec::new(), len: Vec::new(), seam_slot: vec![None; n], pairs: KeyMap::default(), multi: false, refused: Default::default(), paths: vec![Vec::new(); n] };
        // One slot map per kind: A's chords, B's chords, seam edges.
        let mut slots: [KeyMap; 3] = Default::default();
        let mut open: Vec<Vec<(usize, usize)>> = Vec::new();
        let mut ta = tri[0].clone();
        delaunay(&mut ta, &pieces.flat[0].pts);
        let mut tb = tri[1].clone();
        delaunay(&mut tb, &pieces.flat[1].pts);
        // B's chords that A has too, flipped away where B's flat quads allow: without them the
        // mesh starts with one edge per vertex pair.
        let (pts, a) = (&pieces.flat[1].pts, ta.chords());
        let s2 = metric::size2(pts);
        for _ in 0..8 {
            let shared: Vec<(usize, usize)> = tb.chords().into_iter().filter(|e| a.contains(e)).collect();
            if shared.is_empty() {
                break;
            }
            for (i, j) in shared {
                tb.flip(i, j, pts, s2);
            }
        }
        for (p, t) in [ta, tb].iter().enumerate() {
            for tr in &t.tris {
                // Outward: A's as in its flat piece, B's reversed.
                let tr = if p == 0 { *tr } else { [tr[0], tr[2], tr[1]] };
                let ti = m.tris.len();
                let mut sides = [0; 3];
                for a in 0..3 {
                    let (i, j) = (tr[a], tr[(a + 1) % 3]);
                    let kind = if metric::is_seam(n, i, j) { 2 } else { p };
                    let e = *slots[kind].entry(undirected(i, j)).or_insert_with(|| {
                        m.ends.push((i, j));
                        m.len.push(bar_length(pieces, p, i, j));
                        open.push(Vec::new());
                        m.ends.len() - 1
                    });
                    open[e].push((ti, a));
                    sides[a] = e;
                    if kind == 2 {
                        let s = if (i + 1) % n == j { i } else { j };
                        m.seam_slot[s] = Some(e);
                    }
                }
                m.tris.push(tr);
                m.side.push(sides);
            }
        }
        if m.len.iter().any(|&d| d.is_nan() || d <= 0.0) {
            return None;
        }
        m.halves = open.into_iter().map(|h| (h.len() == 2).then(|| [h[0], h[1]])).collect::<Option<_>>()?;
        for &(i, j) in &m.ends {
            *m.pairs.entry(undirected(i, j)).or_insert(0) += 1;
        }
        (m.seam_slot.iter().all(Option::is_some)).then_some(m)
    }

    /// The mesh whose flips may (`true`) or may not join two vertices that an edge joins already.
    ///
    /// Two edges between the same vertices are two straight segments of the metric, and Bobenko
    /// & Izmestiev's flips may need them: with one edge per pair the embedding stalled, its flips
    /// refused thousands of times, on a triangle with 1 mm corners glued to a circle at the even
    /// sixteenths and on 8 of the survey's congruent gluings. Allowed from the start, though, they
    /// led the same triangle at the odd sixteenths, which converged with one edge per pair, to a
    /// continuation that stalls at curvature 6e-2; [`super::crossing`] tries one edge per pair
    /// first.
    pub(crate) fn multi(mut self, multi: bool) -> Mesh {
        self.multi = multi;
        self
    }

    /// How many flips were refused because an edge joined their new diagonal's ends already.
    pub(crate) fn refused(&self) -> usize {
        self.refused.get()
    }

    /// The number of edges.
    pub(crate) fn edge_count(&self) -> usize {
        self.ends.len()
    }

    /// The length of edge slot `e`.
    pub(crate) fn len(&self, e: usize) -> f64 {
        self.len[e]
    }

    /// The lengths of triangle `ti`'s sides t0 → t1, t1 → t2, t2 → t0.
    pub(crate) fn side_lengths(&self, ti: usize) -> [f64; 3] {
        self.side[ti].map(|e| self.len[e])
    }

    /// The other side of edge slot `side[ti][a]`: (triangle, its side index).
    pub(crate) fn across(&self, ti: usize, a: usize) -> (usize, usize) {
        let h = self.halves[self.side[ti][a]];
        if h[0] == (ti, a) { h[1] } else { h[0] }
    }

    /// Edge slot `e`'s two sides, as (triangle, a).
    pub(crate) fn halves(&self, e: usize) -> [(usize, usize); 2] {
        self.halves[e]
    }

    /// The seam edge s → s + 1 that edge slot `e` is, if any.
    pub(crate) fn seam_of(&self, e: usize) -> Option<usize> {
        let (i, j) = self.ends[e];
        [i, j].into_iter().find(|&s| self.seam_slot[s] == Some(e))
    }

    /// The triangles the path of seam edge `s` → `s + 1` runs through, one per segment between
    /// its consecutive points (the sample, each crossing in order, the next sample); `None` for
    /// a path that crosses nothing, or whose crossings do not chain. Each crossing leads to the
    /// other side of its edge; the first triangle is the side of the first edge that holds `s`
    /// and from which the chain reaches `s + 1`. A triangulation with two edges between one pair
    /// of vertices (different geodesics) can have two triangles on the same three vertices, a
    /// "pillow", and telling triangles apart by their vertices then took the wrong one: a
    /// segment from a crossing of a quad's side to a vertex of the quad was taken to run inside
    /// the quad when it ran in the pillow's other triangle, the flip gave that path a crossing
    /// of the new diagonal it does not make, and the seam could not be cut along. A trapezoid
    /// glued to its mirror image near its flat gluing, and thin triangles glued to their
    /// copies, ended stretched by 8–170 % that way, though their embedding had been found.
    pub(crate) fn triangles_along(&self, s: usize) -> Option<Vec<usize>> {
        let path = &self.paths[s];
        let s1 = (s + 1) % self.n;
        let first = path.first()?.e;
        self.halves[first].into_iter().map(|h| h.0).filter(|&t0| self.tris[t0].contains(&s)).find_map(|t0| {
            let mut chain = Vec::with_capacity(path.len() + 1);
            chain.push(t0);
            for (m, c) in path.iter().enumerate() {
                let cur = chain[chain.len() - 1];
                let [h0, h1] = self.halves[c.e];
                let next = if h0.0 == cur { h1.0 } else if h1.0 == cur { h0.0 } else { return None };
                let holds = match path.get(m + 1) {
                    Some(d) => self.side[next].contains(&d.e),
                    None => self.tris[next].contains(&s1),
                };
                if !holds {
                    return None;
                }
                chain.push(next);
            }
            Some(chain)
        })
    }

    /// The quad of edge slot `e`: (t1, a1) with side i → j, (t2, a2) with side j → i, and the
    /// vertices i, j, k (opposite in t1), l (opposite in t2).
    fn quad(&self, e: usize) -> ((usize, usize), (usize, usize), [usize; 4]) {
        let [(t1, a1), (t2, a2)] = self.halves[e];
        let (u, v) = (self.tris[t1], self.tris[t2]);
        ((t1, a1), (t2, a2), [u[a1], u[(a1 + 1) % 3], u[(a1 + 2) % 3], v[(a2 + 2) % 3]])
    }

    /// The flip of edge slot `e` as [`Mesh::flip`] would do it, without doing it; `None` when
    /// the quad is not strictly convex or would put a vertex twice in a triangle.
    pub(crate) fn flip_preview(&self, e: usize) -> Option<Preview> {
        let ((t1, a1), (t2, a2), [i, j, k, l]) = self.quad(e);
        if k == l || t1 == t2 {
            return None;
        }
        if !self.multi && self.pairs.get(&undirected(k, l)).is_some_and(|&c| c > 0) {
            self.refused.set(self.refused.get() + 1);
            return None;
        }
        let d = self.len[e];
        let (s1, s2) = (self.side[t1], self.side[t2]);
        // t1: i → j (e), j → k, k → i; t2: j → i (e), i → l, l → j.
        let (jk, ki, il, lj) = (self.len[s1[(a1 + 1) % 3]], self.len[s1[(a1 + 2) % 3]], self.len[s2[(a2 + 1) % 3]], self.len[s2[(a2 + 2) % 3]]);
        let pk = apex(d, ki, jk, 1.0);
        let pl = apex(d, il, lj, -1.0);
        let q = [[0.0, 0.0], [d, 0.0], pk, pl];
        let size2 = q.iter().map(|p| p[0] * p[0] + p[1] * p[1]).fold(0.0, f64::max);
        let eps = 1e-12 * size2;
        if orient(q[2], q[0], q[3]) <= eps || orient(q[3], q[1], q[2]) <= eps {
            return None;
        }
        Some(Preview { i, j, k, l, d: (pk[0] - pl[0]).hypot_m(pk[1] - pl[1]), sides: [ki, il, lj, jk], layout: q })
    }

    /// Replaces edge slot `e` by the other diagonal of its quad, with the length of the quad's
    /// layout ([`Preview`]), when [`Mesh::flip_preview`] allows it; the seam paths through the
    /// quad follow. Returns whether it flipped.
    pub(crate) fn flip(&mut self, e: usize) -> bool {
        let Some(pv) = self.flip_preview(e) else { return false };
        let ((t1, a1), (t2, a2), [i, j, k, l]) = self.quad(e);
        let q = pv.layout;
        let quad = [i, j, k, l];
        let at = |v: usize| quad.iter().position(|&w| w == v).map(|a| q[a]);
        let locate = |p: PathPoint| -> Option<[f64; 2]> {
            match p {
                PathPoint::Vertex(v) => at(v),
                PathPoint::On(c) => Some(lerp2(at(c.u)?, at(c.v)?, c.f)),
            }
        };
        let (s1, s2) = (self.side[t1], self.side[t2]);
        let n = self.n;
        // Each path's stretch through the quad (from where it enters to where it leaves, across
        // e or inside one of the two triangles) is one straight segment in the layout: it now
        // crosses k–l there or nothing.
        let on_diagonal = |p: PathPoint| matches!(p, PathPoint::On(c) if c.e == e);
        let mut rewritten: Vec<(usize, Vec<Crossing>)> = Vec::new();
        for (s, path) in self.paths.iter().enumerate() {
            if path.is_empty() {
                continue;
            }
            // Segment m runs inside the quad when its triangle is t1 or t2.
            let Some(through) = self.triangles_along(s) else { return false };
            let inside = |m: usize| through[m] == t1 || through[m] == t2;
            let mut pts: Vec<PathPoint> = Vec::with_capacity(path.len() + 2);
            pts.push(PathPoint::Vertex(s));
            pts.extend(path.iter().map(|&c| PathPoint::On(c)));
            pts.push(PathPoint::Vertex((s + 1) % n));
            let mut out: Vec<PathPoint> = vec![pts[0]];
            let mut changed = false;
            let mut m = 0;
            while m + 1 < pts.len() {
                if on_diagonal(pts[m]) || !inside(m) {
                    out.push(pts[m + 1]);
                    m += 1;
                    continue;
                }
                let mut b = m + 1;
                if on_diagonal(pts[b]) {
                    b += 1;
                    if b >= pts.len() || !inside(b - 1) {
                        return false;
                    }
                }
                let (Some(p0), Some(p1)) = (locate(pts[m]), locate(pts[b])) else { return false };
                if let Some(f) = crossing_fraction(p0, p1, q[2], q[3]) {
                    out.push(PathPoint::On(Crossing { e, u: k, v: l, f }));
                }
                out.push(pts[b]);
                changed = true;
                m = b;
            }
            if changed {
                let crossings: Vec<Crossing> = out[1..out.len() - 1].iter().filter_map(|p| if let PathPoint::On(c) = p { Some(*c) } else { None }).collect();
                // A path that crosses nothing now runs along the new diagonal, from k to l.
                if crossings.is_empty() && undirected(k, l) != undirected(s, (s + 1) % n) {
                    return false;
                }
                rewritten.push((s, crossings));
            }
        }
        // A seam edge that was this edge is now crossed by k–l.
        let mut seam = None;
        if let Some(s) = self.seam_of(e) {
            let (from, to) = if s == i { (q[0], q[1]) } else { (q[1], q[0]) };
            let Some(f) = crossing_fraction(from, to, q[2], q[3]) else { return false };
            seam = Some((s, Crossing { e, u: k, v: l, f }));
        }
        // New triangles k, i, l (sides k → i, i → l, l → k) and l, j, k (l → j, j → k, k → l).
        let (ki, jk, il, lj) = (s1[(a1 + 2) % 3], s1[(a1 + 1) % 3], s2[(a2 + 1) % 3], s2[(a2 + 2) % 3]);
        self.tris[t1] = [k, i, l];
        self.tris[t2] = [l, j, k];
        self.side[t1] = [ki, il, e];
        self.side[t2] = [lj, jk, e];
        for (slot, was, now) in [(ki, (t1, (a1 + 2) % 3), (t1, 0)), (il, (t2, (a2 + 1) % 3), (t1, 1)), (lj, (t2, (a2 + 2) % 3), (t2, 0)), (jk, (t1, (a1 + 1) % 3), (t2, 1))] {
            for h in &mut self.halves[slot] {
                if *h == was {
                    *h = now;
                }
            }
        }
        self.halves[e] = [(t1, 2), (t2, 2)];
        if let Some(c) = self.pairs.get_mut(&undirected(i, j)) {
            *c -= 1;
        }
        *self.pairs.entry(undirected(k, l)).or_insert(0) += 1;
        self.ends[e] = (k, l);
        self.len[e] = pv.d;
        for (s, crossings) in rewritten {
            if crossings.is_empty() {
                self.seam_slot[s] = Some(e);
            }
            self.paths[s] = crossings;
        }
        if let Some((s, c)) = seam {
            self.seam_slot[s] = None;
            self.paths[s].push(c);
        }
        true
    }

    /// Flips away every triangle with a straight angle (three seam samples on a line: both
    /// pieces straight there, or one straight and the other's mean seam lengths shorter) by
    /// flipping the edge across from that angle, which leaves the realized shape as it is (the
    /// middle vertex lies on that edge). Such a triangle has no area to cut along the seam
    /// ([`super::overlay::cut`]). The number of flips.
    pub(crate) fn flip_straight_angles(&mut self) -> usize {
        let mut flips = 0;
        for _ in 0..self.n {
            let mut any = false;
            for ti in 0..self.tris.len() {
                let l = self.side_lengths(ti);
                // The angle at corner a + 2, across from side a.
                let straight = (0..3).find(|&a| cos_opposite(l[a], l[(a + 1) % 3], l[(a + 2) % 3]) < -1.0 + 1e-12);
                if let Some(a) = straight {
                    if self.flip(self.side[ti][a]) {
                        flips += 1;
                        any = true;
                    }
                }
            }
            if !any {
                break;
            }
        }
        flips
    }

    /// The length equations of the edges ([`Bar`]s at their intrinsic lengths), one per slot.
    pub(crate) fn bars(&self) -> Vec<Bar> {
        self.ends.iter().zip(&self.len).map(|(&(i, j), &d)| Bar { i, j, d }).collect()
    }

    /// Every edge slot's ends (i, j).
    pub(crate) fn edges(&self) -> &[(usize, usize)] {
        &self.ends
    }
}

#[cfg(test)]
mod tests {
    use super::super::triangulate;
    use super::*;
    use crate::contour::{Contour, Knot};
    use crate::simulate::seam::Glue;
    use kurbo::Point;

    /// A 200 × 40 rectangle whose corners are rounded by 1 mm (quarter circles as cubics).
    fn rounded_rectangle() -> Contour {
        let (w, h, r, k) = (200.0, 40.0, 1.0, 0.5522847498307936);
        let mut knots = Vec::new();
        for (cx, cy, q) in [(w - r, r, 0.0), (w - r, h - r, 1.0), (r, h - r, 2.0), (r, r, 3.0)] {
            let (a0, a1) = ((q - 1.0) * std::f64::consts::FRAC_PI_2, q * std::f64::consts::FRAC_PI_2);
            let (p0, p1) = (Point::new(cx + r * f64::cos(a0), cy + r * f64::sin(a0)), Point::new(cx + r * f64::cos(a1), cy + r * f64::sin(a1)));
            knots.push(Knot { anchor: p0, left: p0, right: Point::new(p0.x - k * r * a0.sin_m(), p0.y + k * r * a0.cos_m()) });
            knots.push(Knot { anchor: p1, left: Point::new(p1.x + k * r * a1.sin_m(), p1.y - k * r * a1.cos_m()), right: p1 });
        }
        Contour::new(knots, 0).unwrap()
    }

    /// The angle around each vertex, from the edge lengths alone (law of cosines).
    fn angle_sums(m: &Mesh) -> Vec<f64> {
        let mut sum = vec![0.0; m.n];
        for (ti, &t) in m.tris.iter().enumerate() {
            let l = m.side_lengths(ti);
            for a in 0..3 {
                sum[t[a]] += cos_opposite(l[(a + 1) % 3], l[a], l[(a + 2) % 3]).acos_m();
            }
        }
        sum
    }

    /// Intrinsic flips change the triangulation, never the metric: the angle around every vertex
    /// (its curvature) stays what it was, to round-off, after thousands of random flips, some of which
    /// cross the seam; every seam edge stays either an edge of the mesh or a path of crossings,
    /// every crossing lies on an edge of the mesh, and every edge slot's two sides are sides of
    /// triangles with its ends, also where two edges join the same two vertices.
    #[test]
    fn flips_keep_the_metric_and_track_the_seam() {
        let a = rounded_rectangle();
        let glue = Glue::new(&a, &a, 37.0).unwrap();
        let pieces = glue.sample(128);
        let mut m = Mesh::from_chords(&pieces, &[triangulate(&pieces, 0).unwrap(), triangulate(&pieces, 1).unwrap()]).unwrap().multi(true);
        let before = angle_sums(&m);
        let mut seed: u64 = 12345;
        let (mut flips, mut crossed, mut multi) = (0, 0, 0);
        for _ in 0..20_000 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            if m.flip((seed % m.edge_count() as u64) as usize) {
                flips += 1;
            }
            crossed = crossed.max(m.paths.iter().map(Vec::len).sum::<usize>());
            let mut pairs: Vec<u64> = m.edges().iter().map(|&(i, j)| undirected(i, j)).collect();
            pairs.sort_unstable();
            multi = multi.max(pairs.windows(2).filter(|w| w[0] == w[1]).count());
        }
        let after = angle_sums(&m);
        let worst = before.iter().zip(&after).map(|(b, a)| (b - a).abs()).fold(0.0, f64::max);
        assert!(flips > 1000 && crossed > 0, "wanted many flips, some across the seam: got {flips} flips, at most {crossed} crossings");
        // Round-off only: each new length comes from a layout of lengths that came from layouts,
        // and an angle near π is read through acos (~1e-8 rad); a wrong layout would be off by
        // whole angles.
        assert!(worst < 1e-5, "wanted every vertex's angle unchanged by {flips} flips, got a change of {worst:.2e} rad");
        for s in 0..m.n {
            let s1 = (s + 1) % m.n;
            if m.paths[s].is_empty() {
                let e = m.seam_slot[s].unwrap_or_else(|| panic!("seam edge {s} is neither an edge nor a path"));
                let (i, j) = m.edges()[e];
                assert!((i, j) == (s, s1) || (i, j) == (s1, s), "seam edge {s} is slot {e}, which joins {i} and {j}");
            }
            for c in &m.paths[s] {
                let (i, j) = m.edges()[c.e];
                assert!(((i, j) == (c.u, c.v) || (i, j) == (c.v, c.u)) && c.f > 0.0 && c.f < 1.0, "seam edge {s}: crossing {c:?} is not inside an edge of the mesh");
            }
        }
        // Every slot's two sides are sides of triangles that name it, with the slot's ends.
        for e in 0..m.edge_count() {
            for (ti, a) in m.halves(e) {
                let t = m.tris[ti];
                let (i, j) = m.edges()[e];
                assert_eq!(m.side[ti][a], e, "slot {e}: side {a} of triangle {ti} is slot {}", m.side[ti][a]);
                assert!([t[a], t[(a + 1) % 3]] == [i, j] || [t[a], t[(a + 1) % 3]] == [j, i], "slot {e} joins {i} and {j}, triangle {ti}'s side {a} {t:?}");
            }
        }
        assert!(multi > 0, "wanted some vertex pairs joined by two edges on the way, got none");
    }
}
