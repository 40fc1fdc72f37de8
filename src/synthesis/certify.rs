//! The certificate of a design: a continuation sweep from target to
//! target over the whole driver range. It must assemble everywhere, meet
//! no singular pose (a dead point, or a branch point where it could change
//! branch), come to each target's pose on the branch it was designed on
//! and in the targets' order, keep the transmission angle, and pass the
//! designer's own checks. A design that fails is not returned: the defect
//! says which and where.

use linkage_runtime::{Drive, Error, EventKind, Linkage, SweepOptions, SweepPose};
use nalgebra::SVector;
use std::f64::consts::TAU;

/// The driver range a design must run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Range {
    /// A whole revolution: the targets in cyclic order, and back to the
    /// first on the same branch.
    Revolution,
    /// From the first target to the last, the driver moving one way.
    Between,
}

/// What a design must satisfy over its range.
pub struct Requirements<'a, L, const M: usize> {
    pub range: Range,
    /// Sweep steps per radian of the driver.
    pub steps_per_radian: f64,
    /// The smallest transmission angle allowed and how to compute it at a
    /// pose (radians; angles beyond 90° count as their supplement).
    pub transmission: Option<(f64, TransmissionAngle<'a, L, M>)>,
    /// Checks of the design itself (a Grashof type): `Err(why)` rejects it.
    pub check: Option<DesignCheck<'a, L>>,
}

/// The transmission angle of a design at a pose.
pub type TransmissionAngle<'a, L, const M: usize> =
    Box<dyn Fn(&L, &SweepPose<M, 1>) -> f64 + Send + Sync + 'a>;

/// A check of a design.
pub type DesignCheck<'a, L> = Box<dyn Fn(&L) -> Result<(), String> + Send + Sync + 'a>;

impl<L, const M: usize> Requirements<'_, L, M> {
    /// Run the `range`, nothing else asked.
    pub fn new(range: Range) -> Self {
        Requirements {
            range,
            steps_per_radian: 60.0,
            transmission: None,
            check: None,
        }
    }
}

/// Why a design is not returned.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Defect {
    /// It misses a target (precision points) by `error`.
    Misses { target: usize, error: f64 },
    /// The targets' drivers are not in the targets' order along the range.
    Order { drivers: Vec<f64> },
    /// It cannot be followed from one target to the next (near `v`).
    Stops { v: f64, why: Error },
    /// Its sweep towards `v` ended early.
    Incomplete { v: f64 },
    /// It meets a singular pose at `v`.
    Singular { v: f64, kind: EventKind },
    /// Arriving at target `target`'s driver, it is on another branch (or
    /// elsewhere) than the pose it was designed with.
    Branch { target: usize, v: f64 },
    /// Its transmission angle falls to `angle` at `v`.
    Transmission { v: f64, angle: f64 },
    /// The designer's check refused it.
    Check(String),
}

/// Certifies the design `model` through the targets' poses `poses` at the
/// drivers `drivers` (in the targets' order).
pub fn certify<L, const M: usize>(
    model: &L,
    poses: &[SVector<f64, M>],
    drivers: &[f64],
    requirements: &Requirements<'_, L, M>,
    options: &SweepOptions,
) -> Result<(), Defect>
where
    L: Linkage<M, 1>,
{
    if let Some(check) = &requirements.check {
        check(model).map_err(Defect::Check)?;
    }
    let legs = legs(drivers, requirements.range).ok_or_else(|| Defect::Order {
        drivers: drivers.to_vec(),
    })?;
    for (from, start, to, end) in legs {
        follow(
            model,
            &poses[from],
            start,
            to,
            &poses[end],
            end,
            requirements,
            options,
        )?;
    }
    Ok(())
}

/// The legs of the range: (target it starts from, driver it starts at,
/// driver it ends at, target whose pose it must end in); `None` if the
/// drivers are not in order. Over a revolution each leg starts where the
/// last one ended, which may differ from its target's driver by whole
/// turns (the same pose).
fn legs(drivers: &[f64], range: Range) -> Option<Vec<(usize, f64, f64, usize)>> {
    let n = drivers.len();
    match range {
        Range::Between => {
            let rising = n < 2 || drivers[1] > drivers[0];
            let ordered = drivers
                .windows(2)
                .all(|w| (w[1] > w[0]) == rising && w[1] != w[0]);
            ordered.then(|| {
                (1..n)
                    .map(|i| (i - 1, drivers[i - 1], drivers[i], i))
                    .collect()
            })
        }
        Range::Revolution => {
            // Forward (or backward) gaps that add up to exactly one turn.
            let gap = |a: f64, b: f64, sign: f64| (sign * (b - a)).rem_euclid(TAU);
            for sign in [1.0, -1.0] {
                let gaps: Vec<f64> = (0..n)
                    .map(|i| gap(drivers[i], drivers[(i + 1) % n], sign))
                    .collect();
                let turn: f64 = gaps.iter().sum();
                if gaps.iter().all(|&g| g > 0.0) && (turn - TAU).abs() < 1e-9 || n == 1 {
                    let mut at = drivers[0];
                    return Some(
                        (0..n)
                            .map(|i| {
                                let start = at;
                                at += sign * if n == 1 { TAU } else { gaps[i] };
                                (i, start, at, (i + 1) % n)
                            })
                            .collect(),
                    );
                }
            }
            None
        }
    }
}

/// One leg: sweeps from target `from`'s pose at `v0` to the driver `to`,
/// and checks that it ends in the pose `end_pose` of target `end`.
#[allow(clippy::too_many_arguments)]
fn follow<L, const M: usize>(
    model: &L,
    start: &SVector<f64, M>,
    v0: f64,
    to: f64,
    end_pose: &SVector<f64, M>,
    end: usize,
    requirements: &Requirements<'_, L, M>,
    options: &SweepOptions,
) -> Result<(), Defect>
where
    L: Linkage<M, 1>,
{
    let steps = ((to - v0).abs() * requirements.steps_per_radian)
        .ceil()
        .max(2.0) as usize;
    let drive = Drive::Line {
        from: SVector::from([v0]),
        to: SVector::from([to]),
        steps,
    };
    let mut last = *start;
    let mut low: Option<(f64, f64)> = None;
    let summary = model
        .sweep_each(start, &drive, options, |pose| {
            last = pose.u;
            if let Some((_, angle)) = &requirements.transmission {
                let mu = angle(model, pose);
                let acute = mu.abs().min(std::f64::consts::PI - mu.abs());
                if low.is_none_or(|(_, a)| acute < a) {
                    low = Some((pose.v[0], acute));
                }
            }
        })
        .map_err(|why| Defect::Stops { v: v0, why })?;
    if let Some(event) = summary.events.first() {
        return Err(Defect::Singular {
            v: event.v[0],
            kind: event.kind,
        });
    }
    if !summary.complete {
        return Err(Defect::Incomplete { v: to });
    }
    if let (Some((minimum, _)), Some((v, angle))) = (&requirements.transmission, low) {
        if angle < *minimum {
            return Err(Defect::Transmission { v, angle });
        }
    }
    // The same pose, up to whole turns of an angle.
    let same = (0..M).all(|i| {
        let d = last[i] - end_pose[i];
        (d - TAU * (d / TAU).round()).abs() <= 1e-7 * end_pose[i].abs().max(1.0)
    });
    if !same {
        return Err(Defect::Branch { target: end, v: to });
    }
    Ok(())
}
