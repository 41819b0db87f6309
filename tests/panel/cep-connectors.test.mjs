// Issue 15 in the real panel with the real bridge in the simulated Illustrator DOM: locking leaves
// write their slots on the cut layer, a seam allowance writes the cut line and scores the seam line,
// labels can be switched off, one path normalizes to an exact length, and each new bad input (a
// dovetail angle too wide, a flank angle too steep for the pitch, an odd leaf count, an allowance
// that makes the cut line cross itself) shows its message, disables Apply and leaves the document
// untouched.
// Requires `node uxp-panel/build.mjs`.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePanelBrowser, waitReady } from './support.mjs';
import { openPanel } from './cep-stand-in.mjs';
import { applyOk, items, lengthOf, TWO_SHAPES } from './cep-document.mjs';

const panel = usePanelBrowser();

const corner = (x, y) => ({ anchor: [x, y], left: [x, y], right: [x, y] });
/** A U with a slot 20 pt (7.06 mm) wide, and a square: a 5 mm allowance closes the slot. */
const U_AND_SQUARE = {
  units: 'mm',
  shapes: [
    { name: 'U', path: { closed: true, points: [[0, 0], [200, 0], [200, 200], [110, 200], [110, 50], [90, 50], [90, 200], [0, 200]].map(([x, y]) => corner(x, y)) } },
    { name: 'Square', path: { closed: true, points: [[300, 0], [500, 0], [500, 200], [300, 200]].map(([x, y]) => corner(x, y)) } },
  ],
};
// The panel recomputes on the next animation frame after an input; until then its state is the
// previous design's: wait two frames before reading it (as browser-laser-connectors does).
const frames = (page) => page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
const ready = async (page) => {
  await frames(page);
  await page.waitForFunction(() => document.body.dataset.state === 'ready');
};
const failed = async (page) => {
  await frames(page);
  await page.waitForFunction(() => document.body.dataset.state === 'error');
};

test('locking leaves: slots on the cut layer of both pieces, in the preview and in the document', async () => {
  const { page, host } = await openPanel(panel.browser, panel.url, TWO_SHAPES);
  await waitReady(page);
  await page.click('#kind button[data-kind="leaves"]');
  await page.selectOption('#leaf', 'lock');
  await page.fill('#count', '12');
  await ready(page);
  assert.equal(await page.$$eval('#preview .slot', (s) => s.length), 12, 'preview: 6 slots on each piece');
  await applyOk(page);
  const all = items(host.snapshot()[0]);
  const slots = all.filter((i) => /^slot \d+$/.test(i.name));
  assert.equal(slots.length, 12, 'document: 6 slots per piece');
  assert.ok(slots.every((s) => s.layer === 'Cut'), `slots on the cut layer: ${[...new Set(slots.map((s) => s.layer))]}`);
});

test('seam allowance: each cut line is 2π·a longer than its seam line, the seam line is scored, labels off writes none', async () => {
  const { page, host } = await openPanel(panel.browser, panel.url, TWO_SHAPES);
  await waitReady(page);
  await page.click('#kind button[data-kind="stitch"]');
  await page.fill('#count', '20');
  await page.fill('#allowance', '3');
  await page.click('#sec-layers summary');
  await page.uncheck('#labels-on');
  await ready(page);
  assert.equal(await page.$$eval('#preview .seam', (s) => s.length), 2, 'preview: a seam line per piece');
  assert.equal(await page.$$eval('#preview .label', (s) => s.length), 0, 'labels off: none in the preview');
  await applyOk(page);
  const all = items(host.snapshot()[0]);
  const seams = all.filter((i) => i.name === 'seam line');
  assert.equal(seams.length, 2);
  assert.ok(seams.every((s) => s.layer === 'Score'), 'seam lines on the score layer');
  assert.equal(all.filter((i) => /^label \d+$/.test(i.name)).length, 0, 'labels off: none written');
  // Both pieces are convex, so each cut line (drawn on the cut layer) is its seam line's length
  // plus 2π·a (Steiner's formula for the parallel curve of a convex curve).
  const cuts = all.filter((i) => i.name === 'outline' && i.layer === 'Cut');
  assert.equal(cuts.length, 2, 'a cut line per piece');
  const a = 3 * (72 / 25.4);
  for (const [k, cut] of cuts.entries()) {
    const want = lengthOf(seams[k]) + 2 * Math.PI * a;
    assert.ok(Math.abs(lengthOf(cut) - want) < 1e-4 * want, `cut line ${k + 1}: wanted ${want} pt, got ${lengthOf(cut)}`);
  }
});

test('one path, exact length: Normalize alone scales it in place about its first anchor', async () => {
  const { page, host } = await openPanel(panel.browser, panel.url, { units: 'mm', shapes: [TWO_SHAPES.shapes[1]] });
  await waitReady(page);
  await page.selectOption('#norm-target', 'exact');
  await page.fill('#norm-exact', '300');
  await page.selectOption('#norm-pivot', 'start');
  await ready(page);
  const first = items(host.snapshot()[0]).find((i) => i.name === 'Circle').points[0].a;
  await applyOk(page);
  const c = items(host.snapshot()[0]).find((i) => i.name === 'Circle');
  assert.ok(Math.abs(lengthOf(c) - 300 * 72 / 25.4) < 1e-6 * 300 * 72 / 25.4, `perimeter ${lengthOf(c)} pt`);
  assert.ok(Math.hypot(c.points[0].a[0] - first[0], c.points[0].a[1] - first[1]) < 1e-9, 'the first anchor stays');
});

test('each new bad input: its message, Apply disabled, the document untouched', async () => {
  const cases = [
    ['dovetail angle too wide', async (page) => { await page.click('#kind button[data-kind="teeth"]'); await page.fill('#count', '40'); await page.fill('#length', '20'); await page.fill('#angle', '160'); }, /dovetails' corners collide\. At this pitch the flank angle must be between [\d.]+° and [\d.]+°/],
    ['flank angle too steep for the pitch', async (page) => { await page.click('#kind button[data-kind="teeth"]'); await page.fill('#count', '40'); await page.fill('#length', '20'); await page.fill('#angle', '10'); }, /Teeth 20\.00 mm long with 10° flanks do not fit a pitch of [\d.]+ mm: the flanks meet\. At this pitch the flank angle must be between [\d.]+° and [\d.]+°/],
    ['odd leaf count', async (page) => { await page.click('#kind button[data-kind="leaves"]'); await page.fill('#count', '13'); }, /must be even, got 13: use 12 or 14/],
    ['allowance wider than a gap', async (page) => { await page.click('#kind button[data-kind="stitch"]'); await page.fill('#count', '20'); await page.fill('#allowance', '5'); }, /A seam allowance of 5\.00 mm makes the cut line of piece [AB] cross itself/, U_AND_SQUARE],
  ];
  for (const [what, act, message, doc] of cases) {
    const { page, host } = await openPanel(panel.browser, panel.url, doc || TWO_SHAPES);
    await waitReady(page);
    const before = JSON.stringify(host.snapshot());
    await act(page);
    await failed(page);
    const text = await page.textContent('#message');
    assert.match(text, message, `${what}: ${text}`);
    assert.doesNotMatch(text, /\d\.\d{5,}/, `${what}: raw number in ${text}`);
    assert.equal(await page.isDisabled('#apply-btn'), true, `${what}: Apply must be disabled`);
    assert.equal(JSON.stringify(host.snapshot()), before, `${what}: the document must be untouched`);
    await page.close();
  }
});
