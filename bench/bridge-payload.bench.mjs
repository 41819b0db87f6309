// Benchmark (not a test): how a 10,000-connector Apply request reaches the bridge (issue 11, item 11).
// Before: a JSON string parsed by the bridge's ES3 reader one character at a time (dformer_parse);
// now: an ES3 object literal (strict-ASCII JSON text) that the script engine parses natively.
// Both run here in Node's V8 (the simulated DOM, tests/illustrator/jsx-host.mjs), so the figures are a
// lower bound for ExtendScript, whose interpreter runs such a loop far slower than V8's JIT; the ratio
// is what to read. The baseline (native parse of the same text) runs in the same process.
//   node bench/bridge-payload.bench.mjs
import { performance } from 'node:perf_hooks';
import vm from 'node:vm';
import { createHost } from '../tests/illustrator/jsx-host.mjs';

const N = 10000;
const circle = (x, y, r) => {
  const k = 0.5523 * r;
  return { closed: true, points: [
    { anchor: [x + r, y], left: [x + r, y - k], right: [x + r, y + k] },
    { anchor: [x, y + r], left: [x + k, y + r], right: [x - k, y + r] },
    { anchor: [x - r, y], left: [x - r, y + k], right: [x - r, y - k] },
    { anchor: [x, y - r], left: [x - k, y - r], right: [x + k, y - r] },
  ] };
};
const piece = (name, dx) => ({
  name,
  holes: Array.from({ length: N }, (_, i) => circle(dx + Math.cos(i / 1591.5) * 1000.123456789, Math.sin(i / 1591.5) * 1000.987654321, 2.834645669291339)),
  labels: Array.from({ length: N }, (_, i) => ({ text: String(i + 1), at: [dx + i * 0.731, i * 0.377], angle: (i * 7.3) % 360 })),
  marks: [],
});
const payload = { document: 'D\u00e9coupe.ai', updates: [], pieces: [piece('piece A', 0), piece('piece B', 3000)], labelSize: 6 };
const json = JSON.stringify(payload);
const literal = json.replace(/[^\x20-\x7e]/g, (c) => `\\u${c.charCodeAt(0).toString(16).padStart(4, '0')}`);

const h = createHost();
const script = new vm.Script(`(${literal})`);
const median = (xs) => xs.slice().sort((a, b) => a - b)[xs.length >> 1];
function time(f, rounds = 3) {
  f();
  const ms = [];
  for (let r = 0; r < rounds; r++) {
    const t0 = performance.now();
    f();
    ms.push(performance.now() - t0);
  }
  return median(ms);
}

const es3 = time(() => h.context.dformer_parse(json));
const native = time(() => script.runInContext(h.context));
const nativeJson = time(() => JSON.parse(json));
const mb = (json.length / 1e6).toFixed(1);
console.log(`request: 2 pieces x ${N} holes + ${N} labels, ${mb} MB of JSON text`);
console.log(`  before: JSON string through the bridge's ES3 reader (dformer_parse): ${es3.toFixed(1)} ms`);
console.log(`  now:    ES3 object literal, parsed natively by the script engine:   ${native.toFixed(1)} ms  (x${(es3 / native).toFixed(1)} faster)`);
console.log(`  baseline: the platform's JSON.parse of the same text:              ${nativeJson.toFixed(1)} ms`);
console.log('  (V8 figures; ExtendScript interprets the ES3 loop, so the "before" cost there is much higher.)');
