// measure(path, accuracy?) from Node against closed forms and an independent quadrature.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { perimeter, ellipse, polygon, ellipsePerimeter, rel } from './reference.mjs';

const require = createRequire(import.meta.url);
const m = require(process.env.DFORMER_PKG ?? '../../core/pkg/dformer.js');

const close = (got, want, tol, what) =>
  assert.ok(rel(got, want) <= tol, `${what}: wanted ${want}, got ${got} (relative error ${rel(got, want).toExponential(2)} > ${tol})`);

test('polygon: perimeter, area, orientation, bounds and centroid are exact', () => {
  const tri = polygon([[0, 0], [3, 0], [3, 4]]);
  const r = m.measure(tri);
  close(r.perimeter, 12, 1e-15, 'perimeter');
  close(r.area, 6, 1e-15, 'area');
  assert.equal(r.orientation, 'ccw');
  assert.deepEqual(r.bounds, { min: [0, 0], max: [3, 4] });
  close(r.centroid[0], 2, 1e-15, 'centroid x');
  close(r.centroid[1], 4 / 3, 1e-15, 'centroid y');
  const cw = m.measure(polygon([[0, 0], [3, 4], [3, 0]]));
  assert.equal(cw.orientation, 'cw', 'clockwise triangle');
  close(cw.area, 6, 1e-15, 'area of the clockwise triangle');
});

test('Bézier circles and ellipses: perimeter within 1e-12 of the quadrature, any size and place', () => {
  for (const [a, b] of [[1, 1], [5, 2]]) for (const scale of [0.01, 1, 1e4]) for (const at of [[0, 0], [1e5, -1e5]]) for (const cw of [false, true]) {
    const e = ellipse(at, a * scale, b * scale, 4, cw);
    const r = m.measure(e);
    close(r.perimeter, perimeter(e), 1e-12, `ellipse ${a}×${b} ×${scale} at ${at} ${cw ? 'cw' : 'ccw'}`);
    assert.equal(r.orientation, cw ? 'cw' : 'ccw');
    close(r.centroid[0] - at[0] + scale, scale, 1e-9, 'centroid x (symmetric shape: the centre)');
    close(r.centroid[1] - at[1] + scale, scale, 1e-9, 'centroid y');
    // Bounds 1e5 from the origin carry that position's rounding (ulp(1e5) ≈ 1.5e-11).
    const bound = r.bounds.max[0] - at[0], tol = 1e-12 * a * scale + 2 ** -52 * Math.abs(at[0]);
    assert.ok(Math.abs(bound - a * scale) <= tol, `right bound: wanted ${a * scale}, got ${bound}`);
  }
});

test('256-arc ellipse: perimeter matches the elliptic integral (AGM closed form)', () => {
  // The 256-arc approximation deviates from the true ellipse by ~1e-14 relative (θ⁶ law of the
  // cubic circle arc), so 1e-12 tests the module, not the approximation.
  for (const [a, b] of [[3, 1], [10, 9]]) {
    const got = m.measure(ellipse([7, -3], a, b, 256)).perimeter;
    close(got, ellipsePerimeter(a, b), 1e-12, `ellipse ${a}×${b}`);
  }
});

test('accuracy argument: every requested relative accuracy is met', () => {
  const e = ellipse([0, 0], 5, 1, 4);
  const want = perimeter(e);
  for (let k = 3; k <= 13; k++) close(m.measure(e, 10 ** -k).perimeter, want, 10 ** -k, `accuracy 1e-${k}`);
  assert.equal(m.DEFAULT_ACCURACY(), 1e-13);
});

test('degenerate segments and handles on anchors are normal input', () => {
  const p = { closed: true, points: [
    { anchor: [0, 0], left: [0, 0], right: [0, 0] },
    { anchor: [0, 0] },
    { anchor: [10, 0], left: [10, 0], right: [12, 3] },
    { anchor: [10, 10], left: null, right: null },
  ] };
  close(m.measure(p).perimeter, perimeter(p), 1e-12, 'perimeter');
});

const throws = (fn, re, what) => assert.throws(fn, (e) => e instanceof Error && re.test(e.message), what);

test('bad input throws an Error with a specific message', () => {
  const sq = polygon([[0, 0], [1, 0], [1, 1], [0, 1]]);
  throws(() => m.measure({ ...sq, closed: false }), /path is open/, 'open path');
  throws(() => m.measure(polygon([[0, 0]])), /has 1 point; an outline needs at least 2/, 'one point');
  throws(() => m.measure(polygon([])), /has 0 points/, 'no points');
  throws(() => m.measure(polygon([[0, 0], [NaN, 1], [1, 1]])), /not a finite number \(point 2, anchor\)/, 'NaN');
  throws(() => m.measure(polygon([[0, 0], [1, Infinity], [1, 1]])), /not a finite number/, 'Infinity');
  throws(() => m.measure(polygon([[0, 0], [1, 1], [1, 0], [0, 1]])), /crosses itself: segment 1 .* intersects segment 3/, 'bow tie');
  throws(() => m.measure({ closed: true, points: [{ anchor: [0, 0], right: [2, 1] }, { anchor: [1, 0], left: [-1, 1] }, { anchor: [1, -1] }] }),
    /segment 1 .*loops over itself/, 'loop inside one cubic');
  throws(() => m.measure(polygon([[1, 1], [1, 1], [1, 1]])), /zero length/, 'all points equal');
  throws(() => m.measure(sq, 0), /Option `accuracy`: must be a relative tolerance between/, 'accuracy 0');
  throws(() => m.measure(sq, NaN), /accuracy/, 'accuracy NaN');
  throws(() => m.measure({ closed: true, points: [{ anchor: [0, 'x'] }, { anchor: [1, 1] }] }), /Invalid input: path/, 'string coordinate');
  throws(() => m.measure(42), /Invalid input: path/, 'not an object');
});
