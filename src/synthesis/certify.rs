//! The certificate of a design: a continuation sweep over the whole
//! driver range — a revolution, or the task's range from one end to the
//! other through every target. It must assemble everywhere, meet no
//! singular pose (a dead point, or a branch point where it could change
//! branch), come to each target's pose on the branch it was designed on
//! and in the targets' order, keep the transmission angle, and pass the
//! designer's own checks. A design that fails is not returned: the defect
//! says which and where. One that passes gets its [`Certificate`]: the
//! range swept, its worst transmission angle and where, its Grashof type.

use super::continuation;
use crate::closed_form::Grashof;
use crate::runtime::{Error, EventKind, Linkage, SweepOptions, SweepPose};
use crate::transmission::{acute_from_cosine, equivalent_angle};
use nalgebra::SVector;
use std::f64::consts::TAU;
use std::fmt;

/// The driver range a design must run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Range {
    /// A whole revolution: the targets in cyclic order, and back to the
    /// first on the same branch.
    Revolution,
    /// The task's driver range, stated in the problem
    /// ([`Problem::driver_range`](super::Problem::driver_range); a
    /// function over a range states its own): from its one end to the
    /// other, the driver moving one way, through every target in order.
    Task,
    /// From the first target's driver to the last's, the driver moving
    /// one way: the span the targets cover and no more, for a task that
    /// is its targets (a body through given poses). Where the task has a
    /// wider range of its own (a function over an interval whose precision
    /// points lie inside it), certify over [`Range::Task`].
    Targets,
}

/// The smallest transmission angle a design of one loop in two
/// coordinates (a four-bar, a slider-crank) must keep by default: 40°, the
/// textbook's lower limit. For such a mechanism the equivalent
/// transmission angle is exactly the textbook's.
pub const DEFAULT_MIN_TRANSMISSION: f64 = 40.0 * std::f64::consts::PI / 180.0;

/// The smallest equivalent transmission angle a design of any other size
/// must keep by default: 10°, a floor under near-singular poses. With more
/// coordinates the equivalent angle depends on how they were chosen (the
/// worksheet's four-bar described by its coupler's position and angle,
/// four coordinates, has 33.6° where its transmission angle is 57°), so a
/// textbook limit does not carry over: give such a mechanism its own
/// measure ([`Transmission::Cosine`]) and limit.
pub const DEFAULT_MIN_EQUIVALENT_ANGLE: f64 = 10.0 * std::f64::consts::PI / 180.0;

/// What a design must satisfy over its range.
pub struct Requirements<'a, L, const M: usize> {
    pub range: Range,
    /// Sweep steps per radian of the driver.
    pub steps_per_radian: f64,
    /// The smallest transmission angle allowed (radians; an angle beyond
    /// 90° counts as its supplement): by default
    /// [`DEFAULT_MIN_TRANSMISSION`] for two coordinates,
    /// [`DEFAULT_MIN_EQUIVALENT_ANGLE`] for any other number; 0 asks for
    /// none (a singular pose is refused all the same).
    pub min_transmission: f64,
    /// How the transmission angle is measured.
    pub transmission: Transmission<'a, L, M>,
    /// Checks of the design itself (a Grashof type): `Err(why)` rejects it.
    pub check: Option<DesignCheck<'a, L>>,
    /// The design's Grashof type, for the certificate (four-bars:
    /// `FourBar::grashof` and its siblings in [`mechanisms`](crate::mechanisms)).
    pub grashof: Option<fn(&L) -> Grashof>,
}

/// How a design's transmission angle is measured.
pub enum Transmission<'a, L, const M: usize> {
    /// The equivalent transmission angle of any mechanism, read from Ψ_u
    /// ([`transmission::equivalent_angle`](crate::transmission::equivalent_angle)):
    /// exactly the transmission angle of a four-bar or a slider-crank, the
    /// worst loop's of a mechanism of several.
    Equivalent,
    /// The cosine of the transmission angle at a pose, as the designer
    /// defines it (a cosine cannot wrap: any angle's cosine is the same
    /// whatever its turns).
    Cosine(TransmissionAngle<'a, L, M>),
}

/// The cosine of a design's transmission angle at a pose.
pub type TransmissionAngle<'a, L, const M: usize> =
    Box<dyn Fn(&L, &SweepPose<M, 1>) -> f64 + Send + Sync + 'a>;

/// A check of a design.
pub type DesignCheck<'a, L> = Box<dyn Fn(&L) -> Result<(), String> + Send + Sync + 'a>;

impl<L, const M: usize> Requirements<'_, L, M> {
    /// Run the `range` keeping the equivalent transmission angle at
    /// [`DEFAULT_MIN_TRANSMISSION`] at least (two coordinates: a four-bar's
    /// or a slider-crank's own), or [`DEFAULT_MIN_EQUIVALENT_ANGLE`] (any
    /// other number), 60 sweep steps per radian, no check of the design's
    /// own.
    pub fn new(range: Range) -> Self {
        Requirements {
            range,
            steps_per_radian: 60.0,
            min_transmission: if M == 2 {
                DEFAULT_MIN_TRANSMISSION
            } else {
                DEFAULT_MIN_EQUIVALENT_ANGLE
            },
            transmission: Transmission::Equivalent,
            check: None,
            grashof: None,
        }
    }
}

/// What a certified design was checked over, and how well it transmits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Certificate {
    /// The driver range swept, in the direction of travel: from `from` to
    /// `to` (a revolution: `to` = `from` ± 2π).
    pub from: f64,
    pub to: f64,
    /// The smallest transmission angle over the range (radians, acute, as
    /// [`Requirements::transmission`] measures it), and the driver there.
    pub transmission: f64,
    pub transmission_at: f64,
    /// Its Grashof type, where [`Requirements::grashof`] gives one.
    pub grashof: Option<Grashof>,
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

impl fmt::Display for Defect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let degrees = |a: f64| a.to_degrees();
        match self {
            Defect::Misses { target, error } => write!(f, "it misses target {target} by {error:e}"),
            Defect::Order { drivers } => write!(
                f,
                "its drivers at the targets ({drivers:?}) are not in the targets' order along the range"
            ),
            Defect::Stops { v, why } => {
                write!(f, "it cannot be followed from the driver {v}: {why}")
            }
            Defect::Incomplete { v } => write!(f, "its sweep ends before reaching the driver {v}"),
            Defect::Singular { v, kind } => {
                write!(f, "it meets a singular pose ({kind:?}) at the driver {v}")
            }
            Defect::Branch { target, v } => write!(
                f,
                "at the driver {v} it reaches target {target} on another assembly branch than designed"
            ),
            Defect::Transmission { v, angle } => write!(
                f,
                "its transmission angle falls to {:.2}° at the driver {v} ({:.2}°)",
                degrees(*angle),
                degrees(*v)
            ),
            Defect::Check(why) => write!(f, "the designer's check refused it: {why}"),
        }
    }
}

/// Certifies the design `model` through the targets' poses `poses` at the
/// drivers `drivers` (in the targets' order), over `requirements.range`
/// (for [`Range::Task`], the task's range `task`, from its first end to
/// its second; a design without one cannot be certified over it and is
/// refused with [`Defect::Order`]).
pub fn certify<L, const M: usize>(
    model: &L,
    poses: &[SVector<f64, M>],
    drivers: &[f64],
    task: Option<(f64, f64)>,
    requirements: &Requirements<'_, L, M>,
    options: &SweepOptions,
) -> Result<Certificate, Defect>
where
    L: Linkage<M, 1>,
{
    if let Some(check) = &requirements.check {
        check(model).map_err(Defect::Check)?;
    }
    let order = || Defect::Order {
        drivers: drivers.to_vec(),
    };
    let range = match requirements.range {
        Range::Revolution => None,
        Range::Task => Some(task.ok_or_else(order)?),
        Range::Targets => Some(
            drivers
                .first()
                .zip(drivers.last())
                .map(|(a, b)| (*a, *b))
                .ok_or_else(order)?,
        ),
    };
    let legs = legs(drivers, range).ok_or_else(order)?;
    let mut worst = Worst {
        angle: f64::INFINITY,
        at: drivers.first().copied().unwrap_or(0.0),
    };
    for leg in &legs {
        follow(model, poses, leg, requirements, options, &mut worst)?;
    }
    // A range of one target is swept nowhere: its pose is the range.
    if !legs.iter().any(Leg::sweeps) {
        for (u, &v) in poses.iter().zip(drivers) {
            let angle =
                transmission_angle(model, requirements, u, v, None).unwrap_or(f64::INFINITY);
            worst.meet(angle, v);
        }
        worst.keeps(requirements.min_transmission)?;
    }
    let (from, to) = match range {
        Some(range) => range,
        None => (legs[0].from, legs[legs.len() - 1].to),
    };
    Ok(Certificate {
        from,
        to,
        transmission: worst.angle,
        transmission_at: worst.at,
        grashof: requirements.grashof.map(|g| g(model)),
    })
}

/// One leg of the range: from target `start`'s pose at the driver `from`
/// to the driver `to`, ending in target `end`'s pose if any (the legs from
/// the first target back to the range's start and from the last target
/// on to its end arrive at no target).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Leg {
    start: usize,
    from: f64,
    to: f64,
    end: Option<usize>,
}

impl Leg {
    /// Whether the leg is swept: it moves the driver or arrives at a
    /// target (a whole turn back to the start).
    fn sweeps(&self) -> bool {
        self.from != self.to || self.end.is_some()
    }
}

/// The legs of the range (a revolution if `range` is `None`); `None` if
/// the drivers are not in order along it, or outside it.
fn legs(drivers: &[f64], range: Option<(f64, f64)>) -> Option<Vec<Leg>> {
    let n = drivers.len();
    let leg = |start, from, to, end| Leg {
        start,
        from,
        to,
        end,
    };
    match range {
        Some((from, to)) => {
            // Each target strictly after the last in the direction of travel,
            // all within [from, to].
            let sign = (to - from).signum();
            let within = drivers
                .iter()
                .all(|&d| sign * (d - from) >= 0.0 && sign * (to - d) >= 0.0);
            let ordered = drivers.windows(2).all(|w| sign * (w[1] - w[0]) > 0.0);
            if !(within && ordered && n > 0) {
                return None;
            }
            let mut legs = vec![leg(0, drivers[0], from, None)];
            legs.extend((1..n).map(|i| leg(i - 1, drivers[i - 1], drivers[i], Some(i))));
            legs.push(leg(n - 1, drivers[n - 1], to, None));
            Some(legs)
        }
        None => {
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
                                leg(i, start, at, Some((i + 1) % n))
                            })
                            .collect(),
                    );
                }
            }
            None
        }
    }
}

/// The transmission angle at a pose as the requirements measure it; a
/// designer's cosine reads the sweep's pose, so at a pose given alone
/// (`pose` `None`) only the equivalent angle is measured.
fn transmission_angle<L, const M: usize>(
    model: &L,
    requirements: &Requirements<'_, L, M>,
    u: &SVector<f64, M>,
    v: f64,
    pose: Option<&SweepPose<M, 1>>,
) -> Option<f64>
where
    L: Linkage<M, 1>,
{
    match (&requirements.transmission, pose) {
        (Transmission::Equivalent, _) => {
            Some(equivalent_angle(&model.psi_u(u, &SVector::from([v]))))
        }
        (Transmission::Cosine(cosine), Some(pose)) => Some(acute_from_cosine(cosine(model, pose))),
        (Transmission::Cosine(_), None) => None,
    }
}

/// The smallest transmission angle met so far, and the driver there.
struct Worst {
    angle: f64,
    at: f64,
}

impl Worst {
    /// Takes in the angle `angle` met at the driver `at`.
    fn meet(&mut self, angle: f64, at: f64) {
        if angle < self.angle {
            *self = Worst { angle, at };
        }
    }

    /// The requirement's smallest angle kept, or the defect where not.
    fn keeps(&self, min: f64) -> Result<(), Defect> {
        if self.angle < min {
            return Err(Defect::Transmission {
                v: self.at,
                angle: self.angle,
            });
        }
        Ok(())
    }
}

/// One leg: sweeps from its start target's pose to its end, keeping the
/// worst transmission angle, and checks that it ends in its end target's
/// pose.
fn follow<L, const M: usize>(
    model: &L,
    poses: &[SVector<f64, M>],
    leg: &Leg,
    requirements: &Requirements<'_, L, M>,
    options: &SweepOptions,
    worst: &mut Worst,
) -> Result<(), Defect>
where
    L: Linkage<M, 1>,
{
    if !leg.sweeps() {
        return Ok(());
    }
    let mut low = Worst {
        angle: f64::INFINITY,
        at: leg.from,
    };
    let followed = continuation::follow(
        model,
        &poses[leg.start],
        (leg.from, leg.to),
        requirements.steps_per_radian,
        options,
        |pose| {
            let angle = transmission_angle(model, requirements, &pose.u, pose.v[0], Some(pose))
                .unwrap_or(f64::INFINITY);
            low.meet(angle, pose.v[0]);
        },
    )
    .map_err(|why| Defect::Stops { v: leg.from, why })?;
    let summary = &followed.summary;
    if let Some(event) = summary.events.first() {
        return Err(Defect::Singular {
            v: event.v[0],
            kind: event.kind,
        });
    }
    if !summary.complete {
        return Err(Defect::Incomplete { v: leg.to });
    }
    low.keeps(requirements.min_transmission)?;
    worst.meet(low.angle, low.at);
    let Some(end) = leg.end else {
        return Ok(());
    };
    if !continuation::same_pose(model, &followed.u, &poses[end], 1e-7) {
        return Err(Defect::Branch {
            target: end,
            v: leg.to,
        });
    }
    Ok(())
}
