//! `simulate` against the closed-form facts of convex D-forms (Alexandrov–Pogorelov uniqueness,
//! Demaine & Price: the surface is the convex hull of its seam): every edge keeps its flat
//! length, the area is the pieces' area, the mesh is convex and closed, congruent pieces glued
//! congruently give the flat doubly covered piece, and the shape does not depend on resolution.
//! All figures are recomputed here from the returned mesh, not taken from the solver's stats.

#[path = "simulate_common/shapes.rs"]
mod shapes;

use dformer::arclen::ArcTable;
use dformer::contour::{Contour, Knot};
use dformer::simulate::{simulate, SimulateOptions, Simulation};
use dformer::Error;
use kurbo::{Affine, Point};
use std::collections::HashMap;

const K: f64 = 0.552_284_749_830_793_4;

/// Ellipse with semi-axes rx, ry, first anchor at (rx, 0), counter-clockwise.
fn ellipse(rx: f64, ry: f64) -> Contour {
    let knots = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)]
        .iter()
        .map(|&(x, y): &(f64, f64)| {
            let a = Point::new(rx * x, ry * y);
            let t = (-y * rx * K, x * ry * K);
            Knot { anchor: a, left: Point::new(a.x - t.0, a.y - t.1), right: Point::new(a.x + t.0, a.y + t.1) }
        })
        .collect();
    Contour::new(knots, 0).unwrap()
}

fn perimeter(c: &Contour) -> f64 {
    ArcTable::new(c, 1e-13).total()
}

fn circle_like(e: &Contour) -> Contour {
    let c = ellipse(1.0, 1.0);
    c.transformed(Affine::scale(perimeter(e) / perimeter(&c)))
}

fn run(a: &Contour, b: &Contour, offset: f64, n: usize) -> Simulation {
    simulate(a, b, &SimulateOptions { offset, resolution: n, ..Default::default() }).expect("simulate")
}

type V3 = [f64; 3];
fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Volume and area from the mesh (divergence theorem, cross products).
fn volume_area(s: &Simulation) -> (f64, f64) {
    let x = &s.vertices;
    let (mut v, mut a) = (0.0, 0.0);
    for &[i, j, k] in &s.triangles {
        v += dot(x[i], cross(x[j], x[k])) / 6.0;
        a += dot(cross(sub(x[j], x[i]), sub(x[k], x[i])), cross(sub(x[j], x[i]), sub(x[k], x[i]))).sqrt() / 2.0;
    }
    (v, a)
}

/// Every directed edge once and its reverse once: a closed, consistently oriented surface.
fn assert_closed(s: &Simulation) {
    let mut seen: HashMap<(usize, usize), usize> = HashMap::new();
    for t in &s.triangles {
        for m in 0..3 {
            *seen.entry((t[m], t[(m + 1) % 3])).or_default() += 1;
        }
    }
    for (&(a, b), &c) in &seen {
        assert_eq!(c, 1, "directed edge {a}->{b} used {c} times");
        assert_eq!(seen.get(&(b, a)), Some(&1), "edge {a}->{b} has no opposite: the mesh is not closed");
    }
}

/// Largest height of a vertex above any face's plane, relative to the size (the largest
/// distance of a vertex from the origin): 0 for a convex mesh.
fn convexity_violation(s: &Simulation) -> f64 {
    let size = s.vertices.iter().map(|p| dot(*p, *p).sqrt()).fold(0.0, f64::max);
    mesh_checks::outside_faces(s, size, 0.0)
}

#[test]
fn ellipses_at_quarter_offset_keep_lengths_area_and_are_convex() {
    let e = ellipse(2.0, 1.0);
    let p = perimeter(&e);
    let s = run(&e, &e, p / 4.0, 128);
    assert!(s.stats.converged, "wanted converged, got {:?}", s.stats);
    assert_closed(&s);
    let (v, a) = volume_area(&s);
    assert!((v - s.stats.volume).abs() <= 1e-9 * v, "volume: stats {} vs mesh {v}", s.stats.volume);
    let flat = 2.0 * e.signed_area().abs();
    assert!((a - flat).abs() / flat < 2e-3, "area: wanted {flat}, got {a}");
    // Seam edges are chords of arc length p/n each.
    let n = s.seam.len();
    let seam_len: f64 = (0..n).map(|k| {
        let d = sub(s.vertices[s.seam[(k + 1) % n]], s.vertices[s.seam[k]]);
        dot(d, d).sqrt()
    }).sum();
    assert!((seam_len - p).abs() / p < 1e-3, "seam length: wanted {p}, got {seam_len}");
    assert!(s.stats.max_strain < 1e-3, "max strain: wanted < 1e-3, got {}", s.stats.max_strain);
    let cv = convexity_violation(&s);
    // The solver leaves chords folded the wrong way by a sine below 1e-6 (solver::REFLEX_SINE).
    assert!(cv < 1e-5, "a vertex lies {cv} (relative) outside a face plane: not convex");
    let four_pi = 4.0 * std::f64::consts::PI;
    assert!((s.stats.angle_defect_sum - four_pi).abs() < 1e-6, "seam |defect| sum: wanted 4π, got {}", s.stats.angle_defect_sum);
    assert!(v > 0.1 * flat.powf(1.5) / 10.0, "a real volume, got {v}");
}

/// A w × h rectangle with corners rounded to radius r (quarter-circle cubics), counter-clockwise.
fn rounded_rectangle(w: f64, h: f64, r: f64) -> Contour {
    let k = K * r;
    let corner = |cx: f64, cy: f64, a0: f64| {
        // Quarter arc from angle a0 to a0 + 90° about (cx, cy): its two end knots.
        let (c0, s0, c1, s1) = (a0.cos(), a0.sin(), (a0 + std::f64::consts::FRAC_PI_2).cos(), (a0 + std::f64::consts::FRAC_PI_2).sin());
        let p0 = Point::new(cx + r * c0, cy + r * s0);
        let p1 = Point::new(cx + r * c1, cy + r * s1);
        [
            Knot { anchor: p0, left: p0, right: Point::new(p0.x - k * s0, p0.y + k * c0) },
            Knot { anchor: p1, left: Point::new(p1.x + k * s1, p1.y - k * c1), right: p1 },
        ]
    };
    let q = std::f64::consts::FRAC_PI_2;
    let knots: Vec<Knot> = [corner(w - r, r, -q), corner(w - r, h - r, 0.0), corner(r, h - r, q), corner(r, r, 2.0 * q)]
        .into_iter()
        .flatten()
        .collect();
    Contour::new(knots, 0).unwrap()
}

/// Regression: a rounded rectangle glued to a circle (both convex) never converged. Its D-form
/// has nearly flat regions whose chords settle slowly, and the solver's step budgets dropped the
/// right branch before it got there.
#[test]
fn rounded_rectangle_with_circle_converges_to_a_convex_shape() {
    let r = rounded_rectangle(60.0, 40.0, 10.0);
    let c = circle_like(&r);
    let p = perimeter(&r);
    let s = run(&r, &c, 0.1 * p, 128);
    assert!(s.stats.converged, "wanted converged, got {:?}", s.stats);
    assert_closed(&s);
    assert!(s.stats.max_strain < 1e-3, "max strain: wanted < 1e-3, got {}", s.stats.max_strain);
    let (v, a) = volume_area(&s);
    let flat = r.signed_area().abs() + c.signed_area().abs();
    assert!((a - flat).abs() / flat < 2e-3, "area: wanted {flat}, got {a}");
    let cv = convexity_violation(&s);
    assert!(cv < 1e-5, "a vertex lies {cv} (relative) outside a face plane: not convex");
    let v64 = run(&r, &c, 0.1 * p, 64).stats.volume;
    assert!((v64 - v).abs() / v < 5e-3, "volume 64 vs 128 seam vertices: {v64} vs {v}");
}

/// Regression: a 60 × 40 rectangle with 2 mm rounded corners glued to a circle ended 1.8e-2
/// strained, `converged: false`, at 10 of 16 offsets (256 seam vertices; the same shape at twice
/// the size too), while 1.5, 1.8, 2.2 and 2.5 mm corners converged everywhere. The graded seam
/// puts most of the coarsest level's 32 samples on the corners, and that 32-gon's only converged,
/// undented starts stood 1.23e-2 of the size outside a face, over the multistart's 1e-2: every
/// rung was refused until the steps ran out. A coarse start now only has to be within 2e-2
/// (`convex::COARSE_OUTSIDE_TOL`); the answer is still held to 1e-2, and here to the convexity,
/// the flat lengths (from `flat`) and the pieces' area.
#[test]
fn test_issue_14_a_rectangle_with_2mm_rounded_corners_converges_at_every_offset() {
    // First anchor where the rounding of the corner at the origin meets the left side.
    let r = shapes::rounded_rect(60.0, 40.0, 2.0);
    let c = circle_like(&r);
    let p = perimeter(&r);
    let flat = r.signed_area().abs() + c.signed_area().abs();
    for k in 0..16 {
        let s = run(&r, &c, k as f64 / 16.0 * p, 256);
        assert!(s.stats.converged, "offset {k}/16: wanted converged, got {:?}", s.stats);
        assert_closed(&s);
        let strain = mesh_checks::max_edge_strain(&s);
        assert!(strain <= 1e-3, "offset {k}/16: every edge within 1e-3 of its flat length, got {strain:.2e}");
        // Convex up to the folds between nearly coplanar chords of the flat sides (1.03e-5 at
        // offset 0; the polygon tests allow 1e-4).
        let cv = convexity_violation(&s);
        assert!(cv < 1e-4, "offset {k}/16: a vertex lies {cv} (relative) outside a face plane");
        let (_, a) = volume_area(&s);
        assert!((a - flat).abs() / flat < 2e-3, "offset {k}/16: area wanted {flat}, got {a}");
    }
}

/// Regression: two congruent rounded rectangles at an offset where long straight stretches of
/// both meet on the seam ended 1–7 % stretched. There the glued metric is flat, and the seam
/// edges' mean lengths leave a flat sample's curvature a hair below zero (−4.5e-4), so the
/// Bobenko–Izmestiev continuation flipped the edges around it to and fro and stalled. A
/// rectangle is its own half-turn, so a gluing half a perimeter on is the same gluing: each must
/// converge to its twin's volume (the twins converged before), every edge within 1e-3 of its
/// flat length.
#[test]
fn test_issue_14_congruent_rounded_rectangles_meeting_along_a_flat_seam_converge() {
    for (w, h, r, k, twin) in [(160.0, 60.0, 1.0, 8, 0), (120.0, 80.0, 3.0, 15, 7)] {
        let a = shapes::rounded_rect(w, h, r);
        let p = perimeter(&a);
        let want = volume_area(&run(&a, &a, twin as f64 / 16.0 * p, 256)).0;
        let s = run(&a, &a, k as f64 / 16.0 * p, 256);
        assert!(s.stats.converged, "{w} × {h} r {r} at {k}/16: wanted converged, got {:?}", s.stats);
        assert_closed(&s);
        let strain = mesh_checks::max_edge_strain(&s);
        assert!(strain <= 1e-3, "{w} × {h} r {r} at {k}/16: every edge within 1e-3 of its flat length, got {strain:.2e}");
        let got = volume_area(&s).0;
        println!("{w} × {h} r {r}: volume at {k}/16 {got:.1}, at {twin}/16 {want:.1} (wanted)");
        assert!((got - want).abs() <= 1e-4 * want, "{w} × {h} r {r}: wanted the volume at {twin}/16, {want:.1}, got {got:.1}");
    }
}

/// Regression: two congruent 120 × 80 rectangles with 3 mm corners glued near the offset where
/// they fold flat (74 mm: the gluing is then the mirror in the rectangle's middle line) ended
/// 1–3 % stretched at every offset within a millimetre of it. 222 of the 256 seam samples lie
/// where both pieces are straight, points of the polyhedron's faces rather than vertices, and
/// the intrinsic embedding stalled on them; they are now left out of it and put back after.
/// Offsets 74 ∓ δ mm are mirror images, so each pair must give one volume; the thin pillow
/// grows as √δ; every seam sample must be a vertex of the answer.
#[test]
fn test_issue_14_congruent_rectangles_near_their_flat_gluing_converge() {
    let a = shapes::rounded_rect(120.0, 80.0, 3.0);
    let volumes = [1.0, 4.0].map(|d| {
        let pair = mirror_volumes(&a, 74.0, d);
        for s in &pair.1 {
            assert!(s.seam.len() >= 256, "δ {d} mm: every seam sample a vertex, got {} seam vertices", s.seam.len());
        }
        pair.0
    });
    // Four times the distance from the flat gluing, twice the volume (to 10 %).
    let ratio = volumes[1] / volumes[0];
    assert!((ratio - 2.0).abs() <= 0.2, "wanted the volume to grow as √δ (ratio 2), got {ratio:.3}");
}

/// The congruent gluings of `a` at `flat ∓ d` (mm), where `flat` is an offset at which they fold
/// flat (a mirror gluing), so the two are mirror images: each must converge, every edge within
/// 1e-3 of its flat length, closed, and both must have one volume (to 1e-3). Returns the
/// volume and the two answers.
fn mirror_volumes(a: &Contour, flat: f64, d: f64) -> (f64, Vec<Simulation>) {
    let pair: Vec<Simulation> = [flat - d, flat + d]
        .iter()
        .map(|&o| {
            let s = run(a, a, o, 256);
            assert!(s.stats.converged, "offset {o} mm: wanted converged, got {:?}", s.stats);
            assert_closed(&s);
            let strain = mesh_checks::max_edge_strain(&s);
            assert!(strain <= 1e-3, "offset {o} mm: every edge within 1e-3 of its flat length, got {strain:.2e}");
            s
        })
        .collect();
    let v = [volume_area(&pair[0]).0, volume_area(&pair[1]).0];
    println!("δ {d:.4} mm: volumes {:.1} and {:.1}", v[0], v[1]);
    assert!((v[0] - v[1]).abs() <= 1e-3 * v[0], "δ {d} mm: mirror images must have one volume, got {v:?}");
    (v[0], pair)
}

/// Regression: two congruent 160 × 60 rectangles with 3 mm corners at 2/16 of the perimeter
/// (54.36 mm, 0.36 mm from the offset where they fold flat, 54 mm) were never solved: the
/// intrinsic path found the thin pillow, but the chord meshes' length equations dent such a
/// pillow by 5.3e-3 of its size, and answers dented beyond 2e-3 were refused. Such an answer is
/// now kept when no less dented one is found. Offsets 54 ∓ δ mm are mirror images (one volume
/// each), and the pillow's volume grows as √δ.
#[test]
fn test_issue_14_a_nearly_flat_pillow_dented_by_its_chords_is_kept() {
    let a = shapes::rounded_rect(160.0, 60.0, 3.0);
    let ds = [0.1, 2.0 / 16.0 * perimeter(&a) - 54.0];
    let volumes = ds.map(|d| mirror_volumes(&a, 54.0, d).0);
    let (want, got) = ((ds[1] / ds[0]).sqrt(), volumes[1] / volumes[0]);
    assert!((got - want).abs() <= 0.05 * want, "wanted the volume to grow as √δ (ratio {want:.3}), got {got:.3}");
}

/// Regression: creases across the seam were found only up to 256 seam vertices, counting every
/// sample, so two congruent 200 × 40 rectangles with 1 mm corners at 4/16 ended 36 % stretched
/// at 512. Counted without the samples on the straight stretches both share, they are well
/// within the limit: the gluing and its half-turn twin at 12/16 must converge at 512 to one
/// volume, within 0.5 % of the answer at 256, every edge within 1e-3 of its flat length.
#[test]
fn test_issue_14_creases_across_the_seam_at_512_seam_vertices() {
    let a = shapes::rounded_rect(200.0, 40.0, 1.0);
    let p = perimeter(&a);
    let coarse = volume_area(&run(&a, &a, 4.0 / 16.0 * p, 256)).0;
    let v = [4.0, 12.0].map(|k| {
        let s = run(&a, &a, k / 16.0 * p, 512);
        assert!(s.stats.converged, "{k}/16 at 512: wanted converged, got {:?}", s.stats);
        assert_closed(&s);
        let strain = mesh_checks::max_edge_strain(&s);
        assert!(strain <= 1e-3, "{k}/16 at 512: every edge within 1e-3 of its flat length, got {strain:.2e}");
        assert!(s.seam.len() > 512, "{k}/16 at 512: wanted seam vertices where the creases cross, got {}", s.seam.len());
        volume_area(&s).0
    });
    println!("volumes at 512: {:.1} and {:.1}; at 256: {coarse:.1}", v[0], v[1]);
    assert!((v[0] - v[1]).abs() <= 1e-3 * v[0], "one gluing, one volume: got {v:?}");
    assert!((v[0] - coarse).abs() <= 5e-3 * coarse, "wanted the volume at 256 ({coarse:.1}) within 0.5 %, got {:.1}", v[0]);
}

/// Regression: `converged` promises every edge within 1e-3 of its flat length, but a convex
/// pair's answer was called converged when its polyhedron met its own length equations, whose
/// seam edges take one length between A's and B's chords. A 60 × 40 rectangle with 1 mm corners
/// on a circle was "converged" at 128 seam vertices with edges 1.9e-3 off (7.8e-3 at 64): on so
/// few samples A's chords round the corners and the circle's do not. Such an answer is now
/// `converged: false` with `shortfall: "sampling"`, and its `strainFloor` is the least strain any
/// mesh on those samples can have; at 256 the same pair converges within 1e-3. Every figure is
/// measured here from `flat`.
#[test]
fn test_issue_14_converged_means_every_edge_within_1e_3_at_coarse_resolutions() {
    use dformer::simulate::Shortfall;
    let r = shapes::rounded_rect(60.0, 40.0, 1.0);
    let c = circle_like(&r);
    for n in [64, 128, 256] {
        let s = run(&r, &c, 0.0, n);
        let (strain, floor) = (mesh_checks::max_edge_strain(&s), mesh_checks::seam_floor(&s));
        println!("{n}: strain {strain:.2e}, floor {floor:.2e}, {:?}", s.stats.shortfall);
        assert!((s.stats.strain_floor - floor).abs() <= 1e-12, "{n}: wanted strainFloor {floor:.6e} (from flat), got {:.6e}", s.stats.strain_floor);
        assert_eq!(s.stats.converged, strain <= 1e-3, "{n}: converged must say whether every edge is within 1e-3 (got {strain:.2e})");
        if n < 256 {
            assert!(floor > 1e-3, "{n}: precondition: the samples rule out 1e-3, got a floor of {floor:.2e}");
            // A seam edge at the mean of chords `a < b` is `f/(1 − f)` off `a`, `f` the floor.
            assert!(strain <= floor / (1.0 - floor) + 1e-5, "{n}: wanted the polyhedron, every edge within the floor {floor:.2e}, got {strain:.2e}");
            assert_eq!(s.stats.shortfall, Some(Shortfall::Sampling), "{n}");
        } else {
            assert!(s.stats.converged, "256: wanted converged, got {:?}", s.stats);
        }
    }
}

/// Regression: a 60 × 40 rectangle with corners rounded below 0.3 mm, glued to a circle at 256
/// seam vertices, could not converge: the graded seam's steps were at most 16 times shorter than
/// the even ones, so A's and B's chords across such a corner differed by more than 1e-3 (1.8e-3
/// at r 0.2 mm, 2.6e-2 at 0.05, and most ended 10–180 % stretched). With steps down to a
/// 64th, corners from 0.1 mm up converge, every edge within 1e-3 of its flat length (from
/// `flat`), and the volume approaches the sharp rectangle's as the corners shrink.
#[test]
fn test_issue_14_corners_rounded_below_a_third_of_a_millimetre_converge() {
    let mut last = 0.0;
    for r in [0.3, 0.2, 0.1] {
        let a = shapes::rounded_rect(60.0, 40.0, r);
        let c = shapes::circle_for(&a);
        let mut volumes = Vec::new();
        for k in [0, 3] {
            let s = run(&a, &c, k as f64 / 16.0 * perimeter(&a), 256);
            let strain = mesh_checks::max_edge_strain(&s);
            println!("r {r}, {k}/16: strain {strain:.2e}, floor {:.2e}, volume {:.1}", mesh_checks::seam_floor(&s), s.stats.volume);
            assert!(s.stats.converged && strain <= 1e-3, "r {r} mm, {k}/16: wanted converged within 1e-3, got {strain:.2e}, {:?}", s.stats);
            assert_closed(&s);
            volumes.push(s.stats.volume);
        }
        // A circle is the same wherever the seam starts on it.
        assert!((volumes[0] - volumes[1]).abs() <= 1e-3 * volumes[0], "r {r} mm: volumes at 0 and 3/16 {volumes:?}");
        assert!(volumes[0] > last, "r {r} mm: wanted more volume than the rounder corners' {last}, got {}", volumes[0]);
        last = volumes[0];
    }
}

/// Regression: a rectangle glued to a circle never converged (strain ~10 %). Its corners fell
/// between seam samples, so each straddling seam edge was a corner-cutting chord on the rectangle
/// and a full chord on the circle: no shape can have both lengths. Corners are now seam vertices.
#[test]
fn rectangle_with_circle_converges_with_its_corners_on_the_seam() {
    let r = Contour::new([(0.0, 0.0), (80.0, 0.0), (80.0, 20.0), (0.0, 20.0)].iter().map(|&(x, y)| Knot::corner(Point::new(x, y))).collect(), 0).unwrap();
    let c = circle_arcs(16).transformed(Affine::scale(200.0 / perimeter(&circle_arcs(16))));
    let s = run(&r, &c, 0.0, 128);
    assert!(s.stats.converged, "wanted converged, got {:?}", s.stats);
    assert_closed(&s);
    assert!(s.stats.max_strain < 1e-3, "max strain: wanted < 1e-3, got {}", s.stats.max_strain);
    let cv = convexity_violation(&s);
    assert!(cv < 1e-5, "a vertex lies {cv} (relative) outside a face plane: not convex");
    let v64 = run(&r, &c, 0.0, 64).stats.volume;
    assert!((v64 - s.stats.volume).abs() / s.stats.volume < 5e-3, "volume 64 vs 128 seam vertices: {v64} vs {}", s.stats.volume);
}

/// Regression: a near-square rectangle glued to a circle ended on a wrong branch from every
/// saddle start (strain ~5 %); restarted from the convex hull of where a start ended, it converges.
#[test]
fn near_square_rectangle_with_circle_converges_from_a_hull_restart() {
    let r = Contour::new([(0.0, 0.0), (55.0, 0.0), (55.0, 45.0), (0.0, 45.0)].iter().map(|&(x, y)| Knot::corner(Point::new(x, y))).collect(), 0).unwrap();
    let c = circle_arcs(16).transformed(Affine::scale(200.0 / perimeter(&circle_arcs(16))));
    let s = run(&r, &c, 0.0, 128);
    assert!(s.stats.converged && s.stats.reflex_edges == 0, "wanted converged and convex, got {:?}", s.stats);
    assert_closed(&s);
    let cv = convexity_violation(&s);
    assert!(cv < 1e-5, "a vertex lies {cv} (relative) outside a face plane: not convex");
    let v64 = run(&r, &c, 0.0, 64).stats.volume;
    assert!((v64 - s.stats.volume).abs() / s.stats.volume < 5e-3, "volume 64 vs 128 seam vertices: {v64} vs {}", s.stats.volume);
}

#[test]
fn volume_is_the_same_at_two_resolutions() {
    let e = ellipse(2.0, 1.0);
    let c = circle_like(&e);
    let v64 = run(&e, &c, 0.0, 64).stats.volume;
    let v128 = run(&e, &c, 0.0, 128).stats.volume;
    let rel = (v64 - v128).abs() / v128;
    assert!(rel < 0.02, "volume 64 vs 128 seam vertices: {v64} vs {v128} ({rel:.2e} relative)");
}

#[test]
fn congruent_ellipses_at_zero_offset_give_the_flat_doubly_covered_ellipse() {
    let e = ellipse(2.0, 1.0);
    let s = run(&e, &e, 0.0, 64);
    let (v, a) = volume_area(&s);
    assert!(v.abs() < 1e-9 * a.powf(1.5), "wanted volume 0, got {v}");
    assert!(s.vertices.iter().all(|p| p[2].abs() < 1e-9), "every vertex in one plane");
    assert!(s.stats.converged && s.stats.max_strain < 1e-3, "{:?}", s.stats);
}

/// Regression: an 8:1 ellipse glued to its copy at half its perimeter (congruently, so its
/// D-form is the flat doubly covered ellipse) ended isometric but wavy, its two sheets crossing
/// each other by micrometres, and was called "crossing" at a volume of 1 mm³: laid onto its
/// plane by projection, its edges came out 1.6e-7 short, above the 1e-7 that flattening
/// allowed. Such congruent gluings are now laid out flat before any solve
/// (`simulate::convex::congruent`): thin ellipses from 4:1 to 16:1 (smooth curves through 72
/// points, as a traced drawing has them) lie flat, in one plane, converged.
#[test]
fn test_issue_14_thin_ellipses_with_their_copy_at_half_the_perimeter_lie_flat() {
    for k in [4.0, 8.0, 12.0, 16.0] {
        let pts: Vec<(f64, f64)> = (0..72).map(|i| i as f64 * std::f64::consts::TAU / 72.0).map(|t| (60.0 * t.cos(), 60.0 / k * t.sin())).collect();
        let e = shapes::smooth(&pts);
        let s = run(&e, &e, perimeter(&e) / 2.0, 256);
        let (v, a) = volume_area(&s);
        // The plane of the first three seam vertices far apart: every vertex within 1e-9 of
        // the size from it.
        let n = s.seam.len();
        let [p, q, r] = [0, n / 3, 2 * n / 3].map(|i| s.vertices[s.seam[i]]);
        let m = cross(sub(q, p), sub(r, p));
        let l = dot(m, m).sqrt();
        let off = s.vertices.iter().map(|x| (dot(m, sub(*x, p)) / l).abs()).fold(0.0, f64::max);
        println!("{k}:1: volume {v:.3e}, off the plane {off:.3e} mm, strain {:.2e}, shortfall {:?}", s.stats.max_strain, s.stats.shortfall);
        assert!(v.abs() < 1e-9 * a.powf(1.5), "{k}:1: wanted volume 0, got {v:.3e} mm³");
        assert!(off < 1e-9 * 60.0, "{k}:1: wanted every vertex in one plane, got one {off:.3e} mm off it");
        assert!(s.stats.converged, "{k}:1: wanted converged, got shortfall {:?}", s.stats.shortfall);
    }
}

/// A unit circle as `n` cubic arcs (handle length 4/3·tan(θ/4)), first anchor at (1, 0),
/// counter-clockwise. Its radius wobbles by ~ (θ/4)⁶: 2.7e-4 for 4 arcs, ~7e-8 for 16.
fn circle_arcs(n: usize) -> Contour {
    let th = std::f64::consts::TAU / n as f64;
    let k = 4.0 / 3.0 * (th / 4.0).tan();
    let knots = (0..n)
        .map(|i| {
            let (s, c) = (th * i as f64).sin_cos();
            let a = Point::new(c, s);
            Knot { anchor: a, left: Point::new(c + k * s, s - k * c), right: Point::new(c - k * s, s + k * c) }
        })
        .collect();
    Contour::new(knots, 0).unwrap()
}

/// Circles glued at any offset are congruent, so the D-form is the flat doubly covered disc.
/// The circle must be round to well below the solver's strain tolerance: a Bézier "circle"'s
/// radius wobble makes the gluing at other than a multiple of its arc only nearly congruent, and
/// the true D-form is then slightly inflated, not flat (6 arcs, wobble ~2e-5: a converged convex
/// shape of volume ~3.5e-3 for the unit circle; 4 arcs: ~0.02).
#[test]
fn congruent_circles_give_the_same_flat_shape_at_every_offset() {
    let c = circle_arcs(16);
    let p = perimeter(&c);
    for f in [0.0, 0.1, 0.2, 0.25, 0.37, 0.45] {
        let s = run(&c, &c, f * p, 64);
        let (v, a) = volume_area(&s);
        assert!(v.abs() < 1e-6 * a.powf(1.5), "offset {f}·perimeter: wanted volume 0, got {v}");
    }
}

#[test]
fn mirror_symmetric_input_gives_a_mirror_symmetric_shape() {
    // Ellipse with circle at zero offset: both pieces are symmetric about the x axis through
    // the start point, so the seam's distances are symmetric: |X_k − X_0| = |X_{n−k} − X_0|.
    let e = ellipse(2.0, 1.0);
    let c = circle_like(&e);
    let s = run(&e, &c, 0.0, 64);
    let n = s.seam.len();
    let x = &s.vertices;
    let d = |i: usize, j: usize| dot(sub(x[i], x[j]), sub(x[i], x[j])).sqrt();
    for k in 1..n / 2 {
        let (l, r) = (d(0, k), d(0, n - k));
        assert!((l - r).abs() < 1e-3 * l.max(r), "seam vertex {k}: {l} vs mirror {r}");
    }
}

#[test]
fn warm_start_reaches_the_same_shape() {
    let e = ellipse(2.0, 1.0);
    let p = perimeter(&e);
    let cold = run(&e, &e, p / 4.0, 128);
    let warm = simulate(&e, &e, &SimulateOptions { offset: p / 4.0, resolution: 128, warm: Some(cold.vertices.clone()), ..Default::default() }).unwrap();
    let rel = (warm.stats.volume - cold.stats.volume).abs() / cold.stats.volume;
    assert!(rel < 1e-5 && warm.stats.converged, "warm {} vs cold {} ({rel:.2e})", warm.stats.volume, cold.stats.volume);
}

/// Regression: the warm start used to mirror its (already outward) start while the flat
/// ear-clipping strip gave the volume no meaningful sign, so A's chords flipped onto B's cap and
/// the shape collapsed (volume ≈ 0 in WASM; natively it ran out of steps). Both were hidden by a
/// cold re-solve, whose steps are added to the count: a warm start from the solution itself must
/// take fewer steps than the cold solve, and a slider step must land on the cold answer, convex.
#[test]
fn warm_start_keeps_its_orientation_and_needs_no_cold_resolve() {
    let e = ellipse(2.0, 1.0);
    let p = perimeter(&e);
    let cold = run(&e, &e, p / 4.0, 256);
    let opts = SimulateOptions { offset: p / 4.0, resolution: 256, warm: Some(cold.vertices.clone()), ..Default::default() };
    let warm = simulate(&e, &e, &opts).unwrap();
    assert!(
        warm.stats.iterations < cold.stats.iterations,
        "warm from the solution: wanted fewer steps than the cold solve ({}), got {}",
        cold.stats.iterations,
        warm.stats.iterations
    );
    let rel = (warm.stats.volume - cold.stats.volume).abs() / cold.stats.volume;
    assert!(rel < 1e-6 && warm.stats.reflex_edges == 0, "warm {} vs cold {} ({rel:.2e}), {:?}", warm.stats.volume, cold.stats.volume, warm.stats);
    // One slider step (1 % of the perimeter) from there.
    let next = SimulateOptions { offset: 0.26 * p, ..opts };
    let warm = simulate(&e, &e, &next).unwrap();
    let cold = simulate(&e, &e, &SimulateOptions { warm: None, ..next }).unwrap();
    let rel = (warm.stats.volume - cold.stats.volume).abs() / cold.stats.volume;
    assert!(warm.stats.converged && warm.stats.reflex_edges == 0, "slider step: {:?}", warm.stats);
    assert!(rel < 1e-6, "slider step: warm {} vs cold {} ({rel:.2e})", warm.stats.volume, cold.stats.volume);
}

/// Regression (issue 14: the warm re-solve of a slider step took 1.66× the cold solve): the warm
/// start ear-clipped both pieces and flipped its way back to the convex triangulation, restarting
/// its damping at every flip pass: for the first 1 % step of the crossed 2:1 ellipses here (256
/// seam vertices) 4,211 flips and 81 steps, against 686 and 65 for the whole cold solve. From the
/// hull of the previous result it flips only what the step changes: B's chords, by seam index,
/// move by the few samples the offset moved, so about as many flips as a cold solve (814 there,
/// in 33 steps; since stop 29 the warm start climbs the ladder from 64 seam vertices, 554 flips
/// in 37 steps against the cold solve's 47). Speed is never asserted in a test; the work is:
/// each slider step, warm, must take fewer steps than the cold solve at the same offset and
/// fewer than twice its flips, and land on its volume (to the 1e-5 of the warm test above).
#[test]
fn warm_slider_step_does_not_reflip_every_chord() {
    let e = ellipse(2.0, 1.0);
    let p = perimeter(&e);
    for (name, b, start) in [("crossed ellipses", e.clone(), 0.25), ("ellipse with circle", circle_like(&e), 0.0)] {
        let mut prev = run(&e, &b, start * p, 256);
        for k in 1..=3 {
            let o = SimulateOptions { offset: (start + 0.01 * k as f64) * p, resolution: 256, ..Default::default() };
            let warm = simulate(&e, &b, &SimulateOptions { warm: Some(prev.vertices.clone()), ..o.clone() }).unwrap();
            let cold = simulate(&e, &b, &o).unwrap();
            let (w, c) = (&warm.stats, &cold.stats);
            assert!(w.converged && c.converged, "{name}, step {k}: warm {w:?}, cold {c:?}");
            assert!(
                w.flips < 2 * c.flips && w.iterations < c.iterations,
                "{name}, step {k}: warm took {} flips and {} steps, cold {} and {}",
                w.flips,
                w.iterations,
                c.flips,
                c.iterations
            );
            let rel = (w.volume - c.volume).abs() / c.volume;
            assert!(rel < 1e-5, "{name}, step {k}: warm volume {} vs cold {} ({rel:.2e})", w.volume, c.volume);
            prev = warm;
        }
    }
}

/// A warm start is only a hint (stop 29 made it climb the ladder from a quarter of the
/// resolution): from vertices that are no previous answer of this pair (three points, all at
/// one point, another pair's answer, a previous answer at another resolution, points on a line)
/// the solve still ends converged on the cold answer's volume, or honest, and never panics.
#[test]
fn warm_start_from_odd_vertices_lands_on_the_cold_answer() {
    let e = ellipse(2.0, 1.0);
    let p = perimeter(&e);
    let c = circle_like(&e);
    let cold = run(&e, &e, p / 4.0, 256);
    let other = run(&e, &c, 0.0, 256);
    let coarse = run(&e, &e, p / 4.0, 64);
    let line: Vec<[f64; 3]> = (0..256).map(|k| [k as f64, 0.0, 0.0]).collect();
    let odd: [(&str, Vec<[f64; 3]>); 5] = [
        ("three points", vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]),
        ("one point", vec![[1.0, 2.0, 3.0]; 256]),
        ("another pair's answer", other.vertices.clone()),
        ("this pair at 64 seam vertices", coarse.vertices.clone()),
        ("points on a line", line),
    ];
    for (name, warm) in odd {
        let o = SimulateOptions { offset: p / 4.0, resolution: 256, warm: Some(warm), ..Default::default() };
        let s = simulate(&e, &e, &o).unwrap_or_else(|err| panic!("{name}: wanted an answer, got {err}"));
        let rel = (s.stats.volume - cold.stats.volume).abs() / cold.stats.volume;
        assert!(s.stats.converged && rel < 1e-6, "{name}: wanted converged at volume {}, got {} ({rel:.1e}), {:?}", cold.stats.volume, s.stats.volume, s.stats);
        assert_eq!(s.seam.len(), 256, "{name}: the answer has the resolution's seam vertices");
    }
}

/// Regression (stop 29): a finer level of the ladder that the undamped try cannot settle is
/// relaxed again with the cold damping; given only the steps the try left, the 64-vertex level
/// of two 2:1 ellipses (eight cubic arcs each, 60 × 30) at a quarter offset ran out at its
/// first start and the solve took 862 steps to the same polyhedron instead of 139. The work,
/// not the time, is asserted. At 64 seam vertices A's and B's chords of a seam edge differ by
/// ~1.9e-3, so the answer is the polyhedron but not `converged` (`"sampling"`): every edge is
/// within that floor of its flat length, measured here from `flat`.
#[test]
fn test_issue_14_a_level_that_falls_back_keeps_its_budget() {
    let e = circle_arcs(8).transformed(Affine::scale_non_uniform(60.0, 30.0));
    let p = perimeter(&e);
    let s = run(&e, &e, p / 4.0, 64);
    let (strain, floor) = (mesh_checks::max_edge_strain(&s), mesh_checks::seam_floor(&s));
    assert!(s.stats.iterations <= 300, "64 seam vertices: wanted the polyhedron within 300 steps, got {:?}", s.stats);
    // A seam edge at the mean of chords `a < b` is `f/(1 − f)` off `a`, `f` the floor.
    assert!(floor > 1e-3 && strain <= floor / (1.0 - floor) + 1e-5, "64 seam vertices: wanted every edge within the seam floor {floor:.2e}, got {strain:.2e}");
    assert_eq!(s.stats.shortfall, Some(dformer::simulate::Shortfall::Sampling), "{:?}", s.stats);
}

#[test]
fn non_convex_piece_gives_a_finite_shape_and_honest_stats() {
    // A kidney-like piece (one concave stretch) glued to a circle of the same perimeter.
    let pts = [(3.0, 0.0), (2.0, 2.0), (0.0, 1.2), (-2.0, 2.0), (-3.0, 0.0), (-2.0, -2.0), (2.0, -2.0)];
    let knots: Vec<Knot> = (0..pts.len()).map(|i| {
        let (a, prev, next) = (pts[i], pts[(i + pts.len() - 1) % pts.len()], pts[(i + 1) % pts.len()]);
        let t = ((next.0 - prev.0) / 6.0, (next.1 - prev.1) / 6.0);
        Knot { anchor: Point::new(a.0, a.1), left: Point::new(a.0 - t.0, a.1 - t.1), right: Point::new(a.0 + t.0, a.1 + t.1) }
    }).collect();
    let k = Contour::new(knots, 0).unwrap();
    let c = circle_like(&k);
    let s = run(&k, &c, 0.0, 64);
    assert!(s.vertices.iter().flatten().all(|v| v.is_finite()), "finite vertices");
    let size = perimeter(&k);
    assert!(s.vertices.iter().all(|p| dot(*p, *p).sqrt() < size), "no vertex flies away");
    if s.stats.converged {
        assert!(s.stats.max_strain < 1e-3, "converged but strain {}", s.stats.max_strain);
    }
}

#[test]
fn mismatched_perimeters_and_bad_options_are_clear_errors() {
    let e = ellipse(2.0, 1.0);
    let big = e.transformed(Affine::scale(1.01));
    let err = simulate(&e, &big, &SimulateOptions::default()).unwrap_err();
    assert!(matches!(err, Error::PerimeterMismatch { .. }), "got {err}");
    assert!(err.to_string().contains("Normalize"), "got {err}");
    // The perimeters it names are the input's, not those of the frames the pieces are solved in.
    let Error::PerimeterMismatch { a, b } = err else { unreachable!() };
    let (pa, pb) = (perimeter(&e), perimeter(&big));
    assert!((a / pa - 1.0).abs() < 1e-6 && (b / pb - 1.0).abs() < 1e-6, "wanted the perimeters {pa} and {pb}, got {a} and {b}");
    let err = SimulateOptions::new(Some(f64::NAN), None, None, None).unwrap_err();
    assert!(err.to_string().contains("offset"), "got {err}");
    let err = SimulateOptions::new(None, Some(3.0), None, None).unwrap_err();
    assert!(err.to_string().contains("resolution"), "got {err}");
}

/// Regression: a cold solve of an ellipse with a circle at 0.01·perimeter converged natively but
/// not in WASM (1002 steps, strain 0.22, volume 2.46 instead of 2.98): last-bit differences of
/// libm's sin/cos/atan2/hypot tipped a near-tie in the coarse-to-fine path into a branch that
/// never converged, and the cold solve had no other start to fall back on. A cold solve must
/// converge to the isometric convex shape at every offset; for an ellipse with a circle of the
/// same perimeter (a circle is the same at every offset) the volume must not depend on it.
#[test]
fn cold_solve_converges_at_every_offset_for_ellipse_with_circle_and_two_ellipses() {
    let e = ellipse(2.0, 1.0);
    let c = circle_like(&e);
    let p = perimeter(&e);
    let offsets = [0.0, 0.01, 0.05, 0.13, 0.25, 0.37, 0.5];
    let mut ec_volumes = Vec::new();
    for (name, b) in [("ellipse with circle", &c), ("two ellipses", &e)] {
        for f in offsets {
            let s = run(&e, b, f * p, 128);
            assert!(s.stats.converged, "{name} at {f}·perimeter: wanted converged, got {:?}", s.stats);
            assert!(s.stats.max_strain <= 1e-3, "{name} at {f}·perimeter: wanted max strain ≤ 1e-3, got {}", s.stats.max_strain);
            let cv = convexity_violation(&s);
            assert!(cv < 1e-5, "{name} at {f}·perimeter: a vertex lies {cv} (relative) outside a face plane");
            if name == "ellipse with circle" {
                ec_volumes.push(volume_area(&s).0);
            }
        }
    }
    let (lo, hi) = ec_volumes.iter().fold((f64::MAX, 0.0f64), |(l, h), &v| (l.min(v), h.max(v)));
    // The 4-arc circle wobbles by 2.7e-4 in radius, so the volume may vary a little with offset.
    assert!((hi - lo) / hi < 1e-2, "ellipse with circle: wanted one volume at every offset, got {ec_volumes:?}");
}


/// A w × h rectangle (corners), counter-clockwise from the origin.
fn rectangle(w: f64, h: f64) -> Contour {
    Contour::new([(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)].iter().map(|&(x, y)| Knot::corner(Point::new(x, y))).collect(), 0).unwrap()
}

/// Converged, isometric to 1e-3, closed and convex at 128 seam vertices, with the volume at 64
/// within 2e-3 of it (the polyhedron's O(h²) discretization error).
/// `convex`: the largest relative height of a vertex above a face plane allowed.
fn assert_converges_with_circle(name: &str, piece: &Contour, convex: f64) {
    let c = circle_arcs(16).transformed(Affine::scale(perimeter(piece) / perimeter(&circle_arcs(16))));
    let s = run(piece, &c, 0.0, 128);
    assert!(s.stats.converged, "{name}: wanted converged, got {:?}", s.stats);
    assert!(s.stats.max_strain < 1e-3, "{name}: max strain: wanted < 1e-3, got {}", s.stats.max_strain);
    assert_closed(&s);
    let cv = convexity_violation(&s);
    assert!(cv < convex, "{name}: a vertex lies {cv} (relative) outside a face plane: not convex");
    let v64 = run(piece, &c, 0.0, 64).stats.volume;
    let rel = (v64 - s.stats.volume).abs() / s.stats.volume;
    assert!(rel < 2e-3, "{name}: volume 64 vs 128 seam vertices: {v64} vs {} ({rel:.1e})", s.stats.volume);
}

/// Regression: a 60×40 (and 57×43) rectangle glued to a circle ended on a wrong branch (strain
/// 2–66 %): the ear-clipping strip held rectangle chords longer than the circle's between the
/// same seam vertices (no isometric realization has such an edge), the solver only flipped when
/// Levenberg–Marquardt had fully stalled (~500 steps on such a triangulation), and at 256 seam
/// vertices a corner fell on another sample than one level down, leaving a dent that collinear
/// samples kept from flipping.
#[test]
fn rectangle_60x40_with_circle_converges() {
    assert_converges_with_circle("60×40", &rectangle(60.0, 40.0), 1e-5);
    assert_converges_with_circle("57×43", &rectangle(57.0, 43.0), 1e-5);
}

/// Regression: a square (and a 52×48 rectangle) glued to a circle never converged: its fourfold
/// symmetry gives the saddle start no height, and its D-form's seam has no saddle mode at all.
#[test]
fn square_with_circle_converges() {
    // The square's D-form has wide flat regions; at 128 seam vertices the solver keeps a dozen
    // folds between nearly coplanar triangles there (out-of-plane sine < 1e-2, a vertex ~2e-5 of
    // the size above a face plane), gone at 256.
    assert_converges_with_circle("50×50", &rectangle(50.0, 50.0), 1e-4);
    assert_converges_with_circle("52×48", &rectangle(52.0, 48.0), 1e-5);
}

/// Regression: a stadium (60×40 with r = 19) glued to a circle ended collapsed (strain ~15 %,
/// volume ≈ 0) for the same reason as the rectangles: chords that cannot be edges.
#[test]
fn stadium_with_circle_converges() {
    assert_converges_with_circle("stadium", &rounded_rectangle(60.0, 40.0, 19.0), 1e-5);
}

/// A regular m-gon of circumradius 1 turned by `rot`, counter-clockwise.
fn regular_polygon(m: usize, rot: f64) -> Contour {
    let corner = |i: usize| {
        let t = rot + std::f64::consts::TAU * i as f64 / m as f64;
        Knot::corner(Point::new(t.cos(), t.sin()))
    };
    Contour::new((0..m).map(corner).collect(), 0).unwrap()
}

/// A regular m-gon glued to a circle of the same perimeter at `offset` (a fraction of the
/// perimeter) converges to a closed convex shape at `n` and `2n` seam vertices, isometric to
/// 1e-3, with volumes within `agree` of each other and no vertex more than `convex` (relative
/// to the size) above a face plane. (A circle glued at any offset is the same
/// circle turned, so the shape does not depend on the offset.) Returns the volume at 2n.
fn assert_polygon_with_circle_converges(m: usize, rot: f64, offset: f64, n: usize, agree: f64, convex: f64) -> f64 {
    let piece = regular_polygon(m, rot);
    let c = circle_arcs(16).transformed(Affine::scale(perimeter(&piece) / perimeter(&circle_arcs(16))));
    let p = perimeter(&piece);
    let mut volumes = vec![];
    for k in [n, 2 * n] {
        let s = run(&piece, &c, offset * p, k);
        assert!(s.stats.converged, "{m}-gon, {k} seam vertices: wanted converged, got {:?}", s.stats);
        assert!(s.stats.max_strain < 1e-3, "{m}-gon, {k}: max strain: wanted < 1e-3, got {}", s.stats.max_strain);
        assert_closed(&s);
        let cv = convexity_violation(&s);
        assert!(cv < convex, "{m}-gon, {k}: a vertex lies {cv} (relative) outside a face plane: not convex");
        let (v, _) = volume_area(&s);
        assert!(v > 0.0 && (v - s.stats.volume).abs() <= 1e-9 * v, "{m}-gon, {k}: volume: stats {} vs mesh {v}", s.stats.volume);
        volumes.push(v);
    }
    let rel = (volumes[0] - volumes[1]).abs() / volumes[1];
    assert!(rel < agree, "{m}-gon: volume {n} vs {} seam vertices: {volumes:?} ({rel:.1e})", 2 * n);
    volumes[1]
}

/// Regression: an equilateral triangle glued to a circle (a classic student design) never
/// converged (strain 25–38 %, 5,000 steps). Three causes: (1) no start had its seam's threefold
/// mode (the saddle is twofold, the fourfold start fourfold), so every start fell on a wrong
/// branch; (2) a finer level re-triangulated its straight sides from scratch (their ears have no
/// area), and the flips stalled in fans of chords from one sample to consecutive samples of the
/// other side of a corner, whose reflex chords can never flip; (3) a locally convex realization
/// that is not convex as a whole (no reflex chord, a vertex a whole size outside a face plane,
/// 2 % less volume) was accepted as the answer.
#[test]
fn triangle_with_circle_converges() {
    let v0 = assert_polygon_with_circle_converges(3, 0.3, 0.0, 64, 2e-3, 1e-5);
    let v1 = assert_polygon_with_circle_converges(3, 0.3, 0.13, 64, 2e-3, 1e-5);
    assert!((v0 - v1).abs() / v0 < 1e-4, "the offset turns the circle only: volumes {v0} and {v1}");
}

/// Regression: a regular octagon and a 12-gon glued to a circle ended unconverged (strain
/// 1–3 %): the same missing start mode (cos 8θ, cos 12θ) and the same fans at the corners as
/// the triangle. Their many corners (cone points of small curvature) make the volume converge
/// more slowly with the resolution than a smooth piece's.
#[test]
fn octagon_and_12_gon_with_circle_converge() {
    assert_polygon_with_circle_converges(8, 0.1, 0.13, 128, 3e-3, 1e-4);
    assert_polygon_with_circle_converges(12, 0.0, 0.13, 128, 1e-2, 1e-4);
}

/// A 48-gon glued to a circle is nearly the flat doubly covered disc (nearly congruent pieces),
/// where the solver may not converge; whatever it returns must say so honestly: converged only
/// when isometric and convex.
#[test]
fn nearly_congruent_48_gon_with_circle_is_honest() {
    let piece = regular_polygon(48, 0.0);
    let c = circle_arcs(16).transformed(Affine::scale(perimeter(&piece) / perimeter(&circle_arcs(16))));
    let s = run(&piece, &c, 0.0, 64);
    assert!(s.stats.volume.is_finite() && s.stats.max_strain.is_finite(), "{:?}", s.stats);
    assert_closed(&s);
    if s.stats.converged {
        assert!(s.stats.max_strain < 1e-3, "converged with strain {}", s.stats.max_strain);
        assert!(convexity_violation(&s) < 1e-4, "converged but not convex: {}", convexity_violation(&s));
    }
}

/// Converged, isometric, closed, convex, without reflex chords: the checks of a polyhedral
/// D-form (two polygons), whose mesh is exact (every crease a chord between corners), so the
/// tolerances are near round-off. Returns the volume.
fn assert_polyhedral_pair_converges(name: &str, a: &Contour, b: &Contour, offset: f64, n: usize) -> f64 {
    let s = run(a, b, offset * perimeter(a), n);
    assert!(s.stats.converged, "{name} at offset {offset}, {n} seam vertices: wanted converged, got {:?}", s.stats);
    assert!(s.stats.max_strain < 1e-8, "{name} at offset {offset}: max strain {}", s.stats.max_strain);
    assert_eq!(s.stats.reflex_edges, 0, "{name} at offset {offset}: reflex chords");
    assert_closed(&s);
    let cv = convexity_violation(&s);
    // 1e-5: the fans from a corner to collinear samples have thin triangles, whose planes
    // magnify the positions' round-off (1e-10 strain gives ~2e-6 here).
    assert!(cv < 1e-5, "{name} at offset {offset}: a vertex lies {cv} (relative) outside a face plane: not convex");
    let (v, _) = volume_area(&s);
    v.abs()
}

/// [`assert_polyhedral_pair_converges`] at each of `resolutions`, with one volume (to 1e-8) at
/// all of them: the polyhedron is exact at any sampling that holds its vertices, so its volume
/// does not depend on the sampling (resolutions that are no refinement of each other included).
fn assert_exact_polyhedron(name: &str, a: &Contour, b: &Contour, offset: f64, resolutions: &[usize]) {
    let v: Vec<f64> = resolutions.iter().map(|&n| assert_polyhedral_pair_converges(name, a, b, offset, n)).collect();
    for (n, vn) in resolutions.iter().zip(&v).skip(1) {
        assert!((vn / v[0] - 1.0).abs() < 1e-8, "{name} at offset {offset}: volume {vn} at {n} seam vertices, {} at {}", v[0], resolutions[0]);
    }
}

/// An equilateral triangle (circumradius 30, turned by 0.3) and a square of the same perimeter.
fn triangle_and_square() -> (Contour, Contour) {
    let a = ngon(3, 30.0, 0.3);
    let b = rectangle(50.0, 50.0);
    let b = b.transformed(Affine::scale(perimeter(&a) / perimeter(&b)));
    (a, b)
}

/// Regression: a 90×10 rectangle glued to a square (equal perimeters) at offset 0 (and 1/4,
/// the same gluing by the square's symmetry) ended unconverged (strain 1.2e-7, two reflex
/// chords, 5000 steps): a strip between a corner and two samples of a straight side was
/// folded ("popped") across a flat face, an isometric realization whose chords cannot flip
/// (their quads have three collinear samples). The polyhedron is exact at any sampling that
/// holds the corners, so its volume is the same at 128 and at 160 seam vertices (not nested:
/// 160 samples are no refinement of 128) to round-off.
#[test]
fn thin_rectangle_with_square_converges_at_every_offset() {
    let a = rectangle(90.0, 10.0);
    let b = rectangle(50.0, 50.0);
    let b = b.transformed(Affine::scale(perimeter(&a) / perimeter(&b)));
    for f in [0.13, 0.41] {
        assert_polyhedral_pair_converges("90×10 with a square", &a, &b, f, 128);
    }
    // At 48 it "converged" with three reflex chords at volume 7,961 (a fold DENT_SINE let pass).
    assert_exact_polyhedron("90×10 with a square", &a, &b, 0.0, &[128, 160, 48]);
}

/// A regular m-gon of circumradius r turned by `rot`.
fn ngon(m: usize, r: f64, rot: f64) -> Contour {
    regular_polygon(m, rot).transformed(Affine::scale(r))
}

/// Regression: two equilateral triangles glued at 0.13 of the perimeter ended on a folded,
/// isometric but non-convex branch (strain 3e-10, 14 reflex chords, reflex seam edges): at 128
/// seam vertices every dihedral sign between coplanar triangles of the flat faces is round-off,
/// and the starts fold. Solved on the six corners alone, then laid onto the samples, it is the
/// convex polyhedron (Alexandrov), exact at every sampling that holds the corners: the same
/// volume at 128 and 160 seam vertices.
#[test]
fn two_triangles_at_an_offset_converge() {
    let (a, b) = (ngon(3, 30.0, 0.0), ngon(3, 30.0, 0.0));
    assert_exact_polyhedron("two triangles", &a, &b, 0.13, &[128, 160]);
}

/// Regression: an equilateral triangle glued to a square at 0.13 of the perimeter ended
/// unconverged (strain 9 %, 38 reflex chords); see `two_triangles_at_an_offset_converge`.
#[test]
fn triangle_with_square_converges_at_an_offset() {
    let (a, b) = triangle_and_square();
    assert_exact_polyhedron("triangle with a square", &a, &b, 0.13, &[128, 96]);
}

/// Regression: two equilateral triangles at a quarter-perimeter offset "converged" to volume 0
/// (a flat-folded sheet, flaps folded onto a face, which no dihedral or plane test sees: a 180°
/// fold has out-of-plane sine 0, but its area is more than twice its shadow's), at 40–61 seam
/// vertices with 4–21 reflex chords and volumes from 5,500 to 6,700, and at 52 without a reflex
/// chord but with a vertex 30 % of the size outside a face plane (locally convex, not embedded).
/// Then it ended unconverged (strain 0.3 at 128 and 256): three creases of the polyhedron cross
/// the seam halfway along the short stretches between corners, where no sample sat, so no mesh
/// of chords held it. With a seam vertex at each crossing (the shortest path between two
/// corners, straight in the unfolding across the seam) it is exact: the same volume at 128 and
/// at 96 seam vertices (not nested), and at 52.
#[test]
fn two_triangles_at_a_quarter_offset_converge() {
    let (a, b) = (ngon(3, 30.0, 0.0), ngon(3, 30.0, 0.0));
    assert_exact_polyhedron("two triangles", &a, &b, 0.25, &[128, 96, 52]);
}

/// Regression: two equilateral triangles at 0.41 of the perimeter ended unconverged (strain
/// 0.1), for the same reason as `two_triangles_at_a_quarter_offset_converge`.
#[test]
fn two_triangles_at_an_offset_of_0_41_converge() {
    let (a, b) = (ngon(3, 30.0, 0.0), ngon(3, 30.0, 0.0));
    assert_exact_polyhedron("two triangles", &a, &b, 0.41, &[128, 96]);
}

/// Regression: an equilateral triangle with a square at 0.41 of the perimeter ended unconverged
/// (strain 0.5 at 128 and 256, 0 reflex chords only at 96 and 160, and there 8): creases of the
/// polyhedron cross the seam between corners (see `two_triangles_at_a_quarter_offset_converge`).
#[test]
fn triangle_with_square_at_an_offset_of_0_41_converges() {
    let (a, b) = triangle_and_square();
    assert_exact_polyhedron("triangle with a square", &a, &b, 0.41, &[128, 96]);
}

/// Regression: the restart of a polygon pair after a failed level had its own 300 steps on top of
/// the cap, so `stats.iterations` could pass the user's `max_iterations` by that much per level.
/// Every kind of cold solve (smooth pair, polygon with a curve, polygon pair solved, polygon pair
/// not solved) stays within the cap, whatever it is.
#[test]
fn iterations_never_exceed_max_iterations() {
    let (tri, square) = triangle_and_square();
    let e = ellipse(40.0, 20.0);
    let cases = [("ellipse with circle", e.clone(), circle_like(&e), 0.1), ("triangle with square", tri, square, 0.41), ("two triangles", ngon(3, 30.0, 0.0), ngon(3, 30.0, 0.0), 0.25)];
    for (name, a, b, f) in &cases {
        for cap in [1, 40, 333, 1200] {
            let opts = SimulateOptions { offset: f * perimeter(a), resolution: 64, max_iterations: cap, ..Default::default() };
            let s = simulate(a, b, &opts).expect("simulate");
            assert!(s.stats.iterations <= cap, "{name}, max_iterations {cap}: wanted ≤ {cap} steps, got {}", s.stats.iterations);
            // Warm from another offset's shape (a warm start that fails falls back to a cold solve).
            let warm = SimulateOptions { offset: (f + 0.2) * perimeter(a), warm: Some(s.vertices.clone()), ..opts };
            let w = simulate(a, b, &warm).expect("simulate");
            assert!(w.stats.iterations <= cap, "{name} warm, max_iterations {cap}: wanted ≤ {cap} steps, got {}", w.stats.iterations);
        }
    }
}

/// A 2:1 ellipse flattened into a polyline of `m` points (corners at equal parameter steps, as
/// CAD and laser-cutter SVGs or Inkscape's "Flatten Beziers" give it).
fn polyline_ellipse(m: usize, rx: f64, ry: f64) -> Contour {
    let corner = |i: usize| {
        let t = std::f64::consts::TAU * i as f64 / m as f64;
        Knot::corner(Point::new(rx * t.cos(), ry * t.sin()))
    };
    Contour::new((0..m).map(corner).collect(), 0).unwrap()
}

/// Regression: a 72-point polyline ellipse (2:1) glued to a circle never converged (strain
/// 3e-2 – 3e-1 at 128 and 256 seam vertices, every offset): its 72 corners on the ladder's
/// coarsest level of 32 samples, and the corners left over placed on the next level's midpoints,
/// made seam edges from almost nothing to two steps long, and the ladder ended in a wrong branch.
/// The ladder now starts at the first level with room for the corners (`Glue::nests`). The
/// shape is the smooth ellipse's with a circle, to the polyline's error.
#[test]
fn polyline_ellipse_with_circle_converges() {
    let piece = polyline_ellipse(72, 2.0, 1.0);
    let c = circle_arcs(16).transformed(Affine::scale(perimeter(&piece) / perimeter(&circle_arcs(16))));
    let p = perimeter(&piece);
    // The smooth 2:1 ellipse with a circle, scaled to the polyline's perimeter.
    let e = ellipse(2.0, 1.0);
    let k = p / perimeter(&e);
    let smooth = run(&e, &circle_like(&e), 0.0, 128).stats.volume * k.powi(3);
    for offset in [0.0, 0.13] {
        let s = run(&piece, &c, offset * p, 128);
        assert!(s.stats.converged, "offset {offset}: wanted converged, got {:?}", s.stats);
        assert!(s.stats.max_strain < 1e-3, "offset {offset}: max strain {}", s.stats.max_strain);
        assert_closed(&s);
        let cv = convexity_violation(&s);
        assert!(cv < 1e-4, "offset {offset}: a vertex lies {cv} (relative) outside a face plane");
        let rel = (s.stats.volume - smooth).abs() / smooth;
        assert!(rel < 5e-3, "offset {offset}: volume {} vs the smooth ellipse's {smooth} ({rel:.1e})", s.stats.volume);
    }
}

/// Regression: a 64-gon glued to a circle (nearly congruent pieces, a nearly flat form) never
/// converged (strain 7e-4 at 128 and 256 seam vertices): 64 corners on 32 samples, as for the
/// polyline ellipse above. The form is a thin lens (volume 0.0036 against the disc's area π),
/// whose volume still moves by ~6 % from 128 to 256 seam vertices.
#[test]
fn sixty_four_gon_with_circle_converges() {
    assert_polygon_with_circle_converges(64, 0.0, 0.13, 128, 1e-1, 1e-4);
}

#[path = "simulate_common/mesh_checks.rs"]
#[allow(dead_code)]
mod mesh_checks;

/// Regression (issue 14, requirement 1: converged means every mesh edge within 1e-3 of its flat
/// length): a 60×40 rectangle with 2 mm rounded corners glued to a circle at 256 seam vertices
/// was "converged" with 3.1e-3 edge strain, and with 1 mm corners ended unconverged at 0.12. At
/// equal steps each corner's arc spans one or two seam edges, whose chords on the rectangle and
/// on the circle differ by ~(hκ)²/24; the seam samples are now spaced by curvature
/// (`simulate::density`). Edge strain measured here from `flat` and the vertices alone.
#[test]
fn test_issue_14_tight_rounded_corners_keep_every_edge_within_1e3() {
    for r in [1.0, 2.0, 5.0] {
        let piece = rounded_rectangle(60.0, 40.0, r);
        let c = circle_arcs(16).transformed(Affine::scale(perimeter(&piece) / perimeter(&circle_arcs(16))));
        let s = run(&piece, &c, 0.0, 256);
        let strain = mesh_checks::max_edge_strain(&s);
        assert!(s.stats.converged, "r = {r} mm: wanted converged, got {:?}", s.stats);
        assert!(strain <= 1e-3, "r = {r} mm: wanted every edge within 1e-3 of its flat length, got {strain:.2e}");
        assert_closed(&s);
    }
}

/// Regression (issue 14): a 60×40 rectangle whose corners are rounded at 0.05 mm, glued to a
/// circle, ended 19 % strained at 256 seam vertices and 180 % at 128 (through itself). Each
/// rounding turns by 90° in 0.08 mm, which the graded seam steps (at most 16 times shorter than
/// the even ones, 0.05 mm here) cannot follow: the seam edges cut across it on the rectangle
/// only. Such a turn is now a kink, a seam vertex walked as a corner (`simulate::kink`). The form
/// must be the sharp rectangle's, scaled by the perimeters' ratio cubed (the rounding takes
/// (8 − 2π)r off the perimeter), within 2e-4, at both resolutions; converged, with every edge
/// within 1e-3 of its flat length (from `flat`) and closed. (The walk's deficits shorten the
/// rectangle's seam steps against the circle's by 3.1e-5 per 0.01 mm of radius; past about
/// 1.5e-4 at 256 seam vertices the convex path finds no realization, see issue 14's notes, so
/// the radii stay below 0.05 mm.)
#[test]
fn test_issue_14_corners_rounded_below_the_seam_step_are_taken_as_corners() {
    let sharp = rectangle(60.0, 40.0);
    let with_circle = |piece: &Contour| circle_arcs(16).transformed(Affine::scale(perimeter(piece) / perimeter(&circle_arcs(16))));
    for n in [128, 256] {
        let v0 = run(&sharp, &with_circle(&sharp), 0.0, n).stats.volume;
        for r in [0.01, 0.03, 0.04] {
            let piece = rounded_rectangle(60.0, 40.0, r);
            let s = run(&piece, &with_circle(&piece), 0.0, n);
            assert!(s.stats.converged, "r = {r} mm, {n} seam vertices: wanted converged, got {:?}", s.stats);
            let strain = mesh_checks::max_edge_strain(&s);
            assert!(strain <= 1e-3, "r = {r} mm, {n}: wanted every edge within 1e-3 of its flat length, got {strain:.2e}");
            assert_closed(&s);
            let want = v0 * (perimeter(&piece) / perimeter(&sharp)).powi(3);
            let got = mesh_checks::volume(&s);
            assert!((got / want - 1.0).abs() <= 2e-4, "r = {r} mm, {n}: wanted the sharp rectangle's volume scaled, {want:.1} mm³, got {got:.1}");
        }
    }
}

/// Regression (issue 14): two congruent rectangles with rounded corners glued at an offset, the
/// classic D-form of two equal pieces, converged at few offsets (strain 1e-2 to 0.5 after 5,000
/// steps): the form's creases run from a corner of one piece straight across a side both pieces
/// share into the other, and no mesh whose edges stay inside one piece holds such a crease. The
/// intrinsic path (Bobenko & Izmestiev's method on an intrinsic triangulation, cut along the seam
/// afterwards) adds a seam vertex where a crease crosses the seam.
#[test]
fn test_issue_14_congruent_rounded_rectangles_crease_across_the_seam() {
    let r = shapes::rounded_rect(200.0, 40.0, 1.0);
    let p = perimeter(&r);
    for k in [2, 3, 7] {
        let s = run(&r, &r, k as f64 / 16.0 * p, 256);
        let what = format!("offset {k}/16");
        let v = assert_convex_answer(&s, &what, &r, &r);
        assert!(s.seam.len() > 256, "{what}: wanted seam vertices added where creases cross the seam, got {}", s.seam.len());
        // Convex up to the folds the samples' metric keeps: with each chord at its flat length and
        // each seam edge between its two, it is convex only up to the corners' chord gap, and the
        // plane of a thin face there tilts (2.9e-4 and 2.0e-3 of the size at offsets 2 and 3);
        // the wrong, dented branches the chord ladder ended on stood 0.3 to 1.8 sizes out.
        let cv = convexity_violation(&s);
        assert!(cv < 1e-2, "{what}: a vertex lies {cv:.2e} (relative) outside a face plane");
        assert_same_volume_half_a_turn_on(&r, k, v);
    }
}

/// The rectangle `r` is symmetric under a half turn, so the gluing half a perimeter further on
/// than `k`/16 is the same D-form (Alexandrov's uniqueness): it must have the volume `v`.
fn assert_same_volume_half_a_turn_on(r: &Contour, k: usize, v: f64) {
    let w = run(r, r, (k as f64 / 16.0 + 0.5) * perimeter(r), 256);
    assert!(w.stats.converged, "offset {k}/16 + 1/2: wanted converged, got {:?}", w.stats);
    let (vw, _) = volume_area(&w);
    println!("offset {k}/16: volume {v:.6e}, half a perimeter on {vw:.6e}");
    assert!((vw - v).abs() / v < 1e-3, "offset {k}/16: volume {v} but {vw} half a perimeter on");
}

/// What a converged answer of two convex pieces `a` and `b` promises, checked from the mesh
/// alone: closed; every edge within the seam samples' floor of its flat length (A's and B's
/// chords of one seam edge differ at tight corners), plus the length equations' 1e-5; no vertex
/// more than 1e-2 of the size above a face that is not a sliver ([`sound_convexity_violation`]);
/// no self-intersection; the pieces' area; a seam as long as the outline. Returns the volume.
fn assert_convex_answer(s: &Simulation, what: &str, a: &Contour, b: &Contour) -> f64 {
    assert!(s.stats.converged, "{what}: wanted converged, got {:?}", s.stats);
    assert_closed(s);
    let (strain, floor) = (mesh_checks::max_edge_strain(s), mesh_checks::seam_floor(s));
    assert!(strain <= floor + 1e-5, "{what}: wanted every edge within the seam floor {floor:.2e} of its flat length, got {strain:.2e}");
    let cv = sound_convexity_violation(s);
    assert!(cv < 1e-2, "{what}: a vertex lies {cv:.2e} (relative) outside the plane of a face that is no sliver");
    let (v, area) = volume_area(s);
    let flat = a.signed_area().abs() + b.signed_area().abs();
    assert!((area - flat).abs() / flat < 2e-3, "{what}: area wanted {flat}, got {area}");
    let hits = mesh_checks::self_intersections(s, 1e-9);
    assert!(hits.is_empty(), "{what}: wanted no self-intersection, got {hits:?}");
    let (n, p) = (s.seam.len(), perimeter(a));
    let seam: f64 = (0..n).map(|m| mesh_checks::norm(mesh_checks::sub(s.vertices[s.seam[(m + 1) % n]], s.vertices[s.seam[m]]))).sum();
    assert!((seam - p).abs() / p < 1e-3, "{what}: seam length wanted {p}, got {seam}");
    v
}

/// [`convexity_violation`] against the faces that are not slivers in their flat piece (twice
/// the area at least 2e-2 of the longest side squared, read from `flat`): a sliver's plane tilts
/// with movements that change no length noticeably, and says nothing of the shape.
fn sound_convexity_violation(s: &Simulation) -> f64 {
    let x = &s.vertices;
    let size = x.iter().map(|p| dot(*p, *p).sqrt()).fold(0.0, f64::max);
    let mut worst = 0.0f64;
    for (t, &[i, j, k]) in s.triangles.iter().enumerate() {
        let f = s.flat[t];
        let d2 = |u: [f64; 2], v: [f64; 2]| (u[0] - v[0]).powi(2) + (u[1] - v[1]).powi(2);
        let longest = d2(f[0], f[1]).max(d2(f[1], f[2])).max(d2(f[2], f[0]));
        let twice_area = ((f[1][0] - f[0][0]) * (f[2][1] - f[0][1]) - (f[1][1] - f[0][1]) * (f[2][0] - f[0][0])).abs();
        if twice_area < 2e-2 * longest {
            continue;
        }
        let n = cross(sub(x[j], x[i]), sub(x[k], x[i]));
        let l = dot(n, n).sqrt();
        for p in x {
            worst = worst.max(dot(n, sub(*p, x[i])) / l / size);
        }
    }
    worst
}

/// Regression (issue 14): the intrinsic path's answers were held to the sine of every chord and
/// the plane of every face, and needle triangles (a long crease to two seam samples a fraction of
/// a step apart) and caps (three nearly collinear samples) turn those arbitrarily. Convex forms,
/// isometric to 1e-6, were refused, and the chord ladder then ended 3e-1 strained for two
/// 200 × 40 rectangles with 3 mm corners at 7/16, 5e-1 for 120 × 80 with 1 mm corners at 7/16,
/// and 8e-2 for a triangle with 1 mm corners on a circle at every offset.
#[test]
fn test_issue_14_needle_triangles_do_not_hide_the_convex_form() {
    for (w, h, r, k) in [(200.0, 40.0, 3.0, 7), (120.0, 80.0, 1.0, 7)] {
        let rect = shapes::rounded_rect(w, h, r);
        let s = run(&rect, &rect, k as f64 / 16.0 * perimeter(&rect), 256);
        let v = assert_convex_answer(&s, &format!("{w} × {h} r {r} at {k}/16"), &rect, &rect);
        assert_same_volume_half_a_turn_on(&rect, k, v);
    }
    assert_triangle_on_a_circle_is_one_form(&[1, 3]);
}

/// A triangle with 1 mm corners glued to a circle at the offsets `k`/16: each a convex answer
/// ([`assert_convex_answer`]), and one form (a circle is the same wherever the seam starts on it:
/// the volumes within 1e-3).
fn assert_triangle_on_a_circle_is_one_form(sixteenths: &[usize]) {
    let tri = shapes::rounded_triangle(1.0);
    let circle = shapes::circle_for(&tri);
    let volumes: Vec<f64> = sixteenths
        .iter()
        .map(|&k| assert_convex_answer(&run(&tri, &circle, k as f64 / 16.0 * perimeter(&tri), 256), &format!("triangle r 1 + circle at {k}/16"), &tri, &circle))
        .collect();
    println!("triangle r 1 + circle at {sixteenths:?}/16: volumes {volumes:?}");
    let (lo, hi) = volumes.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    assert!((hi - lo) / hi < 1e-3, "triangle r 1 + circle: wanted one form at every offset, got volumes {volumes:?}");
}

/// Regression (issue 14): two congruent 200 × 40 rectangles with 8 mm corners, a common student
/// design, ended unconverged at 11 of 16 offsets (4e-2 strain after 5,000 steps): the intrinsic
/// path's last relax, whose flips make no cap, settles at 1.5–5e-6 on the length equations and
/// was held to 1e-6. It is now held to 1e-5, a hundredth of what `converged` promises.
#[test]
fn test_issue_14_rectangles_with_8mm_corners_settle_within_1e_5() {
    let rect = shapes::rounded_rect(200.0, 40.0, 8.0);
    for k in [3, 7] {
        let s = run(&rect, &rect, k as f64 / 16.0 * perimeter(&rect), 256);
        let v = assert_convex_answer(&s, &format!("200 × 40 r 8 at {k}/16"), &rect, &rect);
        assert_same_volume_half_a_turn_on(&rect, k, v);
    }
}

/// Regression (issue 14): Bobenko & Izmestiev's flips may need two edges between the same two
/// vertices (two straight segments of the metric), which the intrinsic mesh refused. The
/// embedding then stalled: a triangle with 1 mm corners on a circle ended 8e-2 strained at every
/// even sixteenth, and two congruent hexagons with 1 mm corners 1e-2 at 0 and 1/2.
#[test]
fn test_issue_14_flips_that_need_a_second_edge_between_two_vertices() {
    assert_triangle_on_a_circle_is_one_form(&[0, 2]);
    // A hexagon is symmetric under a half turn.
    let third = std::f64::consts::PI / 3.0;
    let hexagon: Vec<(f64, f64)> = (0..6).map(|k| (50.0 * (k as f64 * third).cos(), 50.0 * (k as f64 * third).sin())).collect();
    let hexagon = shapes::rounded_polygon(&hexagon, 1.0);
    let v = assert_convex_answer(&run(&hexagon, &hexagon, 0.0, 256), "hexagon r 1 with a congruent copy at 0", &hexagon, &hexagon);
    assert_same_volume_half_a_turn_on(&hexagon, 0, v);
}
