// Benchmark (not a test): perimeter speed and accuracy of the WASM core vs the adaptive-Simpson
// arc length of the earlier D-form scripts, in the same process; and the .wasm size.
// Run: wasm-pack build core --target nodejs --out-dir pkg && node bench/core.bench.mjs
// Prints figures and PASS/MISS against the targets; always exits 0.
import { readFileSync, statSync } from 'node:fs';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { perimeter as referencePerimeter, segments } from '../tests/core/reference.mjs';

const here = (p) => fileURLToPath(new URL(p, import.meta.url));
const require = createRequire(import.meta.url);
const core = require(here('../core/pkg/dformer.js'));

const TARGET_ERR = 1e-12, TARGET_RATIO = 20, TARGET_KB = 300;
const N = 1000;

// A smooth, simple 1,000-segment outline: r(θ) = 100 (1 + 0.3 sin 5θ + 0.1 cos 13θ), sampled with
// Hermite handles (handle = anchor ± tangent·Δθ/3), centred away from the origin.
function blob(n) {
  const r = (t) => 100 * (1 + 0.3 * Math.sin(5 * t) + 0.1 * Math.cos(13 * t));
  const dr = (t) => 100 * (1.5 * Math.cos(5 * t) - 1.3 * Math.sin(13 * t));
  const h = (2 * Math.PI) / n;
  const points = [];
  for (let i = 0; i < n; i++) {
    const t = i * h, c = Math.cos(t), s = Math.sin(t);
    const a = [500 + r(t) * c, 300 + r(t) * s];
    const d = [dr(t) * c - r(t) * s, dr(t) * s + r(t) * c];
    points.push({ anchor: a, left: [a[0] - d[0] * h / 3, a[1] - d[1] * h / 3], right: [a[0] + d[0] * h / 3, a[1] + d[1] * h / 3] });
  }
  return { closed: true, points };
}

// |B'(t)| of a cubic given by its control points.
function speed(c, t) {
  const u = 1 - t;
  const x = 3 * (u * u * (c[1][0] - c[0][0]) + 2 * u * t * (c[2][0] - c[1][0]) + t * t * (c[3][0] - c[2][0]));
  const y = 3 * (u * u * (c[1][1] - c[0][1]) + 2 * u * t * (c[2][1] - c[1][1]) + t * t * (c[3][1] - c[2][1]));
  return Math.sqrt(x * x + y * y); // as ExtendScript (ES3, no Math.hypot) scripts wrote it
}

// The baseline: adaptive Simpson on |B'(t)| with tolerance 1e-5 per segment, as the earlier
// D-form scripts computed arc length.
function simpsonLength(c, eps = 1e-5) {
  const f = (t) => speed(c, t);
  const rec = (a, b, fa, fm, fb, whole, eps, depth) => {
    const m = (a + b) / 2, lm = (a + m) / 2, rm = (m + b) / 2;
    const flm = f(lm), frm = f(rm);
    const left = ((m - a) / 6) * (fa + 4 * flm + fm);
    const right = ((b - m) / 6) * (fm + 4 * frm + fb);
    if (depth <= 0 || Math.abs(left + right - whole) <= 15 * eps) return left + right + (left + right - whole) / 15;
    return rec(a, m, fa, flm, fm, left, eps / 2, depth - 1) + rec(m, b, fm, frm, fb, right, eps / 2, depth - 1);
  };
  const fa = f(0), fm = f(0.5), fb = f(1);
  return rec(0, 1, fa, fm, fb, (fa + 4 * fm + fb) / 6, eps, 50);
}
const simpsonPerimeter = (segs) => segs.reduce((s, c) => s + simpsonLength(c), 0);

// Best of 7 rounds of ≥ 60 ms each: the minimum is the figure least disturbed by other load.
function timeIt(fn, rounds = 7, minMs = 60) {
  fn(); fn(); // warm up (JIT, wasm tier-up)
  let best = Infinity;
  for (let r = 0; r < rounds; r++) {
    let iters = 0; const t0 = process.hrtime.bigint(); let t;
    do { fn(); iters++; t = Number(process.hrtime.bigint() - t0) / 1e6; } while (t < minMs);
    best = Math.min(best, t / iters);
  }
  return best; // ms per call
}

const path = blob(N);
const segs = segments(path);
// Reference: composite 20-point Gauss–Legendre, 64 panels per segment, compensated sums.
const truth = referencePerimeter(path);

const wasmP = core.measure(path).perimeter;
const simpP = simpsonPerimeter(segs);
const errW = Math.abs(wasmP - truth) / truth, errS = Math.abs(simpP - truth) / truth;

const msW = timeIt(() => core.measure(path));
const msS = timeIt(() => simpsonPerimeter(segs));
const ratio = msS / msW;
// The arc-length kernel alone: benchPerimeter converts and validates the path once, then
// computes its perimeter REPS times inside WASM (the Simpson baseline also gets its input
// ready-made, as JS arrays).
const REPS = 200;
const kernelP = core.benchPerimeter(path, undefined, 1);
const msK = (timeIt(() => core.benchPerimeter(path, undefined, REPS)) - timeIt(() => core.benchPerimeter(path, undefined, 1))) / (REPS - 1);
const ratioK = msS / msK;
const errK = Math.abs(kernelP - truth) / truth;
const kb = statSync(here('../core/pkg/dformer_bg.wasm')).size / 1024;

const mark = (ok) => (ok ? 'PASS' : 'MISS');
const us = (ms) => `${(ms * 1000 / N).toFixed(3)} µs/segment`;
console.log(`D-former core benchmark — ${N}-segment closed path, Node ${process.version}`);
console.log(`  reference perimeter (GL20×64 panels): ${truth}`);
console.log(`  WASM measure():  ${us(msW)} (${msW.toFixed(3)} ms per path; includes input conversion, validation, area, centroid)`);
console.log(`                   relative error ${errW.toExponential(2)}   ${mark(errW <= TARGET_ERR)} (target ≤ ${TARGET_ERR})`);
console.log(`  JS adaptive Simpson (tol 1e-5): ${us(msS)} (${msS.toFixed(3)} ms per path), relative error ${errS.toExponential(2)}`);
console.log(`  WASM arc-length kernel (perimeter only, input already in WASM): ${us(msK)}, relative error ${errK.toExponential(2)}   ${mark(errK <= TARGET_ERR)}`);
console.log(`  speed-up, kernel vs Simpson:      ${ratioK.toFixed(1)}×   ${mark(ratioK >= TARGET_RATIO)} (target ≥ ${TARGET_RATIO}×)`);
console.log(`  speed-up, measure() vs Simpson:   ${ratio.toFixed(1)}×   ${mark(ratio >= TARGET_RATIO)} (target ≥ ${TARGET_RATIO}×; end to end, incl. JS→WASM conversion and validation)`);
console.log(`  wasm size: ${kb.toFixed(1)} KB   ${mark(kb <= TARGET_KB)} (target ≤ ${TARGET_KB} KB; core/pkg/dformer_bg.wasm as scripts/build-wasm.sh builds it, after wasm-opt -Oz)`);

// A second 1,000-segment path whose segments bend as drawn ones do: a 100-lobed rosette, each
// lobe of 10 segments, so every segment turns by tens of degrees. Simpson has to subdivide here;
// the quadrature kernel's per-segment cost hardly changes. Printed for context; the target above
// is judged on the smooth path, the case least favourable to the kernel.
function rosette(n) {
  const r = (t) => 100 * (1 + 0.2 * Math.sin(100 * t));
  const dr = (t) => 100 * 20 * Math.cos(100 * t);
  const h = (2 * Math.PI) / n;
  const points = [];
  for (let i = 0; i < n; i++) {
    const t = i * h, c = Math.cos(t), s = Math.sin(t);
    const a = [r(t) * c, r(t) * s];
    const d = [dr(t) * c - r(t) * s, dr(t) * s + r(t) * c];
    points.push({ anchor: a, left: [a[0] - d[0] * h / 3, a[1] - d[1] * h / 3], right: [a[0] + d[0] * h / 3, a[1] + d[1] * h / 3] });
  }
  return { closed: true, points };
}
{
  const path2 = rosette(N), segs2 = segments(path2), truth2 = referencePerimeter(path2);
  const msS2 = timeIt(() => simpsonPerimeter(segs2));
  const msK2 = (timeIt(() => core.benchPerimeter(path2, undefined, REPS)) - timeIt(() => core.benchPerimeter(path2, undefined, 1))) / (REPS - 1);
  const errK2 = Math.abs(core.benchPerimeter(path2, undefined, 1) - truth2) / truth2;
  const errS2 = Math.abs(simpsonPerimeter(segs2) - truth2) / truth2;
  console.log(`  rosette (1,000 strongly bent segments): kernel ${us(msK2)} (error ${errK2.toExponential(2)}), Simpson ${us(msS2)} (error ${errS2.toExponential(2)}), speed-up ${(msS2 / msK2).toFixed(1)}×`);
}

// The ceiling of the ratio: a loop that only sums each segment's chord (one square root per
// segment, the curve ignored) does less work than any arc-length method can, since even a straight
// segment's length costs a square root. Simpson divided by this loop bounds every method's speed-up.
{
  const chords = (ss) => {
    let s = 0;
    for (const c of ss) { const x = c[3][0] - c[0][0], y = c[3][1] - c[0][1]; s += Math.sqrt(x * x + y * y); }
    return s;
  };
  const msC = timeIt(() => chords(segs));
  console.log(`  ceiling: chords only (1 square root per segment, no curve): ${us(msC)}; Simpson / that = ${(msS / msC).toFixed(1)}×, the most any method could gain on this path`);
}

// What the speed-up means at equal accuracy: the same Simpson asked for the kernel's 1e-12.
{
  const tol = (1e-12 * truth) / N; // per segment, so the path is within 1e-12 relative
  const simp12 = (ss) => ss.reduce((s, c) => s + simpsonLength(c, tol), 0);
  const err12 = Math.abs(simp12(segs) - truth) / truth;
  const ms12 = timeIt(() => simp12(segs), 3, 60);
  console.log(`  Simpson asked for the same accuracy (tolerance ${tol.toExponential(1)} per segment): ${us(ms12)}, error ${err12.toExponential(2)}; kernel speed-up at equal accuracy ${(ms12 / msK).toFixed(1)}×`);
}
