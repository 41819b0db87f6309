//! Arbitrary bytes → JSON → every api function (what a host could send through the WASM
//! binding). Any panic is a bug: the core must answer Ok or a user-facing Err.
#![no_main]

use dformer::api::{self, normalize::NormalizeOptionsDto, path::PathDto};
use libfuzzer_sys::fuzz_target;
use serde_json::Value;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    // The raw text is also SVG path data.
    if let Ok(paths) = api::path_from_svg(text) {
        for p in &paths {
            let _ = api::measure(p, None);
            let _ = api::path_to_svg(p);
        }
        let _ = api::normalize(&paths, &NormalizeOptionsDto::default());
    }
    let Ok(v) = serde_json::from_str::<Value>(text) else { return };
    if let Ok(p) = serde_json::from_value::<PathDto>(v.clone()) {
        let acc = v.get("accuracy").and_then(Value::as_f64);
        let _ = api::measure(&p, acc);
        let _ = api::path_to_svg(&p);
    }
    let paths: Vec<PathDto> = v.get("paths").cloned().and_then(|p| serde_json::from_value(p).ok()).unwrap_or_default();
    let options: NormalizeOptionsDto = v.get("options").cloned().and_then(|o| serde_json::from_value(o).ok()).unwrap_or_default();
    let _ = api::normalize(&paths, &options);
});
