//! `simulate` on random pieces (convex ovals and often non-convex stars): no error for valid input, no explosion, a
//! closed mesh, and stats that tell the truth. The flat lengths are recomputed here from the
//! pieces (each seam sample checked on its outline at one arc length of the gluing by the
//! independent arc length of `common`), so a solver that claims `converged` while bending an
//! edge is caught.

mod common;
use common::*;
use dformer::api::{self, simulate::SimulateOptionsDto};
use proptest::prelude::*;
use std::collections::HashMap;

type V3 = [f64; 3];

/// The point at arc length `s` (any real, taken modulo the perimeter) walking the path forwards,
/// or backwards (`forward == false`, the walk starting at the same first anchor). Segment lengths
/// by [`cubic_len_adaptive`]; within the segment, Newton's method on the partial length.
fn at_arclen(segs: &[Cubic], lens: &[f64], s: f64, forward: bool) -> P {
    let total = ksum(lens.iter().copied());
    let mut s = s.rem_euclid(total);
    if !forward {
        s = (total - s).rem_euclid(total);
    }
    let mut i = 0;
    while i + 1 < segs.len() && s > lens[i] {
        s -= lens[i];
        i += 1;
    }
    let c = &segs[i];
    let mut t = (s / lens[i].max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
    for _ in 0..40 {
        let d = deriv(c, t);
        let speed = d[0].hypot(d[1]);
        if speed == 0.0 {
            break;
        }
        let next = (t - (cubic_len_adaptive(head(c, t)) - s) / speed).clamp(0.0, 1.0);
        if (next - t).abs() < 1e-15 {
            break;
        }
        t = next;
    }
    eval(c, t)
}

/// The arc length `s` in `[0, L)` at which `walk(s)` is nearest `q` (the nearest of `table`'s
/// evenly spaced points of the walk, then Newton steps along the tangent), and that distance.
fn project(walk: &dyn Fn(f64) -> P, table: &[(f64, P)], q: P, total: f64) -> (f64, f64) {
    let near = |p: P| (p[0] - q[0]).hypot(p[1] - q[1]);
    let mut s = table.iter().min_by(|a, b| near(a.1).total_cmp(&near(b.1))).map_or(0.0, |t| t.0);
    let d = 1e-6 * total;
    for _ in 0..6 {
        let (a, b) = (walk(s - d), walk(s + d));
        let tangent = [(b[0] - a[0]) / (2.0 * d), (b[1] - a[1]) / (2.0 * d)];
        let speed2 = tangent[0] * tangent[0] + tangent[1] * tangent[1];
        if !(speed2 > 0.0) {
            break;
        }
        let p = walk(s);
        let step = ((q[0] - p[0]) * tangent[0] + (q[1] - p[1]) * tangent[1]) / speed2;
        s += step.clamp(-0.01 * total, 0.01 * total);
        if step.abs() < 1e-10 * total {
            break;
        }
    }
    (s.rem_euclid(total), near(walk(s)))
}

fn d3(a: V3, b: V3) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

fn signed_area(p: &[P]) -> f64 {
    (0..p.len()).map(|i| p[i][0] * p[(i + 1) % p.len()][1] - p[(i + 1) % p.len()][0] * p[i][1]).sum::<f64>() / 2.0
}

/// A convex piece: an ellipse (axes ratio 1–3, turned, anywhere), as 4–8 cubic arcs.
fn oval() -> impl Strategy<Value = dformer::api::path::PathDto> {
    (1.0f64..3.0, 0.0f64..std::f64::consts::PI, 4usize..9, -100.0f64..100.0, 1.0f64..50.0).prop_map(|(ratio, turn, knots, o, size)| {
        let (c, s) = (turn.cos(), turn.sin());
        mapped(&ellipse([0.0, 0.0], ratio * size, size, knots, false), |q| [o + c * q[0] - s * q[1], o + s * q[0] + c * q[1]])
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    #[test]
    fn random_pieces_give_a_closed_bounded_mesh_with_honest_stats(
        a in prop_oneof![star(), oval()], b in prop_oneof![star(), oval()], n in 16usize..40, offset in 0.0f64..1.0,
    ) {
        closed_bounded_and_honest(a, b, n, offset)?;
    }
}

/// Regression (issue 14): an ellipse glued first to a non-convex star past half its perimeter is
/// solved half a perimeter back with its flat turned by half a turn, so its seam starts at the
/// seam vertex nearest its first anchor, which this test took for a broken gluing ("seam vertex 0
/// is not at A's first anchor"; proptest's case: a six-arc oval, a 26-point star, 18 seam
/// vertices, offset 0.61 of the perimeter).
#[test]
fn test_issue_14_an_ellipse_first_turned_half_a_perimeter_on_keeps_an_honest_seam() {
    let a = ellipse([3.0, -2.0], 60.0, 25.0, 6, false);
    let b = {
        let rs = [1.0, 1.6, 0.7, 1.3, 0.9, 1.8, 0.6, 1.2, 1.5, 0.8, 1.1];
        let at = |i: usize| {
            let t = std::f64::consts::TAU * i as f64 / rs.len() as f64;
            let r = 40.0 * rs[i % rs.len()];
            [200.0 + r * t.cos(), 50.0 + r * t.sin()]
        };
        let n = rs.len();
        let pts: Vec<(P, P, P)> = (0..n)
            .map(|i| {
                let (p, prev, next) = (at(i), at(i + n - 1), at(i + 1));
                let d = [(next[0] - prev[0]) / 6.0, (next[1] - prev[1]) / 6.0];
                (p, [p[0] - d[0], p[1] - d[1]], [p[0] + d[0], p[1] + d[1]])
            })
            .collect();
        path(&pts)
    };
    for (n, offset) in [(18, 0.6057646528270488), (32, 0.9)] {
        closed_bounded_and_honest(a.clone(), b.clone(), n, offset).unwrap_or_else(|e| panic!("{n} seam vertices, offset {offset}: {e}"));
    }
}

/// The properties of [`random_pieces_give_a_closed_bounded_mesh_with_honest_stats`] for one pair:
/// `b` glued to `a` at `offset` (a share of the perimeter) with `n` seam vertices.
fn closed_bounded_and_honest(a: dformer::api::path::PathDto, b: dformer::api::path::PathDto, n: usize, offset: f64) -> Result<(), TestCaseError> {
    let Some(pieces) = normalized_pair(a, b)? else { return Ok(()) };
    let (segs, lens, perimeter) = segments_and_lengths(&pieces);
    let o = SimulateOptionsDto { offset: Some(offset * perimeter), resolution: Some(n as f64), ..Default::default() };
    let r = api::simulate::simulate(&pieces, &o).map_err(|e| TestCaseError::fail(format!("simulate: {e}")))?;
    let x = &r.vertices;
    prop_assert!(x.iter().flatten().all(|v| v.is_finite()), "non-finite vertex");
    prop_assert_eq!(r.seam.len(), n);
    prop_assert_eq!(r.piece.len(), r.triangles.len());
    // Any two seam vertices are joined along the seam by at most half the perimeter.
    let seam_x: Vec<V3> = r.seam.iter().map(|&v| x[v]).collect();
    let spread = seam_x.iter().flat_map(|p| seam_x.iter().map(move |q| d3(*p, *q))).fold(0.0, f64::max);
    prop_assert!(spread <= 0.5 * perimeter * (1.0 + 1e-3), "vertices {spread} apart, perimeter {perimeter}");
    // Closed and consistently oriented: every directed edge as often as its reverse (once
    // each, or twice where both pieces crease along the same chord, as they may when the
    // solver cannot realize a strongly non-convex gluing).
    let mut seen: HashMap<(usize, usize), usize> = HashMap::new();
    for t in &r.triangles {
        prop_assert!(t.iter().all(|&i| i < x.len()), "triangle {t:?} indexes past {} vertices", x.len());
        for m in 0..3 {
            *seen.entry((t[m], t[(m + 1) % 3])).or_default() += 1;
        }
    }
    for (&(i, j), &c) in &seen {
        prop_assert!(c <= 2 && seen.get(&(j, i)) == Some(&c), "edge {i}->{j}: used {c} times, reverse {:?}", seen.get(&(j, i)));
    }
    // Flat seam samples: where `flat` puts each seam vertex on each piece, checked here to lie
    // on the outline at one arc length u_k of the gluing on both — A walked counter-clockwise
    // from its first anchor, B clockwise from its first anchor + offset (connect's `start`
    // convention) — with u_0 = 0 and u_k increasing. (The core spaces the u_k by curvature,
    // so they are read, not assumed even.)
    let mut flat: Vec<Vec<P>> = vec![vec![[f64::NAN; 2]; n]; 2];
    for (f, (t, &p)) in r.triangles.iter().zip(&r.piece).enumerate() {
        for m in 0..3 {
            // Interior vertices (the sheet path's, numbered after the seam) are not samples.
            if let Some(k) = r.seam.iter().position(|&v| v == t[m]) {
                flat[p as usize][k] = r.flat[f][m];
            }
        }
    }
    prop_assert!(flat.iter().flatten().all(|q| q[0].is_finite()), "a seam vertex in no triangle of a piece");
    // A non-convex piece with a circle is solved at offset 0 and the circle's flat turned by
    // the offset (`stats.offsetFree`, simulate/round.rs): its flat seam points then lie
    // within the circle's own roundness (5e-4 of its radius, as the README says) of its
    // outline, doubled by the turn, and so does the gluing. Which piece is the circle is
    // read here from the outline: its samples' spread about their centroid.
    let radius = perimeter / std::f64::consts::TAU;
    let round: Option<usize> = r.stats.offset_free.then(|| (0..2).find(|&j| {
        let pts: Vec<P> = segs[j].iter().flat_map(|c| (0..16).map(move |m| eval(c, m as f64 / 16.0))).collect();
        let c = pts.iter().fold([0.0, 0.0], |a, q| [a[0] + q[0] / pts.len() as f64, a[1] + q[1] / pts.len() as f64]);
        pts.iter().all(|q| ((q[0] - c[0]).hypot(q[1] - c[1]) - radius).abs() <= 1e-3 * radius)
    })).flatten();
    prop_assert!(!r.stats.offset_free || round.is_some(), "offsetFree, but neither piece is a circle");
    let turned = 2.0 * 5e-4 * radius;
    let mut u = vec![[0.0f64; 2]; n];
    for j in 0..2 {
        let ccw = signed_area(&segs[j].iter().map(|c| c[0]).collect::<Vec<_>>()) > 0.0;
        let forward = if j == 0 { ccw } else { !ccw };
        let s0 = if j == 0 { 0.0 } else { offset * perimeter };
        let walk = |s: f64| at_arclen(&segs[j], &lens[j], s0 + s, forward);
        // Start points for the projection: 64 points a segment, their arc length along the
        // walk summed from chords (close enough to start Newton from).
        let mut table: Vec<(f64, P)> = Vec::new();
        let mut sigma = 0.0;
        for c in &segs[j] {
            let mut last = eval(c, 0.0);
            for m in 0..64 {
                let p = eval(c, m as f64 / 64.0);
                sigma += (p[0] - last[0]).hypot(p[1] - last[1]);
                last = p;
                let s = if forward { sigma - s0 } else { perimeter - sigma - s0 };
                table.push((s.rem_euclid(perimeter), p));
            }
            let end = eval(c, 1.0);
            sigma += (end[0] - last[0]).hypot(end[1] - last[1]);
        }
        for k in 0..n {
            let (s, gap) = project(&walk, &table, flat[j][k], perimeter);
            let off = if round == Some(j) { turned } else { 1e-6 * perimeter };
            prop_assert!(gap <= off, "piece {j}: seam vertex {k} is {gap} off the outline");
            u[k][j] = s;
        }
    }
    // The gluing is exact to the stitching tolerance, except that each kink (a turn tighter
    // than the seam's steps, taken as a corner: `simulate::kink`) may move it by what its
    // rounding loses: at most `KINK_SHIFT` of the perimeter for the seam's own kinks, and what
    // it loses for a rounding the answer previews as a corner (`simulate::corners`, the kinks
    // within `Limits::CORNERS`, which hold the seam's own); a pair without kinks keeps the plain
    // tolerance.
    use dformer::simulate::kink::{kinks_within, Limits, KINK_SHIFT};
    let found: Vec<_> = pieces
        .iter()
        .flat_map(|p| kinks_within(&dformer::arclen::ArcTable::new(&p.to_contour(0).unwrap(), 1e-11), &[], Limits::CORNERS))
        .collect();
    let kinks = found.len();
    let moved: f64 = found.iter().map(|k| (k.before + k.after).max(KINK_SHIFT * perimeter)).sum();
    let glued = 1e-6 * perimeter + moved + if round.is_some() { 2.0 * turned } else { 0.0 };
    // The seam starts at A's first anchor, or at a kink whose window holds it (the kink's
    // tight stretch and `KINK_WINDOW` even steps at `REFERENCE` samples either side).
    use dformer::simulate::density::{KINK_WINDOW, REFERENCE};
    let start = if kinks > 0 { (1e-6 + 2.0 * KINK_WINDOW / REFERENCE) * perimeter } else { 1e-6 * perimeter };
    for k in 0..n {
        let d = (u[k][0] - u[k][1]).rem_euclid(perimeter);
        prop_assert!(d.min(perimeter - d) <= glued, "seam vertex {k}: at {} on A but {} on B ({kinks} kinks)", u[k][0], u[k][1]);
        // Measured from the seam's own first vertex: with `start` added as well (until stop
        // 32) a pair with a kink whose last seam vertex lay within `start` of the end
        // wrapped past the first (proptest's case 1fc29db5: vertex 35 of 36 at 292.69 of a
        // 294.17 perimeter) and was called out of order.
        let along = |k: usize| (u[k][0] - u[0][0]).rem_euclid(perimeter);
        prop_assert!(k == 0 || along(k) > along(k - 1), "seam vertices out of order: {:?}", &u[..=k]);
    }
    // A turned circle A starts its seam at the seam vertex nearest its first anchor, and so
    // does an A that a k-th of a turn carries onto itself, solved at the offset less its
    // whole periods with its flat turned (simulate/round.rs). Whether A is one is read here
    // from the outline: at 32 points, its point a k-th of the perimeter further on is the
    // point turned by a k-th of a turn (either way) about the samples' centroid.
    let ccw = signed_area(&segs[0].iter().map(|c| c[0]).collect::<Vec<_>>()) > 0.0;
    let on_a = |s: f64| at_arclen(&segs[0], &lens[0], s, ccw);
    let centre = (0..256).map(|m| on_a(perimeter * m as f64 / 256.0)).fold([0.0, 0.0], |c, q| [c[0] + q[0] / 256.0, c[1] + q[1] / 256.0]);
    let a_turns = (2..=12).any(|k| {
        [1.0, -1.0].iter().any(|&sense: &f64| {
            let (sn, cs) = (sense * std::f64::consts::TAU / k as f64).sin_cos();
            (0..32).all(|m| {
                let s = perimeter * m as f64 / 32.0;
                let (p, q) = (on_a(s), on_a(s + perimeter / k as f64));
                let (x, y) = (p[0] - centre[0], p[1] - centre[1]);
                (centre[0] + cs * x - sn * y - q[0]).hypot(centre[1] + sn * x + cs * y - q[1]) <= 1e-6 * perimeter
            })
        })
    });
    // A pair with a non-convex piece is solved from its canonical start (simulate/anchor.rs),
    // so where its drawing starts does not change its form, and `seam` then starts at the seam
    // vertex nearest A's first anchor, as above. Whether a piece is non-convex is read here
    // from 64 points a segment: their polygon turns both ways.
    let turns_both_ways = |j: usize| {
        let pts: Vec<P> = segs[j].iter().flat_map(|c| (0..64).map(move |m| eval(c, m as f64 / 64.0))).collect();
        let m = pts.len();
        let turn = |k: usize| {
            let (a, b, c) = (pts[(k + m - 1) % m], pts[k], pts[(k + 1) % m]);
            (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
        };
        let size = perimeter * perimeter / (m * m) as f64;
        (0..m).any(|k| turn(k) > 1e-9 * size) && (0..m).any(|k| turn(k) < -1e-9 * size)
    };
    let restarted = turns_both_ways(0) || turns_both_ways(1);
    let widest = (0..n).map(|k| (u[(k + 1) % n][0] - u[k][0]).rem_euclid(perimeter)).fold(0.0, f64::max);
    let start = if round == Some(0) || a_turns || restarted { start.max(widest) } else { start };
    prop_assert!(u[0][0].min(perimeter - u[0][0]) <= start, "seam vertex 0 is not at A's first anchor ({kinks} kinks)");
    let s = &r.stats;
    let mut strain = 0.0f64;
    // A mesh with interior vertices (the sheet path of a non-convex pair) promises every
    // edge within 1e-3 of its flat length; the seam-vertex polyhedron, the length equations.
    let sheet = x.len() > n;
    for (f, (t, &p)) in r.triangles.iter().zip(&r.piece).enumerate() {
        for m in 0..3 {
            let (i, j) = (t[m], t[(m + 1) % 3]);
            let (want, l) = (dist2(r.flat[f][m], r.flat[f][(m + 1) % 3]), d3(x[i], x[j]));
            strain = strain.max((l - want).abs() / want);
            if !s.converged {
                continue;
            }
            if sheet {
                prop_assert!((l - want).abs() <= 1e-3 * want, "converged, but edge {i}-{j} of piece {p} is {l}, flat {want}");
                continue;
            }
            let (u, v) = (r.seam.iter().position(|&s| s == i).unwrap(), r.seam.iter().position(|&s| s == j).unwrap());
            let other = &flat[1 - p as usize];
            // Converged: a chord keeps its flat length; a seam edge, one length for two
            // pieces, lies between A's chord and B's. Both to 1e-5: the chord path meets its
            // length equations to 1e-7, the intrinsic path (creases across the seam) to 1e-5
            // (`convex::crossing::POLISHED_STRAIN`).
            if u.abs_diff(v) == 1 || u.abs_diff(v) == n - 1 {
                let alt = dist2(other[u], other[v]);
                prop_assert!(l >= want.min(alt) * (1.0 - 1e-5) && l <= want.max(alt) * (1.0 + 1e-5),
                    "converged, but seam edge {u}-{v} is {l}, not between its chords {want} and {alt}");
            } else {
                prop_assert!((l - want).abs() <= 1e-5 * want, "converged, but chord {u}-{v} of piece {p} is {l}, flat {want}");
            }
        }
    }
    prop_assert!((strain - s.max_strain).abs() <= 1e-6 + 1e-3 * strain, "max strain: recomputed {strain:.3e}, stats {:.3e}", s.max_strain);
    let (vol, area) = mesh_volume_area(x, &r.triangles);
    prop_assert!((vol - s.volume).abs() <= 1e-9 * perimeter.powi(3), "volume: mesh {vol}, stats {}", s.volume);
    prop_assert!((area - s.area).abs() <= 1e-9 * perimeter.powi(2), "area: mesh {area}, stats {}", s.area);
    Ok(())
}

/// Volume and area of a closed triangle mesh (divergence theorem; cross products). The volume
/// is positive when the triangles turn counter-clockwise seen from outside.
fn mesh_volume_area(x: &[V3], triangles: &[[usize; 3]]) -> (f64, f64) {
    let cr = |u: V3, v: V3| [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    let sub = |u: V3, v: V3| [u[0] - v[0], u[1] - v[1], u[2] - v[2]];
    let (mut vol, mut area) = (0.0, 0.0);
    for &[i, j, k] in triangles {
        let (a, b, c) = (x[i], x[j], x[k]);
        let bc = cr(b, c);
        vol += (a[0] * bc[0] + a[1] * bc[1] + a[2] * bc[2]) / 6.0;
        let nrm = cr(sub(b, a), sub(c, a));
        area += 0.5 * (nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]).sqrt();
    }
    (vol, area)
}

/// Regression: an unconverged, strongly non-convex gluing came out inside out (negative signed
/// volume, so STL normals pointing in) while `stats.volume` reported the positive value.
#[test]
fn unrealizable_gluing_is_still_outward_oriented() {
    let d: serde_json::Value = serde_json::from_str(include_str!("data/inside-out-gluing.json")).unwrap();
    let pieces: Vec<dformer::api::path::PathDto> = serde_json::from_value(d["pieces"].clone()).unwrap();
    let o = SimulateOptionsDto { offset: d["offset"].as_f64(), resolution: d["resolution"].as_f64(), ..Default::default() };
    let r = api::simulate::simulate(&pieces, &o).expect("simulate");
    let (vol, _) = mesh_volume_area(&r.vertices, &r.triangles);
    assert!(vol > 0.0 && (vol - r.stats.volume).abs() <= 1e-9 * vol, "mesh volume {vol}, stats {}", r.stats.volume);
}

fn dist2(a: P, b: P) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}
