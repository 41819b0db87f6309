// Shared helpers for the panel tests: a static HTTP server for uxp-panel/ (port 0), Chromium via
// playwright-core (usePanelBrowser: both for one test file), and the page readiness wait.
import { after, before } from 'node:test';
import assert from 'node:assert/strict';
import { createServer } from 'node:http';
import { existsSync, mkdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

export const repo = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const panelDir = join(repo, 'uxp-panel');
export const artifacts = join(repo, 'test-artifacts');

const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.wasm': 'application/wasm', '.svg': 'image/svg+xml' };

/** Serves `root` on 127.0.0.1 at a free port; resolves to { url, close }. */
export function serve(root = panelDir) {
  const server = createServer((req, res) => {
    const path = normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname)).replace(/^(\.\.[/\\])+/, '');
    let file = join(root, path);
    if (existsSync(file) && statSync(file).isDirectory()) file = join(file, 'index.html');
    if (!file.startsWith(root) || !existsSync(file)) {
      res.writeHead(404);
      res.end('not found');
      return;
    }
    res.writeHead(200, { 'content-type': TYPES[extname(file)] || 'application/octet-stream' });
    res.end(readFileSync(file));
  });
  return new Promise((resolve) => {
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      resolve({ url: `http://127.0.0.1:${port}/`, close: () => new Promise((r) => server.close(r)) });
    });
  });
}

export function launch() {
  return chromium.launch({
    executablePath: '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update'],
  });
}

/** Registers before/after hooks for a test file: checks the panel is built, serves uxp-panel/ and
 * launches Chromium. The returned object holds `browser` and `url` once the `before` hook has run. */
export function usePanelBrowser() {
  const panel = { browser: null, server: null, get url() { return this.server.url; } };
  before(async () => {
    assert.ok(wasmBuilt(), 'uxp-panel/wasm/dformer.js is missing: run `node uxp-panel/build.mjs --dev` first');
    panel.server = await serve();
    panel.browser = await launch();
  });
  after(async () => {
    await panel.browser?.close();
    await panel.server?.close();
  });
  return panel;
}

export function artifactPath(name) {
  mkdirSync(artifacts, { recursive: true });
  return join(artifacts, name);
}

/** Fails fast with the panel's own message when the page reports an error state. */
export async function waitReady(page, what = 'ready') {
  await page.waitForFunction(() => document.body.dataset.core === 'loaded' || document.body.dataset.core === 'error', null, { timeout: 20000 });
  const core = await page.evaluate(() => document.body.dataset.core);
  if (core !== 'loaded') throw new Error(`core failed to load: ${await page.textContent('#status')}`);
  if (what === 'ready') {
    await page.waitForFunction(() => document.body.dataset.state === 'ready' || (document.body.dataset.state === 'error' && document.querySelector('#message').textContent), null, { timeout: 20000 });
  }
}

export function wasmBuilt() {
  return existsSync(join(panelDir, 'wasm', 'dformer.js'));
}

/** A new page of the browser app (downloads allowed), core loaded; `options` go to newPage. */
export async function openApp(panel, options = {}) {
  const page = await panel.browser.newPage({ viewport: { width: 1100, height: 720 }, acceptDownloads: true, ...options });
  await page.goto(panel.url);
  await waitReady(page, 'load');
  return page;
}

/** Opens SVG texts ([[name, text], …]) with *Open SVG…*; waits until the summary or the status names the first. */
export async function openSvgFiles(page, files) {
  await page.setInputFiles('#open-input', files.map(([name, text]) => ({ name, mimeType: 'image/svg+xml', buffer: Buffer.from(text) })));
  await page.waitForFunction((n) => (document.querySelector('#selection-summary').textContent + document.querySelector('#status').textContent).includes(n), files[0][0]);
}

/** The measure table: [{ key, name, perimeter }] (perimeter as shown, e.g. "320.00 mm"). */
export function measureRows(page) {
  return page.$$eval('#measure-table tr:not(.diff)', (trs) => trs.map((tr) => ({
    key: tr.children[0].textContent, name: tr.children[1].textContent, perimeter: tr.children[2].textContent,
  })));
}

/** Clicks Download SVG (#apply-btn) on `page`; the text of the SVG it saved. */
export async function downloadSvg(page) {
  const [file] = await Promise.all([page.waitForEvent('download'), page.click('#apply-btn')]);
  return readFileSync(await file.path(), 'utf8');
}

/**
 * Reads a downloaded SVG back with Chromium's own SVG engine: `svgText` becomes a blank page's
 * body, and `read(mm)` runs there with `mm` the millimetres per user unit of its root `<svg>`.
 */
export async function readSvgBack(panel, svgText, read) {
  const blank = await panel.browser.newPage();
  try {
    const mm = await blank.evaluate((t) => {
      document.body.innerHTML = t.replace(/^<\?xml[^>]*>/, '');
      const svg = document.querySelector('svg');
      return parseFloat(svg.getAttribute('width')) / svg.viewBox.baseVal.width;
    }, svgText);
    return await blank.evaluate(read, mm);
  } finally {
    await blank.close();
  }
}

/**
 * An init script (`page.addInitScript(holdSolves)`) that wraps the page's Worker so that a test
 * can hold a solve: after `window.__holdNext = true` the next solve job (not the sweep's
 * 'figures' jobs) is held, either never posted (`window.__holdMode` 'job', the default: a solve
 * that never ends) or posted with only its progress reports let through ('result': a solve that
 * reports, then runs on). `window.__held` counts the jobs held, `window.__terminated` the workers
 * terminated.
 */
export function holdSolves() {
  const Real = window.Worker;
  window.__held = 0;
  window.__terminated = 0;
  window.__holdNext = false;
  window.__holdMode = 'job';
  window.Worker = class {
    constructor(url) {
      this.real = new Real(url);
      this.heldId = null;
      this.real.onmessage = (e) => {
        if (e.data.id === this.heldId && !e.data.progress) return;
        if (this.onmessage) this.onmessage(e);
      };
      this.real.onerror = (e) => this.onerror && this.onerror(e);
    }
    postMessage(m) {
      if (window.__holdNext && m.op !== 'figures' && m.pieces) {
        window.__holdNext = false;
        window.__held++;
        if (window.__holdMode === 'job') return;
        this.heldId = m.id;
      }
      this.real.postMessage(m);
    }
    terminate() {
      window.__terminated++;
      this.real.terminate();
    }
  };
}
