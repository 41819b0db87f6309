// Moving the seam-offset slider and clicking OBJ/STL before the re-solve finished used to export the
// form of the *previous* slider position: the file did not match the slider. Now the export waits for
// the form of the slider's position. The solve is held back by the test until after the click (it
// used to rely on the solver being slow, which it no longer is), so the click always lands while the
// new position is still solving. Checked independently: the exported mesh's volume (divergence
// theorem) equals a fresh solve of the design at the final offset, not the one at the first.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { openApp, openSvgFiles, usePanelBrowser } from './support.mjs';
import { meshVolume, objTriangles } from './mesh.mjs';

const panel = usePanelBrowser();

// A rectangle and an ellipse (normalized to one perimeter by the app): unlike a circle, the ellipse
// makes the form depend on where the seam starts, so the two slider positions differ in volume.
const SVG = '<svg xmlns="http://www.w3.org/2000/svg" width="300mm" height="150mm" viewBox="0 0 300 150">' +
  '<rect x="45" y="50" width="55" height="45"/><ellipse cx="220" cy="75" rx="45" ry="22"/></svg>';
const PT3_TO_MM3 = Math.pow(25.4 / 72, 3);


test('3D tab: OBJ clicked while the slider\'s new position is still solving exports the new position\'s form', async () => {
  const page = await openApp(panel);
  await openSvgFiles(page, [['rect-circle.svg', SVG]]);
  await page.click('.tabs button[data-view="3d"]');
  await page.waitForFunction(() => document.body.dataset.solve === 'ok' && !document.body.dataset.solving, null, { timeout: 30000 });
  // A fresh solve of the design, outside the panel's pipeline, at a given slider position (‰ of the perimeter).
  const solveAt = (permille) => page.evaluate((pm) => {
    const d = window.DF.app.design();
    return window.DF.core.simulate(d.pieces.map((p) => p.path), { offset: (pm / 1000) * d.perimeter }).stats.volume;
  }, permille);
  const before = (await solveAt(0)) * PT3_TO_MM3;
  const wanted = (await solveAt(800)) * PT3_TO_MM3;
  assert.ok(Math.abs(before - wanted) > 1, `precondition: the two positions differ in volume (${before} vs ${wanted} mm³)`);

  // Hold every solve's result until the test lets it through.
  await page.evaluate(() => {
    const real = window.DF.solver.solve;
    window.__held = [];
    window.DF.solver.solve = (pieces, options) => real(pieces, options).then((r) => new Promise((resolve) => window.__held.push(() => resolve(r))));
  });
  await page.$eval('#offset3d', (el) => {
    el.value = '800';
    el.dispatchEvent(new Event('input'));
  });
  await page.waitForFunction(() => document.body.dataset.solving === 'yes' && window.__held.length > 0);
  const download = page.waitForEvent('download', { timeout: 30000 });
  await page.click('#export-obj');
  assert.equal(await page.evaluate(() => document.body.dataset.solving), 'yes', 'the click landed while the new position was still solving');
  await page.evaluate(() => { const release = () => window.__held.splice(0).forEach((go) => go()); release(); window.__release = setInterval(release, 20); });
  const dl = await download;
  const got = meshVolume(objTriangles(readFileSync(await dl.path(), 'utf8')));
  assert.equal(await page.$eval('#offset3d', (el) => el.value), '800');
  assert.ok(Math.abs(got - wanted) <= 1e-4 * Math.abs(wanted) + 0.01,
    `exported volume ${got.toFixed(2)} mm³: the form at the slider's position has ${wanted.toFixed(2)}, the previous position's ${before.toFixed(2)}`);
  await page.waitForFunction(() => /Downloaded d-form-mm\.obj/.test(document.querySelector('#status').textContent));
  await page.close();
});
