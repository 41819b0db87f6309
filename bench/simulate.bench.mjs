// WASM benchmark of simulate in Node (not a test): the issue's targets at 256 seam vertices.
// Run: node bench/simulate.bench.mjs   (DFORMER_PKG overrides the package path)
import { createRequire } from 'node:module';
import { maxBend } from './evolver/check.mjs';
import { polygonPath } from './evolver/outline.mjs';
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

// Reference volume: Richardson extrapolation of 256/512/1024 seam vertices with the observed
// order q = log2((v256 − v512)/(v512 − v1024)) (≈ 2): an estimate of the smooth limit, not an
// independent exact embedding.
function richardson(v1, v2, v4) {
  let q = Math.log2(Math.abs((v1 - v2) / (v2 - v4)));
  if (!(Number.isFinite(q) && q > 0.5)) q = 2;
  return [v4 + (v4 - v2) / (2 ** q - 1), q];
}

function run(name, pieces, offset) {
  const vol = (n) => m.simulate(pieces, { offset, resolution: n }).stats.volume;
  const v512 = vol(512), v1024 = vol(1024);
  m.simulate(pieces, { offset, resolution: 256 });
  const reps = 10, times = [];
  let r;
  for (let i = 0; i < reps; i++) {
    const t0 = performance.now();
    r = m.simulate(pieces, { offset, resolution: 256 });
    times.push(performance.now() - t0);
  }
  times.sort((a, b) => a - b);
  const ms = times[reps >> 1];
  const s = r.stats;
  const [exact, q] = richardson(s.volume, v512, v1024);
  // A slider drag: ten steps of 1 % of the perimeter, each re-solved warm from the step before
  // and, for comparison, cold at the same offset. The drag is timed the second time: the first
  // runs the warm path's code in V8's baseline tier (the cold path's was optimized by the timed
  // solves above), which made its first six re-solves 1.5–2.7 times slower than the last four.
  const dragOnce = () => {
    const drag = { warm: [], cold: [], dv: 0, converged: true };
    for (let k = 1, prev = r; k <= 10; k++) {
      const o = { offset: offset + 0.01 * k * P, resolution: 256 };
      let t0 = performance.now();
      const w = m.simulate(pieces, { ...o, warm: prev.vertices });
      drag.warm.push(performance.now() - t0);
      t0 = performance.now();
      const c = m.simulate(pieces, o);
      drag.cold.push(performance.now() - t0);
      drag.dv = Math.max(drag.dv, Math.abs(w.stats.volume - c.stats.volume) / c.stats.volume);
      drag.converged &&= w.stats.converged;
      prev = w;
    }
    return drag;
  };
  dragOnce();
  const drag = dragOnce();
  const median = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];
  const [warmMs, coldMs] = [median(drag.warm), median(drag.cold)];
  const v128 = vol(128);
  const dv = Math.abs(s.volume - exact) / exact, dres = Math.abs(s.volume - v128) / s.volume;
  console.log(`== ${name} (WASM, 256 seam vertices) ==`);
  console.log(`  volume ${s.volume.toFixed(6)} vs reference ${exact.toFixed(6)} (Richardson 256/512/1024, order ${q.toFixed(2)}): ${dv.toExponential(3)} (≤ 2e-3) ${mark(dv <= 2e-3)}`);
  console.log(`  max strain ${s.maxStrain.toExponential(3)} (≤ 1e-3) ${mark(s.maxStrain <= 1e-3)}`);
  console.log(`  seam gap ${(s.seamGap / P).toExponential(3)} of perimeter (≤ 1e-4) ${mark(s.seamGap / P <= 1e-4)}`);
  console.log(`  area error ${s.areaError.toExponential(3)} (≤ 1e-3) ${mark(s.areaError <= 1e-3)}`);
  console.log(`  interior |defect| ${(Math.abs(s.interiorDefectSum) / (4 * Math.PI)).toExponential(3)} of 4π (≤ 5e-3) ${mark(Math.abs(s.interiorDefectSum) <= 5e-3 * 4 * Math.PI)}`);
  console.log(`  volume change 128→256 ${dres.toExponential(3)} (≤ 5e-3) ${mark(dres <= 5e-3)}`);
  console.log(`  time ${ms.toFixed(1)} ms median of ${reps} (min ${times[0].toFixed(1)}) (≤ 300 ms) ${mark(ms <= 300)}  converged ${s.converged} iterations ${s.iterations}`);
  console.log(`  slider drag, 10 steps of 1 % of the perimeter: warm re-solve ${warmMs.toFixed(1)} ms median vs cold ${coldMs.toFixed(1)} ms at the same offsets (${(warmMs / coldMs).toFixed(2)}×, ≤ 1 as issue 14 asks) ${mark(warmMs <= coldMs)}, volume vs cold ≤ ${drag.dv.toExponential(1)}, all converged ${drag.converged}`);
}
run('two ellipses 2:1, quarter-perimeter offset', [e, e], P / 4);
run('ellipse 2:1 with a circle', [e, circle], 0);

// Issue 14's non-convex pairs (each normalized to the first piece): one cold solve at 256 seam
// vertices against the 1 s target. `converged` is the honest verdict (isometric to 1e-3, a closed
// 2-manifold, no crossing, no fold); the convex pairs above are the baseline of the same process.
const smooth = (pts) => ({
  closed: true,
  points: pts.map((a, i) => {
    const p = pts[(i + pts.length - 1) % pts.length], q = pts[(i + 1) % pts.length];
    const t = [(q[0] - p[0]) / 6, (q[1] - p[1]) / 6];
    return { anchor: a, left: [a[0] - t[0], a[1] - t[1]], right: [a[0] + t[0], a[1] + t[1]] };
  }),
});
const polar = (m, r) => smooth(Array.from({ length: m }, (_, k) => { const t = (2 * Math.PI * k) / m; return [r(t) * Math.cos(t), r(t) * Math.sin(t)]; }));
const scaled = (path, s) => ({ closed: true, points: path.points.map((k) => ({ anchor: k.anchor.map((v) => v * s), left: k.left.map((v) => v * s), right: k.right.map((v) => v * s) })) });
const circleFor = (path) => { const c = ellipse(1, 1); return scaled(c, m.measure(path).perimeter / m.measure(c).perimeter); };
// The browser app's bundled "Pebble" (uxp-panel/samples/samples.js), y flipped to y-up.
const pebbleSeg = [[[20, 62], [18, 30], [52, 12]], [[88, 16], [122, 20], [152, 30]], [[150, 62], [148, 92], [126, 106]], [[96, 100], [76, 96], [62, 108]], [[44, 104], [26, 100], [21, 82]]];
const up = ([x, y]) => [x, -y];
const pebble = { closed: true, points: pebbleSeg.map((s, i) => ({ anchor: up(s[0]), right: up(s[1]), left: up(pebbleSeg[(i + 4) % 5][2]) })) };
const kidney = polar(72, (t) => 60 * (1 + 0.35 * Math.cos(2 * t) - 0.25 * Math.cos(t) + 0.2 * Math.sin(3 * t)));
const lobes = polar(80, (t) => 55 * (1 + 0.12 * Math.sin(5 * t)));
// A heart (its tip is a tight smooth turn) and a star with rounded tips, as in core/tests/simulate_common/shapes.rs.
const heart = smooth(Array.from({ length: 64 }, (_, k) => {
  const t = (2 * Math.PI * k) / 64;
  return [3 * 16 * Math.sin(t) ** 3, 3 * (13 * Math.cos(t) - 5 * Math.cos(2 * t) - 2 * Math.cos(3 * t) - Math.cos(4 * t))];
}).reverse());
const star = polar(100, (t) => 50 * (1 + 0.28 * Math.cos(5 * t) ** 3));
// Stars whose tips and valleys are too tight for 128 seam samples to be isometric but not for
// 256 (core/src/simulate/sheet/level.rs, stop 54): 256 is 128's form refined at the seam.
const star4 = polar(100, (t) => 50 * (1 + 0.22 * Math.cos(4 * t) ** 3));
const star6 = polar(100, (t) => 50 * (1 + 0.15 * Math.cos(6 * t) ** 3));
// A five-pointed star polygon (valleys at 0.45 of the tips' 50 mm) with every corner rounded by
// `r` mm, as shapes.rs' star_polygon: sharp, it ends creased in a fifth of a second; rounded by
// 0.1-0.5 mm, below what 256 seam samples resolve and above a kink (core/src/simulate/kink.rs,
// stop 55), the sheet path does not find its form, and since stop 56 the preview takes the
// roundings as corners instead (core/src/simulate/corners.rs): its time is both solves'.
const roundedPolygon = (pts, r) => ({ closed: true, points: pts.flatMap((b, k) => {
  const n = pts.length;
  const unit = (p, q) => { const l = Math.hypot(q[0] - p[0], q[1] - p[1]); return [(q[0] - p[0]) / l, (q[1] - p[1]) / l]; };
  const [u, v] = [unit(b, pts[(k + n - 1) % n]), unit(b, pts[(k + 1) % n])];
  const inside = Math.acos(Math.min(1, Math.max(-1, u[0] * v[0] + u[1] * v[1])));
  const t = r / Math.tan(inside / 2);
  const h = (4 / 3) * Math.tan((Math.PI - inside) / 4) * r;
  const [a, c] = [[b[0] + u[0] * t, b[1] + u[1] * t], [b[0] + v[0] * t, b[1] + v[1] * t]];
  return [{ anchor: a, left: a, right: [a[0] - u[0] * h, a[1] - u[1] * h] }, { anchor: c, left: [c[0] - v[0] * h, c[1] - v[1] * h], right: c }];
}) });
const starCorners = Array.from({ length: 10 }, (_, i) => {
  const [radius, t] = [i % 2 === 0 ? 50 : 22.5, (Math.PI * i) / 5];
  return [radius * Math.sin(t), radius * Math.cos(t)];
});
const starSharp = polygonPath(starCorners);
const starRounded = roundedPolygon(starCorners, 0.25);
// A heart as drawn in Illustrator: corner anchors at the dip and the tip (shapes.rs' drawn_heart).
const knot = (anchor, left, right) => ({ anchor, left, right });
const drawnHeart = { closed: true, points: [
  knot([0, 40], [12, 50], [-12, 50]), knot([-30, 60], [-18, 60], [-42, 60]), knot([-55, 30], [-55, 45], [-55, 15]),
  knot([0, -45], [-20, -20], [20, -20]), knot([55, 30], [55, 15], [55, 45]), knot([30, 60], [42, 60], [18, 60]),
] };

// Each seam edge k → k+1 (k indexing `r.seam`) with its two flat lengths [A's, B's], read from
// the `flat` corners of its two triangles (one in each piece): the seam's own chords,
// independently of the solver's stats.
function seamChords(r) {
  const n = r.seam.length;
  const at = new Map(r.seam.map((v, k) => [v, k]));
  const chords = Array.from({ length: n }, () => [0, 0]);
  r.triangles.forEach((t, f) => {
    for (let q = 0; q < 3; q++) {
      const a = at.get(t[q]), b = at.get(t[(q + 1) % 3]);
      if (a === undefined || b === undefined) continue;
      const k = (a + 1) % n === b ? a : (b + 1) % n === a ? b : -1;
      if (k < 0) continue;
      const [p, w] = [r.flat[f][q], r.flat[f][(q + 1) % 3]];
      chords[k][r.piece[f]] = Math.hypot(p[0] - w[0], p[1] - w[1]);
    }
  });
  return chords;
}

// The sampling floor: a seam edge is one mesh edge with two flat lengths, A's chord and B's chord
// of the same arc (they differ by ~h³(κ_A² − κ_B²)/24), so no mesh on these seam samples can have
// a smaller max edge strain than (c_A − c_B)/(c_A + c_B) on its worst seam edge, whatever the
// solver.
function samplingFloor(r) {
  let worst = 0;
  for (const [ca, cb] of seamChords(r)) if (ca && cb) worst = Math.max(worst, Math.abs(ca - cb) / (ca + cb));
  return worst;
}

// Issue 14's requirement 3, mirror symmetry: a piece symmetric about a line, glued to a circle,
// has a mirror-symmetric form (the gluing maps the axis point's two sides onto each other by arc
// length). Read from the mesh alone: each seam vertex's arc length s along A (its chords, `seamChords`),
// the seam as a curve X(s), and for an axis at s0 the pairs X(s0 + u), X(s0 − u), u up to half
// the perimeter. The mirror plane is the one their differences are most along (the dominant
// eigenvector of Σ ddᵀ, by power iteration) through their midpoints; the gap is how far a
// point's reflection lands from its partner. The axis s0 is searched over the whole seam (a
// coarse scan, then golden section), so no shape's axis is told to it. Returns the largest gap
// and the form's size (its largest seam chord).
function mirrorGap(r) {
  const n = r.seam.length;
  const step = seamChords(r).map(([a]) => a);
  const cum = [0];
  for (let k = 0; k < n; k++) cum.push(cum[k] + step[k]);
  const L = cum[n];
  const X = (s) => {
    s = ((s % L) + L) % L;
    let lo = 0, hi = n;
    while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (cum[mid] <= s) lo = mid; else hi = mid; }
    const t = (s - cum[lo]) / step[lo];
    const [p, q] = [r.vertices[r.seam[lo]], r.vertices[r.seam[(lo + 1) % n]]];
    return [0, 1, 2].map((i) => p[i] + t * (q[i] - p[i]));
  };
  const gaps = (s0) => {
    const pairs = Array.from({ length: 199 }, (_, i) => { const u = (L / 2) * (i + 1) / 200; return [X(s0 + u), X(s0 - u)]; });
    const c = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
    for (const [p, q] of pairs) for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) c[i][j] += (p[i] - q[i]) * (p[j] - q[j]);
    let nrm = [0.6, 0.7, 0.4];
    for (let it = 0; it < 100; it++) { const v = c.map((row) => row[0] * nrm[0] + row[1] * nrm[1] + row[2] * nrm[2]); const l = Math.hypot(...v); nrm = v.map((x) => x / l); }
    const dot = (p) => p[0] * nrm[0] + p[1] * nrm[1] + p[2] * nrm[2];
    const off = pairs.reduce((acc, [p, q]) => acc + (dot(p) + dot(q)) / 2, 0) / pairs.length;
    let worst = 0, sq = 0;
    for (const [p, q] of pairs) {
      const d = dot(p) - off;
      const e = Math.hypot(...[0, 1, 2].map((i) => p[i] - 2 * d * nrm[i] - q[i]));
      worst = Math.max(worst, e);
      sq += e * e;
    }
    return [Math.sqrt(sq / pairs.length), worst];
  };
  let best = 0;
  for (let k = 1; k < 2 * n; k++) if (gaps((k * L) / (2 * n))[0] < gaps((best * L) / (2 * n))[0]) best = k;
  let [lo, hi] = [((best - 1) * L) / (2 * n), ((best + 1) * L) / (2 * n)];
  const g = (Math.sqrt(5) - 1) / 2;
  for (let it = 0; it < 40; it++) {
    const [x1, x2] = [hi - g * (hi - lo), lo + g * (hi - lo)];
    if (gaps(x1)[0] < gaps(x2)[0]) hi = x2; else lo = x1;
  }
  let size = 0;
  for (let i = 0; i < n; i++) for (let j = i + 1; j < n; j++) {
    const [p, q] = [r.vertices[r.seam[i]], r.vertices[r.seam[j]]];
    size = Math.max(size, Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
  }
  return { gap: gaps((lo + hi) / 2)[1], size };
}

// [name, piece, partner (a circle of its perimeter when left out), offset in perimeters]. The
// last two pairs end far off on the homotopy's own weight and are followed again
// (core/src/simulate/sheet/retry.rs): the drawn heart at a thicker weight; the kidney, through
// itself at every weight, with the sheets touching (sheet/contact.rs). The slowest kinds of
// solve a slider step can meet.
const nonConvex = [['Pebble + circle (the browser app sample)', pebble], ['kidney + circle', kidney],
  ['kidney + 2:1 ellipse at 1/8 (the issue\'s table)', kidney, scaled(ellipse(2, 1), m.measure(kidney).perimeter / m.measure(ellipse(2, 1)).perimeter), 1 / 8], ['five-lobed + circle', lobes], ['heart + circle', heart], ['heart drawn with corners + circle', drawnHeart], ['rounded star + circle', star],
  ['four-tipped star + circle', star4], ['six-tipped star + circle', star6],
  ['five-pointed star polygon, sharp corners + circle', starSharp], ['the same star, corners rounded by 0.25 mm + circle', starRounded],
  ['heart drawn with corners + its copy at 3/16 (followed again)', drawnHeart, drawnHeart, 3 / 16],
  ['kidney + its copy at 13/16 (followed again, touching)', kidney, kidney, 13 / 16]];
// The pieces above that are symmetric about a line (with a circle, so is their gluing).
const mirrorSymmetric = new Set([lobes, heart, drawnHeart, star, star4, star6, starSharp, starRounded]);
for (const [name, a, b, share] of nonConvex) {
  const pieces = [a, b ?? circleFor(a)];
  const offset = (share ?? 0) * m.measure(a).perimeter;
  // The first solve of a pair, then three more: the panel's worker re-solves the same pieces as
  // the slider moves, so the median of those is the figure the target is about; the first one
  // also pays for V8 tiering up the sheet path's code, and is printed beside it.
  let t0 = performance.now();
  const r = m.simulate(pieces, { offset, resolution: 256 });
  const first = performance.now() - t0;
  const again = [];
  for (let k = 0; k < 3; k++) {
    t0 = performance.now();
    m.simulate(pieces, { offset, resolution: 256 });
    again.push(performance.now() - t0);
  }
  again.sort((x, y) => x - y);
  const ms = again[1];
  const s = r.stats;
  console.log(`== ${name} (WASM, non-convex, 256 seam vertices) ==`);
  console.log(`  time ${ms.toFixed(1)} ms median of 3 (${again[0].toFixed(0)}–${again[2].toFixed(0)}; first solve ${first.toFixed(0)} ms) (≤ 1000 ms) ${mark(ms <= 1000)}   converged ${s.converged} ${mark(s.converged)}   max strain ${s.maxStrain.toExponential(2)} sharpest bend inside a piece ${maxBend(r.vertices, r.triangles, r.piece).toFixed(0)}° (≤ 90, from the mesh) iterations ${s.iterations}${s.converged ? '' : `   shortfall ${s.shortfall}`}`);
  // Issue 14's requirement 3, resolution independence: the same pair at half the seam vertices.
  // Since stop 48 a request of 256 is its level of 128 refined at the seam where that level's
  // answer is sound (core/src/simulate/sheet/level.rs), so this gap is the seam's refinement;
  // which of the sheet's equilibria the level falls into is a draw of its mesh, the spread over
  // knots nudged by 0.01 mm printed in the sensitivity section.
  const half = m.simulate(pieces, { offset, resolution: 128 }).stats;
  const apart = Math.abs(half.volume - s.volume) / s.volume;
  console.log(`  volume ${s.volume.toFixed(0)} at 256 seam vertices, ${half.volume.toFixed(0)} at 128: ${(100 * apart).toFixed(2)} % apart (≤ 1 %) ${mark(apart <= 1e-2)}${half.converged ? '' : `   at 128 converged false, shortfall ${half.shortfall}`}`);
  if (!b && mirrorSymmetric.has(a)) {
    // The tests' bar (core/tests/simulate_nonconvex.rs): 1e-5 of the size. Such a pair is
    // meshed as a half and its reflection (core/src/simulate/sheet/mirror.rs).
    const { gap, size } = mirrorGap(r);
    console.log(`  mirror symmetry (the piece is symmetric, so the form must be): the seam is ${gap.toExponential(2)} mm from its mirror image, ${(gap / size).toExponential(2)} of the form's size ${size.toFixed(0)} mm (≤ 1e-5) ${mark(gap <= 1e-5 * size)}`);
  }
  const floor = samplingFloor(r);
  console.log(`  sampling floor: no mesh on these seam samples gets below max edge strain ${floor.toExponential(2)} (≤ 1e-3 needed) ${mark(floor <= 1e-3)}${floor > 1e-3 ? ' — the samples, not the solver, rule out a converged answer' : ''}`);
}

// The whole slider of a classic D-form, two congruent pieces: an organic piece with its copy and
// with its mirror image, one solve at each of 16 offsets (k/16 of the perimeter), as the panel's
// slider and its sweep meet them. Printed: how many converged, the median and largest time, and
// the offsets that take over the 1 s a slider step may take or do not converge. (In the panel the
// slider does not wait for a solve it has moved on from for more than 1 s: uxp-panel/src/app.js.)
// And when the panel first shows a form there: the solve's interim form (simulateWithProgress's
// `interim`, the level's converged answer at 128 seam vertices, core/src/simulate/progress.rs)
// or else its result, with how far the interim's volume is from the result's.
const mirrored = (path) => ({ closed: true, points: path.points.map((q) => ({ anchor: [-q.anchor[0], q.anchor[1]], left: [-q.right[0], q.right[1]], right: [-q.left[0], q.left[1]] })).reverse() });
for (const [name, a, b] of [['Pebble + its copy', pebble, pebble], ['kidney + its copy', kidney, kidney], ['kidney + its mirror image', kidney, mirrored(kidney)]]) {
  const P = m.measure(a).perimeter;
  const runs = [];
  for (let k = 0; k < 16; k++) {
    let look = null;
    const t0 = performance.now();
    const s = m.simulateWithProgress([a, b], { offset: (k / 16) * P, resolution: 256 }, (p) => {
      if (p.interim) look = { ms: performance.now() - t0, volume: p.interim.stats.volume };
    }).stats;
    const ms = performance.now() - t0;
    runs.push({ k, ms, converged: s.converged, shortfall: s.shortfall, first: look ? look.ms : ms, dv: look ? Math.abs(look.volume / s.volume - 1) : null });
  }
  const times = runs.map((r) => r.ms).sort((x, y) => x - y);
  const firsts = runs.map((r) => r.first).sort((x, y) => x - y);
  const looks = runs.filter((r) => r.dv !== null);
  const dvs = looks.map((r) => r.dv).sort((x, y) => x - y);
  const slow = runs.filter((r) => r.ms > 1000 || !r.converged).map((r) => `${r.k}/16 ${(r.ms / 1000).toFixed(1)} s${r.dv !== null ? ` (first look ${(r.first / 1000).toFixed(1)} s)` : ''}${r.converged ? '' : ` ${r.shortfall}`}`);
  const conv = runs.filter((r) => r.converged).length;
  console.log(`== ${name}, the whole slider (WASM, non-convex, 256 seam vertices, 16 offsets) ==`);
  console.log(`  converged ${conv} of 16 ${mark(conv === 16)}   time median ${(times[7] / 2 + times[8] / 2).toFixed(0)} ms, largest ${times[15].toFixed(0)} ms (≤ 1000 ms) ${mark(times[15] <= 1000)}${slow.length ? `   over 1 s or not converged: ${slow.join(', ')}` : ''}`);
  console.log(`  first form shown (interim, else the result): median ${(firsts[7] / 2 + firsts[8] / 2).toFixed(0)} ms, largest ${firsts[15].toFixed(0)} ms (≤ 1000 ms) ${mark(firsts[15] <= 1000)}   interims ${looks.length} of 16${looks.length ? `, volume off the result's by median ${(100 * dvs[Math.floor(dvs.length / 2)]).toFixed(2)} %, largest ${(100 * dvs[dvs.length - 1]).toFixed(2)} %` : ''}`);
}

// Flat gluings: congruent pieces glued congruently make the flat doubly covered form. At offset 0
// the two sample polygons coincide and the solve takes one step per level; at another congruent
// gluing (a thin ellipse with its copy at half its perimeter) they differ by the arc-length
// tables' accuracy, which the saddle start turned into a 0.5 s crawl back to flat until
// convex/congruent.rs laid such pairs out directly. Printed against offset 0 in the same process.
{
  const thin = smooth(Array.from({ length: 72 }, (_, i) => { const t = (2 * Math.PI * i) / 72; return [60 * Math.cos(t), 7.5 * Math.sin(t)]; }));
  const P = m.measure(thin).perimeter;
  const time = (offset) => {
    const ms = [];
    let s;
    for (let i = 0; i < 5; i++) {
      const t0 = performance.now();
      s = m.simulate([thin, thin], { offset, resolution: 256 }).stats;
      ms.push(performance.now() - t0);
    }
    return { ms: ms.sort((x, y) => x - y)[2], s };
  };
  const [zero, half] = [time(0), time(P / 2)];
  console.log('== an 8:1 ellipse (72 points) with its copy: flat at offset 0 and at half its perimeter (WASM, 256 seam vertices) ==');
  console.log(`  half the perimeter ${half.ms.toFixed(1)} ms median of 5 vs offset 0 ${zero.ms.toFixed(1)} ms (${(half.ms / zero.ms).toFixed(2)}×, ≤ 2) ${mark(half.ms <= 2 * zero.ms)}   volume ${half.s.volume.toExponential(1)} and ${zero.s.volume.toExponential(1)}, converged ${half.s.converged} and ${zero.s.converged}`);
}

// Issue 14, convex pairs whose creases cross the seam: two congruent rectangles with 1 mm
// rounded corners (the classic D-form of two equal pieces). The chord meshes cannot hold a crease
// across the seam, so these take the intrinsic path (convex/crossing.rs) after the quick chord
// ladder gives up; printed against the 1 s a slider step may take, beside the seam vertices the
// crossings added.
const roundedRect = (w, h, r) => {
  const c = [[w - r, r, 0], [w - r, h - r, 1], [r, h - r, 2], [r, r, 3]];
  const pts = [];
  for (const [cx, cy, q] of c) {
    const a0 = (q - 1) * Math.PI / 2, a1 = q * Math.PI / 2;
    const p0 = [cx + r * Math.cos(a0), cy + r * Math.sin(a0)], p1 = [cx + r * Math.cos(a1), cy + r * Math.sin(a1)];
    const t0 = [-Math.sin(a0) * K * r, Math.cos(a0) * K * r], t1 = [-Math.sin(a1) * K * r, Math.cos(a1) * K * r];
    pts.push({ anchor: p0, left: p0, right: [p0[0] + t0[0], p0[1] + t0[1]] });
    pts.push({ anchor: p1, left: [p1[0] - t1[0], p1[1] - t1[1]], right: p1 });
  }
  return { closed: true, points: pts };
};
const rr = roundedRect(200, 40, 1);
const rrP = m.measure(rr).perimeter;
for (const k of [4, 5, 12]) {
  const o = { offset: (k / 16) * rrP, resolution: 256 };
  const times = [];
  let r;
  for (let i = 0; i < 3; i++) {
    const t0 = performance.now();
    r = m.simulate([rr, rr], o);
    times.push(performance.now() - t0);
  }
  times.sort((x, y) => x - y);
  const s = r.stats;
  console.log(`== two 200 × 40 mm rectangles with 1 mm corners, offset ${k}/16 (WASM, convex, creases across the seam) ==`);
  console.log(`  time ${times[1].toFixed(1)} ms median of 3 (≤ 1000 ms) ${mark(times[1] <= 1000)}   converged ${s.converged} ${mark(s.converged)}   seam vertices ${r.seam.length} (256 sampled)   max strain ${s.maxStrain.toExponential(2)} (sampling floor ${samplingFloor(r).toExponential(2)})   iterations ${s.iterations}`);
}

// Sensitivity (issue 14, requirement 3 presumes it is small): the same pair moved on the
// artboard, the same pair in other units (points, inches, CSS pixels: volumes divided by the
// scale's cube), and one knot of the first piece moved by 0.01 mm (four knots in turn). A
// moved or rescaled pair is the same drawing, so its form should not change at all; a 0.01 mm
// nudge changes the volume by ~1e-4 of itself, so a spread above that is the solver's, not the
// drawing's. Today the sheet path is deterministic for a given mesh, but the flat pieces'
// Delaunay refinement (a circle's samples are all but cocircular) and the seam weights' bins
// turn on the last bits of the samples, and another mesh ends in another equilibrium. Printed:
// the volumes' spread (max − min over min), the distinct answers and how many converged.
const moved = (path, [dx, dy]) => ({ closed: true, points: path.points.map((q) => ({ anchor: [q.anchor[0] + dx, q.anchor[1] + dy], left: [q.left[0] + dx, q.left[1] + dy], right: [q.right[0] + dx, q.right[1] + dy] })) });
const nudged = (path, k) => {
  const j = (7 * k) % path.points.length, d = [0.01, -0.005];
  const move = (p) => [p[0] + d[0], p[1] + d[1]];
  return { closed: true, points: path.points.map((q, i) => (i === j ? { anchor: move(q.anchor), left: move(q.left), right: move(q.right) } : q)) };
};
const spread = (runs) => {
  const vols = runs.map((s) => s.volume);
  const [lo, hi] = [Math.min(...vols), Math.max(...vols)];
  return { dv: (hi - lo) / lo, distinct: new Set(vols.map((v) => v.toPrecision(6))).size, conv: runs.filter((s) => s.converged).length, n: runs.length };
};
// A spread as printed: the volumes' spread against its bound, with the distinct answers.
const line = (w, r, bound) => `${w} ${(100 * r.dv).toFixed(2)} % (${r.distinct} distinct of ${r.n}, converged ${r.conv}) (≤ ${bound} %) ${mark(r.dv <= bound / 100)}`;
// One solve's stats and its wall time in ms.
const solve = (p, q, offset = 0, resolution = 256) => {
  const t0 = performance.now();
  const st = m.simulate([p, q], { offset, resolution }).stats;
  return { ...st, ms: performance.now() - t0 };
};
// An L-shaped hexagon (one reflex corner, shapes.rs' l_shape): every knot a corner.
const lShape = { closed: true, points: [[0, 0], [80, 0], [80, 40], [40, 40], [40, 80], [0, 80]].map((a) => ({ anchor: a, left: a, right: a })) };
console.log('== sensitivity (WASM, 256 seam vertices): the pair moved on the artboard, in other units, one knot moved by 0.01 mm, and the seam offset around the circle ==');
for (const [name, a] of [['kidney + circle', kidney], ['five-lobed + circle', lobes], ['heart drawn with corners + circle', drawnHeart], ['L + circle', lShape]]) {
  const c = circleFor(a);
  const base = solve(a, c);
  const mv = spread([base, ...[[37.3, -11.7], [250.1, 400.9], [-1000.3, 3.3]].map((d) => solve(moved(a, d), moved(c, [d[0] / 2 - 17, d[1]])))]);
  const sc = spread([base, ...[72 / 25.4, 1 / 25.4, 96 / 25.4].map((k) => {
    const s = solve(scaled(a, k), scaled(c, k));
    return { ...s, volume: s.volume / k ** 3 };
  })]);
  const ng = spread([base, ...[1, 2, 3, 4].map((k) => { const p = nudged(a, k); return solve(p, circleFor(p)); })]);
  // Around the circle: a circle turned is itself, so every offset glues one metric (the core
  // solves such a pair at offset 0 and turns the circle, simulate/round.rs; before, each offset
  // drew another mesh of the circle: the kidney spread by 2.8 % over 16 offsets, the L by 15 %).
  const P = m.measure(a).perimeter;
  const around = spread([base, ...[3, 7, 11].map((k) => solve(a, c, (k / 16) * P))]);
  console.log(`  ${name.padEnd(36)} ${line('moved: volume spread', mv, 0.01)}   ${line('in pt, in, px:', sc, 0.01)}   ${line('nudged 0.01 mm:', ng, 1)}   ${line('offsets 0, 3, 7, 11/16:', around, 0.01)}`);
}

// The drawing's bookkeeping (issue 14, requirement 3 presumes the form is the drawing's alone):
// which knot of the first piece is its first anchor, with a circle (a circle's offset is no
// choice, so every start glues one metric), and which piece is picked first (the same offset
// glues the same points either way: A's point at t meets B's at t + s walked clockwise, and
// swapped, B's point at u meets A's at u + s; since stop 51 such a pair is solved in an order
// of its own, core/src/simulate/picked.rs, so the spread is a check of that: it was 2.9 % for
// the kidney with the five lobes). Each is the same drawing, so the bound is the moved pair's. And a turn-symmetric piece picked first: offsets a period apart glue one metric
// and give one form (simulate/round.rs turns A's flat).
console.log('== bookkeeping (WASM, 256 seam vertices): which knot is first, which piece is first, a turn-symmetric first piece a period on ==');
{
  const startedAt = (path, j) => ({ closed: true, points: [...path.points.slice(j), ...path.points.slice(0, j)] });
  const P = m.measure(kidney).perimeter;
  const five = scaled(lobes, P / m.measure(lobes).perimeter);
  for (const [name, b] of [['kidney + five lobes', five], ['kidney + 2:1 ellipse', scaled(e, P / m.measure(e).perimeter)]]) {
    const swaps = [0.05, 0.3].map((f) => spread([solve(kidney, b, f * P), solve(b, kidney, f * P)]));
    const worst = swaps.reduce((w, r) => (r.dv > w.dv ? r : w));
    console.log(`  ${name.padEnd(36)} ${line('picked in either order, worst of offsets 0.05 and 0.3:', worst, 0.01)}`);
  }
  console.log(`  ${'five lobes + kidney'.padEnd(36)} ${line('offsets 0.05, 0.25, 0.45, 0.65:', spread([0.05, 0.25, 0.45, 0.65].map((f) => solve(five, kidney, f * P))), 0.01)}`);
  // The first anchor, with a circle, at up to eight knots and drawn the other way round: one
  // form since stop 49 (a pair with a non-convex piece is solved from its outline's canonical
  // start, core/src/simulate/anchor.rs; the kidney spread by 3.2 %, the smooth heart by 21 %
  // before), so the spread is a check of that, with the time of each start's solve at 256.
  for (const [name, a] of [['Pebble + circle', pebble], ['kidney + circle', kidney], ['five-lobed + circle', lobes], ['heart + circle', heart]]) {
    const c = circleFor(a), k = a.points.length, starts = [...new Set(Array.from({ length: Math.min(8, k) }, (_, i) => Math.floor((i * k) / Math.min(8, k))))];
    const reversed = { closed: true, points: [...a.points].reverse().map((q) => ({ anchor: q.anchor, left: q.right, right: q.left })) };
    const runs = [...starts.map((j) => solve(startedAt(a, j), c, 0, 256)), solve(reversed, c, 0, 256)];
    const ms = runs.map((r) => r.ms).sort((x, y) => x - y);
    console.log(`  ${name.padEnd(36)} ${line('first anchor at knots ' + starts.join(', ') + ' and drawn the other way:', spread(runs), 0.01)}   converged ${runs.filter((r) => r.converged).length} of ${runs.length}; time ${ms[0].toFixed(0)}–${ms[ms.length - 1].toFixed(0)} ms`);
  }
}
