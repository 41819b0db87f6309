// Cubic Bézier helpers for the simulated Illustrator DOM.
// Segment i of a path runs anchor[i] → rightDirection[i] → leftDirection[i+1] → anchor[i+1]
// (Illustrator's PathPoint convention; closed paths wrap to point 0).

/** Point on the cubic p0..p3 at t (Bernstein form). */
export function cubicPoint(p0, p1, p2, p3, t) {
  const u = 1 - t;
  const a = u * u * u, b = 3 * u * u * t, c = 3 * u * t * t, d = t * t * t;
  return [a * p0[0] + b * p1[0] + c * p2[0] + d * p3[0], a * p0[1] + b * p1[1] + c * p2[1] + d * p3[1]];
}

/** Derivative B'(t) = 3[(1-t)²(p1-p0) + 2(1-t)t(p2-p1) + t²(p3-p2)]. */
export function cubicDerivative(p0, p1, p2, p3, t) {
  const u = 1 - t;
  const a = 3 * u * u, b = 6 * u * t, c = 3 * t * t;
  return [
    a * (p1[0] - p0[0]) + b * (p2[0] - p1[0]) + c * (p3[0] - p2[0]),
    a * (p1[1] - p0[1]) + b * (p2[1] - p1[1]) + c * (p3[1] - p2[1]),
  ];
}

// 16-point Gauss–Legendre nodes/weights on [-1, 1] (Abramowitz & Stegun, table 25.4).
const GL_X = [
  0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
  0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499,
];
const GL_W = [
  0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
  0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541,
];

/**
 * Arc length ∫₀¹ |B'(t)| dt by composite 16-point Gauss–Legendre quadrature over `pieces`
 * equal sub-intervals. The integrand is smooth except near cusps, so 64 pieces give
 * ~1e-13 relative error on ordinary segments: "dense quadrature", independent of the core.
 */
export function cubicLength(p0, p1, p2, p3, pieces = 64) {
  let sum = 0;
  const h = 1 / pieces;
  for (let k = 0; k < pieces; k++) {
    const mid = (k + 0.5) * h, half = h / 2;
    for (let i = 0; i < GL_X.length; i++) {
      for (const s of [-1, 1]) {
        const d = cubicDerivative(p0, p1, p2, p3, mid + s * half * GL_X[i]);
        sum += GL_W[i] * half * Math.hypot(d[0], d[1]);
      }
    }
  }
  return sum;
}

/** Real roots in (0,1) of the derivative of one coordinate (for tight bounds). */
function extremaT(a, b, c, d) {
  // B'(t)/3 = A t² + B t + C with A = -a+3b-3c+d, B = 2(a-2b+c), C = b-a
  const A = -a + 3 * b - 3 * c + d, B = 2 * (a - 2 * b + c), C = b - a;
  const out = [];
  if (Math.abs(A) < 1e-15 * (Math.abs(B) + Math.abs(C) + 1e-300)) {
    if (B !== 0) out.push(-C / B);
  } else {
    const disc = B * B - 4 * A * C;
    if (disc >= 0) {
      const r = Math.sqrt(disc);
      out.push((-B + r) / (2 * A), (-B - r) / (2 * A));
    }
  }
  return out.filter((t) => t > 0 && t < 1);
}

/** Tight bounds [minX, minY, maxX, maxY] of a cubic (curve, not control polygon). */
export function cubicBounds(p0, p1, p2, p3) {
  const ts = [0, 1, ...extremaT(p0[0], p1[0], p2[0], p3[0]), ...extremaT(p0[1], p1[1], p2[1], p3[1])];
  let b = [Infinity, Infinity, -Infinity, -Infinity];
  for (const t of ts) {
    const p = cubicPoint(p0, p1, p2, p3, t);
    b = [Math.min(b[0], p[0]), Math.min(b[1], p[1]), Math.max(b[2], p[0]), Math.max(b[3], p[1])];
  }
  return b;
}

/** Segments [p0,p1,p2,p3] of a point list {anchor,left,right}. */
export function segmentsOf(points, closed) {
  const segs = [];
  const n = points.length;
  const last = closed ? n : n - 1;
  for (let i = 0; i < last; i++) {
    const a = points[i], b = points[(i + 1) % n];
    segs.push([a.anchor, a.right, b.left, b.anchor]);
  }
  return segs;
}
