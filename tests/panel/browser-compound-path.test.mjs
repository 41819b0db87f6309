// A compound path (an outline with a hole, as a letter O or a frame is drawn) is ONE shape: its
// outer outline is the piece and the summary says the hole was ignored. It must not become two
// pieces (outline as A, hole as B) pushing the next shape out. A compound path of separate,
// side-by-side outlines has no single outline: it is skipped, named, with what to do.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { measureRows, openApp, openSvgFiles, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();
const head = '<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 200 100">';

test('an outline with a hole: the outer outline is piece A, the shape after it piece B, the hole is named as ignored', async () => {
  const page = await openApp(panel);
  await openSvgFiles(page, [['frame.svg', head +
    '<path id="frame" fill-rule="evenodd" d="M10 10H90V90H10Z M30 30V70H70V30Z"/><rect id="panel" x="110" y="20" width="80" height="60"/></svg>']]);
  await waitReady(page);
  const rows = await measureRows(page);
  assert.deepEqual(rows.map((r) => r.name), ['frame', 'panel']);
  // Independent: the outer square is 80 mm a side; the rectangle 80 × 60 mm.
  assert.equal(rows[0].perimeter, `${(4 * 80).toFixed(2)} mm`);
  assert.equal(rows[1].perimeter, `${(2 * (80 + 60)).toFixed(2)} mm`);
  const summary = await page.textContent('#selection-summary');
  assert.match(summary, /frame/);
  assert.match(summary, /hole.*ignored|ignored.*hole/i, summary);
  assert.equal(await page.$('#skipped-list'), null, 'nothing skipped');
  await page.close();
});

test('a compound path of two separate outlines is skipped by name; the two shapes after it are the pieces', async () => {
  const page = await openApp(panel);
  await openSvgFiles(page, [['pair.svg', head +
    '<path id="twins" d="M0 0H10V10H0Z M20 0H30V10H20Z"/><circle id="c" cx="100" cy="50" r="30"/><rect id="r" x="140" y="20" width="50" height="40"/></svg>']]);
  await waitReady(page);
  const rows = await measureRows(page);
  assert.deepEqual(rows.map((r) => r.name), ['c', 'r']);
  assert.equal(rows[1].perimeter, `${(2 * (50 + 40)).toFixed(2)} mm`);
  const skipped = await page.textContent('#skipped-list');
  assert.match(skipped, /twins: a compound path of 2 separate outlines: split it into separate shapes$/, skipped);
  await page.close();
});
