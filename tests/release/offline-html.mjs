// The browser app as one file (dist/release/d-former-VERSION.html): copied alone into an empty
// folder and opened from disk (file://) in headless Chromium, as a double-click would. It must load
// the core with no other file and no network (every request other than the page itself is
// refused and counted), load a sample, design, and download a laser SVG, which is then read by
// Chromium's own SVG engine in a blank page (none of the app's code): two pieces with equal
// perimeters (getTotalLength), 16 holes each, every hole centre inside its piece (isPointInFill);
// then its 3D form, solved on a worker (single-html.mjs says how a page on disk starts one).
// Not named *.test.mjs: `node --test tests/` runs before the packages exist; tests/release/run.sh
// runs it after `scripts/package.sh`.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { copyFileSync, existsSync, mkdtempSync, readFileSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

const repo = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const version = /\[workspace\.package\][^[]*?\nversion = "([^"]+)"/.exec(readFileSync(join(repo, 'Cargo.toml'), 'utf8'))[1];
const built = join(repo, 'dist', 'release', `d-former-${version}.html`);

test('d-former.html alone on disk: loads offline, designs a sample, downloads a laser SVG', async () => {
  assert.ok(existsSync(built), `${built} is missing: run \`bash scripts/package.sh\` first`);
  const dir = mkdtempSync(join(tmpdir(), 'dformer-html-'));
  const page0 = join(dir, `d-former-${version}.html`);
  copyFileSync(built, page0);
  assert.deepEqual(readdirSync(dir), [`d-former-${version}.html`], 'nothing beside the page');
  const browser = await chromium.launch({
    executablePath: '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update'],
  });
  try {
    const context = await browser.newContext({ acceptDownloads: true, viewport: { width: 1100, height: 720 } });
    const url = pathToFileURL(page0).href;
    const requests = [];
    await context.route('**/*', (route) => {
      const u = route.request().url();
      if (u === url || u.startsWith('data:') || u.startsWith('blob:')) return route.continue();
      requests.push(u);
      return route.abort();
    });
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(url);
    await page.waitForFunction(() => document.body.dataset.core === 'loaded' || document.body.dataset.core === 'error', null, { timeout: 30000 });
    assert.equal(await page.evaluate(() => document.body.dataset.core), 'loaded', await page.textContent('#status'));
    assert.equal(await page.textContent('#version'), `D-former ${version}`, 'the footer shows the core version');
    await page.selectOption('#sample-select', 'pebble-circle');
    await page.waitForFunction(() => document.body.dataset.state === 'ready' || document.body.dataset.state === 'error', null, { timeout: 30000 });
    assert.equal(await page.evaluate(() => document.body.dataset.state), 'ready', await page.textContent('#message'));
    await page.fill('#count', '16');
    await page.waitForFunction(() => /^16 connectors/.test(document.querySelector('#stats').textContent));
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#apply-btn')]);
    const svgText = readFileSync(await download.path(), 'utf8');
    assert.match(svgText, /^<\?xml/, 'an SVG file');

    const blank = await context.newPage();
    const svg = await blank.evaluate((text) => {
      document.body.innerHTML = text.replace(/^<\?xml[^>]*>/, '');
      const root = document.querySelector('svg');
      return {
        width: root.getAttribute('width'),
        pieces: [...root.querySelector('#layer-cut').children].map((g) => {
          const outline = g.querySelector('path.outline');
          const holes = [...g.querySelectorAll('path.hole')].map((h) => {
            const b = h.getBBox();
            return outline.isPointInFill(new DOMPoint(b.x + b.width / 2, b.y + b.height / 2));
          });
          return { perimeter: outline.getTotalLength(), holes };
        }),
      };
    }, svgText);
    assert.match(svg.width, /mm$/, `width in mm, got ${svg.width}`);
    assert.equal(svg.pieces.length, 2, 'two pieces');
    const [a, b] = svg.pieces;
    console.log(`offline page: perimeters ${a.perimeter.toFixed(4)} and ${b.perimeter.toFixed(4)} (Chromium getTotalLength), holes ${a.holes.length} and ${b.holes.length}`);
    assert.ok(Math.abs(a.perimeter - b.perimeter) < 1e-3 * a.perimeter, `equal perimeters wanted, got ${a.perimeter} and ${b.perimeter}`);
    for (const p of svg.pieces) {
      assert.equal(p.holes.length, 16, `wanted 16 holes, got ${p.holes.length}`);
      assert.ok(p.holes.every(Boolean), 'every hole centre inside its piece');
    }

    // The 3D form, solved on a worker started from the page's own text of it (a page opened from
    // file:// may not start one from a file): the same form as the core on the page gives.
    await page.click('.tabs button[data-view="3d"]');
    await page.waitForFunction(() => document.body.dataset.solve && !document.body.dataset.solving, null, { timeout: 60000 });
    const form = await page.evaluate(() => {
      const d = window.DF.app.design();
      return { solve: document.body.dataset.solve, threaded: window.DF.solver.threaded(), shown: window.DF.app.mesh().stats.volume,
        here: window.DF.core.simulate(d.pieces.map((p) => p.path), { offset: d.offset }).stats.volume };
    });
    console.log(`offline page: 3D form solved on a worker: ${form.threaded}, volume ${form.shown} (on the page: ${form.here})`);
    assert.equal(form.solve, 'ok', await page.textContent('#stats3d'));
    assert.equal(form.threaded, true, 'the 3D form is solved on a worker, not on the page\'s thread');
    assert.ok(Math.abs(form.shown - form.here) <= 1e-9 * Math.abs(form.here), `worker ${form.shown} vs page ${form.here}`);
    assert.deepEqual(requests, [], 'the page asked for files or network beside itself');
    assert.deepEqual(errors, []);
  } finally {
    await browser.close();
    rmSync(dir, { recursive: true, force: true });
  }
});
