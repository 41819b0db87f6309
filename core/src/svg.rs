//! SVG path data (`d` attribute) ↔ outlines, shared by every host (browser panel, Node demo,
//! Inkscape CLI).
//!
//! Reading follows the SVG 1.1 path grammar (all of `MmLlHhVvCcSsQqTtAaZz`, implicit command
//! repetition, `M` followed by pairs meaning `L`, flags without separators). Lines become
//! segments with both handles on their anchors (corners); quadratics are degree-elevated
//! exactly (`c1 = p0 + ⅔(q − p0)`, `c2 = p3 + ⅔(q − p3)`); elliptical arcs go through kurbo's
//! endpoint-to-centre conversion (`Arc::from_svg_arc`) and cubic approximation with a tolerance
//! *relative* to the arc's radius ([`ARC_TOLERANCE`]). kurbo's own `BezPath::from_svg` is not
//! used because it uses an absolute arc tolerance of 0.1 unit and a 1e-5 absolute radius
//! threshold (wrong for shapes measured in small units) and stops silently at garbage.
//!
//! Writing emits absolute `M`, `C`, `L`, `Z` with the shortest round-trip text of each `f64`
//! (exponent form when very large or small), so reading back gives bit-identical coordinates.

use crate::contour::Knot;
use crate::error::{Error, Result};
use kurbo::{Arc, PathEl, Point, SvgArc, Vec2};

/// Arc-to-cubic tolerance relative to the larger radius (1e-6: 0.1 µm on a 10 cm arc,
/// three cubics per quarter turn).
pub const ARC_TOLERANCE: f64 = 1e-6;

/// One subpath: knots in order and whether it was closed with `Z`.
#[derive(Debug, Clone, PartialEq)]
pub struct SubPath {
    pub knots: Vec<Knot>,
    pub closed: bool,
}

struct Lexer<'a> {
    s: &'a [u8],
    src: &'a str,
    i: usize,
}

impl<'a> Lexer<'a> {
    fn err(&self, at: usize, problem: impl Into<String>) -> Error {
        // Positions are always at ASCII bytes the lexer looked at, hence char boundaries.
        let near: String = self.src.get(at..).unwrap_or("").chars().take(12).collect();
        let position = self.src.get(..at).map_or(at, |s| s.chars().count());
        Error::SvgSyntax { position, near, problem: problem.into() }
    }
    fn skip_ws(&mut self) {
        while let Some(c) = self.s.get(self.i) {
            if matches!(c, b' ' | b'\t' | b'\n' | b'\r' | 0x0c) {
                self.i += 1;
            } else {
                break;
            }
        }
    }
    fn skip_ws_comma(&mut self) {
        self.skip_ws();
        if self.s.get(self.i) == Some(&b',') {
            self.i += 1;
            self.skip_ws();
        }
    }
    fn peek(&self) -> Option<u8> {
        self.s.get(self.i).copied()
    }
    /// Is a number next (after whitespace)?
    fn number_next(&mut self) -> bool {
        self.skip_ws();
        matches!(self.peek(), Some(b'0'..=b'9' | b'-' | b'+' | b'.'))
    }
    fn number(&mut self) -> Result<f64> {
        self.skip_ws_comma();
        let start = self.i;
        let digits = |lx: &mut Self| {
            let k = lx.i;
            while lx.peek().is_some_and(|c| c.is_ascii_digit()) {
                lx.i += 1;
            }
            lx.i - k
        };
        if matches!(self.peek(), Some(b'-' | b'+')) {
            self.i += 1;
        }
        let mut n = digits(self);
        if self.peek() == Some(b'.') {
            self.i += 1;
            n += digits(self);
        }
        if n == 0 {
            self.i = start;
            return Err(match self.peek() {
                None => self.err(start, "the data ends where a number was expected"),
                Some(_) => self.err(start, "a number was expected"),
            });
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            let save = self.i;
            self.i += 1;
            if matches!(self.peek(), Some(b'-' | b'+')) {
                self.i += 1;
            }
            if digits(self) == 0 {
                self.i = save;
            }
        }
        let text = &self.src[start..self.i];
        match parse_number(text) {
            x if x.is_finite() => Ok(x),
            _ => Err(self.err(start, format!("the number {text} is out of range"))),
        }
    }
    fn pair(&mut self) -> Result<Point> {
        let x = self.number()?;
        let y = self.number()?;
        Ok(Point::new(x, y))
    }
    fn flag(&mut self) -> Result<bool> {
        self.skip_ws_comma();
        match self.peek() {
            Some(b'0') => {
                self.i += 1;
                Ok(false)
            }
            Some(b'1') => {
                self.i += 1;
                Ok(true)
            }
            None => Err(self.err(self.i, "the data ends where an arc flag (0 or 1) was expected")),
            Some(_) => Err(self.err(self.i, "an arc flag (0 or 1) was expected")),
        }
    }
}

/// The value of a number the lexer has accepted (`[+-]? digits [. digits] [(e|E) [+-]? digits]`,
/// at least one mantissa digit), correctly rounded like `str::parse::<f64>`, through
/// minimal-lexical's compact parser: std's parser carries a 10 KB table of powers of five into
/// the `.wasm` for speed that path data, a few numbers per segment, does not need.
fn parse_number(text: &str) -> f64 {
    let digit_run = |s: &[u8]| s.iter().take_while(|c| c.is_ascii_digit()).count();
    let (negative, rest) = match text.as_bytes() {
        [b'-', rest @ ..] => (true, rest),
        [b'+', rest @ ..] => (false, rest),
        rest => (false, rest),
    };
    let (int, rest) = rest.split_at(digit_run(rest));
    let (frac, rest) = match rest {
        [b'.', rest @ ..] => rest.split_at(digit_run(rest)),
        _ => (&[][..], rest),
    };
    let exponent = match rest {
        [_e, b'-', digits @ ..] => -decimal_i32(digits),
        [_e, b'+', digits @ ..] | [_e, digits @ ..] => decimal_i32(digits),
        [] => 0,
    };
    // minimal-lexical wants the integer without leading and the fraction without trailing zeros.
    let int = &int[int.iter().take_while(|&&c| c == b'0').count()..];
    let frac = &frac[..frac.len() - frac.iter().rev().take_while(|&&c| c == b'0').count()];
    let x: f64 = minimal_lexical::parse_float(int.iter(), frac.iter(), exponent);
    if negative { -x } else { x }
}

/// ASCII decimal digits as an `i32`, saturating: an exponent beyond ±2³¹ over- or underflows
/// every mantissa short enough to fit in memory anyway.
fn decimal_i32(digits: &[u8]) -> i32 {
    digits.iter().fold(0i32, |n, &d| n.saturating_mul(10).saturating_add(i32::from(d - b'0')))
}

/// Builds subpaths from segments.
#[derive(Default)]
struct Builder {
    done: Vec<SubPath>,
    knots: Vec<Knot>,
    closed: bool,
}

impl Builder {
    fn finish(&mut self) {
        let mut knots = std::mem::take(&mut self.knots);
        if knots.len() < 2 {
            return; // a lone moveto draws nothing
        }
        if self.closed && knots.len() > 2 {
            // An explicit final segment back onto the start: that start knot receives its
            // incoming handle, and the duplicate goes.
            if let (Some(first), Some(last)) = (knots.first(), knots.last()) {
                if first.anchor == last.anchor {
                    let left = last.left;
                    knots.pop();
                    if let Some(first) = knots.first_mut() {
                        first.left = left;
                    }
                }
            }
        }
        self.done.push(SubPath { knots, closed: self.closed });
        self.closed = false;
    }
    fn move_to(&mut self, p: Point) {
        self.finish();
        self.closed = false;
        self.knots.push(Knot::corner(p));
    }
    fn curve_to(&mut self, p1: Point, p2: Point, p3: Point) {
        if let Some(last) = self.knots.last_mut() {
            last.right = p1;
        }
        self.knots.push(Knot { anchor: p3, left: p2, right: p3 });
    }
}

/// Parses SVG path data into subpaths (one per `M`, or per drawing command after `Z`).
pub fn parse(d: &str) -> Result<Vec<SubPath>> {
    let mut lx = Lexer { s: d.as_bytes(), src: d, i: 0 };
    let mut b = Builder::default();
    let mut cmd: Option<u8> = None;
    let mut start = Point::ORIGIN; // start of the current subpath
    let mut after_close = false;
    let mut cur = Point::ORIGIN; // current point
    // Last control point for S/T reflection, with the kind of command that set it.
    let mut last_cubic_ctrl: Option<Point> = None;
    let mut last_quad_ctrl: Option<Point> = None;
    loop {
        lx.skip_ws();
        let Some(c) = lx.peek() else { break };
        let at = lx.i;
        let c = if c.is_ascii_alphabetic() {
            lx.i += 1;
            c
        } else if lx.number_next() {
            match cmd {
                Some(b'z' | b'Z') | None => return Err(lx.err(at, "a command letter was expected")),
                // Pairs after a moveto are linetos.
                Some(b'M') => b'L',
                Some(b'm') => b'l',
                Some(other) => other,
            }
        } else {
            let ch = d.get(at..).and_then(|s| s.chars().next()).unwrap_or(' ');
            return Err(lx.err(at, format!("{ch:?} is not a path command")));
        };
        if cmd.is_none() && !matches!(c, b'M' | b'm') {
            return Err(lx.err(at, "path data must start with a moveto (M or m)"));
        }
        let rel = c.is_ascii_lowercase();
        if after_close && !matches!(c, b'M' | b'm' | b'Z' | b'z') {
            b.move_to(start);
        }
        after_close = false;
        let abs = |p: Point| if rel { p + cur.to_vec2() } else { p };
        let (mut cubic_ctrl, mut quad_ctrl) = (None, None);
        match c.to_ascii_uppercase() {
            b'M' => {
                let p = abs(lx.pair()?);
                b.move_to(p);
                start = p;
                cur = p;
            }
            b'L' => {
                let p = abs(lx.pair()?);
                b.curve_to(cur, p, p);
                cur = p;
            }
            b'H' => {
                let x = lx.number()?;
                let p = Point::new(if rel { cur.x + x } else { x }, cur.y);
                b.curve_to(cur, p, p);
                cur = p;
            }
            b'V' => {
                let y = lx.number()?;
                let p = Point::new(cur.x, if rel { cur.y + y } else { y });
                b.curve_to(cur, p, p);
                cur = p;
            }
            b'C' | b'S' => {
                let p1 = if c.eq_ignore_ascii_case(&b'S') {
                    last_cubic_ctrl.map_or(cur, |q| cur + (cur - q))
                } else {
                    abs(lx.pair()?)
                };
                let p2 = abs(lx.pair()?);
                let p3 = abs(lx.pair()?);
                b.curve_to(p1, p2, p3);
                cubic_ctrl = Some(p2);
                cur = p3;
            }
            b'Q' | b'T' => {
                let q = if c.eq_ignore_ascii_case(&b'T') {
                    last_quad_ctrl.map_or(cur, |q| cur + (cur - q))
                } else {
                    abs(lx.pair()?)
                };
                let p3 = abs(lx.pair()?);
                // Exact degree elevation.
                b.curve_to(cur + (q - cur) * (2.0 / 3.0), p3 + (q - p3) * (2.0 / 3.0), p3);
                quad_ctrl = Some(q);
                cur = p3;
            }
            b'A' => {
                let rx = lx.number()?;
                let ry = lx.number()?;
                let rot = lx.number()?;
                let large = lx.flag()?;
                let sweep = lx.flag()?;
                let p = abs(lx.pair()?);
                arc_to(&mut b, cur, p, Vec2::new(rx, ry), rot, large, sweep);
                cur = p;
            }
            b'Z' => {
                if !b.knots.is_empty() {
                    b.closed = true;
                    b.finish();
                }
                after_close = true;
                cur = start;
            }
            _ => return Err(lx.err(at, format!("{:?} is not a path command", c as char))),
        }
        last_cubic_ctrl = cubic_ctrl;
        last_quad_ctrl = quad_ctrl;
        cmd = Some(c);
    }
    b.finish();
    Ok(b.done)
}

/// An elliptical arc as cubics. Per SVG: zero radius → straight line; equal end points → nothing.
/// The arc is computed in coordinates where its larger radius is 1 (kurbo's straight-line test
/// and tolerance are absolute), then mapped back.
fn arc_to(b: &mut Builder, from: Point, to: Point, radii: Vec2, rot_deg: f64, large: bool, sweep: bool) {
    if from == to {
        return;
    }
    if radii.x == 0.0 || radii.y == 0.0 {
        b.curve_to(from, to, to);
        return;
    }
    // Unit scale: the larger of the radii and the chord (radii too small for the chord are
    // scaled up by the SVG rules, so the chord bounds the corrected ellipse too). The number
    // of cubics then depends only on the shape of the arc, never on its size.
    let r = radii.x.abs().max(radii.y.abs()).max((to - from).hypot());
    if !(r.is_finite() && r > 0.0) {
        b.curve_to(from, to, to);
        return;
    }
    let unit = SvgArc {
        from: Point::ORIGIN,
        to: ((to - from) / r).to_point(),
        radii: Vec2::new(radii.x.abs() / r, radii.y.abs() / r),
        x_rotation: rot_deg.to_radians(),
        large_arc: large,
        sweep,
    };
    let back = |p: Point| from + p.to_vec2() * r;
    match Arc::from_svg_arc(&unit) {
        Some(arc) => {
            let els: Vec<PathEl> = arc.append_iter(ARC_TOLERANCE).collect();
            let n = els.len();
            for (i, el) in els.into_iter().enumerate() {
                if let PathEl::CurveTo(p1, p2, p3) = el {
                    // The last end point is the exact target, so the path stays connected.
                    let end = if i + 1 == n { to } else { back(p3) };
                    b.curve_to(back(p1), back(p2), end);
                }
            }
        }
        None => b.curve_to(from, to, to),
    }
}

/// Writes one path as SVG path data: `M` then one `C` (or `L` for a segment with both handles
/// on its anchors) per segment; closed paths end with `Z`, the closing segment written out
/// unless it is a straight line (which `Z` draws).
/// Shortest text that reads back as the same `f64`, exponent form for very large or small
/// magnitudes (Rust's `Debug` formatting, without a trailing `.0`).
fn num(x: f64) -> String {
    let s = format!("{x:?}");
    match s.strip_suffix(".0") {
        Some(t) => t.to_owned(),
        None => s,
    }
}

pub fn write(knots: &[Knot], closed: bool) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let Some(first) = knots.first() else { return s };
    let _ = write!(s, "M{} {}", num(first.anchor.x), num(first.anchor.y));
    let n = knots.len();
    let segs = if closed { n } else { n.saturating_sub(1) };
    for i in 0..segs {
        let (Some(a), Some(b)) = (knots.get(i), knots.get((i + 1) % n)) else { break };
        let line = a.right == a.anchor && b.left == b.anchor;
        if line && closed && i + 1 == n {
            break; // Z draws it
        }
        if line {
            let _ = write!(s, " L{} {}", num(b.anchor.x), num(b.anchor.y));
        } else {
            let _ = write!(
                s,
                " C{} {} {} {} {} {}",
                num(a.right.x),
                num(a.right.y),
                num(b.left.x),
                num(b.left.y),
                num(b.anchor.x),
                num(b.anchor.y)
            );
        }
    }
    if closed {
        s.push_str(" Z");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::parse_number;
    use proptest::prelude::*;

    fn same_as_std(text: &str) {
        let want: f64 = text.parse().unwrap();
        let got = parse_number(text);
        assert_eq!(got.to_bits(), want.to_bits(), "{text}: std gives {want:e}, got {got:e}");
    }

    #[test]
    fn numbers_round_like_std() {
        let long = format!("0.{}1e5", "0".repeat(900));
        let many = format!("{}.{}", "7".repeat(400), "3".repeat(500));
        let halfway = format!("9007199254740993.{}1", "0".repeat(800));
        for text in [
            "0", "-0", "+0", "0.000", ".5", "5.", "-.5e-3", "1E5", "12e+3", "00012.500e0", "9007199254740993",
            "2.2250738585072011e-308", "2.2250738585072014e-308", "4.9406564584124654e-324",
            "2.4703282292062327e-324", "2.4703282292062328e-324", "1.7976931348623157e308",
            "1.7976931348623158e308", "1.7976931348623159e308", "1e309", "1e-400", "0e999999999999",
            "1e99999999999", "1e-99999999999", "123456789012345678901234567890", &long, &many, &halfway,
        ] {
            same_as_std(text);
        }
    }

    proptest! {
        #[test]
        fn random_numbers_round_like_std(
            text in "[+-]?[0-9]{0,40}(\\.[0-9]{0,40})?([eE][+-]?[0-9]{1,3})?"
                .prop_filter("a mantissa digit", |t| t.split(['e', 'E']).next().is_some_and(|m| m.bytes().any(|c| c.is_ascii_digit())))
        ) {
            same_as_std(&text);
        }
    }
}
