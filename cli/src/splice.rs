//! Editing an SVG file by splicing text at byte ranges that roxmltree reports, so everything
//! not edited — comments, namespaces, Inkscape metadata, formatting — is kept byte for byte.

use crate::svgdoc::{INKSCAPE_NS, SVG_NS};
use roxmltree::Node;
use std::ops::Range;

/// Escapes text for an XML attribute value or text node.
pub fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A set of non-overlapping replacements on one source text.
#[derive(Default)]
pub struct Edits {
    list: Vec<(Range<usize>, String)>,
}

impl Edits {
    pub fn replace(&mut self, range: Range<usize>, text: String) {
        self.list.push((range, text));
    }

    /// Applies every edit; overlapping edits are a bug in the caller and reported as such.
    pub fn apply(mut self, source: &str) -> Result<String, String> {
        self.list.sort_by_key(|(r, _)| (r.start, r.end));
        let mut out = String::with_capacity(source.len() + 1024);
        let mut at = 0;
        for (range, text) in &self.list {
            if range.start < at {
                return Err(format!(
                    "internal error: overlapping edits at byte {}",
                    range.start
                ));
            }
            out.push_str(&source[at..range.start]);
            out.push_str(text);
            at = range.end;
        }
        out.push_str(&source[at..]);
        Ok(out)
    }
}

/// The element's qualified tag prefix as written (`"svg:"` for `<svg:rect>`, else `""`).
pub fn tag_prefix(source: &str, node: Node) -> String {
    let start = node.range().start + 1;
    let name: String = source[start..]
        .chars()
        .take_while(|c| !c.is_whitespace() && *c != '/' && *c != '>')
        .collect();
    match name.split_once(':') {
        Some((p, _)) => format!("{p}:"),
        None => String::new(),
    }
}

/// Byte range of the element's content between its start and end tags (`None` if empty).
pub fn inner_range(node: Node) -> Option<Range<usize>> {
    Some(node.first_child()?.range().start..node.last_child()?.range().end)
}

/// Byte offset of the element's end tag (`</…>`), for inserting new last children.
pub fn end_tag_start(source: &str, node: Node) -> Option<usize> {
    let r = node.range();
    let text = &source[r.clone()];
    if text.ends_with("/>") {
        return None;
    }
    text.rfind("</").map(|i| r.start + i)
}

/// Namespace declarations a new top-level element needs in this document: the SVG default
/// namespace when the root does not make it the default, and Inkscape's when undeclared.
/// Returns (declarations, inkscape prefix).
pub fn namespaces(root: Node) -> (String, String) {
    let mut decl = String::new();
    if root.lookup_namespace_uri(None) != Some(SVG_NS) {
        decl.push_str(&format!(" xmlns=\"{SVG_NS}\""));
    }
    let prefix = match root.lookup_prefix(INKSCAPE_NS) {
        Some(p) if !p.is_empty() => p.to_string(),
        _ => {
            decl.push_str(&format!(" xmlns:inkscape=\"{INKSCAPE_NS}\""));
            "inkscape".into()
        }
    };
    (decl, prefix)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edits_splice_in_order_and_keep_the_rest() {
        let mut e = Edits::default();
        e.replace(6..7, "X".into());
        e.replace(0..1, "<".into());
        assert_eq!(e.apply("<abcd>e</abcd>").unwrap(), "<abcd>X</abcd>");
    }

    #[test]
    fn prefixes_and_end_tags_are_found() {
        let src = r#"<svg:svg xmlns:svg="http://www.w3.org/2000/svg"><svg:rect/></svg:svg>"#;
        let doc = roxmltree::Document::parse(src).unwrap();
        let root = doc.root_element();
        let rect = root.first_element_child().unwrap();
        assert_eq!(tag_prefix(src, rect), "svg:");
        assert_eq!(&src[end_tag_start(src, root).unwrap()..], "</svg:svg>");
        let (decl, prefix) = namespaces(root);
        assert!(
            decl.contains("xmlns=\"http://www.w3.org/2000/svg\"")
                && decl.contains("xmlns:inkscape"),
            "got {decl}"
        );
        assert_eq!(prefix, "inkscape");
    }
}
