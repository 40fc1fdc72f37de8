//! `linkage sensitivities FILE [-p l2 -p l3]`: the derivatives of the pose
//! at the drivers' `at` by each parameter — of every coordinate and every
//! point, with their velocities and accelerations — the drivers' motion
//! held fixed.

use crate::cli::SensitivitiesArgs;
use crate::failure::Failure;
use crate::load::{Loaded, load};
use crate::sizes::{self, PARAMETERS, SensitivityJob};
use crate::table::Table;
use linkage::mechanism::Fixed;
use linkage::prelude::*;

struct Differentiate<'a> {
    loaded: &'a Loaded,
}

impl SensitivityJob for Differentiate<'_> {
    type Output = Table;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P, PARAMETERS>,
    ) -> Result<Table, Failure> {
        let (drives, pose) = self.loaded.analysed(&model)?;
        let s = model
            .sensitivities_of(&pose, &Options::default())
            .map_err(|e| Failure::Analysis(e.to_string()))?;
        // The chosen parameters' columns (those after them are zero).
        let names: Vec<&str> = model
            .param_names()
            .into_iter()
            .filter(|n| !n.is_empty())
            .collect();
        let columns = names.iter().map(|n| (format!("d/d{n}"), String::new()));
        let mut table = Table::new(
            format!(
                "{}: the derivatives by each parameter at {}",
                model.name(),
                linkage::file::at_text(&model.v_names(), drives.at.as_slice())
            ),
            columns.collect(),
        );
        table.row_header = "quantity".into();
        let primes = ["", "'", "''"];
        for (k, name) in model.u_names().iter().enumerate() {
            for (level, matrix) in [&s.u, &s.udot, &s.uddot].into_iter().enumerate() {
                let row = (0..names.len()).map(|j| matrix[(k, j)]).collect();
                table.push_named(&format!("{name}{}", primes[level]), row);
            }
        }
        let levels = [&s.points, &s.point_velocities, &s.point_accelerations];
        for (p, point) in model.point_names().iter().enumerate() {
            for (level, columns) in levels.iter().enumerate() {
                for (axis, c) in [("x", 0), ("y", 1)] {
                    let row = (0..names.len())
                        .map(|j| columns[j].as_ref()[p][c])
                        .collect();
                    table.push_named(&format!("{point}.{axis}{}", primes[level]), row);
                }
            }
        }
        Ok(table)
    }
}

pub fn run(args: &SensitivitiesArgs) -> Result<(), Failure> {
    let loaded = load(&args.input.file)?;
    let job = Differentiate { loaded: &loaded };
    let table = sizes::run_sensitive(loaded.mechanism(), &args.params, job)?;
    let mut out = Vec::new();
    table
        .write(args.output.format, &mut out)
        .map_err(|e| Failure::Io(e.to_string()))?;
    super::emit(args.input.output.as_deref(), &out)
}
