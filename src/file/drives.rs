//! The drive of a mechanism, in the order of its driving coordinates: each
//! coordinate's driver found in the file, or the mistake of one without
//! its table.

use super::MechanismFile;
use super::drive::{DEFAULT_STEPS, Driver};
use crate::mechanism::{Diagnostic, Diagnostics};

/// The drive of every driving coordinate, in the order of v (in the
/// engine's units).
#[derive(Clone, Debug, PartialEq)]
pub struct Drives {
    /// The pose one analysis takes.
    pub at: Vec<f64>,
    /// Where a sweep starts.
    pub from: Vec<f64>,
    /// Where a sweep ends.
    pub to: Vec<f64>,
    /// v̇.
    pub rate: Vec<f64>,
    /// v̈.
    pub acceleration: Vec<f64>,
    /// The equal steps of a sweep (the drivers share it).
    pub steps: usize,
}

impl MechanismFile {
    /// The drive of the coordinates `v_names` (a mechanism's v, in order):
    /// a coordinate without its `[drive.<name>]` table is a mistake,
    /// located at the mechanism's name, one for each.
    ///
    /// ```
    /// use linkage::file::MechanismFile;
    ///
    /// let text = "name = \"Bar\"\nequations = 'u = [x], v = [t, s], closure = [x - t - s],'\n\
    ///             [drive.t]\nfrom = 0\nto = 2\nsteps = 4\n";
    /// let file = MechanismFile::parse(text).unwrap();
    /// let mistakes = file.drives(&["t", "s"]).unwrap_err();
    /// assert!(mistakes.render("bar.toml", text, false).contains("`s` is a driving coordinate"));
    /// let drives = file.drives(&["t"]).unwrap();
    /// assert_eq!((drives.to, drives.steps), (vec![2.0], 4));
    /// ```
    pub fn drives(&self, v_names: &[&str]) -> Result<Drives, Diagnostics> {
        let mut missing = Diagnostics::new();
        for name in v_names {
            if self.driver(name).is_none() {
                missing.push(Diagnostic::error(
                    format!(
                        "`{name}` is a driving coordinate without its table `[drive.{name}]`: give its `from` and `to`"
                    ),
                    Some(self.name.span.clone()),
                ));
            }
        }
        if !missing.is_empty() {
            return Err(missing);
        }
        let of = |f: &dyn Fn(&Driver) -> f64| -> Vec<f64> {
            (v_names.iter())
                .map(|n| self.driver(n).map_or(0.0, f))
                .collect()
        };
        let steps = (v_names.iter())
            .filter_map(|n| self.driver(n))
            .map(|d| d.steps)
            .max()
            .unwrap_or(DEFAULT_STEPS);
        Ok(Drives {
            at: of(&|d| d.at.value),
            from: of(&|d| d.from.value),
            to: of(&|d| d.to.value),
            rate: of(&|d| d.rate.value),
            acceleration: of(&|d| d.acceleration.value),
            steps,
        })
    }
}
