//! `dformer form FILE.svg`: the 3D D-form of two shapes, as a caster needs it — volume (display
//! unit³ and litres), the mass of a concrete casting, area, principal extents, strain and whether
//! the solve converged; `-o` writes the mesh (`.stl`, `.obj`, in mm) or a picture (`.svg`,
//! [`crate::render`]); `--sweep N` solves N offsets over one full turn and marks the largest and
//! the tallest form (`-o plot.svg`: [`crate::plot`]).

use crate::batch::{pick, read};
use crate::plot::{self, Row};
use crate::render::{self, View};
use crate::svgdoc::SvgFile;
use crate::{meshfile, units};
use dformer::api::form::{self, FiguresDto, FiguresOptionsDto, FormDto, FormStatsDto};
use dformer::api::path::PathDto;
use dformer::api::simulate::{simulate, SimulateDto, SimulateOptionsDto, StatsDto};
use serde_json::json;
use std::path::{Path, PathBuf};

/// Options of `dformer form`.
#[derive(clap::Args)]
pub struct FormArgs {
    /// Seam offset: a length along the seam (30, 30mm, 1.2in) or a fraction of the perimeter
    /// (25%). B's start is moved this far along B; 0 joins the two first anchors.
    #[arg(long, default_value = "0", allow_hyphen_values = true)]
    pub offset: String,
    /// Seam vertices of the mesh (default 256; finer is slower and closer to the smooth form).
    #[arg(long, value_name = "N")]
    pub resolution: Option<f64>,
    /// Density of the casting material in kg/m³ (default 2400, concrete; plaster is about 1000–1300).
    #[arg(long, allow_negative_numbers = true, value_name = "KG_PER_M3")]
    pub density: Option<f64>,
    /// Solve N offsets evenly over one full turn and print a table of volume and height with
    /// the largest and the tallest marked; with -o plot.svg, draw it.
    #[arg(long, value_name = "N")]
    pub sweep: Option<usize>,
    /// Output: .stl or .obj (the mesh, in mm) or .svg (a picture of the form; with --sweep the
    /// plot). Repeatable: `-o form.stl -o form.svg` writes both from one solve.
    #[arg(short, long)]
    pub output: Vec<PathBuf>,
    /// One JSON object instead of text.
    #[arg(long)]
    pub json: bool,
}

/// The two pieces in the display unit, their perimeter, and the unit's size in mm.
struct Pieces {
    paths: Vec<PathDto>,
    perimeter: f64,
    unit: String,
    mm: f64,
}

fn pieces(file: &SvgFile, ids: &[String]) -> Result<Pieces, String> {
    let shapes = pick(file, ids, 2, Some(2))?;
    let paths = read(file, &shapes)?;
    let perimeter = dformer::api::measure(&paths[0], None).map_err(|e| format!("{}: {e}", shapes[0].name))?.perimeter;
    let unit = file.scale.unit.clone();
    let mm = units::px_per(&unit).unwrap_or(1.0) / units::px_per("mm").unwrap_or(1.0);
    Ok(Pieces { paths, perimeter, unit, mm })
}

/// `--offset` → an arc length in [0, perimeter): a length, or a percentage of the perimeter.
pub fn parse_offset(file: &SvgFile, text: &str, perimeter: f64) -> Result<f64, String> {
    let bad = || {
        format!("--offset: `{text}` is not a length (e.g. 30, 30mm, 1.2in) or a fraction of the perimeter (e.g. 25%)")
    };
    let length = match text.trim().strip_suffix('%') {
        Some(pct) => pct.trim().parse::<f64>().ok().filter(|v| v.is_finite()).ok_or_else(bad)? / 100.0 * perimeter,
        None => file.scale.parse(text).map_err(|_| bad())?,
    };
    if !length.is_finite() {
        return Err(bad());
    }
    Ok(length.rem_euclid(perimeter))
}

fn solve(p: &Pieces, offset: f64, a: &FormArgs) -> Result<(SimulateDto, FiguresDto), String> {
    let options = SimulateOptionsDto { offset: Some(offset), resolution: a.resolution, ..Default::default() };
    let sim = simulate(&p.paths, &options).map_err(|e| e.to_string())?;
    let form = FormDto {
        vertices: sim.vertices.clone(),
        triangles: sim.triangles.clone(),
        stats: FormStatsDto { volume: sim.stats.volume },
        ..Default::default()
    };
    let figures = form::figures(&form, &FiguresOptionsDto { mm_per_unit: Some(p.mm), density: a.density })
        .map_err(|e| e.to_string())?;
    Ok((sim, figures))
}

fn extension(path: &Path) -> String {
    path.extension().and_then(|e| e.to_str()).unwrap_or_default().to_ascii_lowercase()
}

fn write(path: &Path, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("could not write {}: {e}", path.display()))
}

fn g(x: f64) -> String {
    // Six significant digits, trailing zeros dropped, no exponent for everyday sizes.
    if x == 0.0 {
        return "0".into();
    }
    if !(1e-4..1e9).contains(&x.abs()) {
        return format!("{x:.5e}");
    }
    let digits = (5 - x.abs().log10().floor() as i32).clamp(0, 9) as usize;
    let s = format!("{x:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// `dformer form`: text (or JSON) on stdout, then the files named by `-o`, written once every
/// solve succeeded.
pub fn run(file: &SvgFile, ids: &[String], a: &FormArgs) -> Result<(), String> {
    if let Some(n) = a.sweep {
        return sweep(file, ids, a, n);
    }
    for path in &a.output {
        if !matches!(extension(path).as_str(), "stl" | "obj" | "svg") {
            return Err(format!("-o {}: write .stl, .obj (the mesh, in mm) or .svg (a picture)", path.display()));
        }
    }
    let p = pieces(file, ids)?;
    let offset = parse_offset(file, &a.offset, p.perimeter)?;
    let (sim, f) = solve(&p, offset, a)?;
    let st = &sim.stats;
    let u = &p.unit;
    let fraction = offset / p.perimeter;
    let text = if a.json {
        format!(
            "{}\n",
            json!({
                "unit": u, "perimeter": p.perimeter, "offset": offset, "fraction": fraction,
                "volume": f.volume, "litres": f.litres, "mass": f.mass, "density": f.density,
                "area": st.area, "height": f.height, "width": f.width, "depth": f.depth,
                "maxStrain": st.max_strain, "converged": st.converged,
                "maxBendDegrees": st.max_bend.to_degrees(), "shortfall": st.shortfall, "offsetFree": st.offset_free,
            })
        )
    } else {
        let mut t = format!("offset     {} {u} ({}% of the perimeter {} {u})\n", g(offset), g(100.0 * fraction), g(p.perimeter));
        if st.offset_free {
            t += "           one piece is a circle: every offset gives this form\n";
        }
        t += &format!("volume     {} {u}³ = {} L\n", g(f.volume), g(f.litres));
        t += &format!("mass       {} kg at {} kg/m³ (concrete: 2400)\n", g(f.mass), g(f.density));
        t += &format!("area       {} {u}²\n", g(st.area));
        t += &format!("extents    height {} {u} × width {} {u} × depth {} {u}\n", g(f.height), g(f.width), g(f.depth));
        t += &format!("strain     {}% at most\n", g(100.0 * st.max_strain));
        t += &format!("converged  {}\n", verdict(st, a.resolution));
        t
    };
    // Everything computed first, then written.
    let mut files = Vec::new();
    for path in &a.output {
        let kind = extension(path);
        let body = match kind.as_str() {
            "stl" => meshfile::stl(&sim, p.mm),
            "obj" => meshfile::obj(&sim, p.mm),
            _ => {
                let caption = format!(
                    "volume {} L · height {} {u} · offset {}%{}",
                    g(f.litres), g(f.height), g(100.0 * fraction),
                    if st.converged { "" } else { " · not converged (approximate)" }
                );
                render::render(&sim, &View::of_axes(f.axes), u, &caption)
            }
        };
        files.push((path, body, kind));
    }
    // The figures first, then what was written.
    print!("{text}");
    std::io::Write::flush(&mut std::io::stdout()).map_err(|e| format!("could not write stdout: {e}"))?;
    for (path, body, kind) in files {
        write(path, &body)?;
        eprintln!("wrote {}{}", path.display(), if kind == "svg" { "" } else { " (mm)" });
    }
    Ok(())
}

/// The N offsets k·P/N, each solved cold (so each row is exactly `simulate` at that offset).
fn sweep(file: &SvgFile, ids: &[String], a: &FormArgs, n: usize) -> Result<(), String> {
    if !(2..=4096).contains(&n) {
        return Err(format!("--sweep: wanted a number of offsets from 2 to 4096, got {n}"));
    }
    if let Some(path) = a.output.iter().find(|p| extension(p) != "svg") {
        return Err(format!("-o {}: with --sweep, -o writes the plot as .svg", path.display()));
    }
    let p = pieces(file, ids)?;
    let mut rows: Vec<Row> = Vec::with_capacity(n);
    let mut offset_free = false;
    for k in 0..n {
        let fraction = k as f64 / n as f64;
        let offset = fraction * p.perimeter;
        // With a circle the core gives offset 0's form at every offset (`offsetFree`): one solve.
        if offset_free {
            rows.push(Row { fraction, offset, ..rows[0] });
            continue;
        }
        let (sim, f) = solve(&p, offset, a)?;
        offset_free = sim.stats.offset_free;
        rows.push(Row { fraction, offset, volume: f.volume, litres: f.litres, height: f.height, converged: sim.stats.converged });
    }
    let (largest, tallest) = if offset_free { (None, None) } else { (plot::best(&rows, |r| r.volume), plot::best(&rows, |r| r.height)) };
    let u = &p.unit;
    let text = if a.json {
        let list: Vec<_> = rows
            .iter()
            .map(|r| json!({ "offset": r.offset, "fraction": r.fraction, "volume": r.volume, "litres": r.litres, "height": r.height, "converged": r.converged }))
            .collect();
        format!("{}\n", json!({ "unit": u, "perimeter": p.perimeter, "rows": list, "largest": largest, "tallest": tallest, "offsetFree": offset_free }))
    } else {
        let mut t = if offset_free { "one piece is a circle: the seam offset does not change the form, every row is the same solve\n".to_string() } else { String::new() };
        t += &format!("{:>4}  {:>12}  {:>6}  {:>14}  {:>10}  {:>10}\n", "#", format!("offset {u}"), "turn", format!("volume {u}³"), "litres", format!("height {u}"));
        for (i, r) in rows.iter().enumerate() {
            let mut marks = Vec::new();
            if largest == Some(i) {
                marks.push("largest");
            }
            if tallest == Some(i) {
                marks.push("tallest");
            }
            let values = if r.converged {
                format!("{:>14}  {:>10}  {:>10}", g(r.volume), g(r.litres), g(r.height))
            } else {
                format!("{:>38}", "not converged")
            };
            let mark = if marks.is_empty() { String::new() } else { format!("  ← {}", marks.join(", ")) };
            t += &format!("{i:>4}  {:>12}  {:>6.4}  {values}{mark}\n", g(r.offset), r.fraction);
        }
        t
    };
    print!("{text}");
    std::io::Write::flush(&mut std::io::stdout()).map_err(|e| format!("could not write stdout: {e}"))?;
    for path in &a.output {
        let title = format!("Volume and height along the seam ({n} offsets, perimeter {} {u})", g(p.perimeter));
        write(path, &plot::plot(&rows, u, &title))?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}

/// The `converged` line: yes, or what the approximate shape misses (`stats.shortfall`);
/// `resolution` is the one asked for (`None`: the core's default).
fn verdict(st: &StatsDto, resolution: Option<f64>) -> String {
    match (st.converged, st.shortfall.as_deref()) {
        (true, _) => "yes".into(),
        (false, Some("sampling")) => {
            let n = resolution.unwrap_or(dformer::simulate::options::DEFAULT_RESOLUTION as f64);
            format!(
                "no: an approximate shape; the outline turns too tightly for {} seam vertices, which alone force \
                 edges up to {}% off their flat lengths (0.1% allowed); try --resolution {}, or round that curve a little more",
                g(n), g(100.0 * st.strain_floor), g((2.0 * n).min(dformer::simulate::options::MAX_RESOLUTION as f64))
            )
        }
        (false, Some("fold")) => format!(
            "no: an approximate shape; the pieces keep their flat lengths, but one is creased by {}° inside it \
             (a shallower inward bay usually avoids it; rounding its corners does not)",
            g(st.max_bend.to_degrees().round())
        ),
        (false, Some("crossing")) => "no: an approximate shape; the pieces pass through each other".into(),
        (false, Some("unsettled")) => format!("no: an approximate shape; the solver stopped before it settled ({} steps)", st.iterations),
        (false, _) => "no: an approximate shape; the pieces would have to stretch (see strain)".into(),
    }
}
