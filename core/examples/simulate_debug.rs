use dformer::arclen::ArcTable;
use dformer::contour::{Contour, Knot};
use dformer::simulate::{simulate, SimulateOptions};
use kurbo::{Affine, Point};
const K: f64 = 0.552_284_749_830_793_4;
fn ellipse(rx: f64, ry: f64) -> Contour {
    let pts = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)];
    let knots = pts.iter().map(|&(x, y)| {
        let a = Point::new(rx * x, ry * y);
        let t = (-y * rx * K, x * ry * K);
        Knot { anchor: a, left: Point::new(a.x - t.0, a.y - t.1), right: Point::new(a.x + t.0, a.y + t.1) }
    }).collect();
    Contour::new(knots, 0).unwrap()
}
fn main() {
    let n: usize = std::env::args().nth(1).unwrap().parse().unwrap();
    let case: usize = std::env::args().nth(2).unwrap().parse().unwrap();
    let e = ellipse(2.0, 1.0);
    let p = ArcTable::new(&e, 1e-13).total();
    let c0 = ellipse(1.0, 1.0);
    let c = c0.transformed(Affine::scale(p / ArcTable::new(&c0, 1e-13).total()));
    let (b, off) = if case == 0 { (e.clone(), p / 4.0) } else { (c, 0.0) };
    let s = simulate(&e, &b, &SimulateOptions { offset: off, resolution: n, ..Default::default() }).unwrap();
    println!("{:?}", s.stats);
}
