// Issue 15 req. 5 in the browser app: the panel starts from the core's defaults() (count, flank
// angle, sizes as fractions of the pitch) with no number of its own, and labels `invert` with the
// meaning the core gives it for each kind ("holes outside" means nothing to leaves).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePanelBrowser, waitReady, measureRows } from './support.mjs';

const panel = usePanelBrowser();

test('every kind starts from defaults(): count, angle, automatic sizes and the invert label', async () => {
  const page = await panel.browser.newPage();
  await page.goto(panel.url);
  await waitReady(page, 'load');
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  await waitReady(page, 'load');
  await page.selectOption('#sample-select', 'ellipse-circle');
  await waitReady(page);
  const core = await page.evaluate(() => window.DF.core.defaults());
  const option = (name, kind, leaf) => core.options.find((o) => o.name === name && o.kinds.includes(kind) && (!o.leaf || o.leaf === leaf));
  const rows = await measureRows(page);
  // Normalize to the largest (the panel's default target): the common perimeter, in mm.
  const perimeter = Math.max(...rows.map((r) => parseFloat(r.perimeter)));
  for (const kind of ['stitch', 'teeth', 'leaves', 'hybrid']) {
    await page.click(`#kind button[data-kind="${kind}"]`);
    await waitReady(page);
    const count = option('count', kind).value;
    assert.equal(Number(await page.inputValue('#count')), count, `${kind}: count`);
    if (kind === 'teeth' || kind === 'hybrid') assert.equal(Number(await page.inputValue('#angle')), option('angle', kind).value, `${kind}: angle`);
    const label = (await page.textContent('#invert-text')).trim();
    assert.equal(label, core.invert[kind], `${kind}: invert label`);
    if (kind === 'leaves') assert.doesNotMatch(label, /inside|outside/i, 'leaves: invert swaps pieces, it does not turn them inside out');
    // Empty sizes show what the core will draw: its fraction of the pitch (perimeter / count).
    const pitch = perimeter / count;
    const size = kind === 'leaves' ? 'length' : kind === 'teeth' ? 'length' : 'diameter';
    const d = option(size, kind, 'tab');
    assert.equal(await page.inputValue(`#${size}`), '', `${kind}: ${size} left to the core`);
    const shown = (await page.getAttribute(`#${size}`, 'placeholder')).match(/^auto ([\d.]+)/);
    assert.ok(shown, `${kind}: ${size} placeholder ${await page.getAttribute(`#${size}`, 'placeholder')}`);
    const want = d.pitch * pitch + (d.length || 0) * 0.5 * pitch;
    assert.ok(Math.abs(Number(shown[1]) - want) <= 0.006 + 1e-4 * want, `${kind}: ${size} shown ${shown[1]} mm, wanted ${want.toFixed(3)} mm`);
  }
  await page.close();
});
