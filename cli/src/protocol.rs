//! `dformer json`: the core's API as JSON on stdin/stdout — the bridge the Inkscape extension uses.
//!
//! A request names the operation and passes the contract's arguments under their JS names:
//!
//! ```json
//! {"op": "measure", "path": {"closed": true, "points": [...]}, "accuracy": 1e-9}
//! {"op": "normalize", "paths": [...], "options": {"target": "largest"}}
//! {"op": "connect", "pieces": [...], "options": {"kind": "stitch", "count": 40}}
//! {"op": "simulate", "pieces": [...], "options": {"offset": 0, "resolution": 128}}
//! {"op": "formFigures", "form": <a simulate result>, "options": {"mmPerUnit": 1, "density": 2400}}
//! {"op": "placeOnForm", "form": <a simulate result>, "points": [[[x, y], ...], [[x, y], ...]]}
//! {"op": "pathFromSvg", "d": "M 0 0 L 10 0 ..."}
//! {"op": "pathToSvg", "path": {...}}
//! {"op": "DEFAULT_ACCURACY"}
//! {"op": "advise", "text": "… close the path …", "host": "inkscape"}
//! {"op": "defaults"}
//! ```
//!
//! Any request may say `"host": "inkscape"` (or `illustrator`, `plain`): its error message then
//! names that host's commands (`crate::advice`, the table `messages/commands.json`); `advise`
//! renders a message of the caller's own the same way.
//!
//! The answer is the function's result exactly as the WASM build returns it to JavaScript, or
//! `{"error": "<the core's user-facing message>"}`. A JSON array of requests is answered by an
//! array of answers in the same order (one process start for many calls).

use dformer::api;
use dformer::Error;
use serde::de::DeserializeOwned;
use serde::Serialize;
use serde_json::{json, Map, Value};

/// Every operation name [`call`] understands, for messages and `--help`.
pub const OPERATIONS: &[&str] = &[
    "measure",
    "normalize",
    "connect",
    "simulate",
    "formFigures",
    "placeOnForm",
    "pathFromSvg",
    "pathToSvg",
    "DEFAULT_ACCURACY",
    "advise",
    "defaults",
];

/// Reads argument `name` of the request as the DTO the core expects. A missing required
/// argument or a wrong shape is the core's `Invalid input` error naming the argument.
fn arg<T: DeserializeOwned>(request: &Map<String, Value>, name: &str) -> Result<T, Error> {
    let value = request.get(name).cloned().unwrap_or(Value::Null);
    serde_json::from_value(value).map_err(|e| Error::Shape {
        detail: format!("{name}: {e}"),
    })
}

/// Like [`arg`], but an absent or `null` argument is the empty object (all options defaulted).
fn options<T: DeserializeOwned>(request: &Map<String, Value>) -> Result<T, Error> {
    let value = match request.get("options") {
        None | Some(Value::Null) => Value::Object(Map::new()),
        Some(v) => v.clone(),
    };
    serde_json::from_value(value).map_err(|e| Error::Shape {
        detail: format!("options: {e}"),
    })
}

fn out<T: Serialize>(value: T) -> Result<Value, Error> {
    serde_json::to_value(value).map_err(|e| Error::Shape {
        detail: format!("internal error while returning the result: {e}"),
    })
}

/// Runs one operation on its JSON arguments; `Err` carries the core's message.
pub fn call(op: &str, request: &Map<String, Value>) -> Result<Value, Error> {
    match op {
        "measure" => out(api::measure(
            &arg(request, "path")?,
            arg(request, "accuracy")?,
        )?),
        "normalize" => out(api::normalize::normalize(
            &arg::<Vec<_>>(request, "paths")?,
            &options(request)?,
        )?),
        "connect" => out(api::connect::connect(
            &arg::<Vec<_>>(request, "pieces")?,
            &options(request)?,
        )?),
        "simulate" => out(api::simulate::simulate(
            &arg::<Vec<_>>(request, "pieces")?,
            &options(request)?,
        )?),
        "formFigures" => out(api::form::figures(&arg(request, "form")?, &options(request)?)?),
        "placeOnForm" => out(api::form::place(
            &arg(request, "form")?,
            &arg::<Vec<_>>(request, "points")?,
        )?),
        "pathFromSvg" => out(api::svg::path_from_svg(&arg::<String>(request, "d")?)?),
        "pathToSvg" => out(api::svg::path_to_svg(&arg(request, "path")?)?),
        "DEFAULT_ACCURACY" => out(dformer::DEFAULT_ACCURACY),
        "advise" => out(crate::advice::render(&arg::<String>(request, "text")?, &host(request)?)
            .map_err(|detail| Error::Shape { detail })?),
        "defaults" => out(api::defaults()),
        other => Err(Error::Shape {
            detail: format!(
                "unknown operation `{other}`; this build knows: {}",
                OPERATIONS.join(", ")
            ),
        }),
    }
}

/// The request's `host` (default `plain`).
fn host(request: &Map<String, Value>) -> Result<String, Error> {
    Ok(arg::<Option<String>>(request, "host")?.unwrap_or_else(|| "plain".into()))
}

/// Answers one request object: the result, or `{"error": message}` (in the words of the
/// request's `host`).
pub fn answer(request: &Value) -> (Value, bool) {
    let Some(object) = request.as_object() else {
        return (
            json!({ "error": "Invalid input: a request must be a JSON object like {\"op\": \"measure\", \"path\": {...}}" }),
            false,
        );
    };
    let op = match object.get("op") {
        Some(Value::String(op)) => op.as_str(),
        _ => {
            return (
                json!({ "error": "Invalid input: the request has no \"op\" naming the operation" }),
                false,
            )
        }
    };
    match call(op, object) {
        Ok(value) => (value, true),
        Err(e) => {
            let text = e.to_string();
            let text = host(object).ok().and_then(|h| crate::advice::render(&text, &h).ok()).unwrap_or(text);
            (json!({ "error": text }), false)
        }
    }
}

/// Answers a whole stdin text: one request or an array of them. Returns the JSON to print and
/// whether every request succeeded (the process exit status).
pub fn answer_text(text: &str) -> (Value, bool) {
    match serde_json::from_str::<Value>(text) {
        Err(e) => (
            json!({ "error": format!("Invalid input: the request is not valid JSON ({e})") }),
            false,
        ),
        Ok(Value::Array(requests)) => {
            let mut ok = true;
            let answers = requests
                .iter()
                .map(|r| {
                    let (value, good) = answer(r);
                    ok &= good;
                    value
                })
                .collect();
            (Value::Array(answers), ok)
        }
        Ok(request) => answer(&request),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(side: f64) -> Value {
        json!({"closed": true, "points": [
            {"anchor": [0.0, 0.0]}, {"anchor": [side, 0.0]}, {"anchor": [side, side]}, {"anchor": [0.0, side]}
        ]})
    }

    #[test]
    fn measure_answers_the_core_result() {
        let (value, ok) = answer_text(&json!({"op": "measure", "path": square(10.0)}).to_string());
        assert!(ok, "wanted success, got {value}");
        assert_eq!(
            value["perimeter"].as_f64(),
            Some(40.0),
            "wanted perimeter 40, got {value}"
        );
    }

    #[test]
    fn batch_answers_each_request_in_order_and_fails_if_any_fails() {
        let text = json!([
            {"op": "measure", "path": square(1.0)},
            {"op": "measure", "path": {"closed": false, "points": [{"anchor": [0, 0]}, {"anchor": [1, 0]}]}},
        ])
        .to_string();
        let (value, ok) = answer_text(&text);
        assert!(
            !ok,
            "wanted failure because the second path is open, got {value}"
        );
        assert_eq!(
            value[0]["perimeter"].as_f64(),
            Some(4.0),
            "wanted 4 first, got {value}"
        );
        let message = value[1]["error"].as_str().unwrap_or_default();
        assert!(
            message.contains("open"),
            "wanted the open-path message second, got {value}"
        );
    }

    #[test]
    fn errors_name_the_commands_of_the_host_that_asked() {
        let open = json!({"closed": false, "points": [{"anchor": [0, 0]}, {"anchor": [1, 0]}]});
        let (plain, _) = answer(&json!({"op": "measure", "path": open}));
        let (ink, _) = answer(&json!({"op": "measure", "path": open, "host": "inkscape"}));
        let plain = plain["error"].as_str().unwrap_or_default().to_string();
        let ink = ink["error"].as_str().unwrap_or_default().to_string();
        assert!(plain.contains("close the path and try again") && !plain.contains('('), "got {plain}");
        assert!(ink.contains("Join selected nodes"), "got {ink}");
        let (advised, ok) = answer(&json!({"op": "advise", "text": "#t is text: convert it to a path first.", "host": "inkscape"}));
        assert!(ok, "got {advised}");
        assert_eq!(advised, json!("#t is text: convert it to a path (Path > Object to Path) first."));
    }

    #[test]
    fn bad_requests_name_the_problem() {
        for (text, wanted) in [
            ("not json", "not valid JSON"),
            ("42", "must be a JSON object"),
            ("{}", "no \"op\""),
            ("{\"op\": \"frobnicate\"}", "unknown operation `frobnicate`"),
            ("{\"op\": \"measure\"}", "path:"),
        ] {
            let (value, ok) = answer_text(text);
            let message = value["error"].as_str().unwrap_or_default();
            assert!(
                !ok && message.contains(wanted),
                "for {text}: wanted an error containing {wanted:?}, got {value}"
            );
        }
    }
}
