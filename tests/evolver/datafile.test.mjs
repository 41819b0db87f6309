// The Evolver peer's datafile generator (bench/evolver/): the geometry it hands to Evolver is
// checked against independent computations, so the bench's peer cannot silently rot.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pairs } from '../../bench/evolver/pairs.mjs';
import { glue, seamSamples } from '../../bench/evolver/sheet.mjs';
import { datafile } from '../../bench/evolver/datafile.mjs';
import { arcTable, signedArea } from '../../bench/evolver/outline.mjs';
import { volume, maxStrain, maxBend, maxBendPerPiece, segmentHitsTriangle, selfIntersections } from '../../bench/evolver/check.mjs';

const N = 48;
const cases = pairs().map((p) => ({ ...p, sheet: glue(p.pieces, p.offset, N) }));

/** The datafile's vertices, edges (with bend flag) and faces (signed edges, form factors), parsed back. */
function parse(text) {
  const v = new Map(), e = new Map(), f = [];
  let section = '';
  for (const line of text.split('\n')) {
    if (/^(vertices|edges|faces)$/.test(line)) { section = line; continue; }
    const w = line.trim().split(/\s+/);
    if (!/^\d+$/.test(w[0] ?? '')) continue;
    if (section === 'vertices') v.set(+w[0], w.slice(1, 4).map(Number));
    if (section === 'edges') e.set(+w[0], { v: [+w[1], +w[2]], bend: line.includes('quantity bend') });
    if (section === 'faces') {
      const ff = line.match(/form_factors \{([^}]*)\}/)[1].split(',').map(Number);
      f.push({ edges: w.slice(1, 4).map(Number), ff, tension: line.match(/tension (\S+)/)[1] });
    }
  }
  return { v, e, f };
}

const dist2 = (a, b) => (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2;

test('every facet\'s form_factors reproduce its own flat edge lengths, in the corner order Evolver reads', () => {
  for (const c of cases) {
    const { e, f } = parse(datafile(c.sheet).text);
    assert.equal(f.length, c.sheet.triangles.length);
    f.forEach((face, t) => {
      // Evolver's facet corners: tail of each oriented edge in turn (a negative id is reversed).
      const tail = (id) => (id > 0 ? e.get(id).v[0] : e.get(-id).v[1]);
      const head = (id) => (id > 0 ? e.get(id).v[1] : e.get(-id).v[0]);
      const corners = face.edges.map(tail);
      face.edges.forEach((id, q) => assert.equal(head(id), tail(face.edges[(q + 1) % 3]), `${c.name}: face ${t + 1} is not a loop`));
      assert.deepEqual(corners, c.sheet.triangles[t].map((i) => i + 1), `${c.name}: face ${t + 1} corner order`);
      const [p0, p1, p2] = c.sheet.flat[t];
      const [s11, s12, s22] = face.ff;
      const want = [dist2(p0, p1), dist2(p0, p2), dist2(p1, p2)];
      const got = [s11, s22, s11 + s22 - 2 * s12];
      want.forEach((w, q) => assert.ok(Math.abs(got[q] - w) <= 1e-9 * w, `${c.name}: face ${t + 1} side ${q}: wanted ${w}, got ${got[q]}`));
      assert.equal(face.tension, '0');
    });
  }
});

test('the seam edges, and only they, carry no bending; each joins the two pieces', () => {
  for (const c of cases) {
    const { e } = parse(datafile(c.sheet).text);
    const free = [...e.values()].filter((x) => !x.bend).map((x) => x.v.map((i) => i - 1).sort((a, b) => a - b).join(','));
    const seam = [...Array(N).keys()].map((k) => [k, (k + 1) % N].sort((a, b) => a - b).join(','));
    assert.deepEqual(free.sort(), seam.sort(), `${c.name}: unbent edges`);
  }
});

test('a seam vertex has one flat position per piece: the arc-length samples of each outline', () => {
  for (const c of cases) {
    const s = seamSamples(c.pieces, c.offset, N);
    const seen = [new Map(), new Map()];
    c.sheet.triangles.forEach((t, f) => t.forEach((i, q) => {
      if (i >= N) return;
      const m = seen[c.sheet.piece[f]];
      if (!m.has(i)) m.set(i, c.sheet.flat[f][q]);
      assert.deepEqual(c.sheet.flat[f][q], m.get(i), `${c.name}: seam vertex ${i} has two positions on one piece`);
    }));
    for (let k = 0; k < N; k++) {
      assert.deepEqual(seen[0].get(k), s.a[k]);
      assert.deepEqual(seen[1].get(k), s.b[k]);
    }
    // Consecutive samples are one seam step h apart along the outline: the arc between them,
    // estimated from chords of the same walk sampled 2× and 4× finer with Richardson
    // extrapolation (chords err by O(h²κ²), Richardson removes the h² and h⁴ terms), is h.
    const h = s.perimeter / N, s2 = seamSamples(c.pieces, c.offset, 2 * N), s4 = seamSamples(c.pieces, c.offset, 4 * N);
    const d = (a, b) => Math.sqrt(dist2(a, b));
    for (const [p1, p2, p4] of [[s.a, s2.a, s4.a], [s.b, s2.b, s4.b]]) for (let k = 0; k < N; k++) {
      const c1 = d(p1[k], p1[(k + 1) % N]);
      const c2 = d(p2[2 * k], p2[2 * k + 1]) + d(p2[2 * k + 1], p2[(2 * k + 2) % (2 * N)]);
      let c4 = 0;
      for (let j = 0; j < 4; j++) c4 += d(p4[4 * k + j], p4[(4 * k + j + 1) % (4 * N)]);
      const r1 = (4 * c2 - c1) / 3, r2 = (4 * c4 - c2) / 3, arc = (16 * r2 - r1) / 15;
      assert.ok(Math.abs(arc - h) < 3e-3 * h, `${c.name}: arc ${k}: wanted ${h}, got ${arc}`);
    }
  }
});

test('each piece\'s facets tile its flat piece: the flat areas add up to the outline\'s area', () => {
  for (const c of cases) {
    for (const which of [0, 1]) {
      let a = 0;
      c.sheet.flat.forEach(([p, q, r], f) => {
        if (c.sheet.piece[f] !== which) return;
        const t = ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])) / 2;
        assert.ok(t > 0, `${c.name}: facet ${f} is inverted on its flat piece`);
        a += t;
      });
      const want = Math.abs(signedArea(c.pieces[which]));
      // The mesh covers the polygon of the seam samples, short of the curved outline by O(h²)
      // (of a polygon, whose corners are samples, by round-off only).
      assert.ok(a < want * (1 + 1e-12) && a > want * (1 - 2e-2), `${c.name} piece ${which}: wanted ≈ ${want}, got ${a}`);
    }
  }
});

test('the glued sheet is a closed oriented sphere with a positive volume at the start', () => {
  for (const c of cases) {
    const { vertices, triangles } = c.sheet;
    const { edges } = datafile(c.sheet); // throws unless every edge has two oppositely oriented facets
    assert.equal(vertices.length - edges.length + triangles.length, 2, `${c.name}: Euler characteristic`);
    assert.ok(volume(vertices, triangles) > 0, `${c.name}: volume ${volume(vertices, triangles)}`);
  }
});

test('arc length: a straight cubic with uneven handles is sampled at exact distances', () => {
  const path = { closed: true, points: [{ anchor: [0, 0], right: [0.1, 0] }, { anchor: [3, 0], left: [2, 0], right: [3, 0] }, { anchor: [0, 4] }] };
  const t = arcTable(path);
  assert.ok(Math.abs(t.perimeter - 12) < 1e-12, `perimeter: wanted 12, got ${t.perimeter}`);
  for (const s of [0.3, 1.7, 2.9]) {
    const p = t.at(s);
    assert.ok(Math.abs(p[0] - s) < 1e-10 && Math.abs(p[1]) < 1e-12, `at(${s}): got ${p}`);
  }
  const p = t.at(3 + 2.5); // halfway along the 3-4-5 hypotenuse
  assert.ok(Math.abs(p[0] - 1.5) < 1e-12 && Math.abs(p[1] - 2) < 1e-12, `at(5.5): got ${p}`);
  assert.ok(Math.abs(signedArea(path) - 6) < 1e-12, `area: wanted 6, got ${signedArea(path)}`);
});

test('checks: volume of a unit tetrahedron, strain, crossing triangles', () => {
  const x = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]];
  const tris = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
  assert.ok(Math.abs(volume(x, tris) - 1 / 6) < 1e-15);
  const flat = tris.map((t) => t.map((i) => [x[i][0] * 1.1, x[i][1] * 1.1]));
  // Facet 0 lies in z = 0 and its flat copy is 10 % larger: strain 1/1.1 − 1 on its sides.
  assert.ok(maxStrain(x, [tris[0]], [flat[0]]) - (1 - 1 / 1.1) < 1e-12);
  assert.ok(segmentHitsTriangle([0.2, 0.2, -1], [0.2, 0.2, 1], [0, 0, 0], [1, 0, 0], [0, 1, 0]));
  assert.ok(!segmentHitsTriangle([0.8, 0.8, -1], [0.8, 0.8, 1], [0, 0, 0], [1, 0, 0], [0, 1, 0]));
  assert.equal(selfIntersections(x, tris, 0.5), 0);
  // A pierced pair: a vertical triangle through the tetrahedron's base.
  const y = [...x, [0.2, 0.2, -1], [0.25, 0.2, 1], [0.2, 0.25, 1]];
  assert.equal(selfIntersections(y, [...tris, [4, 5, 6]], 0.5), 2); // through the base and a side
});

test('checks: each piece\'s sharpest bend, a hinge folded by a known angle', () => {
  // Piece A: two triangles on the hinge (0,0,0)–(1,0,0), the second turned by 120° about it;
  // piece B: two coplanar triangles; one edge shared across the pieces, folded by 90°, counts
  // for neither (a seam edge is a free hinge).
  const t = (120 * Math.PI) / 180;
  const x = [[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -Math.cos(t), -Math.sin(t)], [0, 0, 5], [1, 0, 5], [0.5, 1, 5], [0.5, -1, 5], [0.5, 1, 4]];
  const tris = [[0, 1, 2], [1, 0, 3], [4, 5, 6], [5, 4, 7], [6, 5, 8]];
  const piece = [0, 0, 1, 1, 0];
  const [a, b] = maxBendPerPiece(x, tris, piece);
  assert.ok(Math.abs(a - 120) < 1e-9, `A: wanted 120°, got ${a}`);
  assert.ok(Math.abs(b) < 1e-6, `B: wanted 0°, got ${b}`);
  assert.equal(maxBend(x, tris, piece), a);
});
