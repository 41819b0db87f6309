//! Options of `simulate`, checked once so the solver can trust them.

use crate::error::{Error, Result};

/// Seam vertices when the user gives none: the benchmark resolution, fine enough that the
/// polyhedron's volume is within ~1e-4 of the smooth D-form for ordinary shapes.
pub const DEFAULT_RESOLUTION: usize = 256;
/// Fewest seam vertices (a coarser polygon is not a useful picture of a D-form).
pub const MIN_RESOLUTION: usize = 8;
/// Most seam vertices (beyond this the solve stops being interactive).
pub const MAX_RESOLUTION: usize = 4096;
/// Most Levenberg–Marquardt steps one solve of a pair takes: room for the convex path's patient
/// second pass after a quick first pass of at most 1,000 steps, and for the sheet path's
/// retries.
pub const START_MAX_ITERATIONS: usize = 5000;
/// Default cap on steps in all: room for a non-convex pair solved from two starts
/// ([`crate::simulate::anchor::retry`]), each of at most [`START_MAX_ITERATIONS`].
pub const DEFAULT_MAX_ITERATIONS: usize = 2 * START_MAX_ITERATIONS;

/// Checked options. `warm` holds a previous result's vertices (seam order), if any.
#[derive(Debug, Clone, PartialEq)]
pub struct SimulateOptions {
    /// Arc length by which B's start is shifted along B (walked clockwise), input units.
    pub offset: f64,
    /// Number of seam vertices.
    pub resolution: usize,
    /// Start from these positions (a previous result's `vertices`).
    pub warm: Option<Vec<[f64; 3]>>,
    /// Cap on solver steps.
    pub max_iterations: usize,
}

impl Default for SimulateOptions {
    fn default() -> Self {
        SimulateOptions { offset: 0.0, resolution: DEFAULT_RESOLUTION, warm: None, max_iterations: DEFAULT_MAX_ITERATIONS }
    }
}

impl SimulateOptions {
    /// Checks raw values (as they come from JSON) and fills defaults.
    pub fn new(
        offset: Option<f64>,
        resolution: Option<f64>,
        warm: Option<Vec<[f64; 3]>>,
        max_iterations: Option<f64>,
    ) -> Result<Self> {
        let offset = offset.unwrap_or(0.0);
        if !offset.is_finite() {
            return Err(Error::Option { name: "offset", reason: format!("must be a finite arc length, got {offset}") });
        }
        let resolution = match resolution {
            None => DEFAULT_RESOLUTION,
            Some(r) if r.is_finite() && r.fract() == 0.0 && (MIN_RESOLUTION as f64..=MAX_RESOLUTION as f64).contains(&r) => {
                r as usize
            }
            Some(r) => {
                return Err(Error::Option {
                    name: "resolution",
                    reason: format!(
                        "must be a whole number of seam vertices from {MIN_RESOLUTION} to {MAX_RESOLUTION} (default {DEFAULT_RESOLUTION}), got {r}"
                    ),
                })
            }
        };
        let max_iterations = match max_iterations {
            None => DEFAULT_MAX_ITERATIONS,
            Some(m) if m.is_finite() && m.fract() == 0.0 && (1.0..=100_000.0).contains(&m) => m as usize,
            Some(m) => {
                return Err(Error::Option {
                    name: "maxIterations",
                    reason: format!("must be a whole number from 1 to 100000 (default {DEFAULT_MAX_ITERATIONS}), got {m}"),
                })
            }
        };
        if let Some(w) = &warm {
            if w.len() < 3 {
                return Err(Error::Option {
                    name: "warm",
                    reason: format!("must be a previous result's vertices (at least 3 points), got {} point(s)", w.len()),
                });
            }
            if let Some(i) = w.iter().position(|p| p.iter().any(|c| !c.is_finite())) {
                return Err(Error::Option {
                    name: "warm",
                    reason: format!("vertex {} has a coordinate that is not a finite number", i + 1),
                });
            }
        }
        Ok(SimulateOptions { offset, resolution, warm, max_iterations })
    }
}
