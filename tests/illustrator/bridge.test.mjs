// The real dformer-bridge.jsx run in the simulated Illustrator DOM through the CSInterface stand-in.
import test from 'node:test';
import assert from 'node:assert/strict';
import { createHost } from './jsx-host.mjs';
import { PointType } from './sim/enums.mjs';

const call = (h, fn, arg) => {
  const src = arg === undefined ? `${fn}()` : `${fn}(${JSON.stringify(JSON.stringify(arg))})`;
  const text = h.evalScript(src);
  assert.notEqual(text, 'EvalScript error.', `${fn} threw instead of answering`);
  return JSON.parse(text);
};

const blob = { closed: true, points: [
  { anchor: [0, 0], left: [-30, 40], right: [50, -20] },
  { anchor: [100, 10], left: [80, -40], right: [140, 60] },
  { anchor: [40, 90], left: [90, 120], right: [0, 70] },
] };

function twoShapes(extra = {}) {
  return createHost({
    units: 'mm',
    shapes: [
      { name: 'A', path: blob },
      { name: 'B', ellipse: { top: 300, left: 200, width: 120, height: 80 } },
    ],
    ...extra,
  });
}

test('JSON writer/reader agree with the platform JSON on varied values', () => {
  const h = createHost();
  const values = [
    0, -0, 1e-300, 5e-324, 1.7976931348623157e308, 0.1 + 0.2, -123.456e-7, 1 / 3,
    '', 'plain', 'quote " backslash \\ slash / tab \t newline \n cr \r', '\u0001\u001f', 'é ü 漢字 😀', '\u2028\u2029',
    true, false, null, [], {}, [1, [2, [3, { a: [] }]]], { 'key with "quotes"': { nested: [null, true, 'x'] } },
  ];
  let seed = 7;
  const rnd = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  for (let i = 0; i < 200; i++) values.push((rnd() - 0.5) * 10 ** Math.floor(rnd() * 40 - 20));
  for (const v of values) {
    const ours = h.context.dformer_stringify(v);
    assert.deepEqual(JSON.parse(ours), JSON.parse(JSON.stringify(v)), `stringify ${JSON.stringify(v)} → ${ours}`);
    const back = h.context.dformer_parse(JSON.stringify(v));
    assert.deepEqual(JSON.parse(JSON.stringify(back)), JSON.parse(JSON.stringify(v)), `parse ${JSON.stringify(v)}`);
  }
  for (const bad of ['{', '[1,]', '{"a":1,}', '01', '1.', '"\\x"', 'tru', '{"a" 1}', '"a\nb"', '[1] 2', 'NaN', '']) {
    assert.throws(() => h.context.dformer_parse(bad), (e) => /malformed data/.test(e.dformer), `should reject ${JSON.stringify(bad)}`);
  }
});

test('dformer_units maps every ruler unit and its points per unit', () => {
  const want = { mm: ['mm', 72 / 25.4], cm: ['cm', 720 / 25.4], in: ['in', 72], pt: ['pt', 1], px: ['px', 1], pc: ['pc', 12],
    q: ['mm', 72 / 25.4], m: ['mm', 72 / 25.4], ft: ['in', 72], yd: ['in', 72], unknown: ['pt', 1] };
  for (const [units, [name, ppu]] of Object.entries(want)) {
    const r = call(createHost({ units }), 'dformer_units');
    assert.equal(r.ok, true);
    assert.equal(r.units, name, `units for ${units}`);
    assert.equal(r.pointsPerUnit, ppu, `pointsPerUnit for ${units}`);
  }
  const none = call(createHost({ noDocument: true }), 'dformer_units');
  assert.deepEqual(none, { ok: false, error: 'No document is open. Open or create a document, then select two paths.' });
  assert.equal(call(createHost({ noDocument: true }), 'dformer_info').hasDocument, false);
});

test('selection reads back as core paths in points, y up, with ids, names and anchor selection', () => {
  const h = twoShapes();
  h.find('A').pathPoints[1].selected = h.context.PathPointSelection.NOSELECTION;
  const r = call(h, 'dformer_selection');
  assert.equal(r.ok, true);
  assert.equal(r.units, 'mm');
  assert.equal(r.items.length, 2);
  const A = r.items.find((x) => x.name === 'A');
  const B = r.items.find((x) => x.name === 'B');
  assert.deepEqual(A.path, blob, 'path A exactly as drawn');
  assert.deepEqual(A.selectedAnchors, [0, 2]);
  assert.equal(A.allSelected, false);
  assert.equal(B.allSelected, true);
  assert.equal(B.path.points.length, 4);
  const bItem = h.find('B');
  B.path.points.forEach((q, i) => assert.deepEqual(q.anchor, bItem.pathPoints[i].anchor, `B point ${i}`));
  assert.equal(A.length, h.find('A').length, 'length is Illustrator\'s PathItem.length');
  assert.match(A.id, /^u:/);
  assert.deepEqual(r.skipped, []);
});

test('selection rules: groups descended, one-sub-path compound unwrapped, others skipped with reasons', () => {
  const h = createHost({ shapes: [
    { name: 'in group', rect: { top: 0, left: 0, width: 10, height: 10 }, group: 'G' },
    { name: 'clip', rect: { top: 0, left: 0, width: 10, height: 10 }, group: 'G', clipping: true },
    { name: 'single compound', kind: 'compound', polygon: [[0, 0], [5, 0], [5, 5]] },
    { name: 'donut', kind: 'compound', polygon: [[0, 0], [9, 0], [9, 9]], more: [[[1, 1], [2, 1], [2, 2]]] },
    { name: 'stray', polygon: [[3, 3]] },
    { name: 'words', kind: 'text' },
    { name: 'photo', kind: 'RasterItem' },
    { name: 'sym', kind: 'SymbolItem' },
    { name: 'not selected', rect: { top: 0, left: 0, width: 1, height: 1 }, selected: false },
  ] });
  const r = call(h, 'dformer_selection');
  assert.deepEqual(r.items.map((x) => x.name).sort(), ['<Path>', 'in group'].sort(), 'the single compound\'s sub-path is unnamed');
  const open = call(createHost({ shapes: [{ name: 'open line', polygon: [[0, 0], [5, 5], [9, 0]], closed: false }] }), 'dformer_selection');
  assert.equal(open.items[0].path.closed, false, 'an open path is included');
  const reasons = Object.fromEntries(r.skipped.map((s) => [s.name, s.reason]));
  assert.match(reasons.clip, /clipping path/);
  assert.match(reasons.donut, /compound path with 2 sub-paths: release it/);
  assert.match(reasons.stray, /single anchor point/);
  assert.match(reasons.words, /text frame.*Create Outlines/);
  assert.match(reasons.photo, /image/);
  assert.match(reasons.sym, /symbol/);
  assert.equal(Object.keys(reasons).length, 6);
});

test('hidden or locked art inside a selected group is skipped, not read as a piece', () => {
  const h = createHost({ shapes: [
    { name: 'A', rect: { top: 0, left: 0, width: 10, height: 10 }, group: 'G' },
    { name: 'B', rect: { top: 0, left: 20, width: 10, height: 10 }, group: 'G' },
    { name: 'construction line', polygon: [[0, 0], [30, 0]], closed: false, group: 'G', hidden: true },
    { name: 'reference copy', rect: { top: 0, left: 40, width: 10, height: 10 }, group: 'G', locked: true },
  ] });
  const r = call(h, 'dformer_selection');
  assert.deepEqual(r.items.map((x) => x.name).sort(), ['A', 'B']);
  const reasons = Object.fromEntries(r.skipped.map((s) => [s.name, s.reason]));
  assert.match(reasons['construction line'], /hidden inside a selected group/);
  assert.match(reasons['reference copy'], /locked inside a selected group: unlock it/);
});

test('no selection → ok with no items; selectionKey changes when geometry or anchor selection changes', () => {
  const h = twoShapes();
  const k1 = call(h, 'dformer_selectionKey').key;
  h.find('B').translate(1, 0);
  const k2 = call(h, 'dformer_selectionKey').key;
  assert.notEqual(k1, k2, 'moving a path changes the key');
  h.find('A').pathPoints[0].selected = h.context.PathPointSelection.NOSELECTION;
  const k3 = call(h, 'dformer_selectionKey').key;
  assert.notEqual(k2, k3, 'anchor selection changes the key');
  assert.equal(call(h, 'dformer_selectionKey').key, k3, 'stable when nothing changes');
  h.doc.selection = null;
  assert.deepEqual(call(h, 'dformer_selection').items, []);
});

test('selectionKey changes when a point moves inside the bounds or the points are re-ordered (no stale Apply)', () => {
  // A notched outline: anchor 3 is inside the bounding box, so dragging it with the Direct
  // Selection tool changes the outline but not geometricBounds.
  const h = createHost({ shapes: [
    { name: 'N', polygon: [[0, 0], [100, 0], [100, 100], [50, 50], [0, 100]] },
    { name: 'S', polygon: [[200, 0], [210, 0], [210, 10], [200, 10]] },
  ] });
  const N = h.find('N');
  const k1 = call(h, 'dformer_selectionKey').key;
  N.pathPoints[3].anchor = [50, 40];
  const k2 = call(h, 'dformer_selectionKey').key;
  assert.notEqual(k2, k1, 'moving an interior anchor changes the key');
  N.pathPoints[3].leftDirection = [45, 45];
  const k3 = call(h, 'dformer_selectionKey').key;
  assert.notEqual(k3, k2, 'moving a handle inside the bounds changes the key');
  // Rotating the square by 90° about its centre: same bounds, same length, new first anchor.
  const S = h.find('S');
  S._setPoints([[210, 0], [210, 10], [200, 10], [200, 0]].map((a) => ({ anchor: a, left: a, right: a })));
  const k4 = call(h, 'dformer_selectionKey').key;
  assert.notEqual(k4, k3, 're-ordered points change the key');
  assert.equal(call(h, 'dformer_selectionKey').key, k4, 'stable when nothing changes');
});

/** A payload like the panel's: scale A about its first anchor, one piece per path with holes/labels/marks. */
function payloadFor(sel, scale = 1.1) {
  const A = sel.items.find((x) => x.name === 'A');
  const B = sel.items.find((x) => x.name === 'B');
  const o = A.path.points[0].anchor;
  const s = (p) => [o[0] + (p[0] - o[0]) * scale, o[1] + (p[1] - o[1]) * scale];
  const scaled = { closed: true, points: A.path.points.map((q) => ({ anchor: s(q.anchor), left: s(q.left), right: s(q.right) })) };
  const hole = (x, y) => ({ center: [x, y], diameter: 2, path: { closed: true, points: [
    { anchor: [x + 1, y], left: [x + 1, y - 0.55], right: [x + 1, y + 0.55] },
    { anchor: [x, y + 1], left: [x + 0.55, y + 1], right: [x - 0.55, y + 1] },
    { anchor: [x - 1, y], left: [x - 1, y + 0.55], right: [x - 1, y - 0.55] },
    { anchor: [x, y - 1], left: [x - 0.55, y - 1], right: [x + 0.55, y - 1] },
  ] } });
  const piece = (id, name, base) => ({
    id, name,
    holes: [hole(base, 10), hole(base + 10, 10), hole(base + 20, 10).path],
    labels: [{ text: '1', at: [base, 20], angle: 0 }, { text: '2', at: [base + 10, 20], angle: 45, size: 9 }],
    marks: [{ closed: false, points: [{ anchor: [base, 0] }, { anchor: [base, 5] }] }],
  });
  return {
    document: sel.document,
    updates: [{ id: A.id, path: scaled }],
    pieces: [piece(A.id, 'piece A', 0), piece(B.id, 'piece B', 100)],
    layers: { cut: { name: 'Laser cut', color: [255, 0, 0], width: 0.01 }, score: { color: [0, 0, 255] } },
  };
}

test('apply updates in place (same PathItem, count, appearance) and writes pieces on named, grouped layers', () => {
  const h = twoShapes();
  const sel = call(h, 'dformer_selection');
  const A = h.find('A');
  A.strokeWidth = 3;
  A.fillColor.red = 12;
  const payload = payloadFor(sel);
  const r = call(h, 'dformer_apply', payload);
  assert.equal(r.ok, true, r.error);
  assert.equal(r.updated, 1);
  assert.equal(r.created, 2 * (3 + 2 + 1), 'holes + labels + marks of both pieces');
  assert.deepEqual(r.layers, ['Laser cut', 'Score', 'Engrave']);

  assert.equal(h.find('A'), A, 'same object: updated in place');
  assert.equal(A.pathPoints.length, 3);
  assert.equal(A.strokeWidth, 3, 'appearance kept');
  assert.equal(A.fillColor.red, 12, 'appearance kept');
  payload.updates[0].path.points.forEach((q, i) => {
    assert.deepEqual(A.pathPoints[i].anchor, q.anchor, `anchor ${i}`);
    assert.deepEqual(A.pathPoints[i].leftDirection, q.left, `left ${i}`);
    assert.deepEqual(A.pathPoints[i].rightDirection, q.right, `right ${i}`);
  });

  const layer = (name) => h.doc.layers.getByName(name);
  const cut = layer('Laser cut').groupItems.getByName('D-former piece A connectors');
  assert.equal(cut.pathItems.length, 3);
  const hole1 = cut.pathItems.getByName('hole 1');
  assert.deepEqual(hole1.pathPoints[1].anchor, [0, 11]);
  assert.deepEqual(hole1.pathPoints[1].leftDirection, [0.55, 11]);
  assert.equal(hole1.pathPoints[1].pointType, PointType.SMOOTH, 'collinear opposite handles → smooth');
  assert.equal(hole1.closed, true);
  assert.equal(hole1.filled, false);
  assert.equal(hole1.stroked, true);
  assert.equal(hole1.strokeWidth, 0.01);
  assert.deepEqual([hole1.strokeColor.red, hole1.strokeColor.green, hole1.strokeColor.blue], [255, 0, 0]);

  const marks = layer('Score').groupItems.getByName('D-former piece B marks');
  const mark = marks.pathItems.getByName('start mark');
  assert.equal(mark.closed, false);
  assert.deepEqual(mark.pathPoints[1].anchor, [100, 5]);
  assert.equal(mark.strokeWidth, 0.072, 'default hairline kept where the panel gave none');
  assert.deepEqual([mark.strokeColor.red, mark.strokeColor.green, mark.strokeColor.blue], [0, 0, 255]);
  assert.equal(mark.pathPoints[0].pointType, PointType.CORNER);

  const labels = layer('Engrave').groupItems.getByName('D-former piece B labels');
  const l2 = labels.textFrames.getByName('label 2');
  assert.equal(l2.contents, '2');
  assert.equal(l2.rotation, 45);
  assert.equal(l2.textRange.characterAttributes.size, 9);
  assert.equal(String(l2.textRange.paragraphAttributes.justification), 'Justification.CENTER');
  const c = l2._center();
  assert.ok(Math.hypot(c[0] - 110, c[1] - 20) < 1e-9, `label centre at [110, 20], got ${c}`);
  assert.equal(labels.textFrames.getByName('label 1').textRange.characterAttributes.size, 6, 'default label size');
});

test('re-applying replaces the previous D-former groups instead of stacking duplicates', () => {
  const h = twoShapes();
  const sel = call(h, 'dformer_selection');
  const p = payloadFor(sel);
  delete p.updates;
  assert.equal(call(h, 'dformer_apply', p).ok, true);
  assert.equal(call(h, 'dformer_apply', p).ok, true);
  const cut = h.doc.layers.getByName('Laser cut');
  assert.deepEqual(cut.groupItems.length, 2, 'one connectors group per piece');
  p.replace = false;
  assert.equal(call(h, 'dformer_apply', p).ok, true);
  assert.deepEqual(cut.groupItems.length, 4, 'replace:false keeps the old groups');
});

test('apply leaves the layer the student was drawing on as the current layer', () => {
  const h = twoShapes();
  const sel = call(h, 'dformer_selection');
  assert.equal(h.doc.activeLayer.name, 'Layer 1');
  assert.equal(call(h, 'dformer_apply', payloadFor(sel)).ok, true);
  assert.ok(h.doc._layers.some((l) => l.name === 'Engrave'), 'the Engrave layer was created');
  assert.equal(h.doc.activeLayer.name, 'Layer 1', 'new shapes still go to Layer 1, not to Engrave');
});

test('roles that share one layer name write to one layer, and re-applying replaces on it', () => {
  const h = twoShapes();
  const sel = call(h, 'dformer_selection');
  const p = payloadFor(sel);
  p.layers = { cut: { name: 'Laser', color: [255, 0, 0] }, score: { name: 'Laser', color: [0, 0, 255] }, engrave: { name: 'Laser', color: [0, 0, 0] } };
  const r = call(h, 'dformer_apply', p);
  assert.equal(r.ok, true, r.error);
  assert.deepEqual(r.layers, ['Laser']);
  const named = () => h.doc._layers.filter((l) => l.name === 'Laser');
  assert.equal(named().length, 1, 'one "Laser" layer, not one per role');
  assert.equal(named()[0].groupItems.length, 6, 'connectors, marks and labels of both pieces');
  delete p.updates;
  assert.equal(call(h, 'dformer_apply', p).ok, true);
  assert.equal(named().length, 1);
  assert.equal(named()[0].groupItems.length, 6, 're-applying replaces the groups instead of stacking them');
});

test('an invalid apply changes nothing in the document and says what is wrong', () => {
  const cases = [
    ['unknown id', (p) => { p.updates[0].id = 'u:999999'; }, /updates\[0\]: the path \(u:999999\) is no longer in the document/],
    ['not an id', (p) => { p.pieces[1].id = 'xyz'; }, /pieces\[1\]: "xyz" is not a D-former path id/],
    ['NaN coordinate (object payload)', (p) => { p.pieces[1].holes[2].points[3].anchor[1] = NaN; }, /pieces\[1\] \("piece B"\) holes\[2\] point 3 anchor y: expected a finite number, got NaN/],
    ['null coordinate (what JSON makes of NaN)', (p) => { p.updates[0].path.points[2].left = [1, null]; }, /updates\[0\] \("A"\) point 2 left y: expected a finite number, got null/],
    ['Infinity in a label', (p) => { p.pieces[0].labels[1].at = [Infinity, 0]; }, /labels\[1\] at x: expected a finite number, got Infinity/],
    ['point count changed', (p) => { p.updates[0].path.points.pop(); }, /has 3 anchors in Illustrator but the new path has 2/],
    ['same path twice', (p) => { p.updates.push(p.updates[0]); }, /updated twice/],
    ['other document', (p) => { p.document = 'Other.ai'; }, /active document is "Untitled-1.ai", not "Other.ai"/],
    ['bad colour', (p) => { p.layers.engrave = { color: [0, 0, 300] }; }, /layers.engrave.color: colour components go from 0 to 255, got 300/],
    ['zero width', (p) => { p.layers.cut.width = 0; }, /layers.cut.width: stroke width must be greater than 0/],
    ['one-point hole', (p) => { p.pieces[0].holes[0] = { closed: true, points: [{ anchor: [0, 0] }] }; }, /holes\[0\]: a path needs at least 2 points, got 1/],
    ['label without text', (p) => { delete p.pieces[0].labels[0].text; }, /labels\[0\]: text must be a string/],
    ['duplicate piece names', (p) => { p.pieces[1].name = 'piece A'; }, /two pieces are both named "piece A"/],
    // Illustrator throws past its type sizes mid-write (it used to be rolled back, not refused).
    ['label size above Illustrator’s largest type', (p) => { p.labelSize = 1300; }, /^labelSize must be from 0\.1 to 1296 pt \(Illustrator's type sizes\), got 1300\.$/],
    ['one label below Illustrator’s smallest type', (p) => { p.pieces[1].labels[0].size = 0.05; }, /pieces\[1\] \("piece B"\) labels\[0\]: size must be from 0\.1 to 1296 pt \(Illustrator's type sizes\), got 0\.05\./],
  ];
  for (const [what, spoil, message] of cases) {
    const h = twoShapes();
    const sel = call(h, 'dformer_selection');
    const p = payloadFor(sel);
    spoil(p);
    const before = h.snapshot();
    // Object-literal payload (NaN/Infinity survive), like evalScript('dformer_apply(' + literal + ')').
    const literal = JSON.stringify(p, (k, v) => (typeof v === 'number' && !Number.isFinite(v) ? `@@${v}@@` : v)).replace(/"@@(.*?)@@"/g, '$1');
    const r = JSON.parse(h.evalScript(`dformer_apply(${literal})`));
    assert.equal(r.ok, false, `${what}: should be refused`);
    assert.match(r.error, message, `${what}: message`);
    assert.deepEqual(h.snapshot(), before, `${what}: document must be unchanged`);
  }
});

test('locked target layer or locked path: refused before any write', () => {
  const h = twoShapes();
  const sel = call(h, 'dformer_selection');
  const p = payloadFor(sel);
  h.doc.layers.add().name = 'Engrave';
  h.doc.layers.getByName('Engrave').locked = true;
  let before = h.snapshot();
  let r = call(h, 'dformer_apply', p);
  assert.match(r.error, /Layer "Engrave" is locked; unlock and show it/);
  assert.deepEqual(h.snapshot(), before);
  h.doc.layers.getByName('Engrave').locked = false;
  h.find('A').locked = true;
  before = h.snapshot();
  r = call(h, 'dformer_apply', p);
  assert.match(r.error, /updates\[0\] \("A"\): cannot change the path because it is locked/);
  assert.deepEqual(h.snapshot(), before);
});

test('a locked or hidden previous D-former group: refused before any write, every old group kept (one used to be removed, then the locked one stopped Apply half way)', () => {
  for (const [state, reason] of [['locked', 'it is locked'], ['hidden', 'it is hidden']]) {
    const h = twoShapes();
    const sel = call(h, 'dformer_selection');
    const p = payloadFor(sel);
    delete p.updates;
    assert.equal(call(h, 'dformer_apply', p).ok, true);
    const cut = h.doc.layers.getByName('Laser cut');
    // The stacking order puts piece B's group above piece A's: A's is removed first, B's after.
    cut.groupItems.getByName('D-former piece B connectors')[state] = true;
    const before = h.snapshot();
    const r = call(h, 'dformer_apply', p);
    assert.equal(r.ok, false, `${state}: should be refused`);
    assert.equal(r.error, `The previous "D-former piece B connectors" group on layer "Laser cut" cannot be replaced because ${reason}: ` +
      'unlock and show it (Object > Unlock All, Object > Show All), or delete it, then apply again. Nothing was changed.');
    assert.deepEqual(h.snapshot(), before, `${state}: document unchanged`);
  }
});

test('if Illustrator throws midway, the bridge undoes what it wrote', () => {
  for (const fault of ['textFrames.pointText', 'PathPoint.rightDirection', 'layers.add', 'TextFrame.remove', 'GroupItem.remove']) {
    const h = twoShapes();
    const sel = call(h, 'dformer_selection');
    const p = payloadFor(sel);
    if (fault.endsWith('.remove')) { delete p.updates; call(h, 'dformer_apply', p); }
    const before = h.snapshot();
    // Fail on a late call: after the in-place update and some created items (remove faults hit the replace step).
    h.sim.faults[fault] = fault === 'PathPoint.rightDirection' ? 7 : fault === 'layers.add' ? 2 : 1;
    const r = call(h, 'dformer_apply', p);
    if (fault === 'TextFrame.remove') { assert.equal(r.ok, true, 'replace removes groups, not frames'); continue; }
    assert.equal(r.ok, false, `${fault}: error expected`);
    assert.match(r.error, /Illustrator reported an error while writing: simulated failure in .* \(the changes were undone\)/);
    assert.deepEqual(h.snapshot(), before, `${fault}: document restored`);
  }
});

test('Illustrator 22–23 (no uuid): positional ids work and go stale when the stacking order changes', () => {
  const h = twoShapes({ uuid: false });
  const sel = call(h, 'dformer_selection');
  const A = sel.items.find((x) => x.name === 'A');
  assert.match(A.id, /^p:L0\/\d+#3$/);
  assert.equal(call(h, 'dformer_apply', payloadFor(sel)).ok, true);
  // Apply added layers on top: layer indices moved, the old ids must be refused, not misapplied.
  const r = call(h, 'dformer_apply', payloadFor(sel));
  assert.match(r.error, /no longer in the document or changed since it was read; select the paths again/);
  const again = call(h, 'dformer_selection');
  assert.equal(call(h, 'dformer_apply', payloadFor(again)).ok, true, 'fresh ids work');
});

test('apply accepts a JSON string and reports malformed data', () => {
  const h = twoShapes();
  const sel = call(h, 'dformer_selection');
  assert.equal(call(h, 'dformer_apply', payloadFor(sel)).ok, true);
  const r = JSON.parse(h.evalScript('dformer_apply("{\\"updates\\": [}")'));
  assert.equal(r.ok, false);
  assert.match(r.error, /malformed data \(unexpected character at character 13\)/);
});

// app.coordinateSystem is one global setting that other scripts often leave on
// ARTBOARDCOORDINATESYSTEM; coordinates are then relative to whichever artboard is active.
const ARTBOARDS = [[1000, -300, 1600, -900], [-2000, 4000, -1400, 3400]];
const diamond = (c, r) => ({ closed: true, points: [[c[0] - r, c[1]], [c[0], c[1] - r], [c[0] + r, c[1]], [c[0], c[1] + r]].map((a) => ({ anchor: a })) });

test('coordinateSystem left on ARTBOARD: read on one artboard, Apply after switching artboards writes exactly on the piece; the setting is restored', () => {
  const h = createHost({
    units: 'mm', coordinateSystem: 'artboard', artboards: ARTBOARDS, activeArtboard: 0,
    shapes: [{ name: 'A', rect: { top: -400, left: 1100, width: 200, height: 100 } }],
  });
  const ARTBOARD = h.context.CoordinateSystem.ARTBOARDCOORDINATESYSTEM;
  const A = h.find('A');
  const stored = A._points.map((p) => p._a.slice());   // document coordinates, as Illustrator keeps them
  const key = call(h, 'dformer_selectionKey').key;
  const sel = call(h, 'dformer_selection');
  assert.equal(h.app.coordinateSystem, ARTBOARD, 'the student\'s setting is restored after reading');
  const piece = sel.items[0];
  assert.deepEqual(piece.path.points.map((q) => q.anchor), stored, 'read in document coordinates, whatever the active artboard');

  h.doc.artboards.setActiveArtboardIndex(1);            // the student clicks another artboard before Apply
  assert.equal(call(h, 'dformer_selectionKey').key, key, 'the fingerprint does not depend on the active artboard');
  const corners = piece.path.points.map((q) => q.anchor);
  const r = call(h, 'dformer_apply', {
    document: sel.document,
    updates: [{ id: piece.id, path: piece.path }],
    pieces: [{ id: piece.id, name: 'piece A', holes: corners.map((c) => diamond(c, 2)),
      labels: [{ text: '1', at: corners[0], angle: 0 }], marks: [{ closed: false, points: [{ anchor: corners[0] }, { anchor: corners[1] }] }] }],
  });
  assert.equal(r.ok, true, r.error);
  assert.equal(h.app.coordinateSystem, ARTBOARD, 'the student\'s setting is restored after Apply');
  assert.deepEqual(A._points.map((p) => p._a), stored, 'the in-place update leaves the piece where it is');
  const group = h.doc.layers.getByName('Cut').groupItems.getByName('D-former piece A connectors');
  corners.forEach((c, i) => {
    const hole = group.pathItems.getByName(`hole ${i + 1}`);
    assert.deepEqual(hole._points.map((p) => p._a), diamond(c, 2).points.map((q) => q.anchor), `hole ${i + 1} centred exactly on corner ${i}`);
  });
  const mark = h.doc.layers.getByName('Score').groupItems.getByName('D-former piece A marks').pathItems.getByName('start mark');
  assert.deepEqual(mark._points.map((p) => p._a), [corners[0], corners[1]], 'start mark on the piece');
  const label = h.doc.layers.getByName('Engrave').groupItems.getByName('D-former piece A labels').textFrames.getByName('label 1');
  const c = label._center();
  assert.ok(Math.hypot(c[0] - corners[0][0], c[1] - corners[0][1]) < 1e-9, `label centred on corner 0, got ${c}`);
});

test('the coordinate system is restored when a bridge call fails, and every entry point works in document coordinates', () => {
  const h = createHost({
    units: 'mm', coordinateSystem: 'artboard', artboards: ARTBOARDS, activeArtboard: 1,
    shapes: [{ name: 'A', rect: { top: -400, left: 1100, width: 200, height: 100 } }],
  });
  const ARTBOARD = h.context.CoordinateSystem.ARTBOARDCOORDINATESYSTEM;
  const DOCUMENT = h.context.CoordinateSystem.DOCUMENTCOORDINATESYSTEM;
  const DOC = String(DOCUMENT);
  for (const fn of ['dformer_info', 'dformer_units', 'dformer_selectionKey', 'dformer_selection']) {
    h.sim.coordinateUses = {};
    assert.equal(call(h, fn).ok, true, fn);
    assert.equal(h.app.coordinateSystem, ARTBOARD, `${fn} restores the setting`);
    assert.deepEqual(Object.keys(h.sim.coordinateUses).filter((k) => k !== DOC), [], `${fn} reads coordinates only in document coordinates`);
  }
  assert.ok(h.sim.coordinateUses[DOC] > 0, 'dformer_selection read coordinates');
  // Failures: a refused request, malformed JSON, and Illustrator throwing midway (rolled back).
  const sel = call(h, 'dformer_selection');
  assert.match(call(h, 'dformer_apply', { updates: [{ id: 'u:nope', path: sel.items[0].path }] }).error, /no longer in the document/);
  assert.equal(h.app.coordinateSystem, ARTBOARD, 'restored after a refused Apply');
  assert.match(JSON.parse(h.evalScript('dformer_apply("{")')).error, /malformed data/);
  assert.equal(h.app.coordinateSystem, ARTBOARD, 'restored after malformed data');
  const before = h.snapshot();
  h.sim.faults['pathItems.add'] = 2;
  const r = call(h, 'dformer_apply', { pieces: [{ name: 'piece A', holes: [diamond([0, 0], 1), diamond([5, 5], 1)] }] });
  assert.match(r.error, /simulated failure in pathItems\.add \(the changes were undone\)/);
  assert.deepEqual(h.snapshot(), before);
  assert.equal(h.app.coordinateSystem, ARTBOARD, 'restored after Illustrator threw midway');
  const noDoc = createHost({ noDocument: true, coordinateSystem: 'artboard' });
  assert.equal(call(noDoc, 'dformer_info').hasDocument, false);
  assert.match(call(noDoc, 'dformer_selection').error, /No document is open/);
  assert.equal(noDoc.app.coordinateSystem, noDoc.context.CoordinateSystem.ARTBOARDCOORDINATESYSTEM);
});

test('CMYK document: Apply that would write laser colours is refused with the menu to fix it; nothing changes', () => {
  const h = twoShapes({ colorSpace: 'CMYK' });
  const sel = call(h, 'dformer_selection');
  assert.equal(sel.colorMode, 'CMYK');
  assert.equal(call(h, 'dformer_units').colorMode, 'CMYK');
  const key = call(h, 'dformer_selectionKey').key;
  const before = h.snapshot();
  const r = call(h, 'dformer_apply', payloadFor(sel));
  assert.equal(r.ok, false, 'refused');
  assert.match(r.error, /This document uses CMYK colour/);
  assert.match(r.error, /Laser cut 255,0,0; Score 0,0,255; Engrave 0,0,0/, 'names the colours it would have written');
  assert.match(r.error, /Choose File > Document Color Mode > RGB Color, then Apply again\. Nothing was changed\.$/);
  assert.deepEqual(h.snapshot(), before, 'not even the in-place update is written');

  // Reshaping paths writes no colour: allowed in a CMYK document.
  const p = payloadFor(sel);
  const only = call(h, 'dformer_apply', { document: p.document, updates: p.updates });
  assert.equal(only.ok, true, only.error);
  assert.equal(only.updated, 1);

  // The student switches the document to RGB: the panel sees it, and Apply writes the exact RGB colours.
  h.doc._colorSpace = h.context.DocumentColorSpace.RGB;
  assert.notEqual(call(h, 'dformer_selectionKey').key, key, 'the fingerprint changes with the colour mode');
  assert.equal(call(h, 'dformer_selection').colorMode, 'RGB');
  assert.equal(call(h, 'dformer_apply', payloadFor(sel)).ok, true);
  const hole = h.doc.layers.getByName('Laser cut').groupItems.getByName('D-former piece A connectors').pathItems.getByName('hole 1');
  assert.equal(hole.strokeColor.typename, 'RGBColor');
  assert.deepEqual([hole.strokeColor.red, hole.strokeColor.green, hole.strokeColor.blue], [255, 0, 0]);
});
