//! Seam samples where both pieces run straight: left out of the intrinsic embedding
//! ([`super::crossing`]) and put back on their seam edges afterwards.
//!
//! Such a sample has total angle 2π in the glued metric: it is no vertex of Alexandrov's
//! polyhedron but a point inside one of its faces. Bobenko & Izmestiev's method assumes every
//! vertex is a cone point of positive curvature; at a flat one the weighted Delaunay
//! triangulation wants to hide the vertex, the edge that must flip to do so cannot (its quad is
//! not convex), and the seam edges' mean lengths leave its curvature a hair below zero. Two
//! congruent 120 × 80 rectangles with 3 mm corners glued near the offset where they fold flat
//! (3/16) stalled there at every offset within 0.04/16, 222 of whose 256 samples are flat.
//! Without them the embedding is solved on the cone points alone, and a left-out sample goes
//! back onto its seam edge, which is straight in both pieces and in space, at its own distance
//! along it; the triangle on that edge becomes a fan, isometric as the triangle was.

use super::super::metric::{orient, size2, straight_margin, Triangulation};
use super::super::seam::{FlatPiece, SeamPieces};
use super::super::vec3::V3;
use super::intrinsic::lerp2;
use super::overlay::lerp3;

/// The samples of `pieces` to keep: the first, and every one where either piece turns (its two
/// neighbours not collinear with it within [`straight_margin`]: an anchor added on a straight
/// side is no vertex of the polyhedron).
pub(crate) fn kept(pieces: &SeamPieces) -> Vec<usize> {
    let n = pieces.n;
    let s2 = pieces.flat.each_ref().map(|f| size2(&f.pts));
    let straight = |k: usize| (0..2).all(|p| {
        let f = &pieces.flat[p].pts;
        let (a, c) = (f[(k + n - 1) % n], f[(k + 1) % n]);
        orient(a, f[k], c).abs() <= straight_margin(a, c, s2[p])
    });
    (0..n).filter(|&k| k == 0 || !straight(k)).collect()
}

/// The samples `keep` of `pieces` (increasing, with 0): a seam edge that spans left-out samples
/// is straight in both pieces, and its arc midpoint is its chord's.
pub(crate) fn only(pieces: &SeamPieces, keep: &[usize]) -> SeamPieces {
    let n = pieces.n;
    let m = keep.len();
    let flat = pieces.flat.clone().map(|f| {
        let pts: Vec<[f64; 2]> = keep.iter().map(|&k| f.pts[k]).collect();
        let arc_mid = (0..m)
            .map(|i| {
                let (u, w) = (keep[i], if i + 1 < m { keep[i + 1] } else { n });
                if w == u + 1 { f.arc_mid[u] } else { lerp2(f.pts[u], f.pts[w % n], 0.5) }
            })
            .collect();
        FlatPiece { pts, arc_mid, area: f.area, perimeter: f.perimeter }
    });
    SeamPieces { n: m, flat }
}

/// Share of its straight stretch within which a left-out sample and a point of the answer are
/// one point ([`put_back`]).
pub(crate) const SAME: f64 = 1e-6;

/// Where `p` lies along `a` → `b`: 0 at a, 1 at b.
fn along(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1])
}

/// The answer on the kept samples (`cut`, `x`, `tri`: the seam points in order, with any the
/// crossing path added, their positions and each piece's triangulation) with the left-out
/// samples of `pieces` put back: each onto the seam edge between the points it lies between on
/// A's straight stretch, at its own place along that edge in space, the edge's triangle split
/// into a fan from its third vertex. `None` when a left-out sample's stretch is not found in
/// `cut` or its edge has no triangle.
pub(crate) fn put_back(pieces: &SeamPieces, keep: &[usize], cut: &SeamPieces, x: &[V3], tri: &[Triangulation; 2]) -> Option<(SeamPieces, Vec<V3>, [Triangulation; 2])> {
    let (n, m) = (pieces.n, cut.n);
    let a = &pieces.flat[0].pts;
    // Each kept sample's index among the cut's seam points (the cut keeps them, in order).
    let mut at = Vec::with_capacity(keep.len());
    let mut j = 0;
    for &k in keep {
        while j < m && cut.flat[0].pts[j] != a[k] {
            j += 1;
        }
        if j == m {
            return None;
        }
        at.push(j);
    }
    // The left-out samples of each cut seam edge j → j + 1, with their place along it.
    let mut inside: Vec<Vec<(usize, f64)>> = vec![Vec::new(); m];
    for (i, &k) in keep.iter().enumerate() {
        let next = if i + 1 < keep.len() { keep[i + 1] } else { n };
        let (j0, j1) = (at[i], if i + 1 < keep.len() { at[i + 1] } else { at[0] + m });
        for d in k + 1..next {
            // Among the cut's points from j0 to j1 (crossings may lie on the same stretch).
            let t_of = |j: usize| along(a[k], a[next % n], cut.flat[0].pts[j % m]);
            let t = along(a[k], a[next % n], a[d]);
            let e = (j0..j1).find(|&j| t_of(j) <= t && t <= if j + 1 == j1 { 1.0 } else { t_of(j + 1) })?;
            // A crease can cross the seam where a left-out sample was (from a corner of the other
            // piece): the crossing point is the sample then, and a second point there would make
            // an edge of 1e-7 mm whose relative strain means nothing.
            let next_t = if e + 1 == j1 { 1.0 } else { t_of(e + 1) };
            if t - t_of(e) <= SAME || next_t - t <= SAME {
                continue;
            }
            inside[e % m].push((d, t));
        }
    }
    // New order: each cut point, then the samples put back on its outgoing edge.
    let mut new_of = vec![0usize; m];
    let mut order: Vec<Point> = Vec::with_capacity(m + n - keep.len());
    for j in 0..m {
        new_of[j] = order.len();
        order.push(Point::Cut(j));
        inside[j].sort_by(|p, q| p.1.total_cmp(&q.1));
        order.extend(inside[j].iter().map(|&(d, _)| Point::Sample { d, j }));
    }
    let total = order.len();
    let flat = [0, 1].map(|p| {
        let (c, f) = (&cut.flat[p], &pieces.flat[p]);
        let pts: Vec<[f64; 2]> = order.iter().map(|o| match *o { Point::Cut(j) => c.pts[j], Point::Sample { d, .. } => f.pts[d] }).collect();
        let arc_mid = (0..total)
            .map(|i| match (order[i], order[(i + 1) % total]) {
                (Point::Cut(j), Point::Cut(_)) => c.arc_mid[j],
                _ => lerp2(pts[i], pts[(i + 1) % total], 0.5),
            })
            .collect();
        FlatPiece { pts, arc_mid, area: c.area, perimeter: c.perimeter }
    });
    let xs: Vec<V3> = order
        .iter()
        .map(|o| match *o {
            Point::Cut(j) => x[j],
            // On the edge j → j + 1, which is straight in space as in both pieces.
            Point::Sample { d, j } => lerp3(x[j], x[(j + 1) % m], along(cut.flat[0].pts[j], cut.flat[0].pts[(j + 1) % m], a[d])),
        })
        .collect();
    let mut out = Vec::with_capacity(2);
    for t in tri {
        // Each seam edge u → w with samples put back: the triangle that holds it now is replaced
        // by the fan u → samples → w from its third corner. One after the other, so that a
        // triangle with samples on two of its sides (an ear of the few kept points) is split
        // again where its first fan left that side: splitting the original twice overlapped
        // (two 80 × 50 mm rectangles glued 5 mm from their flat gluing came back with an edge
        // of three triangles and an open one, and were called unsettled).
        let mut tris: Vec<[usize; 3]> = t.tris.iter().map(|tr| tr.map(|v| new_of[v])).collect();
        for (j, on_edge) in inside.iter().enumerate() {
            if on_edge.is_empty() {
                continue;
            }
            let (u, w) = (new_of[j], new_of[(j + 1) % m]);
            let (ti, c) = tris.iter().enumerate().find_map(|(ti, tr)| (0..3).find(|&c| tr[c] == u && tr[(c + 1) % 3] == w).map(|c| (ti, c)))?;
            let apex = tris.swap_remove(ti)[(c + 2) % 3];
            // Counter-clockwise like the triangle it splits.
            let mut chain = vec![u];
            chain.extend((1..=on_edge.len()).map(|s| u + s));
            chain.push(w);
            tris.extend(chain.windows(2).map(|e| [e[0], e[1], apex]));
        }
        out.push(Triangulation::from_tris(total, tris));
    }
    let tri = [out.remove(0), out.remove(0)];
    Some((SeamPieces { n: total, flat }, xs, tri))
}

/// A seam point of [`put_back`]'s answer: point `j` of the cut, or the left-out sample `d` of
/// the pieces, on the cut's seam edge `j` → `j + 1`.
#[derive(Debug, Clone, Copy)]
enum Point {
    Cut(usize),
    Sample { d: usize, j: usize },
}
