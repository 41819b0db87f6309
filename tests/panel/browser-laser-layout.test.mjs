// The downloaded laser SVG never stacks one piece over the other. Normalizing scales each piece
// about its own centre, so a small shape drawn next to a large one grows into it; the file must
// still place the pieces apart. Checked by Chromium's own SVG engine (getBBox, getTotalLength).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();

// Circles of 10 mm and 100 mm radius, 10 mm apart: "Largest" scales the small one ×10.
const SMALL_BESIDE_LARGE = '<svg xmlns="http://www.w3.org/2000/svg" width="300mm" height="200mm" viewBox="0 0 300 200">' +
  '<circle id="small" cx="20" cy="50" r="10"/><circle id="large" cx="140" cy="100" r="100"/></svg>';

test('normalized pieces that would overlap are laid out apart in the laser SVG', async () => {
  const page = await panel.browser.newPage({ acceptDownloads: true });
  await page.goto(panel.url);
  await waitReady(page, 'load');
  await page.setInputFiles('#open-input', [{ name: 'circles.svg', mimeType: 'image/svg+xml', buffer: Buffer.from(SMALL_BESIDE_LARGE) }]);
  await page.waitForFunction(() => /circles\.svg/.test(document.querySelector('#selection-summary').textContent));
  await waitReady(page);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#apply-btn')]);
  const text = readFileSync(await download.path(), 'utf8');

  const blank = await panel.browser.newPage();
  const got = await blank.evaluate((svgText) => {
    document.body.innerHTML = svgText.replace(/^<\?xml[^>]*>/, '');
    const svg = document.querySelector('svg');
    const mmPerUnit = parseFloat(svg.getAttribute('width')) / svg.viewBox.baseVal.width;
    return [...svg.querySelectorAll('#layer-cut path.outline')].map((o) => {
      const b = o.getBBox();
      return { x0: b.x * mmPerUnit, x1: (b.x + b.width) * mmPerUnit, y0: b.y * mmPerUnit, y1: (b.y + b.height) * mmPerUnit, perimeter: o.getTotalLength() * mmPerUnit };
    });
  }, text);
  await blank.close();
  await page.close();

  assert.equal(got.length, 2);
  const [a, b] = got;
  const want = 2 * Math.PI * 100; // both normalized to the large circle
  for (const p of got) {
    assert.ok(Math.abs(p.perimeter - want) < 0.002 * want, `perimeter ${p.perimeter} mm, wanted ${want.toFixed(2)} mm`);
    assert.ok(Math.abs(p.x1 - p.x0 - 200) < 0.5, `diameter ${p.x1 - p.x0} mm, wanted 200 mm`);
  }
  const apart = a.x1 <= b.x0 || b.x1 <= a.x0 || a.y1 <= b.y0 || b.y1 <= a.y0;
  assert.ok(apart, `outlines overlap: A x ${a.x0.toFixed(1)}…${a.x1.toFixed(1)} mm, B x ${b.x0.toFixed(1)}…${b.x1.toFixed(1)} mm`);
});
