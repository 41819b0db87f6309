// The main job on the bundled sample shapes: two different outlines are normalized to one
// perimeter, given paired stitching holes, and written as a laser-ready SVG.
//
//   node scripts/demo.mjs [out.svg]        (scripts/demo.sh builds the core first)
import { createRequire } from 'node:module';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { laserSvg } from '../uxp-panel/src/laser-svg.js';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const core = createRequire(import.meta.url)(join(root, 'core/pkg/dformer.js'));
const out = resolve(process.argv[2] ?? join(root, 'out/demo.svg'));

const samples = ['pebble.json', 'ellipse.json'].map((f) => JSON.parse(readFileSync(join(root, 'samples', f), 'utf8')));
const units = samples[0].units;
const fmt = (v) => `${v.toFixed(3)} ${units}`;

console.log('Bundled samples:');
for (const s of samples) console.log(`  ${s.name.padEnd(28)} perimeter ${fmt(core.measure(s.path).perimeter)}`);

// Both pieces get the mean of the two perimeters, each scaled about its own bounding-box centre.
const norm = core.normalize(samples.map((s) => s.path), { target: 'mean', pivot: 'center' });
console.log(`\nNormalized to ${fmt(norm.perimeter)} (scales ${norm.scales.map((k) => k.toFixed(6)).join(', ')}):`);
norm.paths.forEach((p, i) => console.log(`  ${samples[i].name.padEnd(28)} perimeter ${fmt(core.measure(p).perimeter)}`));

// Stitching holes about every 12 mm, 2.5 mm across, 4 mm in from the edge.
const res = core.connect(norm.paths, { kind: 'stitch', pitch: 12, inset: 4, diameter: 2.5 });
console.log(`\nStitching: ${res.count} paired holes per piece, pitch ${fmt(res.pitch)}`);
for (const w of res.warnings) console.log(`  warning: ${w}`);

const svg = laserSvg({
  pieces: res.pieces.map((p, i) => ({ ...p, name: `${String.fromCharCode(65 + i)}: ${samples[i].name}` })),
  pathToSvg: core.pathToSvg,
  units,
});
mkdirSync(dirname(out), { recursive: true });
writeFileSync(out, svg);
console.log(`\nWrote ${out} (cut: red, score: blue, engrave: black). Open it in a browser, Inkscape or Illustrator.`);
