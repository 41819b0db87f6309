// The CEP manifest, as written in uxp-panel/CSXS/ and as built into dist/com.dformer.panel/CSXS/,
// is valid against Adobe's ExtensionManifest_v_7_0.xsd (CEP-Resources; the CEP 12 Cookbook says it
// applies unchanged to CEP 8-12). Issue 11, item 10: <MinSize> came before <MaxSize> in <Geometry>,
// which the schema's sequence (ScreenPercentage, Size, MaxSize, MinSize) refuses.
// Validated with lxml's XMLSchema through Debian's /usr/bin/python3 (python3-lxml, installed by
// scripts/setup.sh --all). The schema is read from ../shared/cep/ beside the clone (a read-only copy
// of Adobe's file; in a git worktree, beside the main checkout); DFORMER_SHARED overrides the folder.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
const PYTHON = process.env.DFORMER_PYTHON || '/usr/bin/python3'; // Debian's, where python3-lxml goes

function schemaPath() {
  const roots = [process.env.DFORMER_SHARED ? resolve(process.env.DFORMER_SHARED, '..') : null, resolve(repo, '..')];
  try {
    const common = execFileSync('git', ['rev-parse', '--path-format=absolute', '--git-common-dir'], { cwd: repo, encoding: 'utf8' }).trim();
    roots.push(resolve(dirname(common), '..'));
  } catch { /* not a git checkout: only ../shared */ }
  const tried = roots.filter(Boolean).map((r) => join(r, 'shared', 'cep', 'ExtensionManifest_v_7_0.xsd'));
  return { found: tried.find((f) => existsSync(f)), tried };
}

const VALIDATE = `
import sys
from lxml import etree
schema = etree.XMLSchema(etree.parse(sys.argv[1]))
doc = etree.fromstring(sys.stdin.buffer.read())
if schema.validate(doc):
    print("valid")
else:
    for e in schema.error_log:
        print("line %d: %s" % (e.line, e.message))
`;

/** lxml's verdict on an XML text: "valid", or the schema's errors one per line. */
function validate(xml, xsd) {
  const r = spawnSync(PYTHON, ['-c', VALIDATE, xsd], { input: xml, encoding: 'utf8' });
  assert.equal(r.status, 0, `${PYTHON} with lxml failed (install python3-lxml: bash scripts/setup.sh --all): ${r.stderr}`);
  return r.stdout.trim();
}

const { found: XSD, tried } = schemaPath();
const SOURCE = join(repo, 'uxp-panel', 'CSXS', 'manifest.xml');
const BUILT = join(repo, 'dist', 'com.dformer.panel', 'CSXS', 'manifest.xml');

test('Adobe\'s manifest schema is available beside the clone', () => {
  assert.ok(XSD, `ExtensionManifest_v_7_0.xsd not found; looked in ${tried.join(', ')}`);
});

test('test_issue_11_manifest_schema: the source manifest is valid against ExtensionManifest_v_7_0.xsd', () => {
  assert.equal(validate(readFileSync(SOURCE, 'utf8'), XSD), 'valid');
});

test('the built extension\'s manifest is valid against ExtensionManifest_v_7_0.xsd', (t) => {
  if (!existsSync(BUILT)) return t.skip('run `node uxp-panel/build.mjs` first');
  assert.equal(validate(readFileSync(BUILT, 'utf8'), XSD), 'valid');
});

test('the schema check bites: MinSize before MaxSize, a bad host range and an unknown element are refused', () => {
  const xml = readFileSync(SOURCE, 'utf8');
  const swapped = xml.replace(/(\s*<MaxSize>.*?<\/MaxSize>)(\s*<MinSize>.*?<\/MinSize>)/s, '$2$1');
  assert.notEqual(swapped, xml, 'the negative control must change the manifest');
  assert.match(validate(swapped, XSD), /MinSize.*not expected|MaxSize.*not expected/);
  assert.match(validate(xml.replace(/Version="\[22\.0,99\.9\]"/, 'Version="twenty-two"'), XSD), /RangedVersion|pattern/);
  assert.match(validate(xml.replace('<Type>Panel</Type>', '<Type>Panel</Type><Colour>red</Colour>'), XSD), /Colour/);
});
