//! `linkage extremes FILE -w C.x -w "theta4'"`: where quantities are
//! largest and smallest (and zero) over the drive range, located to
//! rounding between the sweep's poses.

use crate::cli::Extremes;
use crate::failure::Failure;
use crate::load::{Loaded, load};
use crate::sizes::{self, Job};
use crate::table::Table;
use linkage::mechanism::Fixed;
use linkage::prelude::*;
use linkage::quantity::{Written, written};
use linkage::watch::{FoundKind, Watch, locate};

/// A watch written on the command line (see [`quantity`]).
fn parse_watch<const M: usize, const F: usize>(text: &str) -> Result<Watch<'static, M, F>, String> {
    match written(text)? {
        Written::Coordinate(name, of) => Ok(Watch::coordinate(name, of)),
        Written::Point(name, axis, of) => Ok(Watch::point(name, axis, of)),
        Written::Path(_) => Err(format!(
            "`{text}`: a path's deviation is a quantity of `linkage tolerance`, not one to watch"
        )),
    }
}

struct Find<'a> {
    loaded: &'a Loaded,
    watches: &'a [String],
    zeros: bool,
}

impl Job for Find<'_> {
    type Output = Table;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<Table, Failure> {
        let written: Vec<String> = if self.watches.is_empty() {
            model.u_names().iter().map(|n| n.to_string()).collect()
        } else {
            self.watches.to_vec()
        };
        // Each watch, and the quantity as written that it watches.
        let mut watches = Vec::new();
        let mut watched: Vec<&str> = Vec::new();
        for text in &written {
            let finds: &[bool] = if self.zeros { &[true, false] } else { &[false] };
            for &zeros in finds {
                let watch = parse_watch::<M, F>(text).map_err(Failure::Analysis)?;
                watches.push(if zeros {
                    watch.zeros()
                } else {
                    watch.extrema()
                });
                watched.push(text);
            }
        }
        let steps = self.loaded.drives(&model)?.steps;
        let mut poses = Vec::new();
        let summary = self
            .loaded
            .sweep_each(&model, steps, &mut |_, pose| poses.push(*pose))?;
        let sweep = Sweep {
            poses,
            events: summary.events,
            complete: summary.complete,
        };
        let found = locate(&model, &sweep, &watches, &Options::default())
            .map_err(|e| Failure::Analysis(e.to_string()))?;
        let mut columns: Vec<(String, String)> = model
            .v_names()
            .iter()
            .map(|n| (n.to_string(), String::new()))
            .collect();
        columns.push(("value".into(), String::new()));
        let mut table = Table::new(
            format!("{}: extremes over the drive range", model.name()),
            columns,
        );
        table.row_header = "quantity: kind".into();
        for f in &found {
            let kind = match f.kind {
                FoundKind::Maximum => "maximum",
                FoundKind::Minimum => "minimum",
                FoundKind::Zero { rising: true } => "zero, rising",
                FoundKind::Zero { rising: false } => "zero, falling",
            };
            let name = watched.get(f.watch).copied().unwrap_or_default();
            let mut row: Vec<f64> = f.v.iter().copied().collect();
            row.push(f.value);
            table.push_named(&format!("{name}: {kind}"), row);
        }
        Ok(table)
    }
}

pub fn run(args: &Extremes) -> Result<(), Failure> {
    let loaded = load(&args.input.file)?;
    let job = Find {
        loaded: &loaded,
        watches: &args.watches,
        zeros: args.zeros,
    };
    let table = sizes::run(loaded.mechanism(), job)?;
    let mut out = Vec::new();
    table
        .write(args.output.format, &mut out)
        .map_err(|e| Failure::Io(e.to_string()))?;
    super::emit(args.input.output.as_deref(), &out)
}
