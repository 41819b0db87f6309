// pathFromSvg / pathToSvg from Node: commands, exact quadratic elevation, arcs, round trips, errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { perimeter, ellipse, rel } from './reference.mjs';

const require = createRequire(import.meta.url);
const m = require(process.env.DFORMER_PKG ?? '../../core/pkg/dformer.js');

test('lines become corners, Z closes, one path per subpath', () => {
  const ps = m.pathFromSvg('M0 0 L10 0 l0 10 H0 Z m 20 0 h5 v5 z M50 50 L60 60');
  assert.equal(ps.length, 3);
  assert.deepEqual(ps[0].points.map((p) => p.anchor), [[0, 0], [10, 0], [10, 10], [0, 10]]);
  assert.ok(ps[0].points.every((p) => p.left[0] === p.anchor[0] && p.right[1] === p.anchor[1]), 'corners');
  assert.equal(ps[0].closed, true);
  assert.deepEqual(ps[1].points.map((p) => p.anchor), [[20, 0], [25, 0], [25, 5]], 'relative m after z starts at the previous start');
  assert.equal(ps[2].closed, false);
  assert.equal(m.measure(ps[0]).perimeter, 40);
});

test('quadratics are elevated exactly; S and T reflect', () => {
  const [p] = m.pathFromSvg('M0 0 Q 3 6 6 0 T 12 0 Z');
  assert.deepEqual(p.points[0].right, [2, 4]);
  assert.deepEqual(p.points[1].left, [4, 4]);
  assert.deepEqual(p.points[1].right, [8, -4], 'T reflects the quadratic control (9,-6) → elevated (8,-4)');
  const [c] = m.pathFromSvg('M0 0 C 0 5 5 10 10 10 S 20 5 20 0 Z');
  assert.deepEqual(c.points[1].right, [15, 10]);
});

test('arcs: a full circle from two arcs has the circle perimeter to the arc tolerance', () => {
  const [p] = m.pathFromSvg('M 10 0 A 10 10 0 0 1 -10 0 A 10 10 0 0 1 10 0 Z');
  const got = m.measure(p).perimeter, want = 2 * Math.PI * 10;
  assert.ok(rel(got, want) < 1e-6, `wanted ${want}, got ${got}`);
  const [tiny] = m.pathFromSvg('M 1e-5 0 A 1e-5 1e-5 0 1 1 -1e-5 0 A 1e-5 1e-5 0 1 1 1e-5 0 Z');
  const t = m.measure(tiny).perimeter;
  assert.ok(rel(t, 2 * Math.PI * 1e-5) < 1e-6, `tiny arc circle: wanted ${2 * Math.PI * 1e-5}, got ${t} (must not become a line)`);
});

test('pathToSvg → pathFromSvg round-trips coordinates bit for bit', () => {
  for (const shape of [ellipse([1e5 + 1 / 3, -Math.PI], 7.1, 0.3, 5), ellipse([0, 0], 1, 1, 4, true)]) {
    const d = m.pathToSvg(shape);
    assert.match(d, /^M\S+ \S+( C(\S+ ){5}\S+)+ Z$/);
    const [back] = m.pathFromSvg(d);
    assert.deepEqual(back.points, shape.points);
    assert.equal(m.measure(back).perimeter, m.measure(shape).perimeter);
    assert.ok(rel(m.measure(back).perimeter, perimeter(shape)) < 1e-12);
  }
  assert.equal(m.pathToSvg({ closed: true, points: [{ anchor: [0, 0] }, { anchor: [1, 0] }, { anchor: [1, 1] }] }), 'M0 0 L1 0 L1 1 Z');
  assert.equal(m.pathToSvg({ closed: false, points: [{ anchor: [0, 0] }, { anchor: [1, 0], left: [0.5, 1] }] }), 'M0 0 C0 0 0.5 1 1 0');
});

const throws = (fn, re, what) => assert.throws(fn, (e) => e instanceof Error && re.test(e.message), what);

test('unreadable path data is quoted in the error', () => {
  throws(() => m.pathFromSvg('M 0 0 L 10 X 5'), /at character 12 \(near "X 5"\): a number was expected/, 'letter for a number');
  throws(() => m.pathFromSvg('M 0 0 L 10 10 # 5'), /near "# 5"\): '#' is not a path command/, 'garbage');
  throws(() => m.pathFromSvg('L 0 0'), /must start with a moveto/, 'no moveto');
  throws(() => m.pathFromSvg('M 0 0 L 1'), /at its end \(character 10\): the data ends where a number was expected/, 'truncated');
  throws(() => m.pathFromSvg('M 0 0 L 1e999 0'), /the number 1e999 is out of range/, 'overflow');
  throws(() => m.pathFromSvg('M 0 0 A 5 5 0 2 1 3 3'), /arc flag \(0 or 1\)/, 'bad flag');
  throws(() => m.pathFromSvg(42), /expects SVG path data as a string/, 'not a string');
  throws(() => m.pathToSvg({ closed: true, points: [{ anchor: [0, 0] }] }), /needs at least 2/, 'one point');
  throws(() => m.pathToSvg({ closed: true, points: [{ anchor: [0, NaN] }, { anchor: [1, 1] }] }), /not a finite number/, 'NaN');
  assert.deepEqual(m.pathFromSvg(''), [], 'empty data draws nothing');
});
