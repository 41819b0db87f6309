//! Fast hand-over of a [`ConnectDto`] to JavaScript (wasm32 only).
//!
//! A connect result with 1,000 holes per piece is ~90,000 small JS objects and arrays. Built
//! through serde-wasm-bindgen, every one of them (and every property key) is a separate call
//! across the WASM boundary, which costs several times the geometry. Here the whole result is
//! written into one `f64` buffer in a fixed order and a small JavaScript function builds the
//! plain objects from it in a single pass: the same shape as the serde output, no JSON text.

use super::ConnectDto;
use crate::api::path::PathDto;
use wasm_bindgen::prelude::*;

#[wasm_bindgen(inline_js = r#"
export function dformer_build_connect(f, warnings) {
  let i = 0;
  const pt = () => [f[i++], f[i++]];
  const path = () => {
    const n = f[i++], points = new Array(n);
    for (let k = 0; k < n; k++) {
      const flags = f[i++], p = { anchor: pt() };
      if (flags & 1) p.left = pt();
      if (flags & 2) p.right = pt();
      points[k] = p;
    }
    return { closed: true, points };
  };
  const piece = () => {
    const outline = path();
    const holes = new Array(f[i++]);
    for (let k = 0; k < holes.length; k++) holes[k] = { center: pt(), diameter: f[i++], path: path() };
    const labels = new Array(f[i++]);
    for (let k = 0; k < labels.length; k++) labels[k] = { text: String(f[i++]), at: pt(), angle: f[i++] };
    const marks = new Array(f[i++]);
    for (let k = 0; k < marks.length; k++) marks[k] = path();
    return { outline, holes, labels, marks };
  };
  const count = f[i++], pitch = f[i++];
  const pieces = [piece(), piece()];
  return { count, pitch, pieces, warnings };
}
"#)]
extern "C" {
    fn dformer_build_connect(f: &[f64], warnings: JsValue) -> JsValue;
}

fn path(out: &mut Vec<f64>, p: &PathDto) {
    out.push(p.points.len() as f64);
    for k in &p.points {
        let flags = k.left.is_some() as u8 | (k.right.is_some() as u8) << 1;
        out.push(flags as f64);
        out.extend_from_slice(&k.anchor);
        if let Some(l) = k.left {
            out.extend_from_slice(&l);
        }
        if let Some(r) = k.right {
            out.extend_from_slice(&r);
        }
    }
}

/// The result as plain JS objects, or `None` when a label is not a plain connector number
/// (then the caller falls back to serde).
pub fn to_js(dto: &ConnectDto) -> Option<JsValue> {
    let mut f = Vec::with_capacity(64 * (dto.pieces[0].holes.len() + 8) * 2);
    f.push(dto.count as f64);
    f.push(dto.pitch);
    for p in &dto.pieces {
        path(&mut f, &p.outline);
        f.push(p.holes.len() as f64);
        for h in &p.holes {
            f.extend_from_slice(&h.center);
            f.push(h.diameter);
            path(&mut f, &h.path);
        }
        f.push(p.labels.len() as f64);
        for l in &p.labels {
            let n: u32 = l.text.parse().ok().filter(|n: &u32| n.to_string() == l.text)?;
            f.push(n as f64);
            f.extend_from_slice(&l.at);
            f.push(l.angle);
        }
        f.push(p.marks.len() as f64);
        for m in &p.marks {
            path(&mut f, m);
        }
    }
    let warnings = serde_wasm_bindgen::to_value(&dto.warnings).ok()?;
    Some(dformer_build_connect(&f, warnings))
}
