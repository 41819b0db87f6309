//! The glued mesh of the two meshed pieces and the elastic shell's terms on it.

use crate::libm_ext::LibmExt;
use super::flatmesh::{interior_angle, mesh_piece_with_fans, FlatMesh};
use super::shell::{Edge, Hinge, Shell};
use crate::simulate::seam::SeamPieces;
use crate::order::pair_key;
use crate::simulate::metric::KeyMap;

/// The glued mesh of the two meshed pieces: seam vertices `0..n` shared, then A's interior
/// vertices, then B's. `faces[p]` are piece p's triangles in the surface's orientation (A's
/// counter-clockwise as meshed, B's reversed: its flat samples are mirrored, see
/// [`crate::simulate::seam`]); `flat[p][v]` is vertex v's position on piece p's flat piece (seam samples
/// have one on each piece; an interior vertex only on its own, the other piece's entry unused).
#[derive(Debug, Clone)]
pub struct SheetMesh {
    pub n: usize,
    pub faces: [Vec<[usize; 3]>; 2],
    pub flat: [Vec<[f64; 2]>; 2],
}

/// Smallest |angle defect| of the glued surface at a seam vertex, `2π` less the two pieces'
/// interior angles there, that gets fans of extra vertices in both pieces
/// ([`super::flatmesh::mesh_piece_with_fans`]): the cone points a corner makes (a square corner
/// on a circle: 90°; the drawn heart's tip: 102°, its dip: −80°). Smooth organic pairs have
/// defects of a few degrees per sample and are meshed as before.
///
/// Around a cone point the sheet is a cone, which bends by a finite angle per unit angle of its
/// fan. With the refinement's own triangles, about three of 60° on a circle's side, the bends
/// across the fan's edges were 95–128°, "folds" that are the mesh's and not the sheet's (the
/// drawn heart's tip 115°, the L's convex corners 96–98°). With fans of at most 30° no hinge at
/// a corner is among the sharpest (L, dart and drawn heart with a circle, 256 seam vertices),
/// and the dart's sheet, which had ended folded back and was replaced by the convex path's
/// answer (2.9e-2 strain), ends 9.6e-4 strained without crossing.
pub const CONE_DEFECT: f64 = 25.0 * std::f64::consts::PI / 180.0;

/// The seam samples that are cone points of the glued surface: |angle defect| above
/// [`CONE_DEFECT`] (a corner of either piece glued to a smooth stretch, or two corners).
pub fn cone_samples(pieces: &SeamPieces) -> Vec<usize> {
    (0..pieces.n)
        .filter(|&k| {
            let total = interior_angle(&pieces.flat[0].pts, k) + interior_angle(&pieces.flat[1].pts, k);
            (std::f64::consts::TAU - total).abs() > CONE_DEFECT
        })
        .collect()
}

/// Each directed edge `i → j` of `faces`, keyed by [`pair_key`]`(i, j)`, and the index of the
/// face that holds it: the face across edge `i → j` of a consistently oriented mesh is the one
/// holding `j → i`.
pub fn face_of(faces: &[[usize; 3]]) -> KeyMap {
    let mut map = KeyMap::default();
    for (f, t) in faces.iter().enumerate() {
        for m in 0..3 {
            map.insert(pair_key(t[m], t[(m + 1) % 3]), f);
        }
    }
    map
}

/// The corner of triangle `t` that is neither `i` nor `j` (a hinge's tip on that side).
pub fn tip(t: [usize; 3], i: usize, j: usize) -> usize {
    t.into_iter().find(|&v| v != i && v != j).unwrap_or(i)
}

/// Tries at splitting the chords B shares with A ([`SheetMesh::new`]); each try re-meshes B.
/// Congruent pieces glued as mirror images (the flat doubly covered form) share the chords of
/// their tips: the heart with its mirror image had chord 127–130 in both at 256 seam vertices.
pub const SHARED_CHORD_SPLITS: usize = 3;

/// The edges of a meshed piece between two seam samples that are not seam neighbours, `(i, j)`
/// with `i < j < n`, sorted.
fn seam_chords(m: &FlatMesh, n: usize) -> Vec<(usize, usize)> {
    let mut out: Vec<(usize, usize)> = m
        .tris
        .iter()
        .flat_map(|t| (0..3).map(move |k| (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]))))
        .filter(|&(i, j)| j < n && j - i != 1 && !(i == 0 && j == n - 1))
        .collect();
    crate::order::sort_dedup_pairs(&mut out);
    out
}

impl SheetMesh {
    /// Meshes both pieces with interior edges of about `interior` times the perimeter (never
    /// shorter than the mean seam step), with fans at the cone points ([`CONE_DEFECT`]); `None`
    /// if either cannot be meshed.
    pub fn new(pieces: &SeamPieces, interior: f64) -> Option<Self> {
        Self::build(pieces, interior, &[], &[Vec::new(), Vec::new()])
    }

    /// [`SheetMesh::new`] with rows of vertices beside the seam samples `saddles`
    /// ([`super::saddle`]): the mesh the thin sheet is relaxed on.
    pub fn layered(pieces: &SeamPieces, interior: f64, saddles: &[usize]) -> Option<Self> {
        Self::build(pieces, interior, saddles, &[Vec::new(), Vec::new()])
    }

    /// [`SheetMesh::layered`] with the points `extra[p]` (inside piece p) kept as vertices too:
    /// the mesh refined where the sheet locked ([`super::adapt`]).
    pub fn refined(pieces: &SeamPieces, interior: f64, saddles: &[usize], extra: &[Vec<[f64; 2]>; 2]) -> Option<Self> {
        Self::build(pieces, interior, saddles, extra)
    }

    fn build(pieces: &SeamPieces, interior: f64, saddles: &[usize], extra: &[Vec<[f64; 2]>; 2]) -> Option<Self> {
        let n = pieces.n;
        let step = pieces.flat[0].perimeter / n as f64;
        let edge = (interior * pieces.flat[0].perimeter).max(step);
        let max_area = 3f64.sqrt() / 4.0 * edge * edge;
        let cones = cone_samples(pieces);
        let [pa, pb] = [&pieces.flat[0].pts, &pieces.flat[1].pts];
        let inner = |p: &[[f64; 2]], k: usize| [super::saddle::rows(p, saddles), extra[k].clone()].concat();
        // A mirror-symmetric pair gets mirror-symmetric meshes ([`super::mirror`]).
        let axis = super::mirror::axis(pieces);
        let mesh = |p: &[[f64; 2]], inner: &[[f64; 2]]| match axis {
            Some(j) => super::mirror::mesh_piece_mirrored(p, max_area, &cones, inner, j).or_else(|| mesh_piece_with_fans(p, max_area, &cones, inner)),
            None => mesh_piece_with_fans(p, max_area, &cones, inner),
        };
        let a = mesh(pa, &inner(pa, 0))?;
        // A chord between the same two seam samples in both pieces would bound four triangles:
        // B's is split at its midpoint ([`SHARED_CHORD_SPLITS`]).
        let in_a = seam_chords(&a, n);
        let mut inner = inner(pb, 1);
        let mut b = mesh(pb, &inner)?;
        for tries in 0.. {
            let shared: Vec<(usize, usize)> = seam_chords(&b, n).into_iter().filter(|c| in_a.binary_search(c).is_ok()).collect();
            if shared.is_empty() {
                break;
            }
            if tries == SHARED_CHORD_SPLITS {
                return None;
            }
            inner.extend(shared.iter().map(|&(i, j)| [(pb[i][0] + pb[j][0]) / 2.0, (pb[i][1] + pb[j][1]) / 2.0]));
            b = mesh(pb, &inner)?;
        }
        let meshes: [FlatMesh; 2] = [a, b];
        let ia = meshes[0].pts.len() - n;
        let total = n + ia + meshes[1].pts.len() - n;
        let global = |p: usize, v: usize| if p == 0 || v < n { v } else { v + ia };
        let mut faces: [Vec<[usize; 3]>; 2] = [Vec::new(), Vec::new()];
        let mut flat = [vec![[f64::NAN; 2]; total], vec![[f64::NAN; 2]; total]];
        for (p, m) in meshes.iter().enumerate() {
            for (v, q) in m.pts.iter().enumerate() {
                flat[p][global(p, v)] = *q;
            }
            faces[p] = m.tris.iter().map(|t| {
                let [a, b, c] = t.map(|v| global(p, v));
                if p == 0 { [a, b, c] } else { [a, c, b] }
            }).collect();
        }
        Some(SheetMesh { n, faces, flat })
    }

    pub fn vertex_count(&self) -> usize {
        self.flat[0].len()
    }

    /// Flat distance between `i` and `j` on piece `p`.
    pub fn rest(&self, p: usize, i: usize, j: usize) -> f64 {
        let (a, b) = (self.flat[p][i], self.flat[p][j]);
        (a[0] - b[0]).hypot_m(a[1] - b[1])
    }

    /// Flat area of triangle `t` of piece `p`.
    fn flat_area(&self, p: usize, t: [usize; 3]) -> f64 {
        let [a, b, c] = t.map(|v| self.flat[p][v]);
        ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs() / 2.0
    }

    /// The shell's terms: every edge of each piece at its flat length, and a hinge on every
    /// interior edge of each piece (none across the seam).
    pub fn shell(&self) -> Shell {
        let mut edges = Vec::new();
        let mut hinges = Vec::new();
        for p in 0..2 {
            let holder = face_of(&self.faces[p]);
            for t in &self.faces[p] {
                for m in 0..3 {
                    let (i, j) = (t[m], t[(m + 1) % 3]);
                    match holder.get(&pair_key(j, i)) {
                        Some(&g) => {
                            if i < j {
                                let other = self.faces[p][g];
                                let len = self.rest(p, i, j);
                                edges.push(Edge { i, j, rest: len, piece: p as u8 });
                                let a = self.flat_area(p, *t) + self.flat_area(p, other);
                                hinges.push(Hinge { v: [i, j, tip(*t, i, j), tip(other, j, i)], weight: 3.0 * len * len / a });
                            }
                        }
                        None => edges.push(Edge { i, j, rest: self.rest(p, i, j), piece: p as u8 }),
                    }
                }
            }
        }
        Shell::new(self.vertex_count(), edges, hinges)
    }
}

