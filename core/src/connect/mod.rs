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
        let n = piece.inward_at(st);
        let text = (k + 1).to_string();
        let angle = circle::readable_angle(piece.along(n));
        let (at, h, clear) =
            labels::place(st.point, n * side, angle, text.len(), depth, size, &boxes, obstacles, &mut scratch);
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

/// The slide that keeps connectors clear of the corners of both pieces when the user gave none
/// ([`phase`]); teeth keep the user's (their gaps and teeth both meet corners anyway).
fn auto_slide(pieces: &[Walked; 2], raw: &RawOptions, set: &Settings) -> f64 {
    if raw.slide.is_some() || set.kind == Kind::Teeth {
        return set.slide;
    }
    let good = match set.kind {
        Kind::Leaves => 0.5 * leaves::WIDTH * set.pitch,
        _ => set.inset,
    }
    .min(0.5 * set.pitch);
    let corners = [phase::corners(&pieces[0]), phase::corners(&pieces[1])];
    let first = [set.start[0] + set.slide * set.pitch, set.start[1] + set.slide * set.pitch];
    let delta = phase::shift(first, [&corners[0], &corners[1]], set.pitch, good);
    (set.slide + delta / set.pitch).rem_euclid(1.0)
}

/// Places paired connectors on two closed pieces `a` and `b` of equal perimeter.
pub fn connect(a: &Contour, b: &Contour, raw: &RawOptions) -> Result<Connection> {
    let accuracy = crate::api::accuracy_or_default(raw.accuracy)?;
    options::kind(raw)?;
    let pieces = [Walked::new(a, 0, true, accuracy)?, Walked::new(b, 1, false, accuracy)?];
    let (pa, pb) = (pieces[0].perimeter(), pieces[1].perimeter());
    if (pa - pb).abs() > PERIMETER_TOLERANCE * pa.max(pb) {
        return Err(Error::PerimeterMismatch { a: pa, b: pb });
    }
    let mut set = options::resolve(raw, pa)?;
    check_feasible(&set)?;
    set.slide = auto_slide(&pieces, raw, &set);
    let mut warnings = Vec::new();
    let mut outs = Vec::with_capacity(2);
    for w in &pieces {
        let connectors = connector_positions(set.start[w.index], set.slide, w.perimeter(), set.count);
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
            let names: Vec<String> = pairs
                .iter()
                .map(|&(i, j)| if i == j { format!("{}", i + 1) } else { format!("{} and {}", i + 1, j + 1) })
                .collect();
            if !names.is_empty() {
                warnings.push(format!(
                    "On the {}, the {what} of connectors {} run into each other (a concave stretch tighter than the {what}): use fewer connectors or shorter {what}, or move them with `slide`.",
                    w.name(),
                    warnings::list(&names)
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
        let label_side = if set.kind.has_holes() { stitch::side(&set) } else { 1.0 };
        if set.kind.has_holes() {
            let centers = stitch::centers(w, &stations, &set);
            warnings.extend(warnings::holes(w.name(), &centers, 0.5 * set.diameter, &edge, !set.invert));
            holes = stitch::holes(&centers, &set, input_ccw);
        }
        let slots = if set.kind == Kind::Leaves { leaves::slots(w, &stations, &set, input_ccw) } else { Vec::new() };
        let discs: Vec<(Point, f64)> = holes.iter().map(|h| (h.center, 0.5 * h.diameter)).collect();
        let slot_boxes: Vec<labels::LabelBox> = slots.iter().map(|s| s.bounds()).collect();
        let obstacles = labels::Obstacles { holes: &discs, slots: &slot_boxes, edge: &edge, inside: label_side > 0.0 };
        let (labels, marks, crowded) = annotate(w, &stations, &set, label_side, &obstacles);
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
