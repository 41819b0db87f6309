// Independent reference geometry for the core's Node tests and bench/core.bench.mjs: arc length by
// composite Gauss–Legendre (not the module's code), closed forms, shape builders.

export function gaussLegendre(n) {
  const out = [];
  for (let i = 0; i < n; i++) {
    let x = Math.cos((Math.PI * (i + 0.75)) / (n + 0.5)), p0, p1, dp;
    for (let it = 0; it < 100; it++) {
      p0 = 1; p1 = x;
      for (let k = 2; k <= n; k++) { const p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k; p0 = p1; p1 = p2; }
      dp = (n * (x * p1 - p0)) / (x * x - 1);
      const dx = p1 / dp; x -= dx;
      if (Math.abs(dx) < 1e-17) break;
    }
    out.push([x, 2 / ((1 - x * x) * dp * dp)]);
  }
  return out;
}
const GL = gaussLegendre(20);

/** Neumaier's compensated summation: the total carries about one rounding error whatever the count. */
export function neumaier() {
  let s = 0, comp = 0;
  return {
    add(v) { const t = s + v; comp += Math.abs(s) >= Math.abs(v) ? (s - t) + v : (v - t) + s; s = t; },
    get total() { return s + comp; },
  };
}

/** Length of a cubic (4 control points), 20-point Gauss–Legendre on 64 panels, compensated sum. */
export function cubicLength(c, panels = 64) {
  const d = [0, 1, 2].map((i) => [c[i + 1][0] - c[i][0], c[i + 1][1] - c[i][1]]);
  const speed = (t) => {
    const u = 1 - t;
    const x = 3 * (u * u * d[0][0] + 2 * u * t * d[1][0] + t * t * d[2][0]);
    const y = 3 * (u * u * d[0][1] + 2 * u * t * d[1][1] + t * t * d[2][1]);
    return Math.hypot(x, y);
  };
  const sum = neumaier();
  const h = 1 / panels;
  for (let k = 0; k < panels; k++) for (const [x, w] of GL) sum.add(0.5 * h * w * speed(k * h + 0.5 * h * (x + 1)));
  return sum.total;
}

export function segments(path) {
  const p = path.points, n = p.length;
  return p.map((a, i) => { const b = p[(i + 1) % n]; return [a.anchor, a.right ?? a.anchor, b.left ?? b.anchor, b.anchor]; });
}

/** Perimeter: the segments' reference lengths, summed with compensation (many segments stay exact). */
export function perimeter(path) {
  const sum = neumaier();
  for (const c of segments(path)) sum.add(cubicLength(c));
  return sum.total;
}

/** Ellipse (a, b) at c as n cubic arcs (handle k = 4/3 tan(θ/4)), ccw unless cw. */
export function ellipse(c, a, b, n = 4, cw = false) {
  const th = (2 * Math.PI) / n, k = (4 / 3) * Math.tan(th / 4), s = cw ? -1 : 1;
  const points = [];
  for (let i = 0; i < n; i++) {
    const t = s * th * i, sn = Math.sin(t), cs = Math.cos(t);
    const at = [c[0] + a * cs, c[1] + b * sn], tan = [-sn * s, cs * s];
    points.push({ anchor: at, left: [at[0] - a * k * tan[0], at[1] - b * k * tan[1]], right: [at[0] + a * k * tan[0], at[1] + b * k * tan[1]] });
  }
  return { closed: true, points };
}

/** The kidney of issue 14, r = 60(1 + 0.35 cos 2θ − 0.25 cos θ + 0.2 sin 3θ), through `n` anchors
 * with Catmull–Rom tangents (the bench's `polar`). */
export function kidneyThrough(n) {
  const rk = (t) => 60 * (1 + 0.35 * Math.cos(2 * t) - 0.25 * Math.cos(t) + 0.2 * Math.sin(3 * t));
  const pts = Array.from({ length: n }, (_, k) => { const t = (2 * Math.PI * k) / n; return [rk(t) * Math.cos(t), rk(t) * Math.sin(t)]; });
  return {
    closed: true,
    points: pts.map(([x, y], i) => {
      const p = pts[(i + n - 1) % n], q = pts[(i + 1) % n];
      const t = [(q[0] - p[0]) / 6, (q[1] - p[1]) / 6];
      return { anchor: [x, y], left: [x - t[0], y - t[1]], right: [x + t[0], y + t[1]] };
    }),
  };
}

export const polygon = (pts) => ({ closed: true, points: pts.map((a) => ({ anchor: a })) });

/** Ellipse perimeter by the AGM (Gauss–Kummer): 2π/AGM(a,b) · (a² − Σ 2^{n−1} c_n²). */
export function ellipsePerimeter(a, b) {
  let an = Math.max(a, b), bn = Math.min(a, b), sum = 0.5 * (an * an - bn * bn), pow = 0.5;
  const a0 = an;
  for (let i = 0; i < 60; i++) {
    const c = 0.5 * (an - bn); [an, bn] = [0.5 * (an + bn), Math.sqrt(an * bn)]; pow *= 2; sum += pow * c * c;
    if (c === 0) break;
  }
  return ((2 * Math.PI) / an) * (a0 * a0 - sum);
}

export const rel = (got, want) => Math.abs(got - want) / Math.abs(want);
