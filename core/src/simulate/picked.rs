//! Which piece of a pair with a non-convex piece is solved first: one of the pair's own choosing,
//! not the one the student happened to pick first.
//!
//! Gluing A to B at `offset` (A's arc length `s`, counter-clockwise, meets B's `offset + s`,
//! clockwise, [`super::seam::Glue::new`]) is the same gluing as B to A at `offset · P_A / P_B`:
//! B's point at clockwise arc length `o + s·P_B/P_A` is at counter-clockwise `P_B − o − s·P_B/P_A`,
//! and A's point at counter-clockwise `s` is at clockwise `P_A − s`, which is
//! `o·P_A/P_B + (P_B − o − s·P_B/P_A)·P_A/P_B`. Both pieces keep their drawn front outward either
//! way (the seam's direction is A's counter-clockwise one and B's clockwise one, as on a
//! pillow), so the two orders ask for one surface. But the seam is sampled from the first
//! piece's start ([`super::anchor`]), so the two orders sample, mesh and solve it differently,
//! and a thin sheet has several equilibria a few percent apart ([`super::sheet::level`]): picked
//! the other way round, the kidney with the five lobes was 2.9 % off in volume and the kidney
//! with a 2:1 ellipse 2.1 % (256 seam vertices, WASM); the 120 random pairs of two blobs of the
//! survey up to 7.8 %, median 0.61 %, 36 of them over 1 % (native).
//!
//! So such a pair is solved in an order that is a function of the two pieces alone
//! ([`second_first`]), and an answer solved the other way round is read back in the order asked
//! ([`swap_back`]): picked either way, a pair gets one mesh and form to the last bit.

use super::anchor::{centre, greatest_rotation, quantum};
use super::{round, Simulation};
use crate::contour::Contour;
use kurbo::Point;

/// Relative difference (of the larger) below which two pieces' areas are taken as equal
/// ([`second_first`]): far above the round-off of where a piece sits (a copy moved on the
/// page), far below any drawn difference.
pub const SAME_AREA: f64 = 1e-9;

/// Whether the pair (`a`, `b`) is solved as (`b`, `a`). The first piece is, in turn:
///
/// - not a circle (a circle is solved as one canonical circle of the other's perimeter,
///   [`round::Canonical`], and the other piece then sets the seam samples);
/// - the one of larger area (compared to [`SAME_AREA`]);
/// - the one whose anchors' distances from their mean, read counter-clockwise from where that
///   sequence is greatest, is the lesser sequence: this tells a piece from its mirror image,
///   whose sequence runs the other way, unless it is symmetric. Either way round would do; of
///   the kidney's gluings to its mirror image at 1–15/16 of the perimeter, 14 converge this way
///   and 12 the other (256 seam vertices, native).
///
/// Only pieces that are alike in all of that keep the order they were picked in: one outline
/// moved or turned (a copy; a symmetric piece's mirror image is one), which the frames
/// ([`super::frame`]) solve the same either way, the piece picked first in A's place.
pub fn second_first(a: &Contour, b: &Contour) -> bool {
    let (circle_a, circle_b) = (round::circle(a).is_some(), round::circle(b).is_some());
    if circle_a != circle_b {
        return circle_a;
    }
    let (area_a, area_b) = (a.signed_area().abs(), b.signed_area().abs());
    if (area_a - area_b).abs() > SAME_AREA * area_a.max(area_b) {
        return area_b > area_a;
    }
    distances(b) < distances(a)
}

/// `c`'s anchors' distances from their mean, quantized relative to the farthest ([`quantum`], as
/// [`super::anchor::canonical_start`] compares them), read counter-clockwise from the
/// rotation that makes the sequence greatest ([`greatest_rotation`]): the same
/// whichever knot `c` starts at and whichever way it runs. Empty for a degenerate outline.
fn distances(c: &Contour) -> Vec<i64> {
    let mut anchors: Vec<Point> = c.knots().iter().map(|k| k.anchor).collect();
    if c.signed_area() < 0.0 {
        anchors.reverse();
    }
    let m = anchors.len();
    let o = centre(&anchors);
    let d: Vec<f64> = anchors.iter().map(|p| p.distance(o)).collect();
    let far = d.iter().copied().fold(0.0, f64::max);
    if !(far.is_finite() && far > 0.0) {
        return Vec::new();
    }
    let q: Vec<i64> = d.iter().map(|&x| quantum(x, far)).collect();
    let best = greatest_rotation(&q);
    (0..m).map(|i| q[(best + i) % m]).collect()
}

/// An answer for the pair solved as (B, A) read as the answer for (A, B): each triangle's
/// `piece` (and each crease's) swapped; the vertices renumbered seam first, then A's interior
/// vertices, then B's, and the triangles A's first, as an answer solved in order lists them;
/// `seam` reversed (it ran counter-clockwise on B, which is clockwise on A) and started at the
/// seam vertex nearest `a_first`, A's first anchor ([`super::anchor::start_seam_at`]).
/// Positions, `flat` and `stats` are the pair's whichever way it was solved.
pub fn swap_back(sim: Simulation, a_first: Point) -> Simulation {
    let Simulation { vertices, triangles, piece, mut seam, flat, mut creases, stats } = sim;
    let n = vertices.len();
    let mut on_seam = vec![false; n];
    for &v in &seam {
        if let Some(s) = on_seam.get_mut(v) {
            *s = true;
        }
    }
    // Each vertex's piece as solved (an interior vertex is in triangles of one piece only).
    let mut of = vec![0u8; n];
    for (t, &p) in triangles.iter().zip(&piece) {
        for &v in t {
            of[v] = p;
        }
    }
    let class = |v: usize| if on_seam[v] { 0 } else if of[v] == 1 { 1 } else { 2 };
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by_key(|&v| class(v));
    let mut new = vec![0; n];
    for (i, &v) in order.iter().enumerate() {
        new[v] = i;
    }
    let mut faces: Vec<usize> = (0..triangles.len()).collect();
    faces.sort_by_key(|&t| 1 - piece[t].min(1));
    seam.reverse();
    for s in &mut seam {
        *s = new[*s];
    }
    for c in &mut creases {
        c.piece = 1 - c.piece.min(1);
        c.vertices = c.vertices.map(|v| new[v]);
    }
    let mut out = Simulation {
        vertices: order.iter().map(|&v| vertices[v]).collect(),
        triangles: faces.iter().map(|&t| triangles[t].map(|v| new[v])).collect(),
        piece: faces.iter().map(|&t| 1 - piece[t].min(1)).collect(),
        seam,
        flat: faces.iter().map(|&t| flat[t]).collect(),
        creases,
        stats,
    };
    super::anchor::start_seam_at(&mut out, a_first);
    out
}
