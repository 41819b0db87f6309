//! The solved form as a design object: principal extents against closed forms (a box, the flat
//! doubly covered ellipse), connectors carried onto the surface (on the mesh to round-off,
//! isometric to their flat place, hole k of A meeting hole k of B across the seam), and the
//! casting figures' units.

mod common;

use common::ellipse;
use dformer::api::connect::{connect, ConnectOptionsDto};
use dformer::api::form::{figures, place, FiguresOptionsDto, FormDto, FormStatsDto};
use dformer::api::simulate::{simulate, SimulateDto, SimulateOptionsDto};

type V = [f64; 3];

fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn norm(a: V) -> f64 {
    dot(a, a).sqrt()
}

/// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, §5.1.5).
fn closest_on_triangle(p: V, a: V, b: V, c: V) -> V {
    let add = |u: V, v: V, s: f64| [u[0] + s * v[0], u[1] + s * v[1], u[2] + s * v[2]];
    let (ab, ac, ap) = (sub(b, a), sub(c, a), sub(p, a));
    let (d1, d2) = (dot(ab, ap), dot(ac, ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = sub(p, b);
    let (d3, d4) = (dot(ab, bp), dot(ac, bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return add(a, ab, d1 / (d1 - d3));
    }
    let cp = sub(p, c);
    let (d5, d6) = (dot(ab, cp), dot(ac, cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return add(a, ac, d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
        return add(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denom = 1.0 / (va + vb + vc);
    add(add(a, ab, vb * denom), ac, vc * denom)
}

fn distance_to_mesh(p: V, s: &SimulateDto) -> f64 {
    s.triangles
        .iter()
        .map(|t| norm(sub(p, closest_on_triangle(p, s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]))))
        .fold(f64::INFINITY, f64::min)
}

fn form_of(s: &SimulateDto) -> FormDto {
    FormDto {
        vertices: s.vertices.clone(),
        triangles: s.triangles.clone(),
        piece: s.piece.clone(),
        flat: s.flat.clone(),
        stats: FormStatsDto { volume: s.stats.volume },
    }
}

/// A closed box mesh with sides `size`, turned by `turn` (a rotation about an oblique axis).
fn box_mesh(size: V, turn: f64) -> (Vec<V>, Vec<[usize; 3]>) {
    let (c, s) = (turn.cos(), turn.sin());
    let corners: Vec<V> = (0..8)
        .map(|k| {
            let p = [
                if k & 1 == 1 { size[0] } else { 0.0 },
                if k & 2 == 2 { size[1] } else { 0.0 },
                if k & 4 == 4 { size[2] } else { 0.0 },
            ];
            // about z, then about x, then moved far from the origin
            let q = [c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]];
            [q[0] + 1000.0, c * q[1] - s * q[2] - 500.0, s * q[1] + c * q[2] + 250.0]
        })
        .collect();
    let faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
    let tris = faces.iter().flat_map(|f| [[f[0], f[1], f[2]], [f[0], f[2], f[3]]]).collect();
    (corners, tris)
}

#[test]
fn extents_of_a_turned_box_are_its_sides_smallest_as_height() {
    for turn in [0.0, 0.4, 1.1] {
        let (vertices, triangles) = box_mesh([30.0, 80.0, 50.0], turn);
        let form = FormDto { vertices, triangles, ..Default::default() };
        let f = figures(&form, &FiguresOptionsDto::default()).unwrap();
        for (name, got, want) in [("height", f.height, 30.0), ("width", f.width, 80.0), ("depth", f.depth, 50.0)] {
            assert!((got - want).abs() < 1e-9, "turn {turn}: {name} wanted {want}, got {got}");
        }
    }
}

#[test]
fn congruent_ellipses_at_offset_zero_lie_flat_height_zero_width_and_depth_the_axes() {
    let e = ellipse([0.0, 0.0], 60.0, 30.0, 4, false);
    let s = simulate(&[e.clone(), e], &SimulateOptionsDto { offset: Some(0.0), resolution: Some(64.0), ..Default::default() }).unwrap();
    let f = figures(&form_of(&s), &FiguresOptionsDto::default()).unwrap();
    println!("flat ellipses: height {} width {} depth {} volume {}", f.height, f.width, f.depth, f.volume);
    assert!(f.height < 1e-6 * 120.0, "wanted height 0 (the form is flat), got {}", f.height);
    // The seam polygon's vertices lie on the ellipse (sampled at equal arc length; the ends of both
    // axes are anchors, so they are among the samples).
    assert!((f.width - 120.0).abs() < 1e-6, "wanted width 120 (the major axis), got {}", f.width);
    assert!((f.depth - 60.0).abs() < 1e-6, "wanted depth 60 (the minor axis), got {}", f.depth);
}

#[test]
fn litres_and_mass_follow_the_unit_and_the_density() {
    let (vertices, triangles) = box_mesh([100.0, 100.0, 100.0], 0.0);
    // A 100 mm cube is 1 litre, 2.4 kg of concrete; in Illustrator points 100 pt is 35.28 mm.
    let form = FormDto { vertices, triangles, stats: FormStatsDto { volume: 1e6 }, ..Default::default() };
    let f = figures(&form, &FiguresOptionsDto::default()).unwrap();
    assert!((f.litres - 1.0).abs() < 1e-12 && (f.mass - 2.4).abs() < 1e-12, "wanted 1 L and 2.4 kg, got {} L {} kg", f.litres, f.mass);
    let pt = figures(&form, &FiguresOptionsDto { mm_per_unit: Some(25.4 / 72.0), density: Some(1000.0) }).unwrap();
    let want = (25.4f64 / 72.0).powi(3);
    assert!((pt.litres - want).abs() < 1e-12 && (pt.mass - want).abs() < 1e-12, "wanted {want} L and kg of water, got {} L {} kg", pt.litres, pt.mass);
    for bad in [0.0, -2400.0, f64::NAN] {
        let err = figures(&form, &FiguresOptionsDto { density: Some(bad), ..Default::default() }).unwrap_err().to_string();
        assert!(err.starts_with("Option `density`: must be a positive number"), "density {bad}: {err}");
    }
}

#[test]
fn connectors_on_the_form_sit_on_the_surface_and_hole_k_of_a_meets_hole_k_of_b() {
    let a = ellipse([0.0, 0.0], 60.0, 30.0, 4, false);
    let b = ellipse([200.0, 0.0], 60.0, 30.0, 4, false);
    let inset = 4.0;
    let count = 16.0;
    let p = dformer::api::measure(&a, None).unwrap().perimeter;
    for offset in [0.0, 0.25 * p, 0.4 * p] {
        let options = ConnectOptionsDto { count: Some(count), inset: Some(inset), diameter: Some(2.0), start: Some([0.0, offset]), ..Default::default() };
        let c = connect(&[a.clone(), b.clone()], &options).unwrap();
        let s = simulate(&[a.clone(), b.clone()], &SimulateOptionsDto { offset: Some(offset), resolution: Some(128.0), ..Default::default() }).unwrap();
        assert!(s.stats.converged, "offset {offset}: {:?}", s.stats);
        let holes: Vec<Vec<[f64; 2]>> = c.pieces.iter().map(|piece| piece.holes.iter().map(|h| h.center).collect()).collect();
        let on = place(&form_of(&s), &holes).unwrap();
        let size = 120.0;
        for (k, (flat, form)) in holes.iter().zip(&on).enumerate() {
            for (i, (f2, f3)) in flat.iter().zip(form).enumerate() {
                let d = distance_to_mesh(*f3, &s);
                assert!(d < 1e-12 * size, "offset {offset}: hole {} of piece {k} is {d} off the surface", i + 1);
                // At its flat place: its distances to its triangle's corners are the flat ones
                // (the triangle's map is the isometry), up to the solve's strain.
                let (t, _) = s
                    .flat
                    .iter()
                    .enumerate()
                    .filter(|(t, _)| s.piece[*t] as usize == k)
                    .map(|(t, tri)| (t, tri))
                    .find(|(_, tri)| inside(tri, *f2))
                    .unwrap_or_else(|| panic!("hole {} of piece {k} is inside no flat triangle", i + 1));
                for m in 0..3 {
                    let d2 = (f2[0] - s.flat[t][m][0]).hypot(f2[1] - s.flat[t][m][1]);
                    let d3 = norm(sub(*f3, s.vertices[s.triangles[t][m]]));
                    assert!((d3 - d2).abs() <= 1e-9 * size + s.stats.max_strain * d2 * 2.0, "offset {offset}: hole {} of piece {k}: flat distance {d2} to corner {m}, on the form {d3}", i + 1);
                }
            }
        }
        // Paired holes face each other across the seam: each is `inset` from the same seam point.
        for i in 0..holes[0].len() {
            let gap = norm(sub(on[0][i], on[1][i]));
            assert!(gap <= 2.0 * inset + 1e-3, "offset {offset}: hole {} of A and of B are {gap} apart on the form (wanted ≤ {})", i + 1, 2.0 * inset);
        }
    }
}

fn inside(t: &[[f64; 2]; 3], p: [f64; 2]) -> bool {
    let cross = |a: [f64; 2], b: [f64; 2]| (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    let s = [cross(t[0], t[1]), cross(t[1], t[2]), cross(t[2], t[0])];
    s.iter().all(|&x| x >= 0.0) || s.iter().all(|&x| x <= 0.0)
}

#[test]
fn bad_forms_get_a_clear_message() {
    let err = |f: &FormDto, pts: &[Vec<[f64; 2]>]| place(f, pts).unwrap_err().to_string();
    let (vertices, triangles) = box_mesh([1.0, 1.0, 1.0], 0.0);
    let f = FormDto { vertices, triangles, ..Default::default() };
    assert!(err(&f, &[vec![], vec![]]).contains("flat triangles"), "{}", err(&f, &[vec![], vec![]]));
    assert_eq!(err(&f, &[vec![]]), "Expected two lists of points (piece A, piece B), got 1.");
    let broken = FormDto { triangles: vec![[0, 1, 99]], ..f.clone() };
    assert!(figures(&broken, &FiguresOptionsDto::default()).unwrap_err().to_string().contains("triangle 0 of the form names a vertex past the 8 vertices"));
    assert!(figures(&FormDto::default(), &FiguresOptionsDto::default()).unwrap_err().to_string().contains("no triangles"));
}

#[test]
fn degenerate_and_extreme_forms_never_panic() {
    // Zero-area triangles, repeated vertices, coordinates near f64's limits, a point far off the piece.
    let cases: Vec<(Vec<V>, Vec<[usize; 3]>)> = vec![
        (vec![[0.0; 3]; 3], vec![[0, 1, 2]]),
        (vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]], vec![[0, 1, 2], [2, 1, 0]]),
        (vec![[1e300, 0.0, 0.0], [0.0, 1e300, 0.0], [0.0, 0.0, 1e300]], vec![[0, 1, 2], [0, 2, 1]]),
        (vec![[1e-300, 0.0, 0.0], [0.0, 1e-300, 0.0], [0.0, 0.0, 1e-300]], vec![[0, 1, 2], [0, 2, 1]]),
    ];
    for (vertices, triangles) in cases {
        let n = triangles.len();
        let flat: Vec<[[f64; 2]; 3]> = triangles.iter().map(|t| t.map(|i| [vertices[i][0], vertices[i][1]])).collect();
        let form = FormDto { vertices, triangles, piece: (0..n).map(|k| (k % 2) as u8).collect(), flat, stats: FormStatsDto { volume: 1.0 } };
        let _ = figures(&form, &FiguresOptionsDto::default());
        let _ = place(&form, &[vec![[0.0, 0.0], [1e308, -1e308]], vec![[5.0, 5.0]]]);
    }
}
