// The Sample menu says which design is loaded. A file that fails to open changes nothing: the
// previous design stays, and so does the menu (it showed "—" while the old sample's pieces were
// still loaded and downloaded). A file opened or dropped on the page replaces the sample: the menu shows "—".
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { measureRows, openApp, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();

async function loadSample(page, id) {
  await page.selectOption('#sample-select', id);
  await page.waitForFunction(() => /Sample: /.test(document.querySelector('#selection-summary').textContent));
  await waitReady(page);
}
async function setFile(page, name, text) {
  await page.setInputFiles('#open-input', [{ name, mimeType: 'image/svg+xml', buffer: Buffer.from(text) }]);
  await page.waitForFunction((n) => (document.querySelector('#selection-summary').textContent + document.querySelector('#status').textContent).includes(n), name);
}
/** The piece labels of a downloaded laser SVG, read with Chromium's DOMParser. */
async function downloadedPieces(page) {
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#apply-btn')]);
  const text = await (await dl.createReadStream()).toArray().then((chunks) => Buffer.concat(chunks).toString('utf8'));
  return page.evaluate((t) => [...new DOMParser().parseFromString(t, 'image/svg+xml').querySelectorAll('[id^="cut-"]')]
    .map((g) => g.getAttribute('inkscape:label')), text);
}

const BROKEN = ['broken.svg', '<svg xmlns="http://www.w3.org/2000/svg"><rect'];
// Open strokes among closed shapes no longer fail a file (they are listed as skipped); a file with
// no closed shape at all still does, naming what it skipped.
const OPEN_PATH = ['strokes.svg', '<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 200 100">' +
  '<path id="open" d="M100 10H190V90"/><polyline id="zig" points="0,0 30,0 30,40"/></svg>'];

for (const [name, text] of [BROKEN, OPEN_PATH]) {
  test(`a file that fails to open (${name}) keeps the sample loaded AND the menu showing it; Download SVG writes that sample`, async () => {
    const page = await openApp(panel);
    await loadSample(page, 'ellipse-circle');
    const before = { rows: await measureRows(page), summary: await page.textContent('#selection-summary') };
    await setFile(page, name, text);
    assert.match(await page.textContent('#status'), new RegExp(name.replace('.', '\\.')), 'the error names the file');
    assert.equal(await page.inputValue('#sample-select'), 'ellipse-circle', 'the menu still names the loaded sample');
    assert.deepEqual(await measureRows(page), before.rows, 'the pieces are the sample’s');
    assert.equal(await page.textContent('#selection-summary'), before.summary);
    const labels = await downloadedPieces(page);
    assert.deepEqual(labels, before.rows.map((r) => `${r.name} connectors`), 'the download is the sample shown');
    await page.close();
  });
}

test('a file dropped on the page replaces the sample: the menu shows "—"', async () => {
  const page = await openApp(panel);
  await loadSample(page, 'pebble-circle');
  await page.evaluate(() => {
    const svg = '<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 200 100">' +
      '<rect id="left" x="10" y="10" width="80" height="60"/><rect id="right" x="110" y="10" width="60" height="80"/></svg>';
    const dt = new DataTransfer();
    dt.items.add(new File([svg], 'dropped.svg', { type: 'image/svg+xml' }));
    document.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  });
  await page.waitForFunction(() => /dropped\.svg/.test(document.querySelector('#selection-summary').textContent));
  assert.deepEqual((await measureRows(page)).map((r) => r.name), ['left', 'right']);
  assert.equal(await page.inputValue('#sample-select'), '', 'the menu no longer names a sample');
  await page.close();
});
