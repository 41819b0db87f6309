// A nested <svg> is a viewport of its own: x, y, width, height (lengths or % of the parent's),
// viewBox and preserveAspectRatio (default xMidYMid meet) place and scale what it holds. Shapes
// inside must be read where and as large as Chromium draws them: Chromium's own getScreenCTM is
// the reference, none of the app's code.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { measureRows, openApp, openSvgFiles, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();
const root = (inner) => `<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 200 100">${inner}</svg>`;
const RECT = '<rect id="inner" x="1" y="2" width="5" height="3"/>';
const CASES = {
  'viewBox scaled ×10': `<svg x="100" y="0" width="100" height="100" viewBox="0 0 10 10">${RECT}</svg>`,
  'meet, wide viewport (centred)': `<svg x="20" y="10" width="100" height="50" viewBox="0 0 10 10">${RECT}</svg>`,
  'meet, tall viewport (centred)': `<svg x="20" y="10" width="30" height="80" viewBox="0 0 10 10">${RECT}</svg>`,
  'preserveAspectRatio none': `<svg x="20" y="10" width="100" height="50" viewBox="0 0 10 10" preserveAspectRatio="none">${RECT}</svg>`,
  'xMaxYMin slice': `<svg x="20" y="10" width="100" height="30" viewBox="0 0 10 10" preserveAspectRatio="xMaxYMin slice">${RECT}</svg>`,
  'xMinYMax meet, viewBox offset': `<svg x="5" y="5" width="60" height="90" viewBox="-2 1 10 10" preserveAspectRatio="xMinYMax meet">${RECT}</svg>`,
  'percentages of the parent': `<svg x="10%" y="20%" width="50%" height="50%" viewBox="0 0 10 10">${RECT}</svg>`,
  'width and height in mm (CSS mm of the parent’s px)': `<svg x="10" y="10" width="20mm" height="10mm" viewBox="0 0 10 10">${RECT}</svg>`,
  'no viewBox: a translation': `<svg x="30" y="40" width="10" height="10">${RECT}</svg>`,
  'nested twice, inside a group': `<g transform="translate(10 5)"><svg x="10" y="10" width="120" height="80" viewBox="0 0 60 40"><svg x="5" y="5" width="20" height="10" viewBox="0 0 5 5">${RECT}</svg></svg></g>`,
};

test('shapes inside nested <svg> viewports are read where Chromium draws them', async () => {
  const page = await openApp(panel);
  const results = await page.evaluate((cases) => {
    const out = {};
    const host = document.createElement('div');
    document.body.appendChild(host);
    for (const [name, svg] of Object.entries(cases)) {
      // Reference: Chromium's own transform from the rect's user space to the root's (mm).
      host.innerHTML = svg;
      const rootEl = host.querySelector('svg');
      const el = host.querySelector('#inner');
      const m = rootEl.getScreenCTM().inverse().multiply(el.getScreenCTM());
      const b = el.getBBox();
      const corners = [[b.x, b.y], [b.x + b.width, b.y], [b.x, b.y + b.height], [b.x + b.width, b.y + b.height]]
        .map(([x, y]) => new DOMPoint(x, y).matrixTransform(m));
      const k = 72 / 25.4;
      const want = {
        min: [Math.min(...corners.map((p) => p.x)) * k, -Math.max(...corners.map((p) => p.y)) * k],
        max: [Math.max(...corners.map((p) => p.x)) * k, -Math.min(...corners.map((p) => p.y)) * k],
      };
      const parsed = window.DF.svgImport.parse(svg, 'nested.svg');
      out[name] = { want, got: window.DF.core.measure(parsed.shapes[0].path).bounds, names: parsed.shapes.map((s) => s.name) };
    }
    return out;
  }, Object.fromEntries(Object.entries(CASES).map(([k, v]) => [k, root(v)])));
  for (const [name, r] of Object.entries(results)) {
    assert.deepEqual(r.names, ['inner'], name);
    for (const end of ['min', 'max']) {
      for (const axis of [0, 1]) {
        // Chromium computes its matrices in float32: 1e-4 pt is 0.035 µm.
        assert.ok(Math.abs(r.got[end][axis] - r.want[end][axis]) < 1e-4, `${name}: bounds.${end}[${axis}] ${r.got[end][axis]} pt, Chromium draws it at ${r.want[end][axis]} pt`);
      }
    }
  }
  await page.close();
});

test('opened as a file: a 5 × 3 rect in a ×10 nested viewport measures 160 mm', async () => {
  const page = await openApp(panel);
  await openSvgFiles(page, [['nested.svg', root(CASES['viewBox scaled ×10'] + '<rect id="r" x="10" y="10" width="40" height="40"/>')]]);
  await waitReady(page);
  const rows = await measureRows(page);
  assert.deepEqual(rows.map((r) => r.name), ['inner', 'r']);
  assert.equal(rows[0].perimeter, `${(2 * (50 + 30)).toFixed(2)} mm`);
  await page.close();
});
