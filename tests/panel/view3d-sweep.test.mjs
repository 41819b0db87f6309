// The 3D tab as a design tool (issue 12): the plot of volume and height over one full turn of the
// seam offset (filled coarse-first on its own worker, cancelled when the pieces change), the
// largest / tallest buttons and click-to-seek, the casting figures, and the connectors drawn on
// the form. Values are checked against separate `simulate` calls and an independent barycentric
// mapping / closest-point distance computed here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { artifactPath, usePanelBrowser, waitReady } from './support.mjs';

const panel = usePanelBrowser();
const SWEEP_TIMEOUT = 240000;

async function open3d(page, sample) {
  await page.goto(panel.url);
  await waitReady(page, 'load');
  await page.selectOption('#sample-select', sample);
  await waitReady(page);
  await page.click('.tabs button[data-view="3d"]');
  await page.waitForFunction(() => document.body.dataset.solve === 'ok', null, { timeout: 60000 });
}

/** Waits for the solve after a seek: the design's offset is `offset` and its form is on show. */
async function waitSolvedAt(page, offset) {
  await page.waitForFunction((o) => {
    const d = window.DF.app.design();
    return d && Math.abs(d.offset - o) < 1e-6 * d.perimeter && document.body.dataset.solving !== 'yes' && document.body.dataset.solve === 'ok';
  }, offset, { timeout: 60000 });
  // …and the mesh is the one for this offset (a solve may have been coalesced behind another).
  await page.waitForFunction(() => !document.body.dataset.solving, null, { timeout: 60000 });
}

test('3D tab: the sweep plot equals separate simulate calls; largest/tallest buttons and a click seek; progress; cancel on new pieces', { timeout: 600000 }, async () => {
  const page = await panel.browser.newPage({ viewport: { width: 1100, height: 760 } });
  await open3d(page, 'two-ellipses');
  // Coarse first: at any moment the sampled offsets are a prefix of 8-then-16-then-32.
  const order = await page.evaluate(() => window.DF.sweep.order(32));
  assert.deepEqual(order.slice(0, 8), [0, 4, 8, 12, 16, 20, 24, 28], 'the first pass is every 4th of 32 offsets');
  let sawProgress = false;
  for (let i = 0; i < 40; i++) {
    const st = await page.evaluate(() => ({ idx: window.DF.app.sweep().points.map((p) => p.index), running: window.DF.app.sweep().running, bar: !document.querySelector('#sweep-progress').hidden, text: document.querySelector('#sweep-status').textContent }));
    const prefix = order.slice(0, st.idx.length).sort((a, b) => a - b);
    assert.deepEqual(st.idx, prefix, `sampled offsets ${st.idx} are not the first ${st.idx.length} of the coarse-first order`);
    if (st.running && st.bar && /Sampling the seam: \d+ of 32 offsets/.test(st.text)) sawProgress = true;
    if (!st.running) break;
    await new Promise((r) => setTimeout(r, 150));
  }
  assert.ok(sawProgress, 'a progress bar and "Sampling the seam: n of 32 offsets…" while the sweep runs');
  await page.waitForFunction(() => document.body.dataset.sweep === 'done', null, { timeout: SWEEP_TIMEOUT });
  const st = await page.evaluate(() => window.DF.app.sweep());
  assert.equal(st.points.length, 32);

  // The plot's values are those of separate simulate calls at the same offsets (every 4th here).
  const check = await page.evaluate((pts) => {
    const d = window.DF.app.design();
    const pieces = d.pieces.map((p) => p.path);
    return pts.map((p) => {
      const f = window.DF.core.simulate(pieces, { offset: p.offset });
      const g = window.DF.core.formFigures(f, { mmPerUnit: 25.4 / 72 });
      return { offset: p.offset, want: [f.stats.volume, g.height, f.stats.converged], got: [p.volume, p.height, p.converged] };
    });
  }, st.points.filter((p) => p.index % 4 === 0));
  for (const c of check) {
    assert.equal(c.got[2], c.want[2], `offset ${c.offset}: converged`);
    assert.ok(Math.abs(c.got[0] - c.want[0]) <= 1e-9 * Math.abs(c.want[0]) + 1e-9, `offset ${c.offset}: plot volume ${c.got[0]}, simulate ${c.want[0]}`);
    assert.ok(Math.abs(c.got[1] - c.want[1]) <= 1e-9 * Math.abs(c.want[1]) + 1e-9, `offset ${c.offset}: plot height ${c.got[1]}, simulate ${c.want[1]}`);
  }
  // Drawn: one dot per converged offset, a × per unconverged one (never a value), the current offset.
  const drawn = await page.evaluate(() => ({
    dots: document.querySelectorAll('#sweep-plot circle.sample').length,
    crosses: document.querySelectorAll('#sweep-plot .unconverged').length,
    current: Number(document.querySelector('#sweep-current').getAttribute('data-fraction')),
    offset: window.DF.app.design().offset / window.DF.app.design().perimeter,
  }));
  const converged = st.points.filter((p) => p.converged).length;
  assert.equal(drawn.dots, converged, 'one dot per converged offset');
  assert.equal(drawn.crosses, 32 - converged, 'one × per offset that did not converge');
  assert.ok(Math.abs(drawn.current - drawn.offset) < 1e-12, `current offset marked at ${drawn.current}, design at ${drawn.offset}`);
  await page.screenshot({ path: artifactPath('browser-3d-sweep.png') });

  // Largest volume: lands on a sampled offset whose volume no sampled offset exceeds.
  const perimeter = await page.evaluate(() => window.DF.app.design().perimeter);
  for (const [button, field] of [['#sweep-largest', 'volume'], ['#sweep-tallest', 'height']]) {
    const best = st.points.filter((p) => p.converged).reduce((a, b) => (b[field] > a[field] ? b : a));
    await page.click(button);
    await waitSolvedAt(page, best.offset);
    const after = await page.evaluate(() => ({ offset: window.DF.app.design().offset, slider: Number(document.querySelector('#offset3d').value), current: Number(document.querySelector('#sweep-current').getAttribute('data-fraction')), figures: window.DF.app.figures(), volume: window.DF.app.mesh().stats.volume }));
    assert.ok(Math.abs(after.offset - best.offset) < 1e-9 * perimeter, `${button}: offset ${after.offset}, wanted ${best.offset}`);
    for (const p of st.points) assert.ok(!p.converged || p[field] <= best[field], `${button}: offset ${p.offset} has ${field} ${p[field]} > ${best[field]}`);
    assert.equal(after.slider, Math.round((best.offset / perimeter) * 1000), `${button}: the slider moved there`);
    assert.ok(Math.abs(after.current - best.offset / perimeter) < 1e-9, `${button}: the plot marks the new offset`);
    const shown = field === 'volume' ? after.volume : after.figures.height;
    assert.ok(Math.abs(shown - best[field]) <= 1e-3 * best[field], `${button}: the form on show has ${field} ${shown}, the plot said ${best[field]}`);
  }
  // A click on the plot moves the slider there.
  const box = await page.locator('#sweep-plot').boundingBox();
  const pad = 6;
  await page.mouse.click(box.x + pad + 0.5 * (box.width - 2 * pad), box.y + box.height / 2);
  await page.waitForFunction(() => Math.abs(window.DF.app.design().offset / window.DF.app.design().perimeter - 0.5) < 0.01, null, { timeout: 20000 });

  // New pieces cancel the sweep: the plot restarts for them, and no point of the old pieces appears.
  const oldKey = st.key;
  await page.selectOption('#sample-select', 'ellipse-circle');
  await waitReady(page);
  await page.waitForFunction((k) => { const s = window.DF.app.sweep(); return s && s.key && s.key !== k && s.points.length >= 1; }, oldKey, { timeout: 60000 });
  const fresh = await page.evaluate(() => {
    const s = window.DF.app.sweep();
    const pieces = window.DF.app.design().pieces.map((p) => p.path);
    const p0 = s.points.find((p) => p.index === 0);
    return { key: s.key === JSON.stringify(pieces), n: s.points.length, v0: p0 && p0.volume, want: p0 && window.DF.core.simulate(pieces, { offset: 0 }).stats.volume };
  });
  assert.ok(fresh.key, 'the sweep is of the new pieces');
  assert.ok(fresh.n < 32, 'the sweep started over');
  assert.ok(Math.abs(fresh.v0 - fresh.want) <= 1e-9 * fresh.want, `offset 0 of the new pieces: plot ${fresh.v0}, simulate ${fresh.want}`);
  await page.close();
});

/** Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, §5.1.5). */
function closest(p, a, b, c) {
  const sub = (u, v) => [u[0] - v[0], u[1] - v[1], u[2] - v[2]];
  const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const add = (u, v, s) => [u[0] + s * v[0], u[1] + s * v[1], u[2] + s * v[2]];
  const ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const bp = sub(p, b), d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return add(a, ab, d1 / (d1 - d3));
  const cp = sub(p, c), d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return add(a, ac, d2 / (d2 - d6));
  const va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return add(b, sub(c, b), (d4 - d3) / (d4 - d3 + (d5 - d6)));
  const den = 1 / (va + vb + vc);
  return add(add(a, ab, vb * den), ac, vc * den);
}

test('3D tab: connectors on the form sit on the surface at their mapped flat positions; casting figures follow the density', { timeout: 300000 }, async () => {
  const page = await panel.browser.newPage({ viewport: { width: 1100, height: 760 } });
  await open3d(page, 'ellipse-circle');
  await page.waitForFunction(() => { const m = window.DF.app.marks(); return m && m.holes.length > 0; }, null, { timeout: 60000 });
  const { mesh, marks, pieces } = await page.evaluate(() => ({
    mesh: window.DF.app.mesh(),
    marks: window.DF.app.marks(),
    pieces: window.DF.app.design().pieces.map((p) => ({ holes: p.holes.map((h) => h.center), labels: p.labels.map((l) => l.text), inset: 0 })),
  }));
  const count = pieces[0].holes.length;
  assert.equal(marks.holes.length, 2 * count, 'every hole of both pieces is on the form');
  assert.equal(marks.labels.length, pieces[0].labels.length + pieces[1].labels.length, 'every number is on the form');
  let size = 0;
  for (const v of mesh.vertices) size = Math.max(size, Math.hypot(v[0], v[1], v[2]));
  marks.holes.forEach((P, i) => {
    const { piece, flat } = marks.holeOf[i];
    // Independently: the flat triangle of this piece that contains the centre, and its barycentric map.
    let best = null;
    mesh.flat.forEach((t, k) => {
      if (mesh.piece[k] !== piece) return;
      const [a, b, c] = t;
      const det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      const w1 = ((flat[0] - a[0]) * (c[1] - a[1]) - (flat[1] - a[1]) * (c[0] - a[0])) / det;
      const w2 = ((b[0] - a[0]) * (flat[1] - a[1]) - (b[1] - a[1]) * (flat[0] - a[0])) / det;
      const w = [1 - w1 - w2, w1, w2];
      const inside = Math.min(...w);
      if (!best || inside > best.inside) best = { inside, w, k };
    });
    assert.ok(best.inside >= -1e-9, `hole ${i}: its centre lies in a flat triangle of its piece`);
    const tri = mesh.triangles[best.k].map((j) => mesh.vertices[j]);
    const want = [0, 1, 2].map((d) => best.w[0] * tri[0][d] + best.w[1] * tri[1][d] + best.w[2] * tri[2][d]);
    assert.ok(Math.hypot(P[0] - want[0], P[1] - want[1], P[2] - want[2]) < 1e-9 * size, `hole ${i}: drawn at ${P}, its flat position maps to ${want}`);
    let d = Infinity;
    for (const t of mesh.triangles) {
      const q = closest(P, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
      d = Math.min(d, Math.hypot(P[0] - q[0], P[1] - q[1], P[2] - q[2]));
    }
    assert.ok(d < 1e-9 * size, `hole ${i}: ${d} off the surface`);
  });
  // Hole k of A meets hole k of B: across the seam, within two insets (4 mm each by default).
  const inset = 4 * 72 / 25.4;
  for (let k = 0; k < count; k++) {
    const [a, b] = [marks.holes[k], marks.holes[count + k]];
    assert.ok(Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) <= 2 * inset * 1.05, `hole ${k + 1} of A and of B are ${Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2])} pt apart`);
  }
  await page.locator('#view3d').screenshot({ path: artifactPath('browser-3d-connectors.png') });

  // Casting figures: the mass is the mesh's own volume (divergence theorem, here) × density.
  let vol = 0;
  for (const [i, j, k] of mesh.triangles) {
    const [a, b, c] = [mesh.vertices[i], mesh.vertices[j], mesh.vertices[k]];
    vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  }
  const m3 = Math.abs(vol) * Math.pow(25.4 / 72, 3) * 1e-9;
  for (const density of [2400, 1000]) {
    if (density !== 2400) await page.fill('#density', String(density));
    const text = await page.textContent('#cast3d');
    const m = /Casting ([\d.,]+) kg · height ([\d.]+) mm × width ([\d.]+) mm × depth ([\d.]+) mm/.exec(text);
    assert.ok(m, `casting line: ${text}`);
    const kg = Number(m[1].replace(/,/g, ''));
    assert.ok(Math.abs(kg - m3 * density) <= 0.005 * m3 * density, `at ${density} kg/m³: shown ${kg} kg, the mesh holds ${m3 * density} kg`);
    const f = await page.evaluate(() => window.DF.app.figures());
    [['height', m[2]], ['width', m[3]], ['depth', m[4]]].forEach(([name, shown]) => {
      assert.ok(Number(shown) > 0 && Math.abs(Number(shown) - f[name] * 25.4 / 72) <= 0.006, `${name}: shown ${shown} mm, formFigures ${f[name] * 25.4 / 72} mm`);
    });
  }
  await page.close();
});

// Regression (issue 14): with the sample "Pebble + circle" the sweep drew 32 solves of one form,
// each on another mesh of the circle, as a curve (volume spread over offsets by up to 3 %), and
// "Largest" chose among meshes. A circle turned about its centre is itself, so every offset is
// the same form: the core now says so (`offsetFree`), the sweep stops after one solve and says
// why, and nothing is ringed as largest or tallest.
test('3D tab: with a circle the sweep is one form at every offset, said so, nothing ringed', { timeout: 300000 }, async () => {
  const page = await panel.browser.newPage({ viewport: { width: 1100, height: 760 } });
  await open3d(page, 'pebble-circle');
  await page.waitForFunction(() => document.body.dataset.sweep === 'done', null, { timeout: SWEEP_TIMEOUT });
  const st = await page.evaluate(() => window.DF.app.sweep());
  assert.equal(st.points.length, 32, 'a point at every offset');
  assert.ok(st.offsetFree, 'the sweep knows the offset does not change the form');
  // Independent of the sweep: simulate at two offsets gives the same 3D vertices and volume.
  const direct = await page.evaluate(() => {
    const d = window.DF.app.design();
    const pieces = d.pieces.map((p) => p.path);
    const [f0, f1] = [0, 0.3 * d.perimeter].map((offset) => window.DF.core.simulate(pieces, { offset }));
    return { same: JSON.stringify(f0.vertices) === JSON.stringify(f1.vertices), v0: f0.stats.volume, v1: f1.stats.volume, free: f0.stats.offsetFree && f1.stats.offsetFree, converged: f0.stats.converged };
  });
  assert.ok(direct.same && direct.v0 === direct.v1 && direct.free, `simulate at offsets 0 and 0.3 of the perimeter: same form ${direct.same}, volumes ${direct.v0} and ${direct.v1}`);
  for (const p of st.points) {
    assert.equal(p.volume, direct.v0, `offset ${p.offset}: the plot's volume is the form's`);
    assert.equal(p.converged, direct.converged);
  }
  const shown = await page.evaluate(() => ({
    text: document.querySelector('#sweep-status').textContent,
    rings: document.querySelectorAll('#sweep-plot circle.best').length,
    largest: document.querySelector('#sweep-largest').disabled,
    tallest: document.querySelector('#sweep-tallest').disabled,
  }));
  assert.match(shown.text, /One piece is a circle, so the seam offset does not change the form: [\d.]+ L, height .+ at every offset/);
  assert.equal(shown.rings, 0, 'no offset ringed as largest or tallest');
  assert.ok(shown.largest && shown.tallest, 'Largest and Tallest have nothing to choose');
  await page.close();
});
