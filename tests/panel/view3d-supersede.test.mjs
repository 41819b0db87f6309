// A solve the slider has moved on from is stopped, not waited for. Two copies of the issue-14
// kidney glued at 13/16 of their perimeter or beyond took 4–9 s per solve in Chromium, and every
// slider position after such a one waited for it. Now the app stops a solve that has run 1 s once
// a newer position is wanted (its worker is terminated: WebAssembly cannot be interrupted) and
// solves the newest. The long solve is made here by the test, not by the solver's speed: the
// page's Worker is wrapped so that one chosen job is never answered, as a solve that runs on.
// Without the stop, the panel waited for it forever and this test timed out. Checked
// independently: the form shown is a fresh solve of the design at the slider's last position.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { holdSolves, openSvgFiles, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();

// A rectangle and an ellipse: the form depends on the seam offset (view3d-export-pending.test.mjs).
const SVG = '<svg xmlns="http://www.w3.org/2000/svg" width="300mm" height="150mm" viewBox="0 0 300 150">' +
  '<rect x="45" y="50" width="55" height="45"/><ellipse cx="220" cy="75" rx="45" ry="22"/></svg>';

test('3D tab: a solve the slider has moved on from is stopped and the newest position is solved', async () => {
  const page = await panel.browser.newPage({ viewport: { width: 1100, height: 720 } });
  await page.addInitScript(holdSolves);
  await page.goto(panel.url);
  await waitReady(page, 'load');
  await openSvgFiles(page, [['rect-ellipse.svg', SVG]]);
  await page.click('.tabs button[data-view="3d"]');
  await page.waitForFunction(() => document.body.dataset.solve === 'ok' && !document.body.dataset.solving, null, { timeout: 30000 });
  assert.equal(await page.evaluate(() => window.DF.solver.threaded()), true, 'precondition: the panel solves on its worker');
  assert.equal(await page.evaluate(() => window.DF.solver.cancel()), false, 'nothing under way: nothing stopped');

  const slide = (permille) => page.$eval('#offset3d', (el, v) => {
    el.value = String(v);
    el.dispatchEvent(new Event('input'));
  }, permille);
  await page.evaluate(() => { window.__holdNext = true; });
  await slide(300);
  await page.waitForFunction(() => document.body.dataset.solving === 'yes' && window.__held === 1);
  await slide(800);
  await page.waitForFunction(() => document.body.dataset.solve === 'ok' && !document.body.dataset.solving, null, { timeout: 30000 });

  const got = await page.evaluate(() => {
    const d = window.DF.app.design();
    const fresh = window.DF.core.simulate(d.pieces.map((p) => p.path), { offset: d.offset }).stats.volume;
    return { terminated: window.__terminated, shown: window.DF.app.mesh().stats.volume, fresh, slider: document.querySelector('#offset3d').value,
      text: document.querySelector('#stats3d').textContent };
  });
  assert.equal(got.terminated, 1, 'the held solve\'s worker was stopped, once');
  assert.equal(got.slider, '800');
  assert.ok(Math.abs(got.shown - got.fresh) <= 1e-6 * Math.abs(got.fresh),
    `the form shown has volume ${got.shown}; a fresh solve at the slider's position has ${got.fresh}`);
  assert.doesNotMatch(got.text, /stopped|replaces/, 'the stop is not reported as an error');
  await page.close();
});
