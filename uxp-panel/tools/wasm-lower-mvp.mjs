// Lowers the post-MVP instructions that Rust's prebuilt standard library brings into a module
// compiled with `-C target-cpu=mvp`, so the panel's WebAssembly runs in CEP 8's Chromium 57:
//   sign-ext      i32.extend8_s x  →  (x << 24) >>s 24   (and the 16/32-bit, i64 forms)
//   bulk-memory   memory.copy / memory.fill  →  calls to added MVP functions (byte loops;
//                 memmove semantics: copies backwards when the ranges overlap that way)
//   nontrapping-fptoint  iNN.trunc_sat_fMM_{s,u}  →  calls to added functions with the
//                 saturating semantics of the spec: NaN → 0, below range → min, above → max,
//                 else the trapping truncation (which cannot trap once the range is checked)
// Anything else post-MVP (SIMD, reference types, …) cannot be lowered and is left as is; the
// feature scan reports it. New functions are appended after the existing ones, so no index moves.
import { Reader, readSections } from './wasm-binary.mjs';
import { importSection, instruction, scanWasmFeatures } from './wasm-features.mjs';

const u32 = (n) => {
  const out = [];
  do {
    let b = n & 0x7f;
    n = Math.floor(n / 128);
    if (n) b |= 0x80;
    out.push(b);
  } while (n);
  return out;
};
const f32 = (x) => [...new Uint8Array(new Float32Array([x]).buffer)];
const f64 = (x) => [...new Uint8Array(new Float64Array([x]).buffer)];
const sleb = (n) => {
  // signed LEB128 of a BigInt
  const out = [];
  let v = BigInt(n);
  for (;;) {
    const b = Number(v & 0x7fn);
    v >>= 7n;
    if ((v === 0n && !(b & 0x40)) || (v === -1n && b & 0x40)) {
      out.push(b);
      return out;
    }
    out.push(b | 0x80);
  }
};

const I32 = 0x7f;
const I64 = 0x7e;
const F32 = 0x7d;
const F64 = 0x7c;

/** Sign-extension opcode → MVP shift pair. */
const SIGN_EXT = {
  0xc0: [0x41, ...sleb(24), 0x74, 0x41, ...sleb(24), 0x75],
  0xc1: [0x41, ...sleb(16), 0x74, 0x41, ...sleb(16), 0x75],
  0xc2: [0x42, ...sleb(56), 0x86, 0x42, ...sleb(56), 0x87],
  0xc3: [0x42, ...sleb(48), 0x86, 0x42, ...sleb(48), 0x87],
  0xc4: [0x42, ...sleb(32), 0x86, 0x42, ...sleb(32), 0x87],
};

/** trunc_sat sub-opcode → { from, to, signed }. */
const TRUNC_SAT = [
  { from: F32, to: I32, signed: true, op: 0xa8 },
  { from: F32, to: I32, signed: false, op: 0xa9 },
  { from: F64, to: I32, signed: true, op: 0xaa },
  { from: F64, to: I32, signed: false, op: 0xab },
  { from: F32, to: I64, signed: true, op: 0xae },
  { from: F32, to: I64, signed: false, op: 0xaf },
  { from: F64, to: I64, signed: true, op: 0xb0 },
  { from: F64, to: I64, signed: false, op: 0xb1 },
];

/** Body (locals + code + end) of a saturating truncation. */
function truncSatBody({ from, to, signed, op }) {
  const bits = to === I32 ? 32 : 64;
  const fconst = (x) => (from === F32 ? [0x43, ...f32(x)] : [0x44, ...f64(x)]);
  const ge = from === F32 ? 0x60 : 0x66;
  const le = from === F32 ? 0x5f : 0x65;
  const ne = from === F32 ? 0x5c : 0x62;
  const iconst = (v) => (to === I32 ? [0x41, ...sleb(v)] : [0x42, ...sleb(v)]);
  const hi = signed ? 2 ** (bits - 1) : 2 ** bits; // smallest value that does not fit
  const max = signed ? (1n << BigInt(bits - 1)) - 1n : -1n; // unsigned max is all ones
  const min = signed ? -(1n << BigInt(bits - 1)) : 0n;
  // Below range: x ≤ −2^(bits−1) − 1 (signed) or x ≤ −1 (unsigned). −2^(bits−1) − 1 is not always
  // representable, so the signed test is x < −2^(bits−1) when the float type cannot hold the former.
  const lowExact = signed ? -(2 ** (bits - 1)) - 1 : -1;
  const representable = from === F64 ? bits === 32 || !signed : !signed;
  const below = representable ? [...fconst(lowExact), le] : [...fconst(-(2 ** (bits - 1))), from === F32 ? 0x5d : 0x63];
  const rt = to;
  return [
    0x00, // no locals
    0x20, 0x00, 0x20, 0x00, ne, 0x04, rt, ...iconst(0n), 0x05,
    0x20, 0x00, ...fconst(hi), ge, 0x04, rt, ...iconst(max), 0x05,
    0x20, 0x00, ...below, 0x04, rt, ...iconst(min), 0x05,
    0x20, 0x00, op,
    0x0b, 0x0b, 0x0b, 0x0b,
  ];
}

/** memmove(dst, src, n): forward when dst ≤ src, else backward; byte at a time. */
const MEMMOVE_BODY = [
  0x00,
  0x20, 0x00, 0x20, 0x01, 0x4d, // dst <= src (u)
  0x04, 0x40,
  0x02, 0x40, 0x03, 0x40,
  0x20, 0x02, 0x45, 0x0d, 0x01, // n == 0 → out
  0x20, 0x00, 0x20, 0x01, 0x2d, 0x00, 0x00, 0x3a, 0x00, 0x00, // *dst = *src
  0x20, 0x00, 0x41, 0x01, 0x6a, 0x21, 0x00,
  0x20, 0x01, 0x41, 0x01, 0x6a, 0x21, 0x01,
  0x20, 0x02, 0x41, 0x01, 0x6b, 0x21, 0x02,
  0x0c, 0x00, 0x0b, 0x0b,
  0x05,
  0x02, 0x40, 0x03, 0x40,
  0x20, 0x02, 0x45, 0x0d, 0x01,
  0x20, 0x02, 0x41, 0x01, 0x6b, 0x21, 0x02, // n -= 1
  0x20, 0x00, 0x20, 0x02, 0x6a, 0x20, 0x01, 0x20, 0x02, 0x6a, 0x2d, 0x00, 0x00, 0x3a, 0x00, 0x00,
  0x0c, 0x00, 0x0b, 0x0b,
  0x0b,
  0x0b,
];

/** memset(dst, value, n). */
const MEMSET_BODY = [
  0x00,
  0x02, 0x40, 0x03, 0x40,
  0x20, 0x02, 0x45, 0x0d, 0x01,
  0x20, 0x00, 0x20, 0x01, 0x3a, 0x00, 0x00,
  0x20, 0x00, 0x41, 0x01, 0x6a, 0x21, 0x00,
  0x20, 0x02, 0x41, 0x01, 0x6b, 0x21, 0x02,
  0x0c, 0x00, 0x0b, 0x0b,
  0x0b,
];

/** Concatenates byte chunks (number arrays or Uint8Arrays) without spreading large arrays. */
const concat = (chunks) => Buffer.concat(chunks.map((c) => (c instanceof Uint8Array ? c : Uint8Array.from(c))));
const section = (id, body) => concat([[id, ...u32(body.length)], body]);

/**
 * Returns `{ bytes, lowered: { name: count } }`. Throws if the module uses memory.init/data.drop
 * (passive data, i.e. threads) — not produced for this target, not worth lowering.
 */
export function lowerToMvp(input) {
  const bytes = input instanceof Uint8Array ? input : new Uint8Array(input);
  const sections = readSections(bytes);
  const get = (id) => sections.find((s) => s.id === id);
  const imports = get(2) ? importSection(new Reader(get(2).body), () => {}) : 0;
  const typeR = new Reader(get(1).body);
  const typeCount = typeR.u32();
  const funcR = new Reader(get(3).body);
  const definedCount = funcR.u32();

  // New functions are created on first use: key → { index, type, body }.
  const added = new Map();
  const newTypes = [];
  const typeIndex = new Map();
  const typeOf = (params, results) => {
    const key = params.join() + '>' + results.join();
    if (!typeIndex.has(key)) {
      typeIndex.set(key, typeCount + newTypes.length);
      newTypes.push([0x60, ...u32(params.length), ...params, ...u32(results.length), ...results]);
    }
    return typeIndex.get(key);
  };
  const helper = (key, params, results, body) => {
    if (!added.has(key)) added.set(key, { index: imports + definedCount + added.size, type: typeOf(params, results), body });
    return added.get(key).index;
  };

  const lowered = {};
  const count = (name) => {
    lowered[name] = (lowered[name] || 0) + 1;
  };
  const code = new Reader(get(10).body);
  const n = code.u32();
  const bodies = [];
  for (let i = 0; i < n; i++) {
    const size = code.u32();
    const end = code.p + size;
    const r = new Reader(code.b, code.p, end);
    const out = [];
    const localsStart = r.p;
    r.vec(() => {
      r.u32();
      r.byte();
    });
    out.push(code.b.subarray(localsStart, r.p));
    while (r.p < end) {
      const start = r.p;
      const op = r.byte();
      let feature = null;
      instruction(op, r, (f) => {
        feature = f;
      });
      if (feature === 'sign-ext') {
        out.push(SIGN_EXT[op]);
        count(feature);
      } else if (op === 0xfc && (feature === 'bulk-memory' || feature === 'nontrapping-fptoint')) {
        const sub = new Reader(code.b, start + 1).u32();
        if (sub <= 7) {
          const t = TRUNC_SAT[sub];
          out.push([0x10, ...u32(helper(`trunc_sat_${sub}`, [t.from], [t.to], truncSatBody(t)))]);
        } else if (sub === 10) out.push([0x10, ...u32(helper('memmove', [I32, I32, I32], [], MEMMOVE_BODY))]);
        else if (sub === 11) out.push([0x10, ...u32(helper('memset', [I32, I32, I32], [], MEMSET_BODY))]);
        else throw new Error(`cannot lower 0xFC ${sub} (passive data/element segments)`);
        count(feature);
      } else out.push(code.b.subarray(start, r.p));
    }
    bodies.push(concat(out));
    code.p = end;
  }
  for (const h of added.values()) bodies.push(Uint8Array.from(h.body));

  const out = [bytes.subarray(0, 8)];
  for (const s of sections) {
    if (s.id === 12) continue; // data count: only needed by memory.init / data.drop
    if (s.id === 1) {
      const rest = get(1).body.subarray(typeR.p);
      out.push(section(1, concat([u32(typeCount + newTypes.length), rest, newTypes.flat()])));
    } else if (s.id === 3) {
      const rest = get(3).body.subarray(funcR.p);
      out.push(section(3, concat([u32(definedCount + added.size), rest, [...added.values()].flatMap((h) => u32(h.type))])));
    } else if (s.id === 10) {
      out.push(section(10, concat([u32(bodies.length), ...bodies.flatMap((b) => [u32(b.length), b])])));
    } else out.push(section(s.id, s.body));
  }
  const result = new Uint8Array(concat(out));
  return { bytes: result, lowered, remaining: scanWasmFeatures(result).features };
}
