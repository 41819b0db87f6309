//! The rotation and shift that take one planar point set onto another best, point for point:
//! the least-squares rigid fit (Kabsch 1976; in 2D the angle is `atan2(Σ u×v, Σ u·v)` of the
//! centred points `u` of the moving set and `v` of the target, no reflection). Congruent pieces
//! are told apart with it, B's samples fitted onto A's ([`super::convex::congruent`]).

use crate::libm_ext::LibmExt;

/// A rigid motion of the plane: `p ↦ to + R(p − from)`, `R` the rotation by the angle whose cosine
/// and sine are `cos`, `sin`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rigid {
    pub from: [f64; 2],
    pub to: [f64; 2],
    pub cos: f64,
    pub sin: f64,
}

impl Rigid {
    /// The least-squares fit of `moving` onto `target` (the same number of points, paired by
    /// index); `None` when the counts differ, either is empty, or the fit is degenerate (all
    /// points of one set at their centroid).
    pub fn fit(moving: &[[f64; 2]], target: &[[f64; 2]]) -> Option<Rigid> {
        if moving.len() != target.len() || moving.is_empty() {
            return None;
        }
        let m = moving.len() as f64;
        let mean = |p: &[[f64; 2]]| p.iter().fold([0.0, 0.0], |s, q| [s[0] + q[0] / m, s[1] + q[1] / m]);
        let (from, to) = (mean(moving), mean(target));
        let (mut d, mut x) = (0.0, 0.0);
        for (p, q) in moving.iter().zip(target) {
            let (u, v) = ([p[0] - from[0], p[1] - from[1]], [q[0] - to[0], q[1] - to[1]]);
            d += u[0] * v[0] + u[1] * v[1];
            x += u[0] * v[1] - u[1] * v[0];
        }
        let r = d.hypot_m(x);
        (r > 0.0).then(|| Rigid { from, to, cos: d / r, sin: x / r })
    }

    /// `p` moved.
    pub fn apply(&self, p: [f64; 2]) -> [f64; 2] {
        let u = [p[0] - self.from[0], p[1] - self.from[1]];
        [self.to[0] + self.cos * u[0] - self.sin * u[1], self.to[1] + self.sin * u[0] + self.cos * u[1]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scalene triangle turned by 2.5 rad and moved is fitted back exactly (to round-off), and
    /// the fit of a set onto its mirror image is no reflection: it leaves a residual.
    #[test]
    fn recovers_a_turn_and_a_shift_and_never_reflects() {
        let a = [[0.0, 0.0], [4.0, 0.0], [1.0, 3.0]];
        let (c, s) = (2.5f64.cos_m(), 2.5f64.sin_m());
        let b: Vec<[f64; 2]> = a.iter().map(|p| [c * p[0] - s * p[1] - 7.0, s * p[0] + c * p[1] + 2.0]).collect();
        let f = Rigid::fit(&a, &b).expect("a fit");
        for (p, q) in a.iter().zip(&b) {
            let m = f.apply(*p);
            assert!((m[0] - q[0]).abs() < 1e-12 && (m[1] - q[1]).abs() < 1e-12, "wanted {q:?}, got {m:?}");
        }
        assert!((f.cos - c).abs() < 1e-12 && (f.sin - s).abs() < 1e-12, "wanted the angle 2.5, got cos {} sin {}", f.cos, f.sin);
        let mirror: Vec<[f64; 2]> = a.iter().map(|p| [-p[0], p[1]]).collect();
        let g = Rigid::fit(&a, &mirror).expect("a fit");
        let worst = a.iter().zip(&mirror).map(|(p, q)| { let m = g.apply(*p); (m[0] - q[0]).hypot_m(m[1] - q[1]) }).fold(0.0, f64::max);
        assert!(worst > 0.1, "a mirror image is no turned copy, got a residual of {worst}");
        assert!(Rigid::fit(&a, &a[..2]).is_none() && Rigid::fit(&[[1.0, 1.0]; 3], &a).is_none());
    }
}
