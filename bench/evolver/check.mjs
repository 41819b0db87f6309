// Checks of a relaxed sheet from its mesh alone: enclosed volume, edge strain against each
// facet's own flat piece, the sharpest bend inside a piece, and self-intersection.

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const norm = (a) => Math.sqrt(dot(a, a));

/** Signed enclosed volume Σ x_i·(x_j × x_k)/6 (divergence theorem on the oriented mesh). */
export function volume(vertices, triangles) {
  let v = 0;
  for (const [i, j, k] of triangles) v += dot(vertices[i], cross(vertices[j], vertices[k])) / 6;
  return v;
}

/** Largest |3D length / flat length − 1| over every facet's three sides. */
export function maxStrain(vertices, triangles, flat) {
  let m = 0;
  triangles.forEach((t, f) => {
    for (let q = 0; q < 3; q++) {
      const a = flat[f][q], b = flat[f][(q + 1) % 3];
      const l0 = Math.hypot(a[0] - b[0], a[1] - b[1]);
      m = Math.max(m, Math.abs(norm(sub(vertices[t[q]], vertices[t[(q + 1) % 3]])) / l0 - 1));
    }
  });
  return m;
}

/** Largest angle (degrees) between the normals of two facets of the same piece sharing an edge. */
export function maxBend(vertices, triangles, piece) {
  return Math.max(...maxBendPerPiece(vertices, triangles, piece));
}

/** [A's, B's]: the sharpest bend inside each piece, as [`maxBend`]. */
export function maxBendPerPiece(vertices, triangles, piece) {
  const normal = triangles.map(([i, j, k]) => {
    const n = cross(sub(vertices[j], vertices[i]), sub(vertices[k], vertices[i]));
    const l = norm(n);
    return [n[0] / l, n[1] / l, n[2] / l];
  });
  const seen = new Map();
  const m = [0, 0];
  triangles.forEach((t, f) => {
    for (let q = 0; q < 3; q++) {
      const a = t[q], b = t[(q + 1) % 3], key = a < b ? `${a},${b}` : `${b},${a}`;
      const g = seen.get(key);
      if (g === undefined) { seen.set(key, f); continue; }
      if (piece[g] !== piece[f]) continue;
      m[piece[f]] = Math.max(m[piece[f]], (Math.acos(Math.max(-1, Math.min(1, dot(normal[f], normal[g])))) * 180) / Math.PI);
    }
  });
  return m;
}

/** Does the open segment p→q cross the interior of triangle (a, b, c)? (Möller & Trumbore 1997) */
export function segmentHitsTriangle(p, q, a, b, c, eps = 1e-12) {
  const d = sub(q, p), e1 = sub(b, a), e2 = sub(c, a);
  const h = cross(d, e2), det = dot(e1, h);
  if (Math.abs(det) < eps * norm(d) * norm(e1) * norm(e2)) return false; // parallel: not a crossing
  const s = sub(p, a), u = dot(s, h) / det;
  if (u <= eps || u >= 1 - eps) return false;
  const qv = cross(s, e1), v = dot(d, qv) / det;
  if (v <= eps || u + v >= 1 - eps) return false;
  const t = dot(e2, qv) / det;
  return t > eps && t < 1 - eps;
}

/**
 * Pairs of facets that cross each other (an edge of one through the interior of the other).
 * Facets sharing an edge are skipped (they meet along it); facets sharing one vertex are
 * tested with the edges opposite it. Candidate pairs come from a uniform grid of cell `cell`.
 * Returns the number of crossing pairs.
 */
export function selfIntersections(vertices, triangles, cell) {
  const grid = new Map();
  const box = triangles.map((t) => {
    const lo = [0, 1, 2].map((c) => Math.min(...t.map((i) => vertices[i][c])));
    const hi = [0, 1, 2].map((c) => Math.max(...t.map((i) => vertices[i][c])));
    return [lo, hi];
  });
  box.forEach(([lo, hi], f) => {
    const [a, b] = [lo.map((x) => Math.floor(x / cell)), hi.map((x) => Math.floor(x / cell))];
    for (let x = a[0]; x <= b[0]; x++) for (let y = a[1]; y <= b[1]; y++) for (let z = a[2]; z <= b[2]; z++) {
      const key = `${x},${y},${z}`;
      if (!grid.has(key)) grid.set(key, []);
      grid.get(key).push(f);
    }
  });
  const tested = new Set();
  let crossings = 0;
  const P = (i) => vertices[i];
  for (const list of grid.values()) {
    for (let u = 0; u < list.length; u++) for (let w = u + 1; w < list.length; w++) {
      const [f, g] = list[u] < list[w] ? [list[u], list[w]] : [list[w], list[u]];
      const key = f * triangles.length + g;
      if (tested.has(key)) continue;
      tested.add(key);
      const [bf, bg] = [box[f], box[g]];
      if ([0, 1, 2].some((c) => bf[1][c] < bg[0][c] || bg[1][c] < bf[0][c])) continue;
      const s = triangles[f], t = triangles[g];
      const shared = s.filter((i) => t.includes(i));
      if (shared.length >= 2) continue;
      const edgesThrough = (x, y) => {
        const e = shared.length === 1 ? [x.filter((i) => i !== shared[0])] : [[x[0], x[1]], [x[1], x[2]], [x[2], x[0]]];
        return e.some(([i, j]) => segmentHitsTriangle(P(i), P(j), P(y[0]), P(y[1]), P(y[2])));
      };
      if (edgesThrough(s, t) || edgesThrough(t, s)) crossings++;
    }
  }
  return crossings;
}
