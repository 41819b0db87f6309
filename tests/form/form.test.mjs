// formFigures and placeOnForm from Node (the WASM edge): a simulate result goes in as JS objects;
// figures are checked against closed forms, and every bad input throws the core's message.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { ellipse } from '../core/reference.mjs';

const require = createRequire(import.meta.url);
const m = require(process.env.DFORMER_PKG ?? '../../core/pkg/dformer.js');

test('formFigures: two congruent ellipses at offset 0 lie flat (height 0, width and depth the axes); litres and mass by unit and density', () => {
  const e = ellipse([0, 0], 60, 30);
  const form = m.simulate([e, e], { offset: 0, resolution: 64 });
  const f = m.formFigures(form);
  assert.ok(f.height < 1e-6 * 120, `wanted height 0, got ${f.height}`);
  assert.ok(Math.abs(f.width - 120) < 1e-6, `wanted width 120, got ${f.width}`);
  assert.ok(Math.abs(f.depth - 60) < 1e-6, `wanted depth 60, got ${f.depth}`);
  const q = m.simulate([e, e], { offset: m.measure(e).perimeter / 4, resolution: 64 });
  const pt = m.formFigures(q, { mmPerUnit: 25.4 / 72, density: 1000 });
  const litres = q.stats.volume * Math.pow(25.4 / 72, 3) / 1e6;
  assert.ok(Math.abs(pt.litres - litres) <= 1e-12 * litres, `litres: wanted ${litres}, got ${pt.litres}`);
  assert.ok(Math.abs(pt.mass - litres) <= 1e-12 * litres, `a litre of water is a kilogram: wanted ${litres}, got ${pt.mass}`);
  assert.ok(Math.abs(m.formFigures(q).mass - 2.4e-6 * q.stats.volume) <= 1e-12 * q.stats.volume, 'default density 2400 kg/m³ (concrete), form in mm');
});

test('placeOnForm: a corner of a flat triangle lands on its 3D vertex', () => {
  const e = ellipse([0, 0], 60, 30);
  const form = m.simulate([e, ellipse([200, 0], 60, 30)], { offset: 40, resolution: 48 });
  const t = form.triangles.findIndex((_, k) => form.piece[k] === 1);
  const [placed] = m.placeOnForm(form, [[], [form.flat[t][2]]])[1];
  const want = form.vertices[form.triangles[t][2]];
  assert.ok(Math.hypot(placed[0] - want[0], placed[1] - want[1], placed[2] - want[2]) < 1e-9, `wanted ${want}, got ${placed}`);
});

test('bad input to formFigures / placeOnForm throws the core message', () => {
  const e = ellipse([0, 0], 60, 30);
  const form = m.simulate([e, e], { offset: 30, resolution: 32 });
  const message = (f) => { try { f(); } catch (err) { return err.message; } return 'no error'; };
  assert.match(message(() => m.formFigures({})), /^Invalid input: form: .*missing field `vertices`/);
  assert.match(message(() => m.formFigures(form, { density: -1 })), /^Option `density`: must be a positive number/);
  assert.match(message(() => m.formFigures(form, { mmPerUnit: 0 })), /^Option `mmPerUnit`: must be a positive number/);
  assert.equal(message(() => m.placeOnForm(form, [[]])), 'Expected two lists of points (piece A, piece B), got 1.');
  assert.match(message(() => m.placeOnForm({ vertices: form.vertices, triangles: form.triangles }, [[], []])), /flat triangles/);
  assert.match(message(() => m.placeOnForm(form, [[[Infinity, 0]], []])), /point 0 of piece A is not finite|Invalid input/);
});
