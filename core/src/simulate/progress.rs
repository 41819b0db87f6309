//! Progress of a solve, for a host that shows it (the panel's "solving… 40 %"): the sheet path
//! of a non-convex pair takes up to a few seconds, through a fixed sequence of stages (the
//! convex path's first pass, the homotopy's steps, the thinning's bending weights), so the share
//! of stages done is an honest measure. A solve that stops early (converged, or stalled) simply
//! ends before `done` reaches `total`.
//!
//! *Interim form.* A request of 256 or more seam samples is solved on its level of 128 to 255
//! ([`crate::simulate::sheet::level`]) and then refined at the seam. When the level converges,
//! its answer is already a D-form that keeps every promise at the level's samples, and the
//! refinement that follows can take four times as long (the kidney with its mirror image at 6/16
//! and 15/16 of its perimeter, 256 seam vertices, native: the level's form at 0.41 and 0.43 s,
//! the answer at 1.76 and 2.01 s; over the 27 kidney pairs with a copy or mirror image that have
//! one, the volumes are 0.02–0.2 % apart, and 1.0 and 1.4 % where the refinement fell back to the
//! requested samples' own path). An observer that asks for it ([`Reporter::new`]'s `interims`)
//! gets that form once, in a report of its own ([`Progress::interim`]), in the same place and
//! units as the answer, so a slider can show a form while the finer one is being solved.

use super::Simulation;

/// One stage of a solve finished: `done` of at most `total` stages, and the largest edge strain
/// of the shape it ended at; or, with `interim`, a converged form at coarser seam samples than
/// asked (`done` repeats the last report's: no stage ended).
#[derive(Debug, Clone)]
pub struct Progress {
    pub done: usize,
    pub total: usize,
    pub max_strain: f64,
    /// The level's converged form (see the module doc), at most once per solve.
    pub interim: Option<Box<Simulation>>,
}

/// Counts stages for an observer.
pub struct Reporter<'a> {
    observe: &'a mut dyn FnMut(Progress),
    done: usize,
    total: usize,
    interims: bool,
}

impl<'a> Reporter<'a> {
    /// Reports to `observe` out of `total` stages; `interims`: whether it wants the interim form
    /// (building it costs a pass over the level's mesh).
    pub fn new(observe: &'a mut dyn FnMut(Progress), total: usize, interims: bool) -> Self {
        Reporter { observe, done: 0, total, interims }
    }

    /// One stage done, ending at strain `max_strain`.
    pub fn stage(&mut self, max_strain: f64) {
        self.done = (self.done + 1).min(self.total);
        (self.observe)(Progress { done: self.done, total: self.total, max_strain, interim: None });
    }

    /// A converged form at coarser samples, built by `form` only when the observer wants it; it
    /// is then told at once. No stage is counted.
    pub fn interim(&mut self, form: impl FnOnce() -> Simulation) {
        if self.interims {
            let sim = form();
            (self.observe)(Progress { done: self.done, total: self.total, max_strain: sim.stats.max_strain, interim: Some(Box::new(sim)) });
            self.interims = false;
        }
    }

    /// `k` stages that this solve does not run (e.g. a homotopy without a twin), counted as done
    /// without a report.
    pub fn skip(&mut self, k: usize) {
        self.done = (self.done + k).min(self.total);
    }
}
