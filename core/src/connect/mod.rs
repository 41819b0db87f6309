//! `connect`: paired connectors along the seam of two pieces with equal perimeters.
//!
//! The pieces are joined face to face, so walking A counter-clockwise and B clockwise (y-up)
//! traces the seam in step. Connector k sits at arc length `s_k = start_i + (k + slide)·pitch`
//! on piece i along its walk ([`spacing`]), both pieces have the same count and connector k is
//! labelled `k + 1` on both. Kinds: [`stitch`] holes, [`teeth`], [`leaves`], and hybrid (teeth
//! with a hole at every connector). Options and defaults: [`options`].
//!
//! Layout of the annotations (depths measured from the edge along the inward normal, or the
//! outward one when `invert` puts stitch holes outside):
//! - label `k + 1` at depth `inset + 1.5·d` for holes (one hole diameter beyond the hole's inner
//!   edge), `L/2 + p/4` for teeth, `p/4` for leaves (the larger one for hybrid); its `angle`
//!   (degrees, counter-clockwise, y-up) follows the tangent, turned so text never reads upside
//!   down. A text height of about `d` (holes) or `p/4` fits.
//! - the mark: one triangle per piece pointing at connector 0, its tip one text height beyond
//!   the label, as tall as a text height.

pub mod allowance;
pub mod circle;
pub mod edge;
pub mod labels;
pub mod leaves;
pub mod options;
pub mod phase;
pub mod piece;
pub mod sharp;
pub mod spacing;
pub mod stitch;
pub mod teeth;
pub mod warnings;

use crate::contour::Contour;
use crate::error::{len, Error, Result};
use kurbo::{CubicBez, Point};
use options::{Kind, Leaf, RawOptions, Settings};
use piece::Walked;
use spacing::{connector_positions, locate_many, Station};

/// Largest relative difference of the two perimeters that still counts as equal: far below a
/// laser cutter's precision, far above the round-off of SVG coordinates.
pub const PERIMETER_TOLERANCE: f64 = 1e-6;

/// A drawn hole.
#[derive(Debug, Clone, PartialEq)]
pub struct Hole {
    pub center: Point,
    /// Drawn diameter (nominal diameter minus kerf).
    pub diameter: f64,
    pub path: Contour,
}

/// A connector number to print.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    pub text: String,
    pub at: Point,
    /// Degrees, counter-clockwise in a y-up system, in (−90, 90].
    pub angle: f64,
    /// Text height that keeps the label clear of everything else ([`labels`]).
    pub size: f64,
}

/// Everything placed on one piece.
#[derive(Debug, Clone, PartialEq)]
pub struct PieceOut {
    /// The new cut outline in the input's drawing direction, or `None` when the edge is
    /// unchanged (stitch holes only).
    pub outline: Option<Contour>,
    pub holes: Vec<Hole>,
    /// Cuts that receive the other piece's locking leaves (empty otherwise).
    pub slots: Vec<leaves::Slot>,
    /// With a seam allowance: the seam line (the input outline), to score; `outline` is then the
    /// cut line.
    pub seam: Option<Contour>,
    pub labels: Vec<Label>,
    pub marks: Vec<Contour>,
}

/// The result of [`connect`].
#[derive(Debug, Clone, PartialEq)]
pub struct Connection {
    pub count: usize,
    pub pitch: f64,
    /// The slide used: as given, or chosen to keep connectors clear of corners ([`phase`]).
    pub slide: f64,
    pub pieces: [PieceOut; 2],
    pub warnings: Vec<String>,
}

/// Depth of the labels (from the seam line, along the inward normal) and the text height they
/// allow.
fn label_layout(set: &Settings) -> (f64, f64) {
    let holes = (set.inset + 1.5 * set.diameter, set.diameter);
    let teeth = (0.5 * set.length + 0.25 * set.pitch, 0.25 * set.pitch);
    let size = 0.25 * set.pitch;
    match set.kind {
        Kind::Stitch => holes,
        Kind::Teeth => teeth,
        Kind::Leaves if set.leaf == Leaf::Lock => {
            (set.allowance + leaves::lock_heights(set).0 + 0.5 * leaves::SLOT * set.pitch + 0.6 * size, size)
        }
        Kind::Leaves => (0.25 * set.pitch, size),
        Kind::Hybrid => (holes.0.max(teeth.0), set.diameter),
    }
}

/// Labels `k + 1` and the connector-0 mark of one piece, clear of its holes, slots and cut line
/// ([`labels::place`]). `side` is +1 to place them inside. Returns also the labels that fit
/// nowhere (by number).
fn annotate(
    piece: &Walked,
    stations: &[Station],
    centers: &[Point],
    set: &Settings,
    side: f64,
    obstacles: &labels::Obstacles,
) -> (Vec<Label>, Vec<Contour>, Vec<String>) {
    let (depth, size) = label_layout(set);
    let mut boxes = Vec::with_capacity(stations.len());
    let mut out = Vec::with_capacity(stations.len());
    let mut crowded = Vec::new();
    let mut scratch = Vec::new();
    for (k, st) in stations.iter().enumerate() {
        // Toward the connector's hole, when it has one (at a corner along the mitre, `|n|·inset`
        // from the corner; beside a sharp corner on the inset line, [`sharp`]): the label goes
        // as deep as its hole plus the usual gap. Else the mitre direction at unit length.
        let (dir, hole) = match centers.get(k) {
            Some(&c) if (c - st.point).hypot() > 0.0 => ((c - st.point).normalize(), Some((c - st.point).hypot())),
            _ => {
                let n = piece.inward_at(st);
                (n / n.hypot() * side, None)
            }
        };
        let text = (k + 1).to_string();
        let angle = circle::readable_angle(piece.along(dir * side));
        let d = depth + hole.map_or(0.0, |h| h - set.inset);
        let before = hole.map(|h| h - 0.5 * set.diameter);
        let (at, h, clear) =
            labels::place(st.point, dir, angle, text.len(), d, size, before, hole.map(|_| k), &boxes, obstacles, &mut scratch);
        if !clear {
            crowded.push(text.clone());
        }
        boxes.push(labels::LabelBox::new(at, angle, h, text.len()));
        out.push(Label { text, at, angle, size: h });
    }
    let marks = stations
        .first()
        .map(|st| {
            let n = piece.inward_at(st) * side;
            vec![circle::triangle(st.point + n * (depth + size), -n, size)]
        })
        .unwrap_or_default();
    (out, marks, crowded)
}

/// Errors for options that cannot give anything sensible anywhere on the seam.
fn check_feasible(set: &Settings) -> Result<()> {
    if set.kind.has_holes() {
        if set.diameter >= set.pitch {
            return Err(Error::Infeasible {
                reason: format!(
                    "Holes of diameter {} do not fit between connectors {} apart: use fewer connectors or smaller holes.",
                    len(set.diameter), len(set.pitch)
                ),
            });
        }
        let floor = if set.kind == Kind::Hybrid { 0.5 * set.length } else { 0.0 };
        if set.inset - 0.5 * set.diameter <= floor {
            return Err(Error::Infeasible {
                reason: format!(
                    "An inset of {} puts holes of diameter {} across the edge{}: increase the inset or use smaller holes.",
                    len(set.inset),
                    len(set.diameter),
                    if floor > 0.0 { format!(" (the gaps between teeth reach {} in)", len(floor)) } else { String::new() }
                ),
            });
        }
    }
    if set.kind.has_teeth() {
        teeth::check(set)?;
    }
    if set.kind == Kind::Leaves {
        leaves::check(set)?;
    }
    Ok(())
}

/// The slide that keeps connectors clear of the corners of both pieces when the user gave
/// neither a slide nor a start (a connector placed by the user stays where it was put)
/// ([`phase`]); teeth keep the user's (their gaps and teeth both meet corners anyway).
fn auto_slide(pieces: &[Walked; 2], raw: &RawOptions, set: &Settings) -> f64 {
    if raw.slide.is_some() || raw.start.is_some() || set.kind == Kind::Teeth {
        return set.slide;
    }
    let corners = [phase::corners(&pieces[0]), phase::corners(&pieces[1])];
    if corners.iter().all(Vec::is_empty) {
        return set.slide;
    }
    let first = [set.start[0] + set.slide * set.pitch, set.start[1] + set.slide * set.pitch];
    let cs = [&corners[0][..], &corners[1][..]];
    let delta = if set.kind == Kind::Leaves {
        phase::shift(first, cs, set.pitch, (0.5 * leaves::WIDTH * set.pitch).min(0.5 * set.pitch))
    } else {
        let r = 0.5 * set.diameter;
        // As clear as on a straight edge: neighbours a pitch apart, the inset from the edge.
        let good = 0.999 * (set.pitch - 2.0 * r).min(set.inset - r);
        let edges = [warnings::Edge::new(pieces[0].contour.segments().collect()), warnings::Edge::new(pieces[1].contour.segments().collect())];
        let clearance = |delta: f64| {
            let mut worst = f64::INFINITY;
            for (i, w) in pieces.iter().enumerate() {
                // Only connectors within two pitches of a corner can be worse than on a straight edge.
                let near: Vec<f64> = corners[i]
                    .iter()
                    .flat_map(|&c| {
                        let k0 = ((c - first[i] - delta) / set.pitch).floor();
                        (-2..=3).map(move |j| first[i] + delta + (k0 + j as f64) * set.pitch)
                    })
                    .collect();
                let st = locate_many(&w.table, &near);
                let centers = stitch::centers(w, &st, set);
                for (j, c) in centers.iter().enumerate() {
                    let d = edges[i].distance_below(*c, set.inset).unwrap_or(set.inset);
                    // A centre on the wrong side of the edge is worse than any crossing.
                    let d = if edges[i].contains(*c) == !set.invert { d } else { -d - set.inset };
                    worst = worst.min(d - r);
                    if j % 6 != 5 {
                        worst = worst.min((centers[j + 1] - *c).hypot() - 2.0 * r);
                    }
                }
            }
            worst
        };
        phase::best(&phase::candidates(first, cs, set.pitch), set.pitch, good, clearance)
    };
    (set.slide + delta / set.pitch).rem_euclid(1.0)
}

/// Stitch holes without a given slide: a hole on every corner when the spacing allows
/// ([`phase::on_corners`]), as arc lengths from the start.
fn corner_positions(pieces: &[Walked; 2], raw: &RawOptions, set: &Settings) -> Option<Vec<f64>> {
    if raw.slide.is_some() || raw.start.is_some() || set.kind != Kind::Stitch {
        return None;
    }
    let corners = [phase::corners(&pieces[0]), phase::corners(&pieces[1])];
    let square = std::f64::consts::FRAC_PI_2 + 1e-6;
    let sharp = pieces.iter().any(|w| !phase::corners_turning(w, square, std::f64::consts::PI).is_empty());
    if sharp {
        return None;
    }
    phase::on_corners([set.start[0], set.start[1]], [&corners[0], &corners[1]], pieces[0].perimeter(), set.count)
}

/// Places paired connectors on two closed pieces `a` and `b` of equal perimeter.
pub fn connect(a: &Contour, b: &Contour, raw: &RawOptions) -> Result<Connection> {
    let unit = options::unit(raw)?;
    let _unit = crate::error::unit_scope(unit);
    let accuracy = crate::api::accuracy_or_default(raw.accuracy)?;
    options::kind(raw)?;
    let pieces = [Walked::new(a, 0, true, accuracy)?, Walked::new(b, 1, false, accuracy)?];
    let (pa, pb) = (pieces[0].perimeter(), pieces[1].perimeter());
    if (pa - pb).abs() > PERIMETER_TOLERANCE * pa.max(pb) {
        return Err(Error::PerimeterMismatch { a: pa, b: pb });
    }
    let mut set = options::resolve(raw, pa)?;
    check_feasible(&set)?;
    let snapped = corner_positions(&pieces, raw, &set);
    set.slide = match &snapped {
        Some(u) => u[0] / set.pitch,
        None => auto_slide(&pieces, raw, &set),
    };
    let mut warnings = Vec::new();
    let mut outs = Vec::with_capacity(2);
    for w in &pieces {
        let connectors = match &snapped {
            Some(u) => u.iter().map(|&x| set.start[w.index] + x).collect(),
            None => connector_positions(set.start[w.index], set.slide, w.perimeter(), set.count),
        };
        let stations = locate_many(&w.table, &connectors);
        // The cut line with a seam allowance, refused when it crosses itself.
        let cut = if set.allowance > 0.0 {
            let c = allowance::outline(w, &set);
            allowance::check(w, &set, &c.1)?;
            Some(c)
        } else {
            None
        };
        // The new edge, in walking direction, with the connector of every segment.
        let built: Option<(Contour, Vec<CubicBez>, Vec<usize>)> = match set.kind {
            Kind::Stitch => cut,
            Kind::Teeth | Kind::Hybrid => Some(teeth::outline(w, &connectors, &set, (w.index == 0) != set.invert)),
            Kind::Leaves => leaves::outline(w, &connectors, &set).or(cut),
        };
        if let (Some((_, segs, tags)), true) = (&built, set.kind != Kind::Stitch) {
            let what = if set.kind == Kind::Leaves { "leaves" } else { "teeth" };
            let pairs = warnings::collisions(segs, tags, 8);
            // Two connectors' shapes crossing, and one connector's shape crossing itself (folded
            // at a sharp corner), are said apart: a connector named once in each list at most.
            let mut own: Vec<usize> = pairs.iter().filter(|&&(i, j)| i == j).map(|&(i, _)| i).collect();
            own.dedup();
            let each: Vec<String> = pairs.iter().filter(|&&(i, j)| i != j).map(|&(i, j)| format!("{} and {}", i + 1, j + 1)).collect();
            let own: Vec<String> = own.iter().map(|i| (i + 1).to_string()).collect();
            let what_ran = match (each.is_empty(), own.is_empty()) {
                (true, true) => None,
                (false, true) => Some(format!("the {what} of connectors {} run into each other", warnings::list(&each))),
                (true, false) => Some(format!("the {what} of connectors {} cross themselves", warnings::list(&own))),
                (false, false) => Some(format!(
                    "the {what} of connectors {} run into each other and those of connectors {} cross themselves",
                    warnings::list(&each),
                    warnings::list(&own)
                )),
            };
            if let Some(what_ran) = what_ran {
                warnings.push(format!(
                    "On the {}, {what_ran} (a corner or a concave stretch tighter than the {what}): use fewer connectors or shorter {what}, or move them with `slide`.",
                    w.name()
                ));
            }
        }
        let input_ccw = (w.turn > 0.0) != w.reversed;
        let edge_segs: Vec<CubicBez> = match &built {
            Some((_, segs, _)) => segs.clone(),
            None => w.contour.segments().collect(),
        };
        let edge = warnings::Edge::new(edge_segs);
        let mut holes = Vec::new();
        let mut centers = Vec::new();
        let label_side = if set.kind.has_holes() { stitch::side(&set) } else { 1.0 };
        if set.kind.has_holes() {
            centers = stitch::centers(w, &stations, &set);
            warnings.extend(warnings::holes(w.name(), &centers, 0.5 * set.diameter, &edge, !set.invert));
            holes = stitch::holes(&centers, &set, input_ccw);
        }
        let slots = if set.kind == Kind::Leaves { leaves::slots(w, &stations, &set, input_ccw) } else { Vec::new() };
        let discs: Vec<(Point, f64)> = holes.iter().map(|h| (h.center, 0.5 * h.diameter)).collect();
        let slot_boxes: Vec<labels::LabelBox> = slots.iter().map(|s| s.bounds()).collect();
        let obstacles = labels::Obstacles { holes: &discs, slots: &slot_boxes, edge: &edge, inside: label_side > 0.0 };
        let (mut labels, marks, mut crowded) = annotate(w, &stations, &centers, &set, label_side, &obstacles);
        if raw.labels == Some(false) {
            labels.clear();
            crowded.clear();
        }
        if !crowded.is_empty() {
            warnings.push(format!(
                "On the {}, the numbers of connectors {} do not fit clear of the holes, slots and edge even at {} of their size: they are drawn small and may touch; use fewer connectors or switch the numbers off.",
                w.name(),
                warnings::list(&crowded),
                "40 %"
            ));
        }
        let outline = built.map(|(c, _, _)| if w.reversed { c.reversed() } else { c });
        let seam = (set.allowance > 0.0).then(|| if w.reversed { w.contour.reversed() } else { w.contour.clone() });
        outs.push(PieceOut { outline, holes, slots, seam, labels, marks });
    }
    let second = outs.pop().expect("two pieces");
    let first = outs.pop().expect("two pieces");
    Ok(Connection { count: set.count, pitch: set.pitch, slide: set.slide, pieces: [first, second], warnings })
}
