// Every .jsx parses as an ES3 script under ESLint (illustrator-scripts/eslint.config.js), and the
// config really rejects ES5+ syntax and library calls (negative controls), so this test can fail.
import test from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { ESLint } from 'eslint';
import { SCRIPTS_DIR } from './jsx-host.mjs';

const eslint = new ESLint({ cwd: SCRIPTS_DIR, overrideConfigFile: path.join(SCRIPTS_DIR, 'eslint.config.js') });
const jsx = fs.readdirSync(SCRIPTS_DIR).filter((f) => f.endsWith('.jsx'));

test('every .jsx in illustrator-scripts/ is clean ES3', async () => {
  assert.ok(jsx.length >= 3, `expected the bridge and two standalone scripts, found ${jsx}`);
  const results = await eslint.lintFiles(jsx);
  const problems = results.flatMap((r) => r.messages.map((m) => `${path.basename(r.filePath)}:${m.line}:${m.column} ${m.message}`));
  assert.deepEqual(problems, [], problems.join('\n'));
  assert.equal(results.length, jsx.length, 'every file was linted (none ignored)');
});

test('the ES3 config rejects ES5+ syntax and library members', async () => {
  const bad = {
    'let x = 1;': /Parsing error/,
    'var f = () => 1;': /Parsing error/,
    'var o = { a: 1, };': /Parsing error/,
    'var o = { get a() { return 1; } };': /Parsing error/,
    '[1].forEach(function () {});': /forEach is ES5\+/,
    'var s = " a ".trim();': /trim is ES5\+/,
    'var j = JSON.stringify({});': /no JSON object/,
    'undeclared = 1;': /'undeclared' is not defined/,
  };
  for (const [code, pattern] of Object.entries(bad)) {
    const [r] = await eslint.lintText(code, { filePath: path.join(SCRIPTS_DIR, 'probe.jsx') });
    assert.ok(r.messages.some((m) => pattern.test(m.message)), `${code} should be rejected with ${pattern}, got ${JSON.stringify(r.messages.map((m) => m.message))}`);
  }
});
