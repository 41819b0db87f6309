use dformer::arclen::ArcTable;
use dformer::contour::{Contour, Knot};
use dformer::simulate::{simulate, SimulateOptions};
use kurbo::Point;
const K: f64 = 0.552_284_749_830_793_4;
fn ellipse(rx: f64, ry: f64) -> Contour {
    let knots = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)].iter().map(|&(x, y): &(f64, f64)| {
        let a = Point::new(rx * x, ry * y);
        let t = (-y * rx * K, x * ry * K);
        Knot { anchor: a, left: Point::new(a.x - t.0, a.y - t.1), right: Point::new(a.x + t.0, a.y + t.1) }
    }).collect();
    Contour::new(knots, 0).unwrap()
}
fn main() {
    let e = ellipse(2.0, 1.0);
    let p = ArcTable::new(&e, 1e-13).total();
    for n in [64usize, 256] {
        let cold = simulate(&e, &e, &SimulateOptions { offset: p / 4.0, resolution: n, ..Default::default() }).unwrap();
        let warm = simulate(&e, &e, &SimulateOptions { offset: p / 4.0, resolution: n, warm: Some(cold.vertices.clone()), ..Default::default() }).unwrap();
        println!("n {n} cold vol {} it {} fl {} ms {:.1} | warm vol {} it {} fl {} conv {} ms {:.1}", cold.stats.volume, cold.stats.iterations, cold.stats.flips, cold.stats.ms, warm.stats.volume, warm.stats.iterations, warm.stats.flips, warm.stats.converged, warm.stats.ms);
    }
}
