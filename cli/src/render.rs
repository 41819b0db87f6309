//! A picture of the solved form as SVG, in Rust with no GPU: orthographic projection, back faces
//! culled, the front faces flat-shaded (Lambert) and painted far to near (painter's algorithm),
//! the visible part of the seam drawn on top, a scale bar in the document's unit.
//!
//! For a convex form (the Alexandrov polyhedron `simulate` finds for convex pieces) culling alone
//! already leaves non-overlapping faces, so the painter's order is exact; for a non-convex form it
//! is the usual centroid-depth approximation. The view looks at the form along its principal
//! axes (`formFigures`): the height axis up on the page, seen from 35° above and 35° round from
//! the depth axis, so the same form always gives the same picture.
//!
//! Lives in the CLI, not in the core: it is a presentation of a result (colours, a caption, a
//! scale bar labelled in the host document's unit), not geometry the other hosts call; the panel
//! draws its interactive view on a canvas (uxp-panel/src/view3d.js).

use crate::splice::escape;
use dformer::api::simulate::SimulateDto;
use std::collections::HashSet;

type V = [f64; 3];

fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V, b: V) -> V {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn unit(a: V) -> V {
    let l = dot(a, a).sqrt();
    if l > 0.0 {
        a.map(|x| x / l)
    } else {
        a
    }
}
fn mix(a: V, ka: f64, b: V, kb: f64) -> V {
    [ka * a[0] + kb * b[0], ka * a[1] + kb * b[1], ka * a[2] + kb * b[2]]
}

/// Piece A warm, piece B cool (the panel's colours); the seam red; creases violet.
pub const COLORS: [[f64; 3]; 2] = [[222.0, 170.0, 110.0], [128.0, 166.0, 214.0]];
const SEAM: &str = "rgb(192,24,42)";
const CREASE: &str = "rgb(112,32,168)";

/// An orthographic camera: `toward` points from the form to the viewer; `right` and `up` span
/// the picture plane; `light` is the direction light comes from.
#[derive(Debug, Clone, Copy)]
pub struct View {
    pub toward: V,
    pub right: V,
    pub up: V,
    pub light: V,
}

impl View {
    /// The view of a form with principal axes `[height, width, depth]` (unit vectors).
    pub fn of_axes(axes: [V; 3]) -> View {
        let [h, w, d] = axes;
        let (az, el) = (35f64.to_radians(), 35f64.to_radians());
        let toward = unit(mix(mix(d, az.cos(), w, az.sin()), el.cos(), h, el.sin()));
        let up = unit(mix(h, 1.0, toward, -dot(h, toward)));
        let right = cross(up, toward);
        // From the upper left, a little in front: every face the viewer sees gets some light.
        let light = unit(mix(mix(right, -0.3, up, 0.45), 1.0, toward, 0.85));
        View { toward, right, up, light }
    }

    /// Lambert factor of a face with unit normal `n`: 0.35 ambient + 0.65 diffuse.
    pub fn shade(&self, n: V) -> f64 {
        0.35 + 0.65 * dot(n, self.light).max(0.0)
    }
}

/// A triangle's unit normal (outward for `simulate`'s counter-clockwise-from-outside order).
pub fn face_normal(vertices: &[V], t: [usize; 3]) -> V {
    let [a, b, c] = t.map(|i| vertices[i]);
    unit(cross(sub(b, a), sub(c, a)))
}

/// A round length near `x` (1, 2 or 5 × 10ᵏ), for the scale bar.
fn round_length(x: f64) -> f64 {
    let p = 10f64.powf(x.log10().floor());
    [5.0, 2.0, 1.0].into_iter().map(|k| k * p).find(|&l| l <= x).unwrap_or(p)
}

fn num(x: f64) -> String {
    let s = format!("{x:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

/// Path data of the edges `(i, j)`, in order, that a front face borders (`front`, each edge as
/// `(min, max)`): consecutive visible edges sharing a vertex are one subpath.
fn visible_path(edges: &[(usize, usize)], front: &HashSet<(usize, usize)>, at: impl Fn(usize) -> [f64; 2]) -> String {
    let mut d = String::new();
    let mut last = None;
    for &(i, j) in edges {
        if !front.contains(&(i.min(j), i.max(j))) {
            last = None;
            continue;
        }
        let (p, q) = (at(i), at(j));
        if last != Some(i) {
            d.push_str(&format!("M{},{}", num(p[0]), num(p[1])));
        }
        d.push_str(&format!("L{},{}", num(q[0]), num(q[1])));
        last = Some(j);
    }
    d
}

/// The SVG picture of `form` (lengths in `unit`) seen with `view`, `caption` written above it.
pub fn render(form: &SimulateDto, view: &View, unit: &str, caption: &str) -> String {
    let vs = &form.vertices;
    let project = |p: V| [dot(p, view.right), -dot(p, view.up)];
    let screen: Vec<[f64; 2]> = vs.iter().map(|&p| project(p)).collect();
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in &screen {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let span = [(hi[0] - lo[0]).max(1e-12), (hi[1] - lo[1]).max(1e-12)];
    let (margin, top, bottom) = (24.0, 36.0, 48.0);
    let s = (592.0 / span[0]).min(420.0 / span[1]);
    let (w, h) = (span[0] * s + 2.0 * margin, span[1] * s + top + bottom);
    let at = |p: [f64; 2]| [margin + (p[0] - lo[0]) * s, top + (p[1] - lo[1]) * s];

    // Front faces, far to near.
    let mut faces: Vec<(f64, usize, V)> = form
        .triangles
        .iter()
        .enumerate()
        .filter_map(|(t, &tri)| {
            let n = face_normal(vs, tri);
            (dot(n, view.toward) > 0.0).then(|| {
                let depth = tri.iter().map(|&i| dot(vs[i], view.toward)).sum::<f64>() / 3.0;
                (depth, t, n)
            })
        })
        .collect();
    faces.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));

    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" \
         data-toward=\"{} {} {}\" data-right=\"{} {} {}\" data-up=\"{} {} {}\" data-light=\"{} {} {}\">\n",
        num(w), num(h), num(w), num(h),
        view.toward[0], view.toward[1], view.toward[2],
        view.right[0], view.right[1], view.right[2],
        view.up[0], view.up[1], view.up[2],
        view.light[0], view.light[1], view.light[2],
    );
    out.push_str(&format!("<title>D-form: {}</title>\n", escape(caption)));
    out.push_str(&format!("<rect width=\"{}\" height=\"{}\" fill=\"#fff\"/>\n", num(w), num(h)));
    out.push_str(&format!(
        "<text x=\"{margin}\" y=\"22\" font-family=\"sans-serif\" font-size=\"13\" fill=\"#333\">{}</text>\n",
        escape(caption)
    ));
    out.push_str("<g id=\"faces\" stroke-linejoin=\"round\" stroke-width=\"0.4\">\n");
    for (_, t, n) in &faces {
        let k = view.shade(*n);
        let c = COLORS[usize::from(form.piece.get(*t).copied().unwrap_or(0) != 0)].map(|x| (x * k).round() as u8);
        let fill = format!("rgb({},{},{})", c[0], c[1], c[2]);
        let pts: Vec<String> = form.triangles[*t].iter().map(|&i| {
            let p = at(screen[i]);
            format!("{},{}", num(p[0]), num(p[1]))
        }).collect();
        // Stroked in its own colour: closes the hairline gaps anti-aliasing leaves between faces.
        out.push_str(&format!("<polygon data-t=\"{t}\" points=\"{}\" fill=\"{fill}\" stroke=\"{fill}\"/>\n", pts.join(" ")));
    }
    out.push_str("</g>\n");

    // The seam where a front face borders it.
    let front: HashSet<(usize, usize)> = faces
        .iter()
        .flat_map(|(_, t, _)| {
            let tri = form.triangles[*t];
            (0..3).map(move |m| {
                let (i, j) = (tri[m], tri[(m + 1) % 3]);
                (i.min(j), i.max(j))
            })
        })
        .collect();
    let n = form.seam.len();
    let seam: Vec<(usize, usize)> = (0..n).map(|k| (form.seam[k], form.seam[(k + 1) % n])).collect();
    out.push_str(&format!(
        "<path id=\"seam\" d=\"{}\" fill=\"none\" stroke=\"{SEAM}\" stroke-width=\"1.6\" stroke-linecap=\"round\" stroke-linejoin=\"round\"/>\n",
        visible_path(&seam, &front, |i| at(screen[i]))
    ));
    // Where a non-convex pair's answer creases (`creases`), where a front face borders it.
    if !form.creases.is_empty() {
        let creases: Vec<(usize, usize)> = form.creases.iter().map(|c| (c.vertices[0], c.vertices[1])).collect();
        out.push_str(&format!(
            "<path id=\"creases\" d=\"{}\" fill=\"none\" stroke=\"{CREASE}\" stroke-width=\"2.4\" stroke-linecap=\"round\"/>\n",
            visible_path(&creases, &front, |i| at(screen[i]))
        ));
    }

    // Scale bar: a round length about a quarter of the picture's width.
    let len = round_length(span[0] / 4.0);
    let (x0, y0, x1) = (margin, h - 20.0, margin + len * s);
    out.push_str(&format!(
        "<g id=\"scale-bar\" data-length=\"{len}\" stroke=\"#333\" stroke-width=\"1.2\" font-family=\"sans-serif\" font-size=\"11\" fill=\"#333\">\
<path d=\"M{a},{b}V{c}H{e}V{b}\" fill=\"none\"/><text x=\"{f}\" y=\"{g}\" stroke=\"none\">{} {unit}</text></g>\n",
        num(len),
        a = num(x0), b = num(y0 - 5.0), c = num(y0), e = num(x1),
        f = num(x1 + 6.0), g = num(y0 + 1.0),
    ));
    out.push_str("</svg>\n");
    out
}
