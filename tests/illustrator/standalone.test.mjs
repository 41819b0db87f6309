// The File > Scripts scripts run in the simulated DOM; results checked with an independent length.
import test from 'node:test';
import assert from 'node:assert/strict';
import { createHost } from './jsx-host.mjs';
import { referenceLengthOf, relErr } from './reference-length.mjs';

const MEASURE = 'D-former – Measure perimeters.jsx';
const NORMALIZE = 'D-former – Normalize perimeters.jsx';
const MM = 25.4 / 72;

const shapes = () => [
  { name: 'A', path: { closed: true, points: [
    { anchor: [0, 0], left: [-30, 40], right: [50, -20] },
    { anchor: [100, 10], left: [80, -40], right: [140, 60] },
    { anchor: [40, 90], left: [90, 120], right: [0, 70] },
  ] } },
  { name: 'B', ellipse: { top: 300, left: 200, width: 120, height: 80 } },
  { name: 'C', rect: { top: -50, left: -100, width: 60, height: 20 }, group: 'G' },
];

/** Fill the normalize dialog like a user: target index, exact text, pivot index; OK or Cancel. */
const answer = (target, exact = '', pivot = 0, ok = true) => (w) => {
  w.findElement('target').selection = target;
  if (exact !== '') w.findElement('length').text = exact;
  w.findElement('pivot').selection = pivot;
  return ok ? 1 : 2;
};

test('Measure lists each perimeter in ruler units (independently measured) and the difference', () => {
  const h = createHost({ units: 'mm', shapes: shapes() });
  const [msg] = h.runScript(MEASURE);
  for (const name of ['A', 'B', 'C']) {
    const m = msg.match(new RegExp(`^${name}: ([0-9.]+) mm$`, 'm'));
    assert.ok(m, `line for ${name} in:\n${msg}`);
    const want = referenceLengthOf(h.find(name)) * MM;
    assert.ok(Math.abs(Number(m[1]) - want) <= 0.0005, `${name}: wanted ${want.toFixed(3)} mm, got ${m[1]} mm`);
  }
  assert.match(msg, /Difference: [0-9.]+ mm \([0-9.]+ %\)\. Run "D-former – Normalize perimeters"/);
  assert.equal(h.snapshot().length, 1);
});

test('Measure refuses politely without a document or selection and names skipped items', () => {
  assert.match(createHost({ noDocument: true }).runScript(MEASURE)[0], /No document is open/);
  const h = createHost({ shapes: [{ name: 'words', kind: 'text' }] });
  assert.match(h.runScript(MEASURE)[0], /Select one or more paths first\.\nNot paths: words\./);
});

for (const [target, label] of [[0, 'largest'], [1, 'smallest'], [2, 'mean'], [3, 'first'], [4, 'exact 250 mm']]) {
  test(`Normalize to the ${label} perimeter makes all perimeters equal (measured independently)`, () => {
    const h = createHost({ units: 'mm', shapes: shapes() });
    const items = ['A', 'B', 'C'].map((n) => h.find(n));
    const before = items.map(referenceLengthOf);
    const order = h.doc.selection.flatMap((x) => (x.typename === 'GroupItem' ? x._items : [x]));
    const want = [Math.max(...before), Math.min(...before), before.reduce((a, b) => a + b) / 3,
      referenceLengthOf(order[0]), 250 / MM][target];
    const centres = items.map((it) => { const [l, t, r, b] = it.geometricBounds; return [(l + r) / 2, (t + b) / 2]; });
    const [msg] = h.runScript(NORMALIZE, answer(target, target === 4 ? ' 250,0 ' : ''));
    assert.match(msg, /^Target perimeter: /);
    items.forEach((it, i) => {
      const got = referenceLengthOf(it);
      assert.ok(relErr(got, want) < 1e-9, `${it.name}: wanted ${want}, got ${got}`);
      const [l, t, r, b] = it.geometricBounds;
      assert.ok(Math.hypot((l + r) / 2 - centres[i][0], (t + b) / 2 - centres[i][1]) < 1e-9, `${it.name}: centre pivot kept`);
    });
  });
}

test('Normalize about the top-left pivot keeps each top-left corner', () => {
  const h = createHost({ units: 'in', shapes: shapes() });
  const corners = ['A', 'B'].map((n) => h.find(n).geometricBounds.slice(0, 2));
  h.runScript(NORMALIZE, answer(0, '', 1));
  ['A', 'B'].forEach((n, i) => {
    const [l, t] = h.find(n).geometricBounds;
    assert.ok(Math.hypot(l - corners[i][0], t - corners[i][1]) < 1e-9, `${n}: top-left ${corners[i]} kept, got ${[l, t]}`);
  });
});

const FIRST_ANCHOR = 9;
const anchors = (it) => Array.from({ length: it.pathPoints.length }, (_, i) => it.pathPoints[i].anchor);

test('Normalize scales one path to the exact length about its first anchor, shape kept', () => {
  const h = createHost({ units: 'mm', shapes: [shapes()[0]] });
  const a = h.find('A');
  const before = anchors(a);
  const k = (250 / MM) / referenceLengthOf(a);
  const [msg] = h.runScript(NORMALIZE, answer(4, '250', FIRST_ANCHOR));
  assert.match(msg, /^Target perimeter: 250\.000 mm\nA: /);
  assert.ok(relErr(referenceLengthOf(a), 250 / MM) < 1e-9, `perimeter ${referenceLengthOf(a) * MM} mm, wanted 250`);
  const after = anchors(a);
  // A uniform scale by k about anchor 1: anchor 1 stays, every other anchor moves to s + k (p - s).
  before.forEach((p, i) => {
    const want = [before[0][0] + k * (p[0] - before[0][0]), before[0][1] + k * (p[1] - before[0][1])];
    assert.ok(Math.hypot(after[i][0] - want[0], after[i][1] - want[1]) < 1e-9 * k * 100, `anchor ${i + 1}: ${after[i]}, wanted ${want}`);
  });
});

test('Normalize about the first anchor keeps every path\'s first anchor in place', () => {
  const h = createHost({ units: 'in', shapes: shapes() });
  const items = ['A', 'B', 'C'].map((n) => h.find(n));
  const firsts = items.map((it) => anchors(it)[0]);
  const want = Math.max(...items.map(referenceLengthOf));
  h.runScript(NORMALIZE, answer(0, '', FIRST_ANCHOR));
  items.forEach((it, i) => {
    assert.ok(relErr(referenceLengthOf(it), want) < 1e-9, `${it.name}: perimeter ${referenceLengthOf(it)}, wanted ${want}`);
    const f = anchors(it)[0];
    assert.ok(Math.hypot(f[0] - firsts[i][0], f[1] - firsts[i][1]) < 1e-9, `${it.name}: first anchor ${firsts[i]} kept, got ${f}`);
  });
});

test('an out-of-range scale is refused with the factor rounded to 4 significant digits', () => {
  const h = createHost({ units: 'mm', shapes: shapes() });
  const before = h.snapshot();
  const lengths = Object.fromEntries(['A', 'B', 'C'].map((n) => [n, referenceLengthOf(h.find(n))]));
  const [msg] = h.runScript(NORMALIZE, answer(4, '1000000000'));
  const m = msg.match(/^Scaling "([ABC])" by ([0-9.e+]+) is out of range; choose another target\. Nothing was changed\.$/);
  assert.ok(m, msg);
  m.shift();
  const want = (1e9 / MM) / lengths[m[0]];
  assert.ok(m[1].replace(/e.*$/, '').replace('.', '').length <= 4, `not rounded: ${m[1]}`);
  assert.ok(relErr(Number(m[1]), want) < 5e-4, `factor ${m[1]}, wanted ${want}`);
  assert.deepEqual(h.snapshot(), before, 'document unchanged');
});

test('Normalize refuses bad selections and bad input, and Cancel changes nothing', () => {
  const check = (opts, respond, pattern) => {
    const h = createHost(opts);
    const before = h.snapshot();
    const alerts = h.runScript(NORMALIZE, respond);
    if (pattern) assert.match(alerts.join('\n'), pattern);
    else assert.deepEqual(alerts, [], 'no message on cancel');
    assert.deepEqual(h.snapshot(), before, `document unchanged (${pattern})`);
  };
  check({ noDocument: true }, undefined, /No document is open/);
  check({ shapes: [] }, undefined, /Select two or more closed paths to give them one perimeter, or one to scale it to an exact length \(found none\)/);
  check({ shapes: [shapes()[0]] }, answer(0), /Only one closed path is selected: choose Exact length to scale it to a perimeter, or select two or more paths to give them one perimeter\. Nothing was changed\./);
  check({ shapes: [shapes()[0], { name: 'line', polygon: [[0, 0], [5, 5]], closed: false }] }, undefined,
    /"line" is an open path\. A D-form needs closed outlines/);
  check({ shapes: shapes() }, answer(4, 'abc'), /Enter an exact length greater than 0 in mm \(got "abc"\)\. Nothing was changed\./);
  check({ shapes: shapes() }, answer(4, '-5'), /Enter an exact length greater than 0/);
  check({ shapes: shapes() }, answer(0, '', 0, false), null);
});

// The two scripts are self-contained on purpose (each must work when copied alone into the
// Scripts folder), so they carry the same helpers twice; this keeps the copies from drifting.
test('both File > Scripts scripts carry identical unit and selection helpers', async () => {
  const { readFileSync } = await import('node:fs');
  const { fileURLToPath } = await import('node:url');
  const read = (f) => readFileSync(fileURLToPath(new URL(`../../illustrator-scripts/${f}`, import.meta.url)), 'utf8');
  const helper = (src, name) => {
    const start = src.indexOf(`  function ${name}(`);
    assert.ok(start > 0, `function ${name} not found`);
    const end = src.indexOf('\n  }\n', start);
    return src.slice(start, end);
  };
  for (const name of ['unitsOf', 'selectedPaths', 'inDocumentCoordinates']) {
    assert.equal(helper(read(NORMALIZE), name), helper(read(MEASURE), name), `${name} differs between the two scripts`);
  }
});

test('Measure and Normalize leave hidden or locked art inside a selected group alone', () => {
  const extra = () => [
    { name: 'ghost', rect: { top: -100, left: -100, width: 400, height: 400 }, group: 'G', hidden: true },
    { name: 'pinned', rect: { top: -100, left: 300, width: 5, height: 5 }, group: 'G', locked: true },
  ];
  const m = createHost({ units: 'mm', shapes: [...shapes(), ...extra()] });
  const [msg] = m.runScript(MEASURE);
  assert.doesNotMatch(msg, /^ghost:/m, 'a hidden path is not measured');
  assert.match(msg, /Skipped \(not paths\): .*ghost \(hidden\)/);
  const h = createHost({ units: 'mm', shapes: [...shapes(), ...extra()] });
  const ghost = h.find('ghost'), pinned = h.find('pinned');
  const before = [referenceLengthOf(ghost), referenceLengthOf(pinned)];
  const lengths = ['A', 'B', 'C'].map((n) => referenceLengthOf(h.find(n)));
  const [out] = h.runScript(NORMALIZE, answer(0));
  assert.match(out, /^Target perimeter: /, out);
  assert.deepEqual([referenceLengthOf(ghost), referenceLengthOf(pinned)], before, 'hidden and locked paths unchanged');
  const want = Math.max(...lengths);
  for (const n of ['A', 'B', 'C']) assert.ok(relErr(referenceLengthOf(h.find(n)), want) < 1e-9, `${n} scaled to the largest visible perimeter`);
});

test('Measure and Normalize work in document coordinates and restore the student\'s app.coordinateSystem on every exit', () => {
  const artboardHost = () => createHost({ units: 'mm', shapes: shapes(), coordinateSystem: 'artboard', artboards: [[500, -200, 900, -600]] });
  const ARTBOARD = (h) => h.context.CoordinateSystem.ARTBOARDCOORDINATESYSTEM;
  const DOC = 'CoordinateSystem.DOCUMENTCOORDINATESYSTEM';
  const m = artboardHost();
  assert.match(m.runScript(MEASURE)[0], /^A: 134\.991 mm$/m);
  assert.equal(m.app.coordinateSystem, ARTBOARD(m), 'Measure restores the setting');

  const h = artboardHost();
  const lengths = ['A', 'B', 'C'].map((n) => referenceLengthOf(h.find(n)));
  h.sim.coordinateUses = {};
  assert.match(h.runScript(NORMALIZE, answer(0))[0], /^Target perimeter: /);
  assert.equal(h.app.coordinateSystem, ARTBOARD(h), 'Normalize restores the setting');
  assert.deepEqual(Object.keys(h.sim.coordinateUses), [DOC], 'Normalize scales in document coordinates');
  for (const n of ['A', 'B', 'C']) assert.ok(relErr(referenceLengthOf(h.find(n)), Math.max(...lengths)) < 1e-9, n);

  const c = artboardHost();
  assert.deepEqual(c.runScript(NORMALIZE, answer(0, '', 0, false)), [], 'Cancel');
  assert.equal(c.app.coordinateSystem, ARTBOARD(c), 'restored after Cancel');
  const t = artboardHost();
  t.sim.faults.resize = 2;
  assert.throws(() => t.runScript(NORMALIZE, answer(0)), /simulated failure in resize/);
  assert.equal(t.app.coordinateSystem, ARTBOARD(t), 'restored when Illustrator throws');
  const none = createHost({ noDocument: true, coordinateSystem: 'artboard' });
  assert.match(none.runScript(MEASURE)[0], /No document is open/);
  assert.equal(none.app.coordinateSystem, ARTBOARD(none));
});

// Issue 11, item 3: a Large Canvas document (Document.scaleFactor 10) reports lengths divided by 10.
test('test_issue_11_large_canvas_standalone: Measure shows real lengths and Normalize reaches an exact length typed in real mm', () => {
  const big = () => createHost({ units: 'mm', scaleFactor: 10, shapes: shapes() });
  const m = big();
  const [msg] = m.runScript(MEASURE);
  const want = 10 * referenceLengthOf(m.find('B')) * MM;
  const got = Number(msg.match(/^B: ([0-9.]+) mm$/m)[1]);
  assert.ok(Math.abs(got - want) <= 0.0005, `B printed: wanted ${want.toFixed(3)} mm (10 x the DOM length), got ${got} mm`);
  const h = big();
  const [out] = h.runScript(NORMALIZE, answer(4, '2500'));
  assert.match(out, /^Target perimeter: 2500\.000 mm$/m, out);
  for (const n of ['A', 'B', 'C']) {
    const real = 10 * referenceLengthOf(h.find(n)) * MM;
    assert.ok(relErr(real, 2500) < 1e-9, `${n}: wanted 2500 mm printed, got ${real} mm (DOM ${referenceLengthOf(h.find(n)) * MM} mm)`);
  }
});

// Issue 11, item 6: a Live Shape rounded rectangle keeps its corner radius under resize() unless
// policyForPreservingCorners is 1 ("Scale Corners"), so one resize by target / length misses.
test('test_issue_11_live_shape_corners: Normalize reaches the target on a Live Shape rounded rectangle and restores Scale Corners', () => {
  for (const preferencesLocked of [false, true]) {
    const h = createHost({ units: 'mm', preferencesLocked, shapes: [
      { name: 'R', roundedRect: { top: 0, left: 0, width: 200, height: 120, radius: 30 } },
      { name: 'E', ellipse: { top: 300, left: 300, width: 260, height: 200 } },
    ] });
    const want = referenceLengthOf(h.find('E'));
    const [out] = h.runScript(NORMALIZE, answer(0));
    const got = referenceLengthOf(h.find('R'));
    const what = preferencesLocked ? 'preference cannot be set (corrected by re-measuring)' : 'Scale Corners set for the resize';
    assert.ok(relErr(got, want) < 1e-9, `${what}: rounded rectangle wanted ${want}, got ${got}`);
    assert.doesNotMatch(out, /Not at the target/, out);
    assert.equal(h.sim.preferences.integer.policyForPreservingCorners, 2, `${what}: the student's Scale Corners setting (off) is restored`);
  }
});

test('test_issue_11_normalize_names_a_path_it_cannot_fit: a path whose resize does not take is named with the fix, the others reach the target', () => {
  const h = createHost({ units: 'mm', shapes: shapes() });
  const stuck = h.find('B');
  stuck.resize = () => {}; // Illustrator accepts the call and changes nothing (an envelope, a live effect...)
  const want = Math.max(...['A', 'B', 'C'].map((n) => referenceLengthOf(h.find(n))));
  const [out] = h.runScript(NORMALIZE, answer(0));
  assert.match(out, /Not at the target: B \([0-9.]+ mm\)\. A Live Shape keeps its corner radius when scaled; expand it \(Object > Shape > Expand Shape\)/, out);
  for (const n of ['A', 'C']) assert.ok(relErr(referenceLengthOf(h.find(n)), want) < 1e-9, `${n} reaches the target`);
});
