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
//! two flat pieces. The mesh holds at most one edge between two vertices and refuses a flip that
//! would make a second; a general intrinsic triangulation allows them, and the few gluings that
//! end unconverged for want of one (a triangle with 1 mm corners on a circle) are left so.

use super::super::isometry::{bars, Bar};
use super::super::metric::{self, orient, KeyMap, Triangulation};
use super::super::seam::SeamPieces;
use crate::order::pair_key;

/// Where a seam edge's path crosses an edge `u`–`v` of the mesh: at fraction `f` from `u`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Crossing {
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
    /// Directed edge (`pair_key(i, j)`) → the triangle holding i → j.
    at: KeyMap,
    /// Undirected edge (`pair_key(min, max)`) → its slot in `ends` and `len`.
    slot: KeyMap,
    ends: Vec<(usize, usize)>,
    len: Vec<f64>,
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
    let angle = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
        (u[0] * v[1] - u[1] * v[0]).abs().atan2(u[0] * v[0] + u[1] * v[1])
    };
    for _ in 0..4 * t.len() {
        let mut any = false;
        for (i, j) in t.chords() {
            let (Some(k), Some(l)) = (t.opposite(i, j), t.opposite(j, i)) else { continue };
            if angle(pts[k], pts[i], pts[j]) + angle(pts[l], pts[i], pts[j]) > std::f64::consts::PI + 1e-12 && t.flip(i, j, pts, s2) {
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
    /// triangulation of its flat polygon ([`delaunay`]), with the chord meshes' lengths ([`bars`]:
    /// a chord at its flat length, a seam edge at the mean of A's and B's chords).
    ///
    /// The two chords of a seam edge differ where the pieces curve differently (by ~1e-3 at a
    /// 1 mm corner against a straight side), and one length for both bends the angles of the
    /// triangles on that edge. In the thin ears of an ear clipping the apex across from such an
    /// edge turned by up to 8e-3 rad, and a seam point where both pieces are straight then had
    /// more than 2π around it: no convex polyhedron has that metric, and the embedding never
    /// converged. In the Delaunay triangulations that apex is a sample of the same curved stretch,
    /// and the worst vertex has −1e-9 rad to spare.
    ///
    /// `None` when an edge has no positive length, or when B keeps a chord that A has too (the
    /// mesh holds one edge per vertex pair; B's shared chords are flipped away first where its
    /// flat quads allow).
    pub(crate) fn from_chords(pieces: &SeamPieces, tri: &[Triangulation; 2]) -> Option<Mesh> {
        let n = pieces.n;
        let mut ta = tri[0].clone();
        delaunay(&mut ta, &pieces.flat[0].pts);
        let mut tb = tri[1].clone();
        delaunay(&mut tb, &pieces.flat[1].pts);
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
        let tri = [ta, tb];
        let mut m = Mesh { n, tris: Vec::new(), at: KeyMap::default(), slot: KeyMap::default(), ends: Vec::new(), len: Vec::new(), paths: vec![Vec::new(); n] };
        for b in bars(pieces, &tri) {
            if m.slot.insert(undirected(b.i, b.j), m.ends.len()).is_some() {
                return None;
            }
            m.ends.push((b.i, b.j));
            m.len.push(b.d);
        }
        let outward = tri[0].tris.iter().copied().chain(tri[1].tris.iter().map(|t| [t[0], t[2], t[1]]));
        for t in outward {
            if (0..3).any(|a| !m.slot.contains_key(&undirected(t[a], t[(a + 1) % 3]))) {
                return None;
            }
            m.tris.push(t);
            m.index(m.tris.len() - 1);
        }
        Some(m)
    }

    fn index(&mut self, ti: usize) {
        let t = self.tris[ti];
        for a in 0..3 {
            self.at.insert(pair_key(t[a], t[(a + 1) % 3]), ti);
        }
    }

    /// The third vertex of the triangle holding the directed edge `i` → `j`.
    pub(crate) fn opposite(&self, i: usize, j: usize) -> Option<usize> {
        let t = self.tris[*self.at.get(&pair_key(i, j))?];
        (0..3).find(|&a| t[a] == i && t[(a + 1) % 3] == j).map(|a| t[(a + 2) % 3])
    }

    /// The triangle holding the directed edge `i` → `j`.
    pub(crate) fn triangle(&self, i: usize, j: usize) -> Option<usize> {
        self.at.get(&pair_key(i, j)).copied()
    }

    /// The length of edge `i`–`j`.
    pub(crate) fn length(&self, i: usize, j: usize) -> Option<f64> {
        self.slot.get(&undirected(i, j)).map(|&s| self.len[s])
    }

    /// The lengths of triangle `t`'s edges t0 → t1, t1 → t2, t2 → t0.
    pub(crate) fn triangle_lengths(&self, t: [usize; 3]) -> Option<[f64; 3]> {
        Some([self.length(t[0], t[1])?, self.length(t[1], t[2])?, self.length(t[2], t[0])?])
    }

    /// Whether the seam edge `s` → `s + 1` is an edge of the mesh (its path crosses nothing).
    pub(crate) fn seam_is_edge(&self, i: usize, j: usize) -> bool {
        let n = self.n;
        let s = if (i + 1) % n == j { i } else if (j + 1) % n == i { j } else { return false };
        self.paths[s].is_empty()
    }

    /// The quad of edge `i`–`j` (triangles i, j, k and j, i, l) laid out in the plane: i at the
    /// origin, j on the positive x axis, k above, l below.
    fn layout(&self, i: usize, j: usize, k: usize, l: usize) -> Option<[[f64; 2]; 4]> {
        let d = self.length(i, j)?;
        let pk = apex(d, self.length(i, k)?, self.length(j, k)?, 1.0);
        let pl = apex(d, self.length(i, l)?, self.length(j, l)?, -1.0);
        Some([[0.0, 0.0], [d, 0.0], pk, pl])
    }

    /// The quad of a flippable edge `i`–`j`: the ends k (on the side of i → j) and l of the other
    /// diagonal and the quad's layout ([`Mesh::layout`]); `None` when that diagonal is an edge
    /// already or the quad is not strictly convex.
    fn flippable(&self, i: usize, j: usize) -> Option<(usize, usize, [[f64; 2]; 4])> {
        let (k, l) = (self.opposite(i, j)?, self.opposite(j, i)?);
        if k == l || self.slot.contains_key(&undirected(k, l)) {
            return None;
        }
        let q = self.layout(i, j, k, l)?;
        let size2 = q.iter().map(|p| p[0] * p[0] + p[1] * p[1]).fold(0.0, f64::max);
        let eps = 1e-12 * size2;
        if orient(q[2], q[0], q[3]) <= eps || orient(q[3], q[1], q[2]) <= eps {
            return None;
        }
        Some((k, l, q))
    }

    /// The flip of edge `i`–`j` as [`Mesh::flip`] would do it, without doing it: the new
    /// diagonal's ends k (on the side of i → j) and l, and its length; `None` when it cannot.
    pub(crate) fn flip_preview(&self, i: usize, j: usize) -> Option<(usize, usize, f64)> {
        let (k, l, q) = self.flippable(i, j)?;
        Some((k, l, (q[2][0] - q[3][0]).hypot(q[2][1] - q[3][1])))
    }

    /// Replaces edge `i`–`j` by the other diagonal of its quad, with the length of the quad's
    /// layout, when the quad is strictly convex and that diagonal is not an edge already; the
    /// seam paths through the quad follow. Returns whether it flipped.
    pub(crate) fn flip(&mut self, i: usize, j: usize) -> bool {
        let (Some(t1), Some(t2)) = (self.triangle(i, j), self.triangle(j, i)) else { return false };
        let Some((k, l, q)) = self.flippable(i, j) else { return false };
        let d = (q[2][0] - q[3][0]).hypot(q[2][1] - q[3][1]);
        let quad = [i, j, k, l];
        let at = |v: usize| quad.iter().position(|&w| w == v).map(|a| q[a]);
        let locate = |p: PathPoint| -> Option<[f64; 2]> {
            match p {
                PathPoint::Vertex(v) => at(v),
                PathPoint::On(c) => Some(lerp2(at(c.u)?, at(c.v)?, c.f)),
            }
        };
        let n = self.n;
        // Each path's stretch through the quad (from where it enters to where it leaves, across
        // i–j or inside one of the two triangles) is one straight segment in the layout: it now
        // crosses k–l there or nothing.
        let closure = |p: PathPoint, t: [usize; 3]| match p {
            PathPoint::Vertex(v) => t.contains(&v),
            PathPoint::On(c) => t.contains(&c.u) && t.contains(&c.v),
        };
        let on_diagonal = |p: PathPoint| matches!(p, PathPoint::On(c) if undirected(c.u, c.v) == undirected(i, j));
        let (tri1, tri2) = ([i, j, k], [j, i, l]);
        let inside = |a: PathPoint, b: PathPoint| (closure(a, tri1) && closure(b, tri1)) || (closure(a, tri2) && closure(b, tri2));
        let mut rewritten: Vec<(usize, Vec<Crossing>)> = Vec::new();
        for (s, path) in self.paths.iter().enumerate() {
            if path.is_empty() {
                continue;
            }
            let mut pts: Vec<PathPoint> = Vec::with_capacity(path.len() + 2);
            pts.push(PathPoint::Vertex(s));
            pts.extend(path.iter().map(|&c| PathPoint::On(c)));
            pts.push(PathPoint::Vertex((s + 1) % n));
            let mut out: Vec<PathPoint> = vec![pts[0]];
            let mut changed = false;
            let mut m = 0;
            while m + 1 < pts.len() {
                if on_diagonal(pts[m]) || !inside(pts[m], pts[m + 1]) {
                    out.push(pts[m + 1]);
                    m += 1;
                    continue;
                }
                let mut b = m + 1;
                if on_diagonal(pts[b]) {
                    b += 1;
                    if b >= pts.len() || !inside(pts[b - 1], pts[b]) {
                        return false;
                    }
                }
                let (Some(p0), Some(p1)) = (locate(pts[m]), locate(pts[b])) else { return false };
                if let Some(f) = crossing_fraction(p0, p1, q[2], q[3]) {
                    out.push(PathPoint::On(Crossing { u: k, v: l, f }));
                }
                out.push(pts[b]);
                changed = true;
                m = b;
            }
            if changed {
                let crossings = out[1..out.len() - 1].iter().filter_map(|p| if let PathPoint::On(c) = p { Some(*c) } else { None }).collect();
                rewritten.push((s, crossings));
            }
        }
        // A seam edge that was an edge of the mesh is now crossed by k–l.
        let mut seam = None;
        if self.seam_is_edge(i, j) {
            let s = if (i + 1) % n == j { i } else { j };
            let Some(f) = crossing_fraction(q[if s == i { 0 } else { 1 }], q[if s == i { 1 } else { 0 }], q[2], q[3]) else { return false };
            seam = Some((s, Crossing { u: k, v: l, f }));
        }
        let Some(slot) = self.slot.remove(&undirected(i, j)) else { return false };
        self.slot.insert(undirected(k, l), slot);
        self.ends[slot] = (k, l);
        self.len[slot] = d;
        for (a, b) in [(i, j), (j, k), (k, i), (j, i), (i, l), (l, j)] {
            self.at.remove(&pair_key(a, b));
        }
        self.tris[t1] = [k, i, l];
        self.tris[t2] = [l, j, k];
        self.index(t1);
        self.index(t2);
        for (s, crossings) in rewritten {
            self.paths[s] = crossings;
        }
        if let Some((s, c)) = seam {
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
                let t = self.tris[ti];
                let Some(l) = self.triangle_lengths(t) else { continue };
                // The angle at corner a + 2, across from edge a → a + 1.
                let straight = (0..3).find(|&a| cos_opposite(l[a], l[(a + 1) % 3], l[(a + 2) % 3]) < -1.0 + 1e-12);
                if let Some(a) = straight {
                    if self.flip(t[a], t[(a + 1) % 3]) {
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

    /// The length equations of the edges ([`Bar`]s at their intrinsic lengths).
    pub(crate) fn bars(&self) -> Vec<Bar> {
        self.ends.iter().zip(&self.len).map(|(&(i, j), &d)| Bar { i, j, d }).collect()
    }

    /// Every edge as (i, j), in the order of their slots ([`Mesh::slot_of`]).
    pub(crate) fn edges(&self) -> &[(usize, usize)] {
        &self.ends
    }

    /// The slot of edge `i`–`j`: its index in [`Mesh::edges`].
    pub(crate) fn slot_of(&self, i: usize, j: usize) -> Option<usize> {
        self.slot.get(&undirected(i, j)).copied()
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
            knots.push(Knot { anchor: p0, left: p0, right: Point::new(p0.x - k * r * a0.sin(), p0.y + k * r * a0.cos()) });
            knots.push(Knot { anchor: p1, left: Point::new(p1.x + k * r * a1.sin(), p1.y - k * r * a1.cos()), right: p1 });
        }
        Contour::new(knots, 0).unwrap()
    }

    /// The angle around each vertex, from the edge lengths alone (law of cosines).
    fn angle_sums(m: &Mesh) -> Vec<f64> {
        let mut sum = vec![0.0; m.n];
        for &t in &m.tris {
            for a in 0..3 {
                let (b, c) = (t[(a + 1) % 3], t[(a + 2) % 3]);
                sum[t[a]] += cos_opposite(m.length(b, c).unwrap(), m.length(t[a], b).unwrap(), m.length(t[a], c).unwrap()).acos();
            }
        }
        sum
    }

    /// Intrinsic flips change the triangulation, never the metric: the angle around every vertex
    /// (its curvature) stays what it was, to round-off, after thousands of random flips, some of which
    /// cross the seam; every seam edge stays either an edge of the mesh or a path of crossings,
    /// and every crossing lies on an edge of the mesh.
    #[test]
    fn flips_keep_the_metric_and_track_the_seam() {
        let a = rounded_rectangle();
        let glue = Glue::new(&a, &a, 37.0).unwrap();
        let pieces = glue.sample(128);
        let mut m = Mesh::from_chords(&pieces, &[triangulate(&pieces, 0).unwrap(), triangulate(&pieces, 1).unwrap()]).unwrap();
        let before = angle_sums(&m);
        let mut seed: u64 = 12345;
        let (mut flips, mut crossed) = (0, 0);
        for _ in 0..20_000 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let (i, j) = m.edges()[(seed % m.edges().len() as u64) as usize];
            if m.flip(i, j) {
                flips += 1;
            }
            crossed = crossed.max(m.paths.iter().map(Vec::len).sum::<usize>());
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
                assert!(m.length(s, s1).is_some(), "seam edge {s} is neither an edge nor a path");
            }
            for c in &m.paths[s] {
                assert!(m.length(c.u, c.v).is_some() && c.f > 0.0 && c.f < 1.0, "seam edge {s}: crossing {c:?} is not inside an edge of the mesh");
            }
        }
    }
}
