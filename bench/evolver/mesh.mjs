// Quality triangle mesh of one flat piece for the Evolver peer: the seam samples on the outline,
// interior points on a hexagonal lattice of the same spacing, Delaunay triangulation (delaunator,
// Mapbox's robust-predicate implementation) clipped to the outline, three Laplacian smoothing
// passes and a final Delaunay. Every outline edge is checked to be a mesh edge: it is one when
// its diametral circle is empty (Gabriel), which the lattice's margin of 0.6 h from the outline
// guarantees away from necks narrower than ~2 h (Shewchuk, "Delaunay Refinement Algorithms for
// Triangular Mesh Generation", 2002, §2).
import Delaunator from 'delaunator';

/** Is p inside the closed polygon `poly` (even–odd rule)? */
export function inside(poly, p) {
  let c = false;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    const a = poly[i], b = poly[j];
    if ((a[1] > p[1]) !== (b[1] > p[1]) && p[0] < ((b[0] - a[0]) * (p[1] - a[1])) / (b[1] - a[1]) + a[0]) c = !c;
  }
  return c;
}

/** Distance from p to the closed polyline `poly`. */
function outlineDistance(poly, p) {
  let d = Infinity;
  for (let i = 0; i < poly.length; i++) {
    const a = poly[i], b = poly[(i + 1) % poly.length];
    const ex = b[0] - a[0], ey = b[1] - a[1];
    const t = Math.max(0, Math.min(1, ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / (ex * ex + ey * ey)));
    d = Math.min(d, Math.hypot(p[0] - a[0] - t * ex, p[1] - a[1] - t * ey));
  }
  return d;
}

const orient = (a, b, c) => (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);

/** Delaunay triangles of `pts` inside `outline` (the first `n` points), counter-clockwise. */
function clipped(pts, n) {
  const poly = pts.slice(0, n);
  const d = Delaunator.from(pts);
  const tris = [];
  for (let t = 0; t < d.triangles.length; t += 3) {
    let [i, j, k] = [d.triangles[t], d.triangles[t + 1], d.triangles[t + 2]];
    const c = [0, 1].map((q) => (pts[i][q] + pts[j][q] + pts[k][q]) / 3);
    if (!inside(poly, c)) continue;
    if (orient(pts[i], pts[j], pts[k]) < 0) [j, k] = [k, j];
    tris.push([i, j, k]);
  }
  return tris;
}

/**
 * Mesh of the flat piece whose outline is the polygon `outline` (seam samples, in seam order,
 * either orientation), interior spacing `h`. Returns `{ points, triangles }`: points[0..n) are
 * the outline samples, triangles counter-clockwise in the piece's plane. Throws with the reason
 * if an outline edge is missing or the mesh is not a disk.
 */
export function meshPiece(outline, h) {
  const n = outline.length;
  const xs = outline.map((p) => p[0]), ys = outline.map((p) => p[1]);
  const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  const pts = outline.map((p) => [p[0], p[1]]);
  const dy = (h * Math.sqrt(3)) / 2;
  for (let r = 0, y = y0 + dy / 2; y < y1; r++, y += dy) {
    for (let x = x0 + ((r % 2) * h) / 2; x < x1; x += h) {
      if (inside(outline, [x, y]) && outlineDistance(outline, [x, y]) >= 0.6 * h) pts.push([x, y]);
    }
  }
  // Laplacian smoothing of the interior points over the Delaunay neighbours (outline fixed).
  for (let pass = 0; pass < 3; pass++) {
    const sum = pts.map(() => [0, 0, 0]);
    for (const t of clipped(pts, n)) {
      for (let q = 0; q < 3; q++) {
        const a = t[q], b = t[(q + 1) % 3];
        sum[a][0] += pts[b][0]; sum[a][1] += pts[b][1]; sum[a][2]++;
        sum[b][0] += pts[a][0]; sum[b][1] += pts[a][1]; sum[b][2]++;
      }
    }
    for (let i = n; i < pts.length; i++) {
      if (sum[i][2] > 0) pts[i] = [sum[i][0] / sum[i][2], sum[i][1] / sum[i][2]];
    }
  }
  const triangles = clipped(pts, n);
  const edges = new Set();
  for (const t of triangles) for (let q = 0; q < 3; q++) edges.add(`${t[q]},${t[(q + 1) % 3]}`);
  for (let k = 0; k < n; k++) {
    const a = k, b = (k + 1) % n;
    if (!edges.has(`${a},${b}`) && !edges.has(`${b},${a}`)) {
      throw new Error(`meshPiece: outline edge ${a}–${b} is not a Delaunay edge (a neck narrower than the spacing ${h.toFixed(3)}?)`);
    }
  }
  // A triangulated disk with V vertices of which n on the outline has 2V − n − 2 triangles.
  if (triangles.length !== 2 * pts.length - n - 2) {
    throw new Error(`meshPiece: ${triangles.length} triangles for ${pts.length} points (${n} on the outline): not a disk`);
  }
  return { points: pts, triangles };
}
