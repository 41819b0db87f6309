// The bridge writes what issue 15 added to a piece: slots (cut layer) and the seam line (score
// layer); a bad slot or seam is refused before anything is written.
import test from 'node:test';
import assert from 'node:assert/strict';
import { createHost } from './jsx-host.mjs';

const call = (h, fn, arg) => JSON.parse(h.evalScript(`${fn}(${JSON.stringify(JSON.stringify(arg))})`));
const square = (x, y, s) => ({ closed: true, points: [[x, y], [x + s, y], [x + s, y + s], [x, y + s]].map((a) => ({ anchor: a })) });
const host = () => createHost({ units: 'mm', shapes: [{ name: 'A', path: square(0, 0, 100) }] });
const payload = () => ({
  pieces: [{ name: 'piece A', outline: square(-3, -3, 106), slots: [square(10, 10, 4), square(50, 10, 4)], seam: square(0, 0, 100), holes: [], labels: [], marks: [] }],
});

test('slots go to the cut layer with the cut line, the seam line to the score layer', () => {
  const h = host();
  const r = call(h, 'dformer_apply', payload());
  assert.equal(r.ok, true, r.error);
  assert.equal(r.created, 4, 'cut line + 2 slots + seam line');
  const cut = h.doc.layers.getByName('Cut').groupItems.getByName('D-former piece A connectors');
  assert.deepEqual(cut.pathItems.getByName('slot 2').pathPoints[0].anchor, [50, 10]);
  const score = h.doc.layers.getByName('Score').groupItems.getByName('D-former piece A marks');
  assert.equal(score.pathItems.getByName('seam line').pathPoints.length, 4);
});

test('a bad slot or seam line is refused and nothing is written', () => {
  for (const [what, spoil, message] of [
    ['NaN in a slot', (p) => { p.pieces[0].slots[1].points[2].anchor[0] = null; }, /slots\[1\] point 2 anchor x: expected a finite number/],
    ['one-point seam', (p) => { p.pieces[0].seam = { closed: true, points: [{ anchor: [0, 0] }] }; }, /seam: a path needs at least 2 points, got 1/],
    ['slots not a list', (p) => { p.pieces[0].slots = 3; }, /slots: expected a list/],
  ]) {
    const h = host();
    const p = payload();
    spoil(p);
    const before = h.snapshot();
    const r = call(h, 'dformer_apply', p);
    assert.equal(r.ok, false, `${what}: should be refused`);
    assert.match(r.error, message, `${what}: ${r.error}`);
    assert.deepEqual(h.snapshot(), before, `${what}: document unchanged`);
  }
});
