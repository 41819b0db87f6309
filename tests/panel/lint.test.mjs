// The panel's scripts must parse in CEP 8's Chromium 57: classic scripts (no ES modules), ES2017
// syntax at most (no object spread, optional chaining, ??, …), no undeclared globals. The
// wasm-bindgen glue is held to the same rule, since CEP loads it as-is.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { ESLint } from 'eslint';
import globals from 'globals';
import { panelDir } from './support.mjs';

const config = {
  languageOptions: {
    ecmaVersion: 2017,
    sourceType: 'script',
    globals: { ...globals.browser },
  },
  rules: { 'no-undef': 'error', 'no-unused-vars': ['error', { args: 'none' }], 'no-redeclare': 'error', strict: 'off' },
};

async function lint(files) {
  const eslint = new ESLint({ overrideConfigFile: true, overrideConfig: config, cwd: panelDir });
  const results = await eslint.lintFiles(files);
  return results.flatMap((r) => r.messages.map((m) => `${r.filePath}:${m.line}:${m.column} ${m.message}`));
}

test('panel scripts are ES2017 classic scripts with no undeclared globals', async () => {
  const files = [
    ...readdirSync(join(panelDir, 'src')).filter((f) => f.endsWith('.js')).map((f) => join(panelDir, 'src', f)),
    join(panelDir, 'samples', 'samples.js'),
  ];
  assert.ok(files.length >= 10, `found ${files.length} panel scripts`);
  const problems = await lint(files);
  assert.deepEqual(problems, [], problems.join('\n'));
});

test('the wasm-bindgen glue parses as an ES2017 classic script (CEP 8 / Chromium 57)', async (t) => {
  const glue = join(panelDir, 'wasm', 'dformer.js');
  if (!existsSync(glue)) return t.skip('run `node uxp-panel/build.mjs --dev` first');
  const eslint = new ESLint({ overrideConfigFile: true, overrideConfig: { languageOptions: config.languageOptions, rules: {} }, cwd: panelDir });
  const [r] = await eslint.lintFiles([glue]);
  const fatal = r.messages.filter((m) => m.fatal).map((m) => `${m.line}:${m.column} ${m.message}`);
  assert.deepEqual(fatal, [], `wasm/dformer.js does not parse as ES2017: ${fatal.join('; ')}`);
});
