// The page itself is a viewport: its viewBox is fitted into its width × height by
// preserveAspectRatio (default xMidYMid meet), one scale for both directions. A 200 × 100 mm page
// over a square viewBox used to be read 2 mm per unit across and 1 mm down, stretching every shape.
// Shapes must be read as large as Chromium draws them: Chromium's own layout and getScreenCTM are
// the reference, none of the app's code.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { measureRows, openApp, openSvgFiles, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();
const RECT = '<rect id="inner" x="10" y="20" width="50" height="30"/>';
const page = (attrs) => `<svg xmlns="http://www.w3.org/2000/svg" ${attrs}>${RECT}</svg>`;
const CASES = {
  'meet, page wider than the viewBox (centred)': 'width="200mm" height="100mm" viewBox="0 0 100 100"',
  'meet, page taller than the viewBox (centred)': 'width="100mm" height="300mm" viewBox="0 0 100 100"',
  'xMaxYMin slice': 'width="200mm" height="100mm" viewBox="0 0 100 100" preserveAspectRatio="xMaxYMin slice"',
  'xMinYMax meet, viewBox offset': 'width="8in" height="4in" viewBox="-5 7 100 100" preserveAspectRatio="xMinYMax meet"',
  'none with equal scales': 'width="200mm" height="100mm" viewBox="0 0 200 100" preserveAspectRatio="none"',
  'height missing: the viewBox proportions': 'width="150mm" viewBox="0 0 100 50"',
  'width missing: the viewBox proportions': 'height="40mm" viewBox="0 0 100 50"',
};

test('the page viewBox is fitted by preserveAspectRatio, as Chromium draws it', async () => {
  const p = await openApp(panel);
  const results = await p.evaluate((cases) => {
    const out = {};
    const host = document.createElement('div');
    document.body.appendChild(host);
    for (const [name, svg] of Object.entries(cases)) {
      host.innerHTML = svg;
      const rootEl = host.querySelector('svg');
      const el = host.querySelector('#inner');
      const origin = rootEl.getBoundingClientRect();
      const m = el.getScreenCTM();
      const b = el.getBBox();
      // CSS px from the page's top-left corner → points (0.75 pt per px), y up.
      const corners = [[b.x, b.y], [b.x + b.width, b.y + b.height]].map(([x, y]) => new DOMPoint(x, y).matrixTransform(m))
        .map((q) => [(q.x - origin.left) * 0.75, -(q.y - origin.top) * 0.75]);
      const want = {
        min: [Math.min(corners[0][0], corners[1][0]), Math.min(corners[0][1], corners[1][1])],
        max: [Math.max(corners[0][0], corners[1][0]), Math.max(corners[0][1], corners[1][1])],
      };
      const parsed = window.DF.svgImport.parse(svg, 'page.svg');
      out[name] = { want, got: window.DF.core.measure(parsed.shapes[0].path).bounds };
    }
    host.remove();
    return out;
  }, Object.fromEntries(Object.entries(CASES).map(([k, v]) => [k, page(v)])));
  for (const [name, r] of Object.entries(results)) {
    for (const end of ['min', 'max']) {
      for (const axis of [0, 1]) {
        // Chromium lays out in float32 and snaps the page origin to layout units (1/64 px): 0.02 pt.
        assert.ok(Math.abs(r.got[end][axis] - r.want[end][axis]) < 0.02, `${name}: bounds.${end}[${axis}] ${r.got[end][axis]} pt, Chromium draws it at ${r.want[end][axis]} pt`);
      }
    }
  }
  await p.close();
});

test('a percentage page size is a share of the viewBox size in px (Inkscape’s reading)', async () => {
  const p = await openApp(panel);
  const bounds = await p.evaluate((svg) => window.DF.core.measure(window.DF.svgImport.parse(svg, 'pct.svg').shapes[0].path).bounds,
    page('width="50%" height="50%" viewBox="0 0 100 100"'));
  // 50 % of 100 units = 50 px for 100 units: 0.5 px = 0.375 pt per unit; the rect is 50 × 30 units.
  assert.ok(Math.abs(bounds.max[0] - bounds.min[0] - 50 * 0.375) < 1e-9, `width ${bounds.max[0] - bounds.min[0]} pt, want ${50 * 0.375}`);
  assert.ok(Math.abs(bounds.max[1] - bounds.min[1] - 30 * 0.375) < 1e-9, `height ${bounds.max[1] - bounds.min[1]} pt, want ${30 * 0.375}`);
  await p.close();
});

test('opened as a file: a 10-unit square on a 200 × 100 mm page over a square viewBox measures 40 mm', async () => {
  const p = await openApp(panel);
  await openSvgFiles(p, [['wide-page.svg', '<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 100 100"><rect id="sq" x="10" y="10" width="10" height="10"/><circle id="c" cx="50" cy="50" r="20"/></svg>']]);
  await waitReady(p);
  const rows = await measureRows(p);
  assert.deepEqual(rows.map((r) => r.name), ['sq', 'c']);
  // meet: min(200 mm / 100, 100 mm / 100) = 1 mm per unit in both directions (it was 2 mm across).
  assert.equal(rows[0].perimeter, '40.00 mm');
  assert.equal(rows[1].perimeter, `${(2 * Math.PI * 20).toFixed(2)} mm`);
  await p.close();
});

test('a page stretched unequally (preserveAspectRatio="none") is refused with the reason and a way out', async () => {
  const p = await openApp(panel);
  const message = await p.evaluate((svg) => {
    try { window.DF.svgImport.parse(svg, 'stretched.svg'); return null; } catch (e) { return e.message; }
  }, page('width="200mm" height="100mm" viewBox="0 0 100 100" preserveAspectRatio="none"'));
  assert.ok(message, 'a stretched page was read');
  assert.match(message, /^stretched\.svg: the page stretches the drawing unequally \(preserveAspectRatio="none", 7\.55906 px per user unit across, 3\.77953 down\)/);
  assert.match(message, /Make the page size proportional to the viewBox, or remove preserveAspectRatio\./);
  await p.close();
});
