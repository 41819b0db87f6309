//! SVG viewports, read the way Inkscape 1.2 draws them (checked with `inkscape --query-*`);
//! the extension's `dformer_viewport.py` follows the same rules.
//!
//! The page: one user unit (root viewBox unit) measures `width / viewBox width` CSS px across
//! and `height / viewBox height` down; `preserveAspectRatio` picks the smaller (`meet`, the
//! default) or the larger (`slice`). With `none` and unequal scales a length depends on its
//! direction, so a perimeter has no single value: such a file is refused. A missing or
//! percentage `width`/`height` is that share of the viewBox size (Inkscape's rule); without a
//! viewBox one user unit is one px.
//!
//! A nested `<svg>` maps its content into the rectangle `x, y, width, height` of its parent's
//! user space (percentages of the parent viewport, missing size = 100%) through its own
//! viewBox and `preserveAspectRatio`, `none` included: an affine map like a group's
//! transform. Inkscape 1.2 ignores `transform` on `<svg>` elements, and so does this.

use crate::units::length_px;
use kurbo::Affine;
use roxmltree::Node;
use svgtypes::{Align, AspectRatio, Length, LengthUnit, ViewBox};

/// A length attribute: absolute (in user units, i.e. CSS px), a percentage, or missing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Len {
    Abs(f64),
    Percent(f64),
    Missing,
}

/// How messages name an `<svg>` element.
pub fn svg_name(n: Node) -> String {
    if n.parent_element().is_none() {
        "the page".into()
    } else {
        match n.attribute("id") {
            Some(id) => format!("the nested <svg> #{id}"),
            None => "a nested <svg>".into(),
        }
    }
}

/// Reads a length attribute; anything but a number, an absolute unit or `%` is refused.
pub fn length(n: Node, name: &str) -> Result<Len, String> {
    let Some(raw) = n.attribute(name).filter(|v| !v.trim().is_empty()) else {
        return Ok(Len::Missing);
    };
    let bad = || {
        format!(
            "{}: {name}=\"{raw}\" cannot be read; use a number, an absolute unit or %",
            svg_name(n)
        )
    };
    match raw.trim().parse::<Length>() {
        Ok(l) if l.unit == LengthUnit::Percent => Ok(Len::Percent(l.number)),
        Ok(_) => length_px(raw).map(Len::Abs).ok_or_else(bad),
        Err(_) => Err(bad()),
    }
}

/// A usable viewBox (width and height > 0).
pub fn view_box(n: Node) -> Option<ViewBox> {
    n.attribute("viewBox")
        .and_then(|v| v.parse::<ViewBox>().ok())
        .filter(|v| v.w > 0.0 && v.h > 0.0)
}

/// `preserveAspectRatio`, SVG's default (`xMidYMid meet`) when missing or unreadable.
pub fn aspect(n: Node) -> AspectRatio {
    n.attribute("preserveAspectRatio")
        .and_then(|v| v.parse().ok())
        .unwrap_or_default()
}

/// Viewport size per viewBox unit (sx, sy) after `preserveAspectRatio`.
pub fn scales(vb: ViewBox, w: f64, h: f64, ar: AspectRatio) -> (f64, f64) {
    let (sx, sy) = (w / vb.w, h / vb.h);
    if ar.align == Align::None {
        (sx, sy)
    } else {
        let s = if ar.slice { sx.max(sy) } else { sx.min(sy) };
        (s, s)
    }
}

/// CSS px per root user unit, the same along every direction, as Inkscape draws the page.
pub fn page_px_per_user(root: Node) -> Result<f64, String> {
    let Some(vb) = view_box(root) else {
        return Ok(1.0);
    };
    let mut size = [0.0; 2];
    for (slot, (name, full)) in size.iter_mut().zip([("width", vb.w), ("height", vb.h)]) {
        *slot = match length(root, name)? {
            Len::Missing => full,
            Len::Percent(p) => full * p / 100.0,
            Len::Abs(v) => v,
        };
        if !(*slot > 0.0 && slot.is_finite()) {
            return Err(format!(
                "the page's {name}=\"{}\" is not a positive length",
                root.attribute(name).unwrap_or_default()
            ));
        }
    }
    let ar = aspect(root);
    let (sx, sy) = (size[0] / vb.w, size[1] / vb.h);
    if ar.align == Align::None && (sx - sy).abs() > 1e-9 * sx.max(sy) {
        return Err(format!(
            "the page stretches the drawing unequally (preserveAspectRatio=\"none\", {sx:.6} px \
             per user unit across, {sy:.6} down), so a length depends on its direction and a \
             perimeter has no single value; make the page size proportional to the viewBox, or \
             remove preserveAspectRatio"
        ));
    }
    Ok(scales(vb, size[0], size[1], ar).0)
}

/// Inkscape's page size when the root has neither a viewBox nor an absolute width/height.
const DEFAULT_SIZE: (f64, f64) = (300.0, 150.0);

/// The page's viewport size in root user units (what nested percentages refer to).
pub fn page_size(root: Node) -> (f64, f64) {
    if let Some(vb) = view_box(root) {
        return (vb.w, vb.h);
    }
    let abs = |name, default| match length(root, name) {
        Ok(Len::Abs(v)) if v > 0.0 => v,
        _ => default,
    };
    (abs("width", DEFAULT_SIZE.0), abs("height", DEFAULT_SIZE.1))
}

/// A nested `<svg>`: its map into the parent's user space, and the size of the viewport it
/// makes for its content. `parent` is the parent viewport's size.
pub fn nested(n: Node, parent: (f64, f64)) -> Result<(Affine, (f64, f64)), String> {
    let resolve = |name, reference: f64, default: f64| {
        Ok::<f64, String>(match length(n, name)? {
            Len::Missing => default,
            Len::Percent(p) => reference * p / 100.0,
            Len::Abs(v) => v,
        })
    };
    let (x, y) = (resolve("x", parent.0, 0.0)?, resolve("y", parent.1, 0.0)?);
    let (w, h) = (
        resolve("width", parent.0, parent.0)?,
        resolve("height", parent.1, parent.1)?,
    );
    if !(w > 0.0 && h > 0.0) {
        return Err(format!(
            "{}, which has zero or negative width or height (SVG draws nothing in it)",
            svg_name(n)
        ));
    }
    let Some(vb) = view_box(n) else {
        return Ok((Affine::translate((x, y)), (w, h)));
    };
    let ar = aspect(n);
    let (sx, sy) = scales(vb, w, h, ar);
    let (ax, ay) = match ar.align {
        Align::None | Align::XMinYMin => (0.0, 0.0),
        Align::XMidYMin => (0.5, 0.0),
        Align::XMaxYMin => (1.0, 0.0),
        Align::XMinYMid => (0.0, 0.5),
        Align::XMidYMid => (0.5, 0.5),
        Align::XMaxYMid => (1.0, 0.5),
        Align::XMinYMax => (0.0, 1.0),
        Align::XMidYMax => (0.5, 1.0),
        Align::XMaxYMax => (1.0, 1.0),
    };
    let tx = x + (w - vb.w * sx) * ax - vb.x * sx;
    let ty = y + (h - vb.h * sy) * ay - vb.y * sy;
    Ok((Affine::new([sx, 0.0, 0.0, sy, tx, ty]), (vb.w, vb.h)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn root_scale(attrs: &str) -> Result<f64, String> {
        let text = format!(r#"<svg xmlns="http://www.w3.org/2000/svg" {attrs}/>"#);
        let doc = roxmltree::Document::parse(&text).unwrap();
        page_px_per_user(doc.root_element())
    }

    const MM: f64 = 96.0 / 25.4;

    #[test]
    fn the_page_scale_is_the_smaller_one_unless_sliced() {
        // 200mm x 100mm page, 100 x 100 viewBox: Inkscape 1.2 draws 1 user unit = 1 mm
        // (`inkscape --query-width` of a 50-unit square: 188.976 px = 50 mm); slice: 2 mm.
        let meet = root_scale(r#"width="200mm" height="100mm" viewBox="0 0 100 100""#).unwrap();
        assert!(
            (meet - MM).abs() < 1e-12,
            "wanted 1 mm per unit, got {meet} px"
        );
        let slice = root_scale(
            r#"width="200mm" height="100mm" viewBox="0 0 100 100" preserveAspectRatio="xMinYMin slice""#,
        )
        .unwrap();
        assert!(
            (slice - 2.0 * MM).abs() < 1e-12,
            "wanted 2 mm per unit, got {slice} px"
        );
    }

    #[test]
    fn a_stretched_page_is_refused_and_a_proportional_one_is_not() {
        let e = root_scale(
            r#"width="200mm" height="100mm" viewBox="0 0 100 100" preserveAspectRatio="none""#,
        )
        .unwrap_err();
        assert!(
            e.contains("preserveAspectRatio=\"none\"") && e.contains("unequally"),
            "got {e}"
        );
        let ok = root_scale(
            r#"width="200mm" height="200mm" viewBox="0 0 100 100" preserveAspectRatio="none""#,
        )
        .unwrap();
        assert!((ok - 2.0 * MM).abs() < 1e-12);
    }

    #[test]
    fn missing_and_percentage_sizes_are_shares_of_the_viewbox_like_inkscape() {
        // Inkscape 1.2: width="200mm" without height over a 100 x 100 viewBox draws 1 px per unit.
        let s = root_scale(r#"width="200mm" viewBox="0 0 100 100""#).unwrap();
        assert!((s - 1.0).abs() < 1e-12, "got {s}");
        let s = root_scale(r#"width="50%" height="200mm" viewBox="0 0 100 100""#).unwrap();
        assert!((s - 0.5).abs() < 1e-12, "got {s}");
        assert_eq!(root_scale(r#"width="200mm" height="100mm""#).unwrap(), 1.0);
        assert!(root_scale(r#"width="3em" viewBox="0 0 1 1""#)
            .unwrap_err()
            .contains("3em"));
    }

    #[test]
    fn nested_viewports_map_like_inkscape() {
        // Inkscape 1.2 (--query-x/--query-width, in mm): the rect at x 6 is drawn at 52 mm, 8 mm wide.
        let text = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200">
            <svg id="n" x="10" y="20" width="60" height="20" viewBox="5 5 10 10" preserveAspectRatio="xMaxYMax meet"/>
            <svg id="p" x="10%" width="25%" height="50" viewBox="0 0 10 10" preserveAspectRatio="none"/>
            <svg id="z" width="0"/></svg>"#;
        let doc = roxmltree::Document::parse(text).unwrap();
        let root = doc.root_element();
        let kid = |id| {
            root.children()
                .find(|c| c.attribute("id") == Some(id))
                .unwrap()
        };
        let (m, size) = nested(kid("n"), page_size(root)).unwrap();
        let (p, q) = (
            m * kurbo::Point::new(6.0, 6.0),
            m * kurbo::Point::new(10.0, 10.0),
        );
        assert!(
            (p.x - 52.0).abs() < 1e-12 && (q.x - p.x - 8.0).abs() < 1e-12,
            "got {p:?} {q:?}"
        );
        assert_eq!(size, (10.0, 10.0));
        // x = 10% of 200, width 25% of 200 = 50, height 50: none stretches 5 across, 5 down.
        let (m, _) = nested(kid("p"), page_size(root)).unwrap();
        assert_eq!(m.as_coeffs(), [5.0, 0.0, 0.0, 5.0, 20.0, 0.0]);
        let e = nested(kid("z"), page_size(root)).unwrap_err();
        assert!(e.contains("#z") && e.contains("zero"), "got {e}");
    }
}
