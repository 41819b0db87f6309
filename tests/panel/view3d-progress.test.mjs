// A non-convex pair takes seconds to solve (the sheet path), and the 3D tab only said
// "· solving…" meanwhile: nothing moved, and a student could not tell a working solver from a
// hung one. Now the solver thread reports each stage, and the tab shows the share done after
// "solving…". Checked on the bundled Pebble + circle: while it solves, the progress shown rises
// (never falls) through at least two values, each a whole percent; when the form arrives it is
// cleared, and the form is the converged one.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openApp, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();

test('3D tab: a long solve shows its progress, rising, and clears it when the form arrives', async () => {
  const page = await openApp(panel);
  await page.selectOption('#sample-select', 'pebble-circle');
  await page.waitForFunction(() => /Sample: /.test(document.querySelector('#selection-summary').textContent));
  await waitReady(page);
  await page.evaluate(() => {
    const el = document.querySelector('#stats3d');
    window.progressSeen = [];
    new MutationObserver(() => window.progressSeen.push(el.dataset.progress || '')).observe(el, { attributes: true, attributeFilter: ['data-progress'] });
  });
  await page.click('.tabs button[data-view="3d"]');
  await page.waitForFunction(() => document.body.dataset.solve && !document.body.dataset.solving, null, { timeout: 60000 });
  const seen = await page.evaluate(() => window.progressSeen);
  const shown = seen.filter((v) => v !== '');
  assert.ok(shown.length >= 2, `wanted at least two progress values while solving, got ${JSON.stringify(seen)}`);
  const numbers = shown.map((v) => {
    const m = /^(\d+) %$/.exec(v);
    assert.ok(m, `wanted a whole percent, got ${JSON.stringify(v)}`);
    return Number(m[1]);
  });
  numbers.forEach((n, i) => {
    assert.ok(n > 0 && n <= 100, `wanted a share in (0, 100], got ${n}`);
    if (i > 0) assert.ok(n >= numbers[i - 1], `progress fell from ${numbers[i - 1]} to ${n}: ${JSON.stringify(shown)}`);
  });
  assert.ok(numbers[numbers.length - 1] > numbers[0], `wanted the progress to rise, got ${JSON.stringify(shown)}`);
  assert.equal(await page.evaluate(() => document.querySelector('#stats3d').dataset.progress), '', 'cleared when the form arrives');
  assert.equal(await page.evaluate(() => document.body.dataset.solve), 'ok');
  assert.equal(await page.locator('#warn3d').isVisible(), false, 'the Pebble + circle form is converged, not approximate');
  await page.close();
});
