//! Connectors written as laser layers, the same layout as the Inkscape extension
//! (`inkscape-extension/dformer_layers.py`): top-level layers `D-former cut` (red hairline:
//! holes and slots), `D-former score` (blue hairline: start marks, the seam line with an
//! allowance), `D-former engrave` (black text:
//! connector numbers); in each, one group per piece with id `dformer-<layer>-<piece>`, which a
//! later run replaces.

use crate::splice::{end_tag_start, escape, namespaces, Edits};
use roxmltree::Node;

/// (layer key, label, colour).
pub const LAYERS: [(&str, &str, &str); 3] = [
    ("cut", "D-former cut", "#ff0000"),
    ("score", "D-former score", "#0000ff"),
    ("engrave", "D-former engrave", "#000000"),
];

/// A hairline: 0.001 in, in CSS px (divide by px per user unit for user units).
pub const HAIRLINE_PX: f64 = 0.096;

/// What one piece adds to one layer.
pub struct Group {
    pub layer: &'static str,
    pub piece_key: String,
    pub title: String,
    /// Child elements, already serialized.
    pub body: String,
}

fn colour(layer: &str) -> &'static str {
    LAYERS
        .iter()
        .find(|l| l.0 == layer)
        .map(|l| l.2)
        .unwrap_or("#000000")
}

/// `<path>` children for path data strings, hairline in the layer's colour.
pub fn paths(layer: &str, ids: &str, data: &[String], hairline_user: f64) -> String {
    let style = format!(
        "fill:none;stroke:{};stroke-width:{hairline_user:.6}",
        colour(layer)
    );
    data.iter()
        .enumerate()
        .map(|(k, d)| {
            format!(
                "<path id=\"{}-{}\" style=\"{style}\" d=\"{}\"/>",
                escape(ids),
                k + 1,
                escape(d)
            )
        })
        .collect()
}

/// `<text>` children: number `text` centred at `at`, turned by `angle` degrees, `size` high
/// (user units; the core sizes each label so that its box clears holes, slots and the cut line).
pub fn labels(ids: &str, items: &[(String, [f64; 2], f64, f64)]) -> String {
    let style = format!(
        "font-family:sans-serif;text-anchor:middle;dominant-baseline:central;fill:{};stroke:none",
        colour("engrave")
    );
    items
        .iter()
        .enumerate()
        .map(|(k, (text, [x, y], angle, size))| {
            format!(
                "<text id=\"{}-{}\" x=\"{x:.6}\" y=\"{y:.6}\" transform=\"rotate({angle:.6} {x:.6} {y:.6})\" style=\"font-size:{size:.6};{style}\">{}</text>",
                escape(ids),
                k + 1,
                escape(text)
            )
        })
        .collect()
}

/// Adds the groups to their layers: into an existing D-former layer (replacing the same
/// piece's group from an earlier run) or into a new top-level layer before `</svg>`.
pub fn write(source: &str, root: Node, groups: &[Group], edits: &mut Edits) -> Result<(), String> {
    let (decl, ink) = namespaces(root);
    let root_end = end_tag_start(source, root).ok_or("the <svg> element is empty (<svg/>)")?;
    for (key, label, _) in LAYERS {
        let mine: Vec<&Group> = groups.iter().filter(|g| g.layer == key).collect();
        if mine.is_empty() {
            continue;
        }
        let layer_id = format!("dformer-{key}");
        let mut xml = String::new();
        for g in &mine {
            let gid = format!("dformer-{key}-{}", g.piece_key);
            xml.push_str(&format!(
                "\n  <g id=\"{}\" {ink}:label=\"{}\">{}</g>",
                escape(&gid),
                escape(&g.title),
                g.body
            ));
            if let Some(old) = root
                .descendants()
                .find(|n| n.attribute("id") == Some(gid.as_str()))
            {
                edits.replace(old.range(), String::new());
            }
        }
        let existing = root
            .descendants()
            .find(|n| n.attribute("id") == Some(layer_id.as_str()));
        match existing.and_then(|layer| end_tag_start(source, layer)) {
            Some(at) => edits.replace(at..at, format!("{xml}\n")),
            None => {
                if let Some(layer) = existing {
                    // A self-closing old layer: replace it whole.
                    edits.replace(layer.range(), String::new());
                }
                edits.replace(
                    root_end..root_end,
                    format!("<g id=\"{layer_id}\"{decl} {ink}:groupmode=\"layer\" {ink}:label=\"{label}\">{xml}\n</g>\n"),
                );
            }
        }
    }
    Ok(())
}
