//! What a loaded file's drive asks of its mechanism, seen at its sizes:
//! the drive as vectors, the assembly the file picks, the analysis at the
//! drivers' `at` and the sweep over their range — failures located at the
//! drive's place in the file.

use super::{Cause, LoadError, Loaded};
use crate::assembly::{Assemble, Pick};
use crate::mechanism::{Diagnostic, Fixed};
use crate::{Analysis, Drive, Kernels, Linkage, Options, SweepOptions, SweepPose, SweepSummary};
use nalgebra::SVector;

/// The file's drive at the mechanism's sizes: each driving coordinate's
/// `at`, `from`, `to`, rate and acceleration, and the steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FixedDrives<const F: usize> {
    pub at: SVector<f64, F>,
    pub from: SVector<f64, F>,
    pub to: SVector<f64, F>,
    pub rate: SVector<f64, F>,
    pub acceleration: SVector<f64, F>,
    pub steps: usize,
}

/// The sweep over the file's drive range: where it starts (the file's
/// assembly at `at`, carried to `from`), the drive, and the options (the
/// drivers' speed along it).
#[derive(Clone, Debug)]
pub struct Swept<const M: usize, const F: usize> {
    pub start: SVector<f64, M>,
    pub drive: Drive<F>,
    pub options: SweepOptions,
}

/// The analysis of a pose of `Fixed<M, F, N, K>`.
pub type FixedAnalysis<const M: usize, const F: usize, const N: usize, const K: usize> =
    Analysis<M, F, <Fixed<M, F, N, K> as Kernels<M, F>>::Points>;

impl Loaded {
    /// The file's drive for `model`: a driving coordinate without its
    /// `[drive.<name>]` table is a mistake in the file.
    pub fn drives<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
    ) -> Result<FixedDrives<F>, LoadError> {
        let drives = (self.file)
            .drives(&model.v_names())
            .map_err(|missing| LoadError::Mistakes(self.located(missing)))?;
        let vector = |values: &[f64]| SVector::<f64, F>::from_fn(|k, _| values[k]);
        Ok(FixedDrives {
            at: vector(&drives.at),
            from: vector(&drives.from),
            to: vector(&drives.to),
            rate: vector(&drives.rate),
            acceleration: vector(&drives.acceleration),
            steps: drives.steps,
        })
    }

    /// The assembly the file picks (its `[assembly]`, or the first mode
    /// found) with the drivers at `at`.
    pub fn assembled<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
        at: &SVector<f64, F>,
    ) -> Result<SVector<f64, M>, LoadError> {
        let pick = match &self.file.assembly {
            None => Pick::Index(0),
            Some(choice) => choice
                .pick::<M>(&model.u_names())
                .map_err(|mistake| LoadError::Mistakes(self.located(mistake.into())))?,
        };
        model.assemble(at, &pick).map(|mode| mode.u).map_err(|e| {
            let mut why = format!(
                "the mechanism does not assemble at the drivers' `at` ({}): {e}",
                at_text(&model.v_names(), at.as_slice())
            );
            // Of a topology, the loop its given lengths open most, as drawn.
            if let Some(topology) = &self.topology
                && let Ok(gaps) = topology.sketch_gaps()
                && let Some((joint, gap)) = gaps.first()
                && *gap > 0.0
            {
                why += &format!(
                    "; as drawn, with the lengths given, the loop closing at joint `{joint}` misses by {gap:.4} {}",
                    self.file.length_unit
                );
            }
            self.at_the_drive(&model.v_names(), Cause::Assembly(e), why)
        })
    }

    /// The file's drive, and the analysis of the pose at its `at` (from
    /// the file's assembly, at the drivers' rates and accelerations).
    pub fn analysed<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
    ) -> Result<(FixedDrives<F>, FixedAnalysis<M, F, N, K>), LoadError> {
        self.analysed_at(model, None)
    }

    /// [`Loaded::analysed`] with the drivers at `v` (`None`: at `at`):
    /// the file's assembly there, at the drivers' rates and accelerations
    /// (what the page shows as its driver moves).
    pub fn analysed_at<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
        v: Option<SVector<f64, F>>,
    ) -> Result<(FixedDrives<F>, FixedAnalysis<M, F, N, K>), LoadError> {
        let drives = self.drives(model)?;
        let v = v.unwrap_or(drives.at);
        let u = self.assembled(model, &v)?;
        let pose = model
            .analyze(
                &u,
                &v,
                &drives.rate,
                &drives.acceleration,
                &Options::default(),
            )
            .map_err(LoadError::analysis)?;
        Ok((drives, pose))
    }

    /// The file's sweep for `model` in `steps` steps.
    pub fn swept<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
        steps: usize,
    ) -> Result<Swept<M, F>, LoadError> {
        let drives = self.drives(model)?;
        let u_at = self.assembled(model, &drives.at)?;
        let mut options = SweepOptions::default();
        if F == 1 {
            options.speed = drives.rate[0];
        }
        let start = if drives.at == drives.from {
            u_at
        } else {
            let back = Drive::Line {
                from: drives.at,
                to: drives.from,
                steps: 100,
            };
            let carried = model.sweep(&u_at, &back, &options).map_err(|e| {
                let why = format!("from `at` back to `from`: {e}");
                self.at_the_drive(&model.v_names(), Cause::Analysis(e), why)
            })?;
            if !carried.complete {
                let why =
                    "the assembly at `at` does not reach `from` (a limit position between them)";
                return Err(self.at_the_drive(
                    &model.v_names(),
                    Cause::LimitBeforeStart,
                    why.to_owned(),
                ));
            }
            carried.poses.last().map_or(u_at, |p| p.u)
        };
        let drive = Drive::Line {
            from: drives.from,
            to: drives.to,
            steps,
        };
        Ok(Swept {
            start,
            drive,
            options,
        })
    }

    /// The poses of the file's sweep ([`Loaded::swept`]), each given to
    /// `on_pose` with its index.
    pub fn sweep_each<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
        steps: usize,
        on_pose: &mut dyn FnMut(usize, &SweepPose<M, F>),
    ) -> Result<SweepSummary<M, F>, LoadError> {
        let Swept {
            start,
            drive,
            options,
        } = self.swept(model, steps)?;
        let mut index = 0;
        model
            .sweep_each(&start, &drive, &options, |pose| {
                on_pose(index, pose);
                index += 1;
            })
            .map_err(LoadError::analysis)
    }

    /// A failure of the analysis at the drivers' `at`, located at the
    /// first driver's `at` (its `from`, if `at` is not written), the
    /// others' labelled.
    fn at_the_drive(&self, names: &[&str], cause: Cause, why: String) -> LoadError {
        let places: Vec<std::ops::Range<usize>> = (names.iter())
            .filter_map(|name| self.file.driver(name))
            .filter_map(|d| d.at.span.clone().or_else(|| d.from.span.clone()))
            .collect();
        let located = places.split_first().map(|(first, others)| {
            let mut diagnostic = Diagnostic::error(why.clone(), Some(first.clone()));
            for place in others {
                diagnostic = diagnostic.with_label(place.clone(), "the drive");
            }
            Box::new(self.located(diagnostic.into()))
        });
        LoadError::Analysis {
            cause,
            why,
            located,
        }
    }
}

/// `theta2 = 0.349066`: driving coordinates and their values, for
/// messages.
pub fn at_text(names: &[&str], v: &[f64]) -> String {
    let parts: Vec<String> = names
        .iter()
        .zip(v)
        .map(|(n, x)| format!("{n} = {x}"))
        .collect();
    parts.join(", ")
}
