// The real panel (uxp-panel/index.html) in headless Chromium with a CEP stand-in whose evalScript
// runs the real ExtendScript bridge in the simulated Illustrator DOM. Requires `node uxp-panel/build.mjs`.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { artifactPath, usePanelBrowser, waitReady } from './support.mjs';
import { openPanel, SKINS } from './cep-stand-in.mjs';
import { applyOk, items, lengthOf, TWO_SHAPES } from './cep-document.mjs';
import { centroidOfAnchors, distance, inside, sample } from './geometry.mjs';

const MM = 72 / 25.4;
const panel = usePanelBrowser();


test('select two shapes, normalize, add stitching, apply: equal perimeters and paired holes in the document', async () => {
  const { page, host, errors } = await openPanel(panel.browser, panel.url, TWO_SHAPES);
  await waitReady(page);
  assert.equal(await page.evaluate(() => document.body.dataset.state), 'ready', `panel not ready: ${await page.textContent('#message')}`);
  const before = items(host.snapshot()[0]);
  const [a0, b0] = ['Ellipse', 'Circle'].map((n) => before.find((i) => i.name === n));
  assert.ok(Math.abs(lengthOf(a0) - lengthOf(b0)) > 1, 'the fixture must start with different perimeters');
  assert.match(await page.textContent('#selection-summary'), /2 paths selected/);
  assert.match(await page.textContent('#units-badge'), /mm/);

  await page.selectOption('#norm-target', 'largest');
  await page.click('#kind button[data-kind="stitch"]');
  await page.fill('#count', '20');
  // Sizes are automatic (the core's fractions of the pitch) unless typed: type the ones checked below.
  await page.fill('#inset', '4');
  await page.fill('#diameter', '2');
  await page.waitForFunction(() => /^20 connectors/.test(document.querySelector('#stats').textContent));
  const previewHoles = await page.$$eval('#preview .hole', (h) => h.length);
  assert.equal(previewHoles, 40, `preview holes: wanted 40 (20 per piece), got ${previewHoles}`);
  assert.deepEqual(items(host.snapshot()[0]), before, 'nothing is written before Apply');

  await applyOk(page);
  assert.match(await page.textContent('#status'), /Updated 2 path\(s\), created \d+ item\(s\)/);

  const after = items(host.snapshot()[0]);
  const [a1, b1] = ['Ellipse', 'Circle'].map((n) => after.find((i) => i.name === n && i.typename === 'PathItem'));
  const [la, lb] = [lengthOf(a1), lengthOf(b1)];
  const largest = Math.max(lengthOf(a0), lengthOf(b0));
  assert.ok(Math.abs(la - lb) <= 1e-9 * la, `perimeters after Apply: A ${la}, B ${lb} (wanted equal to 1e-9)`);
  assert.ok(Math.abs(la - largest) <= 1e-9 * la, `target "largest": wanted ${largest}, got ${la}`);

  // The panel names the pieces A and B in selection (stacking) order; read which item is which.
  const names = await page.$$eval('#measure-table tr', (rows) => rows.slice(0, 2).map((r) => r.children[1].textContent));
  const byKey = { A: after.find((i) => i.name === names[0]), B: after.find((i) => i.name === names[1]) };
  assert.deepEqual([...names].sort(), ['Circle', 'Ellipse'], `measure table names: ${names}`);
  for (const [key, piece] of Object.entries(byKey)) {
    const holes = after.filter((i) => i.group === `D-former piece ${key} connectors` && /^hole \d+$/.test(i.name));
    const labels = after.filter((i) => i.group === `D-former piece ${key} labels` && i.typename === 'TextFrame');
    const marks = after.filter((i) => i.group === `D-former piece ${key} marks`);
    assert.equal(holes.length, 20, `piece ${key} holes: wanted 20, got ${holes.length}`);
    assert.deepEqual(labels.map((l) => Number(l.contents)).sort((x, y) => x - y), Array.from({ length: 20 }, (_, i) => i + 1), `piece ${key} labels 1..20`);
    assert.ok(marks.length >= 1, `piece ${key}: a start mark`);
    assert.ok(holes.every((h) => h.layer === 'Cut' && h.strokeColor.rgb.join() === '255,0,0'), `piece ${key}: holes on the red Cut layer`);
    const outline = sample(piece.points);
    for (const h of holes) {
      const c = centroidOfAnchors(h.points);
      const d = distance(outline, c);
      assert.ok(inside(outline, c), `piece ${key} ${h.name}: centre ${c} must lie inside the piece`);
      assert.ok(Math.abs(d - 4 * MM) < 0.01 * 4 * MM, `piece ${key} ${h.name}: distance to edge wanted ${4 * MM} (inset 4 mm), got ${d}`);
      const dia = Math.max(...h.points.map((p) => Math.hypot(p.a[0] - c[0], p.a[1] - c[1]))) * 2;
      assert.ok(Math.abs(dia - 2 * MM) < 0.01 * 2 * MM, `piece ${key} ${h.name}: diameter wanted ${2 * MM}, got ${dia}`);
    }
  }
  assert.deepEqual(errors, [], 'no page errors');
  await page.close();
});

test('an open path in the selection: message shown, Apply disabled, document untouched', async () => {
  const { page, host } = await openPanel(panel.browser, panel.url, {
    units: 'mm',
    shapes: [
      { name: 'A', ellipse: { top: 300, left: 0, width: 120, height: 80 } },
      { name: 'open', polygon: [[200, 300], [300, 300], [300, 200]], closed: false },
    ],
  });
  await waitReady(page);
  const snap = JSON.stringify(host.snapshot());
  const message = await page.textContent('#message');
  assert.match(message, /open/i, `wanted an "open path" message, got "${message}"`);
  // Illustrator's own menu, from the one table (the core says it in plain words).
  assert.match(message, /close the path \(Object > Path > Join\)/, message);
  assert.equal(await page.isDisabled('#apply-btn'), true, 'Apply must be disabled');
  await page.click('#apply-btn', { force: true });
  await page.waitForTimeout(200);
  assert.equal(JSON.stringify(host.snapshot()), snap, 'the document must be unchanged');
  await page.close();
});

test('Illustrator refuses the write (layer locked after reading): message shown, document untouched', async () => {
  const { page, host } = await openPanel(panel.browser, panel.url, TWO_SHAPES);
  await waitReady(page);
  assert.equal(await page.evaluate(() => document.body.dataset.state), 'ready');
  host.doc.layers.getByName('Layer 1').locked = true;
  const snap = JSON.stringify(host.snapshot());
  await page.click('#apply-btn');
  await page.waitForFunction(() => document.body.dataset.applied);
  assert.equal(await page.evaluate(() => document.body.dataset.applied), 'error');
  const message = await page.textContent('#status');
  assert.match(message, /lock/i, `wanted the bridge's "locked" message, got "${message}"`);
  assert.equal(JSON.stringify(host.snapshot()), snap, 'the document must be unchanged');
  await page.close();
});

test('CMYK (Print) document: the panel says to switch to RGB, Apply is refused with the menu path, document untouched', async () => {
  const { page, host } = await openPanel(panel.browser, panel.url, { ...TWO_SHAPES, colorSpace: 'CMYK' });
  await waitReady(page);
  assert.equal(await page.evaluate(() => document.body.dataset.state), 'ready');
  assert.match(await page.textContent('#selection-summary'), /CMYK document: switch to File > Document Color Mode > RGB Color before Apply/);
  const snap = JSON.stringify(host.snapshot());
  await page.click('#apply-btn');
  await page.waitForFunction(() => document.body.dataset.applied);
  assert.equal(await page.evaluate(() => document.body.dataset.applied), 'error');
  const message = await page.textContent('#status');
  assert.match(message, /CMYK colour.*File > Document Color Mode > RGB Color, then Apply again\. Nothing was changed\./, `status: "${message}"`);
  assert.equal(JSON.stringify(host.snapshot()), snap, 'the document must be unchanged');

  // The student switches the mode: the poll notices (the fingerprint includes it), the note goes, Apply writes exact RGB.
  host.doc._colorSpace = host.context.DocumentColorSpace.RGB;
  await page.waitForFunction(() => !/CMYK/.test(document.querySelector('#selection-summary').textContent));
  await page.evaluate(() => { delete document.body.dataset.applied; });
  await applyOk(page);
  const holes = items(host.snapshot()[0]).filter((i) => /^hole \d+$/.test(i.name));
  assert.ok(holes.length > 0 && holes.every((h) => h.strokeColor.rgb.join() === '255,0,0'), 'holes in exact RGB red');
  await page.close();
});

test('theme follows Illustrator brightness (dark → light on ThemeColorChanged); screenshots', async () => {
  const { page } = await openPanel(panel.browser, panel.url, TWO_SHAPES, { skin: SKINS.dark });
  await waitReady(page);
  assert.equal(await page.evaluate(() => document.body.className), 'theme-dark');
  assert.equal(await page.evaluate(() => getComputedStyle(document.body).backgroundColor), 'rgb(50, 50, 50)');
  await page.screenshot({ path: artifactPath('panel-dark.png') });
  await page.evaluate((rgb) => window.__setSkin(rgb), SKINS.light);
  await page.waitForFunction(() => document.body.classList.contains('theme-light'));
  assert.equal(await page.evaluate(() => getComputedStyle(document.body).backgroundColor), 'rgb(240, 240, 240)');
  await page.screenshot({ path: artifactPath('panel-light.png') });
  await page.close();
});

test('"start at the selected anchor": connector 1 sits at the anchor picked with Direct Selection (float32 document)', async () => {
  const { page, host } = await openPanel(panel.browser, panel.url, {
    units: 'pt',
    float32: true,
    shapes: [
      { name: 'Square', rect: { top: 300, left: 0, width: 120, height: 120 }, selectedAnchors: [1] },
      { name: 'Disc', ellipse: { top: 300, left: 200, width: 150, height: 150 } },
    ],
  });
  await waitReady(page);
  const names = await page.$$eval('#measure-table tr', (rows) => rows.slice(0, 2).map((r) => r.children[1].textContent));
  const squareIndex = names.indexOf('Square');
  assert.ok(squareIndex >= 0, `Square in the measure table: ${names}`);
  const row = `.start[data-piece="${squareIndex}"] .start-mode`;
  await page.selectOption(row, 'selected');
  await page.fill('#count', '12');
  await page.waitForFunction(() => /^12 connectors/.test(document.querySelector('#stats').textContent));
  await applyOk(page);
  const all = items(host.snapshot()[0]);
  const square = all.find((i) => i.name === 'Square' && i.typename === 'PathItem');
  const disc = all.find((i) => i.name === 'Disc' && i.typename === 'PathItem');
  const key = squareIndex === 0 ? 'A' : 'B';
  const hole1 = all.find((i) => i.group === `D-former piece ${key} connectors` && i.name === 'hole 1');
  const c = centroidOfAnchors(hole1.points);
  const nearest = square.points
    .map((p, i) => ({ i, d: Math.hypot(p.a[0] - c[0], p.a[1] - c[1]) }))
    .sort((x, y) => x.d - y.d)[0];
  assert.equal(nearest.i, 1, `hole 1 should sit at the selected anchor 1 (index 1); nearest anchor is ${nearest.i} (${nearest.d} pt away)`);
  const [ls, ld] = [lengthOf(square), lengthOf(disc)];
  assert.ok(Math.abs(ls - ld) <= 1e-6 * ls, `perimeters in a float32 document: ${ls} vs ${ld} (wanted equal to 1e-6)`);
  await page.close();
});

test('layer colours and hairline widths are configurable, used by Apply and remembered by the next session', async () => {
  const context = await panel.browser.newContext();
  const first = await openPanel(panel.browser, panel.url, TWO_SHAPES, { context });
  const { page, host } = first;
  await waitReady(page);
  await page.click('#sec-layers summary');
  await page.$eval('.layer-row[data-layer="cut"] .layer-color', (el) => {
    el.value = '#00aa00';
    el.dispatchEvent(new Event('input'));
  });
  await page.fill('.layer-row[data-layer="cut"] .layer-width', '0.1'); // mm
  await applyOk(page);
  const holes = items(host.snapshot()[0]).filter((i) => /^hole \d+$/.test(i.name));
  assert.ok(holes.length > 0);
  for (const h of holes) {
    assert.deepEqual(h.strokeColor.rgb, [0, 170, 0], `${h.name} stroke colour`);
    assert.ok(Math.abs(h.strokeWidth - 0.1 * MM) < 1e-9, `${h.name} stroke width: wanted ${0.1 * MM} pt, got ${h.strokeWidth}`);
  }
  await page.close();
  const second = await openPanel(panel.browser, panel.url, TWO_SHAPES, { context });
  await waitReady(second.page);
  assert.equal(await second.page.$eval('.layer-row[data-layer="cut"] .layer-color', (el) => el.value), '#00aa00', 'colour remembered');
  assert.equal(await second.page.$eval('.layer-row[data-layer="cut"] .layer-width', (el) => el.value), '0.1', 'width remembered (mm)');
  await context.close();
});

test('teeth: each piece gets its toothed cut outline on the Cut layer; the normalized paths stay equal', async () => {
  const { page, host } = await openPanel(panel.browser, panel.url, TWO_SHAPES);
  await waitReady(page);
  await page.click('#kind button[data-kind="teeth"]');
  await page.fill('#count', '16');
  await page.waitForFunction(() => /^16 connectors/.test(document.querySelector('#stats').textContent));
  await applyOk(page);
  const all = items(host.snapshot()[0]);
  const outlines = ['A', 'B'].map((k) => all.find((i) => i.group === `D-former piece ${k} connectors` && i.name === 'outline'));
  assert.ok(outlines.every(Boolean), 'an outline per piece');
  assert.ok(outlines.every((o) => o.layer === 'Cut' && o.points.length > 16 * 3), `toothed outlines: ${outlines.map((o) => o.points.length)} anchors`);
  assert.equal(all.filter((i) => /^hole \d+$/.test(i.name)).length, 0, 'teeth make no holes');
  const [pa, pb] = ['Ellipse', 'Circle'].map((n) => lengthOf(all.find((i) => i.name === n && i.typename === 'PathItem')));
  assert.ok(Math.abs(pa - pb) <= 1e-9 * pa, `normalized perimeters: ${pa} vs ${pb}`);
  for (const o of outlines) assert.ok(lengthOf(o) > pa, `a toothed edge (${lengthOf(o)}) is longer than the plain one (${pa})`);
  await page.close();
});

// Issue 11, item 7: ExtendScript may decode text crossing evalScript in a legacy encoding; the stand-in's
// 'legacy' transport mangles every non-ASCII character both ways, as that would.
test('test_issue_11_accented_names_in_the_panel: "D\u00e9coupe.ai" with layers "D\u00e9coupe" and "Gravure" applies, names intact', async () => {
  const { page, host, errors } = await openPanel(panel.browser, panel.url, { ...TWO_SHAPES, document: 'D\u00e9coupe.ai', transport: 'legacy' });
  await waitReady(page);
  assert.match(await page.textContent('#selection-summary'), /2 paths selected · D\u00e9coupe\.ai/);
  await page.click('#sec-layers summary');
  await page.fill('.layer-row[data-layer="cut"] .layer-name', 'D\u00e9coupe');
  await page.press('.layer-row[data-layer="cut"] .layer-name', 'Tab');
  await page.fill('.layer-row[data-layer="engrave"] .layer-name', 'Gravure');
  await page.press('.layer-row[data-layer="engrave"] .layer-name', 'Tab');
  await applyOk(page);
  const layers = host.snapshot()[0].layers.map((l) => l.name).sort();
  assert.deepEqual(layers, ['D\u00e9coupe', 'Gravure', 'Layer 1', 'Score'], `layers: ${layers}`);
  assert.deepEqual(errors, [], 'no page errors');
  await page.close();
});

// Issue 11, item 3: a Large Canvas document's DOM reports lengths divided by Document.scaleFactor (10).
test('test_issue_11_large_canvas_in_the_panel: perimeters show at their printed size, and holes are written at DOM size', async () => {
  const { page, host } = await openPanel(panel.browser, panel.url, { ...TWO_SHAPES, scaleFactor: 10 });
  await waitReady(page);
  const rows = await page.$$eval('#measure-table tr:not(.diff)', (trs) => trs.map((tr) => [tr.children[1].textContent, tr.children[2].textContent]));
  for (const [name, shown] of rows) {
    const it = items(host.snapshot()[0]).find((i) => i.name === name && i.typename === 'PathItem');
    const want = (10 * lengthOf(it) * 25.4) / 72;
    assert.ok(Math.abs(parseFloat(shown) - want) <= 0.006, `${name}: wanted ${want.toFixed(2)} mm (10 x the DOM length), shown ${shown}`);
  }
  await page.click('#kind button[data-kind="stitch"]');
  await page.fill('#count', '8');
  // Sizes follow the pitch unless typed (the core's defaults): type the 2 mm hole checked below.
  await page.fill('#diameter', '2');
  await page.waitForFunction(() => /^8 connectors/.test(document.querySelector('#stats').textContent));
  await applyOk(page);
  const hole = items(host.snapshot()[0]).find((i) => i.name === 'hole 1');
  const c = centroidOfAnchors(hole.points);
  const dia = Math.max(...hole.points.map((p) => Math.hypot(p.a[0] - c[0], p.a[1] - c[1]))) * 2;
  assert.ok(Math.abs(10 * dia - 2 * MM) < 0.01 * 2 * MM, `hole diameter printed: wanted ${2 * MM} pt (2 mm), got ${10 * dia} pt (DOM ${dia})`);
  assert.ok(Math.abs(hole.strokeWidth - 0.0072) < 1e-9, `hairline in the DOM: wanted 0.0072 pt (0.072 pt printed), got ${hole.strokeWidth}`);
  await page.close();
});

// Issue 11, item 1: a Select All sends no geometry; the panel asks for two paths.
test('test_issue_11_select_all_in_the_panel: many selected paths give a clear "select two" state, Apply disabled', async () => {
  const shapes = Array.from({ length: 40 }, (_, i) => ({ name: `p${i}`, ellipse: { top: 20 * i, left: 0, width: 15, height: 10 } }));
  const { page } = await openPanel(panel.browser, panel.url, { units: 'mm', shapes });
  await waitReady(page);
  assert.match(await page.textContent('#selection-summary'), /More than two paths \(or more than 500 objects\) are selected: select exactly two closed paths/);
  assert.equal(await page.isDisabled('#apply-btn'), true);
  await page.close();
});
