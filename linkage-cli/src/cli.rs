//! The command line: the subcommands and their arguments.

use crate::table::Format;
use clap::{Args, Parser, Subcommand};
use linkage::tolerance::Tolerance;
use std::path::PathBuf;

/// Planar mechanisms from their closure equations: a mechanism file
/// checked, analysed, swept, differentiated by its dimensions, toleranced,
/// synthesized, drawn, and promoted to Rust.
///
/// FILE is a mechanism file (TOML; see the guide's chapter on mechanism
/// files) or a topology file (joints and links, whose equations are
/// generated), or `-` for standard input. Results go to standard output (or
/// `--output`), messages to standard error.
///
/// Exit status: 0 done; 1 the mechanism file (or a targets file) has mistakes; 2 the command
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
    /// Writes the mechanism file that a topology file (joints and links)
    /// generates: its closure equations, parameters, drive, assembly and
    /// drawing.
    Equations(Input),
    /// A topology file's mechanism for CAD, as DXF: its pose at `at` (each
    /// link an outline with pin holes, a layer each, the traced points'
    /// paths), or with `--cut-sheet` every moving link laid flat and
    /// labelled.
    Dxf(DxfArgs),
    /// Serves the page (a mechanism in the browser: `web/`, its engine
    /// built by `web/build.sh`) to this machine's browser, on the loopback
    /// interface only.
    Serve(ServeArgs),
    /// Reads a mechanism of another tool (a pyslvs expression, pylinkage's
    /// JSON) and writes it as a topology file.
    Import(ImportArgs),
    /// Writes a topology file in another tool's format (a pyslvs
    /// expression, pylinkage's JSON).
    Export(ExportArgs),
    /// Analyses one pose (the drivers at their `at`): coordinates and
    /// points with their velocities and accelerations.
    Analyze(Analysis),
    /// Drives the mechanism through its drive range: every pose, and the
    /// singular poses met.
    Sweep(Sweep),
    /// The extremes (and zeros) of quantities over the drive range.
    Extremes(Extremes),
    /// The derivatives of the pose at the drivers' `at` (coordinates and
    /// points, with their velocities and accelerations) by each parameter.
    Sensitivities(SensitivitiesArgs),
    /// How far tolerances on the parameters move quantities over the drive
    /// range: the worst case, the root-sum-square and σ where each is
    /// largest, with each parameter's share, and a Monte Carlo check.
    Tolerance(ToleranceArgs),
    /// Dimensions that make a point pass through targets, or a coordinate
    /// take values at given drivers: every design found, certified.
    Synthesize(SynthesizeArgs),
    /// Draws the mechanism at its `at` pose, with the paths its points
    /// trace over the drive range (SVG).
    Draw(Draw),
    /// The Rust that makes the file a compiled mechanism: the attribute on
    /// a struct, and its parameters' values (with `--expanded`, the code
    /// the attribute generates).
    Expand(ExpandArgs),
}

/// `dxf`'s arguments.
#[derive(Debug, Args)]
pub struct DxfArgs {
    #[command(flatten)]
    pub input: Input,
    /// Every moving link laid flat, labelled, for cutting.
    #[arg(long)]
    pub cut_sheet: bool,
    /// The links' width, in the file's length unit (default: a twentieth
    /// of the mechanism's size).
    #[arg(long)]
    pub width: Option<f64>,
    /// The pins' holes' diameter (default: two fifths of the width).
    #[arg(long)]
    pub hole: Option<f64>,
}

/// `serve`'s arguments.
#[derive(Debug, Args)]
pub struct ServeArgs {
    /// The page's folder.
    #[arg(default_value = "web")]
    pub dir: PathBuf,
    /// The port on 127.0.0.1 (0: any free one, printed).
    #[arg(long, default_value_t = 8000)]
    pub port: u16,
}

/// The formats of other tools.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum Peer {
    /// pyslvs's expression, `M[J[R, color[Green], P[0, 0], L[ground, L1]], …]`
    Pyslvs,
    /// pylinkage's JSON (`mechanism_to_dict`)
    Pylinkage,
}

/// `import`'s arguments.
#[derive(Debug, Args)]
pub struct ImportArgs {
    /// The format of the source.
    pub from: Peer,
    #[command(flatten)]
    pub input: Input,
    /// A pyslvs input: the joints BASE,DRIVE whose line's angle drives
    /// (as pyslvs's `(base, drive)`); once per input.
    #[arg(long = "input", value_parser = parse_pair)]
    pub inputs: Vec<(usize, usize)>,
    /// The mechanism's name (an identifier); pyslvs's expressions have none.
    #[arg(long, default_value = "Mechanism")]
    pub name: String,
}

/// `export`'s arguments.
#[derive(Debug, Args)]
pub struct ExportArgs {
    /// The format to write.
    pub to: Peer,
    #[command(flatten)]
    pub input: Input,
}

/// `3,4` as (3, 4).
fn parse_pair(text: &str) -> Result<(usize, usize), String> {
    let (a, b) = text
        .split_once(',')
        .ok_or_else(|| format!("`{text}` is not BASE,DRIVE (two joint numbers)"))?;
    let number = |t: &str| {
        t.trim()
            .parse::<usize>()
            .map_err(|_| format!("`{t}` is not a joint number"))
    };
    Ok((number(a)?, number(b)?))
}

/// `expand`'s arguments.
#[derive(Debug, Args)]
pub struct ExpandArgs {
    #[command(flatten)]
    pub input: Input,
    /// Write the code the attribute generates, expanded and formatted,
    /// instead of the attribute.
    #[arg(long)]
    pub expanded: bool,
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

#[derive(Debug, Args)]
pub struct SensitivitiesArgs {
    #[command(flatten)]
    pub input: Input,
    #[command(flatten)]
    pub output: Output,
    /// A parameter to differentiate by (repeat for more); every parameter
    /// the mechanism is differentiated by when none is given.
    #[arg(short, long = "param")]
    pub params: Vec<String>,
}

#[derive(Debug, Args)]
pub struct ToleranceArgs {
    #[command(flatten)]
    pub input: Input,
    #[command(flatten)]
    pub output: Output,
    /// A tolerance: `l2=0.05` is ±0.05 (uniform in a Monte Carlo run),
    /// `l2=normal:0.02` a normal spread of σ = 0.02; in the units the
    /// engine uses (lengths in the file's `length_unit`, angles in
    /// radians). The parameters not named are exact.
    #[arg(short, long = "tolerance", value_parser = parse_tolerance, required = true)]
    pub tolerances: Vec<(String, Tolerance)>,
    /// A quantity: a coordinate (`theta4`), a point's component (`C.x`),
    /// with `'` for its velocity and `''` for its acceleration, or a
    /// point's deviation normal to its path (`C.path`). Every coordinate
    /// of u when none is given.
    #[arg(short, long = "quantity")]
    pub quantities: Vec<String>,
    /// The number of equal steps of the drive range; the file's by default.
    #[arg(long)]
    pub steps: Option<usize>,
    /// Check the linear spreads with this many Monte Carlo samples.
    #[arg(long, default_value_t = 0)]
    pub samples: usize,
    /// The Monte Carlo run's random state (the same state, the same run).
    #[arg(long, default_value_t = 1)]
    pub random_state: u64,
}

/// A tolerance on the command line: `name=0.05` or `name=normal:0.02`.
fn parse_tolerance(text: &str) -> Result<(String, Tolerance), String> {
    let (name, value) = text.split_once('=').ok_or_else(|| {
        format!("`{text}`: write a tolerance as `name=0.05` or `name=normal:0.02`")
    })?;
    let (normal, number) = match value.strip_prefix("normal:") {
        Some(sigma) => (true, sigma),
        None => (false, value),
    };
    let size: f64 = number
        .trim()
        .parse()
        .map_err(|_| format!("`{text}`: `{number}` is not a number"))?;
    if !(size.is_finite() && size >= 0.0) {
        return Err(format!("`{text}`: a tolerance is a finite number ≥ 0"));
    }
    let tolerance = if normal {
        Tolerance::Normal(size)
    } else {
        Tolerance::Band(size)
    };
    Ok((name.trim().to_owned(), tolerance))
}

/// What a synthesis matches.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Timing {
    /// Whenever the mechanism can: the drivers at the targets are unknowns
    /// too (the targets' file has x, y).
    Free,
    /// At the drivers given with the targets (x, y after the driver).
    Prescribed,
    /// At the drivers given plus one offset the same for every target.
    Relative,
}

#[derive(Debug, Args)]
pub struct SynthesizeArgs {
    #[command(flatten)]
    pub input: Input,
    #[command(flatten)]
    pub output: Output,
    /// Path generation: the point that passes through the targets.
    #[arg(
        long,
        conflicts_with = "function",
        required_unless_present = "function"
    )]
    pub path: Option<String>,
    /// Function generation: the coordinate that takes the targets' values
    /// at their drivers.
    #[arg(long)]
    pub function: Option<String>,
    /// The targets, one per line, numbers separated by commas or spaces:
    /// `x, y` for a path with free timing, `driver, x, y` with prescribed
    /// or relative timing, `driver, value` for a function; `#` starts a
    /// comment.
    #[arg(long)]
    pub targets: PathBuf,
    /// When a path's point reaches its targets.
    #[arg(long, value_enum, default_value_t = Timing::Free)]
    pub timing: Timing,
    /// A parameter the synthesis chooses, within bounds: `l2=0.1:0.5`
    /// (repeat for more). The others keep the file's values.
    #[arg(long = "free", value_parser = parse_free, required = true)]
    pub free: Vec<(String, f64, f64)>,
    /// Stop at exactly as many targets as the free parameters can meet
    /// (precision points): the designs then pass through them, certified.
    #[arg(long)]
    pub precision_points: bool,
    /// The number of starts of the search.
    #[arg(long, default_value_t = 32)]
    pub starts: usize,
}

/// A free parameter on the command line: `name=lower:upper`.
fn parse_free(text: &str) -> Result<(String, f64, f64), String> {
    let shape =
        || format!("`{text}`: write a free parameter as `name=lower:upper`, e.g. `l2=0.1:0.5`");
    let (name, bounds) = text.split_once('=').ok_or_else(shape)?;
    let (lower, upper) = bounds.split_once(':').ok_or_else(shape)?;
    let number = |x: &str| {
        x.trim()
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| format!("`{text}`: `{x}` is not a finite number"))
    };
    let (lower, upper) = (number(lower)?, number(upper)?);
    if lower >= upper {
        return Err(format!("`{text}`: the lower bound must be below the upper"));
    }
    Ok((name.trim().to_owned(), lower, upper))
}
