// The panel's CEP host (uxp-panel/src/csinterface.js + host-cep.js) in a CEP stand-in without a
// browser: a fake `window.__adobe_cep__` whose evalScript runs the real bridge in the simulated
// Illustrator DOM (tests/illustrator/jsx-host.mjs), answers asynchronously on a fake clock, and can
// lose callbacks, forget the bridge, mangle non-ASCII text and send CSXS events. Issue 11, items 1,
// 7, 8 and 11; each test failed on the host before the fix.
import test from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import vm from 'node:vm';
import { BRIDGE, createHost } from '../illustrator/jsx-host.mjs';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');

/** setTimeout/setInterval on a clock that moves only when the test says so. */
function fakeClock() {
  let now = 0, seq = 0;
  const timers = new Map();
  const add = (fn, ms, every) => { const id = ++seq; timers.set(id, { at: now + Math.max(0, Number(ms) || 0), fn, every }); return id; };
  const settle = async () => { for (let i = 0; i < 3; i++) await new Promise((r) => setImmediate(r)); };
  return {
    setTimeout: (fn, ms) => add(fn, ms, 0),
    setInterval: (fn, ms) => add(fn, ms, Math.max(1, Number(ms) || 0)),
    clearTimeout: (id) => timers.delete(id),
    clearInterval: (id) => timers.delete(id),
    async advance(ms) {
      const end = now + ms;
      for (;;) {
        await settle();
        let next = null;
        for (const [id, t] of timers) if (t.at <= end && (!next || t.at < next[1].at)) next = [id, t];
        if (!next) break;
        const [id, t] = next;
        now = t.at;
        if (t.every) t.at += t.every; else timers.delete(id);
        t.fn();
      }
      now = end;
      await settle();
    },
  };
}

/** An installed extension folder (with an accent and a space, as user folders have) holding the bridge. */
function extensionFolder() {
  const dir = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'dformer-ext-')), 'Extensions D\u00e9cor', 'com.dformer.panel');
  fs.mkdirSync(path.join(dir, 'jsx'), { recursive: true });
  fs.copyFileSync(BRIDGE, path.join(dir, 'jsx', 'dformer-bridge.jsx'));
  return dir;
}

/**
 * The panel's host over a CEP stand-in. `hostOptions` go to createHost (the simulated document).
 * Returns { host: the panel's CEP host, jsx: the simulated Illustrator, clock, sent: scripts sent,
 * selections: what the panel was told, emit(type, data), drop(n): lose the next n callbacks }.
 */
function panelHost(hostOptions, { timeoutMs = 2000, applyTimeoutMs = 120000, extension = extensionFolder() } = {}) {
  const jsx = createHost(hostOptions);
  const clock = fakeClock();
  const listeners = {};
  const sent = [];
  let dropping = 0;
  let dropWhen = () => false;
  const native = {
    evalScript(script, callback) {
      sent.push(String(script));
      const answer = jsx.evalScript(script);
      if (dropping > 0 || dropWhen(String(script))) { dropping = Math.max(0, dropping - 1); return; } // Illustrator ran it, the callback never comes
      clock.setTimeout(() => callback(answer), 5);
    },
    getHostEnvironment: () => JSON.stringify({ appName: 'ILST', appVersion: '28.0.0', appSkinInfo: { panelBackgroundColor: { color: { red: 50, green: 50, blue: 50 } } } }),
    addEventListener: (type, fn) => { (listeners[type] = listeners[type] || []).push(fn); },
    getSystemPath: (type) => (type === 'extension' ? `file://${encodeURI(extension)}` : ''),
  };
  const context = { console, setTimeout: clock.setTimeout, setInterval: clock.setInterval, clearTimeout: clock.clearTimeout,
    clearInterval: clock.clearInterval, localStorage: { getItem: () => null, setItem: () => {} }, __adobe_cep__: native };
  context.window = context;
  vm.createContext(context);
  for (const f of ['units.js', 'settings.js', 'csinterface.js', 'host-cep.js']) {
    const file = path.join(repo, 'uxp-panel', 'src', f);
    vm.runInContext(fs.readFileSync(file, 'utf8'), context, { filename: file });
  }
  const DF = context.DF;
  const host = DF.createCepHost(new DF.CSInterface(native), { pollMs: 400, timeoutMs, applyTimeoutMs });
  const selections = [];
  const emit = (type, data) => { for (const fn of listeners[type] || []) fn(JSON.stringify({ type, data })); };
  return { host, jsx, clock, sent, selections, emit, drop: (n) => { dropping = n; }, dropWhen: (f) => { dropWhen = f; }, DF,
    start: () => host.start({ selection: (s) => selections.push(s), theme: () => {} }) };
}
const keyPolls = (p) => p.sent.filter((s) => s === 'dformer_selectionKey()').length;
const TWO = { units: 'mm', shapes: [
  { name: 'A', ellipse: { top: 100, left: 0, width: 80, height: 50 } },
  { name: 'B', rect: { top: 100, left: 200, width: 40, height: 60 } },
] };

test('test_issue_11_poll_while_hidden_or_without_document: no polling while the panel is closed or no document is open; it resumes on show and on a new document', async () => {
  const p = panelHost(TWO);
  p.start();
  await p.clock.advance(2000);
  assert.ok(keyPolls(p) >= 5, `shown: wanted a poll every 400 ms, got ${keyPolls(p)} in 2 s`);
  assert.equal(p.selections.at(-1).pieces.length, 2);

  p.emit('com.adobe.csxs.events.panelWindowStatusChanged', 'false');
  await p.clock.advance(10);
  let before = p.sent.length;
  await p.clock.advance(4000);
  assert.equal(p.sent.length - before, 0, `hidden: wanted no evalScript in 4 s, got ${p.sent.slice(before).join(' | ')}`);
  assert.equal(p.host.polling(), false);

  p.jsx.find('A').translate(5, 0); // the student works while the panel is collapsed
  p.emit('com.adobe.csxs.events.panelWindowStatusChanged', 'true');
  await p.clock.advance(100);
  assert.equal(p.host.polling(), true, 'shown again: polling resumes');
  const seen = p.selections.at(-1).pieces.find((x) => x.name === 'A').path.points[0].anchor;
  assert.equal(JSON.stringify(seen), JSON.stringify(p.jsx.find('A').pathPoints[0].anchor), 'and the panel sees the change at once');

  // The student closes the last document: one poll notices, then the panel stops asking.
  const docs = p.jsx.sim.documents.splice(0);
  p.emit('documentAfterDeactivate', '');
  await p.clock.advance(1000);
  assert.equal(p.host.polling(), false, 'no document: polling stops');
  assert.match(p.selections.at(-1).error, /No document is open/);
  before = p.sent.length;
  await p.clock.advance(4000);
  assert.equal(p.sent.length - before, 0, `no document: wanted no evalScript in 4 s, got ${p.sent.length - before}`);
  p.jsx.sim.documents.push(...docs);
  p.emit('documentAfterActivate', '');
  await p.clock.advance(500);
  assert.equal(p.host.polling(), true, 'a document opens: polling resumes');
  assert.equal(p.selections.at(-1).pieces.length, 2);
});

test('test_issue_11_select_all_panel_state: beyond two paths the panel says to select two, and gets no geometry', async () => {
  const shapes = Array.from({ length: 50 }, (_, i) => ({ name: `p${i}`, rect: { top: 10 * i, left: 0, width: 5, height: 5 } }));
  const p = panelHost({ shapes });
  p.start();
  await p.clock.advance(500);
  const sel = p.selections.at(-1);
  assert.equal(sel.ok, false);
  assert.equal(sel.pieces.length, 0);
  assert.match(sel.error, /More than two paths \(or more than 500 objects\) are selected: select exactly two closed paths/);
});

test('test_issue_11_lost_callback: a lost evalScript callback does not stop polling and Apply for good', async () => {
  const p = panelHost(TWO, { timeoutMs: 2000 });
  p.start();
  await p.clock.advance(1000);
  p.drop(1);
  await p.clock.advance(400);
  const stuckAt = keyPolls(p);
  await p.clock.advance(3000);
  assert.ok(keyPolls(p) > stuckAt + 1, `after a lost callback: wanted polls to resume after the 2 s timeout, got ${keyPolls(p) - stuckAt} more`);
  p.jsx.find('B').translate(0, 7);
  await p.clock.advance(1000);
  const b = p.selections.at(-1).pieces.find((x) => x.name === 'B');
  assert.equal(JSON.stringify(b.path.points[0].anchor), JSON.stringify(p.jsx.find('B').pathPoints[0].anchor), 'changes are seen again');
  // The full read after a change loses its answer: the panel reads again on a later poll.
  let lose = 1;
  p.dropWhen((s) => s === 'dformer_selection()' && lose-- > 0);
  p.jsx.find('A').translate(0, 9);
  await p.clock.advance(4000);
  const a = p.selections.at(-1).pieces.find((x) => x.name === 'A');
  assert.ok(a, `after a lost selection read the panel reads again (last: ${JSON.stringify(p.selections.at(-1)).slice(0, 120)})`);
  assert.equal(JSON.stringify(a.path.points[0].anchor), JSON.stringify(p.jsx.find('A').pathPoints[0].anchor));
  // Apply whose answer never comes: a clear message after the Apply timeout, not a panel stuck forever.
  const q = panelHost(TWO, { applyTimeoutMs: 3000 });
  q.drop(Infinity);
  const pending = q.host.apply({ document: 'Untitled-1.ai', updates: [], pieces: [], labelSize: 6, layers: { cut: { name: 'Cut', color: '#ff0000', width: 0.072 }, score: { name: 'Score', color: '#0000ff', width: 0.072 }, engrave: { name: 'Engrave', color: '#000000', width: 0.072 } } });
  await q.clock.advance(3500);
  const r = await pending;
  assert.equal(r.ok, false);
  assert.match(r.error, /has not answered Apply for 3 s\. It may still be writing: check the document/);
});

test('test_issue_11_bridge_lost_reload: when the ExtendScript engine lost the bridge the panel reloads it with $.evalFile instead of saying "reinstall"', async () => {
  const extension = extensionFolder();
  const p = panelHost(TWO, { extension });
  p.start();
  await p.clock.advance(500);
  p.jsx.loseBridge();
  assert.equal(p.jsx.evalScript('dformer_selectionKey()'), 'EvalScript error.', 'the stand-in really lost it');
  p.jsx.find('A').translate(3, 3);
  await p.clock.advance(1000);
  assert.deepEqual(p.jsx.evalFiles, [path.join(extension, 'jsx', 'dformer-bridge.jsx')], 'reloaded from the extension folder (accented path intact)');
  const last = p.selections.at(-1);
  assert.equal(last.ok, true, last.error);
  assert.equal(JSON.stringify(last.pieces.find((x) => x.name === 'A').path.points[0].anchor), JSON.stringify(p.jsx.find('A').pathPoints[0].anchor));
  // The file is gone too: now the message says to reinstall, naming the file.
  const q = panelHost(TWO, { extension: path.join(os.tmpdir(), 'no-such-dformer-extension') });
  q.jsx.loseBridge();
  q.start();
  await q.clock.advance(500);
  assert.match(q.selections.at(-1).error, /lost the D-former script bridge and reloading .*no-such-dformer-extension\/jsx\/dformer-bridge\.jsx failed: reinstall the extension/);
});

const LAYERS = { cut: { name: 'D\u00e9coupe', color: '#ff0000', width: 0.072 }, score: { name: 'Rainure', color: '#0000ff', width: 0.072 }, engrave: { name: 'Gravure', color: '#000000', width: 0.072 } };

test('test_issue_11_accented_names_round_trip: "D\u00e9coupe.ai" and its layers survive evalScript both ways, whatever the text encoding', async () => {
  const p = panelHost({ ...TWO, document: 'D\u00e9coupe.ai', transport: 'legacy' });
  p.start();
  await p.clock.advance(500);
  const sel = p.selections.at(-1);
  assert.equal(sel.document, 'D\u00e9coupe.ai');
  const a = sel.pieces.find((x) => x.name === 'A');
  const pending = p.host.apply({ document: sel.document, updates: [], labelSize: 6, layers: LAYERS,
    pieces: [{ id: a.id, name: 'pi\u00e8ce A', holes: [], marks: [{ closed: false, points: [{ anchor: [0, 0] }, { anchor: [0, 5] }] }], labels: [{ text: '\u00e9t\u00e9 \u2013 1', at: [10, 10] }] }] });
  await p.clock.advance(100);
  const r = await pending;
  assert.equal(r.ok, true, r.error);
  const names = p.jsx.doc._layers.map((l) => l.name).sort();
  assert.deepEqual(names, ['Gravure', 'Layer 1', 'Rainure'], `layers: ${names}`);
  const label = p.jsx.doc.layers.getByName('Gravure').groupItems.getByName('D-former pi\u00e8ce A labels').textFrames[0];
  assert.equal(label.contents, '\u00e9t\u00e9 \u2013 1');
  assert.ok(p.sent.every((s) => /^[\x20-\x7e]*$/.test(s)), 'every script sent is plain ASCII');
});

test('test_issue_11_large_payload: Apply is sent as an ES3 object literal that ExtendScript parses natively; awkward text survives', async () => {
  const p = panelHost(TWO);
  p.start();
  await p.clock.advance(500);
  const sel = p.selections.at(-1);
  const a = sel.pieces.find((x) => x.name === 'A');
  let parsed = 0;
  const parse = p.jsx.context.dformer_parse;
  p.jsx.context.dformer_parse = (t) => { parsed++; return parse(t); };
  const n = 10000;
  const holes = Array.from({ length: n }, (_, i) => ({ closed: true, points: [[i, 0], [i + 0.5, 0.5], [i, 1]].map((q) => ({ anchor: q, left: q, right: q })) }));
  const awkward = 'quote " backslash \\ slash / tab \t nl \n \u2028\u2029 </script> \u00e9 \ud83d\ude00';
  const pending = p.host.apply({ document: sel.document, updates: [], labelSize: 6, layers: LAYERS,
    pieces: [{ id: a.id, name: 'piece A', holes, marks: [], labels: [{ text: awkward, at: [0, 0] }] }] });
  await p.clock.advance(100);
  const r = await pending;
  assert.equal(r.ok, true, r.error);
  assert.equal(parsed, 0, 'the bridge\'s ES3 JSON reader is not used for the request');
  const script = p.sent.find((s) => s.startsWith('dformer_apply('));
  assert.match(script, /^dformer_apply\(\{"document":/, 'an object literal, not a JSON string');
  assert.match(script, /^[\x20-\x7e]*$/, 'plain ASCII');
  const group = p.jsx.doc.layers.getByName('D\u00e9coupe').groupItems.getByName('D-former piece A connectors');
  assert.equal(group.pathItems.length, n, `holes written: wanted ${n}, got ${group.pathItems.length}`);
  assert.equal(p.jsx.doc.layers.getByName('Gravure').groupItems[0].textFrames[0].contents, awkward);
});
