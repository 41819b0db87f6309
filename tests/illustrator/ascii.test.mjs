// Every ExtendScript file is plain ASCII (issue 11, item 7): ExtendScript decodes a .jsx without a
// BOM in the system's legacy encoding on some set-ups (hyperbrew/bolt-cep issue 137, "strings from
// CEP encoded in macroman"; issue 159), so a raw ellipsis or an accent in a message becomes mojibake.
// Characters outside ASCII are written as \uXXXX escapes instead. A negative control keeps the check honest.
import test from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { SCRIPTS_DIR } from './jsx-host.mjs';

/** [line, column, code point] of every byte outside printable ASCII (tab, CR, LF allowed). */
function nonAscii(buf) {
  const out = [];
  let line = 1, col = 1;
  for (const b of buf) {
    if (b === 0x0a) { line++; col = 1; continue; }
    if (b > 0x7e || (b < 0x20 && b !== 0x09 && b !== 0x0d)) out.push(`${line}:${col} byte 0x${b.toString(16)}`);
    col++;
  }
  return out;
}

test('every .jsx in illustrator-scripts/ is ASCII-only (no BOM, no raw non-ASCII text)', () => {
  const files = fs.readdirSync(SCRIPTS_DIR).filter((f) => f.endsWith('.jsx'));
  assert.ok(files.length >= 3, `expected the bridge and two standalone scripts, found ${files}`);
  for (const f of files) {
    const bad = nonAscii(fs.readFileSync(path.join(SCRIPTS_DIR, f)));
    assert.deepEqual(bad, [], `${f}: wanted ASCII only, got ${bad.slice(0, 5).join(', ')}`);
  }
});

test('the ASCII check flags a raw ellipsis, an accent and a BOM (negative control)', () => {
  assert.deepEqual(nonAscii(Buffer.from('var a = "ok";\n')), []);
  assert.equal(nonAscii(Buffer.from('alert("wait\u2026");')).length, 3, 'U+2026 is 3 UTF-8 bytes');
  assert.equal(nonAscii(Buffer.from('// D\u00e9coupe')).length, 2);
  assert.equal(nonAscii(Buffer.from('\ufeffvar x;')).length, 3, 'a UTF-8 BOM');
});
