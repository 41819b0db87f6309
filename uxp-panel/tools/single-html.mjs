// One self-contained HTML file from the built browser app (dist/d-former-web/): every
// <link rel="stylesheet" href> becomes a <style> and every <script src> an inline <script>, so the
// page (WASM bytes included, they are already base64 in wasm/dformer-wasm-inline.js) opens by
// double-click from any folder with nothing beside it. A page opened from file:// may not start a
// worker from a file but may from a Blob: the solver worker's text (the core's glue, sweep-point.js
// and src/solver-worker.js) is carried in a <script type="text/plain" id="dformer-worker-source">,
// from which solver.js starts it, posting it the WASM bytes the page already has. So the 3D form is
// solved off the page's thread there too: the page stays live, shows progress, and a solve the
// slider has moved on from can be stopped (app.js).
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';

/** Text that may sit inside a <script> or <style> element: an end tag, or an HTML comment opener
 * in a script, would end or change the element early (HTML's "script data" states). */
function raw(text, tag) {
  const end = new RegExp(`</(${tag})`, 'gi');
  let out = text.replace(end, '<\\/$1');
  if (tag === 'script') out = out.replace(/<!--/g, '<\\!--');
  return out;
}

/** Returns the single-file page for the app folder `dir` (its index.html and the files it names),
 * stamped with the project version (`<meta name="generator">`; the footer shows the core's own). */
export function singleHtml(dir, version) {
  const html = readFileSync(join(dir, 'index.html'), 'utf8');
  const read = (href) => {
    const file = join(dir, href);
    if (!existsSync(file)) throw new Error(`single-html: ${href} named by index.html is missing from ${dir}`);
    return readFileSync(file, 'utf8');
  };
  let out = html
    .replace('<meta charset="utf-8">', `<meta charset="utf-8">\n<meta name="generator" content="D-former ${version}">`)
    .replace(/<link rel="stylesheet" href="([^"]+)">/g, (_, href) => `<style>/* ${href} */\n${raw(read(href), 'style')}</style>`)
    .replace(/<script src="([^"]+)"><\/script>/g, (_, src) => `<script>/* ${src} */\n${raw(read(src), 'script')}</script>`);
  const worker = ['self.DFORMER_WASM_FROM_PAGE = true;', read('wasm/dformer.js'), read('src/sweep-point.js'), read('src/solver-worker.js')].join('\n');
  out = out.replace('</body>', `<script type="text/plain" id="dformer-worker-source">\n${raw(worker, 'script')}</script>\n</body>`);
  const left = /<(?:script|link|img)\b[^>]*\b(?:src|href)="(?!data:|#)[^"]+"/i.exec(out);
  if (left) throw new Error(`single-html: a reference is left that would need a file beside the page: ${left[0]}`);
  return out;
}
