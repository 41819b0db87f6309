//! `dformer normalize` on a single shape (issue 15, req. 4): one outline scaled to an exact
//! length, about its first node with `--pivot start`, checked against the closed form of a
//! scaled rectangle and circle; without a length it is refused, saying how, and writes nothing.

use std::f64::consts::PI;
mod common;
use common::dformer;


fn write(name: &str, svg: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("dformer-normalize-one-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, svg).unwrap();
    path
}

/// Every number in the `d` of the element with this id.
fn d_numbers(svg: &str, id: &str) -> Vec<f64> {
    let at = svg.find(&format!("id=\"{id}\"")).expect("element kept");
    let tag = &svg[svg[..at].rfind('<').unwrap()..];
    let tag = &tag[..tag.find('>').unwrap()];
    let d = &tag[tag.find(" d=\"").expect("a d attribute") + 4..];
    let d = &d[..d.find('"').unwrap()];
    d.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e'))
        .filter(|t| !t.is_empty())
        .map(|t| t.parse().unwrap())
        .collect()
}

#[test]
fn one_rectangle_scales_to_the_exact_length_about_its_first_node() {
    // 40 × 20 mm at (10, 20): perimeter 120 mm; to 300 mm is a factor 2.5 about (10, 20).
    let input = write("rect.svg", r#"<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="200mm" viewBox="0 0 200 200"><rect id="r" x="10" y="20" width="40" height="20"/></svg>"#);
    let run = dformer(&["normalize", input.to_str().unwrap(), "--target", "300mm", "--pivot", "start", "-o", "-"]);
    assert!(run.ok, "got {}", run.stderr);
    assert!(run.stderr.contains("1 shape normalized to perimeter 300.000000 mm (scale 2.500000)"), "got {}", run.stderr);
    let xy = d_numbers(&run.stdout, "r");
    let want = [[10.0, 20.0], [110.0, 20.0], [110.0, 70.0], [10.0, 70.0]];
    assert_eq!(xy.len(), 8, "four corners, got {xy:?}");
    for (k, w) in want.iter().enumerate() {
        assert!((xy[2 * k] - w[0]).abs() < 1e-9 && (xy[2 * k + 1] - w[1]).abs() < 1e-9, "corner {k}: {:?}, wanted {w:?}", &xy[2 * k..2 * k + 2]);
    }
    let perimeter: f64 = (0..4).map(|k| {
        let (a, b) = (k, (k + 1) % 4);
        (xy[2 * b] - xy[2 * a]).hypot(xy[2 * b + 1] - xy[2 * a + 1])
    }).sum();
    assert!((perimeter - 300.0).abs() < 1e-9, "perimeter {perimeter}");
}

#[test]
fn one_circle_in_inches_scales_to_a_length_in_another_unit_about_its_centre() {
    // r = 1 in: perimeter 2π in; to 100 mm the radius becomes 100 / (2π · 25.4) in, centre kept.
    let input = write("circle.svg", r#"<svg xmlns="http://www.w3.org/2000/svg" width="10in" height="10in" viewBox="0 0 10 10"><circle id="c" cx="5" cy="4" r="1"/></svg>"#);
    let run = dformer(&["normalize", input.to_str().unwrap(), "--target", "100mm", "-o", "-"]);
    assert!(run.ok, "got {}", run.stderr);
    let r = 100.0 / (2.0 * PI * 25.4);
    let xy = d_numbers(&run.stdout, "c");
    // The drawn circle is four cubic arcs, about 2e-7 longer than the true circle, so the radius
    // is met to 1e-6 relative; every handle lies within the handle reach of the circle.
    let far = xy.chunks(2).map(|p| (p[0] - 5.0).hypot(p[1] - 4.0)).fold(0.0, f64::max);
    let near = xy.chunks(2).map(|p| (p[0] - 5.0).hypot(p[1] - 4.0)).fold(f64::INFINITY, f64::min);
    assert!((near - r).abs() < 1e-6 * r, "anchors at radius {near}, wanted {r}");
    assert!(far < r * 1.1, "handles at radius {far}");
    let k = run.stderr.split("(scale ").nth(1).and_then(|s| s.split(')').next()).and_then(|s| s.parse::<f64>().ok()).expect("the scale reported");
    assert!((k - r).abs() < 1e-6 * r + 5e-7, "scale {k}, wanted {r}");
}

#[test]
fn test_one_shape_without_a_length_is_refused_saying_how_and_writes_nothing() {
    let input = write("alone.svg", r#"<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="200mm" viewBox="0 0 200 200"><rect id="r" x="10" y="20" width="40" height="20"/></svg>"#);
    let out = input.with_file_name("alone-out.svg");
    let _ = std::fs::remove_file(&out);
    for target in ["largest", "mean"] {
        let run = dformer(&["normalize", input.to_str().unwrap(), "--target", target, "-o", out.to_str().unwrap()]);
        assert!(!run.ok, "{target}: wanted exit 1");
        assert!(run.stderr.contains("at least 2 closed shapes are needed, the file has 1 closed shape (#r)") && run.stderr.contains("to scale one shape, give its perimeter: --target 300mm"), "{target}: got {}", run.stderr);
        assert!(!out.exists(), "{target}: an output file was written");
    }
}
