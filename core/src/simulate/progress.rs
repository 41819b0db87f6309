//! Progress of a solve, for a host that shows it (the panel's "solving… 40 %"): the sheet path
//! of a non-convex pair takes up to a few seconds, through a fixed sequence of stages (the
//! convex path's first pass, the homotopy's steps, the thinning's bending weights), so the share
//! of stages done is an honest measure. A solve that stops early (converged, or stalled) simply
//! ends before `done` reaches `total`.

/// One stage of a solve finished: `done` of at most `total` stages, and the largest edge strain
/// of the shape it ended at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    pub done: usize,
    pub total: usize,
    pub max_strain: f64,
}

/// Counts stages for an observer.
pub struct Reporter<'a> {
    observe: &'a mut dyn FnMut(Progress),
    done: usize,
    total: usize,
}

impl<'a> Reporter<'a> {
    pub fn new(observe: &'a mut dyn FnMut(Progress), total: usize) -> Self {
        Reporter { observe, done: 0, total }
    }

    /// One stage done, ending at strain `max_strain`.
    pub fn stage(&mut self, max_strain: f64) {
        self.done = (self.done + 1).min(self.total);
        (self.observe)(Progress { done: self.done, total: self.total, max_strain });
    }

    /// `k` stages that this solve does not run (e.g. a homotopy without a twin), counted as done
    /// without a report.
    pub fn skip(&mut self, k: usize) {
        self.done = (self.done + k).min(self.total);
    }
}
