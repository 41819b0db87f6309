// Issue 11: where real Illustrator differs from what the simulated DOM used to model, each case
// taught to the sim (tests/illustrator/sim/dom.mjs) and checked against the real bridge. Every test
// here failed on the bridge before the fix. Sources: illustrator-scripts/BRIDGE.md, "What the
// simulated DOM models".
import test from 'node:test';
import assert from 'node:assert/strict';
import { createHost } from './jsx-host.mjs';
import { ellipsePoints } from './sim/dom.mjs';
import { PointType } from './sim/enums.mjs';
import { referenceLength } from './reference-length.mjs';

const call = (h, fn, arg) => {
  const src = arg === undefined ? `${fn}()` : `${fn}(${JSON.stringify(JSON.stringify(arg))})`;
  const text = h.evalScript(src);
  assert.notEqual(text, 'EvalScript error.', `${fn} threw instead of answering`);
  return JSON.parse(text);
};
const rot = (p, c, deg) => {
  const a = (deg * Math.PI) / 180, x = p[0] - c[0], y = p[1] - c[1];
  return [c[0] + x * Math.cos(a) - y * Math.sin(a), c[1] + x * Math.sin(a) + y * Math.cos(a)];
};
/** A core path rotated by `deg` about `c`, keeping each point's type. */
const rotated = (points, c, deg) => ({ closed: true, points: points.map((q) => ({
  anchor: rot(q.anchor, c, deg), left: rot(q.left, c, deg), right: rot(q.right, c, deg), type: q.type,
})) });
const smoothEllipse = (top, left, w, h) => ellipsePoints(top, left, w, h, false).map((q) => ({ ...q, type: 'SMOOTH' }));
const scaleAbout = (path, o, k) => {
  const s = (p) => [o[0] + (p[0] - o[0]) * k, o[1] + (p[1] - o[1]) * k];
  return { closed: path.closed, points: path.points.map((q) => ({ anchor: s(q.anchor), left: s(q.left), right: s(q.right) })) };
};
const circlePath = (x, y, r) => ({ closed: true, points: ellipsePoints(y + r, x - r, 2 * r, 2 * r, false).map(({ anchor, left, right }) => ({ anchor, left, right })) });

test('test_issue_11_select_all_300_paths_poll_is_bounded: the poll reads a few points and answers in a few bytes, not 360,600 reads and 468 KB', () => {
  const shapes = [];
  for (let i = 0; i < 300; i++) {
    const n = 400, cx = (i % 20) * 30, cy = Math.floor(i / 20) * 30;
    shapes.push({ name: `p${i}`, polygon: Array.from({ length: n }, (_, k) => [cx + 10 * Math.cos((2 * Math.PI * k) / n), cy + 10 * Math.sin((2 * Math.PI * k) / n)]) });
  }
  for (const grouped of [false, true]) {
    const h = createHost({ shapes: grouped ? shapes.map((s) => ({ ...s, group: 'all' })) : shapes });
    h.sim.reads = 0;
    const key = h.evalScript('dformer_selectionKey()');
    const keyReads = h.sim.reads;
    h.sim.reads = 0;
    const sel = h.evalScript('dformer_selection()');
    const selReads = h.sim.reads;
    const what = grouped ? 'one selected group of 300 paths' : '300 selected paths';
    assert.ok(keyReads <= 50, `${what}: selectionKey reads wanted <= 50 point/bounds reads, got ${keyReads}`);
    assert.ok(key.length <= 200, `${what}: selectionKey answer wanted <= 200 characters, got ${key.length}`);
    assert.ok(selReads <= 50, `${what}: selection reads wanted <= 50, got ${selReads}`);
    assert.ok(sel.length <= 400, `${what}: selection answer wanted <= 400 characters, got ${sel.length}`);
    const r = JSON.parse(sel);
    assert.equal(r.ok, true);
    assert.equal(r.more, true, 'more than two paths: the "select two paths" state');
    assert.deepEqual(r.items, [], 'no geometry beyond the two pieces');
    assert.equal(r.selected, grouped ? 1 : 300, 'number of selected objects');
    // Deselecting one path changes the key (the panel re-reads), without reading any geometry.
    if (!grouped) {
      h.find('p7').selected = false;
      assert.notEqual(h.evalScript('dformer_selectionKey()'), key, 'one fewer selected path changes the key');
    }
  }
  // Two paths among 600 text frames: the walk gives up after 500 objects instead of visiting all on every poll.
  const texts = createHost({ shapes: [...shapes.slice(0, 2), ...Array.from({ length: 600 }, (_, i) => ({ name: `t${i}`, kind: 'text' }))] });
  const t = call(texts, 'dformer_selection');
  assert.equal(t.more, true, 'more than 500 selected objects: the "select two paths" state');
  assert.ok(JSON.stringify(t).length <= 400, `answer wanted <= 400 characters, got ${JSON.stringify(t).length}`);
  // Two pieces: the key reads their points (5 per point: selection, anchor, both handles, + bounds), nothing else.
  const two = createHost({ shapes: shapes.slice(0, 2) });
  two.sim.reads = 0;
  call(two, 'dformer_selectionKey');
  assert.ok(two.sim.reads <= 2 * 400 * 4 + 10, `two 400-point pieces: wanted <= ${2 * 400 * 4 + 10} reads, got ${two.sim.reads}`);
});

test('test_issue_11_smooth_points_become_corners_on_apply: a rotated ellipse and a rotated blob keep every point type through an in-place normalize (float32)', () => {
  const blob = [
    { anchor: [0, 0], left: [-30, 40], right: [30, -40], type: 'SMOOTH' },
    { anchor: [100, 10], left: [80, -40], right: [140, 60], type: 'CORNER' },
    // A corner whose handles happen to be collinear and opposite: it must stay a corner.
    { anchor: [40, 90], left: [90, 120], right: [-10, 60], type: 'CORNER' },
  ];
  for (const deg of [17, 37, 123.4]) {
    const h = createHost({ units: 'mm', float32: true, shapes: [
      { name: 'E', path: rotated(smoothEllipse(400, 30, 210, 95), [120, 300], deg) },
      { name: 'B', path: rotated(blob, [50, 50], deg) },
    ] });
    const before = Object.fromEntries(['E', 'B'].map((n) => [n, h.find(n)._points.map((p) => String(p._type))]));
    const sel = call(h, 'dformer_selection');
    const updates = sel.items.map((it) => ({ id: it.id, path: scaleAbout(it.path, it.path.points[0].anchor, 1.0731) }));
    const r = call(h, 'dformer_apply', { document: sel.document, updates });
    assert.equal(r.ok, true, r.error);
    for (const n of ['E', 'B']) {
      const got = h.find(n)._points.map((p) => String(p._type));
      assert.deepEqual(got, before[n], `${n} rotated ${deg} degrees: wanted ${before[n]}, got ${got}`);
    }
  }
});

test('test_issue_11_large_canvas_is_10x_off: with Document.scaleFactor 10 the panel sees real points and Apply writes DOM points', () => {
  const h = createHost({ units: 'mm', scaleFactor: 10, shapes: [
    { name: 'A', ellipse: { top: 100, left: 0, width: 80, height: 50 } },
    { name: 'B', rect: { top: 100, left: 200, width: 40, height: 60 } },
  ] });
  const A = h.find('A');
  const sel = call(h, 'dformer_selection');
  assert.equal(sel.scaleFactor, 10);
  assert.equal(call(h, 'dformer_units').scaleFactor, 10);
  const a = sel.items.find((x) => x.name === 'A');
  a.path.points.forEach((q, i) => assert.deepEqual(q.anchor, A.pathPoints[i].anchor.map((v) => 10 * v), `anchor ${i} in real points`));
  const wantLength = 10 * referenceLength({ closed: true, points: A._plain() });
  assert.ok(Math.abs(a.length - wantLength) < 1e-9 * wantLength, `length: wanted ${wantLength} real pt, got ${a.length}`);
  const r = call(h, 'dformer_apply', {
    document: sel.document,
    updates: [{ id: a.id, path: scaleAbout(a.path, [0, 0], 2) }],
    pieces: [{ id: a.id, name: 'piece A', holes: [circlePath(300, 400, 5)], labels: [{ text: '7', at: [300, 420], angle: 30 }],
      marks: [{ closed: false, points: [{ anchor: [300, 0] }, { anchor: [300, 50] }] }] }],
  });
  assert.equal(r.ok, true, r.error);
  a.path.points.forEach((q, i) => {
    const got = A.pathPoints[i].anchor, want = q.anchor.map((v) => (2 * v) / 10);
    assert.ok(Math.hypot(got[0] - want[0], got[1] - want[1]) < 1e-9, `updated anchor ${i}: wanted DOM ${want}, got ${got}`);
  });
  const cut = h.doc.layers.getByName('Cut').groupItems.getByName('D-former piece A connectors').pathItems.getByName('hole 1');
  assert.deepEqual(cut.pathPoints[0].anchor, [29.5, 40], 'hole (leftmost anchor at real x 295) written at real/10 in the DOM');
  assert.ok(Math.abs(cut.strokeWidth - 0.0072) < 1e-12, `hairline: wanted DOM 0.0072 pt (0.072 pt printed), got ${cut.strokeWidth}`);
  const label = h.doc.layers.getByName('Engrave').groupItems.getByName('D-former piece A labels').textFrames.getByName('label 1');
  assert.ok(Math.abs(label.textRange.characterAttributes.size - 0.6) < 1e-12, `label size: wanted DOM 0.6 pt (6 pt printed), got ${label.textRange.characterAttributes.size}`);
  const c = label._center();
  assert.ok(Math.hypot(c[0] - 30, c[1] - 42) < 1e-6, `label centre: wanted DOM [30, 42], got ${c}`);
  // No scaleFactor property (Illustrator before Large Canvas): read as 1.
  const old = createHost({ scaleFactor: null, shapes: [{ name: 'A', rect: { top: 10, left: 0, width: 10, height: 10 } }] });
  assert.deepEqual(call(old, 'dformer_selection').items[0].path.points[0].anchor, [0, 10]);
});

test('test_issue_11_label_anchor_setter: labels land on their place when TextFrame.anchor works, throws or is ignored', () => {
  for (const labelAnchor of ['works', 'throws', 'ignored']) {
    const h = createHost({ labelAnchor, shapes: [{ name: 'A', rect: { top: 100, left: 0, width: 100, height: 100 } }] });
    const sel = call(h, 'dformer_selection');
    const labels = [[0, [10, 20]], [45, [50, 60]], [90, [-20, 5]], [-30, [70, -40]], [180, [0, 0]]]
      .map(([angle, at], i) => ({ text: String(10 + i), at, angle, size: 8 }));
    const r = call(h, 'dformer_apply', { document: sel.document, pieces: [{ id: sel.items[0].id, name: 'piece A', labels }] });
    assert.equal(r.ok, true, `${labelAnchor}: ${r.error}`);
    const frames = h.doc.layers.getByName('Engrave').groupItems.getByName('D-former piece A labels');
    labels.forEach((l, i) => {
      const tf = frames.textFrames.getByName(`label ${i + 1}`);
      const c = tf._center();
      assert.ok(Math.hypot(c[0] - l.at[0], c[1] - l.at[1]) < 1e-9, `${labelAnchor}: label ${l.text} at ${l.angle} degrees: wanted centre ${l.at}, got ${c}`);
      assert.equal(tf.rotation, l.angle, `${labelAnchor}: rotation`);
    });
  }
});

test('test_issue_11_new_art_inherits_the_current_style: cut, score and engrave items are plain, whatever the student last drew with', () => {
  const style = { strokeDashes: [4, 2], strokeDashOffset: 1, strokeCap: 'ROUNDENDCAP', strokeJoin: 'ROUNDENDJOIN', strokeMiterLimit: 4,
    opacity: 50, blendingMode: 'MULTIPLY', strokeOverprint: true, fillOverprint: true, brush: 'Charcoal - Feather' };
  const h = createHost({ style, shapes: [{ name: 'A', ellipse: { top: 100, left: 0, width: 100, height: 60 } }] });
  const A = h.find('A');
  A.strokeDashes = [9, 9];
  const sel = call(h, 'dformer_selection');
  const id = sel.items[0].id;
  const r = call(h, 'dformer_apply', {
    document: sel.document, updates: [{ id, path: scaleAbout(sel.items[0].path, [0, 0], 1.1) }],
    pieces: [{ id, name: 'piece A', outline: circlePath(50, 70, 40), holes: [circlePath(20, 70, 2)], labels: [{ text: '1', at: [20, 80] }],
      marks: [{ closed: false, points: [{ anchor: [0, 70] }, { anchor: [5, 70] }] }] }],
  });
  assert.equal(r.ok, true, r.error);
  const plain = { strokeDashes: [], strokeDashOffset: 0, strokeCap: 'StrokeCap.BUTTENDCAP', strokeJoin: 'StrokeJoin.MITERENDJOIN', strokeMiterLimit: 10,
    opacity: 100, blendingMode: 'BlendModes.NORMAL', strokeOverprint: false, fillOverprint: false, brush: null };
  const all = [];
  const walk = (items) => { for (const it of items) { all.push(it); if (it.items) walk(it.items); } };
  for (const l of h.snapshot()[0].layers) walk(l.items);
  const made = all.filter((it) => it.typename === 'PathItem' && it.name !== 'A');
  assert.equal(made.length, 3, 'outline, hole and start mark written');
  for (const p of made) assert.deepEqual(p.style, plain, `${p.name}: wanted a plain stroke, got ${JSON.stringify(p.style)}`);
  const text = all.find((it) => it.typename === 'TextFrame');
  assert.deepEqual([text.opacity, text.blendingMode], [100, 'BlendModes.NORMAL'], 'label: opaque, normal blending');
  assert.deepEqual(A.strokeDashes, [9, 9], 'the student\'s own path keeps its style');
});

test('test_issue_11_compound_sub_path_uuid: a compound path\'s sub-path is written through the compound\'s uuid, also when getPageItemFromUuid misses sub-paths', () => {
  for (const [compoundUuid, uuid] of [['throws', true], ['works', true], ['throws', false]]) {
    const what = `uuid ${uuid}, sub-path lookup ${compoundUuid}`;
    const h = createHost({ uuid, compoundUuid, shapes: [
      { name: 'compound', subName: 'inner', kind: 'compound', polygon: [[0, 0], [50, 0], [50, 50], [0, 50]] },
      { name: 'B', rect: { top: 300, left: 200, width: 40, height: 60 } },
    ] });
    const sel = call(h, 'dformer_selection');
    const it = sel.items.find((x) => x.name === 'inner');
    assert.match(it.id, uuid ? /^c:\d+\/0#4$/ : /^p:L0\/\d+\/C0#4$/, what);
    const path = scaleAbout(it.path, [0, 0], 1.5);
    const r = call(h, 'dformer_apply', { document: sel.document, updates: [{ id: it.id, path }] });
    assert.equal(r.ok, true, `${what}: ${r.error}`);
    assert.deepEqual(h.find('inner').pathPoints[2].anchor, [75, 75], `${what}: sub-path updated in place`);
  }
  // A sub-path that is gone (released compound) is refused, not misapplied.
  const h = createHost({ shapes: [{ name: 'compound', subName: 'inner', kind: 'compound', polygon: [[0, 0], [50, 0], [50, 50]] }] });
  const it = call(h, 'dformer_selection').items[0];
  h.find('compound')._items.pop();
  const r = call(h, 'dformer_apply', { updates: [{ id: it.id, path: it.path }] });
  assert.match(r.error, /no longer in the document or changed since it was read/);
});

test('test_issue_11_text_encoding: accented document and layer names come back intact through an evalScript transport that mangles non-ASCII', () => {
  const h = createHost({ document: 'D\u00e9coupe.ai', transport: 'legacy', shapes: [{ name: 'Pi\u00e8ce', rect: { top: 10, left: 0, width: 10, height: 10 } }] });
  const text = h.evalScript('dformer_selection()');
  assert.match(text, /^[\x20-\x7e]*$/, 'the answer is plain ASCII');
  const sel = JSON.parse(text);
  assert.equal(sel.document, 'D\u00e9coupe.ai');
  assert.equal(sel.items[0].name, 'Pi\u00e8ce');
  // The request as plain ASCII (what the panel sends): non-ASCII as \u escapes.
  const payload = { document: sel.document, pieces: [{ id: sel.items[0].id, name: 'pi\u00e8ce A', holes: [circlePath(5, 5, 1)], labels: [{ text: '\u00e9', at: [5, 8] }] }],
    layers: { cut: { name: 'D\u00e9coupe' }, engrave: { name: 'Gravure \u2013 fine' } } };
  const literal = JSON.stringify(payload).replace(/[^\x20-\x7e]/g, (c) => `\\u${c.charCodeAt(0).toString(16).padStart(4, '0')}`);
  const r = JSON.parse(h.evalScript(`dformer_apply(${literal})`));
  assert.equal(r.ok, true, r.error);
  assert.deepEqual(r.layers, ['D\u00e9coupe', 'Gravure \u2013 fine']);
  assert.deepEqual(h.doc._layers.map((l) => l.name).sort(), ['D\u00e9coupe', 'Gravure \u2013 fine', 'Layer 1'].sort());
  assert.ok(h.doc._layers.find((l) => l.name === 'D\u00e9coupe').groupItems.getByName('D-former pi\u00e8ce A connectors'));
});
