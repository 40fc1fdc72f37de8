//! Kinetostatics: the joint reactions and the balancing (driving) moment of
//! a one-degree-of-freedom machine in motion, from a table of bodies and
//! joints, as the course project assembles them.
//!
//! The bodies are numbered from 1 (ground is body 0). A **revolute** joint
//! between bodies i and j at a point carries a force F_ij (on i from j; j
//! feels −F_ij); a **prismatic** joint carries a force normal to its guide
//! and a moment M_ij. Every body carries its loads (the machine's, each
//! assigned to a body), its weight and its d'Alembert inertia loads taken
//! from the kinematics at the given motion (φ, ω = φ̇, ε = φ̈): −m·a_S at
//! the centre of mass, −I·ε_body, and −J·ε for a rotor (a flywheel) on it.
//! One body, the driver, carries the unknown balancing moment.
//!
//! The unknowns, in the course project's order: the x components of every joint's
//! force in the table's order, then the y components, then the prismatic
//! joints' moments, then the balancing moment. The equations: ΣFx = 0 for
//! bodies 1…n, ΣFy = 0, ΣM about the origin = 0, then one condition per
//! prismatic joint, F·guide = 0. The system must be square and regular:
//! otherwise the error names the joints whose reactions it cannot tell.
//!
//! The power balance gives the balancing moment independently:
//! M_b·ω_driver + Σ F·v + Σ M·ω (loads, weights and inertia loads) = 0;
//! [`Kinetostatics::power_balance`] computes it for the check.
//!
//! The builder and its checks are in `build.rs`; this file holds the
//! analysis: the system's assembly and solution, and the power balance.

mod build;

pub use build::{Guide, KinetostaticsBuilder};

use super::{Applied, Machine, MachineError, Pose};
use crate::error::UnknownName;
use crate::runtime::Linkage;
use nalgebra::{DMatrix, DVector, Vector2};

/// What went wrong building or solving the force analysis.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum KinetostaticsError {
    /// A number given is out of its range (a NaN or an infinity among them).
    BadSetting {
        what: &'static str,
        must: &'static str,
        value: f64,
    },
    /// The reactions came out NaN or infinite (numbers so large that the
    /// equilibrium overflows).
    NonFinite,
    UnassignedLoad {
        load: String,
    },
    NoDriver,
    /// Unknowns ≠ equations.
    NotSquare {
        unknowns: usize,
        equations: usize,
        why: &'static str,
    },
    /// The equations do not determine these joints' reactions.
    Indeterminate {
        joints: Vec<String>,
        rcond: f64,
    },
    Machine(MachineError),
    Kinematics(crate::runtime::Error),
    /// A joint, rotor, driver or load names a body, point or coordinate that
    /// neither the table nor the model defines.
    UnknownName(UnknownName),
}

crate::error::error_impls! {
    KinetostaticsError {
        Self::BadSetting { what, must, value } => ("{what} must be {must}, got {value}"),
        Self::NonFinite => ("the reactions are not finite: the loads and speeds overflow the equilibrium"),
        Self::UnassignedLoad { load } => ("the load `{load}` is not assigned to a body (use `load_on`)"),
        Self::NoDriver => ("no driver: say which body carries the balancing moment (`driver`)"),
        Self::NotSquare { equations, unknowns, why, } => ("the table gives {unknowns} unknowns (2 per revolute joint, 3 per prismatic, 1 balancing moment) but {equations} equations (3 per body, 1 per prismatic joint): {why}"),
        Self::Indeterminate { joints, rcond } => ("the reactions of the joints {joints:?} are not determined (reciprocal condition {rcond:.1e}): the structure is statically indeterminate there, or can move by itself"),
        Self::Machine(inner) => ("machine: {inner}"),
        Self::Kinematics(inner) => ("kinematics: {inner}"),
            Self::UnknownName(inner) => ("{inner}"),
    }
    wraps { Machine(MachineError), Kinematics(crate::runtime::Error), UnknownName(UnknownName) }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum PointRef {
    Model(usize),
    Ground(Vector2<f64>),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum ResolvedGuide {
    Fixed(Vector2<f64>),
    Angle(usize),
    Line(PointRef, PointRef),
}

pub(super) struct ResolvedJoint {
    pub(super) name: String,
    pub(super) names: (String, String),
    pub(super) bodies: (usize, usize),
    pub(super) point: PointRef,
    pub(super) guide: Option<ResolvedGuide>,
}

pub(super) struct StaticBody {
    pub(super) name: String,
    /// The machine body it is, if it has mass.
    pub(super) machine_body: Option<usize>,
    /// (inertia, factor) of rotors on it.
    pub(super) rotors: Vec<(f64, f64)>,
}

/// The force analysis of a machine (see the module documentation).
pub struct Kinetostatics<'m, L, const M: usize> {
    pub(super) machine: &'m Machine<L, M>,
    pub(super) bodies: Vec<StaticBody>,
    pub(super) joints: Vec<ResolvedJoint>,
    /// The body each machine load acts on (None: gravity).
    pub(super) load_bodies: Vec<Option<usize>>,
    pub(super) driver: usize,
    pub(super) driver_factor: f64,
}

/// One joint's reaction.
#[derive(Clone, Debug, PartialEq)]
pub struct JointReaction {
    pub name: String,
    /// (i, j): the force is on i from j.
    pub bodies: (String, String),
    pub force: Vector2<f64>,
    /// The moment M_ij of a prismatic joint.
    pub moment: Option<f64>,
}

impl JointReaction {
    pub fn magnitude(&self) -> f64 {
        self.force.norm()
    }

    /// The force's direction, degrees in (−180°, 180°].
    pub fn angle_degrees(&self) -> f64 {
        self.force.y.atan2(self.force.x).to_degrees()
    }
}

/// A body's loads at a pose: the external ones, the weight and the inertia
/// loads, each a force at a point or a couple.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyLoads {
    pub body: String,
    /// (point, force) pairs.
    pub forces: Vec<(Vector2<f64>, Vector2<f64>)>,
    /// The sum of the couples.
    pub couple: f64,
}

/// A body's loads, the velocities of their points, and the power of its
/// couples.
type LoadsAndPower = (BodyLoads, Vec<Vector2<f64>>, f64);

/// The solution at one pose.
#[derive(Clone, Debug, PartialEq)]
pub struct Reactions {
    pub joints: Vec<JointReaction>,
    /// The balancing moment on the driver (positive counter-clockwise).
    pub driving_moment: f64,
    /// The system A·x = b as assembled, and x, in the course project's order.
    pub matrix: DMatrix<f64>,
    pub rhs: DVector<f64>,
    pub unknowns: DVector<f64>,
    /// Each body's loads.
    pub loads: Vec<BodyLoads>,
}

impl<'m, L: Linkage<M, 1>, const M: usize> Kinetostatics<'m, L, M> {
    fn point(&self, pose: &Pose, p: PointRef) -> Vector2<f64> {
        match p {
            PointRef::Model(k) => pose.points[k],
            PointRef::Ground(at) => at,
        }
    }

    fn guide(&self, pose: &Pose, g: ResolvedGuide) -> Vector2<f64> {
        match g {
            ResolvedGuide::Fixed(d) => d,
            ResolvedGuide::Angle(k) => Vector2::new(pose.q[k].cos(), pose.q[k].sin()),
            ResolvedGuide::Line(a, b) => (self.point(pose, b) - self.point(pose, a))
                .try_normalize(0.0)
                .unwrap_or(Vector2::x()),
        }
    }

    /// Each body's loads at φ moving at ω, ε: the machine's loads, the
    /// weights, −m·a_S and −I·ε_body, rotors' −J·ε. Also each body's
    /// angular velocity, and the velocities of the forces' points, for the
    /// power balance.
    fn body_loads(
        &self,
        pose: &Pose,
        omega: f64,
        epsilon: f64,
    ) -> Result<Vec<LoadsAndPower>, MachineError> {
        let n = self.bodies.len();
        let mut out: Vec<LoadsAndPower> = self
            .bodies
            .iter()
            .map(|b| {
                (
                    BodyLoads {
                        body: b.name.clone(),
                        forces: Vec::new(),
                        couple: 0.0,
                    },
                    Vec::new(),
                    0.0,
                )
            })
            .collect();
        // Weights and inertia of the machine's bodies.
        let gravity = self.machine.gravity();
        for (k, body) in self.bodies.iter().enumerate() {
            let (forces, velocities) = {
                let entry = &mut out[k];
                (&mut entry.0.forces, &mut entry.1)
            };
            if let Some(mb) = body.machine_body {
                let b = &self.machine.bodies()[mb];
                if let Some(c) = b.centre {
                    let (p, v_q, a_q) = (pose.points[c], pose.points_phi[c], pose.points_phiphi[c]);
                    let v = v_q * omega;
                    let a = a_q * (omega * omega) + v_q * epsilon;
                    if let Some(g) = gravity {
                        forces.push((p, b.weight(g)));
                        velocities.push(v);
                    }
                    forces.push((p, -a * b.mass));
                    velocities.push(v);
                }
                if let Some(q) = b.angle {
                    let c = b.angle_factor;
                    let w = c * pose.q_phi[q] * omega;
                    let e = c * (pose.q_phiphi[q] * omega * omega + pose.q_phi[q] * epsilon);
                    out[k].0.couple += -b.inertia * e;
                    out[k].2 += -b.inertia * e * w;
                }
            }
            for &(inertia, factor) in &body.rotors {
                let (w, e) = (factor * omega, factor * epsilon);
                out[k].0.couple += -inertia * e;
                out[k].2 += -inertia * e * w;
            }
        }
        // The machine's other loads, on their bodies.
        for (load, applied) in self.machine.applied(pose)? {
            let Some(Some(body)) = self.load_bodies.get(load) else {
                continue;
            };
            if *body == 0 || *body > n {
                continue;
            }
            let entry = &mut out[body - 1];
            match applied {
                Applied::Force { point, force } => {
                    entry.0.forces.push((pose.points[point], force));
                    entry.1.push(pose.points_phi[point] * omega);
                }
                Applied::Moment { coordinate, moment } => {
                    entry.0.couple += moment;
                    entry.2 += moment * pose.q_phi[coordinate] * omega;
                }
            }
        }
        Ok(out)
    }

    /// The reactions and the balancing moment at φ, with the machine
    /// moving at ω = φ̇ and ε = φ̈ (finite).
    pub fn solve(
        &self,
        phi: f64,
        omega: f64,
        epsilon: f64,
    ) -> Result<Reactions, KinetostaticsError> {
        speeds(omega, epsilon, false)?;
        let pose = self.machine.pose(phi)?;
        let n = self.bodies.len();
        let joints = self.joints.len();
        let prismatic: Vec<usize> = (0..joints)
            .filter(|&j| self.joints[j].guide.is_some())
            .collect();
        let size = 3 * n + prismatic.len();
        let mut a = DMatrix::<f64>::zeros(size, size);
        let mut b = DVector::<f64>::zeros(size);
        let (col_x, col_y) = (|j: usize| j, |j: usize| joints + j);
        let col_m = |p: usize| 2 * joints + p;
        let col_d = 2 * joints + prismatic.len();
        for (j, joint) in self.joints.iter().enumerate() {
            let at = self.point(&pose, joint.point);
            for (body, sign) in [(joint.bodies.0, 1.0), (joint.bodies.1, -1.0)] {
                if body == 0 {
                    continue;
                }
                let r = body - 1;
                a[(r, col_x(j))] += sign;
                a[(n + r, col_y(j))] += sign;
                // About the origin: x·Fy − y·Fx.
                a[(2 * n + r, col_x(j))] += -sign * at.y;
                a[(2 * n + r, col_y(j))] += sign * at.x;
                if let Some(p) = prismatic.iter().position(|&k| k == j) {
                    a[(2 * n + r, col_m(p))] += sign;
                }
            }
        }
        if self.driver > 0 {
            a[(2 * n + self.driver - 1, col_d)] = 1.0;
        }
        for (p, &j) in prismatic.iter().enumerate() {
            let d = self.guide(
                &pose,
                self.joints[j]
                    .guide
                    .unwrap_or(ResolvedGuide::Fixed(Vector2::x())),
            );
            a[(3 * n + p, col_x(j))] = d.x;
            a[(3 * n + p, col_y(j))] = d.y;
        }
        let loads = self.body_loads(&pose, omega, epsilon)?;
        for (r, (body, _, _)) in loads.iter().enumerate() {
            let (mut fx, mut fy, mut m) = (0.0, 0.0, body.couple);
            for (p, f) in &body.forces {
                fx += f.x;
                fy += f.y;
                m += p.x * f.y - p.y * f.x;
            }
            b[r] = -fx;
            b[n + r] = -fy;
            b[2 * n + r] = -m;
        }
        let not_finite = || {
            KinetostaticsError::Kinematics(crate::runtime::Error::NonFiniteValue {
                stage: crate::runtime::Stage::Points,
                quantity: "the joint table",
            })
        };
        let svd = crate::runtime::scaled_svd(&a, true).ok_or_else(not_finite)?;
        let (smax, smin) = svd
            .singular_values
            .iter()
            .fold((0.0_f64, f64::INFINITY), |(hi, lo), &s| {
                (hi.max(s), lo.min(s))
            });
        let rcond = if smax > 0.0 { smin / smax } else { 0.0 };
        let regular = rcond > 1e-13;
        if !regular {
            // The unknowns the null space moves: their joints.
            let k = (0..svd.singular_values.len())
                .min_by(|&p, &q| svd.singular_values[p].total_cmp(&svd.singular_values[q]))
                .unwrap_or(0);
            let mut named = Vec::new();
            if let Some(v_t) = &svd.v_t {
                let row = v_t.row(k);
                let big = row.amax();
                for (c, x) in row.iter().enumerate() {
                    if x.abs() > 1e-3 * big {
                        let name = if c < 2 * joints {
                            self.joints[c % joints].name.clone()
                        } else if c < col_d {
                            self.joints[prismatic[c - 2 * joints]].name.clone()
                        } else {
                            "balancing moment".to_string()
                        };
                        if !named.contains(&name) {
                            named.push(name);
                        }
                    }
                }
            }
            return Err(KinetostaticsError::Indeterminate {
                joints: named,
                rcond,
            });
        }
        let x = a
            .clone()
            .lu()
            .solve(&b)
            .ok_or(KinetostaticsError::Indeterminate {
                joints: self.joints.iter().map(|j| j.name.clone()).collect(),
                rcond,
            })?;
        if !x.iter().chain(b.iter()).all(|v| v.is_finite()) {
            return Err(KinetostaticsError::NonFinite);
        }
        let reactions = self
            .joints
            .iter()
            .enumerate()
            .map(|(j, joint)| JointReaction {
                name: joint.name.clone(),
                bodies: joint.names.clone(),
                force: Vector2::new(x[col_x(j)], x[col_y(j)]),
                moment: prismatic.iter().position(|&k| k == j).map(|p| x[col_m(p)]),
            })
            .collect();
        Ok(Reactions {
            joints: reactions,
            driving_moment: x[col_d],
            matrix: a,
            rhs: b,
            unknowns: x,
            loads: loads.into_iter().map(|l| l.0).collect(),
        })
    }

    /// The balancing moment from the power balance alone: M_b·ω_driver +
    /// Σ F·v + Σ M·ω = 0 over every load, weight and inertia load (ω finite
    /// and nonzero: at rest the power balance says nothing of M_b).
    pub fn power_balance(
        &self,
        phi: f64,
        omega: f64,
        epsilon: f64,
    ) -> Result<f64, KinetostaticsError> {
        speeds(omega, epsilon, true)?;
        let pose = self.machine.pose(phi)?;
        let mut power = 0.0;
        for (body, velocities, couple_power) in self.body_loads(&pose, omega, epsilon)? {
            for ((_, f), v) in body.forces.iter().zip(&velocities) {
                power += f.dot(v);
            }
            power += couple_power;
        }
        let moment = -power / (self.driver_factor * omega);
        if !moment.is_finite() {
            return Err(KinetostaticsError::NonFinite);
        }
        Ok(moment)
    }
}

/// ω and ε, checked: finite, and ω nonzero where `moving`.
fn speeds(omega: f64, epsilon: f64, moving: bool) -> Result<(), KinetostaticsError> {
    let omega_ok = omega.is_finite() && (!moving || omega != 0.0);
    if !omega_ok {
        return Err(KinetostaticsError::BadSetting {
            what: "ω",
            must: if moving {
                "finite and nonzero"
            } else {
                "finite"
            },
            value: omega,
        });
    }
    if !epsilon.is_finite() {
        return Err(KinetostaticsError::BadSetting {
            what: "ε",
            must: "finite",
            value: epsilon,
        });
    }
    Ok(())
}
