// The 3D tab gives the volume in litres too, but rounded to 3 decimals: a typical student form of
// 19,614 mm³ read "0.02 L" (2 % off) and a 0.4 cm³ one "0 L". Now litres carry 3 significant digits.
// Checked independently against the exported mesh's volume (divergence theorem), in mm³ → L.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { openApp, openSvgFiles, usePanelBrowser } from './support.mjs';
import { meshVolume, objTriangles } from './mesh.mjs';

const panel = usePanelBrowser();


test('3D tab: the litres shown agree with the exported mesh to 3 significant digits', async () => {
  const page = await openApp(panel);
  // 80 × 20 mm rectangle + circle, both 200 mm around: about 20 cm³.
  await openSvgFiles(page, [['rect-circle.svg', '<svg xmlns="http://www.w3.org/2000/svg" width="300mm" height="150mm" viewBox="0 0 300 150">' +
    `<rect x="30" y="65" width="80" height="20"/><circle cx="220" cy="75" r="${200 / (2 * Math.PI)}"/></svg>`]]);
  await page.click('.tabs button[data-view="3d"]');
  await page.waitForFunction(() => document.body.dataset.solve === 'ok' && !document.body.dataset.solving, null, { timeout: 30000 });
  const stats = await page.textContent('#stats3d');
  const m = /\(([\d,.]+) L\)/.exec(stats);
  assert.ok(m, stats);
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#export-obj')]);
  const litres = meshVolume(objTriangles(readFileSync(await dl.path(), 'utf8'))) / 1e6;
  const shown = Number(m[1].replace(/,/g, ''));
  assert.ok(Math.abs(shown - litres) <= 0.005 * litres, `shown ${m[1]} L, mesh holds ${litres.toFixed(5)} L`);
  await page.close();
});
