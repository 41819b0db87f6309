// A non-convex pair's slider position can take seconds to solve at 256 seam points (the kidney
// with its mirror image at 6/16 of its perimeter: 0.4 s to its level's converged form, 1.8 s in
// all, native), and meanwhile the 3D tab showed the previous position's form. Now the solver hands
// over that coarser form (the core's `interim`) and the tab shows it at once as a "First look",
// until the result replaces it; a drag that has moved on stops such a solve as soon as its first
// look is on show instead of after a second. Checked on the bundled Pebble + circle: the first
// look is a closed mesh on half the seam points whose volume (recomputed here from its triangles)
// is the result's to 1 %, worded as such, and gone when the result arrives; and with the
// one-second stop switched off in the page, a slider move past a solve that has shown its first
// look still stops it and solves the newest position (before, the panel waited on it for ever).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { holdSolves, usePanelBrowser, waitReady } from './support.mjs';
import { meshVolume } from './mesh.mjs';

const panel = usePanelBrowser();

const volumeOf = (form) => meshVolume(form.triangles.map((t) => t.map((v) => form.vertices[v])));

test('3D tab: a long solve shows its first look, then the result; a drag moves on from it at once', async () => {
  const page = await panel.browser.newPage({ viewport: { width: 1100, height: 720 } });
  await page.addInitScript(holdSolves);
  await page.addInitScript(() => {
    // The slider's one-second stop (app.js supersedeLater's timer) never fires here: only the
    // first look may stop a solve the drag has moved on from.
    const later = window.setTimeout;
    window.setTimeout = (fn, ms, ...rest) => (typeof fn === 'function' && /DF\.solver\.cancel/.test(String(fn)) ? 0 : later(fn, ms, ...rest));
  });
  await page.goto(panel.url);
  await waitReady(page, 'load');
  await page.selectOption('#sample-select', 'pebble-circle');
  await page.waitForFunction(() => /Sample: /.test(document.querySelector('#selection-summary').textContent));
  await waitReady(page);
  await page.evaluate(() => {
    window.looks = [];
    new MutationObserver(() => {
      if (document.body.dataset.interim !== 'yes') return;
      window.looks.push({ form: window.DF.app.interim(), text: document.querySelector('#stats3d').textContent,
        warned: !document.querySelector('#warn3d').hidden, solving: document.body.dataset.solving });
    }).observe(document.body, { attributes: true, attributeFilter: ['data-interim'] });
  });
  await page.click('.tabs button[data-view="3d"]');
  await page.waitForFunction(() => document.body.dataset.solve === 'ok' && !document.body.dataset.solving, null, { timeout: 60000 });
  assert.equal(await page.evaluate(() => window.DF.solver.threaded()), true, 'precondition: the panel solves on its worker');
  const first = await page.evaluate(() => ({ looks: window.looks, result: window.DF.app.mesh(), interim: window.DF.app.interim(),
    text: document.querySelector('#stats3d').textContent, flag: document.body.dataset.interim }));
  assert.equal(first.looks.length, 1, 'one first look while the Pebble + circle was solved');
  const look = first.looks[0];
  assert.equal(look.solving, 'yes', 'shown while the solve was under way');
  assert.match(look.text, /^First look: Volume /);
  assert.equal(look.warned, false, 'a first look is converged: no approximate warning');
  assert.equal(look.form.seam.length, 128, 'on half the seam points');
  assert.equal(first.result.seam.length, 256);
  const [vl, vr] = [volumeOf(look.form), volumeOf(first.result)];
  assert.ok(Math.abs(vl / vr - 1) < 1e-2, `first look's volume ${vl} against the result's ${vr}`);
  assert.equal(first.interim, null, 'the result replaced the first look');
  assert.equal(first.flag, '');
  assert.doesNotMatch(first.text, /First look/);

  const slide = (permille) => page.$eval('#offset3d', (el, v) => {
    el.value = String(v);
    el.dispatchEvent(new Event('input'));
  }, permille);
  await page.evaluate(() => { window.__holdMode = 'result'; window.__holdNext = true; });
  await slide(300);
  await page.waitForFunction(() => window.__held === 1 && window.looks.length === 2 && document.body.dataset.solving === 'yes', null, { timeout: 60000 });
  await slide(800);
  await page.waitForFunction(() => document.body.dataset.solve === 'ok' && !document.body.dataset.solving && document.body.dataset.interim === '',
    null, { timeout: 60000 });
  const got = await page.evaluate(() => {
    const d = window.DF.app.design();
    return { terminated: window.__terminated, shown: window.DF.app.mesh().stats.volume, slider: document.querySelector('#offset3d').value,
      fresh: window.DF.core.simulate(d.pieces.map((p) => p.path), { offset: d.offset }).stats.volume };
  });
  assert.equal(got.terminated, 1, 'the solve past its first look was stopped, once');
  assert.equal(got.slider, '800');
  assert.ok(Math.abs(got.shown - got.fresh) <= 1e-6 * Math.abs(got.fresh), `the form shown has volume ${got.shown}; a fresh solve at the slider's position has ${got.fresh}`);
  await page.close();
});
