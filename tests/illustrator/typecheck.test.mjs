// tsc --checkJs over every .jsx against Adobe's Illustrator DOM typings (types-for-adobe 2022 +
// illustrator-scripts/types/illustrator-extras.d.ts), so every DOM member the scripts use exists.
// tsc reads .jsx as React JSX, so the files are copied as .js into a temporary folder whose
// tsconfig extends illustrator-scripts/tsconfig.json. A negative control proves the check bites.
import test from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { SCRIPTS_DIR } from './jsx-host.mjs';

const tsc = createRequire(import.meta.url).resolve('typescript/bin/tsc');

function check(files) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'dformer-tsc-'));
  for (const [name, text] of Object.entries(files)) fs.writeFileSync(path.join(dir, name), text);
  fs.writeFileSync(path.join(dir, 'tsconfig.json'), JSON.stringify({ extends: path.join(SCRIPTS_DIR, 'tsconfig.json'), include: ['*.js'] }));
  const r = spawnSync(process.execPath, [tsc, '-p', path.join(dir, 'tsconfig.json')], { encoding: 'utf8' });
  fs.rmSync(dir, { recursive: true, force: true });
  return { code: r.status, out: (r.stdout + r.stderr).trim() };
}

test('every .jsx type-checks against the Illustrator DOM typings', () => {
  const files = {};
  for (const f of fs.readdirSync(SCRIPTS_DIR).filter((n) => n.endsWith('.jsx'))) {
    files[f.replace(/[^A-Za-z0-9-]+/g, '_').replace(/_jsx$/, '.js')] = fs.readFileSync(path.join(SCRIPTS_DIR, f), 'utf8');
  }
  assert.ok(Object.keys(files).length >= 3);
  const r = check(files);
  assert.equal(r.code, 0, `tsc reported:\n${r.out}`);
});

test('the type check rejects DOM members that do not exist and ES5 library calls', () => {
  const probes = {
    'var d = app.activeDocument; d.pathItems.add().noSuchMember = 1;': /Property 'noSuchMember' does not exist on type 'PathItem'/,
    'app.activeDocument.layers.add().pathItems.addEllipse();': /Property 'addEllipse' does not exist/,
    '[1, 2].forEach(function (x) { return x; });': /Property 'forEach' does not exist/,
    'var s = " a ".trim();': /Property 'trim' does not exist/,
    'var j = JSON.stringify(1);': /Cannot find name 'JSON'/,
  };
  // One tsc run over one file per probe (tsc is slow to start); each probe must produce its own error.
  const files = Object.fromEntries(Object.keys(probes).map((code, i) => [`probe${i}.js`, code]));
  const r = check(files);
  assert.notEqual(r.code, 0, 'the probes should fail the type check');
  Object.entries(probes).forEach(([code, pattern], i) => {
    const mine = r.out.split('\n').filter((line) => line.includes(`probe${i}.js`)).join('\n');
    assert.match(mine, pattern, `${code}: wanted ${pattern}, got:\n${mine}`);
  });
});
