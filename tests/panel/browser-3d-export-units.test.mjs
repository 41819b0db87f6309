// STL has no unit field and every slicer reads it as millimetres; OBJ has none either and CAD/CAM
// tools assume mm too. So both are written in mm whatever unit the panel shows: with inches
// chosen, the exported mesh's volume in mm³ must still be the litres shown on screen × 10⁶
// (litres do not depend on the display unit), and the in³ shown × 16 387.064 mm³/in³.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { openApp, usePanelBrowser, waitReady } from './support.mjs';
import { meshVolume, objTriangles, stlTriangles } from './mesh.mjs';

const panel = usePanelBrowser();

/** Enclosed volume of a closed triangle soup (divergence theorem), in the file's own units³. */
const number = (s) => Number(s.replace(/,/g, ''));

test('with inches chosen, STL and OBJ are still in millimetres (volume = litres shown × 10⁶ mm³)', async (t) => {
  const page = await openApp(panel);
  if (!(await page.evaluate(() => window.DF.core.has('simulate')))) return t.skip('the core build has no simulate()');
  await page.selectOption('#sample-select', 'two-ellipses');
  await waitReady(page);
  await page.selectOption('#unit-select', 'in');
  await page.click('.tabs button[data-view="3d"]');
  await page.waitForFunction(() => document.body.dataset.solve && / in³/.test(document.querySelector('#stats3d').textContent));
  const stats = await page.textContent('#stats3d');
  const m = /Volume ([\d,.]+) in³ \(([\d,.]+) L\)/.exec(stats);
  assert.ok(m, stats);
  const litres = number(m[2]);
  const cubicInches = number(m[1]);

  const [stlDl] = await Promise.all([page.waitForEvent('download'), page.click('#export-stl')]);
  assert.match(stlDl.suggestedFilename(), /mm/, `the file name says the unit: ${stlDl.suggestedFilename()}`);
  const stlVolume = Math.abs(meshVolume(stlTriangles(readFileSync(await stlDl.path(), 'utf8'))));
  assert.ok(Math.abs(stlVolume / 1e6 - litres) <= 0.005 * litres + 0.001, `STL volume ${stlVolume} mm³ vs ${litres} L shown`);
  assert.ok(Math.abs(stlVolume - cubicInches * 25.4 ** 3) <= 0.005 * stlVolume, `STL volume ${stlVolume} mm³ vs ${cubicInches} in³ shown`);

  const [objDl] = await Promise.all([page.waitForEvent('download'), page.click('#export-obj')]);
  const obj = readFileSync(await objDl.path(), 'utf8');
  assert.match(obj, /^# .*units: mm/m, 'the OBJ header names its unit');
  const objVolume = Math.abs(meshVolume(objTriangles(obj)));
  assert.ok(Math.abs(objVolume / 1e6 - litres) <= 0.005 * litres + 0.001, `OBJ volume ${objVolume} mm³ vs ${litres} L shown`);
  assert.match(await page.textContent('#status'), /mm/, 'the status line says the export is in mm');
  await page.close();
});
