// The glued sheet the Evolver peer relaxes: both flat pieces meshed, their seam samples
// identified, every triangle keeping its corners' positions on its own flat piece (a seam vertex
// has one flat position per piece), and a closed starting shape.
//
// Gluing (the contract's convention, core/src/simulate/mod.rs): the point at arc length s on A,
// walked counter-clockwise from its first anchor, meets the point at arc length offset + s on B,
// walked clockwise from its first anchor.
import { arcTable, signedArea } from './outline.mjs';
import { meshPiece } from './mesh.mjs';

/** Seam samples of both pieces: `n` points each, seam vertex k of A meets seam vertex k of B. */
export function seamSamples(pieces, offset, n) {
  const [ta, tb] = pieces.map(arcTable);
  const P = ta.perimeter;
  // Walk direction relative to each path's own direction: A counter-clockwise, B clockwise.
  const sa = signedArea(pieces[0]) > 0 ? 1 : -1;
  const sb = signedArea(pieces[1]) > 0 ? -1 : 1;
  const step = P / n, stepB = tb.perimeter / n;
  const a = [], b = [];
  for (let k = 0; k < n; k++) {
    a.push(ta.at(sa * k * step));
    b.push(tb.at(sb * (offset + k * stepB)));
  }
  return { a, b, perimeter: P, perimeters: [ta.perimeter, tb.perimeter] };
}

/**
 * Solves the uniform-weight Tutte problem (each interior point the mean of its neighbours, the
 * outline pinned on the unit circle at equal angles, Tutte 1963) by conjugate gradients; returns
 * the disk position of every point of the piece's mesh.
 */
function tutteDisk(mesh, n) {
  const m = mesh.points.length;
  const nb = Array.from({ length: m }, () => new Set());
  for (const t of mesh.triangles) for (let q = 0; q < 3; q++) { nb[t[q]].add(t[(q + 1) % 3]); nb[t[(q + 1) % 3]].add(t[q]); }
  const uv = mesh.points.map((_, i) => (i < n ? [Math.cos((2 * Math.PI * i) / n), Math.sin((2 * Math.PI * i) / n)] : [0, 0]));
  for (const c of [0, 1]) {
    // A x = b on the interior unknowns, A = degree − adjacency (SPD), b = pinned neighbours' sum.
    const idx = (i) => i - n, size = m - n;
    const apply = (x) => {
      const y = new Float64Array(size);
      for (let i = n; i < m; i++) {
        let s = nb[i].size * x[idx(i)];
        for (const j of nb[i]) if (j >= n) s -= x[idx(j)];
        y[idx(i)] = s;
      }
      return y;
    };
    const b = new Float64Array(size);
    for (let i = n; i < m; i++) for (const j of nb[i]) if (j < n) b[idx(i)] += uv[j][c];
    const x = new Float64Array(size);
    const r = Float64Array.from(b), p = Float64Array.from(b);
    let rr = r.reduce((s, v) => s + v * v, 0);
    const stop = 1e-24 * Math.max(rr, 1e-300);
    for (let it = 0; it < 4 * size && rr > stop; it++) {
      const ap = apply(p);
      const alpha = rr / p.reduce((s, v, i) => s + v * ap[i], 0);
      for (let i = 0; i < size; i++) { x[i] += alpha * p[i]; r[i] -= alpha * ap[i]; }
      const next = r.reduce((s, v) => s + v * v, 0);
      for (let i = 0; i < size; i++) p[i] = r[i] + (next / rr) * p[i];
      rr = next;
    }
    for (let i = n; i < m; i++) uv[i][c] = x[idx(i)];
  }
  return uv;
}

/**
 * The glued sheet of `pieces` at `offset` with `n` seam vertices and interior spacing equal to
 * the seam step. The start is a pillow: the seam on a circle of the perimeter, each piece's
 * Tutte disk lifted to the paraboloid z = ±start·R·(1 − ρ²) (R the circle's radius).
 * Returns `{ vertices, triangles, flat, piece, seam, perimeter, n }`: vertices[0..n) are the seam
 * in order; triangles are consistently oriented (outward for a positive volume).
 */
export function glue(pieces, offset, n, start = 0.5) {
  const s = seamSamples(pieces, offset, n);
  const h = s.perimeter / n;
  const R = s.perimeter / (2 * Math.PI);
  const vertices = [];
  for (let k = 0; k < n; k++) vertices.push([R * Math.cos((2 * Math.PI * k) / n), R * Math.sin((2 * Math.PI * k) / n), 0]);
  const triangles = [], flat = [], piece = [];
  [s.a, s.b].forEach((outline, which) => {
    const mesh = meshPiece(outline, h);
    const uv = tutteDisk(mesh, n);
    const id = mesh.points.map((_, i) => (i < n ? i : vertices.length + i - n));
    for (let i = n; i < mesh.points.length; i++) {
      const [u, v] = uv[i], z = start * R * (1 - u * u - v * v);
      vertices.push([R * u, R * v, which === 0 ? z : -z]);
    }
    // A's seam runs counter-clockwise in A's plane, B's clockwise in B's: triangles that are
    // counter-clockwise in their own plane therefore cross every seam edge in opposite senses.
    for (const t of mesh.triangles) {
      triangles.push(t.map((i) => id[i]));
      flat.push(t.map((i) => mesh.points[i]));
      piece.push(which);
    }
  });
  return { vertices, triangles, flat, piece, seam: [...Array(n).keys()], perimeter: s.perimeter, n, h };
}
