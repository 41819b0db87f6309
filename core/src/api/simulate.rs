//! `simulate(pieces, options)` of the contract: DTOs and their conversions. The method and
//! every figure's meaning are in [`crate::simulate`].

use super::path::PathDto;
use crate::error::{Error, Result};
use crate::simulate::progress::Progress;
use crate::simulate::{self, Crease, SimulateOptions, Simulation, Stats};
use serde::{Deserialize, Serialize};

/// `options` of `simulate`; every field optional.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct SimulateOptionsDto {
    /// Arc length by which B's start is shifted along B (B walked clockwise), input units.
    #[serde(default)]
    pub offset: Option<f64>,
    /// Number of seam vertices (default 256).
    #[serde(default)]
    pub resolution: Option<f64>,
    /// A previous result's `vertices`, to start from (live sliders).
    #[serde(default)]
    pub warm: Option<Vec<[f64; 3]>>,
    /// Cap on solver steps (default [`crate::simulate::options::DEFAULT_MAX_ITERATIONS`]).
    #[serde(default)]
    pub max_iterations: Option<f64>,
}

/// `stats` of the result (see [`crate::simulate::Stats`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct StatsDto {
    pub max_strain: f64,
    pub mean_strain: f64,
    /// The least `maxStrain` any mesh on these seam samples can have (see
    /// [`crate::simulate::Stats::strain_floor`]); above 1e-3 no answer at this resolution can
    /// be `converged` (`shortfall` `"sampling"`).
    #[serde(default)]
    pub strain_floor: f64,
    pub seam_gap: f64,
    pub area_error: f64,
    pub angle_defect_sum: f64,
    pub interior_defect_sum: f64,
    pub reflex_edges: usize,
    pub volume: f64,
    pub area: f64,
    pub iterations: usize,
    pub flips: usize,
    pub converged: bool,
    pub ms: f64,
    /// Largest bend inside a piece, radians (see [`crate::simulate::Stats::max_bend`]).
    pub max_bend: f64,
    /// `null` when converged, else why not: `"sampling"`, `"stretch"`, `"crossing"`, `"fold"` or
    /// `"unsettled"` ([`crate::simulate::Shortfall`]).
    pub shortfall: Option<String>,
    /// `true` when one piece is a circle and the other is not convex: then the seam offset does
    /// not change the form (every offset gives this mesh, the circle's `flat` turned), see
    /// [`crate::simulate::round`]. Results serialized before it was reported have none.
    #[serde(default)]
    pub offset_free: bool,
}

impl From<&Stats> for StatsDto {
    fn from(s: &Stats) -> Self {
        StatsDto {
            max_strain: s.max_strain,
            mean_strain: s.mean_strain,
            strain_floor: s.strain_floor,
            seam_gap: s.seam_gap,
            area_error: s.area_error,
            angle_defect_sum: s.angle_defect_sum,
            interior_defect_sum: s.interior_defect_sum,
            reflex_edges: s.reflex_edges,
            volume: s.volume,
            area: s.area,
            iterations: s.iterations,
            flips: s.flips,
            converged: s.converged,
            ms: s.ms,
            max_bend: s.max_bend,
            shortfall: s.shortfall.map(|f| f.name().to_string()),
            offset_free: s.offset_free,
        }
    }
}

/// One of `creases`: an interior edge of a non-convex pair's piece bent by more than 90°
/// (see [`crate::simulate::Crease`]): `piece` 0 (A) or 1 (B), `vertices` the edge's two
/// indices into `vertices`, `bend` radians.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CreaseDto {
    pub piece: u8,
    pub vertices: [usize; 2],
    pub bend: f64,
}

impl From<&Crease> for CreaseDto {
    fn from(c: &Crease) -> Self {
        CreaseDto { piece: c.piece, vertices: c.vertices, bend: c.bend }
    }
}

/// `{ vertices, triangles, piece, seam, flat, creases, stats }`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SimulateDto {
    pub vertices: Vec<[f64; 3]>,
    pub triangles: Vec<[usize; 3]>,
    pub piece: Vec<u8>,
    pub seam: Vec<usize>,
    /// `flat[t]`: triangle `t`'s corners on its own flat piece, input coordinates, the corner
    /// order of `triangles[t]` (see [`crate::simulate::Simulation::flat`]).
    pub flat: Vec<[[f64; 2]; 3]>,
    /// Where a non-convex pair's answer creases (`stats.shortfall` `"fold"`): empty otherwise.
    /// Results serialized before creases were reported have none, hence the default.
    #[serde(default)]
    pub creases: Vec<CreaseDto>,
    pub stats: StatsDto,
}

impl From<&Simulation> for SimulateDto {
    fn from(s: &Simulation) -> Self {
        SimulateDto {
            vertices: s.vertices.clone(),
            triangles: s.triangles.clone(),
            piece: s.piece.clone(),
            seam: s.seam.clone(),
            flat: s.flat.clone(),
            creases: s.creases.iter().map(CreaseDto::from).collect(),
            stats: StatsDto::from(&s.stats),
        }
    }
}

impl SimulateOptionsDto {
    /// Checks the options (ranges, finiteness) and fills defaults.
    pub fn check(&self) -> Result<SimulateOptions> {
        SimulateOptions::new(self.offset, self.resolution, self.warm.clone(), self.max_iterations)
    }
}

/// `simulate(pieces, options)`: the 3D D-form of two closed pieces of equal perimeter.
pub fn simulate(pieces: &[PathDto], options: &SimulateOptionsDto) -> Result<SimulateDto> {
    simulate_observed(pieces, options, &mut |_| {})
}

/// One progress report of `simulateWithProgress` (see [`crate::simulate::progress`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct ProgressDto {
    pub done: usize,
    pub total: usize,
    pub max_strain: f64,
    /// Once per solve at most, in a report of its own (`done` repeats the last report's): a
    /// converged form at coarser seam samples than asked, shaped as `simulate`'s result, to show
    /// while the asked one is solved. Absent from every other report.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub interim: Option<Box<SimulateDto>>,
}

impl From<Progress> for ProgressDto {
    fn from(p: Progress) -> Self {
        ProgressDto { done: p.done, total: p.total, max_strain: p.max_strain, interim: p.interim.map(|s| Box::new(SimulateDto::from(&*s))) }
    }
}

/// [`simulate`] telling `observe` of each stage done (the same result).
pub fn simulate_observed(pieces: &[PathDto], options: &SimulateOptionsDto, observe: &mut dyn FnMut(ProgressDto)) -> Result<SimulateDto> {
    if pieces.len() != 2 {
        return Err(Error::PieceCount { wanted: "exactly two pieces to simulate", got: pieces.len() });
    }
    let a = pieces[0].to_contour(0)?;
    let b = pieces[1].to_contour(1)?;
    let options = options.check()?;
    Ok(SimulateDto::from(&simulate::simulate_observed(&a, &b, &options, &mut |p| observe(p.into()))?))
}
