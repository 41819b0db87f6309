//! 3D vector helpers shared by every part of the solver: points and vectors as `[f64; 3]`.

pub(crate) type V3 = [f64; 3];

pub(crate) fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

pub(crate) fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// Centroid of a point set (the mean of its points).
pub(crate) fn centroid(x: &[V3]) -> V3 {
    let n = x.len() as f64;
    x.iter().fold([0.0; 3], |s, p| [s[0] + p[0] / n, s[1] + p[1] / n, s[2] + p[2] / n])
}

/// The centroid of a point set and the largest distance of a point from it.
pub(crate) fn centroid_and_radius(x: &[V3]) -> (V3, f64) {
    let c = centroid(x);
    (c, x.iter().map(|p| norm(sub(*p, c))).fold(0.0, f64::max))
}

/// Size scale of a point set (RMS distance to the centroid).
pub(crate) fn size(x: &[V3]) -> f64 {
    let c = centroid(x);
    (x.iter().map(|p| dot(sub(*p, c), sub(*p, c))).sum::<f64>() / x.len() as f64).sqrt()
}

/// Maps flat point `q` into 3D by the affine map that takes flat triangle `f` to `t`.
pub fn map_affine(f: [[f64; 2]; 3], t: [V3; 3], q: [f64; 2]) -> Option<V3> {
    let det = (f[1][0] - f[0][0]) * (f[2][1] - f[0][1]) - (f[1][1] - f[0][1]) * (f[2][0] - f[0][0]);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let (dx, dy) = (q[0] - f[0][0], q[1] - f[0][1]);
    let b1 = (dx * (f[2][1] - f[0][1]) - dy * (f[2][0] - f[0][0])) / det;
    let b2 = ((f[1][0] - f[0][0]) * dy - (f[1][1] - f[0][1]) * dx) / det;
    let b0 = 1.0 - b1 - b2;
    Some([0, 1, 2].map(|a| b0 * t[0][a] + b1 * t[1][a] + b2 * t[2][a]))
}
