//! `dformer`: the D-former geometry core on the command line.
//!
//! - `dformer json` speaks the core's JSON API on stdin/stdout (the Inkscape extension's bridge).
//! - `dformer measure|normalize|connect FILE.svg` work on SVG files directly, for batch use.

mod batch;
mod laser;
mod protocol;
mod splice;
mod svgdoc;
mod units;

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
    /// normalize, connect, pathFromSvg, pathToSvg, DEFAULT_ACCURACY. Errors: {"error": message}
    /// and exit status 1.
    Json,
    /// Print the perimeter, area and drawing direction of each shape.
    Measure {
        #[command(flatten)]
        file: FileArgs,
        /// One JSON array instead of text lines.
        #[arg(long)]
        json: bool,
    },
    /// Scale the shapes (two or more) to one perimeter, in place.
    Normalize {
        #[command(flatten)]
        file: FileArgs,
        #[command(flatten)]
        out: OutArgs,
        /// largest, smallest, mean, first, or a length such as 300mm.
        #[arg(long, default_value = "largest")]
        target: String,
        /// center (bounding box) or centroid.
        #[arg(long, default_value = "center")]
        pivot: String,
    },
    /// Paired connectors on exactly two shapes of equal perimeter, on laser layers.
    Connect {
        #[command(flatten)]
        file: FileArgs,
        #[command(flatten)]
        out: OutArgs,
        /// stitch, teeth, leaves or hybrid.
        #[arg(long, default_value = "stitch")]
        kind: String,
        /// Number of connectors on each piece (give this or --pitch).
        #[arg(long)]
        count: Option<f64>,
        /// Distance between connectors along the edge, e.g. 12mm (rounded to divide the perimeter).
        #[arg(long)]
        pitch: Option<String>,
        /// Shift of every connector, as a fraction of the pitch (0 to 1).
        #[arg(long)]
        slide: Option<f64>,
        /// Connector 1 on each piece: distances along A and B from their first nodes.
        #[arg(long, num_args = 2, value_names = ["A", "B"])]
        start: Option<Vec<String>>,
        /// Edge to hole centre.
        #[arg(long)]
        inset: Option<String>,
        /// Hole diameter.
        #[arg(long)]
        diameter: Option<String>,
        /// Tooth or leaf length.
        #[arg(long)]
        length: Option<String>,
        /// Tooth flank angle in degrees (90 = square).
        #[arg(long)]
        angle: Option<f64>,
        /// Connectors on the other side of the edge.
        #[arg(long)]
        invert: bool,
        /// Laser kerf to compensate (cut width).
        #[arg(long)]
        kerf: Option<String>,
        /// Height of the engraved numbers (default 40% of the pitch).
        #[arg(long)]
        label_size: Option<String>,
        /// Do not engrave connector numbers.
        #[arg(long)]
        no_labels: bool,
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

fn run_svg(command: Command) -> Result<(), String> {
    match command {
        Command::Json => unreachable!("handled in main"),
        Command::Measure { file, json } => {
            let source = read_input(&file.input)?;
            let svg = svgdoc::SvgFile::parse(&source, file.unit.as_deref())?;
            print!("{}", batch::measure(&svg, &file.ids, json)?);
            Ok(())
        }
        Command::Normalize {
            file,
            out,
            target,
            pivot,
        } => {
            let source = read_input(&file.input)?;
            let svg = svgdoc::SvgFile::parse(&source, file.unit.as_deref())?;
            let (text, report) = batch::normalize(&source, &svg, &file.ids, &target, &pivot)?;
            write_output(&out, &text)?;
            eprint!("{report}");
            Ok(())
        }
        Command::Connect {
            file,
            out,
            kind,
            count,
            pitch,
            slide,
            start,
            inset,
            diameter,
            length,
            angle,
            invert,
            kerf,
            label_size,
            no_labels,
        } => {
            let source = read_input(&file.input)?;
            let svg = svgdoc::SvgFile::parse(&source, file.unit.as_deref())?;
            let args = batch::ConnectArgs {
                kind,
                count,
                pitch,
                slide,
                start: start.map(|v| [v[0].clone(), v[1].clone()]),
                inset,
                diameter,
                length,
                angle,
                invert,
                kerf,
                label_size,
                labels: !no_labels,
            };
            let (text, report) = batch::connect(&source, &svg, &file.ids, &args)?;
            write_output(&out, &text)?;
            eprint!("{report}");
            Ok(())
        }
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
