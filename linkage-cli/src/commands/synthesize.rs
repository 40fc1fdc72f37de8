//! `linkage synthesize FILE --path C --targets points.csv --free l2=0.1:0.5 …`:
//! the dimensions that make a point pass through targets (path
//! generation) or a coordinate take values at given drivers (function
//! generation), from random starts, every design certified over the
//! driver's range; the file's values are where the parameters not freed
//! stay.

use crate::cli::{SynthesizeArgs, Timing};
use crate::failure::Failure;
use crate::load::{Loaded, load};
use crate::progress::Progress;
use crate::sizes::{self, DesignJob, PARAMETERS};
use crate::table::Table;
use linkage::mechanism::Fixed;
use linkage::mechanism::design::{DesignTask, NoDesign, Targets, design};
use linkage::prelude::*;
use linkage::synthesis::{self, Search};
use std::path::Path;

/// The targets' lines: the numbers of each, with its line number.
fn targets(path: &Path, width: usize, what: &str) -> Result<Vec<Vec<f64>>, Failure> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| Failure::Io(format!("cannot read {}: {e}", path.display())))?;
    let mut rows = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let at = || format!("{}:{}", path.display(), k + 1);
        let numbers = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|x| !x.is_empty())
            .map(|x| {
                x.parse::<f64>()
                    .ok()
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| {
                        Failure::Malformed(format!("{}: `{x}` is not a finite number", at()))
                    })
            })
            .collect::<Result<Vec<f64>, Failure>>()?;
        if numbers.len() != width {
            return Err(Failure::Malformed(format!(
                "{}: {} numbers; a target here is {width} ({what})",
                at(),
                numbers.len()
            )));
        }
        rows.push(numbers);
    }
    if rows.is_empty() {
        return Err(Failure::Malformed(format!(
            "{}: no targets ({what} on each line)",
            path.display()
        )));
    }
    Ok(rows)
}

struct Design<'a> {
    loaded: &'a Loaded,
    args: &'a SynthesizeArgs,
}

impl DesignJob for Design<'_> {
    type Output = Table;
    type Error = Failure;
    fn run<const M: usize, const P: usize>(
        self,
        model: Fixed<M, 1, P, PARAMETERS>,
    ) -> Result<Table, Failure> {
        let args = self.args;
        let drives = self.loaded.drives(&model)?;
        let guess = self.loaded.assembled(&model, &drives.at)?;
        let failed = |e: synthesis::SynthesisError| Failure::Analysis(e.to_string());
        let targets = if let Some(point) = &args.path {
            let (rows, timing) = match args.timing {
                Timing::Free => (targets(&args.targets, 2, "x, y")?, synthesis::Timing::Free),
                Timing::Prescribed | Timing::Relative => {
                    let rows = targets(&args.targets, 3, "driver, x, y")?;
                    let drivers = rows.iter().map(|r| r[0]).collect();
                    let timing = if args.timing == Timing::Prescribed {
                        synthesis::Timing::Prescribed(drivers)
                    } else {
                        synthesis::Timing::Relative(drivers)
                    };
                    (rows.iter().map(|r| r[1..].to_vec()).collect(), timing)
                }
            };
            let points = rows.iter().map(|r: &Vec<f64>| [r[0], r[1]]).collect();
            Targets::Path {
                point: point.clone(),
                points,
                timing,
            }
        } else {
            let coordinate = args.function.clone().unwrap_or_default();
            let rows = targets(&args.targets, 2, "driver, value")?;
            let pairs = rows.iter().map(|r| (r[0], r[1])).collect();
            Targets::Function { coordinate, pairs }
        };
        let task = DesignTask {
            targets,
            free: args.free.clone(),
            precision_points: args.precision_points,
            min_transmission: None,
        };
        let search = Search {
            starts: args.starts,
            ..Search::default()
        };
        let progress = Progress::new(args.starts as u64, "starts");
        let found = design(
            &model,
            Some(guess),
            &task,
            &search,
            &|| progress.tick(),
            &|| false,
        );
        progress.finish();
        let found = found.map_err(failed)?;
        if let Some(none) = NoDesign::of(&found) {
            return Err(Failure::Analysis(none.to_string()));
        }
        let names = model.parameter_names();
        let mut columns: Vec<(String, String)> = names
            .iter()
            .map(|n| (n.to_string(), String::new()))
            .collect();
        for c in [
            "RMS error",
            "largest error",
            "certified from",
            "certified to",
            "transmission",
        ] {
            columns.push((c.into(), String::new()));
        }
        let mut table = Table::new(
            format!(
                "{}: {} certified from {} starts",
                model.name(),
                match found.designs.len() {
                    1 => "1 design".to_owned(),
                    n => format!("{n} designs"),
                },
                found.starts
            ),
            columns,
        );
        table.row_header = "design".into();
        for (k, design) in found.designs.iter().enumerate() {
            let mut row = design.model.parameters().to_vec();
            let certificate = design.certificate.as_ref();
            row.extend([
                design.rms_error,
                design.largest_error().1,
                certificate.map_or(f64::NAN, |c| c.from),
                certificate.map_or(f64::NAN, |c| c.to),
                certificate.map_or(f64::NAN, |c| c.transmission),
            ]);
            table.push_named(&(k + 1).to_string(), row);
        }
        Ok(table)
    }
}

pub fn run(args: &SynthesizeArgs) -> Result<(), Failure> {
    let loaded = load(&args.input.file)?;
    let free: Vec<&str> = args.free.iter().map(|(n, _, _)| n.as_str()).collect();
    let job = Design {
        loaded: &loaded,
        args,
    };
    let table = sizes::run_design(loaded.mechanism(), &free, job)?;
    let mut out = Vec::new();
    table
        .write(args.output.format, &mut out)
        .map_err(|e| Failure::Io(e.to_string()))?;
    super::emit(args.input.output.as_deref(), &out)
}
