//! The machine's dynamics differentiated by its design: exact derivatives
//! of J(φ), M(φ), the work A(φ) and the energy method's flywheel J_I by the
//! model's parameters p (through the generated sensitivities) and by each
//! body's mass and moment of inertia.
//!
//! ```text
//! ∂J/∂p = Σ 2m·v_q·∂v_q/∂p + 2I·ω_q·∂ω_q/∂p      ∂J/∂m = |v_q|²   ∂J/∂I = ω_q²
//! ∂M/∂p = Σ F·∂v_q/∂p + ∂F/∂p·v_q                ∂M/∂m = g·v_q (the weight)
//! ∂A/∂p (φ) = ∫₀^φ ∂M/∂p dφ                      (M continuous: no terms from moving kinks)
//! ∂J_I/∂p = (∂ΔT_I/∂p (φ_max) − ∂ΔT_I/∂p (φ_min)) / (δ ω_m²)
//! ∂ΔT_I/∂p (φ) = ∂A/∂p (φ) + ∂M_D/∂p·φ − ½ ∂J/∂p (φ) ω_m²,   ∂M_D/∂p = −∂A/∂p (2π)/2π
//! ```
//!
//! The last line is the envelope theorem: ΔT_I is stationary in φ at its
//! extremes, so their moving with the design adds nothing to first order.
//! Of the loads, the ready-made kinds are differentiated (a process
//! force's magnitude through its table's slope and the displacement's
//! sensitivity, measured from the pose at φ = 0 that moves too; friction
//! and weights through the velocities they multiply); a load given as a
//! function of the pose cannot be, and is an error, as is a reduced moment
//! that jumps (a moving jump would add a term this does not compute).

use super::load::LoadKind;
use super::{Applied, EnergyMethod, Machine, MachineError, Pose};
use crate::numerics;
use crate::runtime::{Linkage, Sensitivities, Sensitivity};
use std::f64::consts::TAU;

/// A machine ready to be differentiated by its design: the model's
/// parameters p (`Sensitivities::param_names`, in order), then each body's
/// mass and moment of inertia ("mass of …", "inertia of …").
pub struct Design<'m, L: Sensitivities<M, 1, K>, const M: usize, const K: usize> {
    machine: &'m Machine<L, M>,
    names: Vec<String>,
    /// ∂P/∂p at φ = 0 of every point (process loads measure from there).
    origins: Sensitivity<M, K, L::Points>,
    /// (φ, ∂A/∂p) at the work's nodes (the grid and the kinks).
    work: Vec<(f64, Vec<f64>)>,
}

/// J′s and M's derivatives by the design at φ, in [`Design::names`] order.
#[derive(Clone, Debug, PartialEq)]
pub struct ReducedGradient {
    pub phi: f64,
    /// ∂J/∂(design)
    pub inertia: Vec<f64>,
    /// ∂M/∂(design)
    pub moment: Vec<f64>,
}

impl<L: Linkage<M, 1>, const M: usize> Machine<L, M> {
    /// The machine ready to be differentiated by its design (see
    /// [`Design`]): checks that every load can be, and integrates ∂M/∂p
    /// over the cycle once.
    pub fn design<const K: usize>(&self) -> Result<Design<'_, L, M, K>, MachineError>
    where
        L: Sensitivities<M, 1, K>,
    {
        for load in &self.loads {
            let why = match &load.load.kind {
                LoadKind::Force { .. } | LoadKind::Moment { .. } => {
                    Some("a function of the pose cannot be differentiated by the design")
                }
                LoadKind::Process { table, .. } if table.jumps() => {
                    Some("its table jumps, and a jump that moves with the design adds a term")
                }
                _ => None,
            };
            if let Some(why) = why {
                return Err(MachineError::NotDifferentiable {
                    what: format!("the load `{}`", load.load.name),
                    why,
                });
            }
        }
        // M must not jump where it kinks (a friction or process force
        // switching on with its point at rest is continuous).
        let h = 1e-9 * TAU;
        for &kink in &self.kinks {
            let jump = self.reduced(kink + h)?.moment - self.reduced(kink - h)?.moment;
            if jump.abs() > 1e-6 * self.moment_scale {
                return Err(MachineError::NotDifferentiable {
                    what: format!("the reduced moment at φ = {kink}"),
                    why: "it jumps there, and a jump that moves with the design adds a term",
                });
            }
        }
        let mut names: Vec<String> = self
            .model
            .param_names()
            .iter()
            .map(|n| n.to_string())
            .collect();
        for body in &self.bodies {
            names.push(format!("mass of {}", body.name));
            names.push(format!("inertia of {}", body.name));
        }
        let (_, origins) = self.sensitivities_at(0.0)?;
        let mut design = Design {
            machine: self,
            names,
            origins,
            work: Vec::new(),
        };
        design.work = design.integrate_work()?;
        Ok(design)
    }

    /// The pose at φ and the sensitivities there, the driver at unit speed
    /// (so that the velocities' sensitivities are those of the analogs).
    fn sensitivities_at<const K: usize>(
        &self,
        phi: f64,
    ) -> Result<(Pose, Sensitivity<M, K, L::Points>), MachineError>
    where
        L: Sensitivities<M, 1, K>,
    {
        let analysis = self.analysis(phi)?;
        let sensitivity = self.model.sensitivities_of(&analysis, &self.options)?;
        Ok((self.pose_of(phi, &analysis), sensitivity))
    }
}

impl<L: Sensitivities<M, 1, K>, const M: usize, const K: usize> Design<'_, L, M, K> {
    /// What the gradients are by, in their order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// ∂J/∂(design) and ∂M/∂(design) at φ.
    pub fn reduced(&self, phi: f64) -> Result<ReducedGradient, MachineError> {
        let machine = self.machine;
        let (pose, s) = machine.sensitivities_at(phi)?;
        let mut inertia = vec![0.0; self.names.len()];
        let mut moment = vec![0.0; self.names.len()];
        // ∂q′/∂p of a coordinate: the driver's analog is 1 whatever p.
        let coordinate_analog = |k: usize, j: usize| if k < M { s.udot[(k, j)] } else { 0.0 };
        let point_analog = |point: usize, j: usize| s.point_velocities[j].as_ref()[point];
        for (b, body) in machine.bodies.iter().enumerate() {
            if let Some(k) = body.angle {
                let c = body.angle_factor;
                let w = c * pose.q_phi[k];
                for (j, d) in inertia.iter_mut().take(K).enumerate() {
                    *d += 2.0 * body.inertia * w * c * coordinate_analog(k, j);
                }
                inertia[K + 2 * b + 1] = w * w;
            }
            if let Some(point) = body.centre {
                let v = pose.points_phi[point];
                for (j, d) in inertia.iter_mut().take(K).enumerate() {
                    *d += 2.0 * body.mass * v.dot(&point_analog(point, j));
                }
                inertia[K + 2 * b] = v.norm_squared();
            }
        }
        // F·∂v/∂p for every force or moment as applied, whatever its kind.
        for (_, applied) in machine.applied(&pose)? {
            for (j, d) in moment.iter_mut().take(K).enumerate() {
                *d += match applied {
                    Applied::Force { point, force } => force.dot(&point_analog(point, j)),
                    Applied::Moment { coordinate, moment } => {
                        moment * coordinate_analog(coordinate, j)
                    }
                };
            }
        }
        // ∂F/∂(design)·v where a force depends on it.
        for load in &machine.loads {
            match &load.load.kind {
                LoadKind::Gravity { g } => {
                    for (b, body) in machine.bodies.iter().enumerate() {
                        if let Some(point) = body.centre {
                            moment[K + 2 * b] += g.dot(&pose.points_phi[point]);
                        }
                    }
                }
                // As `Machine::applied`: −direction·table(travel) while
                // the point moves along the direction.
                LoadKind::Process {
                    direction, table, ..
                } => {
                    let point = load.target;
                    let v = pose.points_phi[point];
                    if v.dot(direction) > 0.0 {
                        let travel = (pose.points[point] - load.origin).dot(direction);
                        let slope = table.slope(travel);
                        for (j, d) in moment.iter_mut().take(K).enumerate() {
                            let moved = s.points[j].as_ref()[point]
                                - self.origins.points[j].as_ref()[point];
                            *d -= slope * moved.dot(direction) * v.dot(direction);
                        }
                    }
                }
                _ => {}
            }
        }
        for (what, values) in [("∂J/∂(design)", &inertia), ("∂M/∂(design)", &moment)] {
            if values.iter().any(|x| !x.is_finite()) {
                return Err(MachineError::Overflow { what, phi });
            }
        }
        Ok(ReducedGradient {
            phi,
            inertia,
            moment,
        })
    }

    /// ∂A/∂(design) at the work's nodes (the integrand is smooth between
    /// nodes, the kinks among them).
    fn integrate_work(&self) -> Result<Vec<(f64, Vec<f64>)>, MachineError> {
        let nodes: Vec<f64> = self.machine.work.iter().map(|&(phi, _)| phi).collect();
        let mut total = vec![0.0; self.names.len()];
        let mut out = vec![(nodes[0], total.clone())];
        for cell in nodes.windows(2) {
            let piece = self.integrate(cell[0], cell[1])?;
            for (t, p) in total.iter_mut().zip(&piece) {
                *t += p;
            }
            out.push((cell[1], total.clone()));
        }
        Ok(out)
    }

    /// ∫ₐᵇ ∂M/∂(design) over a cell (or part of one): one Gauss–Kronrod
    /// rule, the integrand smooth there.
    fn integrate(&self, a: f64, b: f64) -> Result<Vec<f64>, MachineError> {
        let mut f = |phi: f64| self.reduced(phi).map(|r| r.moment);
        numerics::integrate_cell(&mut f, a, b)
    }

    /// ∂A/∂(design) at φ ∈ [0, 2π].
    pub fn work(&self, phi: f64) -> Result<Vec<f64>, MachineError> {
        if !(0.0..=TAU).contains(&phi) {
            return Err(MachineError::BadSetting {
                what: "φ",
                must: "within the cycle [0, 2π]",
                value: phi,
            });
        }
        let k = self.work.partition_point(|(p, _)| *p <= phi).max(1) - 1;
        let (start, below) = &self.work[k];
        let rest = self.integrate(*start, phi)?;
        Ok(below.iter().zip(&rest).map(|(a, b)| a + b).collect())
    }

    /// The energy method's flywheel J_I differentiated by the design
    /// (see the module's documentation); `energy` must be this machine's.
    pub fn flywheel(&self, energy: &EnergyMethod<'_, L, M>) -> Result<Vec<f64>, MachineError> {
        if !std::ptr::eq(energy.machine, self.machine) {
            return Err(MachineError::NotDifferentiable {
                what: "the energy method".into(),
                why: "it was made for another machine than this design's",
            });
        }
        let omega2 = energy.omega_mean * energy.omega_mean;
        let cycle = self.work(TAU)?;
        let delta_t = |phi: f64| -> Result<Vec<f64>, MachineError> {
            let wrapped = phi.rem_euclid(TAU);
            let work = self.work(wrapped)?;
            let reduced = self.reduced(phi)?;
            Ok((0..self.names.len())
                .map(|i| work[i] - cycle[i] / TAU * wrapped - 0.5 * reduced.inertia[i] * omega2)
                .collect())
        };
        let (high, low) = (delta_t(energy.maximum.0)?, delta_t(energy.minimum.0)?);
        Ok(high
            .iter()
            .zip(&low)
            .map(|(h, l)| (h - l) / (energy.delta * omega2))
            .collect())
    }
}
