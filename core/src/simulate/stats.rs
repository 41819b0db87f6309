//! The solved mesh and the figures that say how true it is. Every figure is measured on the
//! returned mesh against the flat pieces, independently of the solver's own residuals.

use crate::libm_ext::LibmExt;
use super::seam::SeamPieces;
use super::checks::reflex_sine;
use super::mesh::{make_outward, signed_volume, split_shared_chords, Solution};
use super::vec3::{cross, dot, map_affine, norm, sub, V3};
use super::Simulation;
use std::f64::consts::TAU;

/// A chord whose out-of-plane sine exceeds this is counted in `reflex_edges` (a visible dent).
pub const REFLEX_REPORT: f64 = 1e-6;

/// How true the shape is. Lengths and areas in the input's units.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Stats {
    /// Largest |3D length / flat length − 1| over every edge of both pieces (seam edges are
    /// measured against each piece's own chord).
    pub max_strain: f64,
    pub mean_strain: f64,
    /// The least `max_strain` any mesh on these seam samples can have ([`strain_floor`]): a
    /// seam edge has two flat lengths, A's chord and B's chord of the same arc.
    pub strain_floor: f64,
    /// Largest distance between A's and B's true (curved) edges at the middle of a seam edge,
    /// each laid onto its piece's triangle at that edge: what the polygonal seam leaves open.
    pub seam_gap: f64,
    /// |surface area − (area of A + area of B)| / (area of A + area of B), true curved outlines.
    pub area_error: f64,
    /// Sum of |angle defect| over the seam vertices: 4π when every seam vertex is convex
    /// (Gauss–Bonnet makes the signed sum 4π for any closed mesh, so |·| is the informative one).
    pub angle_defect_sum: f64,
    /// Sum of |angle defect| over vertices off the seam (the flat parts: should be 0).
    pub interior_defect_sum: f64,
    /// Chords folded the wrong way (dents); 0 for a convex D-form.
    pub reflex_edges: usize,
    pub volume: f64,
    pub area: f64,
    pub iterations: usize,
    pub flips: usize,
    pub converged: bool,
    pub ms: f64,
    /// Largest bend inside a piece, radians: the angle between the normals of two triangles of
    /// the same piece that share an edge (0 flat, π folded back), on the returned mesh.
    pub max_bend: f64,
    /// Why an answer is not `converged` ([`Shortfall`]); `None` when it is.
    pub shortfall: Option<Shortfall>,
    /// One piece is a circle and the other is not convex, so the seam offset does not change
    /// the form: every offset gives this mesh, the circle's flat coordinates turned
    /// ([`crate::simulate::round`]).
    pub offset_free: bool,
}

/// What keeps an unconverged answer from being the D-form, the first of these that holds on the
/// returned mesh, so that a host can say what is wrong with the preview instead of one message
/// for all (the panel told a student that an L glued to a circle "stretches up to 0 %").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shortfall {
    /// Some edge is more than [`crate::simulate::sheet::STRAIN_TARGET`] off its flat length:
    /// the pieces would have to stretch into this shape.
    Stretch,
    /// Two triangles cross: the sheets pass through each other.
    Crossing,
    /// Isometric and embedded, but a non-convex pair's mesh bends by more than
    /// [`crate::simulate::checks::FOLD_BEND`] inside a piece: the sheet is creased there (the
    /// circle across its inside, beside a reflex corner of the other piece; between the
    /// arms of a star).
    Fold,
    /// Embedded and not creased, but some edge is more than
    /// [`crate::simulate::sheet::STRAIN_TARGET`] off its flat length because the seam samples
    /// allow no better: A's and B's chords of a seam edge differ by more than that
    /// ([`Stats::strain_floor`]), and no edge is off by more than the floor plus the target. One
    /// piece curves much more tightly than the other between two samples (a corner rounded by a
    /// millimetre, at 128 seam vertices); more seam vertices or a less tight curve remove it.
    Sampling,
    /// None of the above: the solve stopped within its budget before its length equations were
    /// met to the solver's own tolerance, or the mesh is not a 2-manifold.
    Unsettled,
}

impl Shortfall {
    /// The name the JSON contract uses.
    pub fn name(self) -> &'static str {
        match self {
            Shortfall::Stretch => "stretch",
            Shortfall::Crossing => "crossing",
            Shortfall::Fold => "fold",
            Shortfall::Sampling => "sampling",
            Shortfall::Unsettled => "unsettled",
        }
    }
}

/// An interior edge of a piece bent by more than [`crate::simulate::checks::FOLD_BEND`] in a
/// non-convex pair's answer: where the sheet creases ([`Shortfall::Fold`]), so that a host can
/// show where, not only that.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crease {
    /// 0 for piece A, 1 for piece B.
    pub piece: u8,
    /// The edge's two vertices (indices into the result's vertices).
    pub vertices: [usize; 2],
    /// The angle between the normals of its two triangles, radians (π: folded back).
    pub bend: f64,
}

/// Fills `max_bend`, `shortfall` and `creases` of `sim` from its mesh; `folds` says whether a
/// sharp bend counts against it (a non-convex pair's; a convex pair's sharp chords are edges of
/// its Alexandrov polyhedron, not creases).
pub fn judge(sim: &mut Simulation, folds: bool) {
    let bends = bends_inside(&sim.vertices, &sim.triangles, &sim.piece);
    let bend = bends.iter().map(|c| c.bend).fold(0.0, f64::max);
    sim.stats.max_bend = bend;
    sim.creases = if folds { bends.into_iter().filter(|c| c.bend > super::checks::FOLD_BEND).collect() } else { Vec::new() };
    // `converged` promises every edge within the target. A convex pair's solver calls its
    // polyhedron converged when the polyhedron meets its own length equations, whose seam edges
    // take one length between A's and B's chords: at coarse seams and tight corners those differ
    // by more than the target (a rectangle with 1 mm corners on a circle at 128: 1.9e-3).
    let target = super::sheet::STRAIN_TARGET;
    let floor = strain_floor(&sim.triangles, &sim.flat, &sim.piece);
    sim.stats.strain_floor = floor;
    if sim.stats.max_strain > target {
        sim.stats.converged = false;
    }
    // The samples' share of the strain is not the solver's: beyond the floor, within target.
    let strained = sim.stats.max_strain > target;
    let sampled = floor > target && sim.stats.max_strain <= strain_allowed(floor);
    sim.stats.shortfall = if sim.stats.converged {
        None
    } else if strained && !sampled {
        Some(Shortfall::Stretch)
    } else if super::checks::faces_cross(&sim.vertices, &sim.triangles) {
        Some(Shortfall::Crossing)
    } else if folds && bend > super::checks::FOLD_BEND {
        Some(Shortfall::Fold)
    } else if strained {
        Some(Shortfall::Sampling)
    } else {
        Some(Shortfall::Unsettled)
    };
}

/// The largest edge strain of an answer that is as isometric as seam samples whose floor
/// ([`strain_floor`]) is `floor` allow: the target ([`crate::simulate::sheet::STRAIN_TARGET`]),
/// or, where the floor is above it, the floor plus the target ([`Shortfall::Sampling`]).
pub fn strain_allowed(floor: f64) -> f64 {
    let target = super::sheet::STRAIN_TARGET;
    if floor > target { floor + target } else { target }
}

/// The least largest strain of any mesh with these triangles' flat corners: an edge that two
/// triangles of different pieces share (a seam edge) has two flat lengths `L₁ ≤ L₂` and is
/// strained by at least `(L₂ − L₁)/(L₁ + L₂)` against one of them, whatever its 3D length (the
/// least is at the harmonic mean). Zero for a mesh whose seam edges each have one length.
pub fn strain_floor(triangles: &[[usize; 3]], flat: &[[[f64; 2]; 3]], piece: &[u8]) -> f64 {
    let side = |t: usize, m: usize| {
        let (p, q) = (flat[t][m], flat[t][(m + 1) % 3]);
        (q[0] - p[0]).hypot_m(q[1] - p[1])
    };
    let mut first = super::metric::KeyMap::default();
    let mut floor: f64 = 0.0;
    for (t, tri) in triangles.iter().enumerate() {
        for m in 0..3 {
            let (i, j) = (tri[m], tri[(m + 1) % 3]);
            let key = crate::order::pair_key(i.min(j), i.max(j));
            match first.get(&key) {
                Some(&s) if piece[s / 3] != piece[t] => {
                    let (a, b) = (side(s / 3, s % 3), side(t, m));
                    if a + b > 0.0 {
                        floor = floor.max((a - b).abs() / (a + b));
                    }
                }
                Some(_) => {}
                None => {
                    first.insert(key, 3 * t + m);
                }
            }
        }
    }
    floor
}

/// Largest angle between the normals of two triangles of the same piece sharing an edge.
pub fn max_bend_inside(x: &[V3], triangles: &[[usize; 3]], piece: &[u8]) -> f64 {
    bends_inside(x, triangles, piece).iter().map(|c| c.bend).fold(0.0, f64::max)
}

/// Every edge shared by two triangles of the same piece, with the angle between their normals
/// (edges of a degenerate triangle left out), in the order the triangles first meet them.
pub fn bends_inside(x: &[V3], triangles: &[[usize; 3]], piece: &[u8]) -> Vec<Crease> {
    let mut owner = super::metric::KeyMap::default();
    let normal = |t: usize| {
        let [a, b, c] = triangles[t];
        cross(sub(x[b], x[a]), sub(x[c], x[a]))
    };
    let mut out = Vec::new();
    for (t, tri) in triangles.iter().enumerate() {
        for m in 0..3 {
            let (i, j) = (tri[m], tri[(m + 1) % 3]);
            match owner.get(&crate::order::pair_key(j, i)) {
                Some(&u) if piece[u] == piece[t] => {
                    let (n1, n2) = (normal(u), normal(t));
                    if norm(n1) > 0.0 && norm(n2) > 0.0 {
                        out.push(Crease { piece: piece[t], vertices: [j, i], bend: norm(cross(n1, n2)).atan2_m(dot(n1, n2)) });
                    }
                }
                Some(_) => {}
                None => {
                    owner.insert(crate::order::pair_key(i, j), t);
                }
            }
        }
    }
    out
}


/// Angle at `a` in triangle (a, b, c), robust near 0 and π.
fn angle(a: V3, b: V3, c: V3) -> f64 {
    let (u, v) = (sub(b, a), sub(c, a));
    norm(cross(u, v)).atan2_m(dot(u, v))
}

/// The surface area of `triangles` and, for every vertex of `x`, the sum of its triangles'
/// angles there (2π minus it is the vertex's angle defect, its discrete Gaussian curvature).
pub(crate) fn area_and_angle_sums(x: &[V3], triangles: &[[usize; 3]]) -> (f64, Vec<f64>) {
    let mut angle_sum = vec![0.0; x.len()];
    let mut area = 0.0;
    for &[a, b, c] in triangles {
        area += norm(cross(sub(x[b], x[a]), sub(x[c], x[a]))) / 2.0;
        angle_sum[a] += angle(x[a], x[b], x[c]);
        angle_sum[b] += angle(x[b], x[c], x[a]);
        angle_sum[c] += angle(x[c], x[a], x[b]);
    }
    (area, angle_sum)
}

/// Builds the output mesh and measures it.
pub fn finish(pieces: &SeamPieces, sol: Solution) -> Simulation {
    let n = pieces.n;
    let c = sol.x.iter().fold([0.0; 3], |s, p| [s[0] + p[0], s[1] + p[1], s[2] + p[2]]).map(|v| v / n as f64);
    let mut x: Vec<V3> = sol.x.iter().map(|p| sub(*p, c)).collect();
    // Outward triangles, as promised: the solver keeps a converged shape outward, but a gluing it
    // cannot realize (strongly non-convex pieces) may end inside out. Its mirror image, an
    // isometry, is the same approximation seen with the drawn faces outside.
    make_outward(&mut x, &sol.tri);

    let mut triangles = Vec::with_capacity(2 * n);
    let mut piece = Vec::with_capacity(2 * n);
    let mut flat = Vec::with_capacity(2 * n);
    for (p, t) in sol.tri.iter().enumerate() {
        // The samples of B are mirrored (x → −x, see `seam`); mirroring back gives the input's
        // coordinates, and the reversed corner order keeps each flat triangle beside its 3D one.
        let at = |v: usize| {
            let q = pieces.flat[p].pts[v];
            if p == 0 { q } else { [-q[0], q[1]] }
        };
        for &[a, b, c] in &t.tris {
            let tri = if p == 0 { [a, b, c] } else { [a, c, b] };
            triangles.push(tri);
            flat.push(tri.map(at));
            piece.push(p as u8);
        }
    }

    let (mut max_strain, mut sum_strain, mut count) = (0.0f64, 0.0, 0usize);
    for (p, t) in sol.tri.iter().enumerate() {
        for (i, j) in t.edges() {
            let d = pieces.chord(p, i, j);
            if d > 0.0 {
                let s = (norm(sub(x[j], x[i])) / d - 1.0).abs();
                max_strain = max_strain.max(s);
                sum_strain += s;
                count += 1;
            }
        }
    }

    let mut seam_gap = 0.0f64;
    for k in 0..n {
        let k1 = (k + 1) % n;
        let mid = |p: usize| {
            let r = sol.tri[p].opposite(k, k1)?;
            let f = &pieces.flat[p].pts;
            map_affine([f[k], f[k1], f[r]], [x[k], x[k1], x[r]], pieces.flat[p].arc_mid[k])
        };
        if let (Some(a), Some(b)) = (mid(0), mid(1)) {
            seam_gap = seam_gap.max(norm(sub(a, b)));
        }
    }

    if sol.converged {
        // Only an isometric answer: in a strained one a triangle's new inner edge (a median)
        // may be strained more than its sides, which `max_strain` below would not see.
        split_shared_chords(&mut x, &mut triangles, &mut flat, &mut piece);
    }
    let (area, angle_sum) = area_and_angle_sums(&x, &triangles);
    let flat_area = pieces.flat[0].area + pieces.flat[1].area;
    // Vertices 0..n are the seam; any further vertex would be interior (this mesh has none).
    let defect = |v: usize| (TAU - angle_sum[v]).abs();
    let angle_defect_sum = (0..n).map(defect).sum();
    let interior_defect_sum = (n..x.len()).map(defect).sum();

    let mut reflex_edges = 0;
    for (p, t) in sol.tri.iter().enumerate() {
        for (i, j) in t.chords() {
            if reflex_sine(&x, t, p, i, j).is_some_and(|s| s > REFLEX_REPORT) {
                reflex_edges += 1;
            }
        }
    }

    let stats = Stats {
        max_strain,
        mean_strain: if count > 0 { sum_strain / count as f64 } else { 0.0 },
        strain_floor: 0.0,
        seam_gap,
        area_error: if flat_area > 0.0 { (area - flat_area).abs() / flat_area } else { 0.0 },
        angle_defect_sum,
        interior_defect_sum,
        reflex_edges,
        volume: signed_volume(&x, &sol.tri).abs(),
        area,
        iterations: sol.iterations,
        flips: sol.flips,
        converged: sol.converged,
        ms: 0.0,
        max_bend: 0.0,
        shortfall: None,
        offset_free: false,
    };
    Simulation { vertices: x, triangles, piece, seam: (0..n).collect(), flat, creases: Vec::new(), stats }
}
