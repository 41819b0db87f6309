// The simulated Illustrator DOM checked against the Scripting Reference's documented semantics
// and against geometry computed independently (closed forms, chord polylines).
import test from 'node:test';
import assert from 'node:assert/strict';
import { createHost } from './jsx-host.mjs';
import { referenceLength, referenceLengthOf, relErr } from './reference-length.mjs';
import { PathPointSelection, PointType, Transformation } from './sim/enums.mjs';

const close = (got, want, tol, what) =>
  assert.ok(Math.abs(got - want) <= tol, `${what}: wanted ${want}, got ${got} (tolerance ${tol})`);

test('PathItem.length of a polygon is the exact sum of its sides (closed adds the closing side)', () => {
  const h = createHost({ shapes: [
    { name: 'tri', polygon: [[0, 0], [3, 0], [3, 4]] },
    { name: 'open', polygon: [[0, 0], [3, 0], [3, 4]], closed: false },
  ] });
  close(h.find('tri').length, 12, 1e-12, 'closed 3-4-5 triangle');
  close(h.find('open').length, 7, 1e-12, 'open polyline');
});

test('PathItem.length of curved paths agrees with an independent chord/Richardson length', () => {
  const path = { closed: true, points: [
    { anchor: [0, 0], left: [-30, 40], right: [50, -20] },
    { anchor: [100, 10], left: [80, -40], right: [140, 60] },
    { anchor: [40, 90], left: [90, 120], right: [0, 70] },
  ] };
  const h = createHost({ shapes: [{ name: 'blob', path }, { name: 'e', ellipse: { top: 50, left: -20, width: 300, height: 41 } }] });
  const want = referenceLength(path);
  assert.ok(relErr(h.find('blob').length, want) < 1e-10, `blob: wanted ${want}, got ${h.find('blob').length}`);
  const e = h.find('e');
  assert.ok(relErr(e.length, referenceLengthOf(e)) < 1e-10, `ellipse: wanted ${referenceLengthOf(e)}, got ${e.length}`);
});

test('ellipse() draws 4 kappa-handle arcs inside [top, left, width, height]; a circle is within 0.03% of 2πr', () => {
  const h = createHost();
  const c = h.doc.pathItems.ellipse(110, 10, 200, 200);
  assert.equal(c.pathPoints.length, 4);
  assert.equal(c.closed, true);
  assert.deepEqual(c.geometricBounds, [10, 110, 210, -90], 'geometricBounds [left, top, right, bottom], y up');
  // The 4-arc kappa circle overshoots the true circle by at most 0.027% radially, so its length is
  // within that of 2πr (Riškus / Goldapp's error bound for kappa = 4(√2−1)/3).
  assert.ok(relErr(c.length, 2 * Math.PI * 100) < 3e-4, `circle length ${c.length} vs 2πr ${2 * Math.PI * 100}`);
});

test('PathPoint coordinates are copies; assigning sets them; setEntirePath makes corner points', () => {
  const h = createHost();
  const p = h.doc.pathItems.add();
  p.setEntirePath([[0, 0], [10, 0], [10, 10]]);
  assert.equal(p.pathPoints.length, 3);
  const a = p.pathPoints[1].anchor;
  a[0] = 999;
  assert.deepEqual(p.pathPoints[1].anchor, [10, 0], 'mutating the returned array must not move the point');
  assert.deepEqual(p.pathPoints[1].leftDirection, [10, 0], 'setEntirePath puts handles on the anchor');
  assert.equal(p.pathPoints[1].pointType, PointType.CORNER);
  p.pathPoints[1].rightDirection = [15, 5];
  assert.deepEqual(p.pathPoints[1].rightDirection, [15, 5]);
  assert.throws(() => { p.pathPoints[0].anchor = [1]; }, /2 numbers/);
  assert.throws(() => p.pathPoints[3], /No such element/, 'out-of-range index');
});

test('resize scales by percent about the chosen bounding-box point; length scales linearly', () => {
  const h = createHost({ shapes: [
    { name: 'c', ellipse: { top: 100, left: 0, width: 80, height: 40 } },
    { name: 'r', rect: { top: 50, left: 10, width: 20, height: 30 } },
  ] });
  const c = h.find('c');
  const before = c.length, [l, t, r, b] = c.geometricBounds;
  c.resize(150, 150, true, true, true, true, 100, Transformation.CENTER);
  const nb = c.geometricBounds;
  close((nb[0] + nb[2]) / 2, (l + r) / 2, 1e-9, 'centre x kept');
  close((nb[1] + nb[3]) / 2, (t + b) / 2, 1e-9, 'centre y kept');
  assert.ok(relErr(c.length, 1.5 * before) < 1e-12, `length ×1.5: wanted ${1.5 * before}, got ${c.length}`);
  const rect = h.find('r');
  rect.strokeWidth = 2;
  rect.resize(50, 200, true, true, true, true, 100, Transformation.TOPLEFT);
  assert.deepEqual(rect.geometricBounds, [10, 50, 20, -10], 'top-left fixed, width ×0.5, height ×2');
  assert.equal(rect.strokeWidth, 2, 'changeLineWidths 100 keeps the stroke');
  rect.resize(100, 100, true, true, true, true, 50, Transformation.BOTTOMRIGHT);
  assert.equal(rect.strokeWidth, 1, 'changeLineWidths 50 halves the stroke');
});

test('geometricBounds are the tight curve bounds, not the control polygon', () => {
  const h = createHost({ shapes: [{ name: 'arch', path: { closed: false, points: [
    { anchor: [0, 0], right: [0, 40] }, { anchor: [30, 0], left: [30, 40] },
  ] } }] });
  // x(t) stays in [0, 30]; y(t) = 120 t(1−t) peaks at 30 (control points reach 40).
  const [l, t, r, b] = h.find('arch').geometricBounds;
  close(t, 30, 1e-12, 'top'); close(b, 0, 1e-12, 'bottom'); close(l, 0, 1e-12, 'left'); close(r, 30, 1e-12, 'right');
});

test('collections are live, add() puts new items on top, layers.add() makes the new layer active and topmost', () => {
  const h = createHost();
  const layer = h.doc.layers[0];
  const paths = layer.pathItems;
  assert.equal(paths.length, 0);
  const first = layer.pathItems.add();
  const second = layer.pathItems.add();
  assert.equal(paths.length, 2, 'a collection fetched before add() sees the new items');
  assert.equal(paths[0], second, 'newest on top (index 0)');
  assert.equal(paths[1], first);
  const nl = h.doc.layers.add();
  assert.equal(h.doc.layers[0], nl);
  assert.equal(h.doc.activeLayer, nl);
  const p = h.doc.pathItems.add();
  assert.equal(p.layer, nl, 'document-level add() goes to the active layer');
  assert.throws(() => h.doc.layers.getByName('nope'), /No such element/);
});

test('locked or hidden layers and items cannot be modified', () => {
  const h = createHost({ shapes: [{ name: 'a', rect: { top: 0, left: 0, width: 1, height: 1 } }] });
  const layer = h.doc.layers[0];
  layer.locked = true;
  assert.throws(() => layer.pathItems.add(), /cannot be modified/);
  assert.throws(() => { h.find('a').pathPoints[0].anchor = [1, 1]; }, /cannot be modified/);
  layer.locked = false;
  layer.visible = false;
  assert.throws(() => layer.groupItems.add(), /cannot be modified/);
  layer.visible = true;
  h.find('a').locked = true;
  assert.throws(() => h.find('a').resize(200, 200), /cannot be modified/);
});

test('uuid and getPageItemFromUuid (Illustrator 24+), absent when simulating Illustrator 22', () => {
  const h = createHost({ shapes: [{ name: 'a', rect: { top: 0, left: 0, width: 1, height: 1 } }] });
  const a = h.find('a');
  assert.equal(typeof a.uuid, 'string');
  assert.equal(h.doc.getPageItemFromUuid(a.uuid), a);
  assert.throws(() => h.doc.getPageItemFromUuid('nope'), /No such element/);
  const old = createHost({ uuid: false, shapes: [{ name: 'a', rect: { top: 0, left: 0, width: 1, height: 1 } }] });
  assert.equal(old.find('a').uuid, undefined);
  assert.equal(old.doc.getPageItemFromUuid, undefined);
});

test('selection: selected groups are listed as groups; anchor selection states are per point', () => {
  const h = createHost({ shapes: [
    { name: 'in-group', rect: { top: 0, left: 0, width: 1, height: 1 }, group: 'G' },
    { name: 'loose', rect: { top: 0, left: 5, width: 1, height: 1 }, selectedAnchors: [2] },
    { name: 'unselected', rect: { top: 0, left: 9, width: 1, height: 1 }, selected: false },
  ] });
  const names = h.doc.selection.map((x) => x.name);
  assert.deepEqual(names.sort(), ['G', 'loose']);
  const loose = h.find('loose');
  assert.equal(loose.pathPoints[2].selected, PathPointSelection.ANCHORPOINT);
  assert.equal(loose.pathPoints[0].selected, PathPointSelection.NOSELECTION);
  assert.equal(loose.selectedPathPoints.length, 1);
  h.doc.selection = null;
  assert.equal(h.doc.selection.length, 0);
});

test('float32 mode rounds stored coordinates like Illustrator\'s 32-bit AIReal', () => {
  const h = createHost({ float32: true });
  const p = h.doc.pathItems.add();
  p.setEntirePath([[0.1, 1 / 3], [2, 2]]);
  assert.equal(p.pathPoints[0].anchor[0], Math.fround(0.1));
  assert.notEqual(p.pathPoints[0].anchor[0], 0.1);
});

test('text frames: anchor is settable, rotate() turns about the frame centre', () => {
  const h = createHost();
  const tf = h.doc.textFrames.add();
  tf.contents = 'AB';
  tf.anchor = [10, 20];
  assert.deepEqual(tf.anchor, [10, 20]);
  tf.rotate(90);
  assert.equal(tf.rotation, 90);
  assert.notDeepEqual(tf.anchor, [10, 20], 'rotating about the centre moves the baseline origin');
});

test('app.coordinateSystem: ARTBOARD reads and writes relative to the active artboard\'s top-left corner, y still up', () => {
  const h = createHost({ artboards: [[0, 0, 612, -792], [1000, -300, 1600, -900]], activeArtboard: 1,
    shapes: [{ name: 'r', rect: { top: -400, left: 1100, width: 200, height: 100 } }] });
  const { CoordinateSystem: CS } = h.context;
  const r = h.find('r');
  assert.equal(h.app.coordinateSystem, CS.DOCUMENTCOORDINATESYSTEM, 'default: document coordinates');
  assert.deepEqual(r.geometricBounds, [1100, -400, 1300, -500]);
  h.app.coordinateSystem = CS.ARTBOARDCOORDINATESYSTEM;
  assert.deepEqual(r.geometricBounds, [100, -100, 300, -200], 'relative to artboard 2\'s top-left [1000, -300]');
  assert.deepEqual(r.position, [100, -100]);
  assert.deepEqual(r.pathPoints[0].anchor, [100, -100]);
  assert.deepEqual(h.doc.artboards[1].artboardRect, [0, 0, 600, -600]);
  h.doc.artboards.setActiveArtboardIndex(0);
  assert.deepEqual(r.pathPoints[0].anchor, [1100, -400], 'same point, read against artboard 1 (at the document origin)');
  h.doc.artboards.setActiveArtboardIndex(1);
  r.pathPoints[0].anchor = [0, 0];
  assert.deepEqual(r._points[0]._a, [1000, -300], 'a write lands at the active artboard\'s corner');
  const t = h.doc.textFrames.add();
  t.anchor = [10, -10];
  assert.deepEqual(t._anchor, [1010, -310]);
  const e = h.doc.pathItems.rectangle(-10, 10, 5, 5);
  assert.deepEqual(e._points[0]._a, [1010, -310], 'rectangle(top, left, …) in the current system');
  h.app.coordinateSystem = 0;
  assert.equal(h.app.coordinateSystem, CS.DOCUMENTCOORDINATESYSTEM, 'numbers are accepted like ExtendScript enumerators');
  assert.deepEqual(r.pathPoints[0].anchor, [1000, -300]);
  assert.throws(() => { h.app.coordinateSystem = 7; }, /CoordinateSystem/);
  assert.throws(() => h.doc.artboards.setActiveArtboardIndex(2), /No such element/);
});

test('Document.documentColorSpace is read-only: RGB by default, CMYK when the host says so', () => {
  assert.equal(String(createHost().doc.documentColorSpace), 'DocumentColorSpace.RGB');
  const h = createHost({ colorSpace: 'CMYK' });
  assert.equal(h.doc.documentColorSpace, h.context.DocumentColorSpace.CMYK);
  assert.throws(() => { h.doc.documentColorSpace = h.context.DocumentColorSpace.RGB; });
});

// What real Illustrator does beyond the Scripting Reference's member lists (issue 11; sources in
// illustrator-scripts/BRIDGE.md, "What the simulated DOM models").
test('sim: new paths and text take the current style; [Default] graphic style resets it', () => {
  const h = createHost({ style: { strokeDashes: [4, 2], opacity: 50, blendingMode: 'MULTIPLY', brush: 'Charcoal' } });
  const p = h.doc.pathItems.add();
  assert.deepEqual([...p.strokeDashes], [4, 2]);
  assert.equal(p.opacity, 50);
  assert.equal(String(p.blendingMode), 'BlendModes.MULTIPLY');
  assert.equal(p.brush, 'Charcoal');
  const t = h.doc.textFrames.add();
  assert.equal(t.opacity, 50, 'text frames inherit the transparency too');
  h.doc.graphicStyles[0].applyTo(p);
  assert.deepEqual([[...p.strokeDashes], p.opacity, String(p.blendingMode), p.brush, p.strokeWidth], [[], 100, 'BlendModes.NORMAL', null, 1]);
  const fixture = createHost({ style: { opacity: 10 }, shapes: [{ name: 'A', rect: { top: 0, left: 0, width: 1, height: 1 } }] });
  assert.equal(fixture.find('A').opacity, 100, 'fixture shapes are not drawn with the current style');
});

test('sim: pointText puts the baseline at the point; bounds are the rotated glyph box, centred 0.35 size above the baseline', () => {
  const h = createHost();
  const tf = h.doc.textFrames.pointText([100, 50]);
  tf.contents = 'ABCD';
  tf.textRange.characterAttributes.size = 10;
  tf.textRange.paragraphAttributes.justification = h.context.Justification.CENTER;
  assert.deepEqual(tf.anchor, [100, 50]);
  let [l, t, r, b] = tf.geometricBounds;
  assert.deepEqual([l, t, r, b].map((v) => Math.round(v * 1e9) / 1e9), [88, 59.5, 112, 47.5], '24 wide (0.6 size per glyph), -2.5..+9.5 around the baseline');
  tf.rotate(90);
  [l, t, r, b] = tf.geometricBounds;
  assert.ok(Math.abs((l + r) / 2 - 100) < 1e-9 && Math.abs((t + b) / 2 - 53.5) < 1e-9, 'rotation about the centre keeps the bounds centre');
  assert.ok(Math.abs(r - l - 12) < 1e-9 && Math.abs(t - b - 24) < 1e-9, 'rotated box is 12 wide, 24 high');
  for (const mode of ['throws', 'ignored']) {
    const k = createHost({ labelAnchor: mode }).doc.textFrames.add();
    if (mode === 'throws') assert.throws(() => { k.anchor = [1, 2]; }, /read-only/);
    else { k.anchor = [1, 2]; assert.deepEqual(k.anchor, [0, 0], 'ignored'); }
  }
});

test('sim: Document.scaleFactor, app.preferences and Live Shape corners under resize()', () => {
  assert.equal(createHost().doc.scaleFactor, 1);
  assert.equal(createHost({ scaleFactor: 10 }).doc.scaleFactor, 10);
  assert.equal(createHost({ scaleFactor: null }).doc.scaleFactor, undefined, 'older Illustrator: no such property');
  const h = createHost({ shapes: [{ name: 'R', roundedRect: { top: 0, left: 0, width: 100, height: 60, radius: 10 } }] });
  const R = h.find('R');
  const prefs = h.app.preferences;
  assert.equal(prefs.getIntegerPreference('policyForPreservingCorners'), 2, 'Scale Corners is off by default');
  // Closed form with the simulator's kappa arcs: the straight parts scale, the corners do not.
  const arcs = referenceLengthOf(R) - 2 * (100 + 60 - 4 * 10);
  R.resize(200, 200);
  close(referenceLengthOf(R), 2 * (200 + 120 - 4 * 10) + arcs, 1e-6, 'corner radius kept');
  prefs.setIntegerPreference('policyForPreservingCorners', 1);
  R.resize(50, 50);
  close(referenceLengthOf(R), (2 * (200 + 120 - 4 * 10) + arcs) / 2, 1e-6, 'Scale Corners on: uniform scaling halves the length');
  const locked = createHost({ preferencesLocked: true });
  locked.app.preferences.setIntegerPreference('policyForPreservingCorners', 1);
  assert.equal(locked.app.preferences.getIntegerPreference('policyForPreservingCorners'), 2, 'a locked store ignores the setter');
});

test('sim: getPageItemFromUuid misses a compound path\'s sub-path unless told otherwise', () => {
  const shapes = [{ name: 'C', subName: 'inner', kind: 'compound', polygon: [[0, 0], [5, 0], [5, 5]] }];
  const h = createHost({ shapes });
  const inner = h.find('inner');
  assert.equal(h.doc.getPageItemFromUuid(h.find('C').uuid), h.find('C'));
  assert.throws(() => h.doc.getPageItemFromUuid(inner.uuid), /No such element/);
  const w = createHost({ shapes, compoundUuid: 'works' });
  assert.equal(w.doc.getPageItemFromUuid(w.find('inner').uuid), w.find('inner'));
});
