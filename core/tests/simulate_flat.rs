//! `flat` of `simulate`'s result: for every triangle, its corners on its own flat piece, in the
//! input's coordinates and in the corner order of `triangles`. Checked here against the input
//! outlines themselves (sampled with kurbo, not with the crate's arc tables), against the mesh's
//! own 3D edge lengths, and by the flat triangles tiling each piece.

use dformer::arclen::ArcTable;
use dformer::contour::{Contour, Knot};
use dformer::simulate::{simulate, SimulateOptions};
use kurbo::{Affine, ParamCurve, Point};

const K: f64 = 0.552_284_749_830_793_4;

fn ellipse(rx: f64, ry: f64) -> Contour {
    let knots = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)]
        .iter()
        .map(|&(x, y): &(f64, f64)| {
            let a = Point::new(rx * x, ry * y);
            let t = (-y * rx * K, x * ry * K);
            Knot {
                anchor: a,
                left: Point::new(a.x - t.0, a.y - t.1),
                right: Point::new(a.x + t.0, a.y + t.1),
            }
        })
        .collect();
    Contour::new(knots, 0).unwrap()
}

/// Dense samples of the outline straight from its cubics.
fn samples(c: &Contour, per_segment: usize) -> Vec<Point> {
    c.segments()
        .flat_map(|s| (0..per_segment).map(move |i| s.eval(i as f64 / per_segment as f64)))
        .collect()
}

fn distance_to(pts: &[Point], p: [f64; 2]) -> f64 {
    pts.iter()
        .map(|q| (q.x - p[0]).hypot(q.y - p[1]))
        .fold(f64::INFINITY, f64::min)
}

fn shoelace(pts: &[Point]) -> f64 {
    let n = pts.len();
    (0..n)
        .map(|i| pts[i].x * pts[(i + 1) % n].y - pts[(i + 1) % n].x * pts[i].y)
        .sum::<f64>()
        / 2.0
}

#[test]
fn flat_corners_lie_on_the_input_outlines_and_match_the_mesh_lengths() {
    // Off the origin, turned, and B drawn clockwise: the coordinates must be the input's own.
    let a =
        ellipse(60.0, 30.0).transformed(Affine::translate((140.0, -20.0)) * Affine::rotate(0.4));
    let circle = ellipse(1.0, 1.0);
    let scale = ArcTable::new(&a, 1e-13).total() / ArcTable::new(&circle, 1e-13).total();
    let b = circle
        .transformed(Affine::translate((-50.0, 75.0)) * Affine::scale(scale))
        .reversed();
    let p = ArcTable::new(&a, 1e-13).total();
    let s = simulate(
        &a,
        &b,
        &SimulateOptions {
            offset: 0.3 * p,
            resolution: 128,
            ..Default::default()
        },
    )
    .unwrap();
    assert!(
        s.stats.converged,
        "wanted a converged form, got {:?}",
        s.stats
    );
    assert_eq!(
        s.flat.len(),
        s.triangles.len(),
        "one flat triangle per triangle"
    );

    let outlines = [samples(&a, 4000), samples(&b, 4000)];
    let size = 60.0;
    let mut flat_area = [0.0f64; 2];
    for (t, (tri, f)) in s.triangles.iter().zip(&s.flat).enumerate() {
        let piece = s.piece[t] as usize;
        for m in 0..3 {
            let d = distance_to(&outlines[piece], f[m]);
            assert!(
                d < 1e-3 * size,
                "triangle {t} corner {m}: flat {:?} is {d} off piece {piece}'s outline",
                f[m]
            );
            let (i, j) = (tri[m], tri[(m + 1) % 3]);
            let d3 = {
                let (u, v) = (s.vertices[i], s.vertices[j]);
                ((u[0] - v[0]).powi(2) + (u[1] - v[1]).powi(2) + (u[2] - v[2]).powi(2)).sqrt()
            };
            let d2 = (f[m][0] - f[(m + 1) % 3][0]).hypot(f[m][1] - f[(m + 1) % 3][1]);
            assert!(
                (d3 / d2 - 1.0).abs() < 1e-3,
                "triangle {t} edge {i}-{j}: flat {d2}, 3D {d3}"
            );
        }
        let [p0, p1, p2] = *f;
        flat_area[piece] +=
            ((p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1])) / 2.0;
    }
    // The flat triangles tile each piece (a polygon inscribed in the outline: area within the
    // sagitta of 128 samples), and one orientation per piece.
    for (piece, outline) in outlines.iter().enumerate() {
        let want = shoelace(outline).abs();
        let got = flat_area[piece].abs();
        assert!(
            (got - want).abs() / want < 2e-3,
            "piece {piece}: flat triangles cover {got}, the outline {want}"
        );
    }
}
