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

/// The relative accuracy used when none is given.
#[wasm_bindgen(js_name = DEFAULT_ACCURACY)]
pub fn default_accuracy() -> f64 {
    crate::arclen::DEFAULT_ACCURACY
}
