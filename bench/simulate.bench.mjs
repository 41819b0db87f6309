// WASM benchmark of simulate in Node (not a test): the targets at 256 seam vertices.
// Run: node bench/simulate.bench.mjs   (DFORMER_PKG overrides the package path)
import { createRequire } from 'node:module';
const require = createRequire(import.meta.url);
const m = require(process.env.DFORMER_PKG ?? '../core/pkg/dformer.js');

const K = 0.5522847498307936;
const ellipse = (rx, ry, s = 1) => ({
  closed: true,
  points: [[1, 0], [0, 1], [-1, 0], [0, -1]].map(([x, y]) => {
    const a = [s * rx * x, s * ry * y], t = [-y * rx * K * s, x * ry * K * s];
    return { anchor: a, left: [a[0] - t[0], a[1] - t[1]], right: [a[0] + t[0], a[1] + t[1]] };
  }),
});
const e = ellipse(2, 1);
const P = m.measure(e).perimeter;
const circle = ellipse(1, 1, P / m.measure(ellipse(1, 1)).perimeter);
const mark = (ok) => (ok ? 'PASS' : 'MISS');

function run(name, pieces, offset) {
  const vol = (n) => m.simulate(pieces, { offset, resolution: n }).stats.volume;
  // Reference: Richardson extrapolation (O(h²)) of 1024 and 2048 seam vertices.
  const v1 = vol(1024), v2 = vol(2048);
  const exact = v2 + (v2 - v1) / 3;
  m.simulate(pieces, { offset, resolution: 256 });
  const reps = 5;
  const t0 = performance.now();
  let r;
  for (let i = 0; i < reps; i++) r = m.simulate(pieces, { offset, resolution: 256 });
  const ms = (performance.now() - t0) / reps;
  const s = r.stats;
  const v128 = vol(128);
  const dv = Math.abs(s.volume - exact) / exact, dres = Math.abs(s.volume - v128) / s.volume;
  console.log(`== ${name} (WASM, 256 seam vertices) ==`);
  console.log(`  volume ${s.volume.toFixed(6)} vs extrapolated ${exact.toFixed(6)}: ${dv.toExponential(3)} (≤ 2e-3) ${mark(dv <= 2e-3)}`);
  console.log(`  max strain ${s.maxStrain.toExponential(3)} (≤ 1e-3) ${mark(s.maxStrain <= 1e-3)}`);
  console.log(`  seam gap ${(s.seamGap / P).toExponential(3)} of perimeter (≤ 1e-4) ${mark(s.seamGap / P <= 1e-4)}`);
  console.log(`  area error ${s.areaError.toExponential(3)} (≤ 1e-3) ${mark(s.areaError <= 1e-3)}`);
  console.log(`  interior |defect| ${(s.interiorDefectSum / (4 * Math.PI)).toExponential(3)} of 4π (≤ 5e-3) ${mark(s.interiorDefectSum <= 5e-3 * 4 * Math.PI)}`);
  console.log(`  volume change 128→256 ${dres.toExponential(3)} (≤ 5e-3) ${mark(dres <= 5e-3)}`);
  console.log(`  time ${ms.toFixed(1)} ms (≤ 300 ms) ${mark(ms <= 300)}  converged ${s.converged} iterations ${s.iterations}`);
}
run('two ellipses 2:1, quarter-perimeter offset', [e, e], P / 4);
run('ellipse 2:1 with a circle', [e, circle], 0);
