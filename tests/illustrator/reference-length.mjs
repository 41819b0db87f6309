// Independent arc length for the tests: chord polylines with Richardson extrapolation.
// A chord polyline with n chords per segment underestimates a smooth curve by c/n² + O(1/n⁴), so
// (4·L(2n) − L(n)) / 3 cancels the 1/n² term. Shares no code with the simulator's Gauss–Legendre.

function point(p0, p1, p2, p3, t) {
  const u = 1 - t;
  return [
    u * u * u * p0[0] + 3 * u * u * t * p1[0] + 3 * u * t * t * p2[0] + t * t * t * p3[0],
    u * u * u * p0[1] + 3 * u * u * t * p1[1] + 3 * u * t * t * p2[1] + t * t * t * p3[1],
  ];
}

function chords(seg, n) {
  let s = 0, prev = seg[0];
  for (let k = 1; k <= n; k++) {
    const q = point(...seg, k / n);
    s += Math.hypot(q[0] - prev[0], q[1] - prev[1]);
    prev = q;
  }
  return s;
}

/** Length of a core-style path {closed, points:[{anchor,left,right}]} (left/right default to anchor). */
export function referenceLength(path, n = 2000) {
  const pts = path.points.map((q) => ({ a: q.anchor, l: q.left || q.anchor, r: q.right || q.anchor }));
  const last = path.closed === false ? pts.length - 1 : pts.length;
  let total = 0;
  for (let i = 0; i < last; i++) {
    const a = pts[i], b = pts[(i + 1) % pts.length];
    const seg = [a.a, a.r, b.l, b.a];
    total += (4 * chords(seg, 2 * n) - chords(seg, n)) / 3;
  }
  return total;
}

/** The same for a simulated PathItem (reads its internal points, not the script-visible API). */
export function referenceLengthOf(item) {
  return referenceLength({ closed: item.closed, points: item._points.map((p) => ({ anchor: p._a, left: p._l, right: p._r })) });
}

export function relErr(got, want) {
  return Math.abs(got - want) / Math.abs(want);
}
