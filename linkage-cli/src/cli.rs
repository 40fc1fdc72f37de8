//! The command line: the subcommands and their arguments.

use crate::table::Format;
use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

/// Planar mechanisms from their closure equations: a mechanism file
/// checked, analysed, swept, drawn, and promoted to Rust.
///
/// FILE is a mechanism file (TOML; see the guide's chapter on mechanism
/// files), or `-` for standard input. Results go to standard output (or
/// `--output`), messages to standard error.
///
/// Exit status: 0 done; 1 the mechanism file has mistakes; 2 the command
/// line is wrong; 3 the analysis failed (the mechanism does not assemble,
/// a singular pose, …); 4 a file could not be read or written.
#[derive(Debug, Parser)]
#[command(name = "linkage", version, about, long_about)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Reads a mechanism file and reports every mistake in it, or its sizes.
    Check(Input),
    /// Analyses one pose (the drivers at their `at`): coordinates and
    /// points with their velocities and accelerations.
    Analyze(Analysis),
    /// Drives the mechanism through its drive range: every pose, and the
    /// singular poses met.
    Sweep(Sweep),
    /// The extremes (and zeros) of quantities over the drive range.
    Extremes(Extremes),
    /// Draws the mechanism at its `at` pose, with the paths its points
    /// trace over the drive range (SVG).
    Draw(Draw),
    /// The Rust that makes the file a compiled mechanism: the attribute on
    /// a struct, and its parameters' values.
    Expand(Input),
}

/// The mechanism file.
#[derive(Debug, Args)]
pub struct Input {
    /// The mechanism file, or `-` for standard input.
    pub file: PathBuf,
    /// Write the result here instead of to standard output.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
}

/// How a table is written.
#[derive(Debug, Args)]
pub struct Output {
    /// `table` for a terminal, `csv` or `json` for programs.
    #[arg(short, long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

#[derive(Debug, Args)]
pub struct Analysis {
    #[command(flatten)]
    pub input: Input,
    #[command(flatten)]
    pub output: Output,
}

#[derive(Debug, Args)]
pub struct Sweep {
    #[command(flatten)]
    pub input: Input,
    #[command(flatten)]
    pub output: Output,
    /// The number of equal steps (poses: steps + 1); the file's by default.
    #[arg(long)]
    pub steps: Option<usize>,
    /// Include the points' positions, velocities and accelerations.
    #[arg(long)]
    pub points: bool,
}

#[derive(Debug, Args)]
pub struct Extremes {
    #[command(flatten)]
    pub input: Input,
    #[command(flatten)]
    pub output: Output,
    /// A quantity to watch: a coordinate (`theta4`) or a point's component
    /// (`C.x`), with `'` for its velocity and `''` for its acceleration
    /// (`C.x''`). Every coordinate of u when none is given.
    #[arg(short, long = "watch")]
    pub watches: Vec<String>,
    /// Also the quantities' zeros.
    #[arg(long)]
    pub zeros: bool,
}

#[derive(Debug, Args)]
pub struct Draw {
    #[command(flatten)]
    pub input: Input,
    /// The picture's width in pixels.
    #[arg(long, default_value_t = 800.0)]
    pub width: f64,
}
