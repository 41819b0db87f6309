// normalize(paths, options) from Node: perimeters re-measured by an independent quadrature.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { perimeter, ellipse, polygon, rel } from './reference.mjs';

const require = createRequire(import.meta.url);
const m = require(process.env.DFORMER_PKG ?? '../../core/pkg/dformer.js');

const egg = { closed: true, points: [
  { anchor: [60, 0], left: [60, -21], right: [60, 24] },
  { anchor: [0, 40], left: [33, 40], right: [-27, 40] },
  { anchor: [-50, 0], left: [-50, 22], right: [-50, -19] },
  { anchor: [0, -35], left: [-27, -35], right: [33, -35] },
] };
const square = polygon([[1000, 1000], [1090, 1000], [1090, 1090], [1000, 1090]]);
const tiny = ellipse([1e5, 1e5], 0.02, 0.01, 4, true);

test('every target gives equal perimeters (re-measured independently) and keeps point structure', () => {
  const shapes = [egg, square, tiny];
  const ps = shapes.map(perimeter);
  const want = { largest: Math.max(...ps), smallest: Math.min(...ps), mean: ps.reduce((a, b) => a + b) / ps.length, first: ps[0], 123.5: 123.5 };
  for (const [name, target] of Object.entries(want)) {
    const r = m.normalize(shapes, { target: name === '123.5' ? 123.5 : name });
    assert.ok(rel(r.perimeter, target) <= 1e-12, `${name}: wanted perimeter ${target}, got ${r.perimeter}`);
    r.paths.forEach((p, i) => {
      assert.equal(p.points.length, shapes[i].points.length, `${name}: path ${i} keeps its points`);
      assert.equal(p.closed, true);
      const got = perimeter(p);
      // 1e-12, unless the result is too small for its position to hold 12 digits: each
      // coordinate is rounded to ulp(|coordinate|), which moves the perimeter by up to
      // 2 ulp per coordinate (the 90-unit square shrunk to 0.1 units at x ≈ 1045).
      const maxc = Math.max(...p.points.flatMap((q) => [...q.anchor, ...q.left, ...q.right].map(Math.abs)));
      const tol = 1e-12 + (4 * p.points.length * 2 * 2 ** -52 * maxc) / r.perimeter;
      assert.ok(rel(got, r.perimeter) <= tol, `${name}: path ${i} wanted ${r.perimeter}, got ${got} (rel ${rel(got, r.perimeter).toExponential(2)})`);
      assert.ok(rel(r.scales[i], r.perimeter / ps[i]) <= 1e-12, `${name}: scale ${i} wanted ${r.perimeter / ps[i]}, got ${r.scales[i]}`);
    });
  }
});

test('target "first" leaves the first path untouched', () => {
  const r = m.normalize([egg, square], { target: 'first' });
  assert.equal(r.scales[0], 1);
  assert.deepEqual(r.paths[0].points.map((p) => p.anchor), egg.points.map((p) => p.anchor));
});

test('pivots: centre keeps the bounding-box centre, a point stays fixed, centroid keeps the centroid', () => {
  const before = m.measure(square);
  const c = m.normalize([square, egg], { target: 'largest', pivot: 'center' });
  const after = m.measure(c.paths[0]);
  for (const k of [0, 1]) {
    const mid = (b) => (b.min[k] + b.max[k]) / 2;
    assert.ok(Math.abs(mid(after.bounds) - mid(before.bounds)) < 1e-9, `bbox centre ${k}: wanted ${mid(before.bounds)}, got ${mid(after.bounds)}`);
  }
  const at = m.normalize([square, egg], { target: 500, pivot: [1000, 1000] });
  assert.deepEqual(at.paths[0].points[0].anchor, [1000, 1000], 'the pivot anchor does not move');
  const g = m.normalize([square, egg], { target: 500, pivot: 'centroid' });
  const ga = m.measure(g.paths[1]).centroid, gb = m.measure(egg).centroid;
  assert.ok(Math.hypot(ga[0] - gb[0], ga[1] - gb[1]) < 1e-9, `centroid wanted ${gb}, got ${ga}`);
});

const throws = (fn, re, what) => assert.throws(fn, (e) => e instanceof Error && re.test(e.message), what);

test('one path scales to a numeric target; pivot "start" keeps every first anchor in place', () => {
  const r = m.normalize([egg], { target: 200, pivot: 'start' });
  assert.ok(Math.abs(m.measure(r.paths[0]).perimeter - 200) < 1e-9 * 200, `perimeter ${m.measure(r.paths[0]).perimeter}`);
  assert.deepEqual(r.paths[0].points[0].anchor, egg.points[0].anchor, 'the first anchor stays');
  const two = m.normalize([egg, square], { pivot: 'start' });
  [egg, square].forEach((p, i) => assert.deepEqual(two.paths[i].points[0].anchor, p.points[0].anchor, `path ${i + 1}: first anchor`));
  // The other anchors move away from the first by the scale: |q − q0| grows by exactly s.
  const s = two.scales[1], q0 = square.points[0].anchor, q = square.points[2].anchor, g = two.paths[1].points[2].anchor;
  assert.ok(Math.abs(Math.hypot(g[0] - q0[0], g[1] - q0[1]) - s * Math.hypot(q[0] - q0[0], q[1] - q0[1])) < 1e-9, 'scaled about the first anchor');
});

test('bad options and inputs throw specific errors', () => {
  throws(() => m.normalize([egg], {}), /Expected at least 2 closed paths to normalize, or 1 with a number as the target perimeter, got 1/, 'one path');
  throws(() => m.normalize([], {}), /got 0/, 'no paths');
  throws(() => m.normalize([egg, square], { target: 'bigest' }), /Option `target`: must be "largest", "smallest", "mean", "first" or a perimeter .*got "bigest"/, 'unknown target');
  throws(() => m.normalize([egg, square], { target: 0 }), /Option `target`.*got 0/, 'zero target');
  throws(() => m.normalize([egg, square], { target: -5 }), /Option `target`.*got -5/, 'negative target');
  throws(() => m.normalize([egg, square], { target: NaN }), /Option `target`.*got NaN/, 'NaN target');
  throws(() => m.normalize([egg, square], { pivot: [1] }), /Option `pivot`: must be "center" .*"centroid", "start" \(each path's first anchor\) or a point \[x, y\].*got \[1\]/, 'short pivot');
  throws(() => m.normalize([egg, square], { pivot: 'middle' }), /Option `pivot`.*got "middle"/, 'unknown pivot');
  throws(() => m.normalize([egg, square], { pivot: [0, NaN] }), /Option `pivot`/, 'NaN pivot');
  throws(() => m.normalize([egg, square], { accuracy: 'high' }), /Option `accuracy`: must be a number, got "high"/, 'accuracy type');
  throws(() => m.normalize([egg, { ...square, closed: false }], {}), /The second path is open/, 'open second path');
  throws(() => m.normalize([egg, polygon([[0, 0], [1, 1], [1, 0], [0, 1]])], {}), /The second path crosses itself: segment 1 .* segment 3/, 'bow tie');
  throws(() => m.normalize([egg, square], { target: 1e306, pivot: [1e10, 0] }), /Option `target`.*leaves the range of numbers/, 'overflowing target');
  throws(() => m.normalize('paths', {}), /Invalid input: paths/, 'not an array');
});
