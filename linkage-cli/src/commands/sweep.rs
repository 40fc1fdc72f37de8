//! `linkage sweep FILE`: every pose over the drive range, with a progress
//! bar on a terminal; the singular poses met are reported on standard
//! error.

use crate::cli::Sweep;
use crate::failure::Failure;
use crate::load::{Loaded, load};
use crate::progress::Progress;
use crate::sizes::{self, Job};
use crate::table::Table;
use linkage::mechanism::Fixed;
use linkage::prelude::*;

struct Poses<'a> {
    loaded: &'a Loaded,
    steps: Option<usize>,
    points: bool,
}

impl Job for Poses<'_> {
    type Output = Table;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<Table, Failure> {
        let unit = self.loaded.file().length_unit.clone();
        let mut columns: Vec<(String, String)> = Vec::new();
        for name in model.v_names() {
            columns.push((name.into(), String::new()));
        }
        for suffix in ["", "'", "''"] {
            for name in model.u_names() {
                columns.push((format!("{name}{suffix}"), String::new()));
            }
        }
        if self.points {
            for suffix in ["", "'", "''"] {
                for name in model.point_names() {
                    for axis in ["x", "y"] {
                        columns.push((format!("{name}.{axis}{suffix}"), unit.clone()));
                    }
                }
            }
        }
        let mut table = Table::new(format!("{}: a sweep", model.name()), columns);
        let steps = match self.steps {
            Some(steps) => steps,
            None => self.loaded.drives(&model)?.steps,
        };
        let progress = Progress::new(steps as u64 + 1, "poses");
        let summary = self.loaded.sweep_each(&model, steps, &mut |_, pose| {
            let mut row: Vec<f64> = pose.v.iter().copied().collect();
            row.extend(pose.u.iter().chain(&pose.udot).chain(&pose.uddot));
            if self.points {
                let p = model.point_positions(&pose.u, &pose.v);
                let pv = model.point_velocities(&pose.u, &pose.v, &pose.udot, &pose.vdot);
                let pa = model.point_accelerations(
                    &pose.u,
                    &pose.v,
                    &pose.udot,
                    &pose.vdot,
                    &pose.uddot,
                    &SVector::zeros(),
                );
                for set in [p.as_ref(), pv.as_ref(), pa.as_ref()] {
                    row.extend(set.iter().flat_map(|q| [q.x, q.y]));
                }
            }
            table.push(row);
            progress.tick();
        })?;
        progress.finish();
        for event in &summary.events {
            eprintln!(
                "note: {:?} at {}",
                event.kind,
                linkage::file::at_text(&model.v_names(), event.v.as_slice())
            );
        }
        if !summary.complete {
            eprintln!("note: the sweep stopped before the end of the drive range");
        }
        Ok(table)
    }
}

pub fn run(args: &Sweep) -> Result<(), Failure> {
    let loaded = load(&args.input.file)?;
    if args.steps == Some(0) {
        return Err(Failure::Analysis("`--steps` must be at least 1".into()));
    }
    let job = Poses {
        loaded: &loaded,
        steps: args.steps,
        points: args.points,
    };
    let table = sizes::run(loaded.mechanism(), job)?;
    let mut out = Vec::new();
    table
        .write(args.output.format, &mut out)
        .map_err(|e| Failure::Io(e.to_string()))?;
    super::emit(args.input.output.as_deref(), &out)
}
