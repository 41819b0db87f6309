// <polyline> is read like <polygon>, except that it is only closed when it comes back to its first
// point (SVG draws no closing segment): a closed one is a piece; an open one is listed as skipped
// with why — never silently left out, and never an error for the whole file.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { measureRows, openApp, openSvgFiles, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();
const head = '<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 200 100">';

test('a polyline that returns to its first point is a piece (3-4-5 triangle: 120 mm)', async () => {
  const page = await openApp(panel);
  await openSvgFiles(page, [['tri.svg', head +
    '<g transform="translate(10 20)"><polyline id="tri" points="0,0 30,0 30,40 0,0"/></g><rect id="r" x="100" y="10" width="40" height="20"/></svg>']]);
  await waitReady(page);
  const rows = await measureRows(page);
  assert.deepEqual(rows.map((r) => r.name), ['tri', 'r']);
  assert.equal(rows[0].perimeter, `${(30 + 40 + Math.hypot(30, 40)).toFixed(2)} mm`);
  assert.equal(await page.$('#skipped-list'), null, 'nothing skipped');
  await page.close();
});

test('an open polyline is listed as skipped, an open path, with what to do — never silently left out', async () => {
  const page = await openApp(panel);
  await openSvgFiles(page, [['zig.svg', head +
    '<polyline id="zig" points="0,0 30,0 30,40"/><rect id="r" x="100" y="10" width="40" height="20"/></svg>']]);
  const skipped = await page.$$eval('#skipped-list li', (lis) => lis.map((li) => li.textContent));
  assert.deepEqual(skipped, ['zig: an open path (a stroke): a piece must be a closed outline, so close the path to use it']);
  assert.equal(await page.textContent('#status'), '', 'an open stroke is not an error for the file');
  await page.close();
});
