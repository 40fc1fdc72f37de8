//! Describing a machine: [`MachineBuilder`], and `build`, which resolves
//! the bodies' and loads' names, follows the cycle and integrates the work.

use super::body::MassBody;
use super::cycle::GridPose;
use super::load::{LoadKind, ResolvedLoad, unit_direction};
use super::{Body, Load, Machine, MachineError};
use crate::quantity::Names;
use crate::runtime::{Drive, Linkage, Options, SweepOptions};
use nalgebra::{SVector, Vector2};
use std::f64::consts::TAU;

/// A [`Machine`] being described.
pub struct MachineBuilder<L, const M: usize> {
    model: L,
    guess: SVector<f64, M>,
    bodies: Vec<Body>,
    loads: Vec<Load>,
    grid: usize,
    options: Options,
}

impl<L: Linkage<M, 1>, const M: usize> Machine<L, M> {
    /// A machine made of `model`, whose pose at φ = 0 is near `guess`.
    #[allow(clippy::new_ret_no_self)]
    pub fn new(model: L, guess: SVector<f64, M>) -> MachineBuilder<L, M> {
        MachineBuilder {
            model,
            guess,
            bodies: Vec::new(),
            loads: Vec::new(),
            grid: 720,
            options: Options::default(),
        }
    }
}

impl<L: Linkage<M, 1>, const M: usize> MachineBuilder<L, M> {
    pub fn body(mut self, body: Body) -> Self {
        self.bodies.push(body);
        self
    }

    pub fn load(mut self, load: Load) -> Self {
        self.loads.push(load);
        self
    }

    /// Poses precomputed over the cycle (default 720, from 8 to 10⁶): they
    /// start every later position solve and bracket the loads' kinks.
    pub fn grid(mut self, poses: usize) -> Self {
        self.grid = poses;
        self
    }

    /// The solver's options.
    pub fn options(mut self, options: Options) -> Self {
        self.options = options;
        self
    }

    /// Checks every name, follows the cycle φ ∈ [0, 2π] by continuation from
    /// the guess, and finds the loads' kinks.
    pub fn build(self) -> Result<Machine<L, M>, MachineError> {
        if !(8..=1_000_000).contains(&self.grid) {
            return Err(MachineError::BadSetting {
                what: "the grid",
                must: "from 8 to 10⁶ poses",
                value: self.grid as f64,
            });
        }
        let names = Names::of(&self.model);
        let bodies = self
            .bodies
            .iter()
            .map(|body| resolve_body(body, &names))
            .collect::<Result<Vec<_>, _>>()?;
        let loads = self
            .loads
            .iter()
            .map(|load| resolve_load(load, &names))
            .collect::<Result<Vec<_>, _>>()?;
        let grid = follow_cycle(&self.model, &self.guess, self.grid, self.options)?;
        let mut machine = Machine {
            model: self.model,
            bodies,
            loads,
            grid,
            options: self.options,
            kinks: Vec::new(),
            work: Vec::new(),
            moment_scale: 0.0,
            coordinates: names.coordinates().to_vec(),
        };
        // Displacements are measured from the positions at φ = 0.
        let start = machine.pose(0.0)?;
        for load in &mut machine.loads {
            if let LoadKind::Process { .. } = load.load.kind {
                load.origin = start.points[load.target];
            }
        }
        machine.kinks = machine.find_kinks()?;
        machine.moment_scale = machine
            .grid
            .iter()
            .map(|g| machine.reduced(g.phi).map(|r| r.moment.abs()))
            .collect::<Result<Vec<f64>, _>>()?
            .into_iter()
            .fold(f64::MIN_POSITIVE, f64::max);
        machine.work = machine.integrate_work()?;
        Ok(machine)
    }
}

/// A body's numbers checked and its names resolved.
fn resolve_body(body: &Body, names: &Names) -> Result<MassBody, MachineError> {
    for (what, value) in [("a mass", body.mass), ("a moment of inertia", body.inertia)] {
        if !(value.is_finite() && value >= 0.0) {
            return Err(MachineError::BadSetting {
                what,
                must: "finite and ≥ 0",
                value,
            });
        }
    }
    if !body.angle_factor.is_finite() {
        return Err(MachineError::BadSetting {
            what: "an angle factor",
            must: "finite",
            value: body.angle_factor,
        });
    }
    Ok(MassBody {
        name: body.name.clone(),
        angle_factor: body.angle_factor,
        mass: body.mass,
        inertia: body.inertia,
        centre: body
            .centre
            .as_deref()
            .map(|p| names.point(&body.name, p))
            .transpose()?,
        angle: body
            .angle
            .as_deref()
            .map(|c| names.coordinate(&body.name, c))
            .transpose()?,
    })
}

/// A load's numbers checked (its direction made a unit vector) and its
/// point or coordinate resolved.
fn resolve_load(load: &Load, names: &Names) -> Result<ResolvedLoad, MachineError> {
    let mut load = load.clone();
    match &mut load.kind {
        LoadKind::Process { direction, .. } | LoadKind::Friction { direction, .. } => {
            *direction = unit_direction(*direction)?;
        }
        LoadKind::Gravity { g } if !(g.x.is_finite() && g.y.is_finite()) => {
            return Err(MachineError::BadSetting {
                what: "the acceleration of gravity",
                must: "finite",
                value: if g.x.is_finite() { g.y } else { g.x },
            });
        }
        _ => {}
    }
    let target = match &load.kind {
        LoadKind::Force { point: p, .. }
        | LoadKind::Process { point: p, .. }
        | LoadKind::Friction { point: p, .. } => names.point(&load.name, p)?,
        LoadKind::Moment { coordinate: c, .. } => names.coordinate(&load.name, c)?,
        LoadKind::Gravity { .. } => 0,
    };
    if let LoadKind::Friction { magnitude, .. } = load.kind {
        if !magnitude.is_finite() {
            return Err(MachineError::BadSetting {
                what: "a friction force",
                must: "finite",
                value: magnitude,
            });
        }
    }
    Ok(ResolvedLoad {
        load,
        target,
        origin: Vector2::zeros(),
    })
}

/// The cycle by continuation from `guess`: the poses of the grid, or why
/// the mechanism does not complete it.
fn follow_cycle<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    guess: &SVector<f64, M>,
    steps: usize,
    options: Options,
) -> Result<Vec<GridPose<M>>, MachineError> {
    let sweep = model.sweep(
        guess,
        &Drive::Line {
            from: SVector::<f64, 1>::zeros(),
            to: SVector::<f64, 1>::from_element(TAU),
            steps,
        },
        &SweepOptions {
            options,
            ..SweepOptions::default()
        },
    )?;
    if let Some(event) = sweep.events.first() {
        return Err(MachineError::Incomplete {
            phi: event.v[0],
            why: match event.kind {
                crate::runtime::EventKind::LimitPosition => "a limit position",
                crate::runtime::EventKind::BranchPoint => {
                    "a branch point, where the motion is not determined"
                }
            },
        });
    }
    if !sweep.complete || sweep.poses.len() != steps + 1 {
        let last = sweep.poses.last().map_or(0.0, |p| p.v[0]);
        return Err(MachineError::Incomplete {
            phi: last,
            why: if sweep.events.is_empty() {
                "a pose could not be kept to the requested accuracy"
            } else {
                "a singular pose"
            },
        });
    }
    Ok(sweep
        .poses
        .iter()
        .map(|p| GridPose {
            phi: p.v[0],
            u: p.u,
            u_phi: p.udot,
            u_phiphi: p.uddot,
        })
        .collect())
}
