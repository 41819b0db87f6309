//! The WASM edge: JS values → DTOs → [`crate::api`] → DTOs → JS values.
//! Every error becomes a JS `Error` whose message is the core's user-facing text.

use crate::api::{self, path::PathDto};
use crate::error::Error;
use serde::de::DeserializeOwned;
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// The one error helper: any core error → JS `Error` with its message.
fn js_error(e: Error) -> JsError {
    JsError::new(&e.to_string())
}

/// Reads a JS value as a DTO; a shape mismatch names the argument.
fn from_js<T: DeserializeOwned>(value: JsValue, what: &str) -> Result<T, JsError> {
    serde_wasm_bindgen::from_value(value)
        .map_err(|e| js_error(Error::Shape { detail: format!("{what}: {e}") }))
}

/// Writes a DTO as plain JS objects and arrays.
fn to_js<T: Serialize>(value: &T) -> Result<JsValue, JsError> {
    value
        .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&format!("internal error while returning the result: {e}")))
}

/// `measure(path, accuracy?)` → `{ perimeter, area, orientation, bounds, centroid }`.
#[wasm_bindgen]
pub fn measure(path: JsValue, accuracy: Option<f64>) -> Result<JsValue, JsError> {
    let path: PathDto = from_js(path, "path")?;
    to_js(&api::measure(&path, accuracy).map_err(js_error)?)
}

/// `connect(pieces, options)` → `{ count, pitch, pieces: [PieceResult, PieceResult], warnings }`.
#[wasm_bindgen]
pub fn connect(pieces: JsValue, options: JsValue) -> Result<JsValue, JsError> {
    let pieces: Vec<api::path::PathDto> = from_js(pieces, "pieces")?;
    let options: api::connect::ConnectOptionsDto =
        if options.is_undefined() || options.is_null() { Default::default() } else { from_js(options, "options")? };
    to_js(&api::connect::connect(&pieces, &options).map_err(js_error)?)
}

/// `normalize(paths, options)` → `{ paths, scales, perimeter }`.
#[wasm_bindgen]
pub fn normalize(paths: JsValue, options: JsValue) -> Result<JsValue, JsError> {
    let paths: Vec<PathDto> = from_js(paths, "paths")?;
    let options: api::normalize::NormalizeOptionsDto =
        if options.is_undefined() || options.is_null() { Default::default() } else { from_js(options, "options")? };
    to_js(&api::normalize::normalize(&paths, &options).map_err(js_error)?)
}

/// `pathFromSvg(d)` → one path per subpath of the SVG path data `d`.
#[wasm_bindgen(js_name = pathFromSvg)]
pub fn path_from_svg(d: JsValue) -> Result<JsValue, JsError> {
    let d = d.as_string().ok_or_else(|| {
        js_error(Error::Shape { detail: "pathFromSvg expects SVG path data as a string (the d attribute)".into() })
    })?;
    to_js(&api::svg::path_from_svg(&d).map_err(js_error)?)
}

/// `pathToSvg(path)` → SVG path data string.
#[wasm_bindgen(js_name = pathToSvg)]
pub fn path_to_svg(path: JsValue) -> Result<String, JsError> {
    let path: PathDto = from_js(path, "path")?;
    api::svg::path_to_svg(&path).map_err(js_error)
}

/// The relative accuracy used when none is given.
#[wasm_bindgen(js_name = DEFAULT_ACCURACY)]
pub fn default_accuracy() -> f64 {
    crate::arclen::DEFAULT_ACCURACY
}
