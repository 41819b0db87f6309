//! Other paths for a sheet that ends far off: the homotopy followed again at other bending
//! weights.
//!
//! The homotopy from convex twins ([`super::follow`]) is followed as a thick sheet
//! ([`super::HOMOTOPY_KB`]). On most pairs that path reaches an equilibrium the thinning takes to
//! the form. On some it ends far off: strained by percents, or with the sheets through each
//! other. The kidney with a congruent copy at 1/16 of its perimeter is an example: its homotopy
//! holds 221,000 mm³ to the last blend and then, relaxed, collapses to 100,000 through itself.
//! The same pairs end in the same state from every twin share ([`super::TWIN_CIRCLE_SHARES`])
//! and with 4, 8 or 16 blends, but not from another thickness:
//!
//! - at `kb/R²` = 1e-5 the kidney with its copy at 1/16 converges (221,639 mm³);
//! - at 1e-3 the drawn heart with its copy at 3/16 and 13/16 ends isometric and uncrossed
//!   (creased by 103° and 119°), where it had ended 8.5 % stretched through itself.
//!
//! So a sheet that ends far off ([`far_off`]) is followed again at the weights of [`KB`], in
//! order, until one ends sound: converged, or isometric and uncrossed (creased); then, while the
//! best still passes through itself, with the sheets touching ([`TOUCH`], [`super::contact`]).
//! The best of all the attempts is the answer ([`Attempt::grade`]).
//!
//! *Order and stop.* Of the 18 far-off pairs of 312 (stop 38's set: random pairs of two blobs,
//! and six drawings with their copies and mirror images at six offsets, 256 seam vertices,
//! native), the thick weight 1e-3 is the one that ends sound on five: converged on the smooth
//! heart with its mirror image at 1/16, creased and less bent than at 1e-5 on the drawn heart
//! with its copy and mirror image at 3/16 and 13/16 (discrete bending energy 314 against 540,
//! 346 against 439). Tried first, and ending the search there, it spares those pairs the other
//! attempt: 0.2–0.8 s native (the drawn heart with its copy at 13/16: 1.27 → 0.49 s). Only the
//! kidney with its copy at 1/16, which converges at 1e-5 alone, pays for the other order (0.68 →
//! 0.94 s). On the other 12 both weights are tried either way, and every pair keeps its answer.
//!
//! A third weight, 1e-6, was measured and not kept. With it, the kidney with its mirror image at
//! 5/16 and with its copy at 13/16 end isometric and uncrossed, creased by 96° and 124°. But the
//! smooth heart with its copy or mirror image at 5/16 and 11/16 then ends nearly flat (about
//! 2,200 mm³ against 36,000–45,000) at 1.3–1.5 % strain, which outranks its 4–5 % on strain, and
//! far-off pairs take up to 3.5 s native.

use super::glued::SheetMesh;
use super::shell::Shell;
use super::{adapt, follow, FirstStart, Path, Relaxed, Touch, FAR_ABOVE, STRAIN_TARGET};
use crate::simulate::checks::{faces_cross, thickness};
use crate::simulate::progress::Reporter;
use crate::simulate::seam::SeamPieces;

/// The bending weights (`kb / R²`) a far-off sheet's homotopy is followed at again, in order.
pub const KB: [f64; 2] = [1e-3, 1e-5];

/// The bending weight of the last paths, with self-contact ([`super::contact`]), tried when
/// the best answer still crosses itself. With contact at the first path's weight
/// ([`super::HOMOTOPY_KB`]) the smooth heart with its copy ended 26–30 % strained, through
/// itself; at this one it ends sound.
pub const CONTACT_KB: f64 = 1e-3;

/// The contacts of the last paths, in order, each tried while the best answer still crosses
/// itself. On stop 38's set (the far-off pairs, 256 seam vertices, native):
///
/// - faces only: the smooth heart with its copy at 3/16 and 13/16 and with its mirror image at
///   3/16 end isometric and uncrossed (creased), where they had ended 4.2–4.8 % stretched
///   through themselves; on faces and seam they end 1.01e-3 and 1.07e-3 strained instead;
/// - faces and seam: the kidney with its copy at 13/16 (1.95 % through itself) and the smooth
///   heart with its copy at 1/16 (4.95 %) converge.
pub const TOUCH: [Touch; 2] = [Touch::Faces, Touch::FacesAndSeam];

/// Largest strain of the best answer for which the touching paths ([`TOUCH`]) are tried. Every
/// sheet they have freed was strained by a few percent through itself before them (the kidney
/// with its copy at 13/16: 1.95e-2; the smooth heart with its copy at 1/16, 3/16 and 13/16 and
/// its mirror image at 3/16: 4.2–4.95e-2, stop 38's set). A sheet strained by tens of percent
/// is crumpled, not squeezed: contact does not unfold it, and its vertex–face candidates grow
/// with the crumpling. A fuzz pair (a rounded rectangle with a spiky blob, 128 seam vertices)
/// ended 231 % strained after 59 s native, 46 % of it in the contact terms.
pub const TOUCH_BELOW: f64 = super::CRUMPLED;

/// One path's answer: the mesh it ended on (refined where it was held, [`adapt`]), its shell and
/// its shape, and whether the sheets cross.
pub struct Attempt {
    pub mesh: SheetMesh,
    pub shell: Shell,
    pub relaxed: Relaxed,
    pub crossing: bool,
}

impl Attempt {
    /// How good an answer is, best first: converged; isometric and uncrossed (creased); uncrossed
    /// but stretched; through itself. Within the first two the least bending energy
    /// ([`Attempt::bending`]) is better, the least-bending equilibrium issue 14 asks for; within
    /// the last two, the lesser strain.
    pub fn grade(&self) -> (u8, f64) {
        let r = &self.relaxed;
        let isometric = r.max_strain <= STRAIN_TARGET;
        match (r.converged, isometric && !self.crossing, self.crossing) {
            (true, _, _) => (0, self.bending()),
            (false, true, _) => (1, self.bending()),
            (false, false, false) => (2, r.max_strain),
            (false, false, true) => (3, r.max_strain),
        }
    }

    /// Converged, or isometric and uncrossed (creased): an answer that keeps its flat lengths,
    /// which a far-off sheet's search ends at ([`others`]).
    pub fn sound(&self) -> bool {
        self.grade().0 <= 1
    }

    /// Sound, or uncrossed and as isometric as seam samples whose floor is `floor` allow
    /// ([`crate::simulate::stats::strain_allowed`]): where the samples' chords on the two pieces
    /// differ by more than the target, no answer on them is isometric, and this is the best.
    pub fn sound_on(&self, floor: f64) -> bool {
        self.sound() || (!self.crossing && self.relaxed.max_strain <= crate::simulate::stats::strain_allowed(floor))
    }

    /// The discrete shells' bending energy of the shape, `Σ w θ²` over the hinges (weight
    /// `3|e|²/A`, Grinspun et al. 2003): the shell's energy at unit bending weight less its
    /// membrane part.
    pub fn bending(&self) -> f64 {
        self.shell.cost(&self.relaxed.x, 1.0) - self.shell.cost(&self.relaxed.x, 0.0)
    }
}

/// Whether an answer is far off: not converged, and strained beyond [`FAR_ABOVE`] times the
/// target, through itself, or flat ([`FLAT`]).
pub fn far_off(a: &Attempt) -> bool {
    !a.relaxed.converged && (a.relaxed.max_strain > FAR_ABOVE * STRAIN_TARGET || a.crossing || thickness(&a.relaxed.x, a.mesh.n) < FLAT)
}

/// Thickness ([`thickness`], relative to the size) below which an unconverged sheet is flat: the
/// doubly covered sheet, which is the form only of congruent pieces glued congruently (where it
/// is isometric and converges). Flat and strained, it is a symmetric equilibrium: the membrane's
/// forces lie in its plane, so no thinner stage lifts it out. Near such a gluing the thick
/// homotopy ([`super::HOMOTOPY_KB`]) flattens the twins' thin pillow. The five lobes with their
/// copy at 6/64 of the perimeter (a slider position; 5/64 and 7/64 converge) ended flat and
/// 3.5e-3 strained, and so did the Pebble and the five lobes with their mirror images 0.2 mm off
/// (3.1e-3, 4.3e-3; thickness 3e-8–4e-7). The thinner path of [`KB`] keeps the pillow: all
/// three converge (19,733, 13,536 and 22,336 mm³). The forms that converge 1 mm off have
/// thickness 5e-2–8e-2. Of 512 slider positions (kidney, Pebble, five lobes and blob with their
/// copies and mirror images at k/64) no other changes.
pub const FLAT: f64 = 1e-4;

/// The homotopy along `path` and the thinning ([`follow`]), refined where the mesh holds the
/// sheet ([`adapt::unlock`]); the first path's homotopy from `first` when given ([`follow`]).
/// `None` when no twin pair can be built and solved.
pub fn attempt(pieces: &SeamPieces, mesh: &SheetMesh, saddles: &[usize], path: Path, first: Option<&mut FirstStart>, budget: usize, report: &mut Reporter) -> Option<Attempt> {
    let (shell, r) = follow(pieces, mesh, !saddles.is_empty(), path, first, budget, report)?;
    let (mesh, shell, relaxed) = adapt::unlock(pieces, saddles, path, (mesh.clone(), shell, r), budget, report);
    // A converged answer is sound ([`super::finish::sound`]), so it does not cross: only the
    // others are tested, not every pair's answer.
    let crossing = !relaxed.converged && faces_cross(&relaxed.x, &mesh.faces.iter().flatten().copied().collect::<Vec<_>>());
    Some(Attempt { mesh, shell, relaxed, crossing })
}

/// `first`, or when it is far off ([`far_off`]) the best ([`Attempt::grade`]) of it and the
/// attempts at the weights of [`KB`], tried in order until one is sound ([`Attempt::sound`]),
/// then while the best still crosses itself, strained by at most [`TOUCH_BELOW`], at
/// [`CONTACT_KB`] with the contacts of [`TOUCH`], within `budget` steps in all. The answer's
/// `steps` count every attempt's. One stage is reported per attempt tried, at the best answer's
/// strain.
pub fn others(pieces: &SeamPieces, mesh: &SheetMesh, saddles: &[usize], first: Attempt, budget: usize, report: &mut Reporter) -> Attempt {
    if !far_off(&first) {
        return first;
    }
    let mut spent = first.relaxed.steps;
    let mut best = first;
    let paths = KB.iter().map(|&kb| Path::plain(kb)).chain(TOUCH.iter().map(|&touch| Path { kb: CONTACT_KB, touch }));
    for path in paths {
        if spent >= budget || best.sound() || (path.touch != Touch::Free && (!best.crossing || best.relaxed.max_strain > TOUCH_BELOW)) {
            break;
        }
        let mut quiet = |_| {};
        let Some(a) = attempt(pieces, mesh, saddles, path, None, budget - spent, &mut Reporter::new(&mut quiet, super::STAGES, false)) else { break };
        spent += a.relaxed.steps;
        if a.grade() < best.grade() {
            best = a;
        }
        report.stage(best.relaxed.max_strain);
    }
    best.relaxed.steps = spent;
    best
}
