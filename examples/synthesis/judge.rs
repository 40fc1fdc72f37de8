//! One judge for every design, ours and pylinkage's alike: the error at
//! the targets, measured on the design's own swept curve, and linkage's
//! certificate (`synthesis::certify`) over the required range from the
//! poses where the design meets its targets.
//!
//! A design is given as its dimensions and one pose (the pose it was
//! exported at: its assembly). The curve is swept over a whole turn from
//! that pose; a target's error is its distance from that curve (the
//! closest sample, refined by Newton on the distance). Where the design
//! meets a target is the closest pose on either assembly; the certificate
//! then sweeps from target to target and refuses a design that passes a
//! singular pose, reaches a target on the other assembly (a branch defect)
//! or out of the targets' order (an order defect).

use crate::tasks::FunctionTask;
use linkage::mechanisms::{CouplerFourBar, FourBar};
use linkage::prelude::*;
use linkage::synthesis::{Certificate, Defect, Range, Requirements, certify};
use std::f64::consts::{PI, TAU};

/// Samples of a turn.
const STEPS: usize = 3600;

/// What the certificate says.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    Certified,
    Defective(Defect),
    /// It cannot be assembled, or not over the whole range.
    DoesNotAssemble(String),
}

impl Verdict {
    /// The certificate's answer.
    fn of(certified: Result<Certificate, Defect>) -> Verdict {
        match certified {
            Ok(_) => Verdict::Certified,
            Err(defect) => Verdict::Defective(defect),
        }
    }

    pub fn defective(&self) -> bool {
        matches!(self, Verdict::Defective(_))
    }

    pub fn assembles(&self) -> bool {
        !matches!(self, Verdict::DoesNotAssemble(_))
    }

    /// One line for tables and the CSV (no commas).
    pub fn describe(&self) -> String {
        let text = match self {
            Verdict::Certified => "certified".to_owned(),
            Verdict::Defective(defect) => match defect {
                Defect::Order { .. } => "order defect: targets out of order".to_owned(),
                Defect::Branch { target, v } => format!(
                    "branch defect: target {target} reached on the other assembly (θ2 = {:.1}°)",
                    v.to_degrees()
                ),
                Defect::Singular { v, kind } => {
                    format!("singular pose {kind:?} at θ2 = {:.1}°", v.to_degrees())
                }
                Defect::Transmission { v, angle } => format!(
                    "transmission angle {:.1}° at θ2 = {:.1}°",
                    angle.to_degrees(),
                    v.to_degrees().rem_euclid(360.0)
                ),
                other => other.to_string(),
            },
            Verdict::DoesNotAssemble(why) => format!("does not assemble: {why}"),
        };
        text.replace(',', ";")
    }
}

/// A judged design.
#[derive(Clone, Debug)]
pub struct Judged {
    /// Each target's error (mm for a path, radians for a function).
    pub errors: Vec<f64>,
    pub verdict: Verdict,
    /// The coupler curve on the design's assembly (a path design).
    pub curve: Vec<Vector2<f64>>,
    /// The largest error of the output over the whole range (a function).
    pub over_range: Option<f64>,
}

impl Judged {
    pub fn error(&self) -> f64 {
        self.errors.iter().copied().fold(0.0, f64::max)
    }

    fn refused(why: String, targets: usize) -> Judged {
        Judged {
            errors: vec![f64::INFINITY; targets],
            verdict: Verdict::DoesNotAssemble(why),
            curve: Vec::new(),
            over_range: None,
        }
    }
}

/// A pose of a sweep.
#[derive(Clone, Copy, Debug)]
struct Sample {
    v: f64,
    u: SVector<f64, 2>,
}

/// The design's turn from the pose `u` at θ2 = `v`, or why not.
fn turn<L: Linkage<2, 1>>(model: &L, u: &SVector<f64, 2>, v: f64) -> Result<Vec<Sample>, String> {
    let drive = Drive::Line {
        from: vector![v],
        to: vector![v + TAU],
        steps: STEPS,
    };
    let sweep = model
        .sweep(u, &drive, &SweepOptions::default())
        .map_err(|e| e.to_string())?;
    if !sweep.complete {
        let end = sweep.poses.last().map_or(v, |p| p.v[0]);
        return Err(format!(
            "its crank stops at θ2 = {:.1}°",
            end.to_degrees().rem_euclid(360.0)
        ));
    }
    Ok(sweep
        .poses
        .iter()
        .map(|p| Sample { v: p.v[0], u: p.u })
        .collect())
}

/// The pose of the other assembly at the pose `u`, θ2 = `v`: C reflected in
/// the line B–D.
fn mirrored(model: &CouplerFourBar, u: &SVector<f64, 2>, v: f64) -> SVector<f64, 2> {
    let b = vector![model.xa + model.l2 * v.cos(), model.ya + model.l2 * v.sin()];
    let d = vector![model.xd, model.yd];
    let c = b + model.l3 * vector![u[0].cos(), u[0].sin()];
    let axis = (d - b).normalize();
    let along = (c - b).dot(&axis) * axis;
    let reflected = b + 2.0 * along - (c - b);
    let (bc, cd) = (reflected - b, d - reflected);
    vector![bc.y.atan2(bc.x), cd.y.atan2(cd.x)]
}

/// A turn's samples with P at each.
struct Curve {
    samples: Vec<Sample>,
    points: Vec<Vector2<f64>>,
}

impl Curve {
    fn new(model: &CouplerFourBar, samples: Vec<Sample>) -> Curve {
        let points = samples
            .iter()
            .map(|s| model.point_positions(&s.u, &vector![s.v])[CouplerFourBar::P])
            .collect();
        Curve { samples, points }
    }
}

/// The point of `curve` closest to `target`: (distance, θ2, pose), the
/// closest sample refined by Newton on d(θ2) = |P − T|².
fn closest(
    model: &CouplerFourBar,
    curve: &Curve,
    target: &Vector2<f64>,
) -> (f64, f64, SVector<f64, 2>) {
    let samples = &curve.samples;
    let distance = |k: usize| (curve.points[k] - target).norm();
    let k = (0..samples.len())
        .min_by(|&a, &b| distance(a).total_cmp(&distance(b)))
        .expect("a turn has samples");
    let (lo, hi) = (
        samples[k.saturating_sub(1)].v.min(samples[k].v),
        samples[(k + 1).min(samples.len() - 1)].v.max(samples[k].v),
    );
    let mut best = (distance(k), samples[k].v, samples[k].u);
    let (mut v, mut u) = (samples[k].v, samples[k].u);
    for _ in 0..30 {
        let Ok(a) = model.analyze(
            &u,
            &vector![v],
            &vector![1.0],
            &vector![0.0],
            &Options::default(),
        ) else {
            break;
        };
        let at = a.points.as_ref()[CouplerFourBar::P] - target;
        let (d1, d2) = (
            a.point_velocities.as_ref()[CouplerFourBar::P],
            a.point_accelerations.as_ref()[CouplerFourBar::P],
        );
        if at.norm() < best.0 {
            best = (at.norm(), v, a.u);
        }
        let (g, slope) = (at.dot(&d1), d1.dot(&d1) + at.dot(&d2));
        if slope <= 0.0 {
            break;
        }
        let next = (v - g / slope).clamp(lo, hi);
        if (next - v).abs() <= 1e-15 * v.abs().max(1.0) {
            break;
        }
        (v, u) = (next, a.u);
    }
    best
}

/// The design's own curve from its exported pose `u` at θ2 = `v`, or why
/// it has none.
fn own_curve(
    model: &CouplerFourBar,
    u: &SVector<f64, 2>,
    v: f64,
) -> Result<(SVector<f64, 2>, Curve), String> {
    let start = model
        .solve_position(u, &vector![v], &Options::default())
        .map_err(|e| e.to_string())?
        .u;
    Ok((start, Curve::new(model, turn(model, &start, v)?)))
}

/// A path design: `model` at its exported pose `u` (θ2 = `v`), its
/// coupler point P through `targets` over a turn, in their order.
pub fn path(
    model: &CouplerFourBar,
    u: &SVector<f64, 2>,
    v: f64,
    targets: &[Vector2<f64>],
) -> Judged {
    let (start, own) = match own_curve(model, u, v) {
        Ok(found) => found,
        Err(why) => return Judged::refused(why, targets.len()),
    };
    // The other assembly, where it runs a turn too.
    let other = model
        .solve_position(
            &mirrored(model, &start, v),
            &vector![v],
            &Options::default(),
        )
        .ok()
        .and_then(|pose| turn(model, &pose.u, v).ok())
        .map(|samples| Curve::new(model, samples));
    let mut errors = Vec::new();
    let mut drivers = Vec::new();
    let mut poses = Vec::new();
    for target in targets {
        let mine = closest(model, &own, target);
        errors.push(mine.0);
        let met = match other.as_ref().map(|o| closest(model, o, target)) {
            Some(theirs) if theirs.0 < mine.0 => theirs,
            _ => mine,
        };
        drivers.push(met.1);
        poses.push(met.2);
    }
    let verdict = Verdict::of(certify(
        model,
        &poses,
        &drivers,
        None,
        &Requirements::new(Range::Revolution),
        &SweepOptions::default(),
    ));
    Judged {
        errors,
        verdict,
        curve: own.points,
        over_range: None,
    }
}

/// The largest error of a path design at `targets` alone, without the
/// certificate: for the many designs of an optimiser's convergence.
/// `None` if it does not run a turn.
pub fn path_error(
    model: &CouplerFourBar,
    u: &SVector<f64, 2>,
    v: f64,
    targets: &[Vector2<f64>],
) -> Option<f64> {
    let (_, own) = own_curve(model, u, v).ok()?;
    Some(
        targets
            .iter()
            .map(|t| closest(model, &own, t).0)
            .fold(0.0, f64::max),
    )
}

/// The assemblies of the four-bar `l` at θ2 = `theta`, as (θ3, θ4): the
/// closed form's two branches (one where they meet, none where it does not
/// assemble).
fn assemblies(l: &FourBar, theta: f64) -> Vec<SVector<f64, 2>> {
    let bar = l.closed_form();
    [1.0, -1.0]
        .into_iter()
        .filter_map(|sigma| bar.position(theta, sigma))
        .map(SVector::from)
        .collect()
}

/// An angle's difference, within (−π, π].
fn wrapped(a: f64) -> f64 {
    a - TAU * (a / TAU).round()
}

/// A function design: `model` at its exported pose `u` at the first
/// target's crank angle; the rocker's φ = θ4 + π against the task.
pub fn function(model: &FourBar, u: &SVector<f64, 2>, task: &FunctionTask) -> Judged {
    let n = task.targets.len();
    let first = task.targets[0].0;
    let Ok(start) = model.solve_position(u, &vector![first], &Options::default()) else {
        return Judged::refused("not at its first precision point".to_owned(), n);
    };
    // φ along the design's own assembly over the whole range, the targets
    // among the steps.
    let last = task.targets[n - 1].0;
    let steps = 600;
    let drive = Drive::Line {
        from: vector![first],
        to: vector![last],
        steps,
    };
    let sweep = match model.sweep(&start.u, &drive, &SweepOptions::default()) {
        Ok(sweep) if sweep.complete => sweep,
        Ok(_) => return Judged::refused("not over the whole range".to_owned(), n),
        Err(e) => return Judged::refused(format!("{e}"), n),
    };
    let phi_at = |theta: f64| -> Option<f64> {
        let near = sweep
            .poses
            .iter()
            .min_by(|a, b| (a.v[0] - theta).abs().total_cmp(&(b.v[0] - theta).abs()))?;
        let pose = model
            .solve_position(&near.u, &vector![theta], &Options::default())
            .ok()?;
        Some(pose.u[1] + PI)
    };
    let errors: Vec<f64> = task
        .targets
        .iter()
        .map(|&(theta, phi)| phi_at(theta).map_or(f64::INFINITY, |p| wrapped(p - phi).abs()))
        .collect();
    let over_range = sweep
        .poses
        .iter()
        .map(|p| {
            let x = 1.0
                + 9.0 * (p.v[0].to_degrees() - crate::tasks::CRANK.0)
                    / (crate::tasks::CRANK.1 - crate::tasks::CRANK.0);
            wrapped(p.u[1] + PI - FunctionTask::angles(x).1).abs()
        })
        .fold(0.0, f64::max);
    // Where the design meets each target: the assembly nearest the wanted φ.
    let mut poses = Vec::new();
    for &(theta, phi) in &task.targets {
        let Some(nearest) = assemblies(model, theta).into_iter().min_by(|a, b| {
            wrapped(a[1] + PI - phi)
                .abs()
                .total_cmp(&wrapped(b[1] + PI - phi).abs())
        }) else {
            return Judged::refused(format!("not at θ2 = {:.1}°", theta.to_degrees()), n);
        };
        poses.push(nearest);
    }
    let drivers: Vec<f64> = task.targets.iter().map(|t| t.0).collect();
    let verdict = Verdict::of(certify(
        model,
        &poses,
        &drivers,
        Some(FunctionTask::crank_range()),
        &FunctionTask::requirements(),
        &SweepOptions::default(),
    ));
    Judged {
        errors,
        verdict,
        curve: Vec::new(),
        over_range: Some(over_range),
    }
}
