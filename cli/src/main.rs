//! `dformer`: the D-former geometry core on the command line.
//!
//! - `dformer json` speaks the core's JSON API on stdin/stdout (the Inkscape extension's bridge).
//! - `dformer measure|normalize|connect FILE.svg` work on SVG files directly, for batch use.
//! - `dformer form FILE.svg` solves the 3D form (figures, mesh, picture, sweep of the seam offset).

mod advice;
mod batch;
mod form;
mod laser;
mod meshfile;
mod plot;
mod protocol;
mod render;
mod splice;
mod svgdoc;
mod units;
mod viewport;

use clap::{Args, Parser, Subcommand};
use std::io::{Read, Write};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "dformer",
    version,
    about = "D-former: equal perimeters and paired connectors for D-forms"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// What every SVG command shares.
#[derive(Args)]
struct FileArgs {
    /// Input SVG file ("-" for stdin).
    input: PathBuf,
    /// Shapes to use, by id, in order (repeatable). Default: every shape in the file.
    #[arg(long = "id")]
    ids: Vec<String>,
    /// Use the N largest closed shapes (longest perimeters, kept in file order), e.g.
    /// `--largest 2` for connect, instead of naming them with --id.
    #[arg(long, value_name = "N")]
    largest: Option<usize>,
    /// Unit of lengths shown and of bare numbers in options: mm, cm, in, pt, pc, px.
    /// Default: the document's display unit (Inkscape's document-units, else the unit of width).
    #[arg(long)]
    unit: Option<String>,
}

#[derive(Args)]
struct OutArgs {
    /// Output SVG file ("-" or absent: stdout).
    #[arg(short, long)]
    output: Option<PathBuf>,
}

#[derive(Subcommand)]
enum Command {
    /// Read one JSON request (or an array of them) on stdin, write the answer on stdout.
    /// A request is {"op": NAME, ...arguments by their JS names}; operations: measure,
    /// normalize, connect, simulate, formFigures, placeOnForm, pathFromSvg, pathToSvg,
    /// DEFAULT_ACCURACY. Errors: {"error": message}
    /// and exit status 1.
    Json,
    /// Print the perimeter, area and drawing direction of each closed shape; what cannot be a
    /// piece (open paths, text, images…) is listed with why on stderr.
    Measure {
        #[command(flatten)]
        file: FileArgs,
        /// One JSON array instead of text lines.
        #[arg(long)]
        json: bool,
    },
    /// Scale the shapes (two or more, or one with --target LENGTH) to one perimeter, in place.
    Normalize {
        #[command(flatten)]
        file: FileArgs,
        #[command(flatten)]
        out: OutArgs,
        /// largest, smallest, mean, first, or a length such as 300mm.
        #[arg(long, default_value = "largest")]
        target: String,
        /// center (bounding box), centroid, or start (each shape's first node stays in place).
        #[arg(long, default_value = "center")]
        pivot: String,
    },
    /// Paired connectors on exactly two shapes of equal perimeter, on laser layers.
    Connect {
        #[command(flatten)]
        file: FileArgs,
        #[command(flatten)]
        out: OutArgs,
        #[command(flatten)]
        connect: batch::ConnectArgs,
    },
    /// The 3D D-form of exactly two shapes of equal perimeter: volume, litres, concrete mass,
    /// area, height/width/depth, strain; -o writes .stl/.obj (mm) or .svg (a picture).
    Form {
        #[command(flatten)]
        file: FileArgs,
        #[command(flatten)]
        form: form::FormArgs,
    },
}

fn run_json() -> ExitCode {
    let mut text = String::new();
    if let Err(e) = std::io::stdin().read_to_string(&mut text) {
        println!(
            "{}",
            serde_json::json!({ "error": format!("could not read stdin: {e}") })
        );
        return ExitCode::FAILURE;
    }
    let (answer, ok) = protocol::answer_text(&text);
    let mut stdout = std::io::stdout().lock();
    if writeln!(stdout, "{answer}").is_err() {
        return ExitCode::FAILURE;
    }
    if ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}

fn read_input(path: &PathBuf) -> Result<String, String> {
    if path.as_os_str() == "-" {
        let mut text = String::new();
        std::io::stdin()
            .read_to_string(&mut text)
            .map_err(|e| format!("could not read stdin: {e}"))?;
        Ok(text)
    } else {
        std::fs::read_to_string(path).map_err(|e| format!("could not read {}: {e}", path.display()))
    }
}

fn write_output(out: &OutArgs, text: &str) -> Result<(), String> {
    match &out.output {
        Some(p) if p.as_os_str() != "-" => {
            std::fs::write(p, text).map_err(|e| format!("could not write {}: {e}", p.display()))
        }
        _ => std::io::stdout()
            .write_all(text.as_bytes())
            .map_err(|e| format!("could not write stdout: {e}")),
    }
}

impl FileArgs {
    fn choice(&self) -> batch::Choice<'_> {
        batch::Choice { ids: &self.ids, largest: self.largest }
    }
}

/// Reads and parses the input SVG, then runs `f` on its text and the parsed document.
fn with_svg<T>(
    file: &FileArgs,
    f: impl FnOnce(&str, &svgdoc::SvgFile<'_>) -> Result<T, String>,
) -> Result<T, String> {
    let source = read_input(&file.input)?;
    let svg = svgdoc::SvgFile::parse(&source, file.unit.as_deref())?;
    f(&source, &svg)
}

/// Writes the edited SVG and prints the report on stderr.
fn finish(out: &OutArgs, (text, report): (String, String)) -> Result<(), String> {
    write_output(out, &text)?;
    eprint!("{report}");
    Ok(())
}

fn run_svg(command: Command) -> Result<(), String> {
    match command {
        Command::Json => unreachable!("handled in main"),
        Command::Measure { file, json } => {
            let (table, skipped) = with_svg(&file, |_, svg| batch::measure(svg, file.choice(), json))?;
            print!("{table}");
            eprint!("{skipped}");
            Ok(())
        }
        Command::Normalize {
            file,
            out,
            target,
            pivot,
        } => finish(
            &out,
            with_svg(&file, |source, svg| {
                batch::normalize(source, svg, file.choice(), &target, &pivot)
            })?,
        ),
        Command::Form { file, form } => with_svg(&file, |_, svg| form::run(svg, &file.ids, &form)),
        Command::Connect { file, out, connect } => finish(
            &out,
            with_svg(&file, |source, svg| {
                batch::connect(source, svg, file.choice(), &connect)
            })?,
        ),
    }
}

fn main() -> ExitCode {
    match Cli::parse().command {
        Command::Json => run_json(),
        other => match run_svg(other) {
            Ok(()) => ExitCode::SUCCESS,
            Err(message) => {
                eprintln!("dformer: {message}");
                ExitCode::FAILURE
            }
        },
    }
}
