//! Host command names in messages: the one table `messages/commands.json`, compiled in.
//!
//! Every message says what to do in plain words ("close the path"); a host that has its own
//! menus (Inkscape, through `dformer json` requests with `"host": "inkscape"`, or the extension's
//! own messages through op `advise`) gets each plain phrase replaced by that host's column
//! ("close the path (Node tool: … Join selected nodes …)"). The CLI itself prints plain words.

use serde::Deserialize;
use std::sync::OnceLock;

const TABLE: &str = include_str!("../../messages/commands.json");

#[derive(Deserialize)]
struct Table {
    hosts: Vec<String>,
    advice: Vec<serde_json::Map<String, serde_json::Value>>,
    /// Why a drawn element is not a piece, by kind (`open`, or the element's tag name).
    skipped: std::collections::BTreeMap<String, String>,
}

fn table() -> &'static Table {
    static T: OnceLock<Table> = OnceLock::new();
    // The table is part of the source; a broken one fails the `table_is_complete` test.
    T.get_or_init(|| {
        serde_json::from_str(TABLE).unwrap_or(Table { hosts: vec!["plain".into()], advice: Vec::new(), skipped: Default::default() })
    })
}

/// Why an element of this kind (`open`, `text`, `image`, `use`, `foreignObject`) is skipped;
/// `None` for a kind that is offered.
pub fn skipped(kind: &str) -> Option<&'static str> {
    table().skipped.get(kind).map(String::as_str)
}

/// `text` with every plain phrase of the table replaced by `host`'s wording. An unknown host
/// is an error naming the known ones; `plain` returns the text unchanged.
pub fn render(text: &str, host: &str) -> Result<String, String> {
    let t = table();
    if !t.hosts.iter().any(|h| h == host) {
        return Err(format!("unknown host \"{host}\"; the table knows: {}", t.hosts.join(", ")));
    }
    let mut out = text.to_string();
    for row in &t.advice {
        let (Some(plain), Some(own)) = (row.get("plain").and_then(|v| v.as_str()), row.get(host).and_then(|v| v.as_str())) else {
            continue;
        };
        if plain != own {
            out = out.replace(plain, own);
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_is_complete() {
        let t: Table = serde_json::from_str(TABLE).expect("messages/commands.json is valid JSON");
        for kind in ["open", "text", "image", "use", "foreignObject"] {
            assert!(t.skipped.get(kind).is_some_and(|r| !r.is_empty()), "no skipped reason for {kind}");
        }
        for row in &t.advice {
            for h in &t.hosts {
                let text = row.get(h).and_then(|v| v.as_str()).unwrap_or("");
                assert!(!text.is_empty(), "row {row:?} has no {h} wording");
                let plain = row["plain"].as_str().unwrap_or("");
                assert!(text.starts_with(plain), "{h}: {text:?} does not start with the plain phrase {plain:?}");
            }
        }
    }

    #[test]
    fn the_core_open_path_message_gets_each_hosts_command() {
        // Inkscape's extension said "close the path (Object > Path > Join)": an Illustrator menu.
        let open = dformer::Error::OpenPath { piece: 0 }.to_string();
        assert!(!open.contains("Object >"), "the core names no host menu: {open}");
        let ink = render(&open, "inkscape").unwrap();
        assert!(ink.contains("Join selected nodes") && ink.contains("Path > Combine"), "got {ink}");
        assert!(!ink.contains("Object >"), "got {ink}");
        let ai = render(&open, "illustrator").unwrap();
        assert!(ai.contains("(Object > Path > Join)"), "got {ai}");
        assert_eq!(render(&open, "plain").unwrap(), open);
        assert!(render(&open, "corel").unwrap_err().contains("plain, illustrator, inkscape"));
    }
}
