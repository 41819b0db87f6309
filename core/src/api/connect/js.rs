//! Fast hand-over of `connect`'s input and result between JavaScript and WASM (wasm32 only).
//!
//! A connect result with 1,000 holes per piece is ~90,000 small JS objects and arrays. Built
//! through serde-wasm-bindgen, every one of them (and every property key) is a separate call
//! across the WASM boundary, which costs several times the geometry. Here the whole result is
//! written into one `f64` buffer in a fixed order and a small JavaScript function builds the
//! plain objects from it in a single pass: the same shape as the serde output, no JSON text.
//! The input pieces come the other way the same way ([`pieces_from_js`]).

use super::ConnectDto;
use crate::api::path::{PathDto, PointDto};
use wasm_bindgen::prelude::*;

// Object literals are written whole (not grown property by property), so every point, hole and
// label of one kind shares one hidden class, and arrays are filled by push (packed elements).
#[wasm_bindgen(inline_js = r#"
export function dformer_build_connect(f, warnings) {
  let i = 0;
  const path = () => {
    const n = f[i++], points = [];
    for (let k = 0; k < n; k++) {
      const flags = f[i], anchor = [f[i + 1], f[i + 2]];
      i += 3;
      if (flags === 3) {
        points.push({ anchor, left: [f[i], f[i + 1]], right: [f[i + 2], f[i + 3]] });
        i += 4;
      } else if (flags === 0) {
        points.push({ anchor });
      } else {
        const p = { anchor };
        if (flags & 1) { p.left = [f[i], f[i + 1]]; i += 2; }
        if (flags & 2) { p.right = [f[i], f[i + 1]]; i += 2; }
        points.push(p);
      }
    }
    return { closed: true, points };
  };
  const piece = () => {
    const outline = path();
    const holes = [], slots = [], labels = [], marks = [];
    for (let k = 0, n = f[i++]; k < n; k++) {
      const center = [f[i], f[i + 1]], diameter = f[i + 2];
      i += 3;
      holes.push({ center, diameter, path: path() });
    }
    for (let k = 0, n = f[i++]; k < n; k++) slots.push(path());
    const seam = f[i++] === 1 ? path() : undefined;
    for (let k = 0, n = f[i++]; k < n; k++) {
      labels.push({ text: String(f[i]), at: [f[i + 1], f[i + 2]], angle: f[i + 3], size: f[i + 4] });
      i += 5;
    }
    for (let k = 0, n = f[i++]; k < n; k++) marks.push(path());
    return seam === undefined ? { outline, holes, slots, labels, marks } : { outline, holes, slots, seam, labels, marks };
  };
  const count = f[i++], pitch = f[i++], slide = f[i++];
  const pieces = [piece(), piece()];
  return { count, pitch, slide, pieces, warnings };
}

// The pieces as one Float64Array: [count, then per piece: closed (1/0), n, then per point
// flags (1: left given, 2: right given), anchor, left, right (0 when absent)]. Anything not
// plainly shaped like the contract gives undefined: serde then reads it and names the problem.
// A null handle is absent, as for serde.
const num2 = (a) => Array.isArray(a) && a.length === 2 && typeof a[0] === 'number' && typeof a[1] === 'number';
export function dformer_flatten_pieces(ps) {
  if (!Array.isArray(ps)) return undefined;
  let len = 1;
  for (let j = 0; j < ps.length; j++) {
    const p = ps[j];
    if (p === null || typeof p !== 'object' || !Array.isArray(p.points)) return undefined;
    if (p.closed !== undefined && typeof p.closed !== 'boolean') return undefined;
    len += 2 + 7 * p.points.length;
  }
  const out = new Float64Array(len);
  out[0] = ps.length;
  let k = 1;
  for (let j = 0; j < ps.length; j++) {
    const p = ps[j], pts = p.points, n = pts.length;
    out[k] = p.closed === true ? 1 : 0;
    out[k + 1] = n;
    k += 2;
    for (let i = 0; i < n; i++, k += 7) {
      const q = pts[i];
      if (q === null || typeof q !== 'object') return undefined;
      const a = q.anchor, l = q.left, r = q.right;
      if (!num2(a)) return undefined;
      let flags = 0;
      if (l !== null && l !== undefined) {
        if (!num2(l)) return undefined;
        flags |= 1;
        out[k + 3] = l[0]; out[k + 4] = l[1];
      }
      if (r !== null && r !== undefined) {
        if (!num2(r)) return undefined;
        flags |= 2;
        out[k + 5] = r[0]; out[k + 6] = r[1];
      }
      out[k] = flags; out[k + 1] = a[0]; out[k + 2] = a[1];
    }
  }
  return out;
}
"#)]
extern "C" {
    fn dformer_build_connect(f: &[f64], warnings: JsValue) -> JsValue;
    fn dformer_flatten_pieces(p: &JsValue) -> Option<Vec<f64>>;
}

/// The `pieces` argument of `connect` read through one flat array, or `None` when it is not
/// plainly shaped like the contract (then the caller reads it with serde, whose error names the
/// problem). Absent or null handles stay absent, exactly as serde reads them, so an unchanged
/// outline is handed back point for point.
pub fn pieces_from_js(value: &JsValue) -> Option<Vec<PathDto>> {
    let flat = dformer_flatten_pieces(value)?;
    let (&count, mut rest) = flat.split_first()?;
    let mut pieces = Vec::with_capacity(count as usize);
    for _ in 0..count as usize {
        let (head, tail) = rest.split_at_checked(2)?;
        let n = head[1] as usize;
        let (body, tail) = tail.split_at_checked(7 * n)?;
        let points = body
            .chunks_exact(7)
            .map(|c| {
                let flags = c[0] as u8;
                PointDto {
                    anchor: [c[1], c[2]],
                    left: (flags & 1 != 0).then_some([c[3], c[4]]),
                    right: (flags & 2 != 0).then_some([c[5], c[6]]),
                }
            })
            .collect();
        pieces.push(PathDto { closed: head[0] == 1.0, points });
        rest = tail;
    }
    Some(pieces)
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

/// A label's text as the connector number it spells (decimal digits, no sign, no leading zero),
/// so that `String(n)` in JavaScript gives the text back exactly.
fn label_number(text: &str) -> Option<u32> {
    let b = text.as_bytes();
    let plain = !b.is_empty() && b.iter().all(u8::is_ascii_digit) && (b.len() == 1 || b[0] != b'0');
    if plain { text.parse().ok() } else { None }
}

/// Number of `f64`s [`path`] writes for `p`.
fn path_len(p: &PathDto) -> usize {
    1 + p.points.iter().map(|k| 3 + 2 * (k.left.is_some() as usize + k.right.is_some() as usize)).sum::<usize>()
}

/// The result as plain JS objects, or `None` when a label is not a plain connector number
/// (then the caller falls back to serde).
pub fn to_js(dto: &ConnectDto) -> Option<JsValue> {
    let len = 3 + dto
        .pieces
        .iter()
        .map(|p| {
            path_len(&p.outline)
                + 5
                + p.holes.iter().map(|h| 3 + path_len(&h.path)).sum::<usize>()
                + p.slots.iter().map(path_len).sum::<usize>()
                + p.seam.as_ref().map(path_len).unwrap_or(0)
                + 5 * p.labels.len()
                + p.marks.iter().map(path_len).sum::<usize>()
        })
        .sum::<usize>();
    let mut f = Vec::with_capacity(len);
    f.push(dto.count as f64);
    f.push(dto.pitch);
    f.push(dto.slide);
    for p in &dto.pieces {
        path(&mut f, &p.outline);
        f.push(p.holes.len() as f64);
        for h in &p.holes {
            f.extend_from_slice(&h.center);
            f.push(h.diameter);
            path(&mut f, &h.path);
        }
        f.push(p.slots.len() as f64);
        for s in &p.slots {
            path(&mut f, s);
        }
        f.push(p.seam.is_some() as u8 as f64);
        if let Some(s) = &p.seam {
            path(&mut f, s);
        }
        f.push(p.labels.len() as f64);
        for l in &p.labels {
            f.push(label_number(&l.text)? as f64);
            f.extend_from_slice(&l.at);
            f.push(l.angle);
            f.push(l.size);
        }
        f.push(p.marks.len() as f64);
        for m in &p.marks {
            path(&mut f, m);
        }
    }
    let warnings = serde_wasm_bindgen::to_value(&dto.warnings).ok()?;
    Some(dformer_build_connect(&f, warnings))
}
