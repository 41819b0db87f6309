// Exported 3D files read back independently of the panel: triangles of an OBJ or ASCII STL,
// and the volume and area of a triangle mesh.

/** Triangles [[a, b, c], …] (each vertex [x, y, z]) of an OBJ file's `v` and `f` lines. */
export function objTriangles(text) {
  const v = [];
  const t = [];
  for (const line of text.split('\n')) {
    const p = line.trim().split(/\s+/);
    if (p[0] === 'v') v.push(p.slice(1, 4).map(Number));
    if (p[0] === 'f') t.push(p.slice(1, 4).map((x) => v[Number(x.split('/')[0]) - 1]));
  }
  return t;
}

/** Triangles of an ASCII STL file (three `vertex` lines a facet). */
export function stlTriangles(text) {
  const v = [...text.matchAll(/^\s*vertex (\S+) (\S+) (\S+)/gm)].map((m) => [Number(m[1]), Number(m[2]), Number(m[3])]);
  const t = [];
  for (let i = 0; i < v.length; i += 3) t.push([v[i], v[i + 1], v[i + 2]]);
  return t;
}

/** Signed volume (divergence theorem): positive when the triangles turn outward. */
export function meshVolume(triangles) {
  let v = 0;
  for (const [a, b, c] of triangles) {
    v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  }
  return v;
}

/** Total area of the triangles. */
export function meshArea(triangles) {
  let area = 0;
  for (const [a, b, c] of triangles) {
    const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    const w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    area += Math.hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]) / 2;
  }
  return area;
}

/**
 * The largest bend (radians: 0 flat, π folded back) across an edge shared by two triangles of the
 * same `g` group of an OBJ file (the panel writes one group per piece): a fold inside a piece,
 * which the pieces cannot take, unlike the seam between the groups.
 */
export function maxBendInsidePieces(text) {
  const v = [];
  const faces = [];
  let group = '';
  for (const line of text.split('\n')) {
    const p = line.trim().split(/\s+/);
    if (p[0] === 'v') v.push(p.slice(1, 4).map(Number));
    if (p[0] === 'g') group = p[1];
    if (p[0] === 'f') faces.push({ f: p.slice(1, 4).map((x) => Number(x.split('/')[0]) - 1), group });
  }
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const normal = ({ f }) => cross(sub(v[f[1]], v[f[0]]), sub(v[f[2]], v[f[0]]));
  const owner = new Map();
  let worst = 0;
  faces.forEach((face, t) => {
    for (let m = 0; m < 3; m++) {
      const i = face.f[m], j = face.f[(m + 1) % 3];
      const u = owner.get(`${j},${i}`);
      if (u === undefined) { owner.set(`${i},${j}`, t); continue; }
      if (faces[u].group !== face.group) continue;
      const n1 = normal(faces[u]), n2 = normal(face);
      const c = cross(n1, n2);
      worst = Math.max(worst, Math.atan2(Math.hypot(...c), n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2]));
    }
  });
  return worst;
}
