//! Refinement where the thin sheet locks: the mesh made finer at the triangles whose edges stay
//! stretched, and the sheet thinned again on it.
//!
//! A linear triangle held to 1e-3 strain bends isometrically only about its own edges
//! (membrane locking, see [`super`]): where the developable sheet must bend along a line the
//! mesh has no edge for, a few edges stay strained at every bending weight. The saddle rows
//! ([`super::saddle`]) give the mesh such edges where one piece's bay meets the other; where
//! both pieces are concave at one place (two organic blobs whose bays meet, a piece with its
//! mirror image at a small offset) they do not suffice: the kidney with its mirror image at 1/16
//! of its perimeter ended 3.4e-3 strained, the blob with its mirror image 3.1e-3, with no fold
//! and no crossing. A uniformly finer mesh frees such pairs at many times the cost (2 seam steps
//! instead of 5: 12 times the time).
//!
//! So the refinement is a-posteriori and local, as in adaptive finite elements: every triangle
//! with an edge strained beyond [`MARK`] of the target gets a vertex at its centroid, both pieces
//! are meshed again with those vertices kept (the Delaunay refinement grades the triangles
//! around them), the sheet's shape is carried onto the new mesh ([`super::refine::carry`]) and
//! thinned again from [`RESTART_KB`]; up to [`ROUNDS`] rounds, each adding the sheet's strained
//! triangles of the round before, while they stay few ([`GROWTH`]).
//!
//! Measured at 256 seam vertices, native, on the 11 pairs that ended stretched by less than 2e-2
//! among 240 random pairs of two blobs (the survey's, seeds 11, 23, 5, 31, 47 and 59) and the
//! blob, kidney, five lobes, Pebble, drawn heart and smooth heart each with its copy and with its
//! mirror image at 1, 3, 5, 8, 11 and 13/16: 10 converge, in 0.5–1.6 s instead of 0.3–0.6 (the
//! kidney with its mirror image at 5/16, 1.5e-2 strained with crossing sheets, has too many
//! strained triangles to be a lock). Their volumes move by 0.03–1.1 %: the same equilibrium,
//! now isometric. No other pair of those 312 is touched (each converged, folded or ended more
//! strained). Tried and not kept: thinning again from the first stage (1e-5; the blob with its
//! mirror image then moved by 3.3 %), or from 1e-7 (the blob with its mirror image stayed
//! locked); marking at the target itself (8 of 11) or a quarter of it (8); two rounds (9).

use super::glued::SheetMesh;
use super::shell::Shell;
use super::{refine, thin, Relaxed, SCHEDULE, STRAIN_TARGET};
use crate::simulate::progress::Reporter;
use crate::simulate::seam::SeamPieces;
use crate::simulate::vec3::{norm, sub, V3};

/// Rounds of refinement at most, each one thinning.
pub const ROUNDS: usize = 3;

/// A triangle is refined when one of its edges is strained beyond `MARK` times
/// [`STRAIN_TARGET`]: the edges just below the target lock the sheet as well.
pub const MARK: f64 = 0.5;

/// The bending weight (`kb / R²`, [`SCHEDULE`]) the thinning starts again from on the finer
/// mesh: thin enough to keep the locked sheet's equilibrium, thick enough to let it move.
pub const RESTART_KB: f64 = 1e-6;

/// Largest strain (over [`STRAIN_TARGET`]) of a sheet that is refined: one strained by percents
/// is not locked but on a wrong equilibrium or through itself (the bound of
/// [`super::PATIENT_ABOVE`]).
pub const BELOW: f64 = super::PATIENT_ABOVE;

/// Largest share of the mesh's vertices a round may add: more strained triangles than that are
/// no local lock.
pub const GROWTH: f64 = 0.4;

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
            .map(|t| {
                let c = t.map(|v| mesh.flat[p][v]);
                [(c[0][0] + c[1][0] + c[2][0]) / 3.0, (c[0][1] + c[1][1] + c[2][1]) / 3.0]
            })
            .collect()
    })
}

/// The sheet `relaxed` on `mesh` refined where it stays strained (see the module docs), within
/// `budget` steps in all (those `relaxed` took included). Returns the mesh, shell and shape of
/// the answer: the first round that converged, else the least strained of all, `relaxed`'s own
/// when no round was tried or none did better. One stage is reported per round.
pub fn unlock(pieces: &SeamPieces, saddles: &[usize], mesh: SheetMesh, shell: Shell, relaxed: Relaxed, budget: usize, report: &mut Reporter) -> (SheetMesh, Shell, Relaxed) {
    let mut best = (mesh, shell, relaxed);
    if best.2.converged || best.2.max_strain > BELOW * STRAIN_TARGET || best.1.strain_floor() > STRAIN_TARGET {
        return best;
    }
    let radius = pieces.flat[0].perimeter / std::f64::consts::TAU;
    let thinner: Vec<f64> = SCHEDULE.iter().copied().filter(|&b| b <= RESTART_KB).collect();
    let mut extra: [Vec<[f64; 2]>; 2] = [Vec::new(), Vec::new()];
    let (mut mesh, mut x, mut steps) = (best.0.clone(), best.2.x.clone(), best.2.steps);
    for _ in 0..ROUNDS {
        let strained = strained_centroids(&mesh, &x);
        let added = strained[0].len() + strained[1].len();
        if added == 0 || added as f64 > GROWTH * mesh.vertex_count() as f64 || steps >= budget {
            break;
        }
        for p in 0..2 {
            extra[p].extend_from_slice(&strained[p]);
        }
        let Some(finer) = SheetMesh::refined(pieces, super::INTERIOR_EDGE, saddles, &extra) else { break };
        let Some(start) = refine::carry(&mesh, &x, &finer) else { break };
        let mut shell = finer.shell();
        let faces: Vec<[usize; 3]> = finer.faces.iter().flatten().copied().collect();
        let mut quiet = |_| {};
        let mut r = thin(&mut shell, start, radius, budget - steps, &thinner, &faces, &mut Reporter::new(&mut quiet, thinner.len()));
        steps += r.steps;
        r.steps = steps;
        x = r.x.clone();
        mesh = finer;
        if r.converged || r.max_strain < best.2.max_strain {
            best = (mesh.clone(), shell, r);
        }
        report.stage(best.2.max_strain);
        if best.2.converged {
            break;
        }
    }
    best.2.steps = steps;
    best
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
}
