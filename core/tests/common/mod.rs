//! Test helpers: an arc length computed independently of the crate (and of kurbo), shape
//! builders, and closed forms.
#![allow(dead_code)]

use dformer::api::path::{PathDto, PointDto};
use proptest::prelude::*;

pub type P = [f64; 2];

/// P_n(x) and P_n'(x) by the three-term recurrence k·P_k = (2k−1)·x·P_{k−1} − (k−1)·P_{k−2}
/// and P_n' = n·(x·P_n − P_{n−1}) / (x² − 1).
fn legendre(n: usize, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    for k in 2..=n {
        let k = k as f64;
        let p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
    }
    (p1, n as f64 * (x * p1 - p0) / (x * x - 1.0))
}

/// Gauss–Legendre nodes and weights on [-1, 1] by Newton's method on P_n; weight 2/((1−x²)·P_n'(x)²).
pub fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        for _ in 0..100 {
            let (p, dp) = legendre(n, x);
            let dx = p / dp;
            x -= dx;
            if dx.abs() < 1e-17 {
                break;
            }
        }
        let (_, dp) = legendre(n, x);
        out.push((x, 2.0 / ((1.0 - x * x) * dp * dp)));
    }
    out
}

/// Neumaier-compensated sum.
pub fn ksum(xs: impl IntoIterator<Item = f64>) -> f64 {
    let (mut s, mut c) = (0.0f64, 0.0f64);
    for x in xs {
        let t = s + x;
        c += if s.abs() >= x.abs() { (s - t) + x } else { (x - t) + s };
        s = t;
    }
    s + c
}

/// The speed |B'(t)| of the cubic p0..p3, evaluated from control-point *differences*
/// (translation-exact).
fn speed(p: [P; 4]) -> impl Fn(f64) -> f64 {
    let d = |i: usize, k: usize| p[i + 1][k] - p[i][k];
    let (d0, d1, d2) = ([d(0, 0), d(0, 1)], [d(1, 0), d(1, 1)], [d(2, 0), d(2, 1)]);
    move |t: f64| {
        let u = 1.0 - t;
        let x = 3.0 * (u * u * d0[0] + 2.0 * u * t * d1[0] + t * t * d2[0]);
        let y = 3.0 * (u * u * d0[1] + 2.0 * u * t * d1[1] + t * t * d2[1]);
        x.hypot(y)
    }
}

/// Length of the cubic p0..p3 by composite 20-point Gauss–Legendre on `panels` equal panels,
/// with the speed |B'(t)| evaluated from control-point *differences* (translation-exact) and
/// compensated summation. Independent of kurbo and of the crate.
pub fn cubic_len_truth(p: [P; 4], panels: usize) -> f64 {
    let gl = gauss_legendre(20);
    let speed = &speed(p);
    let h = 1.0 / panels as f64;
    ksum((0..panels).flat_map(|k| {
        let a = k as f64 * h;
        gl.iter().map(move |&(x, w)| 0.5 * h * w * speed(a + 0.5 * h * (x + 1.0))).collect::<Vec<_>>()
    }))
}

/// Length of the cubic by adaptive bisection of 20-point Gauss–Legendre panels: a panel is
/// accepted when it agrees with the sum of its two halves to 1e-17 of the segment's length
/// (or 60 levels deep). Handles that almost collapse put a near-singularity of |B'| next to an
/// end point, which any fixed panel grid can miss; bisection resolves it. Independent of kurbo.
pub fn cubic_len_adaptive(p: [P; 4]) -> f64 {
    let gl = gauss_legendre(20);
    let speed = &speed(p);
    let panel = |a: f64, b: f64| ksum(gl.iter().map(|&(x, w)| 0.5 * (b - a) * w * speed(a + 0.5 * (b - a) * (x + 1.0))));
    let scale = cubic_len_truth(p, 16).abs().max(f64::MIN_POSITIVE);
    fn rec(a: f64, b: f64, whole: f64, depth: u32, tol: f64, panel: &dyn Fn(f64, f64) -> f64, out: &mut Vec<f64>) {
        let m = 0.5 * (a + b);
        let (l, r) = (panel(a, m), panel(m, b));
        if depth >= 60 || (l + r - whole).abs() <= tol {
            out.push(l);
            out.push(r);
        } else {
            rec(a, m, l, depth + 1, tol, panel, out);
            rec(m, b, r, depth + 1, tol, panel, out);
        }
    }
    let mut parts = Vec::new();
    for k in 0..8 {
        let (a, b) = (k as f64 / 8.0, (k + 1) as f64 / 8.0);
        rec(a, b, panel(a, b), 0, 1e-17 * scale, &panel, &mut parts);
    }
    ksum(parts)
}

/// Perimeter of a closed path by [`cubic_len_adaptive`] on every segment.
pub fn perimeter_truth(path: &PathDto) -> f64 {
    let n = path.points.len();
    ksum((0..n).map(|i| {
        let a = &path.points[i];
        let b = &path.points[(i + 1) % n];
        let p = [a.anchor, a.right.unwrap_or(a.anchor), b.left.unwrap_or(b.anchor), b.anchor];
        cubic_len_adaptive(p)
    }))
}

/// Ellipse perimeter by the arithmetic–geometric mean (Gauss–Kummer closed form):
/// `L = 2π/AGM(a, b) · (a² − Σ_{n≥0} 2^{n−1} c_n²)`, `c_0² = a² − b²`, `c_{n+1} = (a_n − b_n)/2`.
pub fn ellipse_perimeter(a: f64, b: f64) -> f64 {
    let (mut an, mut bn) = (a.max(b), a.min(b));
    let mut sum = 0.5 * (an * an - bn * bn);
    let mut pow = 0.5;
    for _ in 0..60 {
        let c = 0.5 * (an - bn);
        let (a1, b1) = (0.5 * (an + bn), (an * bn).sqrt());
        an = a1;
        bn = b1;
        pow *= 2.0;
        sum += pow * c * c;
        if c.abs() < 1e-300 || c == 0.0 {
            break;
        }
    }
    2.0 * std::f64::consts::PI / an * (a.max(b).powi(2) - sum)
}

/// Closed path from (anchor, left, right) triples.
pub fn path(points: &[(P, P, P)]) -> PathDto {
    PathDto {
        closed: true,
        points: points.iter().map(|&(a, l, r)| PointDto { anchor: a, left: Some(l), right: Some(r) }).collect(),
    }
}

/// Closed polygon (corners only; handles omitted as the contract allows).
pub fn polygon(pts: &[P]) -> PathDto {
    PathDto { closed: true, points: pts.iter().map(|&a| PointDto { anchor: a, left: None, right: None }).collect() }
}

/// Ellipse (a, b) centred at c as n cubic arcs, the standard circle arc with handle length
/// `k = 4/3 tan(θ/4)` mapped by diag(a, b); counter-clockwise unless `cw`.
pub fn ellipse(c: P, a: f64, b: f64, n: usize, cw: bool) -> PathDto {
    let th = std::f64::consts::TAU / n as f64;
    let k = 4.0 / 3.0 * (th / 4.0).tan();
    let s = if cw { -1.0 } else { 1.0 };
    let pts: Vec<(P, P, P)> = (0..n)
        .map(|i| {
            let t = s * th * i as f64;
            let (sn, cs) = t.sin_cos();
            let at = [c[0] + a * cs, c[1] + b * sn];
            // Tangent direction of travel (d/dt of (cos, sin) times s).
            let tan = [-sn * s, cs * s];
            let r = [at[0] + a * k * tan[0], at[1] + b * k * tan[1]];
            let l = [at[0] - a * k * tan[0], at[1] - b * k * tan[1]];
            (at, l, r)
        })
        .collect();
    path(&pts)
}

/// The path scaled by `scale` about the origin, then shifted by `offset`.
pub fn moved(p: &PathDto, scale: f64, offset: P) -> PathDto {
    mapped(p, |q| [q[0] * scale + offset[0], q[1] * scale + offset[1]])
}

/// The path with every anchor and handle mapped by `f` (an affine map maps the curve exactly).
pub fn mapped(p: &PathDto, f: impl Fn(P) -> P) -> PathDto {
    let mut out = p.clone();
    for pt in &mut out.points {
        pt.anchor = f(pt.anchor);
        pt.left = pt.left.map(&f);
        pt.right = pt.right.map(&f);
    }
    out
}

/// The same outline drawn the other way round, starting at the same anchor (handles swap sides).
pub fn reversed(p: &PathDto) -> PathDto {
    let n = p.points.len();
    let mut out = p.clone();
    out.points = (0..n)
        .map(|i| {
            let q = &p.points[(n - i) % n];
            PointDto { anchor: q.anchor, left: q.right, right: q.left }
        })
        .collect();
    out
}

pub fn rel(got: f64, want: f64) -> f64 {
    (got - want).abs() / want.abs()
}

/// A star-shaped smooth outline: radii in [0.5, 2] at jittered angles, Hermite handles scaled by
/// `k ∈ [0, 1]` (0: a polygon). Usually simple; callers skip the rare self-intersecting one.
pub fn star() -> impl Strategy<Value = PathDto> {
    (3usize..30, 0.0f64..=1.0, -1e3f64..1e3, -1e3f64..1e3, 0.01f64..100.0, any::<bool>())
        .prop_flat_map(|(n, k, ox, oy, s, cw)| {
            (prop::collection::vec((0.5f64..2.0, -0.3f64..0.3), n), Just((k, ox, oy, s, cw)))
        })
        .prop_map(|(rs, (k, ox, oy, s, cw))| {
            let n = rs.len();
            let h = std::f64::consts::TAU / n as f64;
            let at = |i: usize| {
                let (r, j) = rs[i % n];
                let t = (i as f64 + j) * h * if cw { -1.0 } else { 1.0 };
                [ox + s * r * t.cos(), oy + s * r * t.sin()]
            };
            let pts: Vec<(P, P, P)> = (0..n)
                .map(|i| {
                    let (a, prev, next) = (at(i), at(i + n - 1), at(i + 1));
                    let d = [(next[0] - prev[0]) / 6.0 * k, (next[1] - prev[1]) / 6.0 * k];
                    (a, [a[0] - d[0], a[1] - d[1]], [a[0] + d[0], a[1] + d[1]])
                })
                .collect();
            path(&pts)
        })
}

pub type Cubic = [P; 4];

/// The segments of a closed path as control points.
pub fn cubics(p: &PathDto) -> Vec<Cubic> {
    let n = p.points.len();
    (0..n)
        .map(|i| {
            let (a, b) = (&p.points[i], &p.points[(i + 1) % n]);
            [a.anchor, a.right.unwrap_or(a.anchor), b.left.unwrap_or(b.anchor), b.anchor]
        })
        .collect()
}

/// B(t).
pub fn eval(c: &Cubic, t: f64) -> P {
    let u = 1.0 - t;
    let w = [u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t];
    [0, 1].map(|k| (0..4).map(|i| w[i] * c[i][k]).sum())
}

/// B'(t).
pub fn deriv(c: &Cubic, t: f64) -> P {
    let u = 1.0 - t;
    let w = [3.0 * u * u, 6.0 * u * t, 3.0 * t * t];
    [0, 1].map(|k| (0..3).map(|i| w[i] * (c[i + 1][k] - c[i][k])).sum())
}

/// B''(t).
pub fn deriv2(c: &Cubic, t: f64) -> P {
    [0, 1].map(|k| 6.0 * ((1.0 - t) * (c[2][k] - 2.0 * c[1][k] + c[0][k]) + t * (c[3][k] - 2.0 * c[2][k] + c[1][k])))
}

/// The first part of `c`, up to parameter `t` (de Casteljau).
pub fn head(c: &Cubic, t: f64) -> Cubic {
    let lerp = |a: P, b: P| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
    let (p01, p12, p23) = (lerp(c[0], c[1]), lerp(c[1], c[2]), lerp(c[2], c[3]));
    let (p012, p123) = (lerp(p01, p12), lerp(p12, p23));
    [c[0], p01, p012, lerp(p012, p123)]
}

/// Two random pieces scaled to their mean perimeter, or `None` for the strategies' rare
/// self-intersecting draw; any other refusal fails the test.
pub fn normalized_pair(a: PathDto, b: PathDto) -> Result<Option<Vec<PathDto>>, TestCaseError> {
    use dformer::api::{self, normalize::NormalizeOptionsDto, value::Value};
    let opts = NormalizeOptionsDto { target: Some(Value::Text("mean".into())), ..Default::default() };
    match api::normalize(&[a, b], &opts) {
        Ok(r) => Ok(Some(r.paths)),
        Err(dformer::Error::SelfIntersection { .. }) => Ok(None),
        Err(e) => Err(TestCaseError::fail(format!("valid pieces rejected: {e}"))),
    }
}

/// Both pieces' segments, their independent lengths ([`cubic_len_adaptive`]) and the first
/// piece's perimeter.
pub fn segments_and_lengths(pieces: &[PathDto]) -> ([Vec<Cubic>; 2], Vec<Vec<f64>>, f64) {
    let segs = [cubics(&pieces[0]), cubics(&pieces[1])];
    let lens: Vec<Vec<f64>> = segs.iter().map(|s| s.iter().map(|&c| cubic_len_adaptive(c)).collect()).collect();
    let perimeter = ksum(lens[0].iter().copied());
    (segs, lens, perimeter)
}

/// The closed path as a polyline of `per_seg` chords per segment (uniform in t), first point
/// not repeated.
pub fn flatten(p: &PathDto, per_seg: usize) -> Vec<P> {
    cubics(p).iter().flat_map(|c| (0..per_seg).map(move |j| eval(c, j as f64 / per_seg as f64))).collect()
}

/// Even–odd point-in-polygon test (crossings of a ray to +x).
pub fn inside_poly(poly: &[P], q: P) -> bool {
    let mut inside = false;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        if (a[1] > q[1]) != (b[1] > q[1]) && q[0] < a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]) {
            inside = !inside;
        }
    }
    inside
}

/// Distance from `q` to the segment ab.
pub fn dist_seg(q: P, a: P, b: P) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l2 = dx * dx + dy * dy;
    let t = if l2 == 0.0 { 0.0 } else { (((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / l2).clamp(0.0, 1.0) };
    (q[0] - a[0] - t * dx).hypot(q[1] - a[1] - t * dy)
}

/// Distance from `q` to a closed polyline.
pub fn dist_poly(poly: &[P], q: P) -> f64 {
    (0..poly.len()).map(|i| dist_seg(q, poly[i], poly[(i + 1) % poly.len()])).fold(f64::INFINITY, f64::min)
}
