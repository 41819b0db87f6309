//! `pathFromSvg(d)` and `pathToSvg(path)`: SVG path data ↔ contract paths (see [`crate::svg`]).

use super::path::{arr, pt, PathDto, PointDto};
use crate::contour::{Contour, Knot};
use crate::error::Result;
use crate::svg;

/// `pathFromSvg(d)` → one path per subpath, `closed` from `Z`, both handles always written.
pub fn path_from_svg(d: &str) -> Result<Vec<PathDto>> {
    Ok(svg::parse(d)?
        .into_iter()
        .map(|sp| PathDto {
            closed: sp.closed,
            points: sp
                .knots
                .iter()
                .map(|k| PointDto { anchor: arr(k.anchor), left: Some(arr(k.left)), right: Some(arr(k.right)) })
                .collect(),
        })
        .collect())
}

/// `pathToSvg(path)` → SVG path data (absolute `M`/`C`/`L`, `Z` when closed, shortest
/// round-trip numbers). Open paths are accepted; at least two finite points are required.
pub fn path_to_svg(path: &PathDto) -> Result<String> {
    let knots: Vec<Knot> = path
        .points
        .iter()
        .map(|p| {
            let a = pt(p.anchor);
            Knot { anchor: a, left: p.left.map(pt).unwrap_or(a), right: p.right.map(pt).unwrap_or(a) }
        })
        .collect();
    // Same checks as every other entry point: at least two points, all finite.
    let c = Contour::new(knots, 0)?;
    Ok(svg::write(c.knots(), path.closed))
}
