// Opening a file: shapes in a hidden layer are not pieces, and an open stroke is listed as skipped
// by its id instead of blocking the file.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();

async function openFile(name, text) {
  const page = await panel.browser.newPage();
  await page.goto(panel.url);
  await waitReady(page, 'load');
  await page.setInputFiles('#open-input', [{ name, mimeType: 'image/svg+xml', buffer: Buffer.from(text) }]);
  await page.waitForFunction((n) => (document.querySelector('#selection-summary').textContent + document.querySelector('#status').textContent).includes(n), name);
  return page;
}

test('an Inkscape layer switched off (display:none) is not read', async () => {
  const svg = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" width="300mm" height="100mm" viewBox="0 0 300 100">' +
    '<g inkscape:groupmode="layer" inkscape:label="draft" style="display:none"><rect id="draft" x="5" y="5" width="20" height="20"/></g>' +
    '<g inkscape:groupmode="layer" inkscape:label="Layer 1"><circle id="keepA" cx="100" cy="50" r="40"/><rect id="keepB" x="160" y="10" width="80" height="60"/></g>' +
    '<rect id="off" display="none" x="250" y="10" width="10" height="10"/></svg>';
  const page = await openFile('layers.svg', svg);
  const names = await page.$$eval('#measure-table td.name', (tds) => tds.map((t) => t.textContent));
  assert.deepEqual(names.slice(0, 2), ['keepA', 'keepB']);
  const perims = await page.$$eval('#measure-table td.perimeter', (tds) => tds.map((t) => t.textContent));
  assert.equal(perims[1], `${(2 * (80 + 60)).toFixed(2)} mm`);
  assert.equal(await page.$('#skipped-list'), null, 'nothing skipped');
  await page.close();
});

test('test_issue_16 an open stroke among closed shapes: skipped by name, the file still opens', async () => {
  // Was: "open.svg, shape “unclosed”: The path is open. … (Object > Path > Join)" for the whole
  // file, with an Illustrator menu inside a browser.
  const svg = '<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 200 100">' +
    '<circle id="c" cx="50" cy="50" r="40"/><path id="unclosed" d="M 110 10 L 190 10 L 190 90 L 110 90"/></svg>';
  const page = await openFile('open.svg', svg);
  assert.equal(await page.textContent('#status'), '');
  const skipped = await page.textContent('#skipped-list');
  assert.match(skipped, /unclosed: an open path/, skipped);
  assert.doesNotMatch(skipped, /Object >|Path >/, 'plain words in the browser');
  assert.match(await page.textContent('#message'), /Only one closed shape/);
  await page.close();
});
