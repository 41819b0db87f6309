// The MVP lowering of the build (uxp-panel/tools/wasm-lower-mvp.mjs) must not change what a
// module computes: hand-assembled functions using every lowered instruction are run in V8 before
// and after lowering, on edge cases (NaN, ±∞, range limits, overlapping copies), and must agree.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { lowerToMvp } from '../../uxp-panel/tools/wasm-lower-mvp.mjs';
import { scanWasmFeatures } from '../../uxp-panel/tools/wasm-features.mjs';
import { section, str, u32, vec } from './wasm-assemble.mjs';

const I32 = 0x7f;
const I64 = 0x7e;
const F32 = 0x7d;
const F64 = 0x7c;

/** fns: [{ name, params, results, code }] → a module exporting them and its memory "mem". */
function build(fns) {
  const types = section(1, vec(fns.map((f) => [0x60, ...vec(f.params.map((p) => [p])), ...vec(f.results.map((r) => [r]))])));
  const funcs = section(3, vec(fns.map((_, i) => u32(i))));
  const mem = section(5, vec([[0x00, 0x01]]));
  const exps = section(7, vec([...fns.map((f, i) => [...str(f.name), 0x00, ...u32(i)]), [...str('mem'), 0x02, 0x00]]));
  const code = section(10, vec(fns.map((f) => {
    const body = [0x00, ...f.code, 0x0b];
    return [...u32(body.length), ...body];
  })));
  return new Uint8Array([0x00, 0x61, 0x73, 0x6d, 0x01, 0x00, 0x00, 0x00, ...types, ...funcs, ...mem, ...exps, ...code]);
}

const FNS = [
  { name: 'ext8', params: [I32], results: [I32], code: [0x20, 0, 0xc0] },
  { name: 'ext16', params: [I32], results: [I32], code: [0x20, 0, 0xc1] },
  { name: 'ext64_8', params: [I64], results: [I64], code: [0x20, 0, 0xc2] },
  { name: 'ext64_16', params: [I64], results: [I64], code: [0x20, 0, 0xc3] },
  { name: 'ext64_32', params: [I64], results: [I64], code: [0x20, 0, 0xc4] },
  ...[
    [F32, I32], [F32, I32], [F64, I32], [F64, I32], [F32, I64], [F32, I64], [F64, I64], [F64, I64],
  ].map(([from, to], sub) => ({ name: `sat${sub}`, params: [from], results: [to], code: [0x20, 0, 0xfc, sub] })),
  { name: 'copy', params: [I32, I32, I32], results: [], code: [0x20, 0, 0x20, 1, 0x20, 2, 0xfc, 0x0a, 0x00, 0x00] },
  { name: 'fill', params: [I32, I32, I32], results: [], code: [0x20, 0, 0x20, 1, 0x20, 2, 0xfc, 0x0b, 0x00] },
];

const original = build(FNS);
const { bytes: lowered, lowered: counts } = lowerToMvp(original);
const inst = async (bytes) => (await WebAssembly.instantiate(bytes)).instance.exports;

test('lowering leaves an MVP module that V8 validates', () => {
  assert.ok(WebAssembly.validate(original), 'fixture must be valid');
  assert.ok(WebAssembly.validate(lowered), 'lowered module must be valid');
  assert.deepEqual(scanWasmFeatures(original).features, { 'sign-ext': 5, 'nontrapping-fptoint': 8, 'bulk-memory': 2 });
  assert.deepEqual(scanWasmFeatures(lowered).features, {}, 'no post-MVP feature left');
  assert.deepEqual(counts, { 'sign-ext': 5, 'nontrapping-fptoint': 8, 'bulk-memory': 2 });
});

test('sign extension: same results on every byte/half-word/word pattern', async () => {
  const [a, b] = [await inst(original), await inst(lowered)];
  for (const x of [0, 1, 0x7f, 0x80, 0xff, 0x100, 0x7fff, 0x8000, 0xffff, 0x12345678, -1, -128, 0x7fffffff, -0x80000000]) {
    assert.equal(b.ext8(x), a.ext8(x), `i32.extend8_s(${x})`);
    assert.equal(b.ext16(x), a.ext16(x), `i32.extend16_s(${x})`);
  }
  for (const x of [0n, 0x80n, 0xffn, 0x8000n, 0x80000000n, 0xffffffffn, 0x7fffffffffffffffn, -1n, -(2n ** 63n), 0x123456789abcdefn]) {
    assert.equal(b.ext64_8(x), a.ext64_8(x), `i64.extend8_s(${x})`);
    assert.equal(b.ext64_16(x), a.ext64_16(x), `i64.extend16_s(${x})`);
    assert.equal(b.ext64_32(x), a.ext64_32(x), `i64.extend32_s(${x})`);
  }
});

test('saturating truncation: NaN, infinities, range limits and ordinary values agree', async () => {
  const [a, b] = [await inst(original), await inst(lowered)];
  const values = [NaN, Infinity, -Infinity, 0, -0, 0.5, -0.5, -0.99, -1, -1.5, 1.9, 123.7, -123.7,
    2 ** 31 - 1, 2 ** 31 - 0.5, 2 ** 31, 2 ** 31 + 1, -(2 ** 31), -(2 ** 31) - 0.5, -(2 ** 31) - 1, -(2 ** 31) - 2,
    2 ** 32 - 1, 2 ** 32, 2 ** 32 + 1, 2 ** 53, 2 ** 63, 2 ** 63 - 1024, -(2 ** 63), -(2 ** 63) - 4096, 2 ** 64, 2 ** 64 - 4096, 1e300, -1e300];
  for (let sub = 0; sub < 8; sub++) {
    for (const x of values) {
      assert.equal(b[`sat${sub}`](x), a[`sat${sub}`](x), `trunc_sat 0xFC ${sub} of ${x}`);
    }
  }
});

test('memory.copy (both overlap directions) and memory.fill agree byte for byte', async () => {
  const [a, b] = [await inst(original), await inst(lowered)];
  const cases = [[100, 0, 64], [0, 100, 64], [10, 0, 50], [0, 10, 50], [5, 5, 20], [200, 300, 0], [1000, 0, 4096]];
  for (const [d, s, n] of cases) {
    for (const m of [a, b]) {
      const mem = new Uint8Array(m.mem.buffer);
      for (let i = 0; i < 8192; i++) mem[i] = (i * 37 + 11) & 255;
      m.copy(d, s, n);
    }
    assert.deepEqual(new Uint8Array(b.mem.buffer, 0, 8192), new Uint8Array(a.mem.buffer, 0, 8192), `memory.copy(${d}, ${s}, ${n})`);
  }
  for (const m of [a, b]) m.fill(7, 0xab, 300);
  assert.deepEqual(new Uint8Array(b.mem.buffer, 0, 512), new Uint8Array(a.mem.buffer, 0, 512), 'memory.fill');
});
