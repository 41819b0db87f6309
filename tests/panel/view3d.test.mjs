// Phase 2: the 3D form next to the 2D preview (browser app and CEP panel): shaded surface, seam,
// orbit, live seam-offset slider, volume/area in document units (+ litres), OBJ/STL export.
// The figures on screen are checked against the exported mesh (divergence theorem, triangle areas).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { artifactPath, usePanelBrowser, waitReady } from './support.mjs';
import { openPanel, SKINS } from './cep-stand-in.mjs';

const panel = usePanelBrowser();

function parseObj(text) {
  const v = [];
  const f = [];
  for (const line of text.split('\n')) {
    const p = line.trim().split(/\s+/);
    if (p[0] === 'v') v.push(p.slice(1, 4).map(Number));
    if (p[0] === 'f') f.push(p.slice(1, 4).map((x) => Number(x.split('/')[0]) - 1));
  }
  return { v, f };
}
/** Enclosed volume (divergence theorem) and surface area of a closed triangle mesh. */
function volumeArea({ v, f }) {
  let vol = 0;
  let area = 0;
  for (const [i, j, k] of f) {
    const [a, b, c] = [v[i], v[j], v[k]];
    vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
    const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    const w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    area += Math.hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]) / 2;
  }
  return { volume: Math.abs(vol), area };
}
const number = (s) => Number(s.replace(/,/g, ''));

async function hasSimulate(page) {
  return page.evaluate(() => window.DF.core.has('simulate'));
}

test('browser app: 3D form of two crossed ellipses — figures match the exported mesh; slider re-solves; orbit; OBJ/STL', async (t) => {
  const page = await panel.browser.newPage({ viewport: { width: 1100, height: 720 }, acceptDownloads: true });
  await page.goto(panel.url);
  await waitReady(page, 'load');
  if (!(await hasSimulate(page))) return t.skip('the core build has no simulate() yet');
  await page.selectOption('#sample-select', 'two-ellipses');
  await waitReady(page);
  await page.click('.tabs button[data-view="3d"]');
  await page.waitForFunction(() => document.body.dataset.solve);
  assert.equal(await page.evaluate(() => document.body.dataset.solve), 'ok', await page.textContent('#stats3d'));
  assert.equal(await page.evaluate(() => window.DF.solver.threaded()), true, 'served over http, the solver runs on a worker thread');
  const stats = await page.textContent('#stats3d');
  const m = /Volume ([\d,.]+) mm³ \(([\d,.]+) L\) · area ([\d,.]+) mm²/.exec(stats);
  assert.ok(m, `stats line: ${stats}`);
  await page.screenshot({ path: artifactPath('browser-3d.png') });

  const [objDl] = await Promise.all([page.waitForEvent('download'), page.click('#export-obj')]);
  const obj = parseObj(readFileSync(await objDl.path(), 'utf8'));
  const mesh = await page.evaluate(() => ({ v: window.DF.app.mesh().vertices.length, t: window.DF.app.mesh().triangles.length }));
  assert.equal(obj.v.length, mesh.v, 'OBJ vertex count');
  assert.equal(obj.f.length, mesh.t, 'OBJ face count');
  const { volume, area } = volumeArea(obj);
  assert.ok(Math.abs(number(m[1]) - volume) <= 0.002 * volume + 1, `volume shown ${m[1]} mm³ vs mesh ${volume}`);
  assert.ok(Math.abs(number(m[2]) - volume / 1e6) <= 0.002 * (volume / 1e6) + 0.001, `litres shown ${m[2]} vs ${volume / 1e6}`);
  assert.ok(Math.abs(number(m[3]) - area) <= 0.002 * area + 1, `area shown ${m[3]} mm² vs mesh ${area}`);

  const [stlDl] = await Promise.all([page.waitForEvent('download'), page.click('#export-stl')]);
  const stl = readFileSync(await stlDl.path(), 'utf8');
  assert.match(stl, /^solid d-form\n/);
  assert.equal((stl.match(/^ facet normal /gm) || []).length, mesh.t, 'STL facet count');

  // Orbit: a drag changes the picture.
  const canvas = await page.$('#view3d');
  const before = await canvas.screenshot();
  const box = await canvas.boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 80, box.y + box.height / 2 + 30, { steps: 5 });
  await page.mouse.up();
  assert.notDeepEqual(await canvas.screenshot(), before, 'dragging must orbit the view');

  // The seam-offset slider re-solves (warm-started) and moves B's connectors by the same offset.
  const vol0 = number(m[1]);
  await page.$eval('#offset3d', (el) => {
    el.value = '250';
    el.dispatchEvent(new Event('input'));
  });
  await page.waitForFunction((v) => {
    const s = document.querySelector('#stats3d').textContent;
    const x = /Volume ([\d,.]+)/.exec(s);
    return x && Number(x[1].replace(/,/g, '')) !== v;
  }, vol0);
  const design = await page.evaluate(() => ({ offset: window.DF.app.design().offset, perimeter: window.DF.app.design().perimeter }));
  assert.ok(Math.abs(design.offset - 0.25 * design.perimeter) < 1e-6 * design.perimeter, `seam offset: wanted a quarter perimeter, got ${design.offset} of ${design.perimeter}`);
  await page.screenshot({ path: artifactPath('browser-3d-offset.png') });
  await page.close();
});

test('CEP panel: the 3D tab in a docked panel (dark theme screenshot)', async (t) => {
  const { page } = await openPanel(panel.browser, panel.url, {
    units: 'cm',
    shapes: [
      { name: 'Ellipse', ellipse: { top: 400, left: 0, width: 220, height: 110 } },
      { name: 'Circle', ellipse: { top: 400, left: 260, width: 150, height: 150 } },
    ],
  }, { skin: SKINS.mediumDark });
  await waitReady(page);
  if (!(await hasSimulate(page))) return t.skip('the core build has no simulate() yet');
  await page.click('.tabs button[data-view="3d"]');
  await page.waitForFunction(() => document.body.dataset.solve);
  const stats = await page.textContent('#stats3d');
  assert.equal(await page.evaluate(() => document.body.dataset.solve), 'ok', stats);
  assert.match(stats, /cm³ \([\d.,]+ L\) · area [\d.,]+ cm²/, `volume and area in the document's units: ${stats}`);
  await page.screenshot({ path: artifactPath('panel-3d-dark.png') });
  await page.close();
});
