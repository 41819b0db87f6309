//! How often `simulate` finds the D-form of the pairs students draw (not a test: it prints
//! counts, to be compared between commits). Run: `cargo run --release -p dformer --example
//! simulate_survey` (about a minute; `scripts/bench.sh` runs it).
//!
//! 1. *Convex pairs*: ellipses, superellipses (|x/a|⁴ + |y/b|⁴ = 1), rectangles with rounded
//!    corners and rounded polygons, each glued to a circle of its perimeter and to a congruent
//!    copy of itself (the classic D-form of two equal pieces), at 16 offsets. Alexandrov's theorem
//!    says each has exactly one convex form, so every unconverged answer is the solver's failure.
//!    (The superellipses and the 200 × 40 ellipse are drawn through 64 points with smooth
//!    handles, which bend inward by a hair between points: their 256 seam samples are not
//!    convex, so `simulate` solves them as a non-convex pair, on the sheet path; counted as
//!    "solved as sheets".) Also counted: answers whose creases
//!    cross the seam (the intrinsic path adds seam vertices there) and the slowest answer.
//!    Also checked: offsets that are one gluing (any two with a circle; half a perimeter apart
//!    on a centrally symmetric piece with its copy) must converge to one volume, by Alexandrov's
//!    uniqueness, an independent check of what `converged` claims (to 0.1 %; to 1 % where
//!    either answer is a sheet, whose volume depends on its mesh).
//!    Also counted: answers called converged with an edge more than 1e-3 off its flat length (the
//!    seam samples' floor at tight corners, see `simulate::density`).
//! 2. *Organic pairs*: smooth random blobs r = 50(1 + Σ a_k cos(kθ + φ_k)), k = 2…5, glued to a
//!    circle at a random offset (a fixed xorshift seed), and to another blob; and the Pebble,
//!    the kidney and the smooth heart each with a copy of itself at six offsets, the blob and the
//!    kidney each with its mirror image at the same six; counted by `stats.shortfall`.
//! 3. *Bays*: an 80 mm L whose notch deepens from 10 to 40 mm, with a circle: where the form
//!    starts to crease (the panel's advice for a creased form rests on this).
//!
//! Every answer is judged by the solver's own `converged` and `shortfall`, which the tests check
//! against the mesh (`core/tests/simulate_*.rs`).

#[path = "../tests/simulate_common/shapes.rs"]
mod shapes;

use dformer::contour::Contour;
use dformer::simulate::{simulate, SimulateOptions, Simulation};
use std::collections::BTreeMap;
use std::f64::consts::{PI, TAU};

const N: usize = 256;

fn solve(a: &Contour, b: &Contour, offset: f64) -> Simulation {
    let o = SimulateOptions { resolution: N, offset: offset * shapes::perimeter(a), ..Default::default() };
    simulate(a, b, &o).expect("simulate")
}

fn ellipse(a: f64, b: f64) -> Contour {
    shapes::polar(64, |t| 1.0 / ((t.cos() / a).powi(2) + (t.sin() / b).powi(2)).sqrt())
}

fn superellipse(a: f64, b: f64) -> Contour {
    shapes::polar(64, |t| 1.0 / ((t.cos() / a).abs().powi(4) + (t.sin() / b).abs().powi(4)).powf(0.25))
}

fn convex_pairs() {
    let mut pieces: Vec<(String, Contour)> = Vec::new();
    for (a, b) in [(60.0, 40.0), (80.0, 30.0), (50.0, 45.0), (100.0, 20.0)] {
        pieces.push((format!("ellipse {a}×{b}"), ellipse(a, b)));
        pieces.push((format!("superellipse {a}×{b}"), superellipse(a, b)));
        for r in [1.0, 3.0, 8.0] {
            let rect = [(0.0, 0.0), (2.0 * a, 0.0), (2.0 * a, 2.0 * b), (0.0, 2.0 * b)];
            pieces.push((format!("rectangle {}×{} r {r}", 2.0 * a, 2.0 * b), shapes::rounded_polygon(&rect, r)));
        }
    }
    for r in [1.0, 4.0] {
        pieces.push((format!("triangle r {r}"), shapes::rounded_triangle(r)));
        let hexagon: Vec<(f64, f64)> = (0..6).map(|k| (50.0 * (k as f64 * PI / 3.0).cos(), 50.0 * (k as f64 * PI / 3.0).sin())).collect();
        pieces.push((format!("hexagon r {r}"), shapes::rounded_polygon(&hexagon, r)));
    }
    println!("1. Convex pairs, {N} seam vertices, 16 offsets each ([k: strain] unconverged at offset k/16, (k: strain) converged above 1e-3, <i≠j> two offsets of one gluing converged to volumes 0.1 % apart, 1 % for sheets)");
    let mut by_partner = BTreeMap::new();
    for partner in ["circle", "congruent copy"] {
        let (mut good, mut failed, mut over) = (0, 0, 0);
        let (mut crossed, mut sheets, mut slowest) = (0, 0, 0.0f64);
        let mut twins = 0;
        for (name, a) in &pieces {
            let b = if partner == "circle" { shapes::circle_for(a) } else { a.clone() };
            let mut line = String::new();
            let mut volumes: Vec<Option<(f64, bool)>> = Vec::new();
            let tiny = 1e-9 * shapes::perimeter(a).powi(3);
            for k in 0..16 {
                let s = solve(a, &b, k as f64 / 16.0);
                // Interior vertices: the sheet path's answer (samples not convex at N).
                let sheet = s.vertices.len() > s.seam.len();
                volumes.push((s.stats.converged && s.stats.max_strain <= 1e-3).then_some((s.stats.volume, sheet)));
                slowest = slowest.max(s.stats.ms);
                crossed += usize::from(s.seam.len() > N);
                sheets += usize::from(sheet);
                if !s.stats.converged {
                    failed += 1;
                    line += &format!(" [{k}: {:.0e}]", s.stats.max_strain);
                } else if s.stats.max_strain > 1e-3 {
                    over += 1;
                    line += &format!(" ({k}: {:.1e})", s.stats.max_strain);
                } else {
                    good += 1;
                }
            }
            // One gluing, one volume (Alexandrov): with a circle (eight arcs) every offset two
            // sixteenths on is the same gluing, and every other is within the arcs' 1e-5 of it;
            // a centrally symmetric piece with a copy of itself is the same gluing half a
            // perimeter on (the half-turn maps arc length s to s + L/2).
            let twin_pairs: Vec<(usize, usize)> = if partner == "circle" {
                (1..16).map(|k| (0, k)).collect()
            } else if name.starts_with("triangle") {
                Vec::new()
            } else {
                (0..8).map(|k| (k, k + 8)).collect()
            };
            for (i, j) in twin_pairs {
                if let (Some((u, su)), Some((v, sv))) = (volumes[i], volumes[j]) {
                    // A sheet's volume depends on its mesh by up to 1 % (issue 14's bar).
                    let rel = if su || sv { 1e-2 } else { 1e-3 };
                    if (u - v).abs() > rel * u.abs().max(v.abs()) + tiny {
                        twins += 1;
                        line += &format!(" <{i}≠{j}: {u:.0} vs {v:.0}>");
                    }
                }
            }
            if !line.is_empty() {
                println!("  {name} + {partner}:{line}");
            }
        }
        by_partner.insert(partner, (good, over, failed, crossed, sheets, twins, slowest));
    }
    for (partner, (good, over, failed, crossed, sheets, twins, slowest)) in by_partner {
        let total = good + over + failed;
        println!("  with a {partner}: {good} of {total} converged within 1e-3, {over} converged above it, {failed} not converged; {crossed} with creases across the seam (seam vertices added); {sheets} solved as sheets (samples not quite convex); {twins} converged twins of one gluing with volumes apart; slowest {slowest:.0} ms native");
    }
}

/// A xorshift generator of numbers in [0, 1) from `seed`.
fn xorshift(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % 1_000_000) as f64 / 1e6
    }
}

/// A smooth random blob r = 50(1 + Σ a_k cos(kθ + φ_k)), k = 2…5, |a_k| < 1/(2k).
fn blob(rnd: &mut impl FnMut() -> f64) -> Contour {
    let h: Vec<(f64, f64, f64)> = (2..6).map(|k| (k as f64, (rnd() - 0.5) / k as f64, rnd() * TAU)).collect();
    shapes::polar(48, move |t| 50.0 * (1.0 + h.iter().map(|(k, amp, ph)| amp * (k * t + ph).cos()).sum::<f64>()))
}

fn tally_of(answers: impl Iterator<Item = Simulation>) -> (BTreeMap<String, usize>, f64) {
    let mut tally: BTreeMap<String, usize> = BTreeMap::new();
    let mut worst_ms: f64 = 0.0;
    for s in answers {
        worst_ms = worst_ms.max(s.stats.ms);
        let key = s.stats.shortfall.map_or("converged".to_string(), |f| f.name().to_string());
        *tally.entry(key).or_default() += 1;
    }
    (tally, worst_ms)
}

fn organic_pairs() {
    let mut rnd = xorshift(7);
    let count = 30;
    let (tally, worst_ms) = tally_of((0..count).map(|_| {
        let a = blob(&mut rnd);
        let offset = rnd();
        solve(&a, &shapes::circle_for(&a), offset)
    }));
    println!("2. Organic blobs with a circle, {count} random pairs (seed 7), {N} seam vertices: {tally:?}, slowest {worst_ms:.0} ms native");
    // Two blobs, the second scaled to the first's perimeter, at offsets 0.37 of a perimeter
    // apart: where a bay of one meets the other the seam is a saddle (`simulate::sheet::saddle`).
    let mut rnd = xorshift(11);
    let count = 40;
    let (tally, worst_ms) = tally_of((0..count).map(|i| {
        let a = blob(&mut rnd);
        let b = shapes::with_perimeter(&blob(&mut rnd), shapes::perimeter(&a));
        solve(&a, &b, (i as f64 * 0.37) % 1.0)
    }));
    println!("   Two organic blobs, {count} random pairs (seed 11), {N} seam vertices: {tally:?}, slowest {worst_ms:.0} ms native");
    // One drawing duplicated and turned, the classic D-form of two equal pieces: the pieces are
    // congruent, not mirror images, so only offsets other than the mirror gluing inflate.
    for (name, a) in [("Pebble", shapes::pebble()), ("kidney", shapes::kidney()), ("smooth heart", shapes::heart())] {
        let offsets = [1, 3, 5, 8, 11, 13];
        let (tally, worst_ms) = tally_of(offsets.iter().map(|&k| solve(&a, &a, k as f64 / 16.0)));
        println!("   The {name} with its copy at offsets 1, 3, 5, 8, 11, 13/16: {tally:?}, slowest {worst_ms:.0} ms native");
    }
    // A piece with its mirror image (the drawing flipped): offset 0 folds flat, and at small
    // offsets the two pieces' bays meet, where the sheet locks unless refined there
    // (`simulate::sheet::adapt`).
    for (name, a) in [("blob", shapes::blob()), ("kidney", shapes::kidney())] {
        let offsets = [1, 3, 5, 8, 11, 13];
        let (tally, worst_ms) = tally_of(offsets.iter().map(|&k| solve(&a, &shapes::mirrored(&a), k as f64 / 16.0)));
        println!("   The {name} with its mirror image at offsets 1, 3, 5, 8, 11, 13/16: {tally:?}, slowest {worst_ms:.0} ms native");
    }
}

fn bays() {
    print!("3. An 80 mm L with a circle, notch depth → sharpest bend inside a piece (shortfall):");
    for depth in [10.0, 20.0, 30.0, 40.0] {
        let a = shapes::notched_l(depth, 0.0);
        let s = solve(&a, &shapes::circle_for(&a), 0.0);
        let why = s.stats.shortfall.map_or("converged", |f| f.name());
        print!(" {depth} mm → {:.0}° ({why});", s.stats.max_bend.to_degrees());
    }
    println!();
}

fn main() {
    convex_pairs();
    organic_pairs();
    bays();
}
