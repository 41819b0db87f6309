// The scanner that decides which CEP (and Illustrator) can run the panel's WebAssembly:
// hand-assembled modules (validated by V8 first) with exactly one post-MVP feature each.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { minimumCep, scanWasmFeatures } from '../../uxp-panel/tools/wasm-features.mjs';
import { panelDir, repo } from './support.mjs';
import { section, u32, vec } from './wasm-assemble.mjs';

/** A module with one function of type `type` (bytes of a functype) and body `code` (without locals/end). */
function module({ params = [0x7f], results = [0x7f], code, memory = false, table = null, extraTypes = [] }) {
  const types = section(1, vec([[0x60, ...vec(params.map((p) => [p])), ...vec(results.map((r) => [r]))], ...extraTypes]));
  const funcs = section(3, vec([[0]]));
  const tables = table ? section(4, vec([table])) : [];
  const mems = memory ? section(5, vec([[0x00, 0x01]])) : [];
  const body = [0x00, ...code, 0x0b];
  const codeSec = section(10, vec([[...u32(body.length), ...body]]));
  return new Uint8Array([0x00, 0x61, 0x73, 0x6d, 0x01, 0x00, 0x00, 0x00, ...types, ...funcs, ...tables, ...mems, ...codeSec]);
}

const CASES = [
  { name: 'MVP only', mod: { code: [0x20, 0x00, 0x41, 0x05, 0x6a] }, features: {}, chromium: 57 },
  { name: 'sign-ext (i32.extend8_s)', mod: { code: [0x20, 0x00, 0xc0] }, features: { 'sign-ext': 1 }, chromium: 74 },
  { name: 'nontrapping-fptoint (i32.trunc_sat_f64_s)', mod: { params: [0x7c], code: [0x20, 0x00, 0xfc, 0x02] }, features: { 'nontrapping-fptoint': 1 }, chromium: 75 },
  {
    name: 'bulk-memory (memory.copy)',
    mod: { memory: true, code: [0x41, 0x00, 0x41, 0x08, 0x41, 0x04, 0xfc, 0x0a, 0x00, 0x00, 0x20, 0x00] },
    features: { 'bulk-memory': 1 },
    chromium: 75,
  },
  { name: 'multi-value (two results)', mod: { results: [0x7f, 0x7f], code: [0x20, 0x00, 0x20, 0x00] }, features: { 'multi-value': 1 }, chromium: 85 },
  {
    name: 'SIMD (v128.const + i32x4.extract_lane), decoded through',
    mod: { code: [0xfd, 0x0c, ...new Array(16).fill(1), 0xfd, 0x1b, 0x00, 0x20, 0x00, 0x6a] },
    features: { simd: 2 },
    chromium: 91,
  },
  { name: 'reference types (externref table)', mod: { table: [0x6f, 0x00, 0x01], code: [0x20, 0x00] }, features: { 'reference-types': 1 }, chromium: 96 },
];

for (const c of CASES) {
  test(`scanner: ${c.name}`, () => {
    const bytes = module(c.mod);
    assert.ok(WebAssembly.validate(bytes), 'the hand-assembled module must be valid WebAssembly');
    const { features, minChromium } = scanWasmFeatures(bytes);
    assert.deepEqual(features, c.features);
    assert.equal(minChromium, c.chromium, `wanted Chromium ${c.chromium}, got ${minChromium}`);
  });
}

test('CEP mapping: MVP → CEP 8 / Illustrator 22; SIMD → CEP 12 / Illustrator 29.5.1 (the CEP 12 Cookbook\'s table)', () => {
  assert.deepEqual(minimumCep(57), { cep: 8, chromium: 57, illustrator: '22.0' });
  assert.deepEqual(minimumCep(75), { cep: 11, chromium: 88, illustrator: '25.3' });
  assert.equal(minimumCep(91).cep, 12);
  assert.equal(minimumCep(91).illustrator, '29.5.1');
  assert.equal(minimumCep(114), null);
});

test('the built extension requires the CEP its WebAssembly needs (manifest written from the scan)', (t) => {
  const manifest = join(repo, 'dist', 'com.dformer.panel', 'CSXS', 'manifest.xml');
  const wasm = join(panelDir, 'wasm', 'dformer_bg.wasm');
  if (!existsSync(manifest) || !existsSync(wasm)) return t.skip('run `node uxp-panel/build.mjs` first');
  const { minChromium } = scanWasmFeatures(readFileSync(wasm));
  const cep = minimumCep(minChromium);
  const xml = readFileSync(manifest, 'utf8');
  const runtime = /<RequiredRuntime Name="CSXS" Version="([\d.]+)"/.exec(xml)[1];
  assert.equal(runtime, `${cep.cep}.0`, `CSXS runtime: wanted ${cep.cep}.0 for Chromium ${minChromium}, got ${runtime}`);
  if (cep.illustrator) assert.match(xml, new RegExp(`<Host Name="ILST" Version="\\[${cep.illustrator.replace('.', '\\.')},`));
});

// Regression: a solver dependency (faer) once put WebAssembly SIMD into the module, which raised the
// panel's minimum from Illustrator 22 (CEP 8, Chromium 57) to CEP 12. The issue asks for 22+.
test('the panel WebAssembly is pure MVP: the extension loads in Illustrator 22 (CEP 8)', (t) => {
  const wasm = join(panelDir, 'wasm', 'dformer_bg.wasm');
  if (!existsSync(wasm)) return t.skip('run `node uxp-panel/build.mjs` first');
  const scan = scanWasmFeatures(readFileSync(wasm));
  assert.equal(scan.minChromium, 57, `wanted Chromium 57 (CEP 8), got ${scan.minChromium}: ${JSON.stringify(scan.features ?? scan)}`.slice(0, 600));
  assert.equal(minimumCep(scan.minChromium).illustrator, '22.0');
});
