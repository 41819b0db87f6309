//! `pathFromSvg(d)` and `pathToSvg(path)`: SVG path data ↔ contract paths (see [`crate::svg`]).

use super::path::{PathDto, PointDto};
use crate::contour::Contour;
use crate::error::Result;
use crate::svg;

/// `pathFromSvg(d)` → one path per subpath, `closed` from `Z`, both handles always written.
pub fn path_from_svg(d: &str) -> Result<Vec<PathDto>> {
    Ok(svg::parse(d)?
        .into_iter()
        .map(|sp| PathDto { closed: sp.closed, points: sp.knots.iter().map(PointDto::from).collect() })
        .collect())
}

/// `pathToSvg(path)` → SVG path data (absolute `M`/`C`/`L`, `Z` when closed, shortest
/// round-trip numbers). Open paths are accepted; at least two finite points are required.
pub fn path_to_svg(path: &PathDto) -> Result<String> {
    // Same checks as every other entry point: at least two points, all finite.
    let c = Contour::new(path.points.iter().map(PointDto::to_knot).collect(), 0)?;
    Ok(svg::write(c.knots(), path.closed))
}
