//! Principal extents of a closed triangle mesh: the form's height, width and depth.
//!
//! The axes are the eigenvectors of the covariance of the *surface* (uniform density on the
//! triangles, not on the vertices, which are all seam samples and would over-weight the seam):
//! for a triangle with corners `a, b, c` and area `A`,
//!
//! ```text
//! ∫_T x dA = A (a + b + c) / 3,     ∫_T x xᵀ dA = A / 12 · (a aᵀ + b bᵀ + c cᵀ + s sᵀ),  s = a + b + c
//! ```
//!
//! (the exact second moment of a triangle; e.g. Eberly, "Polyhedral mass properties", 2002). The
//! extent along an axis is the spread of the vertices' projections on it (a polyhedron's extreme
//! points are vertices). Names: the axis of least spread is the **height** (the form resting on
//! its broad side, as on a table: a flat, doubly covered form has height 0), the axis of most
//! spread the **width**, the remaining one the **depth**. When two spreads are equal (a form with
//! rotational symmetry) the axes in that plane are not unique, and neither are the two extents.
//! Eigenvectors by cyclic Jacobi rotations (Golub & Van Loan, *Matrix Computations*, §8.5), which
//! are exact to round-off for a 3 × 3 symmetric matrix in a handful of sweeps.

/// Height, width and depth of a form, and the unit axes they are measured along.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extents {
    pub height: f64,
    pub width: f64,
    pub depth: f64,
    /// Unit axes of `[height, width, depth]`.
    pub axes: [[f64; 3]; 3],
    /// Area-weighted centroid of the surface.
    pub center: [f64; 3],
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// Eigen-decomposition of a symmetric 3 × 3 matrix by cyclic Jacobi: `(values, vectors)` with
/// `vectors[k]` the unit eigenvector of `values[k]`.
fn symmetric_eigen(mut m: [[f64; 3]; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]; // columns = eigenvectors
    for _ in 0..50 {
        let off = m[0][1].powi(2) + m[0][2].powi(2) + m[1][2].powi(2);
        let diag = m[0][0].powi(2) + m[1][1].powi(2) + m[2][2].powi(2);
        if off <= 1e-32 * diag || off == 0.0 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if m[p][q] == 0.0 {
                continue;
            }
            // The rotation that zeroes m[p][q] (Golub & Van Loan, Algorithm 8.5.1).
            let theta = (m[q][q] - m[p][p]) / (2.0 * m[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let t = if theta == 0.0 { 1.0 } else { t };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            for k in 0..3 {
                let (mkp, mkq) = (m[k][p], m[k][q]);
                m[k][p] = c * mkp - s * mkq;
                m[k][q] = s * mkp + c * mkq;
            }
            for k in 0..3 {
                let (mpk, mqk) = (m[p][k], m[q][k]);
                m[p][k] = c * mpk - s * mqk;
                m[q][k] = s * mpk + c * mqk;
            }
            for row in v.iter_mut() {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
        }
    }
    let vectors = [0, 1, 2].map(|k| [v[0][k], v[1][k], v[2][k]]);
    ([m[0][0], m[1][1], m[2][2]], vectors)
}

/// Principal extents of the mesh (see the module doc). `None` for a mesh with no area.
/// Triangle indices must be in range (the caller checks input from outside the crate).
pub fn principal_extents(vertices: &[[f64; 3]], triangles: &[[usize; 3]]) -> Option<Extents> {
    let mut area = 0.0;
    let mut first = [0.0; 3];
    let mut second = [[0.0; 3]; 3];
    // Moments about the first vertex: keeps round-off relative to the form's size, not its position.
    let origin = *vertices.first()?;
    for t in triangles {
        let [a, b, c] = t.map(|i| sub(vertices[i], origin));
        let n = cross(sub(b, a), sub(c, a));
        let da = 0.5 * dot(n, n).sqrt();
        let s = [a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]];
        area += da;
        for i in 0..3 {
            first[i] += da * s[i] / 3.0;
            for j in 0..3 {
                second[i][j] += da / 12.0 * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
            }
        }
    }
    if !(area > 0.0 && area.is_finite()) {
        return None;
    }
    let mean = first.map(|x| x / area);
    let mut cov = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            cov[i][j] = second[i][j] / area - mean[i] * mean[j];
        }
    }
    let (values, vectors) = symmetric_eigen(cov);
    let mut order = [0usize, 1, 2];
    order.sort_by(|&i, &j| values[i].total_cmp(&values[j]));
    let spread = |axis: [f64; 3]| {
        let (lo, hi) = vertices.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            let x = dot(*v, axis);
            (lo.min(x), hi.max(x))
        });
        hi - lo
    };
    // Least spread = height, most = width, the middle one = depth.
    let axes = [vectors[order[0]], vectors[order[2]], vectors[order[1]]];
    Some(Extents {
        height: spread(axes[0]),
        width: spread(axes[1]),
        depth: spread(axes[2]),
        axes,
        center: [origin[0] + mean[0], origin[1] + mean[1], origin[2] + mean[2]],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jacobi_recovers_a_rotated_diagonal_matrix() {
        // R diag(1, 4, 9) Rᵀ with R = Rz(0.3) Rx(0.7): eigenvalues 1, 4, 9, eigenvectors R's columns.
        let (cz, sz, cx, sx) = (0.3f64.cos(), 0.3f64.sin(), 0.7f64.cos(), 0.7f64.sin());
        let rz = [[cz, -sz, 0.0], [sz, cz, 0.0], [0.0, 0.0, 1.0]];
        let rx = [[1.0, 0.0, 0.0], [0.0, cx, -sx], [0.0, sx, cx]];
        let mul = |a: [[f64; 3]; 3], b: [[f64; 3]; 3]| {
            let mut m = [[0.0; 3]; 3];
            for i in 0..3 {
                for j in 0..3 {
                    m[i][j] = (0..3).map(|k| a[i][k] * b[k][j]).sum();
                }
            }
            m
        };
        let r = mul(rz, rx);
        let d = [1.0, 4.0, 9.0];
        let mut m = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                m[i][j] = (0..3).map(|k| r[i][k] * d[k] * r[j][k]).sum();
            }
        }
        let (values, vectors) = symmetric_eigen(m);
        for k in 0..3 {
            let want = d.iter().position(|&x| (x - values[k]).abs() < 1e-12);
            let Some(col) = want else { panic!("eigenvalue {} is not one of {d:?}", values[k]) };
            let axis = [r[0][col], r[1][col], r[2][col]];
            assert!((dot(axis, vectors[k]).abs() - 1.0).abs() < 1e-12, "eigenvector {k}: wanted ±{axis:?}, got {:?}", vectors[k]);
        }
    }
}
