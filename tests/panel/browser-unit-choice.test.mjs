// The unit the user picks sticks: the next sample or file does not switch it back to the file's
// unit, and the next session opens in it. The file's unit is only the default while the user has
// not chosen one.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { measureRows, openApp, openSvgFiles, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();
const MM_FILE = ['mm.svg', '<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 200 100">' +
  '<rect id="a" x="10" y="10" width="50.8" height="25.4"/><rect id="b" x="100" y="10" width="25.4" height="50.8"/></svg>'];
const INCH = `${(2 * (2 + 1)).toFixed(4)} in`; // a 50.8 × 25.4 mm rectangle is 2 × 1 in

test('inches chosen: kept for the next sample, the next file (drawn in mm), the download and the next session', async () => {
  const page = await openApp(panel);
  await page.selectOption('#unit-select', 'in');
  await page.selectOption('#sample-select', 'pebble-circle');
  await page.waitForFunction(() => /Pebble/.test(document.querySelector('#selection-summary').textContent));
  await waitReady(page);
  assert.equal(await page.inputValue('#unit-select'), 'in');
  assert.match((await measureRows(page))[0].perimeter, / in$/);

  await openSvgFiles(page, [MM_FILE]);
  await waitReady(page);
  assert.equal(await page.inputValue('#unit-select'), 'in', 'a file drawn in mm does not override the choice');
  assert.equal((await measureRows(page))[0].perimeter, INCH);
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#apply-btn')]);
  const text = Buffer.concat(await (await dl.createReadStream()).toArray()).toString('utf8');
  assert.match(/<svg[^>]*\swidth="([^"]+)"/.exec(text)[1], /in$/, 'the laser SVG is sized in the chosen unit');

  await page.reload();
  await waitReady(page);
  assert.equal(await page.inputValue('#unit-select'), 'in', 'remembered by the next session');
  assert.match((await measureRows(page))[0].perimeter, / in$/);
  await page.close();
});

test('no unit chosen yet: the file’s unit is used', async () => {
  const page = await openApp(panel);
  await openSvgFiles(page, [['inch.svg', '<svg xmlns="http://www.w3.org/2000/svg" width="8in" height="4in" viewBox="0 0 8 4">' +
    '<rect id="a" x="0.5" y="0.5" width="2" height="1"/><rect id="b" x="4" y="0.5" width="1" height="2"/></svg>']]);
  await waitReady(page);
  assert.equal(await page.inputValue('#unit-select'), 'in');
  assert.equal((await measureRows(page))[0].perimeter, INCH);
  await page.close();
});
