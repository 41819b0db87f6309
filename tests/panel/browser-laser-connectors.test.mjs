// Issue 15 req. 8 in the browser app: Download SVG writes locking leaves' slots on the cut layer
// inside the piece that receives them, a seam allowance's cut line on the cut layer and its seam
// line on the score layer, and dovetails as the cut line. Read back by Chromium's own SVG engine
// (getTotalLength, isPointInFill) and checked against closed forms of the two circles drawn here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePanelBrowser, openApp, openSvgFiles, waitReady, downloadSvg, readSvgBack } from './support.mjs';

const panel = usePanelBrowser();

const R = 30; // mm
const TWO_CIRCLES = '<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 200 100">' +
  `<circle id="a" cx="45" cy="50" r="${R}"/><circle id="b" cx="150" cy="50" r="${R}"/></svg>`;
// The page recomputes the design on the next animation frame after an input (app.js `recompute`),
// and until then its state is still the previous design's "ready": wait two frames first, or the
// preview read below is sometimes the one before the change (1 run in 3 showed no seam lines).
const ready = async (page) => {
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  await page.waitForFunction(() => document.body.dataset.state === 'ready');
};

/** Sets the design up with `act`, downloads the laser SVG and reads it back in a blank page. */
async function download(act) {
  const page = await openApp(panel);
  await openSvgFiles(page, [['circles.svg', TWO_CIRCLES]]);
  await waitReady(page);
  await act(page);
  await ready(page);
  const preview = await page.evaluate(() => ({
    slots: document.querySelectorAll('#preview .slot').length,
    seams: document.querySelectorAll('#preview .seam').length,
  }));
  const text = await downloadSvg(page);
  await page.close();
  const got = await readSvgBack(panel, text, (mm) => {
    const svg = document.querySelector('svg');
    const pieces = [...svg.querySelectorAll('#layer-cut > g')].map((g) => {
      const key = g.id.replace(/^cut-/, '');
      const outline = g.querySelector('path.outline');
      const slots = [...g.querySelectorAll('path.slot')].map((s) => {
        const b = s.getBBox();
        const c = svg.createSVGPoint();
        c.x = b.x + b.width / 2;
        c.y = b.y + b.height / 2;
        return { inside: outline.isPointInFill(c) };
      });
      const seam = svg.querySelector(`#layer-score #score-${key} path.seam`);
      return {
        key,
        cut: outline.getTotalLength() * mm,
        slots,
        seam: seam ? seam.getTotalLength() * mm : null,
      };
    });
    return {
      pieces,
      seamsElsewhere: svg.querySelectorAll('path.seam').length - svg.querySelectorAll('#layer-score path.seam').length,
      slotsElsewhere: svg.querySelectorAll('path.slot').length - svg.querySelectorAll('#layer-cut path.slot').length,
    };
  });
  return { preview, ...got };
}

test('Download SVG: a seam allowance puts the cut line 2π·a longer on the cut layer, the seam line on the score layer', async () => {
  const a = 3;
  const got = await download(async (page) => {
    await page.click('#kind button[data-kind="stitch"]');
    await page.fill('#count', '20');
    await page.fill('#allowance', String(a));
  });
  assert.equal(got.preview.seams, 2, 'preview: a seam line per piece');
  assert.equal(got.pieces.length, 2);
  assert.equal(got.seamsElsewhere, 0, 'every seam line on the score layer');
  for (const p of got.pieces) {
    // A circle of radius R: the seam line is 2πR, the cut line its parallel curve 2π(R + a).
    assert.ok(p.seam !== null, `${p.key}: no seam line on the score layer`);
    assert.ok(Math.abs(p.seam - 2 * Math.PI * R) < 1e-3 * 2 * Math.PI * R, `${p.key}: seam line ${p.seam} mm, wanted ${2 * Math.PI * R}`);
    assert.ok(Math.abs(p.cut - 2 * Math.PI * (R + a)) < 1e-3 * 2 * Math.PI * (R + a), `${p.key}: cut line ${p.cut} mm, wanted ${2 * Math.PI * (R + a)}`);
  }
});

test('Download SVG: locking leaves put half the slots on each piece, on the cut layer, inside the piece', async () => {
  const count = 12;
  const got = await download(async (page) => {
    await page.click('#kind button[data-kind="leaves"]');
    await page.selectOption('#leaf', 'lock');
    await page.fill('#count', String(count));
  });
  assert.equal(got.preview.slots, count, 'preview: every slot drawn');
  assert.equal(got.slotsElsewhere, 0, 'every slot on the cut layer');
  for (const p of got.pieces) {
    // Leaves alternate: each piece receives the other's count / 2 leaves.
    assert.equal(p.slots.length, count / 2, `${p.key}: ${p.slots.length} slots`);
    p.slots.forEach((s, i) => assert.ok(s.inside, `${p.key}: slot ${i + 1} outside its piece`));
    assert.equal(p.seam, null, `${p.key}: no allowance, no seam line`);
  }
});

test('Download SVG: dovetails change both cut lines alike, no seam line without an allowance', async () => {
  const got = await download(async (page) => {
    await page.click('#kind button[data-kind="teeth"]');
    await page.fill('#count', '12');
    await page.fill('#angle', '110');
  });
  const [A, B] = got.pieces;
  // A's teeth are B's gaps on equal circles: the two profiles are the same path turned half a
  // pitch, so equally long, and longer than the circle by the flanks (2 per tooth and gap).
  assert.ok(Math.abs(A.cut - B.cut) < 1e-3 * A.cut, `cut lines ${A.cut} and ${B.cut} mm`);
  assert.ok(A.cut > 2 * Math.PI * R * 1.05, `cut line ${A.cut} mm: no teeth`);
  assert.equal(A.seam, null);
  assert.equal(B.seam, null);
});
