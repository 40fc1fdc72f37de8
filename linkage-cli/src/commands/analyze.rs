//! `linkage analyze FILE`: the pose at the drivers' `at`, with velocities
//! and accelerations at their rates.

use crate::cli::Analysis;
use crate::failure::Failure;
use crate::load::{Loaded, load};
use crate::sizes::{self, Job};
use crate::table::Table;
use linkage::file::at_text;
use linkage::mechanism::Fixed;
use linkage::prelude::*;

struct Analyze<'a> {
    loaded: &'a Loaded,
}

impl Job for Analyze<'_> {
    type Output = Table;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<Table, Failure> {
        let (drives, pose) = self.loaded.analysed(&model)?;
        let unit = &self.loaded.file().length_unit;
        let mut table = Table::new(
            format!(
                "{} at {}",
                model.name(),
                at_text(&model.v_names(), drives.at.as_slice())
            ),
            vec![
                ("value".into(), String::new()),
                ("velocity".into(), "/s".into()),
                ("acceleration".into(), "/s²".into()),
            ],
        );
        table.row_header = "quantity".into();
        for (k, name) in model.u_names().iter().enumerate() {
            table.push_named(name, vec![pose.u[k], pose.udot[k], pose.uddot[k]]);
        }
        for (k, name) in model.v_names().iter().enumerate() {
            table.push_named(
                name,
                vec![drives.at[k], drives.rate[k], drives.acceleration[k]],
            );
        }
        let (p, pv, pa) = (
            pose.points.as_ref(),
            pose.point_velocities.as_ref(),
            pose.point_accelerations.as_ref(),
        );
        for (k, name) in model.point_names().iter().enumerate() {
            for (axis, c) in [("x", 0), ("y", 1)] {
                table.push_named(
                    &format!("{name}.{axis} [{unit}]"),
                    vec![p[k][c], pv[k][c], pa[k][c]],
                );
            }
        }
        Ok(table)
    }
}

pub fn run(args: &Analysis) -> Result<(), Failure> {
    let loaded = load(&args.input.file)?;
    let table = sizes::run(loaded.mechanism(), Analyze { loaded: &loaded })?;
    let mut out = Vec::new();
    table
        .write(args.output.format, &mut out)
        .map_err(|e| Failure::Io(e.to_string()))?;
    super::emit(args.input.output.as_deref(), &out)
}
