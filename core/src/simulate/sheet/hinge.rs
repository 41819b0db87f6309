//! The dihedral angle of a hinge (two triangles sharing an edge) and its gradient.
//!
//! Hinge `(i, j, k, l)`: edge `e = x_j − x_i` with triangle `(i, j, k)` on one side and
//! `(j, i, l)` on the other, both oriented as the surface. With `n₁ = e × (x_k − x_i)` and
//! `n₂ = (x_l − x_i) × e`, the signed angle between the normals is
//! `θ = atan2((n₁ × n₂)·ê, n₁·n₂)`: 0 for a flat hinge, positive when the hinge bends away from
//! the normals (a convex edge of an outward surface), ±π when folded flat onto itself.
//!
//! Its gradient (e.g. Wardetzky, Bergou, Harmon, Zorin & Grinspun, "Discrete quadratic curvature
//! energies", CAGD 24, 2007, §4; Tamstorf & Grinspun 2013): moving the tip `x_k` along the unit
//! normal by δ turns its triangle by δ/h_k (h_k its height over the edge), so
//! `∂θ/∂x_k = −n̂₁/h_k = −|e| n₁/|n₁|²`, likewise `∂θ/∂x_l = −|e| n₂/|n₂|²`; the edge's ends
//! share the opposite of both by the tips' positions along the edge, `t = (x − x_i)·e/|e|²`:
//! `∂θ/∂x_i = −(1 − t_k)∂θ/∂x_k − (1 − t_l)∂θ/∂x_l`, `∂θ/∂x_j = −t_k ∂θ/∂x_k − t_l ∂θ/∂x_l`
//! (the gradient is invariant under translations and rotations).

use crate::libm_ext::LibmExt;
use crate::simulate::vec3::{cross, dot, norm, sub, V3};

/// The signed dihedral angle of hinge `(i, j, k, l)` at positions `x` (see the module docs).
pub fn angle(xi: V3, xj: V3, xk: V3, xl: V3) -> f64 {
    let e = sub(xj, xi);
    let n1 = cross(e, sub(xk, xi));
    let n2 = cross(sub(xl, xi), e);
    let le = norm(e);
    if le == 0.0 {
        return 0.0;
    }
    let s = dot(cross(n1, n2), e) / le;
    s.atan2_m(dot(n1, n2))
}

/// The angle and its gradient with respect to `x_i, x_j, x_k, x_l`; `None` for a degenerate
/// hinge (a zero edge or a zero-area triangle).
pub fn angle_and_gradient(xi: V3, xj: V3, xk: V3, xl: V3) -> Option<(f64, [V3; 4])> {
    let e = sub(xj, xi);
    let n1 = cross(e, sub(xk, xi));
    let n2 = cross(sub(xl, xi), e);
    let (le2, a1, a2) = (dot(e, e), dot(n1, n1), dot(n2, n2));
    if !(le2 > 0.0 && a1 > 0.0 && a2 > 0.0) {
        return None;
    }
    let le = le2.sqrt();
    let theta = (dot(cross(n1, n2), e) / le).atan2_m(dot(n1, n2));
    let gk = n1.map(|v| -le * v / a1);
    let gl = n2.map(|v| -le * v / a2);
    let tk = dot(sub(xk, xi), e) / le2;
    let tl = dot(sub(xl, xi), e) / le2;
    let gi = [0, 1, 2].map(|a| -(1.0 - tk) * gk[a] - (1.0 - tl) * gl[a]);
    let gj = [0, 1, 2].map(|a| -tk * gk[a] - tl * gl[a]);
    Some((theta, [gi, gj, gk, gl]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The gradient against central differences of [`angle`], on hinges bent both ways and
    /// nearly folded: wanted the difference quotient, got the formula.
    #[test]
    fn gradient_matches_central_differences() {
        let hinges: [[V3; 4]; 4] = [
            [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.3, 1.0, 0.2], [0.6, -0.8, 0.5]],
            [[0.1, 0.2, 0.0], [1.3, -0.1, 0.4], [0.2, 1.1, -0.6], [0.9, -0.7, -0.3]],
            [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [1.5, 0.7, 0.0], [-0.2, 0.6, 0.3]],
            [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 1.0, 0.0], [0.5, -1.0, 0.01]],
        ];
        for (h, x) in hinges.iter().enumerate() {
            let (theta, g) = angle_and_gradient(x[0], x[1], x[2], x[3]).expect("a proper hinge");
            assert!((theta - angle(x[0], x[1], x[2], x[3])).abs() < 1e-15);
            for v in 0..4 {
                for a in 0..3 {
                    let d = 1e-6;
                    let mut p = *x;
                    p[v][a] += d;
                    let up = angle(p[0], p[1], p[2], p[3]);
                    p[v][a] -= 2.0 * d;
                    let down = angle(p[0], p[1], p[2], p[3]);
                    let fd = (up - down) / (2.0 * d);
                    assert!((fd - g[v][a]).abs() < 1e-7, "hinge {h}, vertex {v}, axis {a}: wanted {fd}, got {}", g[v][a]);
                }
            }
        }
    }

    /// A flat hinge has angle 0; lifting the far tip of a right-handed hinge over the plane of
    /// its normals gives the sign the module promises.
    #[test]
    fn flat_hinges_have_angle_zero_and_convex_ones_are_positive() {
        let flat = angle([0.0; 3], [1.0, 0.0, 0.0], [0.5, 1.0, 0.0], [0.5, -1.0, 0.0]);
        assert!(flat.abs() < 1e-15, "wanted 0, got {flat}");
        // Normals point to +z; tips dropped below the plane make the edge a ridge (convex).
        let ridge = angle([0.0; 3], [1.0, 0.0, 0.0], [0.5, 1.0, -0.3], [0.5, -1.0, -0.3]);
        assert!(ridge > 0.0, "a ridge: wanted a positive angle, got {ridge}");
    }
}
