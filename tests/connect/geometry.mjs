// Independent geometry for the connect tests: flatten paths by dense de Casteljau evaluation,
// measure arc length along the polyline, find nearest points, test insideness. Nothing here
// calls the module's own arc-length code.

/** de Casteljau evaluation of the cubic p0 p1 p2 p3 at t. */
export function casteljau(p0, p1, p2, p3, t) {
  const l = (a, b) => [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
  const a = l(p0, p1), b = l(p1, p2), c = l(p2, p3);
  const d = l(a, b), e = l(b, c);
  return l(d, e);
}

/** Dense polyline of a closed path (contract shape), `per` samples per segment, closed (last = first). */
export function flatten(path, per = 2000) {
  const P = path.points, n = P.length, out = [];
  for (let i = 0; i < n; i++) {
    const a = P[i], b = P[(i + 1) % n];
    const p0 = a.anchor, p1 = a.right ?? a.anchor, p2 = b.left ?? b.anchor, p3 = b.anchor;
    for (let j = 0; j < per; j++) out.push(casteljau(p0, p1, p2, p3, j / per));
  }
  out.push(out[0]);
  return out;
}

/** Cumulative chord lengths of a polyline. */
export function cumulative(poly) {
  const c = [0];
  for (let i = 1; i < poly.length; i++) c.push(c[i - 1] + Math.hypot(poly[i][0] - poly[i - 1][0], poly[i][1] - poly[i - 1][1]));
  return c;
}

/** Nearest point of a polyline to q: { dist, s (arc length from the start), i }. */
export function nearest(poly, cum, q) {
  let best = { dist: Infinity, s: 0, i: 0 };
  for (let i = 0; i + 1 < poly.length; i++) {
    const a = poly[i], b = poly[i + 1];
    const dx = b[0] - a[0], dy = b[1] - a[1], L2 = dx * dx + dy * dy;
    let t = L2 > 0 ? ((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / L2 : 0;
    t = Math.max(0, Math.min(1, t));
    const x = a[0] + t * dx, y = a[1] + t * dy, d = Math.hypot(q[0] - x, q[1] - y);
    if (d < best.dist) best = { dist: d, s: cum[i] + t * (cum[i + 1] - cum[i]), i };
  }
  return best;
}

/** Even-odd point in polygon. */
export function inside(poly, q) {
  let c = false;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    const a = poly[i], b = poly[j];
    if ((a[1] > q[1]) !== (b[1] > q[1]) && q[0] < ((b[0] - a[0]) * (q[1] - a[1])) / (b[1] - a[1]) + a[0]) c = !c;
  }
  return c;
}

/** Shoelace area of a polyline (positive = counter-clockwise, y-up). */
export function area(poly) {
  let s = 0;
  for (let i = 0; i + 1 < poly.length; i++) s += poly[i][0] * poly[i + 1][1] - poly[i + 1][0] * poly[i][1];
  return s / 2;
}

/** Point and outward unit normal at arc length s along a polyline of total length cum.at(-1). */
export function frameAt(poly, cum, s) {
  const P = cum[cum.length - 1];
  s = ((s % P) + P) % P;
  let lo = 0, hi = cum.length - 1;
  while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (cum[mid] <= s) lo = mid; else hi = mid; }
  const a = poly[lo], b = poly[lo + 1], L = cum[lo + 1] - cum[lo], t = L > 0 ? (s - cum[lo]) / L : 0;
  const tx = (b[0] - a[0]) / (L || 1), ty = (b[1] - a[1]) / (L || 1);
  const ccw = area(poly) > 0;
  // Outward normal: right of the direction of travel on a ccw polygon.
  const n = ccw ? [ty, -tx] : [-ty, tx];
  return { p: [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])], n };
}

/** Signed difference a − b wrapped into (−P/2, P/2]. */
export function wrapDiff(a, b, P) {
  let d = (((a - b) % P) + P) % P;
  if (d > P / 2) d -= P;
  return d;
}

/** A copy of a path drawn the other way round, starting at the same first anchor. */
export function reversed(path) {
  const n = path.points.length;
  return {
    closed: true,
    points: Array.from({ length: n }, (_, i) => {
      const k = path.points[(n - i) % n];
      return { anchor: k.anchor, left: k.right ?? k.anchor, right: k.left ?? k.anchor };
    }),
  };
}

/** The path scaled by f about the origin. */
export function scaled(path, f) {
  const s = (p) => (p ? [p[0] * f, p[1] * f] : p);
  return { closed: true, points: path.points.map((k) => ({ anchor: s(k.anchor), left: s(k.left), right: s(k.right) })) };
}

/** A closed polygon path from corner points. */
export function polygon(pts) {
  return { closed: true, points: pts.map((a) => ({ anchor: a })) };
}

// ---- Exact-to-round-off measures on the cubics themselves (no polyline error) ----

/** The cubic segments [p0, p1, p2, p3] of a closed path, in drawing order. */
export function cubics(path) {
  const P = path.points, n = P.length;
  return P.map((a, i) => {
    const b = P[(i + 1) % n];
    return [a.anchor, a.right ?? a.anchor, b.left ?? b.anchor, b.anchor];
  });
}

/** B'(t) of a cubic from its Bernstein form: 3[(1−t)²(p1−p0) + 2t(1−t)(p2−p1) + t²(p3−p2)]. */
function deriv(c, t) {
  const u = 1 - t, k = [3 * u * u, 6 * t * u, 3 * t * t];
  return [0, 1].map((j) => k[0] * (c[1][j] - c[0][j]) + k[1] * (c[2][j] - c[1][j]) + k[2] * (c[3][j] - c[2][j]));
}

function deriv2(c, t) {
  const u = 1 - t;
  return [0, 1].map((j) => 6 * (u * (c[2][j] - 2 * c[1][j] + c[0][j]) + t * (c[3][j] - 2 * c[2][j] + c[1][j])));
}

// 8-point Gauss–Legendre nodes and weights on [−1, 1].
const GL8 = [
  [0.1834346424956498, 0.3626837833783620], [-0.1834346424956498, 0.3626837833783620],
  [0.5255324099163290, 0.3137066458778873], [-0.5255324099163290, 0.3137066458778873],
  [0.7966664774136267, 0.2223810344533745], [-0.7966664774136267, 0.2223810344533745],
  [0.9602898564975363, 0.1012285362903763], [-0.9602898564975363, 0.1012285362903763],
];

/** ∫_a^b |B'(t)| dt by composite 8-point Gauss–Legendre on `pieces` equal panels. */
export function arcLength(c, a = 0, b = 1, pieces = 64) {
  let s = 0;
  const h = (b - a) / pieces;
  for (let i = 0; i < pieces; i++) {
    const m = a + (i + 0.5) * h;
    for (const [x, w] of GL8) {
      const d = deriv(c, m + 0.5 * h * x);
      s += 0.5 * h * w * Math.hypot(d[0], d[1]);
    }
  }
  return s;
}

/** A closed path prepared for exact queries: its cubics, their lengths and cumulative starts. */
export function exact(path) {
  const cs = cubics(path);
  const lens = cs.map((c) => arcLength(c));
  const start = [0];
  for (const l of lens) start.push(start[start.length - 1] + l);
  return { cs, lens, start, total: start[start.length - 1], poly: flatten(path, 400) };
}

/**
 * Nearest point of the path to q: coarse search on a 400-per-segment polyline, then Newton on
 * d/dt |B(t) − q|² = 2 B'·(B − q) in the cubic found (and its neighbours). Returns dist, the
 * arc length s from the first anchor, and the segment/t.
 */
export function nearestExact(ex, q) {
  const per = 400, n = ex.cs.length;
  let bi = 0, bd = Infinity;
  for (let i = 0; i < ex.poly.length - 1; i++) {
    const d = Math.hypot(ex.poly[i][0] - q[0], ex.poly[i][1] - q[1]);
    if (d < bd) { bd = d; bi = i; }
  }
  let best = null;
  for (const off of [-1, 0, 1]) {
    const idx = bi + off;
    if (idx < 0) continue;
    const seg = Math.floor(idx / per) % n;
    const c = ex.cs[seg];
    let t = Math.min(1, Math.max(0, (idx - Math.floor(idx / per) * per) / per));
    for (let it = 0; it < 50; it++) {
      const p = casteljau(c[0], c[1], c[2], c[3], t), d1 = deriv(c, t), d2 = deriv2(c, t);
      const r = [p[0] - q[0], p[1] - q[1]];
      const f = d1[0] * r[0] + d1[1] * r[1];
      const fp = d1[0] * d1[0] + d1[1] * d1[1] + d2[0] * r[0] + d2[1] * r[1];
      if (fp <= 0) break;
      const nt = Math.min(1, Math.max(0, t - f / fp));
      if (Math.abs(nt - t) < 1e-15) { t = nt; break; }
      t = nt;
    }
    const p = casteljau(c[0], c[1], c[2], c[3], t);
    const dist = Math.hypot(p[0] - q[0], p[1] - q[1]);
    if (!best || dist < best.dist) best = { dist, seg, t, s: ex.start[seg] + arcLength(c, 0, t) };
  }
  return best;
}
