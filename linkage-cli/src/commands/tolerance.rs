//! `linkage tolerance FILE -t l2=0.05 -t l3=normal:0.02 -q theta4 -q C.path`:
//! how far the tolerances move each quantity over the drive range — the
//! worst case, the root-sum-square and σ at the pose where the worst case
//! is largest, each parameter's share of it, and, with `--samples`, the σ
//! of a Monte Carlo run at that pose.

use crate::cli::ToleranceArgs;
use crate::failure::Failure;
use crate::load::{Loaded, load};
use crate::progress::Progress;
use crate::sizes::{self, PARAMETERS, SensitivityJob};
use crate::table::Table;
use linkage::mechanism::Fixed;
use linkage::prelude::*;
use linkage::quantity::{Written, written};
use linkage::tolerance::{self, MonteCarlo, Output, Tolerance, Tolerances};

struct Spread<'a> {
    loaded: &'a Loaded,
    args: &'a ToleranceArgs,
}

/// A quantity as a tolerance output.
fn output<const M: usize, const F: usize, const K: usize>(
    text: &str,
) -> Result<Output<'static, M, F, K>, Failure> {
    Ok(match written(text).map_err(Failure::Analysis)? {
        Written::Coordinate(name, of) => Output::coordinate(name, of),
        Written::Point(name, axis, of) => Output::point(name, axis, of),
        Written::Path(name) => Output::path(name),
    })
}

impl SensitivityJob for Spread<'_> {
    type Output = Table;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P, PARAMETERS>,
    ) -> Result<Table, Failure> {
        let args = self.args;
        let written: Vec<String> = if args.quantities.is_empty() {
            model.u_names().iter().map(|n| n.to_string()).collect()
        } else {
            args.quantities.clone()
        };
        let outputs = written
            .iter()
            .map(|text| output::<M, F, PARAMETERS>(text))
            .collect::<Result<Vec<_>, _>>()?;
        let given: Vec<(&str, Tolerance)> = (args.tolerances.iter())
            .map(|(n, t)| (n.as_str(), *t))
            .collect();
        let tolerances = Tolerances::by_name(&model.param_names(), &given)
            .map_err(|e| Failure::Analysis(e.to_string()))?;
        let steps = match args.steps {
            Some(steps) => steps,
            None => self.loaded.drives(&model)?.steps,
        };
        let swept = self.loaded.swept(&model, steps)?;
        let (start, drive, options) = (&swept.start, &swept.drive, &swept.options);
        let cycle = tolerance::cycle(&model, start, drive, options, &outputs, &tolerances)
            .map_err(|e| Failure::Analysis(e.to_string()))?;
        let samples = (args.samples > 0)
            .then(|| {
                let run = MonteCarlo {
                    samples: args.samples,
                    random_state: args.random_state,
                };
                let progress = Progress::new(args.samples as u64, "samples");
                let samples = tolerance::monte_carlo_cycle_observed(
                    &model,
                    start,
                    drive,
                    options,
                    &outputs,
                    &tolerances,
                    &run,
                    &|| progress.tick(),
                );
                progress.finish();
                samples.map_err(|e| Failure::Analysis(e.to_string()))
            })
            .transpose()?;
        if let Some(limit) = cycle.limit.as_ref().filter(|l| l.reaches_limit()) {
            eprintln!(
                "warning: within the tolerances the mechanism reaches a limit position \
                 (at {}): the linear spreads do not describe the band there{}",
                linkage::file::at_text(&model.v_names(), limit.v.as_slice()),
                if samples.is_some() {
                    ""
                } else {
                    "; check them with --samples"
                }
            );
        }
        let names = model.param_names();
        let chosen: Vec<usize> = (0..PARAMETERS).filter(|&j| !names[j].is_empty()).collect();
        let mut columns: Vec<(String, String)> = (model.v_names().iter())
            .map(|n| (format!("at {n}"), String::new()))
            .collect();
        for c in ["value", "worst case", "RSS", "σ"] {
            columns.push((c.into(), String::new()));
        }
        if samples.is_some() {
            columns.push(("σ (Monte Carlo)".into(), String::new()));
        }
        for &j in &chosen {
            columns.push((format!("share of {}", names[j]), String::new()));
        }
        let mut table = Table::new(
            format!(
                "{}: the largest spread of each quantity over the drive range",
                model.name()
            ),
            columns,
        );
        table.row_header = "quantity".into();
        for (o, (band, text)) in cycle.bands.iter().zip(&written).enumerate() {
            let Some((k, spread)) = band.largest() else {
                eprintln!("warning: `{text}` has no spread at any pose of the drive range");
                continue;
            };
            let mut row: Vec<f64> = band.v[k].iter().copied().collect();
            row.extend([band.value[k], spread.worst_case, spread.rss, spread.sigma]);
            if let Some(samples) = &samples {
                row.push(samples.statistics[o].get(k).map_or(f64::NAN, |s| s.std()));
            }
            let shares = band.gradient[k]
                .map(|g| tolerances.contributions(&g))
                .unwrap_or_else(SVector::zeros);
            row.extend(chosen.iter().map(|&j| shares[j]));
            table.push_named(text, row);
        }
        if let Some(samples) = samples.as_ref().filter(|s| !s.failures.is_empty()) {
            eprintln!(
                "note: {} of {} Monte Carlo samples do not run the drive range",
                samples.failures.len(),
                samples.samples
            );
        }
        Ok(table)
    }
}

pub fn run(args: &ToleranceArgs) -> Result<(), Failure> {
    let loaded = load(&args.input.file)?;
    let names: Vec<String> = args.tolerances.iter().map(|(n, _)| n.clone()).collect();
    let job = Spread {
        loaded: &loaded,
        args,
    };
    let table = sizes::run_sensitive(loaded.mechanism(), &names, job)?;
    let mut out = Vec::new();
    table
        .write(args.output.format, &mut out)
        .map_err(|e| Failure::Io(e.to_string()))?;
    super::emit(args.input.output.as_deref(), &out)
}
