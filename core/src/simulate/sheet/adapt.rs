//! Refinement where the thin sheet locks: the mesh made finer at the triangles that hold it,
//! and the sheet thinned again on it.
//!
//! A linear triangle held to 1e-3 strain bends isometrically only about its own edges
//! (membrane locking, see [`super`]), and the mesh can hold the sheet in two ways ([`Lock`]):
//!
//! - *Stretched.* Where the developable sheet must bend along a line the mesh has no edge for, a
//!   few edges stay strained at every bending weight. The saddle rows ([`super::saddle`]) give
//!   the mesh such edges where one piece's bay meets the other; where both pieces are concave at
//!   one place (two organic blobs whose bays meet, a piece with its mirror image at a small
//!   offset) they do not suffice: the kidney with its mirror image at 1/16 of its perimeter
//!   ended 3.4e-3 strained, the blob with its mirror image 3.1e-3, with no fold and no crossing.
//! - *Folded.* On a smooth pair (no cone point on the seam) a line of high curvature bends by
//!   60–110° between neighbouring triangles, and where the sharpest passes 90° the answer was
//!   called creased: the kidney with a circle at 128 seam vertices (101°), 15 of 240 random
//!   pairs of two blobs (91–103°). Paper creases only where it is forced to (a reflex corner or a
//!   cusp meeting the other piece: the L's crease stays at 116–125° however the mesh is refined),
//!   so on a smooth pair such a bend is the mesh's, and a finer mesh along the line shares it
//!   among more edges. Pairs with a cone point are not refined: their creases are the form's.
//!
//! A uniformly finer mesh frees such pairs at many times the cost (2 seam steps instead of 5:
//! 12 times the time). So the refinement is a-posteriori and local, as in adaptive finite
//! elements: every triangle with an edge strained beyond [`MARK`] of the target, or beside an
//! edge bent by more than [`BEND_MARK`], gets a vertex at its centroid; both pieces are meshed
//! again with those vertices kept (the Delaunay refinement grades the triangles around them),
//! the sheet's shape is carried onto the new mesh ([`super::refine::carry`]) and thinned again,
//! a stretched sheet from [`RESTART_KB`], a folded one from the stage it folded at; up to
//! [`ROUNDS`] rounds, each adding the marks of the round before, while they stay few
//! ([`GROWTH`]). A folded sheet's answer changes only when a round converges; when none does,
//! the rounds start over from the unrefined mesh, thinned from [`RESTART_KB`] (a thicker sheet
//! that can still move the line of high curvature).
//!
//! *The second pass of a folded sheet.* After the first pass two of the 240 two-blob pairs
//! (seed 5, pairs 14 and 15) stayed folded by 100° and 93°, and the kidney with a circle at 384
//! seam vertices by 91°. From [`RESTART_KB`] each converges, in the second or third round
//! (bends 82°, 83° and 65°; the kidney's volume 250,040 mm³ against 251,311 at 256), for 0.4–0.5
//! s more native. No other pair of the 312 or of the named pairs with a circle at 128, 256 and
//! 384 changes. A smooth pair that stays folded pays for both passes: the rounded star with a
//! circle at 384 seam vertices, 1.8 → 3.5 s native (at 256 its seam samples' floor is above the
//! target, and it is not refined). Thinning every folded sheet from [`RESTART_KB`] at once (one
//! pass) converged those three too, but folded another (seed 31, pair 14, converged before) by
//! 92° and moved 13 converged pairs' volumes by up to 0.5 %.
//!
//! Measured at 256 seam vertices, native, on 312 pairs: 240 random pairs of two blobs (the
//! survey's generator, seeds 11, 23, 5, 31, 47 and 59), and the blob, kidney, five lobes,
//! Pebble, drawn heart and smooth heart each with its copy and with its mirror image at 1, 3, 5,
//! 8, 11 and 13/16. 268 converged before, 292 now; of the two blobs 238 of 240 (219). Of the 11
//! stretched by less than 2e-2, 10 converge (the kidney with its mirror image at 5/16, 1.5e-2
//! strained through itself, has too many strained triangles to be a lock), in 0.5–1.6 s instead
//! of 0.3–0.6; of the 16 smooth folds, 14, in 0.36–0.63 s instead of 0.28–0.49. Volumes move by
//! 0.0–1.1 %: the same equilibrium, now isometric or unfolded. No other pair changes. In WASM the
//! kidney with a circle (folded by 98°) converges at 87° in 0.88 s instead of 0.63.
//!
//! Tried and not kept: thinning a stretched sheet again from the first stage (1e-5; the blob
//! with its mirror image then moved by 3.3 %) or from 1e-7 (stayed locked); marking at the
//! target itself (8 of the 11) or a quarter of it (8); two rounds (9). A folded sheet thinned
//! again from 1e-6 converged 15 of 16, but in WASM pairs with a cone point then took up to 1.7 s
//! (the heart with a circle, 0.39 before) for three futile rounds; marking at 45° converged 13.

use super::glued::{cone_samples, face_of, tip, SheetMesh};
use super::{finish, hinge};
use crate::order::pair_key;
use crate::simulate::checks::{faces_cross, FOLD_BEND};
use super::shell::Shell;
use super::{refine, thin, Path, Relaxed, SCHEDULE, STRAIN_TARGET};
use crate::simulate::progress::Reporter;
use crate::simulate::seam::SeamPieces;
use crate::simulate::vec3::{norm, sub, V3};

/// Rounds of refinement at most, each one thinning.
pub const ROUNDS: usize = 3;

/// A triangle is refined when one of its edges is strained beyond `MARK` times
/// [`STRAIN_TARGET`]: the edges just below the target lock the sheet as well.
pub const MARK: f64 = 0.5;

/// The bending weight (`kb / R²`, [`SCHEDULE`]) a stretched sheet's thinning starts again from
/// on the finer mesh: thin enough to keep the locked sheet's equilibrium, thick enough to let it
/// move. (A folded sheet starts again from the stage it folded at, where it is within the
/// target, and only when that does not converge from here: see the module docs.)
pub const RESTART_KB: f64 = 1e-6;

/// Largest strain (over [`STRAIN_TARGET`]) of a sheet that is refined: one strained by percents
/// is not locked but on a wrong equilibrium or through itself (the bound of
/// [`super::FAR_ABOVE`]).
pub const BELOW: f64 = super::FAR_ABOVE;

/// A folded sheet is refined at both triangles of every edge bent by more than this (radians):
/// the hinges beside the sharpest bend on a smooth sheet's high-curvature line, which share it
/// once the mesh is finer there.
pub const BEND_MARK: f64 = 60.0 * std::f64::consts::PI / 180.0;

/// Largest share of the mesh's vertices a round may add: more strained triangles than that are
/// no local lock.
///
/// Measured at 256 seam vertices, native (stop 46): on 240 random pairs of two blobs (the
/// survey's generator, seeds 11, 23, 5, 31, 47 and 59) and on the kidney, smooth heart, blob,
/// five lobes and Pebble with their copies and mirror images at 1–15/16 (the drawn heart at 2,
/// 4, 6, 7, 9, 10 and 12/16), every round that freed a sheet added at most 15 % (213
/// vertices to 1,422 on one blob pair; the others 1–11 %). The only rounds above 20 % were the
/// kidney with its copy at 14/16, on its touching path ([`super::retry::TOUCH`]): 327 of 1,421
/// (23 %), then 682 of 1,748 (39 %), each ending more strained (5.2e-3 and 3.0e-2 against
/// 3.33e-3) on meshes of up to 2,605 vertices: 5.0 of its 7.4 s. At 0.2 that pair returns the
/// same answer in 2.4 s, and no other pair of those 404 changes. At 0.4 (until stop 46) both
/// of its rounds ran.
pub const GROWTH: f64 = 0.2;

/// The centroid of triangle `t` of piece `p` on its flat piece.
fn flat_centroid(mesh: &SheetMesh, p: usize, t: [usize; 3]) -> [f64; 2] {
    let c = t.map(|v| mesh.flat[p][v]);
    [(c[0][0] + c[1][0] + c[2][0]) / 3.0, (c[0][1] + c[1][1] + c[2][1]) / 3.0]
}

/// The centroids of piece p's triangles that have an edge strained beyond [`MARK`] times
/// [`STRAIN_TARGET`] in the shape `x`, per piece.
pub fn strained_centroids(mesh: &SheetMesh, x: &[V3]) -> [Vec<[f64; 2]>; 2] {
    [0, 1].map(|p| {
        mesh.faces[p]
            .iter()
            .filter(|t| (0..3).any(|k| {
                let (i, j) = (t[k], t[(k + 1) % 3]);
                (norm(sub(x[i], x[j])) / mesh.rest(p, i, j) - 1.0).abs() > MARK * STRAIN_TARGET
            }))
            .map(|t| flat_centroid(mesh, p, *t))
            .collect()
    })
}

/// The centroids of piece p's triangles on either side of an edge bent by more than `above`
/// (radians) in the shape `x`, per piece (the hinges of [`SheetMesh::shell`]).
pub fn bent_centroids(mesh: &SheetMesh, x: &[V3], above: f64) -> [Vec<[f64; 2]>; 2] {
    [0, 1].map(|p| {
        let faces = &mesh.faces[p];
        let holder = face_of(faces);
        let mut marked = vec![false; faces.len()];
        for (f, t) in faces.iter().enumerate() {
            for m in 0..3 {
                let (i, j) = (t[m], t[(m + 1) % 3]);
                if let Some(&g) = holder.get(&pair_key(j, i)) {
                    if i < j && hinge::angle(x[i], x[j], x[tip(*t, i, j)], x[tip(faces[g], j, i)]).abs() > above {
                        marked[f] = true;
                        marked[g] = true;
                    }
                }
            }
        }
        faces.iter().zip(&marked).filter(|(_, &m)| m).map(|(t, _)| flat_centroid(mesh, p, *t))
            .collect()
    })
}

/// How a sheet that did not converge may be locked by its mesh rather than by its form.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Lock {
    /// A few edges stay stretched (beyond the target, below [`BELOW`] times it), where the
    /// samples allow (the seam's floor is within the target).
    Stretched,
    /// Isometric and not through itself, but bent by more than [`FOLD_BEND`] between two
    /// triangles of a piece, on a seam without cone points ([`cone_samples`]).
    Folded,
}

impl Lock {
    /// The lock of a sheet `relaxed` of `pieces` on `mesh` with `shell`, if any.
    pub fn of(pieces: &SeamPieces, mesh: &SheetMesh, shell: &Shell, relaxed: &Relaxed) -> Option<Lock> {
        if relaxed.converged || shell.strain_floor() > STRAIN_TARGET {
            return None;
        }
        if relaxed.max_strain > STRAIN_TARGET {
            return (relaxed.max_strain <= BELOW * STRAIN_TARGET).then_some(Lock::Stretched);
        }
        if !cone_samples(pieces).is_empty() {
            return None;
        }
        let faces: Vec<[usize; 3]> = mesh.faces.iter().flatten().copied().collect();
        (finish::max_bend(&relaxed.x, shell) > FOLD_BEND && !faces_cross(&relaxed.x, &faces)).then_some(Lock::Folded)
    }

    /// Where to refine: the centroids of the triangles that lock the shape `x`, per piece.
    fn marks(self, mesh: &SheetMesh, x: &[V3]) -> [Vec<[f64; 2]>; 2] {
        match self {
            Lock::Stretched => strained_centroids(mesh, x),
            Lock::Folded => bent_centroids(mesh, x, BEND_MARK),
        }
    }
}

/// The `sheet` (a mesh, its shell and the shape `relaxed` on it) refined where it locks
/// ([`Lock`], see the module docs), within `budget` steps in all (those `relaxed` took
/// included). Returns the mesh, shell and shape of the answer: the first round that converged;
/// else, for a stretched sheet, the least strained of all; else `sheet` itself (a fold that
/// refinement does not remove is the form's crease, reported as such). A folded sheet is thinned
/// again from the stage it folded at, and when no round converges, from [`RESTART_KB`] (see the
/// module docs). The finer meshes' shells are `path`'s (with its contact, [`Path::shell`]). One
/// stage is reported per round of the first pass.
pub fn unlock(pieces: &SeamPieces, saddles: &[usize], path: Path, sheet: (SheetMesh, Shell, Relaxed), budget: usize, report: &mut Reporter) -> (SheetMesh, Shell, Relaxed) {
    let (mesh, shell, relaxed) = sheet;
    let Some(lock) = Lock::of(pieces, &mesh, &shell, &relaxed) else { return (mesh, shell, relaxed) };
    let from = if lock == Lock::Folded { relaxed.stage } else { RESTART_KB };
    let refiner = Refiner { pieces, saddles, path, lock, origin: (mesh.clone(), relaxed.x.clone()), budget };
    let mut steps = relaxed.steps;
    let mut best = (mesh, shell, relaxed);
    refiner.rounds(from, &mut best, &mut steps, report);
    if !best.2.converged && RESTART_KB > from {
        // Only a folded sheet starts below RESTART_KB: its second pass, from a thicker sheet.
        let mut quiet = |_| {};
        refiner.rounds(RESTART_KB, &mut best, &mut steps, &mut Reporter::new(&mut quiet, ROUNDS, false));
    }
    best.2.steps = steps;
    best
}

/// What the rounds of refinement of one locked sheet share ([`unlock`]): the pieces, the seam
/// samples with saddle rows, the path (its contact), the lock, the unrefined mesh and shape, and
/// the step budget.
struct Refiner<'a> {
    pieces: &'a SeamPieces,
    saddles: &'a [usize],
    path: Path,
    lock: Lock,
    origin: (SheetMesh, Vec<V3>),
    budget: usize,
}

impl Refiner<'_> {
    /// Up to [`ROUNDS`] rounds of refinement of the unrefined shape, each thinned from the
    /// bending weight `from`; `best` is replaced by a round that converges or, for a stretched
    /// sheet, that is less strained. `steps` counts the steps taken so far.
    fn rounds(&self, from: f64, best: &mut (SheetMesh, Shell, Relaxed), steps: &mut usize, report: &mut Reporter) {
        let (pieces, lock) = (self.pieces, self.lock);
        let radius = pieces.flat[0].perimeter / std::f64::consts::TAU;
        let thinner: Vec<f64> = SCHEDULE.iter().copied().filter(|&b| b <= from).collect();
        let mut extra: [Vec<[f64; 2]>; 2] = [Vec::new(), Vec::new()];
        let (mut mesh_now, mut x) = self.origin.clone();
        for _ in 0..ROUNDS {
            let marked = lock.marks(&mesh_now, &x);
            let added = marked[0].len() + marked[1].len();
            if added == 0 || added as f64 > GROWTH * mesh_now.vertex_count() as f64 || *steps >= self.budget {
                break;
            }
            for p in 0..2 {
                extra[p].extend_from_slice(&marked[p]);
            }
            let Some(finer) = SheetMesh::refined(pieces, super::INTERIOR_EDGE, self.saddles, &extra) else { break };
            let Some(start) = refine::carry(&mesh_now, &x, &finer) else { break };
            let mut shell = self.path.shell(pieces, &finer);
            let faces: Vec<[usize; 3]> = finer.faces.iter().flatten().copied().collect();
            let mut quiet = |_| {};
            let mut r = thin(&mut shell, start, radius, self.budget - *steps, &thinner, &faces, &mut Reporter::new(&mut quiet, thinner.len(), false));
            *steps += r.steps;
            r.steps = *steps;
            x = r.x.clone();
            mesh_now = finer;
            if r.converged || (lock == Lock::Stretched && r.max_strain < best.2.max_strain) {
                *best = (mesh_now.clone(), shell, r);
            }
            report.stage(best.2.max_strain);
            if best.2.converged {
                break;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit square of two triangles in each piece, vertex 3 pulled out along the diagonal
    /// through it: only the triangles at vertex 3 are marked, at their flat centroids, and only
    /// once the pull strains an edge beyond [`MARK`] of the target.
    #[test]
    fn marks_the_triangles_of_a_stretched_edge_at_their_centroids() {
        let square = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let mesh = SheetMesh { n: 4, faces: [vec![[0, 1, 2], [0, 2, 3]], vec![[0, 2, 1], [0, 3, 2]]], flat: [square.clone(), square.clone()] };
        let lift = |pull: f64| -> Vec<V3> {
            let mut x: Vec<V3> = square.iter().map(|q| [q[0], q[1], 0.0]).collect();
            // Along the diagonal from vertex 1: the edges 0–3 and 2–3 grow by about pull/√2.
            x[3] = [-pull / 2f64.sqrt(), 1.0 + pull / 2f64.sqrt(), 0.0];
            x
        };
        assert_eq!(strained_centroids(&mesh, &lift(0.0)), [Vec::<[f64; 2]>::new(), Vec::new()], "an isometric shape marks nothing");
        assert_eq!(strained_centroids(&mesh, &lift(0.4 * MARK * STRAIN_TARGET)), [Vec::<[f64; 2]>::new(), Vec::new()], "a strain below the mark marks nothing");
        let marked = strained_centroids(&mesh, &lift(4.0 * MARK * STRAIN_TARGET));
        let want = [1.0 / 3.0, 2.0 / 3.0];
        for p in 0..2 {
            assert_eq!(marked[p].len(), 1, "piece {p}: wanted only the triangle 0–2–3, got {:?}", marked[p]);
            let got = marked[p][0];
            assert!((got[0] - want[0]).abs() < 1e-15 && (got[1] - want[1]).abs() < 1e-15, "piece {p}: wanted the centroid {want:?}, got {got:?}");
        }
    }

    /// Two triangles hinged on the diagonal 0–2 of a unit square (both pieces are the same two
    /// triangles on the same vertices), vertex 3 turned about it by `turn`: both triangles are
    /// marked in each piece, at their flat centroids, exactly when the turn exceeds the mark.
    #[test]
    fn marks_both_triangles_of_a_hinge_bent_beyond_the_mark() {
        let square = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let mesh = SheetMesh { n: 4, faces: [vec![[0, 1, 2], [0, 2, 3]], vec![[0, 2, 1], [0, 3, 2]]], flat: [square.clone(), square.clone()] };
        // Vertex 3 rotated by `turn` about the axis through 0 and 2: it keeps its distances to
        // both, so the mesh stays isometric.
        let bent = |turn: f64| -> Vec<V3> {
        let (c, s) = (turn.cos(), turn.sin());
            let (mid, off) = ([0.5, 0.5, 0.0], [-0.5, 0.5, 0.0]);
            let axis_normal = [0.0, 0.0, 1.0];
            let p = [0, 1, 2].map(|a| mid[a] + c * off[a] + s * 0.5f64.sqrt() * axis_normal[a]);
            vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], p]
        };
        let below = bent_centroids(&mesh, &bent(BEND_MARK - 0.01), BEND_MARK);
        assert!(below[0].is_empty() && below[1].is_empty(), "a bend below the mark marks nothing, got {below:?}");
        let above = bent_centroids(&mesh, &bent(BEND_MARK + 0.01), BEND_MARK);
        let want = [[1.0 / 3.0, 2.0 / 3.0], [2.0 / 3.0, 1.0 / 3.0]];
        for p in 0..2 {
            let mut got = above[p].clone();
            got.sort_by(|a, b| a[0].total_cmp(&b[0]));
            assert_eq!(got.len(), 2, "piece {p}: wanted both triangles of the hinge, got {got:?}");
            for (g, w) in got.iter().zip(&want) {
                assert!((g[0] - w[0]).abs() < 1e-15 && (g[1] - w[1]).abs() < 1e-15, "piece {p}: wanted the centroid {w:?}, got {g:?}");
            }
        }
    }
}
