//! An intrinsic triangulation ([`super::intrinsic::Mesh`]) cut along the seam into a mesh of
//! the two flat pieces: the common subdivision of the triangulation and the seam (Sharp,
//! Soliman & Crane 2019, §5) for the one curve that matters here.
//!
//! Where a seam edge's path crosses a mesh edge, the crossing becomes a seam vertex (its flat
//! position is on the seam edge of each piece, at its share of the path's length; its 3D
//! position on the mesh edge). Each triangle is cut along the path segments inside it into
//! convex polygons, each lying in one piece (A to the left of a seam path, which runs as A's
//! outline does), and the polygons are triangulated in that piece's flat coordinates. The
//! result is a chord mesh like any other, on more seam vertices than the samples: every one of
//! its triangles is isometric to its flat triangle, and every vertex is a seam point.

use crate::libm_ext::LibmExt;
use super::super::metric::{self, orient, Triangulation};
use super::super::seam::{FlatPiece, SeamPieces};
use super::super::vec3::{norm, sub, V3};
use super::intrinsic::{lerp2, Mesh};

pub(crate) fn lerp3(a: V3, b: V3, t: f64) -> V3 {
    [0, 1, 2].map(|c| a[c] + t * (b[c] - a[c]))
}

/// A convex polygon (counter-clockwise in `pts`, possibly with several vertices on a line)
/// cut into triangles of positive area: each cut takes off a strictly convex vertex, one next to
/// a straight vertex first, so that a run of collinear vertices never ends up alone.
fn triangulate_convex(poly: &[usize], pts: &[[f64; 2]], eps: f64) -> Option<Vec<[usize; 3]>> {
    let mut v = poly.to_vec();
    let mut out = Vec::with_capacity(v.len().saturating_sub(2));
    while v.len() > 3 {
        let k = v.len();
        let turn = |m: usize| orient(pts[v[(m + k - 1) % k]], pts[v[m]], pts[v[(m + 1) % k]]);
        let straight = |m: usize| turn(m).abs() <= eps;
        let m = (0..k)
            .find(|&m| turn(m) > eps && (straight((m + 1) % k) || straight((m + k - 1) % k)))
            .or_else(|| (0..k).find(|&m| turn(m) > eps))?;
        out.push([v[(m + k - 1) % k], v[m], v[(m + 1) % k]]);
        v.remove(m);
    }
    if v.len() == 3 {
        if orient(pts[v[0]], pts[v[1]], pts[v[2]]) <= eps {
            return None;
        }
        out.push([v[0], v[1], v[2]]);
    }
    Some(out)
}

/// The polygons `cycles` of one piece (counter-clockwise in its flat coordinates `pts`) with
/// each one of no area (every turn within `eps`, the doubled area: points on one line) merged
/// into a neighbour that shares its boundary: the neighbour's stretch along that line, from
/// one end of the sliver to the other, then runs through all of the sliver's points in order,
/// straight vertices that [`triangulate_convex`] cuts off with triangles of area. Such a sliver
/// is three seam samples on a straight stretch of this piece (with any crossings on its sides)
/// that the embedding joined in a triangle, the other piece's chords there being shorter (a
/// 9-gon glued to a circle: samples 15 µm apart beside a corner, refused as a mesh that could
/// not be cut along). Merging it is the flip of its long side, done on the flat piece, where its
/// zero area is plain.
fn merge_slivers(mut cycles: Vec<Vec<usize>>, pts: &[[f64; 2]], eps: f64) -> Vec<Vec<usize>> {
    let flat = |c: &[usize]| {
        let k = c.len();
        (0..k).all(|m| orient(pts[c[(m + k - 1) % k]], pts[c[m]], pts[c[(m + 1) % k]]).abs() <= eps)
    };
    let mut c = 0;
    while c < cycles.len() {
        if !flat(&cycles[c]) {
            c += 1;
            continue;
        }
        let sliver = cycles[c].clone();
        // Along the line: from the first point towards the farthest.
        let far = sliver.iter().copied().max_by(|&u, &v| {
            let d = |w: usize| (pts[w][0] - pts[sliver[0]][0]).hypot_m(pts[w][1] - pts[sliver[0]][1]);
            d(u).total_cmp(&d(v))
        });
        let Some(far) = far else {
            c += 1;
            continue;
        };
        let dir = [pts[far][0] - pts[sliver[0]][0], pts[far][1] - pts[sliver[0]][1]];
        let along = |w: usize| (pts[w][0] - pts[sliver[0]][0]) * dir[0] + (pts[w][1] - pts[sliver[0]][1]) * dir[1];
        let host = (0..cycles.len()).filter(|&h| h != c).find_map(|h| {
            let g = &cycles[h];
            let k = g.len();
            // A run of the host's points that are all the sliver's, from an edge the two share.
            let start = (0..k).find(|&i| sliver.contains(&g[i]) && !sliver.contains(&g[(i + k - 1) % k]))?;
            let mut end = start;
            while sliver.contains(&g[(end + 1) % k]) && (end + 1) % k != start {
                end = (end + 1) % k;
            }
            (end != start).then_some((h, start, end))
        });
        let Some((h, start, end)) = host else {
            c += 1;
            continue;
        };
        let g = &cycles[h];
        let k = g.len();
        let (from, to) = (g[start], g[end]);
        let (lo, hi) = (along(from).min(along(to)), along(from).max(along(to)));
        // The run must span the sliver: its ends are the sliver's ends on the line.
        if sliver.iter().any(|&w| along(w) < lo - eps || along(w) > hi + eps) {
            c += 1;
            continue;
        }
        let mut run: Vec<usize> = sliver.clone();
        run.sort_by(|&u, &v| along(u).total_cmp(&along(v)));
        if along(from) > along(to) {
            run.reverse();
        }
        let rest: Vec<usize> = (1..k - ((end + k - start) % k)).map(|m| g[(end + m) % k]).collect();
        let mut merged = run;
        merged.extend(rest);
        cycles[h] = merged;
        cycles.swap_remove(c);
        c = 0;
    }
    cycles
}

/// A polygon of a cut triangle: its vertices (new indices, counter-clockwise seen from
/// outside) and the piece it lies in, once known.
struct Part {
    cycle: Vec<usize>,
    piece: Option<usize>,
}

/// Whether `a` → `b` is an edge of `cycle` in that direction.
fn has_edge(cycle: &[usize], a: usize, b: usize) -> bool {
    let k = cycle.len();
    (0..k).any(|m| cycle[m] == a && cycle[(m + 1) % k] == b)
}

/// `mesh` with positions `x` (of the seam samples of `pieces`) cut along the seam (see the
/// module docs): the pieces on the old and new seam points, the positions and each piece's
/// triangulation. `None` when the paths and the triangles do not fit together (a path point
/// outside the triangle it should be in, a polygon that does not triangulate).
pub(crate) fn cut(mesh: &Mesh, pieces: &SeamPieces, x: &[V3]) -> Option<(SeamPieces, Vec<V3>, [Triangulation; 2])> {
    let n = mesh.n;
    // The seam points in order: each sample, then its path's crossings.
    let mut pts: [Vec<[f64; 2]>; 2] = [Vec::new(), Vec::new()];
    let mut xs: Vec<V3> = Vec::new();
    let mut sample = vec![0usize; n];
    // (edge slot, fraction from its first end, new index), and each path's new indices.
    let mut on_edge: Vec<(usize, f64, usize)> = Vec::new();
    let mut crossing_index: Vec<Vec<usize>> = vec![Vec::new(); n];
    for s in 0..n {
        let s1 = (s + 1) % n;
        sample[s] = xs.len();
        for (q, f) in pts.iter_mut().zip(&pieces.flat) {
            q.push(f.pts[s]);
        }
        xs.push(x[s]);
        let path = &mesh.paths[s];
        let at: Vec<V3> = path.iter().map(|c| lerp3(x[c.u], x[c.v], c.f)).collect();
        let mut run = Vec::with_capacity(at.len());
        let mut acc = 0.0;
        let mut last = x[s];
        for &q in &at {
            acc += norm(sub(q, last));
            run.push(acc);
            last = q;
        }
        let total = acc + norm(sub(x[s1], last));
        for (m, c) in path.iter().enumerate() {
            let tau = if total > 0.0 { run[m] / total } else { 0.5 };
            for (q, f) in pts.iter_mut().zip(&pieces.flat) {
                q.push(lerp2(f.pts[s], f.pts[s1], tau));
            }
            let idx = xs.len();
            xs.push(at[m]);
            let f = if mesh.edges()[c.e].0 == c.u { c.f } else { 1.0 - c.f };
            on_edge.push((c.e, f, idx));
            crossing_index[s].push(idx);
        }
    }
    let nm = xs.len();
    let new = |v: usize| sample[v];
    // Each triangle's boundary, with the crossings on its edges in order.
    let crossings_on = |e: usize, a: usize| -> Vec<usize> {
        let forward = mesh.edges()[e].0 == a;
        let mut c: Vec<(f64, usize)> = on_edge.iter().filter(|o| o.0 == e).map(|o| (if forward { o.1 } else { 1.0 - o.1 }, o.2)).collect();
        c.sort_by(|p, q| p.0.total_cmp(&q.0));
        c.into_iter().map(|e| e.1).collect()
    };
    let mut parts: Vec<Vec<Part>> = mesh
        .tris
        .iter()
        .enumerate()
        .map(|(ti, t)| {
            let mut cycle = Vec::new();
            for (&v, &e) in t.iter().zip(&mesh.side[ti]) {
                cycle.push(new(v));
                cycle.extend(crossings_on(e, v));
            }
            vec![Part { cycle, piece: None }]
        })
        .collect();
    // The path segments, each cut into the triangle it runs through
    // ([`Mesh::triangles_along`]): A lies to its left. A path's points by their new indices: its
    // sample, its crossings, the next sample.
    for (s, (path, indices)) in mesh.paths.iter().zip(&crossing_index).enumerate() {
        if path.is_empty() {
            continue;
        }
        let s1 = (s + 1) % n;
        let mut points = vec![new(s)];
        points.extend(indices);
        points.push(new(s1));
        let through = mesh.triangles_along(s)?;
        for (w, &ti) in points.windows(2).zip(&through) {
            let (p, q) = (w[0], w[1]);
            let list = &mut parts[ti];
            let pi = list.iter().position(|part| part.cycle.contains(&p) && part.cycle.contains(&q))?;
            let part = list.swap_remove(pi);
            let k = part.cycle.len();
            let (a, b) = (part.cycle.iter().position(|&v| v == p)?, part.cycle.iter().position(|&v| v == q)?);
            if (a + 1) % k == b || (b + 1) % k == a {
                return None;
            }
            // From P round to Q (closed by Q → P: right of the path, B), and from Q round to P
            // (closed by P → Q: left of the path, A).
            let walk = |from: usize, to: usize| {
                let mut c = vec![part.cycle[from]];
                let mut m = from;
                while m != to {
                    m = (m + 1) % k;
                    c.push(part.cycle[m]);
                }
                c
            };
            list.push(Part { cycle: walk(a, b), piece: Some(1) });
            list.push(Part { cycle: walk(b, a), piece: Some(0) });
        }
    }
    // Whole triangles: the piece of a seam edge they hold, else that of a neighbour across an
    // edge inside a piece.
    for (ti, t) in mesh.tris.iter().enumerate() {
        for (&v, &e) in t.iter().zip(&mesh.side[ti]) {
            if let (true, Some(s)) = (parts[ti].len() == 1 && parts[ti][0].piece.is_none(), mesh.seam_of(e)) {
                parts[ti][0].piece = Some(if v == s { 0 } else { 1 });
            }
        }
    }
    loop {
        let mut changed = false;
        let mut open = false;
        for ti in 0..mesh.tris.len() {
            if parts[ti].len() != 1 || parts[ti][0].piece.is_some() {
                continue;
            }
            open = true;
            let t = mesh.tris[ti];
            for a in 0..3 {
                let (u, v) = (t[a], t[(a + 1) % 3]);
                if mesh.seam_of(mesh.side[ti][a]).is_some() {
                    continue;
                }
                let (tj, _) = mesh.across(ti, a);
                let (nu, nv) = (new(u), new(v));
                if let Some(p) = parts[tj].iter().find(|part| has_edge(&part.cycle, nv, nu)).and_then(|part| part.piece) {
                    parts[ti][0].piece = Some(p);
                    changed = true;
                    break;
                }
            }
        }
        if !open {
            break;
        }
        if !changed {
            return None;
        }
    }
    // The new pieces and their triangulations.
    let mut flat: Vec<FlatPiece> = Vec::with_capacity(2);
    let mut tri: Vec<Triangulation> = Vec::with_capacity(2);
    for (p, q) in pts.iter().enumerate() {
        let eps = 1e-12 * metric::size2(q);
        let mut tris = Vec::with_capacity(nm - 2);
        // B's flat piece is mirrored: its counter-clockwise order is the reverse of outward.
        let cycles = parts.iter().flatten().filter(|part| part.piece == Some(p)).map(|part| if p == 0 { part.cycle.clone() } else { part.cycle.iter().rev().copied().collect() }).collect();
        for cycle in merge_slivers(cycles, q, eps) {
            tris.extend(triangulate_convex(&cycle, q, eps)?);
        }
        let area: f64 = tris.iter().map(|&[a, b, c]| orient(q[a], q[b], q[c])).sum();
        let polygon: f64 = (0..nm).map(|m| orient([0.0, 0.0], q[m], q[(m + 1) % nm])).sum();
        if tris.len() != nm - 2 || (area - polygon).abs() > 1e-9 * polygon.abs() {
            return None;
        }
        flat.push(FlatPiece::on_chords(q.clone(), pieces.flat[p].area, pieces.flat[p].perimeter));
        tri.push(Triangulation::from_tris(nm, tris));
    }
    let (b, a) = (flat.pop()?, flat.pop()?);
    let (tb, ta) = (tri.pop()?, tri.pop()?);
    Some((SeamPieces { n: nm, flat: [a, b] }, xs, [ta, tb]))
}
