//! Numbers in `normalize`'s messages are rounded for people (issue 15 req. 6): a bad target
//! perimeter was printed as given ("got -3.14159265358979"), and a target that scales a path out
//! of the range of numbers as two raw floats, one of them 307 digits long.

mod common;
use common::*;
use dformer::api::{self, normalize::NormalizeOptionsDto, value::Value};

fn message(paths: &[dformer::api::path::PathDto], target: f64, pivot: Option<Value>) -> String {
    let o = NormalizeOptionsDto { target: Some(Value::Number(target)), pivot, ..Default::default() };
    api::normalize(paths, &o).unwrap_err().to_string()
}

#[test]
fn test_a_negative_target_perimeter_is_shown_to_4_significant_digits() {
    let square = polygon(&[[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]);
    let e = message(&[square.clone()], -std::f64::consts::PI, None);
    assert!(e.contains("or a perimeter (a positive number), got -3.142"), "got {e}");
    assert!(!e.contains("3.1415"), "raw number in {e}");
}

#[test]
fn test_a_target_out_of_range_shows_the_scale_and_the_target_in_e_notation() {
    // A 10 × 10 square (perimeter 40) to 1e306: scale 2.5e304, about a pivot 1e10 away, which
    // moves the far corner to about -2.5e314: beyond f64.
    let square = polygon(&[[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]);
    let e = message(&[square], 1e306, Some(Value::List(vec![Value::Number(1e10), Value::Number(0.0)])));
    let scale = 1e306 / 40.0;
    assert!(e.contains(&format!("scaling the first path by {scale:.3e} to perimeter 1.000e306 leaves the range of numbers")), "got {e}");
    assert!(e.contains("by 2.500e304"), "got {e}");
    assert!(e.len() < 200, "a message for people, got {} characters: {e}", e.len());
}
