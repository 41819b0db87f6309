//! The sheet path's coarse-to-fine carry ([`dformer::simulate::sheet::refine::carry`]): a shape
//! on the coarse level's mesh taken onto the fine mesh of the same pieces, checked against a
//! closed form, an affine map of the flat pieces, which a piecewise-linear carry must reproduce
//! exactly, extrapolated seam samples included.

#[allow(dead_code)]
#[path = "simulate_common/shapes.rs"]
mod shapes;

use dformer::simulate::seam::Glue;
use dformer::simulate::sheet::{level::COARSE_STRIDE, refine::carry, SheetMesh, INTERIOR_EDGE};

type V3 = [f64; 3];

/// A tilted, scaled, shifted embedding of the plane in space.
fn affine(q: [f64; 2]) -> V3 {
    [1.2 * q[0] - 0.3 * q[1] + 4.0, 0.5 * q[0] + 0.9 * q[1] - 2.0, 0.25 * q[0] - 0.4 * q[1] + 7.0]
}

/// The affine map taking B's flat samples onto A's (congruent pieces glued at offset 0): fitted
/// on three samples, checked on all.
fn b_onto_a(a: &[[f64; 2]], b: &[[f64; 2]]) -> impl Fn([f64; 2]) -> [f64; 2] {
    let (i, j, k) = (0, a.len() / 3, 2 * a.len() / 3);
    // Solve [b_j − b_i, b_k − b_i] M = [a_j − a_i, a_k − a_i] for the 2×2 linear part M.
    let (u, v) = ([b[j][0] - b[i][0], b[j][1] - b[i][1]], [b[k][0] - b[i][0], b[k][1] - b[i][1]]);
    let (p, q) = ([a[j][0] - a[i][0], a[j][1] - a[i][1]], [a[k][0] - a[i][0], a[k][1] - a[i][1]]);
    let det = u[0] * v[1] - u[1] * v[0];
    // Columns: the images of the unit vectors, from (u, v) → (p, q).
    let inv = [[v[1] / det, -v[0] / det], [-u[1] / det, u[0] / det]];
    let m = [[p[0] * inv[0][0] + q[0] * inv[1][0], p[0] * inv[0][1] + q[0] * inv[1][1]], [p[1] * inv[0][0] + q[1] * inv[1][0], p[1] * inv[0][1] + q[1] * inv[1][1]]];
    let (bi, ai) = (b[i], a[i]);
    move |r: [f64; 2]| {
        let d = [r[0] - bi[0], r[1] - bi[1]];
        [ai[0] + m[0][0] * d[0] + m[0][1] * d[1], ai[1] + m[1][0] * d[0] + m[1][1] * d[1]]
    }
}

fn dist(a: V3, b: V3) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// Every fine vertex lands where the affine map takes its flat position: interior vertices of
/// either piece, the seam samples the coarse level shares, and the ones between them (just off
/// the coarse polygon, where the carry extends the nearest coarse triangle).
#[test]
fn carry_reproduces_an_affine_shape_on_every_fine_vertex() {
    // Mirror-symmetric about the x axis and starting on it, so that B (the same outline walked the
    // other way) has its samples where A's are mirrored, and one affine map of A's flat piece
    // is a shape of both: a bean with a concave side, a rectangle notched at its start, a rounded star.
    let bean = shapes::polar(48, |t| 50.0 * (1.0 + 0.3 * (2.0 * t).cos() + 0.15 * (3.0 * t).cos()));
    let notched = shapes::polyline(&[(10.0, 0.0), (40.0, 10.0), (40.0, 30.0), (0.0, 30.0), (0.0, -30.0), (40.0, -30.0), (40.0, -10.0)]);
    let star = shapes::polar(60, |t| 50.0 * (1.0 + 0.25 * (5.0 * t).cos()));
    for (name, c) in [("bean", bean), ("notched polyline", notched), ("rounded star", star)] {
        let fine_pieces = Glue::new(&c, &c, 0.0).unwrap().sample(256);
        let coarse_pieces = fine_pieces.every(COARSE_STRIDE);
        let fine = SheetMesh::new(&fine_pieces, INTERIOR_EDGE).unwrap();
        let coarse = SheetMesh::new(&coarse_pieces, INTERIOR_EDGE * COARSE_STRIDE as f64).unwrap();
        let to_a = b_onto_a(&fine_pieces.flat[0].pts, &fine_pieces.flat[1].pts);
        for k in 0..fine.n {
            let (a, b) = (fine.flat[0][k], to_a(fine.flat[1][k]));
            assert!((a[0] - b[0]).hypot(a[1] - b[1]) < 1e-9, "{name}: precondition: B's sample {k} is A's mirrored, {a:?} against {b:?}");
        }
        // A's vertices through A's flat positions, B's interior ones through B's taken onto A's.
        let place = |m: &SheetMesh, v: usize| if v < m.n || m.faces[0].iter().flatten().any(|&w| w == v) { affine(m.flat[0][v]) } else { affine(to_a(m.flat[1][v])) };
        let x: Vec<V3> = (0..coarse.vertex_count()).map(|v| place(&coarse, v)).collect();
        let got = carry(&coarse, &x, &fine).expect("a carry between levels of the same pieces");
        assert_eq!(got.len(), fine.vertex_count());
        let worst = (0..fine.vertex_count()).map(|v| (dist(got[v], place(&fine, v)), v)).fold((0.0, 0), |a, b| if b.0 > a.0 { b } else { a });
        println!("{name}: {} → {} vertices, worst {:.1e} at vertex {}", coarse.vertex_count(), fine.vertex_count(), worst.0, worst.1);
        assert!(worst.0 < 1e-9, "{name}: wanted every vertex on the affine image, vertex {} is {:.3e} off", worst.1, worst.0);
    }
}

#[test]
fn carry_refuses_levels_that_do_not_nest() {
    let c = shapes::kidney();
    let pieces = Glue::new(&c, &shapes::circle_for(&c), 0.0).unwrap();
    let (a, b) = (SheetMesh::new(&pieces.sample(96), INTERIOR_EDGE).unwrap(), SheetMesh::new(&pieces.sample(128), INTERIOR_EDGE).unwrap());
    let x = vec![[0.0; 3]; a.vertex_count()];
    assert!(carry(&a, &x, &b).is_none(), "96 seam samples are no level of 128");
    assert!(carry(&a, &x[1..], &a).is_none(), "a shape with a vertex missing");
}

/// Barycentric coordinates of `q` in the flat triangle `t`.
fn barycentric(t: [[f64; 2]; 3], q: [f64; 2]) -> [f64; 3] {
    let [a, b, c] = t;
    let det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    let w1 = ((q[0] - a[0]) * (c[1] - a[1]) - (q[1] - a[1]) * (c[0] - a[0])) / det;
    let w2 = ((b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])) / det;
    [1.0 - w1 - w2, w1, w2]
}

/// A curved shape (a paraboloid over each flat piece) is carried as the coarse mesh's
/// piecewise-linear interpolant: every fine interior vertex inside a coarse triangle lands on
/// that triangle's plane, found here by testing every coarse triangle.
#[test]
fn carry_interpolates_a_curved_shape_in_the_coarse_triangle_that_holds_each_vertex() {
    let c = shapes::kidney();
    let pieces = Glue::new(&c, &shapes::circle_for(&c), 0.0).unwrap().sample(256);
    let fine = SheetMesh::new(&pieces, INTERIOR_EDGE).unwrap();
    let coarse = SheetMesh::new(&pieces.every(COARSE_STRIDE), INTERIOR_EDGE * COARSE_STRIDE as f64).unwrap();
    let bowl = |q: [f64; 2]| [q[0], q[1], 0.01 * (q[0] * q[0] + q[1] * q[1])];
    // Each vertex on its own piece's paraboloid (the seam on A's: the two disagree there, which
    // only the seam vertices see).
    let own = |m: &SheetMesh, v: usize| if v < m.n || m.faces[0].iter().flatten().any(|&w| w == v) { 0 } else { 1 };
    let x: Vec<V3> = (0..coarse.vertex_count()).map(|v| bowl(coarse.flat[own(&coarse, v)][v])).collect();
    let got = carry(&coarse, &x, &fine).unwrap();
    let (mut checked, mut worst) = (0, 0.0f64);
    for v in fine.n..fine.vertex_count() {
        let p = own(&fine, v);
        let q = fine.flat[p][v];
        // Inside a coarse triangle none of whose corners is on the seam (whose position is A's).
        let holder = coarse.faces[p].iter().map(|t| (t, barycentric(t.map(|w| coarse.flat[p][w]), q))).find(|(t, b)| b.iter().all(|&w| w > 1e-9) && t.iter().all(|&w| w >= coarse.n));
        let Some((t, b)) = holder else { continue };
        let want: V3 = [0, 1, 2].map(|a| b[0] * x[t[0]][a] + b[1] * x[t[1]][a] + b[2] * x[t[2]][a]);
        worst = worst.max(dist(got[v], want));
        checked += 1;
    }
    println!("{checked} of {} interior vertices checked, worst {worst:.1e}", fine.vertex_count() - fine.n);
    assert!(checked > (fine.vertex_count() - fine.n) / 2, "precondition: most interior vertices are inside an interior coarse triangle, {checked}");
    assert!(worst < 1e-9, "wanted each vertex on its coarse triangle's plane, worst {worst:.3e} off");
}
