//! `dformer form --sweep N -o plot.svg`: volume and height against the seam offset over one
//! full turn, as an SVG chart. Offsets where the solve did not converge are drawn as such (grey
//! crosses on the axis), never as values; the largest and the tallest form are marked.

use crate::splice::escape;

/// One sampled offset.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// Offset as a fraction of the perimeter, in [0, 1).
    pub fraction: f64,
    /// Offset along the seam, display unit.
    pub offset: f64,
    /// Volume in the display unit³ and in litres.
    pub volume: f64,
    pub litres: f64,
    /// Principal height, display unit.
    pub height: f64,
    pub converged: bool,
}

/// Index of the converged row with the greatest `key` (first one on ties).
pub fn best(rows: &[Row], key: impl Fn(&Row) -> f64) -> Option<usize> {
    let mut out: Option<usize> = None;
    for (i, r) in rows.iter().enumerate() {
        if r.converged && out.is_none_or(|b| key(r) > key(&rows[b])) {
            out = Some(i);
        }
    }
    out
}

fn nice_max(x: f64) -> f64 {
    if !(x > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0].into_iter().map(|k| k * p).find(|&m| m >= x).unwrap_or(10.0 * p)
}

fn num(x: f64) -> String {
    let s = format!("{x:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

fn label(x: f64) -> String {
    let s = format!("{:.3}", x);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}

/// The chart; `unit` names the height's unit, `title` goes on top.
pub fn plot(rows: &[Row], unit: &str, title: &str) -> String {
    let (w, h) = (640.0, 360.0);
    let (l, r, t, b) = (64.0, 64.0, 40.0, 56.0);
    let (pw, ph) = (w - l - r, h - t - b);
    let vmax = nice_max(rows.iter().filter(|r| r.converged).map(|r| r.litres).fold(0.0, f64::max));
    let hmax = nice_max(rows.iter().filter(|r| r.converged).map(|r| r.height).fold(0.0, f64::max));
    let x = |f: f64| l + f * pw;
    let yv = |v: f64| t + ph * (1.0 - v / vmax);
    let yh = |v: f64| t + ph * (1.0 - v / hmax);
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" font-family=\"sans-serif\" font-size=\"11\">\n\
<title>{}</title>\n<rect width=\"{w}\" height=\"{h}\" fill=\"#fff\"/>\n\
<text x=\"{l}\" y=\"22\" font-size=\"13\" fill=\"#333\">{}</text>\n",
        escape(title), escape(title)
    );
    // Axes and ticks.
    out.push_str(&format!("<g id=\"axes\" stroke=\"#999\" fill=\"#333\"><path d=\"M{l},{t}V{}H{}V{t}\" fill=\"none\"/>\n", t + ph, l + pw));
    for k in 0..=4 {
        let f = k as f64 / 4.0;
        out.push_str(&format!(
            "<path d=\"M{x0},{y0}v4\"/><text x=\"{x0}\" y=\"{ty}\" stroke=\"none\" text-anchor=\"middle\">{}</text>\n",
            ["0", "¼", "½", "¾", "1"][k],
            x0 = num(x(f)), y0 = num(t + ph), ty = num(t + ph + 16.0)
        ));
        let v = vmax * f;
        let hv = hmax * f;
        out.push_str(&format!(
            "<text x=\"{}\" y=\"{y}\" stroke=\"none\" text-anchor=\"end\" fill=\"#2a62b8\">{}</text><text x=\"{}\" y=\"{y}\" stroke=\"none\" fill=\"#c05a00\">{}</text>\n",
            num(l - 6.0), label(v), num(l + pw + 6.0), label(hv), y = num(yv(v) + 4.0)
        ));
    }
    out.push_str(&format!(
        "<text x=\"{}\" y=\"{}\" stroke=\"none\" text-anchor=\"middle\">seam offset (turns: fraction of the perimeter)</text>\n\
<text x=\"14\" y=\"{}\" stroke=\"none\" fill=\"#2a62b8\" transform=\"rotate(-90 14 {})\" text-anchor=\"middle\">volume (L)</text>\n\
<text x=\"{}\" y=\"{}\" stroke=\"none\" fill=\"#c05a00\" transform=\"rotate(90 {} {})\" text-anchor=\"middle\">height ({})</text></g>\n",
        num(l + pw / 2.0), num(h - 14.0), num(t + ph / 2.0), num(t + ph / 2.0),
        num(w - 14.0), num(t + ph / 2.0), num(w - 14.0), num(t + ph / 2.0), escape(unit)
    ));
    // The curves, broken where a solve did not converge; the turn closes on itself (1 = 0).
    let mut closed: Vec<&Row> = rows.iter().collect();
    let wrap = rows.first().map(|r0| Row { fraction: 1.0, ..r0.clone() });
    if let Some(w) = &wrap {
        closed.push(w);
    }
    for (id, color, dash, y) in [
        ("volume", "#2a62b8", "", &yv as &dyn Fn(f64) -> f64),
        ("height", "#c05a00", " stroke-dasharray=\"5 3\"", &yh),
    ] {
        let mut d = String::new();
        let mut pen = false;
        for r in &closed {
            if !r.converged {
                pen = false;
                continue;
            }
            let v = if id == "volume" { r.litres } else { r.height };
            d.push_str(&format!("{}{},{}", if pen { "L" } else { "M" }, num(x(r.fraction)), num(y(v))));
            pen = true;
        }
        out.push_str(&format!("<path id=\"{id}\" d=\"{d}\" fill=\"none\" stroke=\"{color}\" stroke-width=\"1.8\"{dash}/>\n"));
    }
    out.push_str("<g id=\"samples\">\n");
    for r in rows {
        if r.converged {
            out.push_str(&format!(
                "<circle class=\"sample\" cx=\"{}\" cy=\"{}\" r=\"2\" fill=\"#2a62b8\"/>\n",
                num(x(r.fraction)), num(yv(r.litres))
            ));
        } else {
            let (cx, cy) = (x(r.fraction), t + ph - 8.0);
            out.push_str(&format!(
                "<path class=\"unconverged\" d=\"M{},{}l6,6m0,-6l-6,6\" stroke=\"#888\" stroke-width=\"1.4\"><title>not converged at {}</title></path>\n",
                num(cx - 3.0), num(cy - 3.0), label(r.fraction)
            ));
        }
    }
    out.push_str("</g>\n");
    for (id, i, y, text) in [
        ("largest", best(rows, |r| r.volume), &yv as &dyn Fn(f64) -> f64, "largest"),
        ("tallest", best(rows, |r| r.height), &yh, "tallest"),
    ] {
        let Some(i) = i else { continue };
        let r = &rows[i];
        let v = if id == "largest" { r.litres } else { r.height };
        let color = if id == "largest" { "#2a62b8" } else { "#c05a00" };
        out.push_str(&format!(
            "<g id=\"{id}\" data-index=\"{i}\"><circle cx=\"{cx}\" cy=\"{cy}\" r=\"5\" fill=\"none\" stroke=\"{color}\" stroke-width=\"2\"/>\
<text x=\"{cx}\" y=\"{ty}\" text-anchor=\"middle\" fill=\"{color}\">{text} at {}</text></g>\n",
            label(r.fraction),
            cx = num(x(r.fraction)), cy = num(y(v)), ty = num(y(v) - 9.0)
        ));
    }
    out.push_str("</svg>\n");
    out
}
