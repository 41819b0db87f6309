// Benchmark (not a test): connect() with 1,000 stitch holes on a 200-anchor path, from the
// WASM build in Node. Target: ≤ 5 ms per call. Build first (release):
//   wasm-pack build core --release --target nodejs --out-dir pkg
// then: node bench/connect.bench.mjs   (DFORMER_PKG=/path/to/dformer.js to use another build)
import { createRequire } from 'node:module';
import { performance } from 'node:perf_hooks';

const require = createRequire(import.meta.url);
const m = require(process.env.DFORMER_PKG ?? '../core/pkg/dformer.js');

/** A wavy closed curve with `n` smooth cubic anchors (Catmull–Rom handles), radius ~100. */
function wavy(n, lobes, cx = 0) {
  const pt = (i) => {
    const a = (2 * Math.PI * i) / n, r = 100 + 8 * Math.sin(lobes * a);
    return [cx + r * Math.cos(a), r * Math.sin(a)];
  };
  return {
    closed: true,
    points: Array.from({ length: n }, (_, i) => {
      const p = pt(i), q = pt(i + 1), o = pt(i - 1);
      const h = [(q[0] - o[0]) / 6, (q[1] - o[1]) / 6];
      return { anchor: p, left: [p[0] - h[0], p[1] - h[1]], right: [p[0] + h[0], p[1] + h[1]] };
    }),
  };
}

const A = wavy(200, 7);
// B: A mirrored (same perimeter exactly), drawn clockwise.
const B = { closed: true, points: A.points.map((k) => ({ anchor: [300 - k.anchor[0], k.anchor[1]], left: [300 - k.left[0], k.left[1]], right: [300 - k.right[0], k.right[1]] })) };
const opts = { kind: 'stitch', count: 1000, inset: 0.2, diameter: 0.15 };

/** Median and minimum ms per call of `f` over `rounds` rounds of `reps` calls (after warm-up). */
const time = (f, reps, rounds = 1) => {
  for (let i = 0; i < 3; i++) f();
  const per = [];
  for (let r = 0; r < rounds; r++) {
    const t0 = performance.now();
    for (let i = 0; i < reps; i++) f();
    per.push((performance.now() - t0) / reps);
  }
  per.sort((x, y) => x - y);
  return { median: per[per.length >> 1], min: per[0] };
};

const r = m.connect([A, B], opts);
// The machine may be shared: rounds of connect and of the same-process baseline (measure() of
// both pieces, which reads, validates and measures the same input) alternate, so both see the
// same load and their ratio stays meaningful.
const conn = [], meas = [];
for (let round = 0; round < 15; round++) {
  conn.push(time(() => m.connect([A, B], opts), 10).median);
  meas.push(time(() => { m.measure(A); m.measure(B); }, 10).median);
}
const med = (xs) => [...xs].sort((x, y) => x - y)[xs.length >> 1];
const msConnect = med(conn), msMeasure = med(meas), best = Math.min(...conn);
const target = 5;
console.log(`connect: ${r.count} holes per piece on a ${A.points.length}-anchor path (both pieces, ${2 * r.count} holes in all), warnings: ${r.warnings.length}`);
console.log(`connect time: ${msConnect.toFixed(3)} ms per call, median of 15 rounds (best round ${best.toFixed(3)} ms; target ≤ ${target} ms): ${msConnect <= target ? 'MET' : 'MISSED'}, ratio ${(msConnect / target).toFixed(2)} of target`);
console.log(`baseline in the same process: measure() of both pieces ${msMeasure.toFixed(3)} ms; connect / measure = ${(msConnect / msMeasure).toFixed(1)}×`);
for (const kind of ['teeth', 'leaves', 'hybrid']) {
  const o = { kind, count: 1000, inset: 0.3, diameter: 0.1, length: 0.2 };
  console.log(`  ${kind}: ${time(() => m.connect([A, B], o), 5).median.toFixed(2)} ms (no target)`);
}
