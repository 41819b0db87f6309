// Where the form on show is approximate (creased, stretched, through itself), the sweep under the
// slider may already know seam offsets whose form is exact: two copies of a drawn heart converge
// at about half the offsets and crease at the others. "Nearest exact" moves the slider to the
// converged sampled offset nearest to the one on show (either way round the seam), and the
// approximate warning points to it. Checked independently: the nearest is found here from the
// sweep's points, and the form then shown is converged.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { artifactPath, openApp, openSvgFiles, usePanelBrowser } from './support.mjs';

const panel = usePanelBrowser();

// The heart of core/tests/simulate_common/shapes.rs (drawn_heart: six cubics, corners at the dip
// and the tip), twice, y flipped for SVG.
const heart = (dx) => {
  const p = ([x, y]) => `${x + dx},${80 - y}`;
  const segs = [[[-12, 50], [-18, 60], [-30, 60]], [[-42, 60], [-55, 45], [-55, 30]], [[-55, 15], [-20, -20], [0, -45]],
    [[20, -20], [55, 15], [55, 30]], [[55, 45], [42, 60], [30, 60]], [[18, 60], [12, 50], [0, 40]]];
  return `<path d="M${p([0, 40])} ${segs.map((s) => `C${s.map(p).join(' ')}`).join(' ')}Z"/>`;
};
const SVG = `<svg xmlns="http://www.w3.org/2000/svg" width="260mm" height="140mm" viewBox="0 0 260 140">${heart(70)}${heart(190)}</svg>`;

test('3D tab: "Nearest exact" moves an approximate form to the nearest seam offset whose form is exact', { timeout: 600000 }, async () => {
  const page = await openApp(panel);
  await openSvgFiles(page, [['two-hearts.svg', SVG]]);
  await page.click('.tabs button[data-view="3d"]');
  await page.waitForFunction(() => document.body.dataset.solve === 'ok' && !document.body.dataset.solving, null, { timeout: 60000 });
  await page.waitForFunction(() => document.body.dataset.sweep === 'done', null, { timeout: 300000 });
  const points = await page.evaluate(() => window.DF.app.sweep().points.map((p) => ({ fraction: p.fraction, offset: p.offset, converged: p.converged })));
  const creased = points.filter((p) => !p.converged);
  assert.ok(creased.length > 0 && creased.length < points.length, `precondition: some offsets exact, some not (${creased.length} of ${points.length} not)`);

  const slide = (permille) => page.$eval('#offset3d', (el, v) => {
    el.value = String(v);
    el.dispatchEvent(new Event('input'));
  }, permille);
  const settled = () => page.waitForFunction(() => document.body.dataset.solve === 'ok' && !document.body.dataset.solving, null, { timeout: 60000 });
  // A slider position whose form is approximate: at (or beside) an offset the sweep found creased.
  let at = null;
  for (const p of creased) {
    await slide(Math.round(p.fraction * 1000));
    await settled();
    if (!(await page.evaluate(() => window.DF.app.mesh().stats.converged))) {
      at = await page.evaluate(() => window.DF.app.design().offset / window.DF.app.design().perimeter);
      break;
    }
  }
  assert.ok(at !== null, 'precondition: a slider position with an approximate form');
  assert.equal(await page.locator('#sweep-exact').isEnabled(), true, 'the button is offered');
  assert.match(await page.textContent('#warn3d'), /Nearest exact/, 'the warning points to it');

  // The nearest converged sampled offset, either way round the seam.
  const gap = (f) => { const d = Math.abs(f - at) % 1; return Math.min(d, 1 - d); };
  const want = points.filter((p) => p.converged).reduce((a, b) => (gap(b.fraction) < gap(a.fraction) ? b : a));
  await page.screenshot({ path: artifactPath('browser-3d-nearest-exact.png') });
  await page.click('#sweep-exact');
  await page.waitForFunction((o) => Math.abs(window.DF.app.design().offset - o) < 1e-9 * window.DF.app.design().perimeter, want.offset, { timeout: 20000 });
  await settled();
  const after = await page.evaluate(() => ({ converged: window.DF.app.mesh().stats.converged, warn: !document.querySelector('#warn3d').hidden,
    button: document.querySelector('#sweep-exact').disabled }));
  assert.equal(after.converged, true, `the form at ${want.offset} (the sweep's nearest exact) is exact`);
  assert.equal(after.warn, false, 'no approximate warning');
  assert.equal(after.button, true, 'the button is not offered for an exact form');
  await page.close();
});
