// Issue 15 req. 4 in the browser app: one shape is measured, and Normalize with an exact length
// scales it (pivot "start" offered); Download SVG writes it at that perimeter. Checked against the
// closed form of the circle drawn here and read back by Chromium's SVG engine (getTotalLength).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePanelBrowser, openApp, openSvgFiles, waitReady, measureRows, downloadSvg, readSvgBack } from './support.mjs';

const panel = usePanelBrowser();

const R = 30; // mm
const ONE_CIRCLE = `<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100"><circle id="c" cx="50" cy="50" r="${R}"/></svg>`;

test('one shape: measured, then scaled to an exact length (pivot start) and downloaded at it', async () => {
  const page = await openApp(panel);
  await openSvgFiles(page, [['circle.svg', ONE_CIRCLE]]);
  await waitReady(page);
  const rows = await measureRows(page);
  assert.equal(rows.length, 1, 'one row in the measure table');
  assert.ok(Math.abs(parseFloat(rows[0].perimeter) - 2 * Math.PI * R) < 0.006, `measured ${rows[0].perimeter}, wanted ${(2 * Math.PI * R).toFixed(2)} mm`);
  const pivots = await page.$$eval('#norm-pivot option', (o) => o.map((x) => x.value));
  assert.ok(pivots.includes('start'), `pivot "start" offered: ${pivots}`);
  await page.selectOption('#norm-target', 'exact');
  await page.fill('#norm-exact', '300');
  await page.selectOption('#norm-pivot', 'start');
  // The page recomputes on the next animation frame; until then its state is the last design's.
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  await page.waitForFunction(() => document.body.dataset.state === 'ready');
  assert.equal(await page.isDisabled('#apply-btn'), false, 'Download SVG enabled for one scaled shape');
  const text = await downloadSvg(page);
  await page.close();
  const got = await readSvgBack(panel, text, (mm) => [...document.querySelectorAll('#layer-cut path.outline')].map((o) => {
    const b = o.getBBox();
    return { perimeter: o.getTotalLength() * mm, width: b.width * mm, height: b.height * mm };
  }));
  assert.equal(got.length, 1, 'one outline on the cut layer');
  // Scaled 300 / 2πR: still a circle, of diameter 300 / π.
  assert.ok(Math.abs(got[0].perimeter - 300) < 1e-3 * 300, `perimeter ${got[0].perimeter} mm, wanted 300`);
  for (const side of [got[0].width, got[0].height]) assert.ok(Math.abs(side - 300 / Math.PI) < 1e-3 * 100, `diameter ${side} mm, wanted ${300 / Math.PI}`);
});
