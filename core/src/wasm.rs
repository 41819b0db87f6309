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

/// Reads an optional `options` argument: `undefined` or `null` is every default.
fn options_or_default<T: DeserializeOwned + Default>(options: JsValue) -> Result<T, JsError> {
    if options.is_undefined() || options.is_null() { Ok(T::default()) } else { from_js(options, "options") }
}

/// Writes a DTO as plain JS objects and arrays.
fn to_js<T: Serialize>(value: &T) -> Result<JsValue, JsError> {
    value
        .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&format!("internal error while returning the result: {e}")))
}

// Fast path for the one large input, a path: flattening it in JS and copying one Float64Array
// costs ~50× less than serde-wasm-bindgen's per-field reflection. Anything not plainly shaped
// like the contract returns undefined, and `path_from_js` falls back to serde, whose error
// names the problem. A missing or null handle is the anchor (a corner), as in the contract.
#[wasm_bindgen(inline_js = r#"
const num2 = (a) => Array.isArray(a) && a.length === 2 && typeof a[0] === 'number' && typeof a[1] === 'number';
export function dformer_flatten_path(p) {
  if (p === null || typeof p !== 'object' || !Array.isArray(p.points)) return undefined;
  if (p.closed !== undefined && typeof p.closed !== 'boolean') return undefined;
  const pts = p.points, n = pts.length, out = new Float64Array(1 + 6 * n);
  out[0] = p.closed === true ? 1 : 0;
  for (let i = 0, k = 1; i < n; i++, k += 6) {
    const q = pts[i];
    if (q === null || typeof q !== 'object') return undefined;
    const a = q.anchor, l = q.left ?? a, r = q.right ?? a;
    if (!num2(a) || !num2(l) || !num2(r)) return undefined;
    out[k] = a[0]; out[k + 1] = a[1]; out[k + 2] = l[0]; out[k + 3] = l[1]; out[k + 4] = r[0]; out[k + 5] = r[1];
  }
  return out;
}
"#)]
extern "C" {
    fn dformer_flatten_path(p: &JsValue) -> Option<Vec<f64>>;
}

/// Reads a path: the flat fast path, else serde (for the precise error message).
fn path_from_js(value: JsValue, what: &str) -> Result<PathDto, JsError> {
    match dformer_flatten_path(&value) {
        Some(flat) => {
            let closed = flat.first() == Some(&1.0);
            let points = flat
                .get(1..)
                .unwrap_or(&[])
                .chunks_exact(6)
                .map(|c| api::path::PointDto {
                    anchor: [c[0], c[1]],
                    left: Some([c[2], c[3]]),
                    right: Some([c[4], c[5]]),
                })
                .collect();
            Ok(PathDto { closed, points })
        }
        None => from_js(value, what),
    }
}

/// `measure(path, accuracy?)` → `{ perimeter, area, orientation, bounds, centroid }`.
#[wasm_bindgen]
pub fn measure(path: JsValue, accuracy: Option<f64>) -> Result<JsValue, JsError> {
    let path: PathDto = path_from_js(path, "path")?;
    to_js(&api::measure(&path, accuracy).map_err(js_error)?)
}

/// Bench only (bench/core.bench.mjs), not part of the contract: validates `path` once, then
/// computes its perimeter `repeats` times (at least once), so the arc-length kernel can be
/// timed from JS without the input conversion. Returns the perimeter.
#[wasm_bindgen(js_name = benchPerimeter)]
pub fn bench_perimeter(path: JsValue, accuracy: Option<f64>, repeats: u32) -> Result<f64, JsError> {
    let path: PathDto = path_from_js(path, "path")?;
    let accuracy = api::accuracy_or_default(accuracy).map_err(js_error)?;
    let contour = path.to_contour(0).map_err(js_error)?;
    let mut p = 0.0;
    for _ in 0..repeats.max(1) {
        p = crate::arclen::perimeter(std::hint::black_box(&contour), accuracy);
    }
    Ok(p)
}

/// `connect(pieces, options)` → `{ count, pitch, pieces: [PieceResult, PieceResult], warnings }`.
#[wasm_bindgen]
pub fn connect(pieces: JsValue, options: JsValue) -> Result<JsValue, JsError> {
    let pieces: Vec<api::path::PathDto> = match api::connect::js::pieces_from_js(&pieces) {
        Some(p) => p,
        None => from_js(pieces, "pieces")?,
    };
    let options: api::connect::ConnectOptionsDto = options_or_default(options)?;
    let result = api::connect::connect(&pieces, &options).map_err(js_error)?;
    match api::connect::js::to_js(&result) {
        Some(v) => Ok(v),
        None => to_js(&result),
    }
}

/// `normalize(paths, options)` → `{ paths, scales, perimeter }`.
#[wasm_bindgen]
pub fn normalize(paths: JsValue, options: JsValue) -> Result<JsValue, JsError> {
    let paths: Vec<PathDto> = from_js(paths, "paths")?;
    let options: api::normalize::NormalizeOptionsDto = options_or_default(options)?;
    to_js(&api::normalize::normalize(&paths, &options).map_err(js_error)?)
}

/// `defaults()` → the default connector options and how each is derived (see `api::defaults`).
#[wasm_bindgen]
pub fn defaults() -> Result<JsValue, JsError> {
    to_js(&api::defaults())
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
    let path: PathDto = path_from_js(path, "path")?;
    api::svg::path_to_svg(&path).map_err(js_error)
}

/// The project's one version number, `[workspace.package] version` in the workspace Cargo.toml
/// (the same as `dformer --version`); the panel shows it in its footer.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// The relative accuracy used when none is given.
#[wasm_bindgen(js_name = DEFAULT_ACCURACY)]
pub fn default_accuracy() -> f64 {
    crate::arclen::DEFAULT_ACCURACY
}

/// `simulate(pieces, options)` → `{ vertices, triangles, piece, seam, flat, stats }` (see `crate::simulate`).
#[wasm_bindgen]
pub fn simulate(pieces: JsValue, options: JsValue) -> Result<JsValue, JsError> {
    let pieces: Vec<api::path::PathDto> = from_js(pieces, "pieces")?;
    let options: api::simulate::SimulateOptionsDto = options_or_default(options)?;
    to_js(&api::simulate::simulate(&pieces, &options).map_err(js_error)?)
}

#[wasm_bindgen]
extern "C" {
    /// A JS function, called with one argument.
    #[wasm_bindgen(js_name = Function)]
    pub type Callback;
    #[wasm_bindgen(method, catch, js_name = call)]
    fn call1(this: &Callback, context: &JsValue, argument: &JsValue) -> Result<JsValue, JsValue>;
}

/// `simulateWithProgress(pieces, options, onProgress)`: `simulate`, calling `onProgress({ done,
/// total, maxStrain })` each time a stage of a non-convex pair's solve ends, and once with
/// `interim` (a converged form at coarser seam samples, shaped as the result) when there is one
/// (see `crate::simulate::progress`); the same result. What the callback throws is ignored.
#[wasm_bindgen(js_name = simulateWithProgress)]
pub fn simulate_with_progress(pieces: JsValue, options: JsValue, on_progress: JsValue) -> Result<JsValue, JsError> {
    let pieces: Vec<api::path::PathDto> = from_js(pieces, "pieces")?;
    let options: api::simulate::SimulateOptionsDto = options_or_default(options)?;
    if !on_progress.is_function() {
        return Err(js_error(Error::Shape { detail: "onProgress: expected a function".into() }));
    }
    let callback: Callback = on_progress.unchecked_into();
    let mut observe = |p: api::simulate::ProgressDto| {
        if let Ok(v) = to_js(&p) {
            let _ = callback.call1(&JsValue::NULL, &v);
        }
    };
    to_js(&api::simulate::simulate_observed(&pieces, &options, &mut observe).map_err(js_error)?)
}

/// `formFigures(form, options?)` → `{ volume, litres, mass, density, height, width, depth, axes, center }`
/// of a `simulate` result (see `crate::api::form`).
#[wasm_bindgen(js_name = formFigures)]
pub fn form_figures(form: JsValue, options: JsValue) -> Result<JsValue, JsError> {
    let form: api::form::FormDto = from_js(form, "form")?;
    let options: api::form::FiguresOptionsDto = options_or_default(options)?;
    to_js(&api::form::figures(&form, &options).map_err(js_error)?)
}

/// `placeOnForm(form, [pointsOfA, pointsOfB])` → the points on the 3D surface of a `simulate` result.
#[wasm_bindgen(js_name = placeOnForm)]
pub fn place_on_form(form: JsValue, points: JsValue) -> Result<JsValue, JsError> {
    let form: api::form::FormDto = from_js(form, "form")?;
    let points: Vec<Vec<[f64; 2]>> = from_js(points, "points")?;
    to_js(&api::form::place(&form, &points).map_err(js_error)?)
}
