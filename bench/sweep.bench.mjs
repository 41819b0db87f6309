// WASM benchmark of the 3D tab's seam-offset sweep in Node (not a test): the time to a complete
// 32-point sweep — at each offset k·P/32 a cold `simulate` at the default 256 seam vertices and
// `formFigures`, exactly what the panel's sweep worker runs (uxp-panel/src/sweep-point.js), in
// its coarse-first order — for the two pairs of bench/simulate.bench.mjs. Baseline in the same
// process: 32 × the median single `simulate` at the pair's bench offset (so the ratio says
// whether some offsets are much dearer than the bench one), and the first 8-point pass (when the
// curve's shape first shows).
// Run: node bench/sweep.bench.mjs   (DFORMER_PKG overrides the package path)
import { createRequire } from 'node:module';
import { readFileSync } from 'node:fs';
import { runInThisContext } from 'node:vm';
import { ellipse } from '../tests/core/reference.mjs';
const require = createRequire(import.meta.url);
const m = require(process.env.DFORMER_PKG ?? '../core/pkg/dformer.js');
globalThis.window = globalThis; // sweep-point.js and sweep.js are the panel's classic scripts
for (const f of ['sweep-point.js', 'sweep.js']) runInThisContext(readFileSync(new URL(`../uxp-panel/src/${f}`, import.meta.url), 'utf8'));
const { sweepPoint, sweep } = globalThis.DF;

// The bench pairs of bench/simulate.bench.mjs: a 2:1 ellipse (four cubic arcs) twice, and with the
// circle of the same perimeter.
const e = ellipse([0, 0], 2, 1);
const P = m.measure(e).perimeter;
const r = P / m.measure(ellipse([0, 0], 1, 1)).perimeter;
const circle = ellipse([0, 0], r, r);
const median = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];

function run(name, pieces, benchOffset) {
  const single = [];
  for (let i = 0; i < 5; i++) {
    const t0 = performance.now();
    m.simulate(pieces, { offset: benchOffset });
    single.push(performance.now() - t0);
  }
  const one = median(single);
  const order = sweep.order(sweep.COUNT);
  const t0 = performance.now();
  let firstPass = 0;
  const points = [];
  order.forEach((k, i) => {
    points.push(sweepPoint(m, pieces, { offset: (k / sweep.COUNT) * P }, { mmPerUnit: 1 }));
    if (i === 7) firstPass = performance.now() - t0;
  });
  const total = performance.now() - t0;
  const unconverged = points.filter((p) => !p.converged).length;
  const big = sweep.best(points, 'volume');
  console.log(`== ${name} (WASM, 32 offsets × 256 seam vertices, cold) ==`);
  console.log(`  complete sweep ${total.toFixed(0)} ms (${(total / 32).toFixed(1)} ms per offset); first 8-offset pass ${firstPass.toFixed(0)} ms`);
  console.log(`  baseline: 32 × single simulate at the bench offset ${(32 * one).toFixed(0)} ms (${one.toFixed(1)} ms median of 5): ratio ${(total / (32 * one)).toFixed(2)}×`);
  console.log(`  ${32 - unconverged} of 32 converged; largest volume ${big ? big.volume.toFixed(4) : '—'} at ${big ? (big.offset / P).toFixed(4) : '—'} of the perimeter`);
}
run('two ellipses 2:1', [e, e], P / 4);
run('ellipse 2:1 with a circle', [e, circle], 0);
