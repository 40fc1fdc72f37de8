//! The subcommands, one per file, and what they share: the drive the file
//! says, the assembly it starts from, and where the result goes.

pub mod analyze;
pub mod check;
pub mod draw;
pub mod dxf;
pub mod equations;
pub mod expand;
pub mod export;
pub mod extremes;
pub mod import;
pub mod sensitivities;
pub mod sweep;
pub mod synthesize;
pub mod tolerance;

use crate::failure::Failure;
use crate::load::{Loaded, report};
use linkage::mechanism::{Diagnostic, Fixed};
use linkage::prelude::*;
use std::io::Write;
use std::path::Path;

/// The file's drive at the mechanism's sizes: each driving coordinate's
/// `at`, `from`, `to`, rate and acceleration, and the steps.
pub struct Drives<const F: usize> {
    pub at: SVector<f64, F>,
    pub from: SVector<f64, F>,
    pub to: SVector<f64, F>,
    pub rate: SVector<f64, F>,
    pub acceleration: SVector<f64, F>,
    pub steps: usize,
}

/// The drive of `loaded` for `model`: a driving coordinate without its
/// `[drive.<name>]` table is a mistake in the file.
pub fn drives<const M: usize, const F: usize, const K: usize>(
    loaded: &Loaded,
    model: &Fixed<M, F, 32, K>,
) -> Result<Drives<F>, Failure> {
    let drives = (loaded.file).drives(&model.v_names()).map_err(|missing| {
        report(&missing, &loaded.shown, &loaded.text);
        Failure::Mistakes
    })?;
    let vector = |values: &[f64]| SVector::<f64, F>::from_fn(|k, _| values[k]);
    Ok(Drives {
        at: vector(&drives.at),
        from: vector(&drives.from),
        to: vector(&drives.to),
        rate: vector(&drives.rate),
        acceleration: vector(&drives.acceleration),
        steps: drives.steps,
    })
}

/// The assembly the file picks at the drivers' `at`.
pub fn assembled<const M: usize, const F: usize, const K: usize>(
    loaded: &Loaded,
    model: &Fixed<M, F, 32, K>,
    at: &SVector<f64, F>,
) -> Result<SVector<f64, M>, Failure> {
    use linkage::assembly::{Assemble, Pick};
    let pick = match &loaded.file.assembly {
        None => Pick::Index(0),
        Some(choice) => match choice.pick::<M>(&model.u_names()) {
            Ok(pick) => pick,
            Err(mistake) => {
                report(&mistake.into(), &loaded.shown, &loaded.text);
                return Err(Failure::Mistakes);
            }
        },
    };
    model.assemble(at, &pick).map(|mode| mode.u).map_err(|e| {
        let mut why = format!(
            "the mechanism does not assemble at the drivers' `at` ({}): {e}",
            analyze::at_text(&model.v_names(), at.as_slice())
        );
        // Of a topology, the loop its given lengths open most, as drawn.
        if let Some(topology) = &loaded.topology
            && let Ok(gaps) = topology.sketch_gaps()
            && let Some((joint, gap)) = gaps.first()
            && *gap > 0.0
        {
            why += &format!(
                "; as drawn, with the lengths given, the loop closing at joint `{joint}` misses by {gap:.4} {}",
                loaded.file.length_unit
            );
        }
        at_the_drive(loaded, &model.v_names(), why, "the drive")
    })
}

/// A failure of the analysis at the drivers' `at`, written to standard
/// error located at the first driver's `at` (its `from`, if `at` is not
/// written), the others' labelled.
fn at_the_drive(loaded: &Loaded, names: &[&str], why: String, label: &str) -> Failure {
    let places: Vec<std::ops::Range<usize>> = (names.iter())
        .filter_map(|name| loaded.file.driver(name))
        .filter_map(|d| d.at.span.clone().or_else(|| d.from.span.clone()))
        .collect();
    let Some((first, others)) = places.split_first() else {
        return Failure::Analysis(why);
    };
    let mut diagnostic = Diagnostic::error(why, Some(first.clone()));
    for place in others {
        diagnostic = diagnostic.with_label(place.clone(), label);
    }
    report(&diagnostic.into(), &loaded.shown, &loaded.text);
    Failure::AnalysisAt
}

/// The file's drive, and the analysis of the pose at its `at` (from the
/// file's assembly, at the drivers' rates and accelerations).
#[allow(clippy::type_complexity)]
pub fn analysed<const M: usize, const F: usize, const K: usize>(
    loaded: &Loaded,
    model: &Fixed<M, F, 32, K>,
) -> Result<
    (
        Drives<F>,
        Analysis<M, F, <Fixed<M, F, 32, K> as Kernels<M, F>>::Points>,
    ),
    Failure,
> {
    let drives = drives(loaded, model)?;
    let u = assembled(loaded, model, &drives.at)?;
    let pose = model
        .analyze(
            &u,
            &drives.at,
            &drives.rate,
            &drives.acceleration,
            &Options::default(),
        )
        .map_err(|e| Failure::Analysis(e.to_string()))?;
    Ok((drives, pose))
}

/// The sweep over the file's drive range in `steps` steps: where it
/// starts (the file's assembly at `at`, carried to `from`), the drive, and
/// the options (the drivers' speed along it).
pub struct Swept<const M: usize, const F: usize> {
    pub start: SVector<f64, M>,
    pub drive: Drive<F>,
    pub options: SweepOptions,
}

/// The file's sweep for `model` in `steps` steps.
pub fn swept<const M: usize, const F: usize, const K: usize>(
    loaded: &Loaded,
    model: &Fixed<M, F, 32, K>,
    steps: usize,
) -> Result<Swept<M, F>, Failure> {
    let drives = drives(loaded, model)?;
    let u_at = assembled(loaded, model, &drives.at)?;
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
            at_the_drive(loaded, &model.v_names(), why, "the drive")
        })?;
        if !carried.complete {
            let why = "the assembly at `at` does not reach `from` (a limit position between them)";
            return Err(at_the_drive(
                loaded,
                &model.v_names(),
                why.to_owned(),
                "the drive",
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

/// The poses of the file's sweep ([`swept`]); each pose is given to
/// `on_pose` with its index.
pub fn sweep_each<const M: usize, const F: usize, const K: usize>(
    loaded: &Loaded,
    model: &Fixed<M, F, 32, K>,
    steps: usize,
    on_pose: &mut dyn FnMut(usize, &SweepPose<M, F>),
) -> Result<SweepSummary<M, F>, Failure> {
    let Swept {
        start,
        drive,
        options,
    } = swept(loaded, model, steps)?;
    let mut index = 0;
    model
        .sweep_each(&start, &drive, &options, |pose| {
            on_pose(index, pose);
            index += 1;
        })
        .map_err(|e| Failure::Analysis(e.to_string()))
}

/// Writes `bytes` to the file `output`, or to standard output.
pub fn emit(output: Option<&Path>, bytes: &[u8]) -> Result<(), Failure> {
    match output {
        Some(path) => std::fs::write(path, bytes)
            .map_err(|e| Failure::Io(format!("cannot write {}: {e}", path.display()))),
        None => {
            let mut out = std::io::stdout().lock();
            out.write_all(bytes)
                .and_then(|()| out.flush())
                .or_else(|e| match e.kind() {
                    // A reader that stopped reading (`| head`) is not a failure.
                    std::io::ErrorKind::BrokenPipe => Ok(()),
                    _ => Err(e),
                })
                .map_err(|e| Failure::Io(format!("cannot write to standard output: {e}")))
        }
    }
}
