//! `dformer measure / normalize / connect` on drawings written the way real editors write them
//! (tests/fixtures/drawings: Inkscape 0.92 and 1.x, Illustrator's SVG export, compound paths).
//! Every closed shape is measured and checked against a closed form or an independent sum computed
//! here from the drawing's own parameters; everything else is listed as skipped, with why.

use std::f64::consts::PI;
use std::path::PathBuf;
mod common;
use common::{dformer, Run};

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests/fixtures/drawings").join(name)
}


/// `dformer measure FILE`: (name, perimeter) per stdout line.
fn measured(run: &Run) -> Vec<(String, f64)> {
    run.stdout
        .lines()
        .map(|l| {
            let mut cols = l.split('\t');
            let name = cols.next().unwrap_or_default().to_string();
            let p = cols.next().unwrap_or_default().split(' ').nth(1).and_then(|v| v.parse().ok()).unwrap_or(f64::NAN);
            (name, p)
        })
        .collect()
}

/// The `skipped: NAME: REASON` lines of stderr.
fn skipped(run: &Run) -> Vec<(String, String)> {
    run.stderr
        .lines()
        .filter_map(|l| l.strip_prefix("skipped: "))
        .filter_map(|l| l.split_once(": ").map(|(n, r)| (n.to_string(), r.to_string())))
        .collect()
}

fn polygon(points: &[(f64, f64)]) -> f64 {
    (0..points.len())
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % points.len()]);
            (b.0 - a.0).hypot(b.1 - a.1)
        })
        .sum()
}

/// Ellipse perimeter by summing 400 000 chords of x = a cos t, y = b sin t (relative error ~1e-11).
fn ellipse(a: f64, b: f64) -> f64 {
    let n = 400_000;
    polygon(&(0..n).map(|k| (a * (2.0 * PI * k as f64 / n as f64).cos(), b * (2.0 * PI * k as f64 / n as f64).sin())).collect::<Vec<_>>())
}

fn assert_measures(file: &str, run: &Run, wanted: &[(&str, f64)], tolerance: f64) {
    assert!(run.ok, "{file}: wanted exit 0, got stderr {}", run.stderr);
    let got = measured(run);
    let names: Vec<&str> = got.iter().map(|(n, _)| n.as_str()).collect();
    let want_names: Vec<&str> = wanted.iter().map(|(n, _)| *n).collect();
    assert_eq!(names, want_names, "{file}: closed shapes offered (wanted, got)");
    for ((name, p), (_, want)) in got.iter().zip(wanted) {
        assert!((p - want).abs() <= tolerance, "{file} {name}: wanted perimeter {want:.6}, got {p:.6}");
    }
}

fn assert_skipped(file: &str, run: &Run, wanted: &[(&str, &str)]) {
    let got = skipped(run);
    let names: Vec<&str> = got.iter().map(|(n, _)| n.as_str()).collect();
    let want_names: Vec<&str> = wanted.iter().map(|(n, _)| *n).collect();
    assert_eq!(names, want_names, "{file}: skipped (wanted, got); stderr {}", run.stderr);
    for ((name, reason), (_, want)) in got.iter().zip(wanted) {
        assert!(reason.contains(want), "{file} {name}: wanted a reason with {want:?}, got {reason:?}");
    }
}

#[test]
fn inkscape_092_drawing_with_stray_strokes_measures_its_three_closed_shapes() {
    // Was: exit 1 at the first open path ("The first path is open").
    let file = "inkscape-092.svg";
    let run = dformer(&["measure", fixture(file).to_str().unwrap()]);
    // The 14-point star from its sodipodi parameters: 28 edges between radius 30 and 14, π/14 apart.
    let (r1, r2) = (30.0f64, 14.0f64);
    let star = 28.0 * (r1 * r1 + r2 * r2 - 2.0 * r1 * r2 * (PI / 14.0).cos()).sqrt();
    // h 60 v 40: a 60 × 40 rectangle; four `a 25,25` arcs: a circle of radius 25.
    assert_measures(file, &run, &[("#rect10", 200.0), ("#path12 (Disc)", 2.0 * PI * 25.0), ("#path14", star)], 2e-4);
    let open = "an open path";
    assert_skipped(file, &run, &[("#path16", open), ("#path9", open), ("#path1", open), ("#text20", "text")]);
    assert!(run.stderr.contains("close the path"), "the open strokes say what to do: {}", run.stderr);
}

#[test]
fn inkscape_1x_drawing_offers_every_visible_closed_shape() {
    let file = "inkscape-1x.svg";
    let run = dformer(&["measure", fixture(file).to_str().unwrap()]);
    let petal = polygon(&[(30.0, 80.0), (70.0, 80.0), (80.0, 100.0), (50.0, 125.0), (20.0, 110.0)]);
    assert_measures(
        file,
        &run,
        &[
            // 50 × 30 with corner radius 5: the straight sides lose 4 × 2r, the corners add one circle.
            ("#rect846 (Body)", 2.0 * (50.0 + 30.0) - 8.0 * 5.0 + 2.0 * PI * 5.0),
            ("#path1010", 2.0 * PI * 20.0),
            ("#path1012", ellipse(15.0, 10.0)),
            ("#path2044 (Petal)", petal),
            // V/H absolute, 40 × 30, rotated by its group: length unchanged.
            ("#path300", 140.0),
        ],
        2e-4,
    );
    // #rect9 is on the hidden "Sketch" layer: not drawn, neither offered nor skipped.
    assert_skipped(file, &run, &[("#path3000", "an open path"), ("#path3001", "an open path"), ("#image77", "an image")]);
}

#[test]
fn illustrator_export_with_style_block_and_group_transforms() {
    let file = "illustrator-export.svg";
    let text = std::fs::read_to_string(fixture(file)).unwrap();
    // The hexagon's perimeter from its own points attribute.
    let points: Vec<f64> = text.split("points=\"").nth(1).unwrap().split('"').next().unwrap().split(' ').map(|v| v.parse().unwrap()).collect();
    let hexagon = polygon(&points.chunks(2).map(|p| (p[0], p[1])).collect::<Vec<_>>());
    let run = dformer(&["measure", fixture(file).to_str().unwrap()]);
    assert_measures(
        file,
        &run,
        &[
            ("#Hexagon", hexagon),
            ("<rect> number 2", 2.0 * (141.73 + 85.04)),
            ("<circle> number 3", 2.0 * PI * 56.69),
            // A 100 × 50 rectangle in a group scaled by 0.8.
            ("#Small_panel", 0.8 * 300.0),
        ],
        2e-4,
    );
    assert_skipped(file, &run, &[("<polyline> number 4", "an open path"), ("<line> number 5", "an open path")]);
}

#[test]
fn compound_and_self_crossing_paths_are_skipped_with_why() {
    let file = "compound.svg";
    let run = dformer(&["measure", fixture(file).to_str().unwrap()]);
    // Two arcs of radius 40 over a 60 chord: each spans 2·asin(30/40).
    assert_measures(file, &run, &[("#lens", 2.0 * 40.0 * 2.0 * (0.75f64).asin()), ("#plate", 200.0)], 2e-4);
    assert_skipped(
        file,
        &run,
        &[("#frame (Frame)", "split it into separate shapes"), ("#twins", "compound path of 2 subpaths"), ("#bow", "crosses itself")],
    );
}

#[test]
fn a_file_with_no_closed_shape_fails_naming_what_was_skipped() {
    let dir = std::env::temp_dir().join(format!("dformer-real-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("strokes.svg");
    std::fs::write(&path, r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><path id="s1" d="m 10,10 50,0"/><text id="t">hi</text></svg>"#).unwrap();
    let run = dformer(&["measure", path.to_str().unwrap()]);
    assert!(!run.ok, "wanted exit 1, got {}", run.stdout);
    assert!(run.stderr.contains("no closed shape") && run.stderr.contains("#s1: an open path") && run.stderr.contains("#t: text"), "got {}", run.stderr);
}

#[test]
fn connect_refuses_three_closed_shapes_and_normalize_then_connect_take_the_largest_two() {
    let input = fixture("inkscape-092.svg");
    let input = input.to_str().unwrap();
    let run = dformer(&["connect", input, "-o", "-"]);
    assert!(!run.ok, "three closed shapes are ambiguous for connect");
    assert!(
        run.stderr.contains("exactly 2 closed shapes are needed, the file has 3 closed shapes (#rect10, #path12 (Disc), #path14)")
            && run.stderr.contains("--largest 2"),
        "got {}",
        run.stderr
    );
    let both = dformer(&["connect", input, "--largest", "2", "--id", "rect10"]);
    assert!(!both.ok && both.stderr.contains("not both"), "got {}", both.stderr);

    let dir = std::env::temp_dir().join(format!("dformer-largest-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let normalized = dir.join("normalized.svg");
    let run = dformer(&["normalize", input, "--largest", "2", "-o", normalized.to_str().unwrap()]);
    assert!(run.ok, "got {}", run.stderr);
    assert!(run.stderr.contains("2 shapes normalized"), "got {}", run.stderr);
    // The two longest (the star and the rectangle) now share the star's perimeter; the disc is untouched.
    let after = measured(&dformer(&["measure", normalized.to_str().unwrap()]));
    let (r1, r2) = (30.0f64, 14.0f64);
    let star = 28.0 * (r1 * r1 + r2 * r2 - 2.0 * r1 * r2 * (PI / 14.0).cos()).sqrt();
    let p = |name: &str| after.iter().find(|(n, _)| n == name).map(|(_, p)| *p).unwrap_or(f64::NAN);
    assert!((p("#rect10") - star).abs() < 2e-4 && (p("#path14") - star).abs() < 2e-4, "wanted both {star:.6}, got {after:?}");
    assert!((p("#path12 (Disc)") - 2.0 * PI * 25.0).abs() < 2e-4, "got {after:?}");
    let out = dformer(&["connect", normalized.to_str().unwrap(), "--largest", "2", "--count", "12", "-o", "-"]);
    assert!(out.ok, "got {}", out.stderr);
    assert!(out.stdout.contains("Piece A #rect10") && out.stdout.contains("Piece B #path14"), "the same two pieces, in file order");
    let _ = std::fs::remove_dir_all(&dir);
}
