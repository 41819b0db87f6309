//! Points of a flat piece carried onto the 3D surface.
//!
//! Every triangle of the mesh is isometric to its flat counterpart (`Simulation::flat`): its
//! corners on its own piece, in the input's coordinates and the corner order of `triangles`. A
//! point `p` of piece `k` therefore lands at
//!
//! ```text
//! P = w₀ X_i + w₁ X_j + w₂ X_l,   (w₀, w₁, w₂) = barycentric coordinates of p in flat[t],
//! ```
//!
//! for the triangle `t` of piece `k` whose flat copy contains `p` — the affine map of a triangle
//! is the isometry itself, so distances within a triangle are kept exactly. The flat triangles
//! tile the polygon of the seam samples; a point outside it (in the sliver between a chord and
//! the curved edge, or off the piece) goes to the triangle it is least outside of, its weights
//! clamped to that triangle, so the answer is always on the surface.

/// Barycentric coordinates of `p` in the triangle `t` (`None` when `t` has no area).
pub(crate) fn barycentric(t: &[[f64; 2]; 3], p: [f64; 2]) -> Option<[f64; 3]> {
    let [a, b, c] = *t;
    let det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let w1 = ((p[0] - a[0]) * (c[1] - a[1]) - (p[1] - a[1]) * (c[0] - a[0])) / det;
    let w2 = ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) / det;
    Some([1.0 - w1 - w2, w1, w2])
}

/// `p` (a point of piece `piece`, 0 = A, 1 = B) on the surface, with the triangle it lies in;
/// `None` when the piece has no triangle with area. Indices must be in range.
pub fn place(
    vertices: &[[f64; 3]],
    triangles: &[[usize; 3]],
    pieces: &[u8],
    flat: &[[[f64; 2]; 3]],
    piece: u8,
    p: [f64; 2],
) -> Option<([f64; 3], usize)> {
    let mut best: Option<(f64, usize, [f64; 3])> = None;
    for (t, corners) in flat.iter().enumerate() {
        if pieces.get(t) != Some(&piece) {
            continue;
        }
        let Some(w) = barycentric(corners, p) else { continue };
        let inside = w[0].min(w[1]).min(w[2]);
        if best.is_none_or(|(b, _, _)| inside > b) {
            best = Some((inside, t, w));
        }
    }
    let (_, t, w) = best?;
    let w = w.map(|x| x.max(0.0));
    let sum = w[0] + w[1] + w[2];
    let [i, j, l] = triangles[t];
    let at = |k: usize| (w[0] * vertices[i][k] + w[1] * vertices[j][k] + w[2] * vertices[l][k]) / sum;
    Some(([at(0), at(1), at(2)], t))
}
