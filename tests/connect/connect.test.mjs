// connect(pieces, options) from Node, checked against independent geometry (geometry.mjs):
// dense de Casteljau polylines, not the module's arc-length code.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { flatten, cumulative, nearest, inside, frameAt, wrapDiff, reversed, scaled, polygon, exact, nearestExact } from './geometry.mjs';

const require = createRequire(import.meta.url);
const m = require(process.env.DFORMER_PKG ?? '../../core/pkg/dformer.js');

const K = 0.5522847498307936;
/** A smooth convex egg, drawn counter-clockwise. */
const egg = {
  closed: true,
  points: [
    { anchor: [60, 0], left: [60, -35 * K * 1.1], right: [60, 40 * K * 1.1] },
    { anchor: [0, 40], left: [60 * K, 40], right: [-50 * K, 40] },
    { anchor: [-50, 0], left: [-50, 40 * K], right: [-50, -35 * K] },
    { anchor: [0, -35], left: [-50 * K, -35], right: [60 * K, -35] },
  ],
};
/** A flatter ellipse-like piece, scaled to the egg's perimeter and drawn clockwise. */
const flat0 = {
  closed: true,
  points: [
    { anchor: [80, 0], left: [80, -30 * K], right: [80, 30 * K] },
    { anchor: [0, 30], left: [80 * K, 30], right: [-80 * K, 30] },
    { anchor: [-80, 0], left: [-80, 30 * K], right: [-80, -30 * K] },
    { anchor: [0, -30], left: [-80 * K, -30], right: [80 * K, -30] },
  ],
};
const P = m.measure(egg).perimeter;
const flat = reversed(scaled(flat0, P / m.measure(flat0).perimeter));

/** Walk polyline of a piece: A counter-clockwise, B clockwise, from the first anchor. */
function walk(path, ccw) {
  const isCcw = m.measure(path).orientation === 'ccw';
  const walked = isCcw === ccw ? path : reversed(path);
  const poly = flatten(walked);
  return { poly, cum: cumulative(poly), ex: exact(walked) };
}
const WA = walk(egg, true), WB = walk(flat, false);

function close(got, want, tol, what) {
  assert.ok(Math.abs(got - want) <= tol, `${what}: wanted ${want}, got ${got} (tolerance ${tol})`);
}

test('holes are spaced exactly one pitch apart and sit at the inset from the edge', () => {
  const inset = 3, r = m.connect([egg, flat], { count: 40, inset, diameter: 2 });
  assert.equal(r.count, 40);
  close(r.pitch * 40, P, 1e-9 * P, 'count × pitch');
  for (const [i, w] of [WA, WB].entries()) {
    const feet = r.pieces[i].holes.map((h) => nearestExact(w.ex, h.center));
    feet.forEach((f, k) => close(f.dist, inset, 1e-9, `piece ${i} hole ${k + 1} distance to edge`));
    for (let k = 0; k < 40; k++) {
      const step = wrapDiff(feet[(k + 1) % 40].s, feet[k].s, P);
      close(step, r.pitch, 1e-9, `piece ${i} arc length from hole ${k + 1} to ${k + 2}`);
    }
  }
});

test('start and slide shift connector 0 to sA + slide·pitch on A and sB + slide·pitch on B', () => {
  const start = [17.5, 101.25], slide = 0.3;
  const r = m.connect([egg, flat], { count: 25, start, slide });
  for (const [i, w] of [WA, WB].entries()) {
    r.pieces[i].holes.forEach((h, k) => {
      const f = nearestExact(w.ex, h.center);
      close(wrapDiff(f.s, start[i] + (k + slide) * r.pitch, P), 0, 1e-9, `piece ${i} connector ${k + 1} arc length`);
    });
  }
});

test('B is walked clockwise whichever way it is drawn, and A counter-clockwise', () => {
  const opts = { count: 18, start: [5, 9] };
  const r1 = m.connect([egg, flat], opts);
  const r2 = m.connect([reversed(egg), reversed(flat)], opts);
  for (const i of [0, 1]) {
    r1.pieces[i].holes.forEach((h, k) => {
      const g = r2.pieces[i].holes[k].center;
      close(Math.hypot(h.center[0] - g[0], h.center[1] - g[1]), 0, 1e-9, `piece ${i} hole ${k + 1} moved when drawn the other way`);
    });
  }
  // Clockwise walk on B: the signed polar angle of successive holes about the centre decreases.
  const c = r1.pieces[1].holes.map((h) => Math.atan2(h.center[1], h.center[0]));
  const turn = c.slice(1).reduce((acc, a, k) => acc + wrapDiff(a, c[k], 2 * Math.PI), 0);
  assert.ok(turn < 0, `B's holes should run clockwise, total turn ${turn}`);
  const ca = r1.pieces[0].holes.map((h) => Math.atan2(h.center[1], h.center[0]));
  const turnA = ca.slice(1).reduce((acc, a, k) => acc + wrapDiff(a, ca[k], 2 * Math.PI), 0);
  assert.ok(turnA > 0, `A's holes should run counter-clockwise, total turn ${turnA}`);
});

test('labels are paired: label k+1 at the same arc length on A and B, inside and beyond its hole', () => {
  const r = m.connect([egg, flat], { count: 30, start: [3, 40] });
  let moved = 0;
  for (const [i, w] of [WA, WB].entries()) {
    const piece = r.pieces[i];
    assert.equal(piece.labels.length, 30);
    piece.labels.forEach((l, k) => {
      assert.equal(l.text, String(k + 1), `piece ${i} label ${k}`);
      const fl = nearestExact(w.ex, l.at), fh = nearestExact(w.ex, piece.holes[k].center);
      // A label that had to move clear of its neighbours (tight ends of the flat piece) still
      // sits by its own hole: nearer to it than to any other.
      const d = piece.holes.map((h) => Math.hypot(h.center[0] - l.at[0], h.center[1] - l.at[1]));
      assert.equal(d.indexOf(Math.min(...d)), k, `piece ${i} label ${k + 1} is nearer another hole than its own`);
      if (Math.abs(wrapDiff(fl.s, fh.s, P)) > 1e-9 || fl.dist < fh.dist) moved++;
      else assert.ok(fl.dist > fh.dist + piece.holes[k].diameter / 2, `piece ${i} label ${k + 1} not beyond its hole`);
      assert.ok(inside(w.poly, l.at), `piece ${i} label ${k + 1} outside`);
      assert.ok(l.angle > -90 && l.angle <= 90, `label angle ${l.angle} reads upside down`);
    });
  }
  assert.ok(moved <= 6, `only labels at the flat piece's tight ends move along the edge, ${moved} did`);
  // Where neither moved, label k + 1 is at the same arc length from the start on A and B.
  const sA = r.pieces[0].labels.map((l) => nearestExact(WA.ex, l.at).s - 3);
  const sB = r.pieces[1].labels.map((l) => nearestExact(WB.ex, l.at).s - 40);
  const hA = r.pieces[0].holes.map((h) => nearestExact(WA.ex, h.center).s - 3);
  const hB = r.pieces[1].holes.map((h) => nearestExact(WB.ex, h.center).s - 40);
  sA.forEach((s, k) => {
    if (Math.abs(wrapDiff(s, hA[k], P)) < 1e-9 && Math.abs(wrapDiff(sB[k], hB[k], P)) < 1e-9) close(wrapDiff(s, sB[k], P), 0, 1e-9, `label ${k + 1}: A vs B arc length from start`);
  });
  // One mark per piece, pointing at connector 0.
  for (const i of [0, 1]) assert.equal(r.pieces[i].marks.length, 1, `piece ${i} marks`);
});

test('every hole lies inside its piece and clear of the edge; stitch leaves the outline as drawn', () => {
  const r = m.connect([egg, flat], { pitch: 7, kerf: 0.2 });
  close(r.pitch * r.count, P, 1e-9 * P, 'pitch × count');
  assert.equal(r.count, Math.round(P / 7));
  for (const [i, w] of [WA, WB].entries()) {
    for (const [k, h] of r.pieces[i].holes.entries()) {
      assert.ok(inside(w.poly, h.center), `piece ${i} hole ${k + 1} outside`);
      close(h.diameter, r.pitch / 4 - 0.2, 1e-12, `hole ${k + 1} drawn diameter (nominal − kerf)`);
      const rim = flatten(h.path, 50).map((q) => Math.hypot(q[0] - h.center[0], q[1] - h.center[1]));
      assert.ok(rim.every((d) => Math.abs(d - h.diameter / 2) < 1e-3 * h.diameter), `hole ${k + 1} path is not its circle`);
      assert.ok(nearest(w.poly, w.cum, h.center).dist > h.diameter / 2, `hole ${k + 1} crosses the edge`);
    }
  }
  assert.deepEqual(r.pieces[0].outline, egg);
  assert.deepEqual(r.pieces[1].outline, flat);
  assert.deepEqual(r.warnings, []);
});

/** Arc lengths (walk order) where a piece's new outline stands out of its original edge. */
function standsOut(w, outline, us, depth) {
  const poly = flatten(outline, 200);
  return us.map((u) => {
    const { p, n } = frameAt(w.poly, w.cum, u);
    return inside(poly, [p[0] + depth * n[0], p[1] + depth * n[1]]);
  });
}

test('teeth are complementary: A has a tooth exactly where B has a gap', () => {
  const count = 16, start = [4, 11];
  const r = m.connect([egg, flat], { kind: 'teeth', count, start, length: 3 });
  assert.deepEqual(r.warnings, []);
  const p = r.pitch;
  // Sample the seam in A's connector frame; skip 2% of a pitch around each flank (at ±p/4).
  const rel = [];
  for (let j = 0; j < 4000; j++) {
    const x = (j / 4000) * P, ph = (((x % p) + p) % p) / p;
    if ([0.25, 0.75].some((f) => Math.abs(ph - f) < 0.02)) continue;
    rel.push(x);
  }
  const a = standsOut(WA, r.pieces[0].outline, rel.map((x) => start[0] + x), 0.75);
  const b = standsOut(WB, r.pieces[1].outline, rel.map((x) => start[1] + x), 0.75);
  rel.forEach((x, j) => {
    const ph = (((x % p) + p) % p) / p;
    const wantA = ph < 0.25 || ph > 0.75; // A's tooth centred on each connector
    assert.equal(a[j], wantA, `A at ${x.toFixed(3)} past connector 0: tooth wanted ${wantA}`);
    assert.equal(b[j], !wantA, `B at ${x.toFixed(3)} past connector 0: tooth wanted ${!wantA}`);
  });
  // invert swaps them.
  const ri = m.connect([egg, flat], { kind: 'teeth', count, start, length: 3, invert: true });
  const ai = standsOut(WA, ri.pieces[0].outline, [start[0]], 0.75);
  assert.equal(ai[0], false, 'inverted: A should have a gap at connector 0');
});

test('kerf grows each tooth by kerf/2 on every side', () => {
  const kerf = 0.4, count = 16, length = 3;
  const r = m.connect([egg, flat], { kind: 'teeth', count, length, kerf });
  const p = r.pitch, poly = flatten(r.pieces[0].outline, 200);
  // Just outside the nominal tooth flank (p/4 from the connector) the tooth now covers the seam line.
  const probe = (u, depth) => {
    const { p: q, n } = frameAt(WA.poly, WA.cum, u);
    return inside(poly, [q[0] + depth * n[0], q[1] + depth * n[1]]);
  };
  assert.equal(probe(p / 4 + 0.15, 0.01), true, 'tooth should reach kerf/2 past its nominal flank');
  assert.equal(probe(p / 4 + 0.25, 0.01), false, 'tooth should stop kerf/2 past its nominal flank');
  assert.equal(probe(0, length / 2 + 0.15), true, 'tooth top should stand kerf/2 higher');
  assert.equal(probe(0, length / 2 + 0.25), false, 'tooth top should stand only kerf/2 higher');
});

test('leaves alternate between the pieces: connector k has its leaf on A when k is even, on B when odd', () => {
  const count = 14, length = 4;
  const r = m.connect([egg, flat], { kind: 'leaves', count, length, start: [2, 7] });
  assert.deepEqual(r.warnings, []);
  const conn = (s0) => Array.from({ length: count }, (_, k) => s0 + k * r.pitch);
  const a = standsOut(WA, r.pieces[0].outline, conn(2), length / 2);
  const b = standsOut(WB, r.pieces[1].outline, conn(7), length / 2);
  a.forEach((v, k) => assert.equal(v, k % 2 === 0, `A connector ${k + 1}: leaf wanted ${k % 2 === 0}`));
  b.forEach((v, k) => assert.equal(v, k % 2 === 1, `B connector ${k + 1}: leaf wanted ${k % 2 === 1}`));
});

test('hybrid: teeth plus a hole at every connector, inside both pieces', () => {
  const r = m.connect([egg, flat], { kind: 'hybrid', count: 16, length: 3, inset: 5, diameter: 2 });
  assert.deepEqual(r.warnings, []);
  for (const i of [0, 1]) {
    const poly = flatten(r.pieces[i].outline, 200);
    assert.equal(r.pieces[i].holes.length, 16);
    r.pieces[i].holes.forEach((h, k) => {
      assert.ok(inside(poly, h.center), `piece ${i} hole ${k + 1} outside the toothed outline`);
      assert.ok(nearest(poly, cumulative(poly), h.center).dist > h.diameter / 2, `piece ${i} hole ${k + 1} crosses the teeth`);
    });
  }
});

test('perimeters that differ by more than 1e-6 relative are refused, naming both', () => {
  const big = scaled(flat, 1 + 1e-5);
  assert.throws(() => m.connect([egg, big], { count: 10 }), (e) => {
    assert.match(e.message, /different perimeters/);
    assert.match(e.message, /Normalize/);
    assert.ok(e.message.includes(String(P).slice(0, 8)), `message should name ${P}: ${e.message}`);
    return true;
  });
  // Within tolerance is accepted.
  assert.equal(m.connect([egg, scaled(flat, 1 + 1e-8)], { count: 10 }).count, 10);
});

test('every bad input gets its own message', () => {
  const cases = [
    [[egg], { count: 3 }, /Expected exactly two pieces to connect, got 1/],
    [[egg, flat, egg], { count: 3 }, /got 3/],
    [[egg, flat], { count: 0 }, /`count`: must be a whole number from 1 to 10000, got 0/],
    [[egg, flat], { count: 10001 }, /from 1 to 10000, got 10001/],
    [[egg, flat], { count: 2.5 }, /whole number/],
    [[egg, flat], { count: 3, pitch: 4 }, /either `count` or `pitch`, not both/],
    [[egg, flat], {}, /give either `count` \(number of connectors\) or `pitch`/],
    [[egg, flat], undefined, /give either `count`/],
    [[egg, flat], { pitch: -1 }, /`pitch`: must be a positive number, got -1/],
    [[egg, flat], { pitch: 0.001 }, /at most 10000 are allowed/],
    [[egg, flat], { count: 3, slide: 1.5 }, /`slide`: must be between 0 and 1/],
    [[egg, flat], { count: 3, slide: -0.1 }, /`slide`/],
    [[egg, flat], { count: 3, kind: 'zipper' }, /`kind`: must be one of "stitch", "teeth", "leaves", "hybrid", got "zipper"/],
    [[egg, flat], { count: 3, diameter: 0 }, /`diameter`: must be a positive number, got 0/],
    [[egg, flat], { count: 3, inset: -2 }, /`inset`: must be a positive number, got -2/],
    [[egg, flat], { count: 3, kind: 'teeth', length: 0 }, /`length`: must be a positive number/],
    [[egg, flat], { count: 3, kind: 'teeth', angle: 180 }, /`angle`: must be a flank angle in degrees, more than 0 and less than 180 \(90 square, more than 90 a dovetail\), got 180/],
    [[egg, flat], { count: 40, kind: 'teeth', angle: 170 }, /dovetails' corners collide\. At this pitch the flank angle must be between [\d.]+° and [\d.]+°/],
    [[egg, flat], { count: 13, kind: 'leaves' }, /`count`: leaves alternate between the two pieces, so their number must be even, got 13: use 12 or 14/],
    [[egg, flat], { count: 12, kind: 'leaves', leaf: 'knot' }, /`leaf`: must be "tab" \(glued\) or "lock"/],
    [[egg, flat], { count: 12, allowance: -1 }, /`allowance`: must be zero or a positive distance/],
    [[egg, flat], { count: 12, kind: 'teeth', allowance: 1 }, /teeth interlock on the seam line itself/],
    [[egg, flat], { count: 3, kerf: -0.1 }, /`kerf`: must be zero or a positive cut width/],
    [[egg, flat], { count: 3, diameter: 1, kerf: 1 }, /the holes would vanish/],
    [[egg, flat], { count: 3, start: [0, NaN] }, /`start`/],
    [[egg, flat], { count: 3, accuracy: 2 }, /`accuracy`/],
    [[egg, flat], { count: 40, diameter: 20 }, /do not fit between connectors/],
    [[egg, flat], { count: 10, inset: 1, diameter: 4 }, /across the edge/],
    [[egg, flat], { count: 40, kind: 'teeth', angle: 10 }, /flanks meet/],
    [[{ ...egg, closed: false }, flat], { count: 3 }, /first path is open/],
    [[egg, { closed: true, points: [{ anchor: [0, 0] }, { anchor: [NaN, 1] }] }], { count: 3 }, /second path has a coordinate that is not a finite number/],
  ];
  for (const [pieces, opts, re] of cases) {
    assert.throws(() => m.connect(pieces, opts), (e) => {
      assert.ok(e instanceof Error, 'should throw an Error');
      assert.match(e.message, re, `options ${JSON.stringify(opts)}`);
      return true;
    });
  }
});

test('a narrow tongue: warnings name exactly the holes that cross the edge', () => {
  // A square with a tongue 5 wide standing up from its top edge.
  const tongue = polygon([[0, 0], [100, 0], [100, 100], [52.5, 100], [52.5, 160], [47.5, 160], [47.5, 100], [0, 100]]);
  const Pt = m.measure(tongue).perimeter;
  const other = scaled(polygon([[0, 0], [0, 100], [100, 100], [100, 0]]), Pt / 400);
  const inset = 2, diameter = 2, count = 100;
  const r = m.connect([tongue, other], { count, inset, diameter, slide: 0.5 });
  const w = walk(tongue, true);
  const crossing = r.pieces[0].holes
    .map((h, k) => ({ k: k + 1, d: nearest(w.poly, w.cum, h.center).dist }))
    .filter((x) => x.d < diameter / 2 * 0.99).map((x) => x.k);
  assert.ok(crossing.length > 0, 'the test shape should make some holes cross the edge');
  const msg = r.warnings.find((s) => s.startsWith('On the first piece') && s.includes('cross the edge'));
  assert.ok(msg, `wanted a crossing warning, got ${JSON.stringify(r.warnings)}`);
  const named = msg.match(/connectors ([\d, ]+) cross/)[1].split(', ').map(Number);
  assert.deepEqual(named.sort((a, b) => a - b), crossing, 'named connectors vs independently measured ones');
});

test('a tight concave notch: teeth running into each other are reported by connector', () => {
  // A V notch 4 wide and 50 deep cut into the top edge.
  const notch = polygon([[0, 0], [100, 0], [100, 100], [52, 100], [50, 50], [48, 100], [0, 100]]);
  const Pn = m.measure(notch).perimeter;
  const other = scaled(polygon([[0, 0], [0, 100], [100, 100], [100, 0]]), Pn / 400);
  const count = 60, length = 4;
  const r = m.connect([notch, other], { kind: 'teeth', count, length });
  const msg = r.warnings.find((s) => s.startsWith('On the first piece') && s.includes('run into each other'));
  assert.ok(msg, `wanted a collision warning, got ${JSON.stringify(r.warnings)}`);
  // Every named connector sits on the notch walls or next to them (arc length 248 to 348 from (0, 0)).
  const wall0 = 248, wall1 = 248 + 2 * Math.hypot(2, 50);
  const numbers = [...msg.matchAll(/\d+/g)].map((x) => Number(x[0])).filter((k) => k >= 1 && k <= count);
  for (const k of numbers) {
    const s = (k - 1) * r.pitch;
    assert.ok(s > wall0 - r.pitch * 1.5 && s < wall1 + r.pitch * 1.5, `connector ${k} at ${s} is far from the notch [${wall0}, ${wall1}]`);
  }
  assert.ok(!r.warnings.some((s) => s.startsWith('On the second piece')), 'the plain square should not warn');
});

test('defaults(): the options every host starts from, and how sizes follow the pitch', () => {
  const d = m.defaults();
  const one = (name, kind, leaf) => d.options.find((o) => o.name === name && o.kinds.includes(kind) && (!o.leaf || o.leaf === leaf));
  assert.equal(one('count', 'stitch').value, 24);
  assert.equal(one('angle', 'teeth').value, 90);
  assert.equal(one('leaf', 'leaves').value, 'tab');
  assert.equal(one('allowance', 'stitch').value, 0);
  // The derived sizes are what connect() uses when they are absent.
  const r = m.connect([egg, flat], { count: 20 });
  const dia = one('diameter', 'stitch').pitch * r.pitch;
  close(r.pieces[0].holes[0].diameter, dia, 1e-12, 'default hole diameter = defaults().diameter.pitch × pitch');
  const f = nearestExact(WA.ex, r.pieces[0].holes[0].center);
  close(f.dist, one('inset', 'stitch').pitch * r.pitch, 1e-9, 'default inset');
  for (const k of ['stitch', 'teeth', 'leaves', 'hybrid']) assert.ok(d.invert[k].length > 10, `invert's meaning for ${k}`);
});
