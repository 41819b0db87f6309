// The native `dformer` (the program the Inkscape extension runs, `dformer json`) and the
// WebAssembly (the panel and the browser app) give the same answer to the same request, to the
// last bit: the core computes its sines, arctangents and hypotenuses with the `libm` crate on
// every target (core/src/libm_ext.rs), and the CLI parses JSON numbers correctly rounded.
// Compared leaf by leaf against each other, two independent builds of the core.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { ellipse, kidneyThrough } from './reference.mjs';

const require = createRequire(import.meta.url);
const m = require(process.env.DFORMER_PKG ?? '../../core/pkg/dformer.js');
const repo = fileURLToPath(new URL('../..', import.meta.url));

/** The debug `dformer` as `cargo test --workspace` (scripts/test.sh) has built it, rebuilt here if
 *  it is missing or stale: the path cargo reports for the binary artifact. */
function nativeBinary() {
  const r = spawnSync('cargo', ['build', '--quiet', '-p', 'dformer-cli', '--message-format=json'], { cwd: repo, encoding: 'utf8', maxBuffer: 1 << 26 });
  assert.equal(r.status, 0, `cargo build -p dformer-cli failed:\n${r.stderr}`);
  const exe = r.stdout.split('\n').filter(Boolean).map((l) => JSON.parse(l)).filter((j) => j.reason === 'compiler-artifact' && j.executable).map((j) => j.executable).pop();
  assert.ok(exe, 'cargo reported no dformer executable');
  return exe;
}

/** Every number, string and boolean of an answer by its path (`stats.ms`, the solve's own clock
 *  time, left out; null and absent alike). */
function leaves(v, path = '', out = new Map()) {
  if (v === null || v === undefined) return out;
  if (Array.isArray(v)) v.forEach((x, i) => leaves(x, `${path}[${i}]`, out));
  else if (typeof v === 'object') for (const k of Object.keys(v)) { if (path === '.stats' && k === 'ms') continue; leaves(v[k], `${path}.${k}`, out); }
  else out.set(path, v);
  return out;
}

test('test_issue_14_native_and_browser_give_the_same_form: measure, stitch, leaves and simulate agree to the bit', () => {
  // The kidney of issue 14 and a 2:1 ellipse of its perimeter; two 2:1 ellipses.
  const kidney = kidneyThrough(72);
  const P = m.measure(kidney).perimeter;
  const s = P / m.measure(ellipse([0, 0], 1, 0.5)).perimeter;
  const oval = ellipse([0, 0], s, s / 2);
  const e = ellipse([0, 0], 60, 30);
  const requests = [
    ['measure the kidney', { op: 'measure', path: kidney }, () => m.measure(kidney)],
    ['stitch holes on the kidney and the oval', { op: 'connect', pieces: [kidney, oval], options: { kind: 'stitch', count: 40 } }, () => m.connect([kidney, oval], { kind: 'stitch', count: 40 })],
    ['leaves on the kidney and the oval', { op: 'connect', pieces: [kidney, oval], options: { kind: 'leaves', count: 24 } }, () => m.connect([kidney, oval], { kind: 'leaves', count: 24 })],
    ['the form of two ellipses a quarter apart (convex path)', { op: 'simulate', pieces: [e, e], options: { offset: m.measure(e).perimeter / 4, resolution: 64 } }, () => m.simulate([e, e], { offset: m.measure(e).perimeter / 4, resolution: 64 })],
    // Natively on glibc this gave 248421.2659427339 mm³ against the browser's 248421.26592422873.
    ['the form of the kidney and the oval (sheet path)', { op: 'simulate', pieces: [kidney, oval], options: { offset: P / 8, resolution: 32 } }, () => m.simulate([kidney, oval], { offset: P / 8, resolution: 32 })],
  ];
  const exe = nativeBinary();
  const r = spawnSync(exe, ['json'], { input: JSON.stringify(requests.map(([, req]) => req)), encoding: 'utf8', maxBuffer: 1 << 28 });
  assert.equal(r.status, 0, `dformer json failed:\n${r.stderr}`);
  const native = JSON.parse(r.stdout);
  requests.forEach(([what, , wasm], i) => {
    const want = leaves(JSON.parse(JSON.stringify(wasm())));
    const got = leaves(native[i]);
    assert.deepEqual([...got.keys()].sort(), [...want.keys()].sort(), `${what}: the two answers have other fields`);
    const differ = [...want].filter(([k, v]) => got.get(k) !== v);
    const first = differ.slice(0, 3).map(([k, v]) => `${k}: browser ${v}, native ${got.get(k)}`).join('; ');
    console.log(`${what}: ${want.size} values, ${differ.length} differ`);
    assert.equal(differ.length, 0, `${what}: ${differ.length} of ${want.size} values differ between the browser build and dformer (${first})`);
  });
});
