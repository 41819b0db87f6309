// Circles, ellipses and rounded corners are SVG arcs; they are read as the arcs SVG defines (as the
// Inkscape extension does, converted by the core), so their perimeters are the true ones: 2πr for
// a circle, not the 0.014 % longer four-Bézier approximation (a 100 mm circle read 314.20 mm).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { measureRows, openApp, openSvgFiles, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();
const MM = 72 / 25.4;

/** Ellipse perimeter by the composite Simpson rule on 4a∫₀^{π/2}√(1 − e² sin²t) dt (independent). */
function ellipsePerimeter(a, b) {
  const n = 20000;
  const e2 = 1 - (b * b) / (a * a);
  const g = (t) => Math.sqrt(1 - e2 * Math.sin(t) ** 2);
  const h = Math.PI / 2 / n;
  let s = g(0) + g(Math.PI / 2);
  for (let i = 1; i < n; i++) s += (i % 2 ? 4 : 2) * g(i * h);
  return 4 * a * (s * h) / 3;
}

const CASES = [
  ['circle r = 50', '<circle id="s" cx="60" cy="60" r="50"/>', 2 * Math.PI * 50],
  ['ellipse 70 × 35', '<ellipse id="s" cx="80" cy="50" rx="70" ry="35"/>', ellipsePerimeter(70, 35)],
  ['rect 80 × 50, corners r = 10', '<rect id="s" x="10" y="10" width="80" height="50" rx="10"/>', 2 * (80 + 50) - 8 * 10 + 2 * Math.PI * 10],
  ['rect 80 × 50, corners 20 × 8', '<rect id="s" x="10" y="10" width="80" height="50" rx="20" ry="8"/>', 2 * (80 + 50) - 4 * (20 + 8) + ellipsePerimeter(20, 8)],
];

for (const [name, shape, want] of CASES) {
  test(`${name}: perimeter ${want.toFixed(4)} mm`, async () => {
    const page = await openApp(panel);
    await openSvgFiles(page, [['shapes.svg', '<svg xmlns="http://www.w3.org/2000/svg" width="300mm" height="200mm" viewBox="0 0 300 200">' +
      shape + '<rect id="other" x="200" y="10" width="50" height="50"/></svg>']]);
    await waitReady(page);
    assert.equal((await measureRows(page))[0].perimeter, `${want.toFixed(2)} mm`);
    const got = await page.evaluate(() => window.DF.app.design().measures[0].m.perimeter) / MM;
    assert.ok(Math.abs(got - want) <= 2e-6 * want, `${got} mm, wanted ${want} mm (relative error ${(got - want) / want})`);
    await page.close();
  });
}
