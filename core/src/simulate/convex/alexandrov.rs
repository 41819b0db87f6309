//! Alexandrov's polyhedron of an intrinsic triangulation by the variational method of Bobenko &
//! Izmestiev ("Alexandrov's theorem, weighted Delaunay triangulations, and mixed volumes",
//! Annales de l'Institut Fourier 58, 2008), as geometry-central's `embed_convex` runs it.
//!
//! Every triangle of the metric becomes the base of a tetrahedron whose apex is one point inside
//! the polyhedron, at distance `r_i` from vertex i. For given radii the tetrahedra glue around
//! each radial edge with the angle `Σ β`; its defect `κ_i = 2π − Σ β` is the curvature of the
//! "generalized polyhedron", and the radii where every `κ_i` vanishes give the convex polyhedron
//! (the tetrahedra then close up in space). The triangulation is kept weighted Delaunay (every
//! base edge convex: the dihedral angles `α` of its two tetrahedra sum to at most π) by
//! intrinsic flips. Starting from equal radii large enough that the generalized polyhedron is
//! convex with `0 ≤ κ_i ≤ δ_i` (δ the metric's own curvature), the curvatures are shrunk by
//! Newton's method on `κ(r) = (1 − τ)·κ(r₀)`, whose Jacobian is the Hessian of the
//! Hilbert–Einstein functional and non-degenerate along the way (Bobenko & Izmestiev prove it),
//! with a smaller τ whenever Newton's method fails and a larger one after it succeeds. Unlike
//! flips driven by a 3D shape ([`super::relax`]), this path is proved to reach the polyhedron of
//! a convex metric.
//!
//! The Newton systems are solved dense (n ≤ a few hundred here: ~2 ms native at 256 seam
//! vertices). The Jacobian is indefinite, so the block LDLᵀ of the length equations does not
//! apply; through the normal equations `J² v = J u` it did, but the squared conditioning lost the
//! final digits and two of the bench's rounded-rectangle gluings stopped converging.

use crate::libm_ext::LibmExt;
use super::intrinsic::{cos_opposite, Mesh};
use super::super::vec3::{cross, dot, norm, sub, V3};
use std::f64::consts::{PI, TAU};

fn sin_of(c: f64) -> f64 {
    (1.0 - c * c).max(0.0).sqrt()
}

/// What the radii give on one triangle i, j, k (corners in this order): per corner the base
/// angle γ (only when asked for: it does not depend on the radii, and acos was a quarter of the
/// time), the dihedral angle β at its radial edge, and per edge (i→j, j→k, k→i) the dihedral
/// angle α at that base edge on this triangle's side.
struct Tet {
    /// Whether the tetrahedron exists: every spherical triangle at a corner is proper.
    real: bool,
    gamma: [f64; 3],
    beta: [f64; 3],
    alpha: [f64; 3],
}

fn tet(l: [f64; 3], r: [f64; 3], with_gamma: bool) -> Tet {
    // l[a] is the length of edge a → a+1; r[a] the radius at corner a.
    let mut gamma = [0.0; 3];
    let mut beta = [0.0; 3];
    let mut alpha = [0.0; 3];
    let mut real = true;
    for a in 0..3 {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        // At corner a: the base edges to b (length l[a]) and to c (length l[c]), and the radius.
        let cg = cos_opposite(l[b], l[a], l[c]);
        // ρ toward b: the angle at a between the edge a–b and the radius, in triangle (apex, a, b).
        let crb = cos_opposite(r[b], l[a], r[a]);
        let crc = cos_opposite(r[c], l[c], r[a]);
        let (sg, srb, src) = (sin_of(cg), sin_of(crb), sin_of(crc));
        if with_gamma {
            gamma[a] = cg.acos_m();
        }
        let cb = (cg - crb * crc) / (srb * src);
        // The dihedral angle at edge a → b, seen at a (the spherical triangle of the three edges).
        let ca = (crc - crb * cg) / (srb * sg);
        real &= cb.abs() < 1.0 + REAL_TOL && ca.abs() < 1.0 + REAL_TOL;
        beta[a] = cb.clamp(-1.0, 1.0).acos_m();
        alpha[a] = ca.clamp(-1.0, 1.0).acos_m();
    }
    Tet { real, gamma, beta, alpha }
}

/// The state of the generalized polyhedron for radii `r` on `mesh`.
struct State {
    kappa: Vec<f64>,
    /// The metric's curvature `2π − Σ γ` per vertex (when asked for, else 2π).
    delta: Vec<f64>,
    /// Per triangle, per edge a → a+1: α.
    alpha: Vec<[f64; 3]>,
    /// Per edge (in the order of [`Mesh::edges`]): θ, the sum of its two α.
    theta: Vec<f64>,
}

fn state(mesh: &Mesh, r: &[f64]) -> Option<State> {
    state_with(mesh, r, false)
}

/// [`state`], with the metric's curvature δ when `with_delta`.
fn state_with(mesh: &Mesh, r: &[f64], with_delta: bool) -> Option<State> {
    let n = mesh.n;
    let mut kappa = vec![TAU; n];
    let mut delta = vec![TAU; n];
    let mut alpha = Vec::with_capacity(mesh.tris.len());
    let mut theta = vec![0.0; mesh.edge_count()];
    for (ti, &t) in mesh.tris.iter().enumerate() {
        let g = tet(mesh.side_lengths(ti), t.map(|v| r[v]), with_delta);
        if !g.real {
            return None;
        }
        for a in 0..3 {
            kappa[t[a]] -= g.beta[a];
            delta[t[a]] -= g.gamma[a];
            theta[mesh.side[ti][a]] += g.alpha[a];
        }
        alpha.push(g.alpha);
    }
    kappa.iter().chain(&delta).all(|v| v.is_finite()).then_some(State { kappa, delta, alpha, theta })
}

/// The smallest slack of the triangle inequality over the triangles (apex, i, j): positive when
/// every tetrahedron side is a real triangle.
fn slack(mesh: &Mesh, r: &[f64]) -> f64 {
    mesh.edges()
        .iter()
        .enumerate()
        .map(|(e, &(i, j))| {
            let l = mesh.len(e);
            (l + r[i] - r[j]).min(r[i] + r[j] - l).min(l + r[j] - r[i])
        })
        .fold(f64::INFINITY, f64::min)
}

/// The Jacobian ∂κ/∂r (Bobenko & Izmestiev 2008; as geometry-central assembles it): for an
/// edge i–j, `(cot α_ij + cot α_ji) / (l_ij sin ρ_ij sin ρ_ji)` off the diagonal, and on it
/// minus the sum of those times `cos φ_ij` (φ the apex angle of triangle apex, i, j). Sparse:
/// the diagonal, and one entry per edge in the order of [`Mesh::edges`].
fn jacobian(mesh: &Mesh, r: &[f64], s: &State) -> Option<(Vec<f64>, Vec<f64>)> {
    let n = mesh.n;
    let mut diag = vec![0.0; n];
    let mut off = vec![0.0; mesh.edge_count()];
    for (ti, &t) in mesh.tris.iter().enumerate() {
        for a in 0..3 {
            let (i, j) = (t[a], t[(a + 1) % 3]);
            let l = mesh.len(mesh.side[ti][a]);
            let (ri, rj) = (r[i], r[j]);
            let sij = sin_of(cos_opposite(rj, l, ri));
            let sji = sin_of(cos_opposite(ri, l, rj));
            // This triangle's half of the edge's entry: cot α on its side.
            let v = 1.0 / s.alpha[ti][a].tan_m() / (l * sij * sji);
            let cphi = cos_opposite(l, ri, rj);
            off[mesh.side[ti][a]] += v;
            diag[i] -= cphi * v;
            diag[j] -= cphi * v;
        }
    }
    (diag.iter().chain(&off).all(|v| v.is_finite())).then_some((diag, off))
}

/// Solves `J v = u` for the symmetric Jacobian `(diag, off)` of [`jacobian`] (indefinite: the
/// Hilbert–Einstein functional is not concave everywhere) by Gaussian elimination with partial
/// pivoting on the dense matrix; `None` when it is singular to round-off.
fn solve_dense(mesh: &Mesh, diag: &[f64], off: &[f64], u: &[f64]) -> Option<Vec<f64>> {
    let n = mesh.n;
    let mut a = vec![0.0; n * n];
    for v in 0..n {
        a[v * n + v] = diag[v];
    }
    for (e, &(i, j)) in mesh.edges().iter().enumerate() {
        a[i * n + j] += off[e];
        a[j * n + i] += off[e];
    }
    let mut b = u.to_vec();
    let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for c in 0..n {
        let p = (c..n).max_by(|&x, &y| a[x * n + c].abs().total_cmp(&a[y * n + c].abs()))?;
        if a[p * n + c].abs() <= 1e-14 * scale {
            return None;
        }
        if p != c {
            for k in 0..n {
                a.swap(p * n + k, c * n + k);
            }
            b.swap(p, c);
        }
        let d = a[c * n + c];
        for row in c + 1..n {
            let f = a[row * n + c] / d;
            if f == 0.0 {
                continue;
            }
            for k in c..n {
                a[row * n + k] -= f * a[c * n + k];
            }
            b[row] -= f * b[c];
        }
    }
    let mut x = vec![0.0; n];
    for c in (0..n).rev() {
        let s: f64 = (c + 1..n).map(|k| a[c * n + k] * x[k]).sum();
        x[c] = (b[c] - s) / a[c * n + c];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Newton's method for `κ(r) = target` from `r`, in place: at most [`NEWTON_STEPS`] steps, each
/// shortened until every tetrahedron stays real. Whether `|κ − target|` fell below `tol`.
fn newton(mesh: &mut Mesh, r: &mut [f64], target: &[f64], tol: f64, iterations: &mut usize) -> bool {
    let size = r.iter().fold(0.0f64, |m, v| m.max(*v));
    let Some(mut s) = state(mesh, r) else { return false };
    for _ in 0..NEWTON_STEPS {
        let u: Vec<f64> = s.kappa.iter().zip(target).map(|(k, t)| k - t).collect();
        if u.iter().fold(0.0f64, |m, v| m.max(v.abs())) < tol {
            return true;
        }
        *iterations += 1;
        let Some((hd, ho)) = jacobian(mesh, r, &s) else { return false };
        let Some(v) = solve_dense(mesh, &hd, &ho, &u) else { return false };
        let r0 = r.to_vec();
        let mut tau = 1.0;
        loop {
            for k in 0..r.len() {
                r[k] = r0[k] - tau * v[k];
            }
            let fits = if slack(mesh, r) > 1e-9 * size { state(mesh, r).filter(|s| s.theta.iter().all(|&t| t <= PI + STEP_THETA)) } else { None };
            if let Some(st) = fits {
                // Keep the triangulation weighted Delaunay as the radii move; the state is
                // computed again only when something flipped.
                let Some(next) = (if flip_to_convex(mesh, r, STEP_FLIP_EPS, Some(&st)) > 0 { state(mesh, r) } else { Some(st) }) else { return false };
                s = next;
                break;
            }
            tau *= 0.5;
            if tau < 1e-9 {
                r.copy_from_slice(&r0);
                return false;
            }
        }
    }
    false
}

/// Steps of one Newton solve before it counts as failed.
pub(crate) const NEWTON_STEPS: usize = 20;

/// Flips every edge whose dihedral angle sum exceeds π by more than `eps` (the generalized
/// polyhedron folds inward there) until none does or none can be flipped; `known` is the state
/// at `r` when the caller has it. The number of flips.
fn flip_to_convex(mesh: &mut Mesh, r: &[f64], eps: f64, known: Option<&State>) -> usize {
    // The dihedral angle sum at edge slot e: the angles of the two tetrahedra on its sides.
    let theta_at = |mesh: &Mesh, e: usize| -> f64 {
        mesh.halves(e).iter().map(|&(ti, a)| tet(mesh.side_lengths(ti), mesh.tris[ti].map(|w| r[w]), false).alpha[a]).sum()
    };
    let mut flips = 0;
    for pass in 0..mesh.n {
        let mut any = false;
        let fresh;
        let s = match known.filter(|_| pass == 0) {
            Some(s) => s,
            None => match state(mesh, r) {
                Some(s) => {
                    fresh = s;
                    &fresh
                }
                None => return flips,
            },
        };
        let candidates: Vec<usize> = (0..mesh.edge_count()).filter(|&e| s.theta[e] > PI + eps).collect();
        for e in candidates {
            // Earlier flips of this pass may have changed it: measured again.
            if theta_at(mesh, e) <= PI + eps {
                continue;
            }
            let Some(p) = mesh.flip_preview(e) else { continue };
            // Only a flip whose two new tetrahedra exist (k, i, l and l, j, k).
            let real = |sides: [f64; 3], v: [usize; 3]| tet(sides, v.map(|w| r[w]), false).real;
            let [ki, il, lj, jk] = p.sides;
            if real([ki, il, p.d], [p.k, p.i, p.l]) && real([lj, jk, p.d], [p.l, p.j, p.k]) && mesh.flip(e) {
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

/// Flips the mesh to the intrinsic Delaunay triangulation of its metric (every edge's two
/// opposite angles sum to at most π), the start of [`embed`]. The number of flips.
pub(crate) fn flip_to_delaunay(mesh: &mut Mesh) -> usize {
    let mut flips = 0;
    for _ in 0..8 * mesh.n {
        let mut any = false;
        for e in 0..mesh.edge_count() {
            // The angle across from e in each of its triangles.
            let angle: f64 = mesh
                .halves(e)
                .iter()
                .map(|&(ti, a)| {
                    let l = mesh.side_lengths(ti);
                    cos_opposite(l[a], l[(a + 1) % 3], l[(a + 2) % 3]).acos_m()
                })
                .sum();
            if angle > PI + 1e-12 && mesh.flip(e) {
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

/// The point at distances `da`, `db`, `dc` from `a`, `b`, `c` on the side where (a, b, c) turns
/// counter-clockwise when `above`, else on the other side.
fn fourth_point(a: V3, b: V3, c: V3, da: f64, db: f64, dc: f64, above: bool) -> V3 {
    let ab = sub(b, a);
    let d = norm(ab);
    let ex = ab.map(|v| v / d);
    let ac = sub(c, a);
    let i = dot(ex, ac);
    let ey0 = [ac[0] - i * ex[0], ac[1] - i * ex[1], ac[2] - i * ex[2]];
    let ny = norm(ey0);
    let ey = ey0.map(|v| v / ny);
    let ez = cross(ex, ey);
    let j = dot(ey, ac);
    let x = (da * da - db * db + d * d) / (2.0 * d);
    let y = (da * da - dc * dc + i * i + j * j) / (2.0 * j) - i / j * x;
    let z = (da * da - x * x - y * y).max(0.0).sqrt() * if above { 1.0 } else { -1.0 };
    [0, 1, 2].map(|k| a[k] + x * ex[k] + y * ey[k] + z * ez[k])
}

/// Vertex positions from the radii: the tetrahedra laid out one after another across their
/// shared faces from the first, the apex at the origin, each vertex at the mean of its corners'
/// layouts (they agree once every κ vanishes).
fn layout(mesh: &Mesh, r: &[f64]) -> Option<Vec<V3>> {
    let n = mesh.n;
    let t0 = *mesh.tris.first()?;
    let l = mesh.side_lengths(0);
    let apex = [0.0; 3];
    // The first triangle in the plane z = 0, counter-clockwise seen from +z, the apex below.
    let c0 = cos_opposite(l[1], l[2], l[0]);
    let p = [[0.0, 0.0, 0.0], [l[0], 0.0, 0.0], [l[2] * c0, l[2] * sin_of(c0), 0.0]];
    let o = fourth_point(p[0], p[1], p[2], r[t0[0]], r[t0[1]], r[t0[2]], false);
    let p = p.map(|q| sub(q, o));
    let mut corner: Vec<Option<[V3; 3]>> = vec![None; mesh.tris.len()];
    corner[0] = Some(p);
    let mut queue = std::collections::VecDeque::from([0usize]);
    while let Some(ti) = queue.pop_front() {
        let t = mesh.tris[ti];
        let q = corner[ti]?;
        for a in 0..3 {
            let (u, v) = (t[a], t[(a + 1) % 3]);
            // Across side a: triangle tj with side b = v → u, then u → w and w → v.
            let (tj, b) = mesh.across(ti, a);
            if corner[tj].is_some() {
                continue;
            }
            let w = mesh.tris[tj][(b + 2) % 3];
            let lj = mesh.side_lengths(tj);
            let (xu, xv) = (q[a], q[(a + 1) % 3]);
            // Triangle v, u, w is outward (its normal points away from the apex): w lies on the
            // side of the plane through v, u and the apex where (v, u, apex) turns counter-clockwise.
            let xw = fourth_point(xv, xu, apex, lj[(b + 2) % 3], lj[(b + 1) % 3], r[w], true);
            let tw = mesh.tris[tj];
            corner[tj] = Some(tw.map(|z| if z == u { xu } else if z == v { xv } else { xw }));
            queue.push_back(tj);
        }
    }
    let mut sum = vec![[0.0; 3]; n];
    let mut count = vec![0usize; n];
    for (ti, t) in mesh.tris.iter().enumerate() {
        let q = corner[ti]?;
        for a in 0..3 {
            sum[t[a]] = [0, 1, 2].map(|k| sum[t[a]][k] + q[a][k]);
            count[t[a]] += 1;
        }
    }
    (0..n).map(|v| (count[v] > 0).then(|| sum[v].map(|s| s / count[v] as f64))).collect()
}

/// Largest |κ| accepted as the polyhedron: the positions are polished by
/// [`super::relax::relax_with`] afterwards, which needs only a start this close.
pub(crate) const KAPPA_TOL: f64 = 1e-7;

/// Embeds `mesh` (flipped in place to the weighted Delaunay triangulation of the answer): the
/// positions of its vertices, or `None` when the radii cannot be initialized or the curvature
/// does not vanish within `max_newton` Newton steps in all (counted in `iterations`).
pub(crate) fn embed(mesh: &mut Mesh, max_newton: usize, iterations: &mut usize) -> Option<Vec<V3>> {
    flip_to_delaunay(mesh);
    let n = mesh.n;
    let mut big = 0.0f64;
    for ti in 0..mesh.tris.len() {
        let l = mesh.side_lengths(ti);
        let s = 0.5 * (l[0] + l[1] + l[2]);
        let area = (s * (s - l[0]) * (s - l[1]) * (s - l[2])).max(0.0).sqrt();
        big = big.max(l[0] * l[1] * l[2] / (4.0 * area.max(f64::MIN_POSITIVE)));
    }
    let mut r = vec![big; n];
    // Radii large enough that the generalized polyhedron is convex with 0 ≤ κ ≤ δ (down to δ
    // where the metric's δ is below zero, see [`KAPPA_SLACK`]).
    let mut ok = false;
    for _ in 0..80 {
        r.iter_mut().for_each(|v| *v = big);
        flip_to_convex(mesh, &r, FLIP_EPS, None);
        if let Some(s) = state_with(mesh, &r, true) {
            let convex = s.theta.iter().all(|&t| t <= PI + 1e-3);
            if convex && (0..n).all(|i| s.kappa[i] >= s.delta[i].min(0.0) - KAPPA_SLACK && s.delta[i] >= s.kappa[i] - KAPPA_SLACK) {
                ok = true;
                break;
            }
        }
        big *= 1.5;
    }
    if !ok {
        return None;
    }
    let mut tau = 1.0f64;
    while *iterations < max_newton {
        let s = state(mesh, &r)?;
        let kmax = s.kappa.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        if kmax <= KAPPA_TOL {
            return layout(mesh, &r);
        }
        let target: Vec<f64> = s.kappa.iter().map(|k| (1.0 - tau) * k).collect();
        let r0 = r.clone();
        let tol = if tau >= 1.0 { 0.9 * KAPPA_TOL } else { (0.25 * tau * kmax).min(1e-4) };
        // A failed Newton solve leaves the radii and the triangulation as they were.
        let m0 = mesh.clone();
        let before = *iterations;
        if newton(mesh, &mut r, &target, tol, iterations) {
            flip_to_convex(mesh, &r, STEP_FLIP_EPS, None);
            if *iterations - before <= EASY_NEWTON {
                tau = (2.0 * tau).min(1.0);
            }
        } else {
            *mesh = m0;
            r = r0;
            tau *= 0.5;
            if tau < 1e-6 {
                return None;
            }
        }
    }
    None
}

/// How far below zero (or below δ, where δ is) a vertex's curvature κ may start, and how far
/// above δ (see [`embed`]). The metric's own δ is ≥ 0 for convex pieces up to the seam edges'
/// mean lengths (see [`Mesh::from_chords`]): ~1e-9 on curved seams, but −4.5e-4 at a sample
/// beside a 3 mm corner of two congruent 120 × 80 rectangles at 3/16, where the embedding then
/// stalls, and −1.3e-2 beside a sharp corner of a convex 7-gon glued to a circle. As the radii
/// grow, κ tends to δ, so with the bound at −`KAPPA_SLACK` alone that gluing found no start at
/// any radius and ended 10 % stretched; started at κ ≈ δ it converges in 11 Newton steps,
/// convex to 8e-10 of its size. An outline that bends inward by a little between coarse samples
/// is no convex pair at the resolution and does not come here (`simulate` tests the
/// resolution's samples).
pub(crate) const KAPPA_SLACK: f64 = 1e-2;

/// How far past π an edge's dihedral angle sum may go before it is flipped, while the starting
/// radii are sought ([`embed`]).
pub(crate) const FLIP_EPS: f64 = 1e-9;

/// [`FLIP_EPS`] along the continuation, after every Newton step: an edge stays unflipped until
/// its dihedral angle sum is 1e-4 past π. Where both pieces are straight the metric is flat, and
/// the seam edges' mean lengths ([`Mesh::from_chords`]) leave such vertices' δ a little off
/// zero, down to −4.5e-4: no convex polyhedron has them, and the polyhedron the continuation
/// nears bends the other way there by a hair. With 1e-9 the edges around them flipped to and
/// fro and the Newton steps stalled: two congruent rounded rectangles (160 × 60 with 1 mm corners
/// at 8/16, 120 × 80 with 3 mm at 15/16, 200 × 40 with 8 mm at 1/16 and 9/16) ended 1–7 %
/// stretched. With 1e-4 they converge, 160 × 60 at 8/16 to the volume of its half-turn twin at
/// 0/16 (117,805 mm³, to 3e-6) and 120 × 80 at 15/16 to that of 7/16 (135,723 mm³, to 1e-7);
/// what is left of the hair is polished away on the chord meshes ([`super::crossing`]), whose
/// answer is still held to convexity by its sound faces. 1e-3 solved the same four.
pub(crate) const STEP_FLIP_EPS: f64 = 1e-4;

/// How far past π a Newton step may take an edge's dihedral angle sum before it is flipped:
/// a flip at π leaves κ continuous, a flip far past it does not.
pub(crate) const STEP_THETA: f64 = 0.05;

/// Round-off allowed in the cosines of a tetrahedron's angles before it counts as not real: the
/// thin tetrahedra of the first, large radii put them within a few ulps of ±1.
pub(crate) const REAL_TOL: f64 = 1e-9;

/// Newton steps within which a solve counts as easy, so that the next target may be twice as far
/// (see [`embed`]); a harder one keeps the step, which spares the failed attempts at the doubled
/// one (each up to [`NEWTON_STEPS`]).
pub(crate) const EASY_NEWTON: usize = 4;
