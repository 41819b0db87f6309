//! Native benchmark of `simulate` (not a test): the targets at 256 seam vertices for two
//! ellipses (axes 2:1) at a quarter-perimeter ("90°") offset and for an ellipse with a circle.
//! Run: `cargo run --release -p dformer --example simulate_bench`.
//!
//! The "exact convex solution" is the Richardson extrapolation (error O(h²) in the seam step h)
//! of this solver's volume at 1024 and 2048 seam vertices; the figures are the targets.

use dformer::arclen::ArcTable;
use dformer::contour::{Contour, Knot};
use dformer::simulate::{simulate, SimulateOptions};
use kurbo::{Affine, Point};
use std::time::Instant;

/// Kappa for a quarter circle by one cubic.
const K: f64 = 0.552_284_749_830_793_4;

/// Ellipse with semi-axes rx, ry, first anchor at (rx, 0), counter-clockwise.
fn ellipse(rx: f64, ry: f64) -> Contour {
    let pts = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)];
    let knots = pts
        .iter()
        .map(|&(x, y)| {
            let a = Point::new(rx * x, ry * y);
            // Tangent (ccw) at (x, y) on the unit circle is (−y, x).
            let t = (-y * rx * K, x * ry * K);
            Knot { anchor: a, left: Point::new(a.x - t.0, a.y - t.1), right: Point::new(a.x + t.0, a.y + t.1) }
        })
        .collect();
    Contour::new(knots, 0).unwrap()
}

fn perimeter(c: &Contour) -> f64 {
    ArcTable::new(c, 1e-13).total()
}

/// `c` scaled about the origin to perimeter `p`.
fn with_perimeter(c: &Contour, p: f64) -> Contour {
    c.transformed(Affine::scale(p / perimeter(c)))
}

fn mark(ok: bool) -> &'static str {
    if ok { "PASS" } else { "MISS" }
}

fn run(name: &str, a: &Contour, b: &Contour, offset: f64) {
    let p = perimeter(a);
    let opts = |n: usize| SimulateOptions { offset, resolution: n, ..Default::default() };
    let v = |n: usize| simulate(a, b, &opts(n)).expect("simulate").stats.volume;
    let exact = {
        let (v1, v2) = (v(1024), v(2048));
        v2 + (v2 - v1) / 3.0
    };
    // Warm-up, then the timed runs.
    let _ = simulate(a, b, &opts(256)).unwrap();
    let reps = 5;
    let t0 = Instant::now();
    let mut sim = None;
    for _ in 0..reps {
        sim = Some(simulate(a, b, &opts(256)).unwrap());
    }
    let ms = t0.elapsed().as_secs_f64() * 1e3 / reps as f64;
    let s = sim.unwrap().stats;
    let v128 = v(128);
    let dv = (s.volume - exact).abs() / exact;
    let dres = (s.volume - v128).abs() / s.volume;
    let four_pi = 4.0 * std::f64::consts::PI;
    println!("== {name} (256 seam vertices, perimeter {p:.6}) ==");
    println!("  volume {:.6} vs extrapolated exact {:.6}: {:.3e} relative (≤ 2e-3) {}", s.volume, exact, dv, mark(dv <= 2e-3));
    println!("  max edge strain {:.3e} (≤ 1e-3) {}   mean {:.3e}", s.max_strain, mark(s.max_strain <= 1e-3), s.mean_strain);
    println!("  seam gap {:.3e} of perimeter (≤ 1e-4) {}", s.seam_gap / p, mark(s.seam_gap / p <= 1e-4));
    println!("  area error {:.3e} (≤ 1e-3) {}", s.area_error, mark(s.area_error <= 1e-3));
    println!(
        "  interior |defect| {:.3e} of 4π (≤ 5e-3) {}   seam |defect| {:.6} (4π = {:.6})",
        s.interior_defect_sum / four_pi,
        mark(s.interior_defect_sum / four_pi <= 5e-3),
        s.angle_defect_sum,
        four_pi
    );
    println!("  volume change 128→256 {:.3e} (≤ 5e-3) {}", dres, mark(dres <= 5e-3));
    println!("  time {:.2} ms (≤ 100 ms) {}   iterations {} flips {} converged {} reflex {}", ms, mark(ms <= 100.0), s.iterations, s.flips, s.converged, s.reflex_edges);
}

fn main() {
    let e = ellipse(2.0, 1.0);
    let p = perimeter(&e);
    run("two ellipses 2:1, offset a quarter perimeter", &e, &e, p / 4.0);
    let c = with_perimeter(&ellipse(1.0, 1.0), p);
    run("ellipse 2:1 with a circle", &e, &c, 0.0);
}
