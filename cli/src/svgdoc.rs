//! Reading an SVG file for batch use: the shapes that can be D-form pieces, their path data in
//! local coordinates and their transform to the root's user space (viewBox units).
//!
//! Scope (stated in `inkscape-extension/README.md`): `path`, `rect` (with `rx`/`ry`), `circle`,
//! `ellipse`, `polygon` (and `polyline`/`line`, which the core reports as open); `transform`
//! attributes on the shape and every ancestor group, and nested `<svg>` viewports
//! (`crate::viewport`), composed. Not followed: `<use>` clones, CSS `transform` properties,
//! shapes in `<defs>`, masks, clips, markers, patterns and symbols, and D-former's own output
//! layers (ids starting `dformer-`).

use crate::units::{length_px, Scale};
use crate::viewport;
use kurbo::Affine;
use roxmltree::{Document, Node};
use std::collections::HashSet;
use std::fmt::Write;

pub const SVG_NS: &str = "http://www.w3.org/2000/svg";
pub const INKSCAPE_NS: &str = "http://www.inkscape.org/namespaces/inkscape";
/// Id prefix of everything D-former writes.
pub const OWN_PREFIX: &str = "dformer-";

/// Elements whose content is never drawn directly.
const NOT_DRAWN: &[&str] = &[
    "defs",
    "clipPath",
    "mask",
    "marker",
    "pattern",
    "symbol",
    "metadata",
    "title",
    "desc",
    "style",
    "script",
    "foreignObject",
    "use",
    "image",
    "text",
];
/// Drawn elements that are not outlines: listed as skipped, with the table's reason
/// (`messages/commands.json`, the browser app's words too).
const NOT_OUTLINES: &[&str] = &["text", "image", "use", "foreignObject"];
const SHAPES: &[&str] = &[
    "path", "rect", "circle", "ellipse", "polygon", "polyline", "line",
];

/// One shape that may be a piece.
#[derive(Debug, Clone)]
pub struct Shape<'a, 'input> {
    pub node: Node<'a, 'input>,
    /// How messages name it: `#id`, or `<rect> number 3` without an id.
    pub name: String,
    /// Its id, or a stable stand-in (`shape3`) for D-former's group ids.
    pub key: String,
    /// Local coordinates → root user space.
    pub ctm: Affine,
    /// Path data in local coordinates.
    pub d: String,
}

/// A drawn element that cannot be a piece, and why (for the "skipped" list).
#[derive(Debug, Clone, PartialEq)]
pub struct Skipped {
    pub name: String,
    pub reason: String,
    /// Where it starts in the text (document order).
    pub at: usize,
}

/// The parsed SVG text plus what the commands need from the root.
pub struct SvgFile<'input> {
    pub doc: Document<'input>,
    pub scale: Scale,
}

fn number(n: Node, name: &str, what: &str) -> Result<f64, String> {
    match n.attribute(name) {
        None => Ok(0.0),
        Some(v) => length_px(v)
            .ok_or_else(|| format!("{what}: attribute {name}=\"{v}\" is not an absolute length")),
    }
}

fn transform_of(n: Node) -> Result<Affine, String> {
    match n.attribute("transform") {
        None => Ok(Affine::IDENTITY),
        Some(t) => {
            let m: svgtypes::Transform = t
                .parse()
                .map_err(|e| format!("transform=\"{t}\" cannot be read ({e})"))?;
            Ok(Affine::new([m.a, m.b, m.c, m.d, m.e, m.f]))
        }
    }
}

/// Path data of a basic shape, in its local coordinates (SVG 1.1 §9 equivalent paths).
fn shape_path(n: Node, what: &str) -> Result<String, String> {
    let g = |name: &str| number(n, name, what);
    let mut d = String::new();
    match n.tag_name().name() {
        "path" => return Ok(n.attribute("d").unwrap_or("").to_string()),
        "rect" => {
            let (x, y, w, h) = (g("x")?, g("y")?, g("width")?, g("height")?);
            if w <= 0.0 || h <= 0.0 {
                return Err(format!("{what} has zero or negative width or height"));
            }
            let (rx0, ry0) = (
                n.attribute("rx").map(|_| g("rx")).transpose()?,
                n.attribute("ry").map(|_| g("ry")).transpose()?,
            );
            // A missing radius takes the other's value; both are clamped to half the side (§9.2).
            let rx = rx0.or(ry0).unwrap_or(0.0).clamp(0.0, w / 2.0);
            let ry = ry0.or(rx0).unwrap_or(0.0).clamp(0.0, h / 2.0);
            if rx > 0.0 && ry > 0.0 {
                let _ = write!(
                    d,
                    "M {} {y} H {} A {rx} {ry} 0 0 1 {} {} V {} A {rx} {ry} 0 0 1 {} {} H {} A {rx} {ry} 0 0 1 {x} {} V {} A {rx} {ry} 0 0 1 {} {y} Z",
                    x + rx, x + w - rx, x + w, y + ry, y + h - ry, x + w - rx, y + h, x + rx, y + h - ry, y + ry, x + rx
                );
            } else {
                let _ = write!(d, "M {x} {y} H {} V {} H {x} Z", x + w, y + h);
            }
        }
        "circle" | "ellipse" => {
            let (cx, cy) = (g("cx")?, g("cy")?);
            let (rx, ry) = if n.tag_name().name() == "circle" {
                (g("r")?, g("r")?)
            } else {
                (g("rx")?, g("ry")?)
            };
            if rx <= 0.0 || ry <= 0.0 {
                return Err(format!("{what} has a zero or negative radius"));
            }
            let _ = write!(
                d,
                "M {} {cy} A {rx} {ry} 0 0 1 {cx} {} A {rx} {ry} 0 0 1 {} {cy} A {rx} {ry} 0 0 1 {cx} {} A {rx} {ry} 0 0 1 {} {cy} Z",
                cx + rx, cy + ry, cx - rx, cy - ry, cx + rx
            );
        }
        "polygon" | "polyline" => {
            for (i, (x, y)) in
                svgtypes::PointsParser::from(n.attribute("points").unwrap_or("")).enumerate()
            {
                let _ = write!(d, "{} {x} {y} ", if i == 0 { "M" } else { "L" });
            }
            if n.tag_name().name() == "polygon" && !d.is_empty() {
                d.push('Z');
            }
        }
        "line" => {
            let _ = write!(d, "M {} {} L {} {}", g("x1")?, g("y1")?, g("x2")?, g("y2")?);
        }
        other => return Err(format!("{what}: <{other}> is not a shape D-former reads")),
    }
    Ok(d)
}

impl<'input> SvgFile<'input> {
    /// Parses the text; the root must be an SVG `<svg>` element.
    pub fn parse(text: &'input str, unit: Option<&str>) -> Result<Self, String> {
        let options = roxmltree::ParsingOptions {
            allow_dtd: true,
            ..Default::default()
        };
        let doc = Document::parse_with_options(text, options)
            .map_err(|e| format!("not a readable SVG/XML file: {e}"))?;
        let root = doc.root_element();
        if root.tag_name().name() != "svg" || root.tag_name().namespace() != Some(SVG_NS) {
            return Err("the root element is not an SVG <svg> element (xmlns=\"http://www.w3.org/2000/svg\")".into());
        }
        let doc_units = root
            .children()
            .find(|c| c.tag_name().name() == "namedview")
            .and_then(|nv| nv.attribute((INKSCAPE_NS, "document-units")));
        let scale = Scale::new(
            viewport::page_px_per_user(root)?,
            root.attribute("width"),
            doc_units,
            unit,
        )?;
        Ok(SvgFile { doc, scale })
    }

    /// Every drawable shape in document order, outside D-former's own output, each read and
    /// checked (the first unreadable one is the error).
    pub fn shapes(&self) -> Result<Vec<Shape<'_, 'input>>, String> {
        self.found().into_iter().map(Found::load).collect()
    }

    /// The shapes with these ids, in this order: only they (and their ancestors) are read and
    /// checked, so an unreadable shape elsewhere in the file does not matter.
    pub fn shapes_by_id(&self, ids: &[String]) -> Result<Vec<Shape<'_, 'input>>, String> {
        // The same shape twice would be one piece used as both (normalize then edited it twice
        // and stopped with an internal error; connect wrote every connector id twice).
        if let Some((k, id)) = ids
            .iter()
            .enumerate()
            .find(|(k, id)| ids[..*k].contains(id))
        {
            return Err(format!(
                "--id \"{id}\" is given twice (choice {} and {}); each piece is a different shape",
                ids.iter().position(|x| x == id).unwrap_or(0) + 1,
                k + 1
            ));
        }
        let found = self.found();
        ids.iter()
            .map(|id| {
                found
                    .iter()
                    .find(|f| f.node.attribute("id") == Some(id.as_str()))
                    .cloned()
                    .ok_or_else(|| format!("no shape with id \"{id}\" in the file"))
                    .and_then(Found::load)
            })
            .collect()
    }

    /// Every drawable shape that can be read, and every drawn element that cannot (unreadable
    /// shapes with their error, text, images, clones), both in document order: one bad element
    /// never hides the others.
    pub fn survey(&self) -> (Vec<Shape<'_, 'input>>, Vec<Skipped>) {
        let mut skipped: Vec<(usize, Skipped)> = Vec::new();
        let mut shapes = Vec::new();
        for f in self.found() {
            let (at, name) = (f.node.range().start, f.name.clone());
            match f.load() {
                Ok(s) => shapes.push(s),
                Err(e) => {
                    // The message starts with the shape's name; the list names it already.
                    let reason = e.strip_prefix(&name).map(|r| r.trim_start_matches([':', ' '])).unwrap_or(&e).to_string();
                    skipped.push((at, Skipped { name, reason, at }));
                }
            }
        }
        let root = self.doc.root_element();
        for n in root.descendants().filter(|n| n.is_element() && n.tag_name().namespace() == Some(SVG_NS)) {
            let tag = n.tag_name().name();
            let Some(reason) = NOT_OUTLINES.contains(&tag).then(|| crate::advice::skipped(tag)).flatten() else { continue };
            let hidden = n.ancestors().any(|a| hidden(a) || (a != n && matches!(a.tag_name().name(), "defs" | "clipPath" | "mask" | "marker" | "pattern" | "symbol" | "text")));
            if hidden || n.attribute("id").is_some_and(|id| id.starts_with(OWN_PREFIX)) {
                continue;
            }
            let name = n.attribute("id").map_or_else(|| format!("<{}>", n.tag_name().name()), |id| format!("#{id}"));
            skipped.push((n.range().start, Skipped { name, reason: (*reason).to_string(), at: n.range().start }));
        }
        skipped.sort_by_key(|(at, _)| *at);
        (shapes, skipped.into_iter().map(|(_, s)| s).collect())
    }

    /// Every drawable shape, not yet read: errors in it or its ancestors are kept for `load`.
    fn found(&self) -> Vec<Found<'_, 'input>> {
        let mut out = Vec::new();
        let root = self.doc.root_element();
        let mut counter = 0usize;
        // Inkscape 1.2 ignores `transform` on <svg> elements (the root's included).
        let size = viewport::page_size(root);
        let taken: HashSet<&str> = root
            .descendants()
            .filter_map(|n| n.attribute("id"))
            .collect();
        let mut walker = Walker {
            out: &mut out,
            counter: &mut counter,
            taken: &taken,
        };
        walker.walk(root, Ok(Affine::IDENTITY), size);
        out
    }
}

/// Hidden with `display: none` (an Inkscape layer switched off, an old draft): not drawn, so
/// neither a piece nor skipped — as the browser app and Inkscape's selection see it.
fn hidden(n: Node) -> bool {
    n.attribute("display").is_some_and(|d| d.trim() == "none")
        || n.attribute("style").is_some_and(|s| {
            s.split(';').any(|decl| {
                let mut kv = decl.splitn(2, ':');
                kv.next().is_some_and(|k| k.trim() == "display") && kv.next().is_some_and(|v| v.trim() == "none")
            })
        })
}

/// A shape found in the tree; `ctm` is the error of an ancestor (a phrase naming it) if one
/// cannot be read.
#[derive(Clone)]
struct Found<'a, 'input> {
    node: Node<'a, 'input>,
    name: String,
    key: String,
    ctm: Result<Affine, String>,
}

impl<'a, 'input> Found<'a, 'input> {
    /// Reads the shape: its transform chain and its outline.
    fn load(self) -> Result<Shape<'a, 'input>, String> {
        let ctm = self
            .ctm
            .map_err(|e| format!("{} is inside {e}", self.name))?;
        let ctm = ctm * transform_of(self.node).map_err(|e| format!("{}: {e}", self.name))?;
        Ok(Shape {
            node: self.node,
            d: shape_path(self.node, &self.name)?,
            name: self.name,
            key: self.key,
            ctm,
        })
    }
}

/// The tree walk's state: what it found, the number of shapes so far, every id in the file (a
/// shape without an id gets a stand-in key, `shape3`, that no element uses: D-former's group
/// ids are made from it, and a shared key wrote duplicate ids).
struct Walker<'w, 'a, 'input> {
    out: &'w mut Vec<Found<'a, 'input>>,
    counter: &'w mut usize,
    taken: &'w HashSet<&'w str>,
}

impl<'w, 'a, 'input> Walker<'w, 'a, 'input> {
    fn walk(&mut self, node: Node<'a, 'input>, ctm: Result<Affine, String>, size: (f64, f64)) {
        for child in node
            .children()
            .filter(|c| c.is_element() && c.tag_name().namespace() == Some(SVG_NS))
        {
            let tag = child.tag_name().name();
            if NOT_DRAWN.contains(&tag)
                || hidden(child)
                || child
                    .attribute("id")
                    .is_some_and(|id| id.starts_with(OWN_PREFIX))
            {
                continue;
            }
            // As the Inkscape extension names objects: `#id (label)`.
            let what = match (child.attribute("id"), child.attribute((INKSCAPE_NS, "label"))) {
                (Some(id), Some(label)) if label != id => format!("#{id} ({label})"),
                (Some(id), _) => format!("#{id}"),
                (None, _) => format!("<{tag}> number {}", *self.counter + 1),
            };
            if SHAPES.contains(&tag) {
                *self.counter += 1;
                let key = child
                    .attribute("id")
                    .map(str::to_string)
                    .unwrap_or_else(|| {
                        let mut key = format!("shape{}", *self.counter);
                        while self.taken.contains(key.as_str()) {
                            key.push('_');
                        }
                        key
                    });
                self.out.push(Found {
                    node: child,
                    name: what,
                    key,
                    ctm: ctm.clone(),
                });
            } else if tag == "svg" {
                match viewport::nested(child, size) {
                    Ok((map, inner)) => self.walk(child, ctm.clone().map(|m| m * map), inner),
                    Err(e) => self.walk(child, Err(ctm.clone().err().unwrap_or(e)), size),
                }
            } else {
                let local = ctm.clone().and_then(|m| {
                    transform_of(child)
                        .map(|t| m * t)
                        .map_err(|e| format!("{what}, whose {e}"))
                });
                self.walk(child, local, size);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nested_group_transforms_compose_outer_first() {
        let text = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" viewBox="0 0 100 100">
            <g transform="translate(10 0)"><g transform="scale(2)"><rect id="r" width="1" height="1"/></g></g>
            <defs><rect id="hidden" width="1" height="1"/></defs></svg>"#;
        let file = SvgFile::parse(text, None).unwrap();
        let shapes = file.shapes().unwrap();
        assert_eq!(
            shapes.len(),
            1,
            "wanted only the drawn rect, got {:?}",
            shapes.iter().map(|s| &s.name).collect::<Vec<_>>()
        );
        let p = shapes[0].ctm * kurbo::Point::new(1.0, 1.0);
        assert_eq!(
            (p.x, p.y),
            (12.0, 2.0),
            "wanted scale then translate: (12, 2), got {p:?}"
        );
        assert_eq!(file.scale.unit, "mm");
    }

    #[test]
    fn nested_svg_viewports_apply_and_svg_transforms_do_not_like_inkscape() {
        // Inkscape 1.2 draws this rect 20 mm wide at x = 105 mm (--query-x/--query-width) and
        // ignores transform on <svg> elements.
        let text = r#"<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="200mm" viewBox="0 0 200 200" transform="scale(3)">
            <svg x="100" y="100" width="50" viewBox="0 0 10 10" transform="scale(2)"><rect id="r" x="1" y="1" width="4" height="4"/></svg></svg>"#;
        let file = SvgFile::parse(text, None).unwrap();
        let shapes = file.shapes().unwrap();
        let (a, b) = (
            shapes[0].ctm * kurbo::Point::new(1.0, 1.0),
            shapes[0].ctm * kurbo::Point::new(5.0, 5.0),
        );
        assert_eq!((a.x, b.x - a.x), (105.0, 20.0), "got {a:?} {b:?}");
    }

    #[test]
    fn only_the_shapes_asked_for_are_read() {
        // r1's percentage width, the bad group transform and the empty nested <svg> made
        // `--id r2` fail; they matter only when one of their shapes is asked for.
        let text = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
            <rect id="r1" width="50%" height="10"/><rect id="r2" width="10" height="10"/>
            <g id="g" transform="skewX(oops)"><rect id="r3" width="1" height="1"/></g>
            <svg id="z" width="0"><rect id="r4" width="1" height="1"/></svg></svg>"#;
        let file = SvgFile::parse(text, None).unwrap();
        let two = file.shapes_by_id(&["r2".into()]).unwrap();
        assert_eq!((two.len(), two[0].name.as_str()), (1, "#r2"));
        let err = |id: &str| file.shapes_by_id(&[id.into()]).unwrap_err();
        assert!(
            err("r1").contains("#r1: attribute width=\"50%\""),
            "got {}",
            err("r1")
        );
        assert!(
            err("r3").starts_with("#r3 is inside #g, whose transform="),
            "got {}",
            err("r3")
        );
        assert!(
            err("r4").starts_with("#r4 is inside the nested <svg> #z, which has zero"),
            "got {}",
            err("r4")
        );
        assert!(
            file.shapes().unwrap_err().contains("#r1"),
            "without ids every shape is read"
        );
    }

    #[test]
    fn a_shape_chosen_twice_is_refused_by_name() {
        let text = r#"<svg xmlns="http://www.w3.org/2000/svg"><rect id="a" width="1" height="1"/><rect id="b" width="1" height="1"/></svg>"#;
        let file = SvgFile::parse(text, None).unwrap();
        let err = file
            .shapes_by_id(&["a".into(), "b".into(), "a".into()])
            .err()
            .unwrap_or_default();
        assert!(
            err.contains("--id \"a\" is given twice (choice 1 and 3)"),
            "got {err:?}"
        );
    }

    #[test]
    fn a_shape_without_id_never_takes_another_elements_id_as_its_key() {
        // The stand-in `shape1` of the first rect was #shape1's id too, so connect wrote
        // `dformer-cut-shape1` (and every hole id) twice.
        let text = r#"<svg xmlns="http://www.w3.org/2000/svg"><rect width="1" height="1"/><rect id="shape1" width="1" height="1"/></svg>"#;
        let file = SvgFile::parse(text, None).unwrap();
        let keys: Vec<String> = file.shapes().unwrap().into_iter().map(|s| s.key).collect();
        assert_eq!(keys, ["shape1_", "shape1"]);
    }

    #[test]
    fn rect_radii_follow_the_svg_rules() {
        let text = r#"<svg xmlns="http://www.w3.org/2000/svg"><rect x="0" y="0" width="10" height="4" rx="3"/></svg>"#;
        let file = SvgFile::parse(text, None).unwrap();
        let d = &file.shapes().unwrap()[0].d;
        // ry takes rx's value (3) and is clamped to half the height (2); rx stays 3.
        assert!(d.contains("A 3 2 0 0 1"), "wanted radii 3 and 2 in {d}");
    }

    #[test]
    fn bad_files_and_shapes_are_named() {
        assert!(SvgFile::parse("<html/>", None)
            .err()
            .unwrap_or_default()
            .contains("not an SVG"));
        let text = r#"<svg xmlns="http://www.w3.org/2000/svg"><circle id="c" r="0"/></svg>"#;
        let err = SvgFile::parse(text, None).unwrap().shapes().unwrap_err();
        assert!(err.contains("#c") && err.contains("radius"), "got {err}");
    }
}
