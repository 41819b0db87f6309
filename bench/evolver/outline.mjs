// The bench's outlines as contract paths (`{ closed, points: [{ anchor, left, right }] }`) and an
// arc-length sampler for them written here, independent of the core's: the Evolver peer must
// not inherit the core's sampling, only the same input paths.
//
// Arc length: 16-point Gauss–Legendre on each cubic split into 8 equal parameter intervals
// (error ≲ 1e-13 relative for the smooth segments used here); inversion of s(t) by Newton on
// the speed |B′(t)| with a bisection fallback (Burden & Faires, "Numerical Analysis", 4.7).

const GL = (() => {
  // Nodes and weights of 16-point Gauss–Legendre on [−1, 1] (Abramowitz & Stegun 25.4.30).
  const x = [0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
    0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499];
  const w = [0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
    0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541];
  return { x: [...x.map((v) => -v), ...x], w: [...w, ...w] };
})();

/** A closed polar curve r(θ) as a path of `n` cubic Hermite arcs (handles p′(θ)·Δθ/3). */
export function polarPath(r, dr, n = 96) {
  const points = [];
  const d = (2 * Math.PI) / n;
  for (let i = 0; i < n; i++) {
    const t = i * d, c = Math.cos(t), s = Math.sin(t);
    const a = [r(t) * c, r(t) * s];
    const v = [dr(t) * c - r(t) * s, dr(t) * s + r(t) * c];
    points.push({ anchor: a, left: [a[0] - (v[0] * d) / 3, a[1] - (v[1] * d) / 3], right: [a[0] + (v[0] * d) / 3, a[1] + (v[1] * d) / 3] });
  }
  return { closed: true, points };
}

/**
 * A closed polygon as a path of straight cubic segments, handles on each side at 1/3 and 2/3,
 * so that every vertex stays a sharp corner (its two handles point along different sides).
 */
export function polygonPath(vertices) {
  const n = vertices.length;
  const toward = (a, b) => [a[0] + (b[0] - a[0]) / 3, a[1] + (b[1] - a[1]) / 3];
  return {
    closed: true,
    points: vertices.map((a, i) => ({ anchor: a, left: toward(a, vertices[(i + n - 1) % n]), right: toward(a, vertices[(i + 1) % n]) })),
  };
}

/** A 2:1-style ellipse of four quarter arcs, the construction of bench/simulate.bench.mjs. */
export function ellipsePath(rx, ry) {
  const K = 0.5522847498307936;
  return {
    closed: true,
    points: [[1, 0], [0, 1], [-1, 0], [0, -1]].map(([x, y]) => {
      const a = [rx * x, ry * y], t = [-y * rx * K, x * ry * K];
      return { anchor: a, left: [a[0] - t[0], a[1] - t[1]], right: [a[0] + t[0], a[1] + t[1]] };
    }),
  };
}

/** The cubic segments [p0, p1, p2, p3] of a closed path (a missing handle is a corner). */
export function segments(path) {
  const pts = path.points, n = pts.length;
  return pts.map((p, i) => {
    const q = pts[(i + 1) % n];
    return [p.anchor, p.right ?? p.anchor, q.left ?? q.anchor, q.anchor];
  });
}

const lerp = (a, b, t) => [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
function point([p0, p1, p2, p3], t) {
  const a = lerp(p0, p1, t), b = lerp(p1, p2, t), c = lerp(p2, p3, t);
  return lerp(lerp(a, b, t), lerp(b, c, t), t);
}
function deriv([p0, p1, p2, p3], t) {
  const u = 1 - t;
  return [0, 1].map((c) => 3 * (u * u * (p1[c] - p0[c]) + 2 * u * t * (p2[c] - p1[c]) + t * t * (p3[c] - p2[c])));
}
const speed = (seg, t) => Math.hypot(...deriv(seg, t));
function arc(seg, t0, t1, parts = 8) {
  let s = 0;
  const h = (t1 - t0) / parts;
  for (let k = 0; k < parts; k++) {
    const m = t0 + (k + 0.5) * h;
    for (let g = 0; g < 16; g++) s += GL.w[g] * speed(seg, m + (GL.x[g] * h) / 2) * (h / 2);
  }
  return s;
}

/** Signed area of a closed path: Green's theorem ½∮(x dy − y dx) by Gauss–Legendre per cubic. */
export function signedArea(path) {
  let a = 0;
  for (const seg of segments(path)) {
    for (let g = 0; g < 16; g++) {
      const t = (GL.x[g] + 1) / 2, p = point(seg, t), d = deriv(seg, t);
      a += (GL.w[g] / 2) * (p[0] * d[1] - p[1] * d[0]) / 2;
    }
  }
  return a;
}

/** Arc-length table of a closed path: `perimeter` and `at(s)`, the point at arc length s. */
export function arcTable(path) {
  const segs = segments(path);
  const lens = segs.map((s) => arc(s, 0, 1));
  const starts = [0];
  for (const l of lens) starts.push(starts[starts.length - 1] + l);
  const perimeter = starts[segs.length];
  function at(s) {
    s = ((s % perimeter) + perimeter) % perimeter;
    let i = 0;
    while (i < segs.length - 1 && starts[i + 1] <= s) i++;
    const seg = segs[i], want = s - starts[i];
    let lo = 0, hi = 1, t = want / lens[i];
    for (let it = 0; it < 50; it++) {
      const f = arc(seg, 0, t, 2) - want;
      if (Math.abs(f) < 1e-12 * perimeter) break;
      if (f > 0) hi = t; else lo = t;
      const next = t - f / speed(seg, t);
      t = next > lo && next < hi ? next : (lo + hi) / 2;
    }
    return point(seg, t);
  }
  return { perimeter, at };
}

/** The path scaled about the origin by `k`. */
export function scaled(path, k) {
  const s = (p) => p && [p[0] * k, p[1] * k];
  return { closed: true, points: path.points.map((p) => ({ anchor: s(p.anchor), left: s(p.left), right: s(p.right) })) };
}
