//! Self-contact: the sheets may touch but not pass through each other.
//!
//! Real paper that meets itself is pushed back; the shell's energy ([`super::shell`]) has no
//! such term, and a sheet that is squeezed can relax through itself. Here each vertex is kept on
//! its side of every triangle near it that is not its neighbour (no corner within two edges of
//! it). A vertex–face pair seen within [`REACH`] seam steps of each other gets the side of the
//! face's plane the vertex is on, and keeps it while it stays a candidate (the candidates are
//! found again at each fresh factorization, [`super::shell::Shell::minimize`]). While the
//! vertex's projection lies in the face and the vertex is less than [`GAP`] seam steps from it
//! on its side, or anywhere on the other, the residual `√w (gap − s)` (`s` the signed distance,
//! `w` = [`WEIGHT`]) pushes it back. Remembering the side is what makes a step that jumps
//! through a face cost more than one that stops short: the usual one-sided penalty treatment of
//! contact (Wriggers, "Computational Contact Mechanics", 2nd ed. 2006, §2.1 and §6.3).
//!
//! The smooth heart with its copy or mirror image ends through itself on every path the sheet
//! path follows without it ([`super::retry`]): its dip is pushed through the other heart's lobe.
//! Followed again with contact (as a thick sheet, `kb/R²` = 1e-3), it ends isometric and
//! uncrossed, creased, at 3/16 and 13/16 (its copy) and at 3/16 (its mirror image), where it
//! had ended 4.2–4.8 % stretched through itself; with contact across the seam too (below), it
//! converges at 1/16 (its copy), and so did the kidney with its copy at 13/16 until stop 49's
//! canonical start ([`crate::simulate::anchor`]).
//!
//! *Sheets that touch (stop 55).* That kidney (256 seam vertices, native) now ends through itself
//! on every free path (3.2e-2, 3.2e-2 and 2.5e-2 strained) and uncrossed only with contact
//! across the seam, 7.0e-2 strained: the strain sits on the seam edges beside each piece's
//! deepest bay (radius 4.3 mm), which meets the other piece where it bends gently. So does
//! the slider from 12.9/16 to 14/16 (stretched by 5.4e-3 to 7.9e-2; 12.8/16 and 14.5/16
//! converge), in 1.7–5.3 s. Surface Evolver, which has no contact, also ends that gluing
//! through itself (75 crossing facet pairs, 9.2e-3 strained, `bench/evolver.bench.mjs`'s
//! touch check): no free equilibrium is missed there; the form is one the sheets hold by
//! touching, which this one-sided penalty does not relax to isometric. The closure below at
//! 0.5°, 1° or 3° instead of 2° moves those answers both ways (12.95/16 converges at 0.5°,
//! 14/16 goes from 7.9e-2 to 1.1e-1).
//!
//! *Across the seam.* The kidney with its mirror image at 5/16 and with its copy at 13/16 cross
//! within 1–4 mm of the seam, between triangles within two edges of each other, which the term
//! above leaves out (a vertex and a face that close are neighbours on a sound form too, where the
//! seam is sharp; counted as contacts, with only the faces on a vertex's own edges left out, the
//! sheet was held apart there but stayed 2.3 % stretched). There the two pieces close through
//! each other across the seam: the seam's opening (the angle between the pieces across it) goes
//! from 10° through 0 to the other side. So, where asked, each seam hinge (its two triangles, one
//! per piece, [`super::hinge`]) keeps its dihedral angle `θ` within `π − CLOSURE` of flat on the
//! side it had at the last refresh (the angle unwrapped from it, so a step through the closure
//! costs its whole way past it).
//!
//! *Why only as a last resort* ([`super::retry::CONTACT_KB`]). With contact on every path, the
//! first one (at the homotopy's weight) ended 26–30 % strained through itself on those hearts,
//! and far-off pairs took up to 3.2 times as long (the smooth heart with its copy at 1/16: 1.2
//! → 3.9 s native). On the thick retry ([`super::retry::KB`]) it cost the drawn heart with its
//! copy 0.1–0.2 s native and changed none of its answers: every evaluation of the energy tests
//! every candidate pair. Tried last, only on answers that still cross, it costs nothing
//! elsewhere.

use super::glued::{face_of, tip, SheetMesh};
use super::hinge::{angle, angle_and_gradient};
use crate::order::pair_key;
use crate::simulate::metric::KeyMap;
use crate::simulate::seam::SeamPieces;
use crate::simulate::vec3::{cross, dot, norm, sub, V3};

/// The distance a vertex is kept from a face, in seam steps (`L/n`).
pub const GAP: f64 = 0.1;

/// The distance within which a vertex–face pair is a candidate, in seam steps.
pub const REACH: f64 = 0.5;

/// The weight of a contact residual against a membrane one: a vertex `δ` too close costs as
/// much as an edge stretched by `10 δ`.
pub const WEIGHT: f64 = 100.0;

/// The smallest opening of the seam (the angle between the two pieces across it), radians: 2°.
/// Its residual is `√w · (L/n) · (|θ| − (π − CLOSURE))` for a seam hinge bent by `|θ|` beyond
/// `π − CLOSURE`. At 5° the kidney with its mirror image at 5/16 ended creased and isometric
/// and the kidney with its copy at 13/16 1.44 % strained, where at 2° the first stays 1.54 %
/// strained and the second converges; at 10° neither is sound. On every path (at 5°), 6 of the
/// 240 two-blob pairs that converge without it ended 2.7–7.9 % strained, and the drawn heart with
/// its copy at 3/16 3.5e-3: seams close below a few degrees on the way to sound forms.
pub const CLOSURE: f64 = 2.0 * std::f64::consts::PI / 180.0;

/// The contact term of a shell.
#[derive(Debug, Clone)]
pub struct Contact {
    /// Faces of both pieces.
    faces: Vec<[usize; 3]>,
    /// For each vertex, the vertices within two edges of it (itself included), sorted: a face
    /// holding one of them is its neighbour, never a contact.
    near: Vec<Vec<usize>>,
    /// The distance it is kept at.
    pub gap: f64,
    /// The distance within which a pair becomes a candidate.
    pub reach: f64,
    /// Weight `w` of the residual.
    pub weight: f64,
    /// The candidates: vertex, face and the side (±1) of the face's plane the vertex keeps.
    pairs: Vec<(usize, usize, f64)>,
    /// The seam's hinges `(i, j, k, l)` (edge i→j, k in A, l in B, [`super::hinge`]) and their
    /// dihedral angles at the last refresh, unwrapped (NaN before the first).
    seam: Vec<[usize; 4]>,
    seam_angle: Vec<f64>,
    /// Smallest opening of the seam, radians, and the factor of its residual (a length).
    closure: f64,
    seam_scale: f64,
}

/// One active term: its residual, its four vertices and their gradient rows.
pub struct Term {
    pub v: [usize; 4],
    pub rows: [V3; 4],
    pub r: f64,
    /// Factors `m` of a majorant of the term's `JᵀJ`: `Σ_a m_a g_a g_aᵀ` on the diagonal
    /// blocks is at least `(Σ_a g_a·δ_a)²` for every `δ`.
    pub major: [f64; 4],
}

impl Contact {
    /// Contact between the faces of both pieces of `mesh` ([`GAP`], [`REACH`], [`WEIGHT`]), and
    /// across the seam ([`CLOSURE`]) when `seam` is set.
    pub fn on(pieces: &SeamPieces, mesh: &SheetMesh, seam: bool) -> Self {
        let step = pieces.flat[0].perimeter / pieces.n as f64;
        let faces: Vec<[usize; 3]> = mesh.faces.iter().flatten().copied().collect();
        let edges: Vec<(usize, usize)> = faces.iter().flat_map(|f| [(f[0], f[1]), (f[1], f[2]), (f[2], f[0])]).collect();
        let mut c = Self::new(mesh.vertex_count(), faces, &edges, GAP * step, REACH * step, WEIGHT);
        if seam {
            // Each directed edge's tip, per piece; the seam edge i→j of A meets j→i of B (the
            // faces are in the surface's orientation, [`SheetMesh`]).
            let holders = [0, 1].map(|p| face_of(&mesh.faces[p]));
            let across = |p: usize, i: usize, j: usize| holders[p].get(&pair_key(i, j)).map(|&f| tip(mesh.faces[p][f], i, j));
            let n = mesh.n;
            c.seam = (0..n)
                .filter_map(|i| {
                    let j = (i + 1) % n;
                    Some([i, j, across(0, i, j)?, across(1, j, i)?])
                })
                .collect();
            c.seam_angle = vec![f64::NAN; c.seam.len()];
            c.closure = CLOSURE;
            c.seam_scale = WEIGHT.sqrt() * step;
        }
        c
    }

    /// Contact between `faces` on `n` vertices joined by `edges` (each edge once or more).
    pub fn new(n: usize, faces: Vec<[usize; 3]>, edges: &[(usize, usize)], gap: f64, reach: f64, weight: f64) -> Self {
        let mut adj = vec![Vec::new(); n];
        for &(i, j) in edges {
            adj[i].push(j);
            adj[j].push(i);
        }
        let near = (0..n)
            .map(|v| {
                let mut s = vec![v];
                for &w in &adj[v] {
                    s.push(w);
                    s.extend(adj[w].iter().copied());
                }
                s.sort_unstable();
                s.dedup();
                s
            })
            .collect();
        Contact { faces, near, gap, reach, weight, pairs: Vec::new(), seam: Vec::new(), seam_angle: Vec::new(), closure: 0.0, seam_scale: 0.0 }
    }

    /// The candidates at `x`: every vertex–face pair within [`Contact::reach`] of each other
    /// that are not neighbours. A pair that was a candidate keeps its side; a new one gets the
    /// side it is on now.
    pub fn refresh(&mut self, x: &[V3]) {
        let old: KeyMap = self.pairs.iter().map(|&(v, f, s)| (pair_key(v, f), if s > 0.0 { 1 } else { 0 })).collect();
        let boxes: Vec<(V3, V3)> = self
            .faces
            .iter()
            .map(|f| {
                let lo = [0, 1, 2].map(|a| f.iter().map(|&v| x[v][a]).fold(f64::INFINITY, f64::min) - self.reach);
                let hi = [0, 1, 2].map(|a| f.iter().map(|&v| x[v][a]).fold(f64::NEG_INFINITY, f64::max) + self.reach);
                (lo, hi)
            })
            .collect();
        // Sweep along x: faces by their boxes' low ends, vertices by x.
        let by_lo = crate::order::argsort(&boxes.iter().map(|b| b.0[0]).collect::<Vec<_>>());
        let verts = crate::order::argsort(&x.iter().map(|p| p[0]).collect::<Vec<_>>());
        let mut pairs = Vec::new();
        let mut open: Vec<usize> = Vec::new();
        let mut next = 0;
        for &v in &verts {
            let p = x[v];
            while next < by_lo.len() && boxes[by_lo[next]].0[0] <= p[0] {
                open.push(by_lo[next]);
                next += 1;
            }
            open.retain(|&f| boxes[f].1[0] >= p[0]);
            for &f in &open {
                let (lo, hi) = boxes[f];
                if (1..3).any(|a| p[a] < lo[a] || p[a] > hi[a]) {
                    continue;
                }
                let face = self.faces[f];
                if face.iter().any(|w| self.near[v].binary_search(w).is_ok()) {
                    continue;
                }
                let side = match old.get(&pair_key(v, f)) {
                    Some(&s) => if s == 1 { 1.0 } else { -1.0 },
                    None => {
                        let (n, a) = plane(x, face);
                        if dot(n, sub(p, a)) >= 0.0 { 1.0 } else { -1.0 }
                    }
                };
                pairs.push((v, f, side));
            }
        }
        self.pairs = pairs;
        for (h, prev) in self.seam.iter().zip(&mut self.seam_angle) {
            let t = angle(x[h[0]], x[h[1]], x[h[2]], x[h[3]]);
            *prev = if prev.is_nan() { t } else { unwrap(t, *prev) };
        }
    }

    /// The active terms at `x`.
    pub fn terms(&self, x: &[V3]) -> Vec<Term> {
        let sw = self.weight.sqrt();
        let mut out = Vec::new();
        for &(v, f, side) in &self.pairs {
            let face = self.faces[f];
            let (n, a) = plane(x, face);
            let l = norm(n);
            if l == 0.0 {
                continue;
            }
            let u = n.map(|c| c / l);
            let p = x[v];
            let s = side * dot(u, sub(p, a));
            if s >= self.gap {
                continue;
            }
            // Barycentric coordinates of the projection.
            let q = sub(p, u.map(|c| c * dot(u, sub(p, a))));
            let [x0, x1, x2] = face.map(|w| x[w]);
            let area = |p0: V3, p1: V3, p2: V3| dot(cross(sub(p1, p0), sub(p2, p0)), u) / l;
            let b = [area(q, x1, x2), area(x0, q, x2), area(x0, x1, q)];
            if b.iter().any(|&c| c < 0.0) {
                continue;
            }
            let d = u.map(|c| side * sw * c);
            // (g·δ_v − Σ bᵢ g·δᵢ)² ≤ 2(g·δ_v)² + 2 Σ bᵢ (g·δᵢ)² (Σ bᵢ = 1, Jensen).
            out.push(Term {
                v: [v, face[0], face[1], face[2]],
                rows: [d.map(|c| -c), d.map(|c| c * b[0]), d.map(|c| c * b[1]), d.map(|c| c * b[2])],
                r: sw * (self.gap - s),
                major: [2.0, jensen(b[0]), jensen(b[1]), jensen(b[2])],
            });
        }
        for (h, &prev) in self.seam.iter().zip(&self.seam_angle) {
            let Some((t, grad)) = angle_and_gradient(x[h[0]], x[h[1]], x[h[2]], x[h[3]]) else { continue };
            let t = if prev.is_nan() { t } else { unwrap(t, prev) };
            let over = t.abs() - (std::f64::consts::PI - self.closure);
            if over <= 0.0 {
                continue;
            }
            let k = t.signum() * self.seam_scale;
            // (Σ g_a·δ_a)² ≤ 4 Σ (g_a·δ_a)² (Cauchy–Schwarz).
            out.push(Term { v: *h, rows: grad.map(|g| g.map(|c| k * c)), r: self.seam_scale * over, major: [4.0; 4] });
        }
        out
    }

    /// The contact energy `Σ r²` at `x`.
    pub fn cost(&self, x: &[V3]) -> f64 {
        self.terms(x).iter().map(|t| t.r * t.r).sum()
    }

}

/// The majorant factor `2/b` of a corner row `b g` ([`Term::major`]): its block is `2 b g gᵀ`.
fn jensen(b: f64) -> f64 {
    if b > 0.0 { 2.0 / b } else { 0.0 }
}

/// `t` moved by whole turns to within half a turn of `prev`.
fn unwrap(t: f64, prev: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    t + tau * ((prev - t) / tau).round()
}

/// A face's normal (not unit) and its first corner.
fn plane(x: &[V3], f: [usize; 3]) -> (V3, V3) {
    (cross(sub(x[f[1]], x[f[0]]), sub(x[f[2]], x[f[0]])), x[f[0]])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit right triangle in the plane z = 0 (vertices 0, 1, 2), a vertex 3 above its
    /// inside at height `z`, and a vertex 4 joined to vertex 0 by an edge.
    fn scene(z: f64) -> (Contact, Vec<V3>) {
        let x = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.25, 0.25, z], [0.3, 0.3, z]];
        let c = Contact::new(5, vec![[0, 1, 2]], &[(0, 1), (1, 2), (2, 0), (0, 4)], 0.1, 0.5, 4.0);
        (c, x)
    }

    #[test]
    fn a_vertex_is_pushed_back_by_the_depth_it_lacks_on_the_side_it_was_seen_on() {
        let (mut c, mut x) = scene(0.05);
        c.refresh(&x);
        let terms = c.terms(&x);
        // Vertex 4 is a neighbour of the face (an edge to its corner 0): never a contact.
        assert_eq!(terms.iter().map(|t| t.v[0]).collect::<Vec<_>>(), vec![3], "wanted one term, of vertex 3");
        // √w (gap − s) = 2 (0.1 − 0.05).
        assert!((terms[0].r - 0.1).abs() < 1e-12, "wanted residual 0.1 at height 0.05, got {}", terms[0].r);
        // The corners share the push by the projection's barycentric coordinates, (0.5, 0.25,
        // 0.25) at (0.25, 0.25): rows[k] = −b_k rows[0].
        let t = &terms[0];
        for (k, b) in [0.5, 0.25, 0.25].into_iter().enumerate() {
            let want = t.rows[0].map(|c| -b * c);
            assert!((0..3).all(|a| (t.rows[k + 1][a] - want[a]).abs() < 1e-12), "corner {k}: wanted row {want:?}, got {:?}", t.rows[k + 1]);
        }
        // Through the face to −0.05: the side seen first is kept, so the depth counts.
        x[3][2] = -0.05;
        c.refresh(&x);
        let r = c.terms(&x)[0].r;
        assert!((r - 0.3).abs() < 1e-12, "wanted residual 2 (0.1 + 0.05) = 0.3 on the wrong side, got {r}");
        assert!((c.cost(&x) - 0.09).abs() < 1e-12, "wanted energy 0.09, got {}", c.cost(&x));
        // Out of the gap on its own side: no term.
        x[3][2] = 0.2;
        c.refresh(&x);
        assert!(c.terms(&x).is_empty(), "wanted no term at height 0.2 (gap 0.1)");
        // Beyond the reach, the pair is forgotten; seen again below, its side is the new one.
        x[3][2] = 1.0;
        c.refresh(&x);
        x[3][2] = -0.05;
        c.refresh(&x);
        let r = c.terms(&x)[0].r;
        assert!((r - 0.1).abs() < 1e-12, "wanted residual 0.1 for a pair seen anew below the face, got {r}");
    }

    /// A seam hinge `(0, 1, 2, 3)`: edge along x, tip 2 at +y, tip 3 turned about the edge by
    /// `phi` from the flat position at −y (so `|θ| = phi` and the opening is `π − phi`).
    fn hinge_scene(phi: f64) -> (Contact, Vec<V3>) {
        let x = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 1.0, 0.0], [0.5, -phi.cos(), phi.sin()]];
        let mut c = Contact::new(4, Vec::new(), &[], 0.1, 0.5, 1.0);
        (c.seam, c.seam_angle, c.closure, c.seam_scale) = (vec![[0, 1, 2, 3]], vec![f64::NAN], CLOSURE, 3.0);
        (c, x)
    }

    #[test]
    fn a_seam_closing_through_itself_costs_its_whole_way_past_the_closure() {
        let deg = std::f64::consts::PI / 180.0;
        let (mut c, mut x) = hinge_scene(170.0 * deg);
        c.refresh(&x);
        assert!(c.terms(&x).is_empty(), "wanted no term at an opening of 10° (closure 2°)");
        let at = |c: &Contact, x: &[V3]| c.terms(x).first().map_or(0.0, |t| t.r);
        x[3] = hinge_scene(179.0 * deg).1[3];
        let r = at(&c, &x);
        assert!((r - 3.0 * deg).abs() < 1e-9, "wanted 3 · 1° (179° against 178°) = {}, got {r}", 3.0 * deg);
        c.refresh(&x);
        // Through the closure to 181°: the raw angle reads −179°, the unwrapped one 181°.
        x[3] = hinge_scene(181.0 * deg).1[3];
        let r = at(&c, &x);
        assert!((r - 9.0 * deg).abs() < 1e-9, "wanted 3 · 3° (181° against 178°) = {}, got {r}", 9.0 * deg);
        // The gradient's rows are the hinge angle's, scaled: the residual grows along them.
        let t = &c.terms(&x)[0];
        let h = 1e-7;
        let mut y = x.clone();
        for a in 0..3 {
            y[3][a] += h * t.rows[3][a];
        }
        let grew = (at(&c, &y) - r) / h;
        let wanted: f64 = t.rows[3].iter().map(|v| v * v).sum();
        assert!((grew - wanted).abs() < 1e-4 * wanted, "wanted a directional derivative of {wanted}, got {grew}");
    }

    #[test]
    fn a_vertex_whose_projection_misses_the_face_has_no_term() {
        let (mut c, mut x) = scene(0.05);
        x[3] = [0.8, 0.8, 0.05];
        c.refresh(&x);
        assert!(c.terms(&x).is_empty(), "wanted no term for a point beside the triangle");
    }
}
