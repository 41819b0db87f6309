//! Tutte's barycentric embedding of a piece's mesh into another boundary polygon: every interior
//! vertex at the mean of its neighbours, the seam vertices where the polygon puts them. For a
//! convex polygon the result is an embedding, every triangle positively oriented (Tutte, "How to
//! draw a graph", 1963; Floater, "Parametrization and smooth approximation of surface
//! triangulations", CAGD 14, 1997). It carries a piece's mesh onto its convex twin.
//!
//! The linear system (the graph Laplacian on the interior vertices, with the boundary on the
//! right-hand side) is symmetric positive definite and solved by conjugate gradients.

/// Positions of `vertices` (global indices; the first `n` of the mesh are the seam) with the
/// seam at `boundary` and the interior by Tutte's embedding; `faces` are the piece's triangles.
/// Returns a position for every global index below `total` (unused ones at 0).
pub fn embed(faces: &[[usize; 3]], n: usize, boundary: &[[f64; 2]], total: usize, tol: f64) -> Vec<[f64; 2]> {
    let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); total];
    for t in faces {
        for m in 0..3 {
            let (a, b) = (t[m], t[(m + 1) % 3]);
            if !neighbours[a].contains(&b) {
                neighbours[a].push(b);
            }
            if !neighbours[b].contains(&a) {
                neighbours[b].push(a);
            }
        }
    }
    let mut out = vec![[0.0; 2]; total];
    out[..n].copy_from_slice(&boundary[..n]);
    let interior: Vec<usize> = (n..total).filter(|&v| !neighbours[v].is_empty()).collect();
    let mut slot = vec![usize::MAX; total];
    for (k, &v) in interior.iter().enumerate() {
        slot[v] = k;
    }
    let m = interior.len();
    // A x = b, A = D − adjacency on the interior.
    let apply = |x: &[f64], y: &mut [f64]| {
        for (k, &v) in interior.iter().enumerate() {
            let mut s = neighbours[v].len() as f64 * x[k];
            for &w in &neighbours[v] {
                if slot[w] != usize::MAX {
                    s -= x[slot[w]];
                }
            }
            y[k] = s;
        }
    };
    for c in 0..2 {
        let b: Vec<f64> = interior.iter().map(|&v| neighbours[v].iter().filter(|&&w| w < n).map(|&w| boundary[w][c]).sum()).collect();
        let mut x: Vec<f64> = vec![0.0; m];
        let mut r = b.clone();
        let mut p = r.clone();
        let mut ap = vec![0.0; m];
        let mut rr: f64 = r.iter().map(|v| v * v).sum();
        let bb = rr.max(f64::MIN_POSITIVE);
        for _ in 0..4 * m + 10 {
            if rr <= tol * tol * bb {
                break;
            }
            apply(&p, &mut ap);
            let pap: f64 = p.iter().zip(&ap).map(|(a, b)| a * b).sum();
            if !(pap > 0.0) {
                break;
            }
            let alpha = rr / pap;
            for k in 0..m {
                x[k] += alpha * p[k];
                r[k] -= alpha * ap[k];
            }
            let next: f64 = r.iter().map(|v| v * v).sum();
            let beta = next / rr;
            rr = next;
            for k in 0..m {
                p[k] = r[k] + beta * p[k];
            }
        }
        for (k, &v) in interior.iter().enumerate() {
            out[v][c] = x[k];
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fan of a square with one interior vertex: Tutte puts it at the mean of the corners.
    #[test]
    fn one_interior_vertex_sits_at_the_mean_of_its_neighbours() {
        let faces = [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]];
        let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        let p = embed(&faces, 4, &square, 5, 1e-14);
        assert!((p[4][0] - 1.0).abs() < 1e-12 && (p[4][1] - 1.0).abs() < 1e-12, "wanted (1, 1), got {:?}", p[4]);
    }
}
