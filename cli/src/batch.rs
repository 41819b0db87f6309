//! `dformer measure|normalize|connect FILE.svg`: the core applied to the shapes of an SVG file,
//! in the root's user space (every transform applied), with lengths shown and entered in the
//! document's unit. Pieces are written back in place (id, style and transform kept).

use crate::laser::{self, Group};
use crate::splice::{escape, inner_range, tag_prefix, Edits};
use crate::svgdoc::{Shape, Skipped, SvgFile, INKSCAPE_NS};
use dformer::api::{self, connect::ConnectOptionsDto, path::PathDto};
use kurbo::{Affine, Point};
use serde_json::{json, Value};

/// Geometry attributes a shape loses when rewritten as a `<path>`.
const GEOMETRY: &[&str] = &[
    "x", "y", "width", "height", "rx", "ry", "cx", "cy", "r", "points", "x1", "y1", "x2", "y2", "d",
];
const SODIPODI_NS: &str = "http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd";

/// Maps anchors and handles through an affine map (exact for Bézier curves).
pub fn map_path(path: &PathDto, a: Affine) -> PathDto {
    let m = |p: [f64; 2]| {
        let q = a * Point::new(p[0], p[1]);
        [q.x, q.y]
    };
    let mut out = path.clone();
    for p in &mut out.points {
        p.anchor = m(p.anchor);
        p.left = p.left.map(m);
        p.right = p.right.map(m);
    }
    out
}

/// How the user chose the pieces: by id (`--id`, in order), the `largest` N closed shapes, or
/// neither (every closed shape in the file).
#[derive(Clone, Copy, Default)]
pub struct Choice<'c> {
    pub ids: &'c [String],
    pub largest: Option<usize>,
}

/// A closed shape that can be a piece: its outline in the display unit and its measures.
pub struct Offered<'a, 'i> {
    pub shape: Shape<'a, 'i>,
    pub path: PathDto,
    pub measure: api::MeasureDto,
}

/// Every closed shape of the file that can be a piece, and every other drawn element with why
/// not (open paths, compound paths, text, images, self-crossing outlines…), in document order.
pub fn offer<'a, 'i>(file: &'a SvgFile<'i>) -> (Vec<Offered<'a, 'i>>, Vec<Skipped>) {
    let (shapes, mut skipped) = file.survey();
    let to_display = to_display(file);
    let mut offered = Vec::new();
    for shape in shapes {
        let skip = |reason: String| Skipped { name: shape.name.clone(), reason, at: shape.node.range().start };
        let subpaths = match api::svg::path_from_svg(&shape.d) {
            Ok(p) => p,
            Err(e) => {
                skipped.push(skip(e.to_string()));
                continue;
            }
        };
        let path = match subpaths.as_slice() {
            [] => {
                skipped.push(skip("an empty path: it draws nothing".into()));
                continue;
            }
            [one] if !one.closed => {
                skipped.push(skip(crate::advice::skipped("open").unwrap_or("an open path").into()));
                continue;
            }
            [one] => map_path(one, to_display * shape.ctm),
            many => {
                skipped.push(skip(format!(
                    "a compound path of {} subpaths: a piece must be one outline, so split it into separate shapes",
                    many.len()
                )));
                continue;
            }
        };
        match api::measure(&path, None) {
            Ok(measure) => offered.push(Offered { shape, path, measure }),
            Err(e) => skipped.push(skip(e.to_string().replacen("The first path ", "The path ", 1))),
        }
    }
    skipped.sort_by_key(|s| s.at);
    (offered, skipped)
}

/// `skipped: NAME: REASON` lines for stderr.
pub fn skipped_report(skipped: &[Skipped]) -> String {
    skipped.iter().map(|s| format!("skipped: {}: {}\n", s.name, s.reason)).collect()
}

/// The pieces the user chose (see [`Choice`]), `min` to `max` of them, with the stderr lines
/// for what was skipped. Ambiguity is refused: naming every closed shape, and how to choose.
pub fn choose<'a, 'i>(
    file: &'a SvgFile<'i>,
    choice: Choice,
    min: usize,
    max: Option<usize>,
) -> Result<(Vec<Shape<'a, 'i>>, Vec<PathDto>, String), String> {
    if !choice.ids.is_empty() {
        if choice.largest.is_some() {
            return Err("give the pieces with --id or with --largest, not both".into());
        }
        let shapes = pick(file, choice.ids, min, max)?;
        let paths = read(file, &shapes)?;
        return Ok((shapes, paths, String::new()));
    }
    let (mut offered, skipped) = offer(file);
    let report = skipped_report(&skipped);
    let names = |o: &[Offered]| o.iter().map(|o| o.shape.name.as_str()).collect::<Vec<_>>().join(", ");
    let found = |o: &[Offered]| match o.len() {
        0 => "no closed shape".to_string(),
        1 => format!("1 closed shape ({})", names(o)),
        n => format!("{n} closed shapes ({})", names(o)),
    };
    let skipped_note = if skipped.is_empty() { String::new() } else { format!("; skipped: {}", skipped.iter().map(|s| format!("{} ({})", s.name, s.reason)).collect::<Vec<_>>().join("; ")) };
    if let Some(n) = choice.largest {
        if n < min || max.is_some_and(|m| n > m) {
            let want = match max {
                Some(m) if m == min => format!("{min}"),
                _ => format!("at least {min}"),
            };
            return Err(format!("--largest {n}: this command needs {want} pieces"));
        }
        if offered.len() < n {
            return Err(format!("--largest {n}: the file has {}{skipped_note}", found(&offered)));
        }
        // Longest perimeter first (ties: larger area, then file order), as the panel preselects;
        // the chosen pieces stay in file order, so A is the one drawn first. By perimeter, not
        // area: normalizing to the largest keeps the same two the largest, so
        // `normalize --largest 2` then `connect --largest 2` picks the same pieces.
        let mut order: Vec<usize> = (0..offered.len()).collect();
        order.sort_by(|&i, &j| {
            let (a, b) = (&offered[i].measure, &offered[j].measure);
            b.perimeter.total_cmp(&a.perimeter).then(b.area.total_cmp(&a.area)).then(i.cmp(&j))
        });
        let mut keep: Vec<usize> = order.into_iter().take(n).collect();
        keep.sort_unstable();
        let mut k = 0;
        offered.retain(|_| {
            k += 1;
            keep.contains(&(k - 1))
        });
    } else if offered.len() < min || max.is_some_and(|m| offered.len() > m) {
        let want = match max {
            Some(m) if m == min => format!("exactly {min}"),
            _ => format!("at least {min}"),
        };
        let how = if offered.len() > min { format!(": choose them with --id (e.g. --id {} --id {}) or take the largest with --largest {min}", offered[0].shape.key, offered[1].shape.key) } else { String::new() };
        let others = match skipped.len() {
            0 => String::new(),
            n => format!(" ({n} other element{} skipped: {}; `dformer measure` says why)", if n == 1 { "" } else { "s" }, skipped.iter().map(|s| s.name.as_str()).collect::<Vec<_>>().join(", ")),
        };
        return Err(format!("{want} closed shapes are needed, the file has {}{how}{others}", found(&offered)));
    }
    let paths = offered.iter().map(|o| o.path.clone()).collect();
    Ok((offered.into_iter().map(|o| o.shape).collect(), paths, report))
}

/// The shapes to work on: those named by `ids` (in that order; only they are read), or every
/// shape in the file.
pub fn pick<'a, 'i>(
    file: &'a SvgFile<'i>,
    ids: &[String],
    min: usize,
    max: Option<usize>,
) -> Result<Vec<Shape<'a, 'i>>, String> {
    let chosen = if ids.is_empty() {
        file.shapes()?
    } else {
        file.shapes_by_id(ids)?
    };
    let n = chosen.len();
    if n < min || max.is_some_and(|m| n > m) {
        let want = match max {
            Some(m) if m == min => format!("exactly {min}"),
            _ => format!("at least {min}"),
        };
        let names: Vec<&str> = chosen.iter().map(|s| s.name.as_str()).collect();
        return Err(format!(
            "{want} shapes are needed, found {n} ({}); choose them with --id",
            names.join(", ")
        ));
    }
    Ok(chosen)
}

/// Root user units → the display unit: the core works in the unit the user reads and types,
/// so the lengths in its messages (perimeters, diameters, pitches) are in that unit too. The
/// core is scale-free (defaults are fractions of the pitch, tolerances relative).
fn to_display(file: &SvgFile) -> Affine {
    Affine::scale(file.scale.to_unit(1.0))
}

/// One core path per shape, in the display unit; a compound shape is an error naming it.
pub fn read(file: &SvgFile, shapes: &[Shape]) -> Result<Vec<PathDto>, String> {
    let to_display = to_display(file);
    shapes
        .iter()
        .map(|s| {
            let subpaths = api::svg::path_from_svg(&s.d).map_err(|e| format!("{}: {e}", s.name))?;
            match subpaths.as_slice() {
                [one] => Ok(map_path(one, to_display * s.ctm)),
                _ => Err(format!(
                    "{} has {} subpaths; a D-form piece must be one outline (break it apart first)",
                    s.name,
                    subpaths.len()
                )),
            }
        })
        .collect()
}

/// Path data of a path in the display unit (root axes) in the shape's local coordinates.
fn local_d(file: &SvgFile, shape: &Shape, path: &PathDto) -> Result<String, String> {
    let ctm = to_display(file) * shape.ctm;
    let inverse = if ctm.determinant().abs() > 0.0 {
        ctm.inverse()
    } else {
        return Err(format!(
            "{} has a transform that flattens it to nothing",
            shape.name
        ));
    };
    api::svg::path_to_svg(&map_path(path, inverse)).map_err(|e| e.to_string())
}

/// Gives the shape a new outline: a `<path>`'s `d` is replaced (Inkscape's sodipodi shape data
/// dropped, so Inkscape does not regenerate the old shape); other shapes become `<path>`.
fn replace_outline(
    source: &str,
    file: &SvgFile,
    shape: &Shape,
    path: &PathDto,
    edits: &mut Edits,
) -> Result<(), String> {
    let node = shape.node;
    if node.attribute((INKSCAPE_NS, "path-effect")).is_some()
        || node.attribute((INKSCAPE_NS, "original-d")).is_some()
    {
        return Err(format!(
            "{} has a live path effect; convert it to a path first",
            shape.name
        ));
    }
    let d = escape(&local_d(file, shape, path)?);
    if node.tag_name().name() == "path" {
        for attr in node.attributes() {
            if attr.namespace() == Some(SODIPODI_NS) {
                edits.replace(attr.range(), String::new());
            } else if attr.namespace().is_none() && attr.name() == "d" {
                edits.replace(attr.range_value(), d.clone());
            }
        }
        return Ok(());
    }
    let prefix = tag_prefix(source, node);
    let mut xml = format!("<{prefix}path");
    for attr in node.attributes() {
        let geometry = attr.namespace().is_none() && GEOMETRY.contains(&attr.name());
        if !geometry && attr.namespace() != Some(SODIPODI_NS) {
            xml.push(' ');
            xml.push_str(&source[attr.range()]);
        }
    }
    xml.push_str(&format!(" d=\"{d}\""));
    match inner_range(node) {
        Some(inner) => xml.push_str(&format!(">{}</{prefix}path>", &source[inner])),
        None => xml.push_str("/>"),
    }
    edits.replace(node.range(), xml);
    Ok(())
}

/// `dformer measure`: one line (or JSON object) per closed shape on stdout, the skipped ones
/// with why on stderr. Named with `--id`, every named shape must measure; otherwise it fails
/// only when the file has no closed shape at all.
pub fn measure(file: &SvgFile, choice: Choice, as_json: bool) -> Result<(String, String), String> {
    let (rows, report): (Vec<(String, String, api::MeasureDto)>, String) = if choice.ids.is_empty() && choice.largest.is_none() {
        let (offered, skipped) = offer(file);
        if offered.is_empty() {
            let what = if skipped.is_empty() { "no shape".to_string() } else { format!("no closed shape (skipped: {})", skipped.iter().map(|s| format!("{}: {}", s.name, s.reason)).collect::<Vec<_>>().join("; ")) };
            return Err(format!("nothing to measure: the file has {what}"));
        }
        (offered.into_iter().map(|o| (o.shape.name, o.shape.key, o.measure)).collect(), skipped_report(&skipped))
    } else {
        let (shapes, paths, report) = choose(file, choice, 1, None)?;
        let mut rows = Vec::new();
        for (s, p) in shapes.into_iter().zip(&paths) {
            let m = api::measure(p, None).map_err(|e| format!("{}: {e}", s.name))?;
            rows.push((s.name, s.key, m));
        }
        (rows, report)
    };
    let unit = &file.scale.unit;
    let mut json_rows = Vec::new();
    let mut text = String::new();
    for (name, key, m) in rows {
        let (perimeter, area) = (m.perimeter, m.area);
        // The core reports orientation for y-up; SVG user space is y-down.
        let screen = if m.orientation == "ccw" {
            "clockwise"
        } else {
            "counter-clockwise"
        };
        text.push_str(&format!(
            "{name}\tperimeter {perimeter:.6} {unit}\tarea {area:.6} {unit}²\t{screen} on screen\n"
        ));
        json_rows.push(json!({ "id": key, "perimeter": perimeter, "area": area, "unit": unit, "direction": screen }));
    }
    let out = if as_json {
        format!("{}\n", Value::Array(json_rows))
    } else {
        text
    };
    Ok((out, report))
}

/// `dformer normalize`: every chosen shape scaled to the common perimeter, in place.
pub fn normalize(
    source: &str,
    file: &SvgFile,
    choice: Choice,
    target: &str,
    pivot: &str,
) -> Result<(String, String), String> {
    let target = match target {
        "largest" | "smallest" | "mean" | "first" => json!(target),
        length => json!(file
            .scale
            .parse(length)
            .map_err(|e| format!("--target: {e}"))?),
    };
    // One shape is scaled to an exact length (a number); the other targets compare two or more.
    let least = if target.is_number() { 1 } else { 2 };
    let (shapes, paths, skipped) = choose(file, choice, least, None).map_err(|e| {
        if least == 2 && e.contains("the file has 1 closed shape") {
            format!("{e}; to scale one shape, give its perimeter: --target 300mm")
        } else {
            e
        }
    })?;
    let options = serde_json::from_value(json!({ "target": target, "pivot": pivot }))
        .map_err(|e| e.to_string())?;
    let result = api::normalize::normalize(&paths, &options).map_err(|e| e.to_string())?;
    let mut edits = Edits::default();
    for (s, p) in shapes.iter().zip(&result.paths) {
        replace_outline(source, file, s, p, &mut edits)?;
    }
    let report = skipped + &format!(
        "{} normalized to perimeter {:.6} {} (scale{} {})\n",
        if shapes.len() == 1 { "1 shape".to_string() } else { format!("{} shapes", shapes.len()) },
        result.perimeter,
        file.scale.unit,
        if shapes.len() == 1 { "" } else { "s" },
        result
            .scales
            .iter()
            .map(|k| format!("{k:.6}"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    Ok((edits.apply(source)?, report))
}

/// Options of `dformer connect` as given on the command line (lengths still as text).
#[derive(clap::Args)]
pub struct ConnectArgs {
    /// stitch, teeth, leaves or hybrid.
    #[arg(long, default_value = "stitch")]
    pub kind: String,
    /// Number of connectors on each piece (give this or --pitch).
    #[arg(long, allow_negative_numbers = true)]
    pub count: Option<f64>,
    /// Distance between connectors along the edge, e.g. 12mm (rounded to divide the perimeter).
    #[arg(long, allow_hyphen_values = true)]
    pub pitch: Option<String>,
    /// Shift of every connector, as a fraction of the pitch (0 to 1).
    #[arg(long, allow_negative_numbers = true)]
    pub slide: Option<f64>,
    /// Connector 1 on each piece: distances along A and B from their first nodes.
    #[arg(long, num_args = 2, value_names = ["A", "B"], allow_hyphen_values = true)]
    pub start: Option<Vec<String>>,
    /// Edge to hole centre.
    #[arg(long, allow_hyphen_values = true)]
    pub inset: Option<String>,
    /// Hole diameter.
    #[arg(long, allow_hyphen_values = true)]
    pub diameter: Option<String>,
    /// Tooth or leaf length.
    #[arg(long, allow_hyphen_values = true)]
    pub length: Option<String>,
    /// Tooth flank angle in degrees: 90 = square, less = tapered, more than 90 = dovetails that
    /// widen toward their tips and lock the pieces together (default: the core's, 90).
    #[arg(long, allow_negative_numbers = true)]
    pub angle: Option<f64>,
    /// Leaves: tab (a rounded flap to glue) or lock (a head on a neck, held in a slot cut in
    /// the other piece).
    #[arg(long)]
    pub leaf: Option<String>,
    /// Seam allowance (stitch, leaves): the cut line moves out by this much, e.g. 3mm; the seam
    /// line is scored.
    #[arg(long, allow_hyphen_values = true)]
    pub allowance: Option<String>,
    /// Stitch: holes outside the piece. Teeth: swap teeth and gaps. Leaves: swap which piece
    /// carries each leaf.
    #[arg(long)]
    pub invert: bool,
    /// Laser kerf to compensate (cut width).
    #[arg(long, allow_hyphen_values = true)]
    pub kerf: Option<String>,
    /// Height of the engraved numbers (default: each number as large as fits clear of the
    /// holes, slots and cut line, as the core sizes it).
    #[arg(long, allow_hyphen_values = true)]
    pub label_size: Option<String>,
    /// Do not engrave connector numbers.
    #[arg(long)]
    pub no_labels: bool,
}

/// `dformer connect`: paired connectors on the two chosen shapes, written as laser layers.
pub fn connect(
    source: &str,
    file: &SvgFile,
    choice: Choice,
    a: &ConnectArgs,
) -> Result<(String, String), String> {
    let (shapes, paths, skipped) = choose(file, choice, 2, Some(2))?;
    let len = |name: &str, v: &Option<String>| {
        v.as_deref()
            .map(|t| file.scale.parse(t).map_err(|e| format!("--{name}: {e}")))
            .transpose()
    };
    let start = match a.start.as_deref() {
        Some([sa, sb]) => Some([file.scale.parse(sa)?, file.scale.parse(sb)?]),
        Some(other) => {
            return Err(format!(
                "--start: wanted two distances (A and B), got {}",
                other.len()
            ))
        }
        None => None,
    };
    // Neither count nor pitch: the core's default count, as in every host.
    let count = match (a.count, &a.pitch) {
        (None, None) => Some(dformer::connect::options::DEFAULT_COUNT as f64),
        (c, _) => c,
    };
    let options = ConnectOptionsDto {
        kind: Some(a.kind.clone()),
        count,
        pitch: len("pitch", &a.pitch)?,
        slide: a.slide,
        start,
        inset: len("inset", &a.inset)?,
        diameter: len("diameter", &a.diameter)?,
        length: len("length", &a.length)?,
        angle: a.angle,
        leaf: a.leaf.clone(),
        allowance: len("allowance", &a.allowance)?,
        invert: Some(a.invert),
        kerf: len("kerf", &a.kerf)?,
        accuracy: None,
        labels: Some(!a.no_labels),
        // Named after every length in the core's messages.
        unit: Some(file.scale.unit.clone()),
    };
    let result = api::connect::connect(&paths, &options).map_err(|e| e.to_string())?;
    let hairline = laser::HAIRLINE_PX / file.scale.px_per_user;
    // The core's results are in the display unit; the layers are drawn in root user units.
    let from_display = to_display(file).inverse();
    let font = match len("label-size", &a.label_size)? {
        None => None,
        Some(size) if size.is_finite() && size > 0.0 => Some(size),
        Some(_) => {
            return Err(format!(
                "--label-size: must be a positive length, got {}",
                a.label_size.as_deref().unwrap_or_default()
            ))
        }
    };
    let mut edits = Edits::default();
    let mut groups = Vec::new();
    for (i, (s, piece)) in shapes.iter().zip(&result.pieces).enumerate() {
        let title = format!("Piece {} {}", ["A", "B"][i], s.name);
        if a.kind != "stitch" || piece.seam.is_some() {
            replace_outline(source, file, s, &piece.outline, &mut edits)?;
        }
        let svg_of = |paths: Vec<&PathDto>| {
            paths
                .into_iter()
                .map(|p| {
                    api::svg::path_to_svg(&map_path(p, from_display)).map_err(|e| e.to_string())
                })
                .collect::<Result<Vec<_>, _>>()
        };
        let holes = svg_of(piece.holes.iter().map(|h| &h.path).collect())?;
        let slots = svg_of(piece.slots.iter().collect())?;
        let marks = svg_of(piece.marks.iter().collect())?;
        let seam = svg_of(piece.seam.iter().collect())?;
        if !holes.is_empty() || !slots.is_empty() {
            let mut body = laser::paths("cut", &format!("dformer-hole-{}", s.key), &holes, hairline);
            body += &laser::paths("cut", &format!("dformer-slot-{}", s.key), &slots, hairline);
            groups.push(Group {
                layer: "cut",
                piece_key: s.key.clone(),
                title: format!("{title}: holes"),
                body,
            });
        }
        if !marks.is_empty() || !seam.is_empty() {
            let mut body = laser::paths(
                "score",
                &format!("dformer-mark-{}", s.key),
                &marks,
                hairline,
            );
            body += &laser::paths("score", &format!("dformer-seam-{}", s.key), &seam, hairline);
            groups.push(Group {
                layer: "score",
                piece_key: s.key.clone(),
                title: format!("{title}: start"),
                body,
            });
        }
        if !a.no_labels {
            let items: Vec<_> = piece
                .labels
                .iter()
                .map(|l| {
                    let at = from_display * Point::new(l.at[0], l.at[1]);
                    let size = font.unwrap_or(l.size) / file.scale.to_unit(1.0);
                    (l.text.clone(), [at.x, at.y], l.angle, size)
                })
                .collect();
            let body = laser::labels(&format!("dformer-label-{}", s.key), &items);
            groups.push(Group {
                layer: "engrave",
                piece_key: s.key.clone(),
                title: format!("{title}: numbers"),
                body,
            });
        }
    }
    laser::write(source, file.doc.root_element(), &groups, &mut edits)?;
    let mut report = skipped + &format!(
        "{} {} connectors per piece, {:.6} {} apart\n",
        result.count, a.kind, result.pitch, file.scale.unit
    );
    for w in &result.warnings {
        report.push_str(&format!("warning: {w}\n"));
    }
    Ok((edits.apply(source)?, report))
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Opts {
        #[command(flatten)]
        connect: ConnectArgs,
    }

    const TWO_SQUARES: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 100 50">
        <rect id="a" x="5" y="5" width="40" height="40"/><rect id="b" x="55" y="5" width="40" height="40"/></svg>"#;

    fn run_connect(args: &[&str]) -> Result<(String, String), String> {
        connect_in(TWO_SQUARES, None, args)
    }

    fn connect_in(
        svg: &str,
        unit: Option<&str>,
        args: &[&str],
    ) -> Result<(String, String), String> {
        let opts = Opts::try_parse_from(std::iter::once("connect").chain(args.iter().copied()))
            .map_err(|e| e.to_string())?;
        let file = SvgFile::parse(svg, unit)?;
        connect(svg, &file, Choice::default(), &opts.connect)
    }

    /// Locking leaves put slots on the cut layer; an allowance moves the cut line and scores the
    /// seam line; the new bad inputs are refused with their message and nothing written.
    #[test]
    fn slots_go_to_the_cut_layer_and_the_seam_line_to_the_score_layer() {
        let (svg, _) = run_connect(&["--kind", "leaves", "--leaf", "lock", "--count", "8"]).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let in_layer = |layer: &str, prefix: &str| {
            doc.descendants()
                .filter(|n| n.attribute("id").is_some_and(|i| i.starts_with(prefix)))
                .filter(|n| n.ancestors().any(|a| a.attribute("id") == Some(&format!("dformer-{layer}-a")[..])))
                .count()
        };
        // 8 leaves alternate: A carries 4 and receives B's 4 in slots.
        assert_eq!(in_layer("cut", "dformer-slot-a-"), 4, "{svg}");
        let (svg, _) = run_connect(&["--count", "8", "--allowance", "2"]).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let seam = doc.descendants().find(|n| n.attribute("id") == Some("dformer-seam-a-1")).expect("seam line");
        assert!(seam.ancestors().any(|a| a.attribute("id") == Some("dformer-score-a")), "seam line not on the score layer");
        // The rect became the cut line, a path 2 mm out.
        let a = doc.descendants().find(|n| n.attribute("id") == Some("a")).unwrap();
        assert_eq!(a.tag_name().name(), "path", "the outline was not replaced by the cut line");
        for (args, want) in [
            (&["--kind", "leaves", "--count", "7"][..], "must be even, got 7: use 6 or 8"),
            (&["--kind", "teeth", "--count", "8", "--length", "9", "--angle", "150"][..], "dovetails' corners collide"),
            (&["--kind", "teeth", "--count", "8", "--allowance", "1"][..], "teeth interlock on the seam line itself"),
        ] {
            let err = run_connect(args).err().unwrap_or_default();
            assert!(err.contains(want), "{args:?}: wanted …{want}…, got {err}");
        }
    }

    #[test]
    fn lengths_in_messages_are_in_the_unit_the_user_types() {
        // A px document read in mm: `--diameter 30 --kerf 40` said "Option `kerf`:
        // 151.1811023622047 is not smaller than the hole diameter 113.38582677165354".
        let px = r#"<svg xmlns="http://www.w3.org/2000/svg" width="800" height="400">
            <rect id="a" x="10" y="10" width="192" height="192"/><rect id="b" x="300" y="10" width="192" height="192"/></svg>"#;
        let err = connect_in(
            px,
            Some("mm"),
            &["--count", "4", "--diameter", "30", "--kerf", "40"],
        )
        .err()
        .unwrap_or_default();
        assert_eq!(
            err,
            "Option `kerf`: 40 mm is not smaller than the hole diameter 30 mm: the holes would vanish"
        );
        let err = connect_in(px, Some("mm"), &["--count", "4", "--diameter", "60"])
            .err()
            .unwrap_or_default();
        assert!(
            err.starts_with("Holes of diameter 60 mm do not fit between connectors 50.8 mm apart"),
            "wanted 60 mm holes 50.8 mm apart, got {err}"
        );
        // In a mm document a length typed in mm comes back as typed (was -1.0000000000000002).
        assert_eq!(
            run_connect(&["--count", "8", "--inset", "-1mm"])
                .err()
                .unwrap_or_default(),
            "Option `inset`: must be a positive number, got -1 mm"
        );
        // The layers are still drawn in the file's px: 4 connectors 50.8 mm = 192 px apart, and
        // 5 mm numbers are 18.9 px high.
        let (svg, report) =
            connect_in(px, Some("mm"), &["--count", "4", "--label-size", "5"]).unwrap();
        assert!(
            report.starts_with("4 stitch connectors per piece, 50.800000 mm apart"),
            "got {report}"
        );
        assert!(
            svg.contains("font-size:18.897638;"),
            "wanted 18.897638 px numbers"
        );
    }

    #[test]
    fn negative_values_reach_the_checks_instead_of_being_taken_for_options() {
        // `--pitch -5` was "unexpected argument '-5' found" (with a tip that does not work), and
        // a negative --start, which the core accepts, could not be given at all.
        let err = |args: &[&str]| run_connect(args).err().unwrap_or_default();
        assert!(
            err(&["--pitch", "-5"])
                .starts_with("Option `pitch`: must be a positive number, got -5"),
            "got {}",
            err(&["--pitch", "-5"])
        );
        assert!(
            err(&["--count", "8", "--inset", "-1mm"])
                .starts_with("Option `inset`: must be a positive number, got -1 mm"),
            "got {}",
            err(&["--count", "8", "--inset", "-1mm"])
        );
        assert_eq!(
            err(&["--count", "-3"]),
            "Option `count`: must be a whole number from 1 to 10000, got -3"
        );
        assert_eq!(
            err(&["--count", "8", "--slide", "-0.5"]),
            "Option `slide`: must be between 0 and 1 (a fraction of the pitch), got -0.5"
        );
        assert!(run_connect(&["--count", "8", "--start", "-5", "3"]).is_ok());
    }

    #[test]
    fn a_label_size_that_is_not_a_positive_length_is_refused() {
        // Each of these wrote `font-size:-1.000000` or `font-size:0.000000`: no numbers engraved.
        for bad in ["-1", "0", "-0.5in"] {
            let err = run_connect(&["--count", "8", &format!("--label-size={bad}")])
                .err()
                .unwrap_or_default();
            assert_eq!(
                err,
                format!("--label-size: must be a positive length, got {bad}"),
                "--label-size={bad}"
            );
        }
        let (svg, _) = run_connect(&["--count", "8", "--label-size", "3"]).unwrap();
        assert!(svg.contains("font-size:3.000000;"), "wanted 3 mm numbers");
    }
}
