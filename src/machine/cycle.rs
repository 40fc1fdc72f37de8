//! A [`Machine`] over its cycle φ ∈ [0, 2π]: poses by Newton from the
//! precomputed grid, the loads applied at a pose, the reduced quantities
//! J, J′ and M, the loads' kinks, and the work A(φ).

use super::body::MassBody;
use super::energy::EnergyMethod;
use super::load::{LoadKind, ResolvedLoad};
use super::steady::{Motor, SteadyMotion};
use super::{Applied, MachineError, Pose};
use crate::numerics;
use crate::runtime::{Analysis, Error, Linkage, Options};
use nalgebra::{SVector, Vector2};
use std::f64::consts::TAU;

/// The reduced quantities at one φ, with each body's and load's share.
#[derive(Clone, Debug, PartialEq)]
pub struct Reduced {
    pub phi: f64,
    /// J(φ) = Σ m·|v_q|² + I·ω_q²
    pub inertia: f64,
    /// J′(φ) = Σ 2m·v_q·a_q + 2I·ω_q·ε_q
    pub inertia_derivative: f64,
    /// M(φ) = Σ F·v_q + Σ M·ω_q
    pub moment: f64,
    /// Per body: (I·ω_q², m·|v_q|², 2I·ω_q·ε_q, 2m·v_q·a_q).
    pub bodies: Vec<[f64; 4]>,
    /// Per load: its reduced moment.
    pub loads: Vec<f64>,
}

#[derive(Clone, Copy, Debug)]
pub(super) struct GridPose<const M: usize> {
    pub(super) phi: f64,
    pub(super) u: SVector<f64, M>,
    pub(super) u_phi: SVector<f64, M>,
    pub(super) u_phiphi: SVector<f64, M>,
}

/// A one-degree-of-freedom machine: a model, its bodies and loads, over
/// the cycle φ ∈ [0, 2π] (see the module documentation).
pub struct Machine<L, const M: usize> {
    pub(super) model: L,
    pub(super) bodies: Vec<MassBody>,
    pub(super) loads: Vec<ResolvedLoad>,
    pub(super) grid: Vec<GridPose<M>>,
    pub(super) options: Options,
    /// The loads' kinks in (0, 2π), ascending.
    pub(super) kinks: Vec<f64>,
    /// (φ, A(φ)) at the grid poses and the kinks.
    pub(super) work: Vec<(f64, f64)>,
    /// The largest |M| on the grid: the scale of the work's tolerance.
    pub(super) moment_scale: f64,
    pub(super) coordinates: Vec<&'static str>,
}

impl<L: Linkage<M, 1>, const M: usize> Machine<L, M> {
    pub fn model(&self) -> &L {
        &self.model
    }

    /// The bodies, resolved (for the kinetostatics).
    pub(crate) fn bodies(&self) -> &[MassBody] {
        &self.bodies
    }

    /// The loads, resolved (for the kinetostatics).
    pub(crate) fn loads(&self) -> &[ResolvedLoad] {
        &self.loads
    }

    /// The acceleration of gravity, if a load is gravity.
    pub(crate) fn gravity(&self) -> Option<Vector2<f64>> {
        self.loads.iter().find_map(|l| match l.load.kind {
            LoadKind::Gravity { g } => Some(g),
            _ => None,
        })
    }

    /// The whole analysis at φ (any real: the cycle repeats every 2π), by
    /// Newton from the nearest precomputed pose.
    pub fn analysis(&self, phi: f64) -> Result<Analysis<M, 1, L::Points>, Error> {
        let wrapped = phi.rem_euclid(TAU);
        let h = TAU / (self.grid.len() - 1) as f64;
        let k = ((wrapped / h).round() as usize).min(self.grid.len() - 1);
        let g = &self.grid[k];
        let d = wrapped - g.phi;
        let guess = g.u + g.u_phi * d + g.u_phiphi * (0.5 * d * d);
        let unit = SVector::<f64, 1>::from_element(1.0);
        self.model.analyze(
            &guess,
            &SVector::<f64, 1>::from_element(phi),
            &unit,
            &SVector::<f64, 1>::zeros(),
            &self.options,
        )
    }

    /// The pose at φ, as loads see it.
    pub fn pose(&self, phi: f64) -> Result<Pose, Error> {
        Ok(self.pose_of(phi, &self.analysis(phi)?))
    }

    /// The pose at φ from its analysis.
    pub(super) fn pose_of(&self, phi: f64, a: &Analysis<M, 1, L::Points>) -> Pose {
        let mut q: Vec<f64> = a.u.iter().copied().collect();
        q.push(phi);
        let mut q_phi: Vec<f64> = a.udot.iter().copied().collect();
        q_phi.push(1.0);
        let mut q_phiphi: Vec<f64> = a.uddot.iter().copied().collect();
        q_phiphi.push(0.0);
        Pose {
            phi,
            q,
            q_phi,
            q_phiphi,
            points: a.points.as_ref().to_vec(),
            points_phi: a.point_velocities.as_ref().to_vec(),
            points_phiphi: a.point_accelerations.as_ref().to_vec(),
            point_names: self.model().point_names(),
            coordinate_names: self.coordinates.clone(),
        }
    }

    /// The loads and weights acting at a pose: a load whose value is not
    /// finite there is an error naming it.
    pub fn applied(&self, pose: &Pose) -> Result<Vec<(usize, Applied)>, MachineError> {
        let mut out = Vec::new();
        for (i, load) in self.loads.iter().enumerate() {
            match &load.load.kind {
                LoadKind::Force { force, .. } => out.push((
                    i,
                    Applied::Force {
                        point: load.target,
                        force: force(pose),
                    },
                )),
                LoadKind::Moment { moment, .. } => out.push((
                    i,
                    Applied::Moment {
                        coordinate: load.target,
                        moment: moment(pose),
                    },
                )),
                LoadKind::Gravity { g } => {
                    for body in &self.bodies {
                        if let Some(centre) = body.centre {
                            out.push((
                                i,
                                Applied::Force {
                                    point: centre,
                                    force: body.weight(*g),
                                },
                            ));
                        }
                    }
                }
                LoadKind::Process {
                    direction, table, ..
                } => {
                    let speed = pose.points_phi[load.target].dot(direction);
                    let travel = (pose.points[load.target] - load.origin).dot(direction);
                    let magnitude = if speed > 0.0 { table.at(travel) } else { 0.0 };
                    out.push((
                        i,
                        Applied::Force {
                            point: load.target,
                            force: -direction * magnitude,
                        },
                    ));
                }
                LoadKind::Friction {
                    direction,
                    magnitude,
                    ..
                } => {
                    let speed = pose.points_phi[load.target].dot(direction);
                    let sign = if speed > 0.0 {
                        1.0
                    } else if speed < 0.0 {
                        -1.0
                    } else {
                        0.0
                    };
                    out.push((
                        i,
                        Applied::Force {
                            point: load.target,
                            force: -direction * (magnitude * sign),
                        },
                    ));
                }
            }
        }
        for &(i, applied) in &out {
            let finite = match applied {
                Applied::Force { force, .. } => force.x.is_finite() && force.y.is_finite(),
                Applied::Moment { moment, .. } => moment.is_finite(),
            };
            if !finite {
                return Err(MachineError::NonFiniteLoad {
                    load: self.loads[i].load.name.clone(),
                    phi: pose.phi,
                });
            }
        }
        Ok(out)
    }

    /// J, J′ and M at φ, with each body's and each load's share.
    pub fn reduced(&self, phi: f64) -> Result<Reduced, MachineError> {
        let pose = self.pose(phi)?;
        self.reduced_at(&pose)
    }

    pub(super) fn reduced_at(&self, pose: &Pose) -> Result<Reduced, MachineError> {
        let mut bodies = Vec::with_capacity(self.bodies.len());
        for body in &self.bodies {
            let (rotation, rotation_d) = match body.angle {
                Some(k) => {
                    let c = body.angle_factor;
                    let (w, e) = (c * pose.q_phi[k], c * pose.q_phiphi[k]);
                    (body.inertia * w * w, 2.0 * body.inertia * w * e)
                }
                None => (0.0, 0.0),
            };
            let (translation, translation_d) = match body.centre {
                Some(p) => {
                    let (v, a) = (pose.points_phi[p], pose.points_phiphi[p]);
                    (body.mass * v.norm_squared(), 2.0 * body.mass * v.dot(&a))
                }
                None => (0.0, 0.0),
            };
            bodies.push([rotation, translation, rotation_d, translation_d]);
        }
        let mut loads = vec![0.0; self.loads.len()];
        for (i, applied) in self.applied(pose)? {
            loads[i] += match applied {
                Applied::Force { point, force } => force.dot(&pose.points_phi[point]),
                Applied::Moment { coordinate, moment } => moment * pose.q_phi[coordinate],
            };
        }
        let reduced = Reduced {
            phi: pose.phi,
            inertia: bodies.iter().map(|b| b[0] + b[1]).sum(),
            inertia_derivative: bodies.iter().map(|b| b[2] + b[3]).sum(),
            moment: loads.iter().sum(),
            bodies,
            loads,
        };
        for (what, value) in [
            ("the reduced moment of inertia J", reduced.inertia),
            ("its derivative J′", reduced.inertia_derivative),
            ("the reduced moment of the loads M", reduced.moment),
        ] {
            if !value.is_finite() {
                return Err(MachineError::Overflow {
                    what,
                    phi: pose.phi,
                });
            }
        }
        Ok(reduced)
    }

    /// The functions whose sign changes mark the loads' kinks, at a pose.
    fn kink_values(&self, pose: &Pose) -> Vec<f64> {
        let mut out = Vec::new();
        for load in &self.loads {
            match &load.load.kind {
                LoadKind::Process {
                    direction, table, ..
                } => {
                    out.push(pose.points_phi[load.target].dot(direction));
                    let travel = (pose.points[load.target] - load.origin).dot(direction);
                    out.extend(table.breakpoints().map(|s| travel - s));
                }
                LoadKind::Friction { direction, .. } => {
                    out.push(pose.points_phi[load.target].dot(direction));
                }
                _ => {}
            }
            if let Some(kinks) = &load.load.kinks {
                out.extend(kinks(pose));
            }
        }
        out
    }

    /// Every kink in (0, 2π): the sign changes of the kink functions over
    /// the grid, each refined to the precision of f64.
    pub(super) fn find_kinks(&self) -> Result<Vec<f64>, MachineError> {
        let values: Vec<Vec<f64>> = self
            .grid
            .iter()
            .map(|g| self.pose(g.phi).map(|p| self.kink_values(&p)))
            .collect::<Result<_, _>>()?;
        let mut kinks = Vec::new();
        let count = values.first().map_or(0, Vec::len);
        for j in 0..count {
            for (k, pair) in values.windows(2).enumerate() {
                let (a, b) = (pair[0][j], pair[1][j]);
                let (pa, pb) = (self.grid[k].phi, self.grid[k + 1].phi);
                if a == 0.0 {
                    kinks.push(pa);
                } else if a * b < 0.0 {
                    let mut g = |phi: f64| self.pose(phi).map(|p| self.kink_values(&p)[j]);
                    kinks.push(numerics::root(&mut g, pa, pb)?);
                }
            }
        }
        kinks.retain(|&k| k > 1e-12 && k < TAU - 1e-12);
        kinks.sort_by(f64::total_cmp);
        kinks.dedup_by(|a, b| (*a - *b).abs() <= 1e-12);
        Ok(kinks)
    }

    /// The segments between kinks: [0, k₁], [k₁, k₂], …, [kₙ, 2π].
    pub(super) fn breaks(&self) -> Vec<f64> {
        let mut b = vec![0.0];
        b.extend(&self.kinks);
        b.push(TAU);
        b
    }

    /// ∫ M over [a, b], smooth there.
    fn integrate_smooth(&self, a: f64, b: f64) -> Result<f64, MachineError> {
        let mut f = |phi: f64| self.reduced(phi).map(|r| r.moment);
        numerics::integrate(&mut f, a, b, 1e-15 * self.moment_scale * (b - a).abs())
    }

    /// A at every grid pose and kink: the nodes of [`Machine::work`].
    pub(super) fn integrate_work(&self) -> Result<Vec<(f64, f64)>, MachineError> {
        let mut nodes: Vec<f64> = self
            .grid
            .iter()
            .map(|g| g.phi)
            .chain(self.kinks.iter().copied())
            .collect();
        nodes.sort_by(f64::total_cmp);
        nodes.dedup();
        let mut work = vec![(nodes[0], 0.0)];
        let mut total = 0.0;
        for w in nodes.windows(2) {
            total += self.integrate_smooth(w[0], w[1])?;
            if !total.is_finite() {
                return Err(MachineError::Overflow {
                    what: "the work of the loads",
                    phi: w[1],
                });
            }
            work.push((w[1], total));
        }
        Ok(work)
    }

    /// The φ in (0, 2π) where a load jumps or kinks.
    pub fn kinks(&self) -> &[f64] {
        &self.kinks
    }

    /// A(φ) = ∫₀^φ M dφ, the work of the loads since φ = 0, for any finite
    /// φ: over whole cycles it adds A(2π) per cycle (negative φ runs the
    /// cycle backwards), as [`Machine::analysis`] repeats the pose every
    /// 2π. The integral over a cycle is kept at every grid pose and kink,
    /// and completed from the nearest below.
    pub fn work(&self, phi: f64) -> Result<f64, MachineError> {
        if !phi.is_finite() {
            return Err(MachineError::BadSetting {
                what: "φ",
                must: "finite",
                value: phi,
            });
        }
        let cycles = (phi / TAU).floor();
        let within = (phi - cycles * TAU).clamp(0.0, TAU);
        let k = self.work.partition_point(|&(p, _)| p <= within).max(1) - 1;
        let (start, value) = self.work[k];
        let work = cycles * self.cycle_work() + value + self.integrate_smooth(start, within)?;
        if !work.is_finite() {
            return Err(MachineError::BadSetting {
                what: "φ",
                must: "small enough that the work of its cycles stays within the range of f64",
                value: phi,
            });
        }
        Ok(work)
    }

    /// A(2π): the work of the loads over a cycle.
    pub fn cycle_work(&self) -> f64 {
        self.work.last().map_or(0.0, |w| w.1)
    }

    /// The constant driving moment that balances the loads over a cycle:
    /// M_D = −A(2π)/2π.
    pub fn mean_driving_moment(&self) -> f64 {
        -self.cycle_work() / TAU
    }

    /// A(φ) at many φ.
    pub fn work_along(&self, phis: &[f64]) -> Result<Vec<f64>, MachineError> {
        phis.iter().map(|&phi| self.work(phi)).collect()
    }

    /// The flywheel by the energy method for the mean speed `omega_mean`
    /// and the coefficient of speed fluctuation `delta` (see
    /// [`EnergyMethod`]).
    pub fn energy_method(
        &self,
        omega_mean: f64,
        delta: f64,
    ) -> Result<EnergyMethod<'_, L, M>, MachineError> {
        EnergyMethod::new(self, omega_mean, delta)
    }

    /// The real periodic motion with a constant reduced inertia `inertia`
    /// (flywheel and rotors) besides J(φ), driven by `motor`, near the mean
    /// speed `omega_mean`, integrated in about `steps` Runge–Kutta steps
    /// over the cycle (10 to 10⁶; every kink is a node besides; 4000 keep
    /// the shaping machine's ω to 1e-12 relative) — see [`SteadyMotion`].
    pub fn steady_motion(
        &self,
        inertia: f64,
        motor: Motor,
        omega_mean: f64,
        steps: usize,
    ) -> Result<SteadyMotion, MachineError> {
        SteadyMotion::find(self, inertia, motor, omega_mean, steps)
    }

    /// The grid's φ values.
    pub fn grid(&self) -> impl Iterator<Item = f64> + '_ {
        self.grid.iter().map(|g| g.phi)
    }
}
