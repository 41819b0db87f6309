// Issue 15 req. 5: switching from spacing by count to spacing by distance fills the pitch with the
// one the core's default count gives, perimeter / defaults().count, rounded to 0.01 of the display
// unit. Before, the panel kept its own number (10 mm) whatever the pieces.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openApp, openSvgFiles, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();
const MM = 72 / 25.4;
const R = 40; // mm: both pieces are this circle, so the connected perimeter is 2πR

const circles = '<svg xmlns="http://www.w3.org/2000/svg" width="300mm" height="200mm" viewBox="0 0 300 200">' +
  `<circle id="a" cx="60" cy="60" r="${R}"/><circle id="b" cx="200" cy="60" r="${R}"/></svg>`;

async function switchToDistance(page, unit = 'mm') {
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  await waitReady(page, 'load');
  await openSvgFiles(page, [['circles.svg', circles]]);
  await waitReady(page);
  await page.selectOption('#unit-select', unit);
  await waitReady(page);
  await page.selectOption('#spacing', 'pitch');
  await waitReady(page);
  await page.waitForFunction(() => document.querySelector('#pitch').value !== '');
}

for (const [unit, perUnit] of [['mm', 1], ['in', 25.4]]) {
  test(`spacing by distance starts at 2πr / the default count, rounded to 0.01 ${unit}`, async () => {
    const page = await openApp(panel);
    await switchToDistance(page, unit);
    const count = await page.evaluate(() => window.DF.core.defaults().options.find((o) => o.name === 'count').value);
    const want = Math.round(((2 * Math.PI * R) / count / perUnit) * 100) / 100; // in the display unit
    assert.equal(Number(await page.inputValue('#pitch')), want, `pitch field (${unit})`);
    // The design is spaced by that pitch: the default count of connectors.
    const design = await page.evaluate(() => window.DF.app.design());
    assert.equal(design.count, count);
    assert.ok(Math.abs(design.pitch / MM / perUnit - want) < 0.005 + 1e-9, `design pitch ${design.pitch / MM / perUnit} ${unit}, wanted about ${want}`);
    await page.close();
  });
}

test('a pitch the user typed is kept when switching back and forth', async () => {
  const page = await openApp(panel);
  await switchToDistance(page);
  await page.fill('#pitch', '7');
  await waitReady(page);
  await page.selectOption('#spacing', 'count');
  await waitReady(page);
  await page.selectOption('#spacing', 'pitch');
  await waitReady(page);
  assert.equal(await page.inputValue('#pitch'), '7');
  const design = await page.evaluate(() => window.DF.app.design());
  assert.equal(design.count, Math.round((2 * Math.PI * R) / 7));
  await page.close();
});
