// Surface Evolver as an independent peer of `simulate` (not a test): the same two flat pieces,
// meshed here with interior vertices, glued along the seam and relaxed by Evolver as
// inextensible elastic sheets with a bending energy (bench/evolver/datafile.mjs says which
// energies and why). Prints Evolver's volume, its max edge strain, whether its mesh
// self-intersects, the volume of `simulate` (called through the contract, WASM) and the ratio;
// for the L with a circle (`crease` in pairs.mjs) also each piece's sharpest bend, both
// solvers', which says whether the crease `simulate` reports is the sheet's own; for the kidney
// with its copy (`touch`) whether each sheet passes through itself, which says whether that
// form needs the sheets to touch.
//
// Run: node bench/evolver.bench.mjs   (scripts/bench.sh installs Evolver and builds the WASM)
// Env: DFORMER_PKG (package path), DFORMER_EVOLVER_SEAM (seam vertices, default 128),
//      DFORMER_EVOLVER_PAIRS (comma-separated pair numbers, default all),
//      DFORMER_EVOLVER_BUDGET (seconds of Evolver per pair, default 600),
//      DFORMER_EVOLVER_STEPS (Newton steps per continuation stage, default 80).
import { createRequire } from 'node:module';
import { pairs } from './evolver/pairs.mjs';
import { glue } from './evolver/sheet.mjs';
import { datafile, script } from './evolver/datafile.mjs';
import { findEvolver, runEvolver } from './evolver/run.mjs';
import { volume, maxStrain, maxBend, maxBendPerPiece, selfIntersections } from './evolver/check.mjs';

const exe = findEvolver();
if (!exe) {
  console.log('Surface Evolver not found on PATH: the Evolver peer is skipped.');
  console.log('  Install Debian\'s evolver-nox (`apt-get install evolver-nox`); scripts/bench.sh installs it when missing.');
  process.exit(0);
}
const require = createRequire(import.meta.url);
let m;
try {
  m = require(process.env.DFORMER_PKG ?? '../core/pkg/dformer.js');
} catch (e) {
  console.log(`The WASM package is missing (${e.message.split('\n')[0]}): build it with bash scripts/build-wasm.sh.`);
  process.exit(1);
}

const SEAM = Number(process.env.DFORMER_EVOLVER_SEAM ?? 128);
const POISSON = 0.3;
// Bending modulus over the stretching one, thick to thin, in units of R²/h (R the seam circle's
// radius, h the mesh step): bending of a curvature 1/R costs ~kb·h/R² per area against ~ε²
// for a strain ε, so kb·h/R² is the square of the sheet's relative thickness up to a constant.
const SCHEDULE = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7];
const STEPS = Number(process.env.DFORMER_EVOLVER_STEPS ?? 80);
// Wall-clock budget of one pair's Evolver run, seconds (the machine may be shared).
const BUDGET = Number(process.env.DFORMER_EVOLVER_BUDGET ?? 600);

// Richardson extrapolation of ours at 256/512/1024 for the convex case, as bench/simulate.bench.mjs.
function richardson(v1, v2, v4) {
  let q = Math.log2(Math.abs((v1 - v2) / (v2 - v4)));
  if (!(Number.isFinite(q) && q > 0.5)) q = 2;
  return v4 + (v4 - v2) / (2 ** q - 1);
}

const which = process.env.DFORMER_EVOLVER_PAIRS?.split(',').map(Number);
let total = 0;
const rows = [];
pairs().forEach((pair, index) => {
  if (which && !which.includes(index + 1)) return;
  console.log(`== ${pair.name} ==`);
  const sheet = glue(pair.pieces, pair.offset, SEAM);
  const R = sheet.perimeter / (2 * Math.PI);
  const schedule = (pair.schedule ?? SCHEDULE).map((r) => (r * R * R) / sheet.h);
  const { text } = datafile(sheet, { poisson: POISSON, kb: schedule[0], title: pair.name });
  const run = runEvolver(exe, text, script(schedule, { steps: STEPS, cg: pair.cg ?? 0 }), { timeoutMs: BUDGET * 1000 });
  total += run.ms;
  if (run.timedOut) console.log(`  Surface Evolver stopped by the ${BUDGET} s budget after ${run.stages.length} of ${schedule.length} stages (DFORMER_EVOLVER_BUDGET raises it)`);
  const bad = [...run.corners].filter(([f, c]) => c.join() !== sheet.triangles[f - 1].map((i) => i + 1).join());
  if ((run.status !== 0 && !run.timedOut) || run.vertices.size !== sheet.vertices.length || bad.length || run.corners.size !== sheet.triangles.length) {
    console.log(`  Surface Evolver failed (exit ${run.status}, ${run.vertices.size} of ${sheet.vertices.length} vertices back, ${bad.length} facets with another corner order); its last lines:`);
    console.log(run.log.split('\n').slice(-15).map((l) => `    ${l}`).join('\n'));
    return;
  }
  const x = sheet.vertices.map((_, i) => run.vertices.get(i + 1));
  const vol = Math.abs(volume(x, sheet.triangles));
  const strain = maxStrain(x, sheet.triangles, sheet.flat);
  const crossings = selfIntersections(x, sheet.triangles, 2 * sheet.h);
  const bend = maxBend(x, sheet.triangles, sheet.piece);
  const last = run.stages[run.stages.length - 1];
  const settled = run.stages.length === schedule.length && last.steps < STEPS;
  for (const s of run.stages) {
    console.log(`  stage kb·h/R² ${((s.kb * sheet.h) / (R * R)).toExponential(0)}: ${String(s.steps).padStart(2)} Newton steps, energy ${s.energy.toExponential(4)} (stretch ${s.stretch.toExponential(3)}, bend ${s.bend.toExponential(3)})`);
  }
  const ok = settled && strain <= 1e-3 && crossings === 0;
  console.log(`  Evolver: ${sheet.vertices.length} vertices (${SEAM} on the seam), ${sheet.triangles.length} facets, ${(run.ms / 1000).toFixed(1)} s`);
  console.log(`  Evolver: volume ${vol.toFixed(1)}, max edge strain ${strain.toExponential(2)}, self-intersecting facet pairs ${crossings}, sharpest bend inside a piece ${bend.toFixed(1)}°`);
  if (!ok) {
    console.log(`  Evolver did NOT converge to an inextensible, embedded equilibrium (${settled ? '' : 'the last stage did not settle or was not reached; '}strain ${strain.toExponential(2)} vs 1e-3, ${crossings} crossings): its volume is not a reference.`);
  }
  const ours = m.simulate(pair.pieces, { offset: pair.offset, resolution: 256 });
  const s = ours.stats;
  let line = `  ours (simulate, WASM, 256 seam vertices): volume ${s.volume.toFixed(1)}, converged ${s.converged}, max strain ${s.maxStrain.toExponential(2)}, ${s.ms.toFixed(0)} ms`;
  let exact = null;
  if (pair.convex) {
    const v = (n) => m.simulate(pair.pieces, { offset: pair.offset, resolution: n }).stats.volume;
    exact = richardson(s.volume, v(512), v(1024));
    line += `; Richardson 256/512/1024 ${exact.toFixed(1)}`;
  }
  console.log(line);
  if (pair.crease) {
    // Each piece's sharpest bend, Evolver's and ours, both from the meshes.
    const [ea, eb] = maxBendPerPiece(x, sheet.triangles, sheet.piece);
    const [oa, ob] = maxBendPerPiece(ours.vertices, ours.triangles, ours.piece);
    const both = eb > 90 && ob > 90;
    console.log(`  sharpest bend inside A / B: Evolver ${ea.toFixed(1)}° / ${eb.toFixed(1)}°, ours ${oa.toFixed(1)}° / ${ob.toFixed(1)}° (shortfall ${s.shortfall})`);
    const verdict = !ok
      ? 'Evolver did not settle into an inextensible, embedded sheet, so this run says nothing about the crease'
      : both
        ? 'both fold the circle by more than 90°, beside the notch: the crease is the sheet\'s, not our solver\'s'
        : 'Evolver and ours disagree on whether the circle folds by more than 90°';
    console.log(`  crease: ${verdict}`);
  }
  if (pair.touch) {
    // Whether each solver's sheet passes through itself, both read from the meshes.
    const oursCrossing = selfIntersections(ours.vertices, ours.triangles, (2 * sheet.perimeter) / 256);
    console.log(`  self-intersecting facet pairs: Evolver ${crossings} (free sheet), ours ${oursCrossing} (shortfall ${s.shortfall})`);
    const verdict = crossings > 0
      ? oursCrossing === 0
        ? 'Evolver\'s free sheet passes through itself where ours is held apart: this form is one the sheets hold by touching'
        : 'both pass through themselves'
      : ok
        ? 'Evolver finds an embedded free equilibrium that ours does not: a miss of our paths'
        : 'Evolver ends embedded but not inextensible, so this run says nothing about touching';
    console.log(`  touch: ${verdict}`);
  }
  const ratio = s.volume / vol;
  console.log(`  ratio ours / Evolver: ${ratio.toFixed(4)} (${((ratio - 1) * 100).toFixed(2)} %)${ok ? '' : ' — Evolver not converged'}`);
  if (exact) console.log(`  calibration: Evolver / exact convex volume ${(vol / exact).toFixed(5)} (${((vol / exact - 1) * 100).toFixed(3)} %; the issue's reference set-up reached 0.05 %)`);
  rows.push({ name: pair.name, vol, strain, crossings, ours: s.volume, ratio, ok });
});
console.log('\n| pair | Evolver volume | Evolver max edge strain | self-intersecting facet pairs | ours (256) | ours / Evolver |');
console.log('| --- | --- | --- | --- | --- | --- |');
for (const r of rows) {
  console.log(`| ${r.name} | ${r.vol.toFixed(1)}${r.ok ? '' : ' (not converged)'} | ${r.strain.toExponential(2)} | ${r.crossings} | ${r.ours.toFixed(1)} | ${r.ratio.toFixed(4)} |`);
}
console.log(`\nSurface Evolver total run time ${(total / 1000).toFixed(1)} s (${exe})`);
