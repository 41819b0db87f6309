//! Gluings of two convex polygons: solved on their cone points (and the seam points where a
//! crease crosses the seam), then laid onto the seam samples.

use crate::libm_ext::LibmExt;
use super::relax::{relax, Orientation};
use super::starts::{initial_guess, on_sphere, Start};
use super::{is_good, multistart, triangulate, Patience};
use super::super::isometry::{bars, max_strain, STEP_TOL};
use super::super::metric::{self, Triangulation};
use super::super::seam::{FlatPiece, SeamPieces};
use super::super::vec3::V3;

/// Steps allowed to a [`cone_restart`], on top of the level's own (it runs only after a level
/// failed, and from a start that is exact up to the cone points' error it needs a few dozen).
pub(crate) const CONE_BUDGET: usize = 300;

/// Places every seam sample between two neighbouring cone points on the straight segment
/// between their positions, by arc length (see [`cone_restart`]).
pub(crate) fn reseat(pieces: &SeamPieces, cones: &[usize], x: &mut [V3]) {
    let n = pieces.n;
    for (m, &c0) in cones.iter().enumerate() {
        let c1 = cones[(m + 1) % cones.len()];
        let span = pieces.chord(0, c0, c1);
        let mut k = (c0 + 1) % n;
        while k != c1 && span > 0.0 {
            let t = pieces.chord(0, c0, k) / span;
            x[k] = [0, 1, 2].map(|a| x[c0][a] + t * (x[c1][a] - x[c0][a]));
            k = (k + 1) % n;
        }
    }
}

/// Largest strain of the cone triangulation at the positions a [`cone_restart`] starts from:
/// it restarts a shape that is isometric but for its folds, not a wrong branch.
pub(crate) const CONE_NEAR: f64 = 1e-3;

/// The restart of a polyhedral gluing (two polygons) from the creases of the convex hull of its
/// cone points ([`super::hull::cone_triangulations`]), relaxed from `x`: the positions, the
/// triangulations and whether it converged, when it is good ([`is_good`]); else `None`.
pub(crate) fn cone_restart(pieces: &SeamPieces, x: &[V3], budget: usize, step_tol: f64, steps: &mut (usize, usize)) -> Option<(Vec<V3>, [Triangulation; 2], bool)> {
    let cones = super::hull::cone_vertices(pieces)?;
    let pre = max_strain(x, &bars(pieces, &super::hull::cone_triangulations(x, pieces)?));
    if pre > CONE_NEAR {
        return None;
    }
    // Between two cone points that are neighbours along the seam both pieces are straight. When
    // every crease of the polyhedron is a chord of one piece between cone points (the case
    // [`super::hull::cone_triangulations`] builds for), no crease meets that stretch inside, so
    // it lies on the boundary of one face of each piece: a straight segment in 3D, its samples
    // evenly spread by arc length. Re-seating them there takes out the folds across flat faces
    // ("popped" strips between a cone and two samples of a straight side, continued across the
    // seam) that the fans from a cone to collinear samples keep: their chords cannot be flipped
    // (the quad has three collinear vertices) and the folded strip is itself isometric, so
    // Gauss–Newton stays in it (a 90×10 rectangle with a square: strain 1.2e-7 and two reflex
    // chords after 5000 steps). Where a crease does cross the seam this is only a start, and
    // [`is_good`] judges the result like any other.
    let mut xc = x.to_vec();
    reseat(pieces, &cones, &mut xc);
    let mut t = super::hull::cone_triangulations(&xc, pieces)?;
    let r = relax(pieces, &mut xc, &mut t, budget, step_tol, Orientation::Kept).tally(steps);
    is_good(&xc, &t, r.converged).then_some((xc, t, r.converged))
}

/// Step budgets of the multistart on the cone points alone ([`solve_polyhedral`]): a handful of
/// vertices, so every start and its hull restart are cheap.
pub(crate) const CONES: Patience = Patience { attempt: 300, level: 300, cap: 3000, hull: true };

/// A polyhedral gluing (two polygons, see [`super::hull::cone_vertices`]) solved on its cone
/// points alone, then laid onto the seam samples.
///
/// By Alexandrov's gluing theorem the D-form of two convex polygons is the convex polyhedron
/// whose vertices are the cone points of the glued metric (the corners; every other seam point
/// has total angle 2π), unique up to isometry (Pogorelov). The seam between two neighbouring
/// cone points is straight in both pieces, so the metric is already the polyhedral metric of the
/// *cone points* as seam vertices: the same isometry equations with a few vertices instead of
/// `n`, where no sample sits on a flat face or a straight crease. There the multistart and the
/// hull restarts ([`super::hull::triangulations`]) work as for a smooth seam, while at `n`
/// samples the flat faces make every dihedral sign between coplanar triangles round-off and the
/// starts end on folded, isometric but non-convex branches (two equilateral triangles at an
/// offset: 14 reflex chords at strain 3e-10; a triangle with a square: strain 9 %). Its solution
/// then places every sample ([`cone_restart`], which keeps only a good result). A cold solve of a
/// polygon pair tries this first: a handful of vertices take a few dozen steps in all (two
/// 80×20 and 60×40 rectangles at a quarter offset took ~1,500 steps on the samples), and when it
/// finds nothing convex the ladder runs as for any other gluing.
///
/// A crease of the polyhedron (a shortest path between two cone points) need not be a chord of
/// either piece: it can run from a corner across one piece, cross the seam at a flat point and
/// go on across the other (straight in the unfolding of the two pieces along the seam). Then no
/// realization on the cone points alone is convex (two equilateral triangles at a quarter
/// offset: every start, and every one of the 196 pairs of triangulations of the six corners,
/// ended locally convex but not convex), and no sampling that misses the crossing holds the
/// polyhedron. Those crossings ([`seam_crossings`]) are then added as seam vertices: the gluing
/// on corners and crossings is solved (from the mismatch starts in convex position,
/// [`on_sphere`]), and laid onto the samples with the nearest sample moved onto each crossing
/// ([`lay_on`]). The returned pieces are then `pieces` with those samples moved (each the
/// nearest free sample of its stretch, along a side that is straight in both pieces), so the
/// mesh is exact.
pub(crate) fn solve_polyhedral(pieces: &SeamPieces, cap: usize, steps: &mut (usize, usize)) -> Option<(SeamPieces, Vec<V3>, [Triangulation; 2], bool)> {
    let cones = super::hull::cone_vertices(pieces)?;
    let k = cones.len();
    let seat = |idx: &[(usize, f64)]| -> SeamPieces {
        let piece = |p: usize| {
            let f = &pieces.flat[p];
            FlatPiece::on_chords(idx.iter().map(|&(m, t)| on_side(f, &cones, m, t)).collect(), f.area, f.perimeter)
        };
        SeamPieces { n: idx.len(), flat: [piece(0), piece(1)] }
    };
    let corners: Vec<(usize, f64)> = (0..k).map(|m| (m, 0.0)).collect();
    let small = seat(&corners);
    let tri = [triangulate(&small, 0).ok()?, triangulate(&small, 1).ok()?];
    let patience = Patience { cap: CONES.cap.min(cap.saturating_sub(steps.0)) + steps.0, ..CONES };
    // (The third field is "good" for a good start, else only "converged": judge it here.)
    let (xs, ts, converged, _) = multistart(&small, &tri, 0, STEP_TOL, patience, steps)?;
    if is_good(&xs, &ts, converged) {
        return lay_on(pieces, &corners, &cones, &xs, &ts, cap, steps);
    }
    // No convex polyhedron with every crease a chord of one piece: add the seam points where the
    // shortest paths between cone points cross the seam ([`seam_crossings`]) as vertices.
    let crossings = seam_crossings(&small);
    if crossings.is_empty() {
        return None;
    }
    let mut idx = corners;
    idx.extend(crossings.iter().map(|c| (c.0, c.1)));
    // In seam order (stretch, then fraction; through [`crate::order`], one sort instantiation).
    let keys: Vec<f64> = idx.iter().map(|&(m, t)| m as f64 + t).collect();
    let mut idx: Vec<(usize, f64)> = crate::order::argsort(&keys).into_iter().map(|i| idx[i]).collect();
    idx.dedup();
    let big = seat(&idx);
    // The start's triangulations hold each crossing path as two chords, i–X of p and X–j of q.
    let at = |m: usize, t: f64| idx.iter().position(|&(a, b)| a == m && b == t);
    let mut chords: [Vec<(usize, usize)>; 2] = [Vec::new(), Vec::new()];
    for &(m, t, i, j, p) in &crossings {
        let x = at(m, t)?;
        for (q, a) in [(p, at(i, 0.0)?), (1 - p, at(j, 0.0)?)] {
            let e = (a.min(x), a.max(x));
            let crossing = chords[q].iter().any(|&(u, v)| (e.0 < u && u < e.1 && e.1 < v) || (u < e.0 && e.0 < v && v < e.1));
            if !metric::is_seam(big.n, e.0, e.1) && !chords[q].contains(&e) && !crossing {
                chords[q].push(e);
            }
        }
    }
    let tri = super::hull::cut_along(&big, &chords)?;
    // From the mismatch starts pushed onto a sphere (see [`on_sphere`]).
    for start in [Start::Mismatch(1.0), Start::Mismatch(2.0)] {
        let budget = CONES.attempt.min(cap.saturating_sub(steps.0));
        if budget == 0 {
            return None;
        }
        let (mut x, mut t) = (on_sphere(initial_guess(&big, start)), tri.clone());
        let r = relax(&big, &mut x, &mut t, budget, STEP_TOL, Orientation::Free).tally(steps);
        if is_good(&x, &t, r.converged) {
            return lay_on(pieces, &idx, &cones, &x, &t, cap, steps);
        }
    }
    None
}

/// Lays the solution `xs`, `ts` on the seam points `idx` of `pieces` (cone point `m` and the
/// fraction along the stretch after it, see [`solve_polyhedral`]) onto `pieces`, and relaxes it
/// there: on the cone points alone by [`cone_restart`]; with seam crossings, with the nearest
/// sample of each crossing's stretch moved onto it, every sample on the straight segment
/// between its neighbouring seam points ([`reseat`]) and each piece cut along the chords of
/// `ts`, so that every triangle lies in one face of the polyhedron and the start is exact up to
/// round-off. The pieces with the moved samples, the positions, the triangulations and whether
/// it converged, when it is good ([`is_good`]); else `None`.
pub(crate) fn lay_on(
    pieces: &SeamPieces,
    idx: &[(usize, f64)],
    cones: &[usize],
    xs: &[V3],
    ts: &[Triangulation; 2],
    cap: usize,
    steps: &mut (usize, usize),
) -> Option<(SeamPieces, Vec<V3>, [Triangulation; 2], bool)> {
    let n = pieces.n;
    if idx.len() == cones.len() {
        let mut x = vec![[0.0; 3]; n];
        for (m, &c) in cones.iter().enumerate() {
            x[c] = xs[m];
        }
        reseat(pieces, cones, &mut x);
        let budget = CONE_BUDGET.min(cap.saturating_sub(steps.0));
        return cone_restart(pieces, &x, budget, STEP_TOL, steps).map(|(x, t, c)| (pieces.clone(), x, t, c));
    }
    // Each extra seam point takes the nearest free sample of its stretch (in order), moved onto
    // it in both pieces (both straight there, so the sample polygons stay convex).
    let mut moved = pieces.clone();
    let mut at = Vec::with_capacity(idx.len());
    let mut last = None::<usize>;
    for &(m, t) in idx {
        if t == 0.0 {
            at.push(cones[m]);
            last = Some(cones[m]);
            continue;
        }
        let (c0, c1) = (cones[m], cones[(m + 1) % cones.len()]);
        let span = pieces.chord(0, c0, c1);
        let mut best: Option<(usize, f64)> = None;
        let mut s = (c0 + 1) % n;
        while s != c1 {
            let free = last.is_none_or(|l| l == c0 || (s + n - c0) % n > (l + n - c0) % n);
            let d = (pieces.chord(0, c0, s) / span - t).abs();
            if free && best.is_none_or(|b| d < b.1) {
                best = Some((s, d));
            }
            s = (s + 1) % n;
        }
        let (s, _) = best?;
        for p in 0..2 {
            moved.flat[p].pts[s] = on_side(&pieces.flat[p], cones, m, t);
        }
        at.push(s);
        last = Some(s);
    }
    for f in moved.flat.iter_mut() {
        *f = FlatPiece::on_chords(std::mem::take(&mut f.pts), f.area, f.perimeter);
    }
    // Every sample on the straight segment between its neighbouring seam points of `small`, and
    // each piece cut along `small`'s chords: every triangle then lies in a face.
    let mut sorted = at.clone();
    crate::order::sort_dedup(&mut sorted);
    let mut x = vec![[0.0; 3]; n];
    for (m, &s) in at.iter().enumerate() {
        x[s] = xs[m];
    }
    reseat(&moved, &sorted, &mut x);
    let chords = [0, 1].map(|p| ts[p].chords().into_iter().map(|(u, v)| (at[u], at[v])).collect::<Vec<_>>());
    let mut t = super::hull::cut_along(&moved, &chords)?;
    let budget = CONE_BUDGET.min(cap.saturating_sub(steps.0));
    let r = relax(&moved, &mut x, &mut t, budget, STEP_TOL, Orientation::Kept).tally(steps);
    is_good(&x, &t, r.converged).then_some((moved, x, t, r.converged))
}

/// The point of piece `f` a fraction `t` along the straight seam stretch from cone point `m` to
/// the next one (`cones` are sample indices of `f`).
pub(crate) fn on_side(f: &FlatPiece, cones: &[usize], m: usize, t: f64) -> [f64; 2] {
    let (a, b) = (f.pts[cones[m]], f.pts[cones[(m + 1) % cones.len()]]);
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
}

/// The seam points, as (stretch, fraction) with the stretches between neighbouring cone points
/// of `small` (the gluing on its cone points alone), where a shortest path between two cone
/// points crosses the seam once.
///
/// The edges of Alexandrov's polyhedron are shortest paths between cone points. Such a path is
/// straight in each piece, and across the seam it is straight in the *unfolding*: the other
/// piece laid along the common stretch, on the far side. A path from cone point i in piece p
/// to cone point j in piece q = 1 − p crossing stretch S once is therefore the segment from i
/// to the image of j under the isometry that lays q's copy of S onto p's with q's interior on
/// the other side; it crosses S inside when the segment does, and (both pieces convex) it then
/// lies in p up to S and in q beyond. When for some pair that path is shorter than both
/// pieces' chords from i to j, no chord can be the crease between them (see [`excess`]), and
/// a crease there crosses the seam at a flat point no cone-point mesh holds: two triangles at
/// a quarter offset and a triangle with a square at 0.41 have no convex realization on their
/// corners alone. With such a crossing as an extra (flat) seam vertex the crease is the
/// chords i–X of p and X–j of q, and the polyhedron is exact again.
pub(crate) fn seam_crossings(small: &SeamPieces) -> Vec<(usize, f64, usize, usize, usize)> {
    let k = small.n;
    let mut out: Vec<(usize, f64, usize, usize, usize)> = Vec::new();
    for i in 0..k {
        for j in i + 2..k {
            if (j + 1) % k == i {
                continue;
            }
            let mut best = small.chord(0, i, j).min(small.chord(1, i, j)) * (1.0 - 1e-9);
            let mut at = None;
            for p in 0..2 {
                for m in 0..k {
                    if let Some((len, t)) = crossing(small, i, j, p, m) {
                        if len < best {
                            best = len;
                            at = Some((m, t, i, j, p));
                        }
                    }
                }
            }
            if let Some(c) = at {
                if let Some(o) = out.iter().find(|o| o.0 == c.0 && (o.1 - c.1).abs() < 1e-9) {
                    let t = o.1;
                    out.push((c.0, t, c.2, c.3, c.4));
                } else {
                    out.push(c);
                }
            }
        }
    }
    out
}

/// The path from seam vertex `i` in piece `p` to `j` in the other piece that crosses the seam
/// once, inside stretch `m` (from vertex m to m + 1), straight in the unfolding (see
/// [`seam_crossings`]): its length and the fraction along the stretch where it crosses.
pub(crate) fn crossing(small: &SeamPieces, i: usize, j: usize, p: usize, m: usize) -> Option<(f64, f64)> {
    let k = small.n;
    let (fp, fq) = (&small.flat[p].pts, &small.flat[1 - p].pts);
    let m1 = (m + 1) % k;
    if [m, m1].contains(&i) || [m, m1].contains(&j) {
        return None;
    }
    let (s0, s1, r0, r1) = (fp[m], fp[m1], fq[m], fq[m1]);
    let (ls, lr) = ((s1[0] - s0[0]).hypot_m(s1[1] - s0[1]), (r1[0] - r0[0]).hypot_m(r1[1] - r0[1]));
    if ls == 0.0 || lr == 0.0 {
        return None;
    }
    let es = [(s1[0] - s0[0]) / ls, (s1[1] - s0[1]) / ls];
    let er = [(r1[0] - r0[0]) / lr, (r1[1] - r0[1]) / lr];
    let y = [fq[j][0] - r0[0], fq[j][1] - r0[1]];
    let (al, be) = (y[0] * er[0] + y[1] * er[1], er[0] * y[1] - er[1] * y[0]);
    // q's interior (left of r0→r1) goes to the right of s0→s1.
    let qj = [s0[0] + al * es[0] + be * es[1], s0[1] + al * es[1] - be * es[0]];
    let pi = fp[i];
    let len = (qj[0] - pi[0]).hypot_m(qj[1] - pi[1]);
    // Where segment pi→qj meets the line s0→s1 (fraction t along it).
    let (o1, o2) = (metric::orient(s0, s1, pi), metric::orient(s0, s1, qj));
    if !(o1 > 0.0 && o2 < 0.0) {
        return None;
    }
    let u = o1 / (o1 - o2);
    let x = [pi[0] + u * (qj[0] - pi[0]), pi[1] + u * (qj[1] - pi[1])];
    let t = ((x[0] - s0[0]) * es[0] + (x[1] - s0[1]) * es[1]) / ls;
    (t > 1e-6 && t < 1.0 - 1e-6).then_some((len, t))
}
