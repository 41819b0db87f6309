// SVG written by Adobe Illustrator counts 72 px to the inch (its px is its point), not the CSS 96:
// a 100 × 50 mm rectangle drawn in Illustrator is 283.46 × 141.73 user units. Read at 96 ppi it
// would come out 75 × 37.5 mm. Other SVG keeps the CSS px.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();
const PT = 25.4 / 72; // mm per point
const RECT_PT = [283.46, 141.73]; // 100 × 50 mm in points, as Illustrator rounds them
const RECT_MM = 2 * (RECT_PT[0] + RECT_PT[1]) * PT;
const ELLIPSE = '<ellipse cx="566.93" cy="226.77" rx="141.73" ry="113.39"/>';

const SAVE_AS = '<?xml version="1.0" encoding="utf-8"?>\n<!-- Generator: Adobe Illustrator 27.0.0, SVG Export Plug-In . SVG Version: 6.00 Build 0)  -->\n' +
  '<svg version="1.1" id="Layer_1" xmlns="http://www.w3.org/2000/svg" x="0px" y="0px" viewBox="0 0 841.89 595.28" style="enable-background:new 0 0 841.89 595.28;" xml:space="preserve">' +
  `<rect x="56.69" y="56.69" width="${RECT_PT[0]}" height="${RECT_PT[1]}"/>${ELLIPSE}</svg>`;
const LEGACY = '<?xml version="1.0" encoding="utf-8"?>\n<!-- Generator: Adobe Illustrator 16.0.0, SVG Export Plug-In . SVG Version: 6.00 Build 0)  -->\n' +
  '<svg version="1.1" xmlns="http://www.w3.org/2000/svg" x="0px" y="0px" width="841.89px" height="595.28px" viewBox="0 0 841.89 595.28">' +
  `<polygon points="56.69,56.69 340.15,56.69 340.15,198.42 56.69,198.42"/>${ELLIPSE}</svg>`;
const EXPORT_AS = '<svg id="Layer_1" data-name="Layer 1" xmlns="http://www.w3.org/2000/svg" viewBox="0 0 841.89 595.28">' +
  `<rect x="56.69" y="56.69" width="${RECT_PT[0]}" height="${RECT_PT[1]}"/>${ELLIPSE}</svg>`;
// Not from Illustrator: 96 px = 1 in.
const CSS = '<svg xmlns="http://www.w3.org/2000/svg" width="400px" height="200px" viewBox="0 0 400 200">' +
  '<rect x="10" y="10" width="96" height="96"/><circle cx="300" cy="100" r="48"/></svg>';

async function firstPerimeter(name, text) {
  const page = await panel.browser.newPage();
  await page.goto(panel.url);
  await waitReady(page, 'load');
  await page.setInputFiles('#open-input', [{ name, mimeType: 'image/svg+xml', buffer: Buffer.from(text) }]);
  await page.waitForFunction((n) => document.querySelector('#selection-summary').textContent.includes(n), name);
  const cell = await page.textContent('#measure-table tr td.perimeter');
  await page.close();
  return cell;
}

for (const [name, text] of [['save-as.svg', SAVE_AS], ['legacy.svg', LEGACY], ['export-as.svg', EXPORT_AS]]) {
  test(`Illustrator ${name}: the rectangle drawn 100 × 50 mm measures ${RECT_MM.toFixed(2)} mm`, async () => {
    assert.equal(await firstPerimeter(name, text), `${RECT_MM.toFixed(2)} mm`);
  });
}

test('an SVG not from Illustrator keeps 96 px per inch: a 96 px square is 1 in a side', async () => {
  assert.equal(await firstPerimeter('css.svg', CSS), `${(4 * 25.4).toFixed(2)} mm`);
});
