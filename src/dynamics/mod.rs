//! Reduced dynamics of a one-degree-of-freedom machine: reduced moment of
//! inertia and reduced moment, work, the flywheel by the energy method, and
//! the machine's real motion.
//!
//! A machine is a `#[linkage::linkage]` model with one driver coordinate φ
//! (the generalized coordinate, usually the crank's angle), the **bodies**
//! that carry mass — each with its mass, its moment of inertia about its
//! centre of mass, the point that is its centre of mass and the coordinate
//! that is its angle, if it turns — and the **loads**: forces at points and
//! moments on coordinates, as functions of the pose, including the usual
//! kinds ready-made (a process-force diagram over a point's displacement,
//! Coulomb friction on a guide, gravity).
//!
//! Everything is reduced to φ with the kinematic analogs of the generated
//! code — v_q = dP/dφ, ω_q = dθ/dφ and their derivatives a_q, ε_q from the
//! generated second-order terms, no numerical differentiation:
//!
//! ```text
//! J(φ)   = Σ m·|v_q|² + I·ω_q²                       reduced moment of inertia
//! J′(φ)  = Σ 2m·v_q·a_q + 2I·ω_q·ε_q                 its derivative, analytic
//! M(φ)   = Σ F·v_q + Σ M·ω_q                          reduced moment of the loads
//! A(φ)   = ∫₀^φ M dφ                                   work, split at the loads' kinks
//! ```
//!
//! The equation of motion of the machine with a constant reduced inertia
//! J_I (flywheel, rotors) besides J(φ), driven by a moment M_D:
//! (J_I + J)·ε + ½·J′·ω² = M + M_D, i.e. d/dφ [½(J_I + J)ω²] = M + M_D.

pub(crate) mod numerics;
mod table;

use linkage_runtime::{Analysis, Drive, Error, Linkage, Options, SweepOptions};
use nalgebra::{SVector, Vector2};
use std::f64::consts::TAU;
use std::sync::Arc;

pub use table::Table;

/// What went wrong setting up or analysing a machine.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum MachineError {
    /// A body or load names a point the model does not have.
    UnknownPoint {
        owner: String,
        name: String,
        known: String,
    },
    /// A body or load names a coordinate the model does not have.
    UnknownCoordinate {
        owner: String,
        name: String,
        known: String,
    },
    /// A force table is not usable.
    BadTable { why: String },
    /// A number given is out of its range.
    BadSetting {
        what: &'static str,
        must: &'static str,
        value: f64,
    },
    /// The kinematics failed (the mechanism cannot be assembled, or meets a
    /// singular pose on its cycle).
    Kinematics(Error),
    /// The machine does not run a whole cycle.
    Incomplete { phi: f64, why: &'static str },
    /// The real motion stops: the kinetic energy would become negative.
    Stalls { phi: f64 },
    /// No periodic motion was found.
    NoSteadyState { omega: f64, why: &'static str },
    /// A load's value (a user's function of the pose, or a weight) is NaN
    /// or infinite at φ.
    NonFiniteLoad { load: String, phi: f64 },
    /// A reduced quantity leaves the range of f64 at φ: the masses,
    /// inertias or loads are too large for it.
    Overflow { what: &'static str, phi: f64 },
}

impl std::fmt::Display for MachineError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::UnknownPoint { known, name, owner } => write!(
                f,
                "`{owner}` names the point `{name}`, which the model does not define (its points: {known})"
            ),
            Self::UnknownCoordinate { known, name, owner } => write!(
                f,
                "`{owner}` names the coordinate `{name}`, which is neither in u nor v (coordinates: {known})"
            ),
            Self::BadTable { why } => write!(f, "the table is not usable: {why}"),
            Self::BadSetting { must, value, what } => {
                write!(f, "{what} must be {must}, got {value}")
            }
            Self::Kinematics(inner) => write!(f, "kinematics: {inner}"),
            Self::Incomplete { phi, why } => write!(
                f,
                "the mechanism does not complete its cycle: it stops at φ = {phi} ({why})"
            ),
            Self::Stalls { phi } => write!(
                f,
                "the machine stalls at φ = {phi}: its kinetic energy runs out"
            ),
            Self::NoSteadyState { omega, why } => {
                write!(f, "no periodic steady state near ω = {omega}: {why}")
            }
            Self::NonFiniteLoad { load, phi } => {
                write!(f, "the load `{load}` is not finite at φ = {phi}")
            }
            Self::Overflow { what, phi } => write!(
                f,
                "{what} leaves the range of f64 at φ = {phi}: the masses, inertias or loads are too large"
            ),
        }
    }
}

impl std::error::Error for MachineError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Kinematics(e) => Some(e),
            _ => None,
        }
    }
}

impl From<Error> for MachineError {
    fn from(e: Error) -> Self {
        Self::Kinematics(e)
    }
}

/// A body that carries mass.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    pub name: String,
    pub mass: f64,
    /// The moment of inertia about the centre of mass.
    pub inertia: f64,
    /// The point that is the centre of mass (none: the body does not
    /// translate, e.g. a rotor on a fixed axis).
    pub centre: Option<String>,
    /// The coordinate that is the body's angle (none: it does not turn).
    pub angle: Option<String>,
    /// The body's angle is `angle_factor` × the coordinate + a constant.
    pub angle_factor: f64,
}

impl Body {
    /// A massless, inertia-less body: add what it has.
    pub fn new(name: &str) -> Body {
        Body {
            name: name.into(),
            mass: 0.0,
            inertia: 0.0,
            centre: None,
            angle: None,
            angle_factor: 1.0,
        }
    }

    pub fn mass(mut self, mass: f64) -> Body {
        self.mass = mass;
        self
    }

    /// The moment of inertia about the centre of mass.
    pub fn inertia(mut self, inertia: f64) -> Body {
        self.inertia = inertia;
        self
    }

    /// The centre of mass is the model's point `point`.
    pub fn at(mut self, point: &str) -> Body {
        self.centre = Some(point.into());
        self
    }

    /// The body turns with the coordinate `coordinate` (its angle, up to a
    /// constant).
    pub fn angle(mut self, coordinate: &str) -> Body {
        self.angle = Some(coordinate.into());
        self
    }

    /// The body's angle is `factor` × `coordinate` + a constant: a crank
    /// turning clockwise as φ grows has factor −1 (angles positive
    /// counter-clockwise).
    pub fn angle_as(mut self, coordinate: &str, factor: f64) -> Body {
        self.angle = Some(coordinate.into());
        self.angle_factor = factor;
        self
    }
}

/// A pose of the machine as loads see it: positions, the kinematic
/// analogs (derivatives with respect to φ) of every coordinate and point.
#[derive(Clone, Debug, PartialEq)]
pub struct Pose {
    /// The generalized coordinate.
    pub phi: f64,
    /// q = (u, φ), q′ = dq/dφ, q″ = d²q/dφ².
    pub q: Vec<f64>,
    pub q_phi: Vec<f64>,
    pub q_phiphi: Vec<f64>,
    /// The points, their analogs v_q = dP/dφ and a_q = d²P/dφ².
    pub points: Vec<Vector2<f64>>,
    pub points_phi: Vec<Vector2<f64>>,
    pub points_phiphi: Vec<Vector2<f64>>,
    point_names: &'static [&'static str],
    coordinate_names: Vec<&'static str>,
}

impl Pose {
    fn point_index(&self, name: &str) -> Option<usize> {
        self.point_names.iter().position(|n| *n == name)
    }

    fn coordinate_index(&self, name: &str) -> Option<usize> {
        self.coordinate_names.iter().position(|n| *n == name)
    }

    /// A point's position.
    pub fn point(&self, name: &str) -> Option<Vector2<f64>> {
        self.point_index(name).map(|k| self.points[k])
    }

    /// A point's v_q = dP/dφ.
    pub fn point_analog(&self, name: &str) -> Option<Vector2<f64>> {
        self.point_index(name).map(|k| self.points_phi[k])
    }

    /// A coordinate's value.
    pub fn coordinate(&self, name: &str) -> Option<f64> {
        self.coordinate_index(name).map(|k| self.q[k])
    }

    /// A coordinate's analog dq/dφ.
    pub fn coordinate_analog(&self, name: &str) -> Option<f64> {
        self.coordinate_index(name).map(|k| self.q_phi[k])
    }
}

type ForceFn = Arc<dyn Fn(&Pose) -> Vector2<f64> + Send + Sync>;
type MomentFn = Arc<dyn Fn(&Pose) -> f64 + Send + Sync>;
type KinksFn = Arc<dyn Fn(&Pose) -> Vec<f64> + Send + Sync>;

/// What a load is.
#[derive(Clone)]
pub(crate) enum LoadKind {
    Force {
        point: String,
        force: ForceFn,
    },
    Moment {
        coordinate: String,
        moment: MomentFn,
    },
    Gravity {
        g: Vector2<f64>,
    },
    Process {
        point: String,
        direction: Vector2<f64>,
        table: Table,
    },
    Friction {
        point: String,
        direction: Vector2<f64>,
        magnitude: f64,
    },
}

/// A load on the machine (see the constructors).
#[derive(Clone)]
pub struct Load {
    pub name: String,
    pub(crate) kind: LoadKind,
    kinks: Option<KinksFn>,
}

impl std::fmt::Debug for Load {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let kind = match &self.kind {
            LoadKind::Force { point, .. } => format!("force at {point}"),
            LoadKind::Moment { coordinate, .. } => format!("moment on {coordinate}"),
            LoadKind::Gravity { g } => format!("gravity {g:?}"),
            LoadKind::Process {
                point, direction, ..
            } => format!("process force at {point} along {direction:?}"),
            LoadKind::Friction {
                point,
                direction,
                magnitude,
            } => format!("friction {magnitude} at {point} along {direction:?}"),
        };
        write!(f, "Load {{ {}: {kind} }}", self.name)
    }
}

impl Load {
    /// A force at `point`, any function of the pose. Where it jumps or
    /// kinks, say so with [`Load::kinks`] so that the work integral splits
    /// there.
    pub fn force(
        name: &str,
        point: &str,
        force: impl Fn(&Pose) -> Vector2<f64> + Send + Sync + 'static,
    ) -> Load {
        Load {
            name: name.into(),
            kind: LoadKind::Force {
                point: point.into(),
                force: Arc::new(force),
            },
            kinks: None,
        }
    }

    /// A moment on the body whose angle is `coordinate` (positive in the
    /// coordinate's sense).
    pub fn moment(
        name: &str,
        coordinate: &str,
        moment: impl Fn(&Pose) -> f64 + Send + Sync + 'static,
    ) -> Load {
        Load {
            name: name.into(),
            kind: LoadKind::Moment {
                coordinate: coordinate.into(),
                moment: Arc::new(moment),
            },
            kinks: None,
        }
    }

    /// The weights m·g of every body, at their centres of mass.
    pub fn gravity(name: &str, g: Vector2<f64>) -> Load {
        Load {
            name: name.into(),
            kind: LoadKind::Gravity { g },
            kinks: None,
        }
    }

    /// A process force — cutting, pressing, pumping — against the motion of
    /// `point` along `direction` (any finite nonzero vector: its unit vector
    /// is taken), while the point moves that way as φ grows (the working
    /// stroke), of the magnitude `table` gives for the point's displacement
    /// along `direction` since φ = 0.
    pub fn process(name: &str, point: &str, direction: Vector2<f64>, table: Table) -> Load {
        Load {
            name: name.into(),
            kind: LoadKind::Process {
                point: point.into(),
                direction,
                table,
            },
            kinks: None,
        }
    }

    /// Coulomb friction of constant magnitude against the motion of `point`
    /// along `direction` (a guide; any finite nonzero vector), zero at rest.
    pub fn friction(name: &str, point: &str, direction: Vector2<f64>, magnitude: f64) -> Load {
        Load {
            name: name.into(),
            kind: LoadKind::Friction {
                point: point.into(),
                direction,
                magnitude,
            },
            kinks: None,
        }
    }

    /// Functions of the pose whose sign changes mark where this load jumps
    /// or kinks (for [`Load::force`] and [`Load::moment`]; the other kinds
    /// know theirs).
    pub fn kinks(mut self, kinks: impl Fn(&Pose) -> Vec<f64> + Send + Sync + 'static) -> Load {
        self.kinks = Some(Arc::new(kinks));
        self
    }
}

/// A load or a weight applied at a pose: a force at a point or a moment on
/// a coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Applied {
    Force { point: usize, force: Vector2<f64> },
    Moment { coordinate: usize, moment: f64 },
}

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

/// A [`Machine`] being described.
pub struct MachineBuilder<L, const M: usize> {
    model: L,
    guess: SVector<f64, M>,
    bodies: Vec<Body>,
    loads: Vec<Load>,
    grid: usize,
    options: Options,
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
    /// seed every later position solve and bracket the loads' kinks.
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
        let coordinates: Vec<&'static str> =
            L::U_NAMES.iter().chain(&L::V_NAMES).copied().collect();
        let point = |owner: &str, name: &str| {
            L::POINT_NAMES
                .iter()
                .position(|n| *n == name)
                .ok_or_else(|| MachineError::UnknownPoint {
                    owner: owner.into(),
                    name: name.into(),
                    known: L::POINT_NAMES.join(", "),
                })
        };
        let coordinate = |owner: &str, name: &str| {
            coordinates.iter().position(|n| *n == name).ok_or_else(|| {
                MachineError::UnknownCoordinate {
                    owner: owner.into(),
                    name: name.into(),
                    known: coordinates.join(", "),
                }
            })
        };
        let mut bodies = Vec::new();
        for body in &self.bodies {
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
            bodies.push(ResolvedBody {
                name: body.name.clone(),
                angle_factor: body.angle_factor,
                mass: body.mass,
                inertia: body.inertia,
                centre: body
                    .centre
                    .as_deref()
                    .map(|p| point(&body.name, p))
                    .transpose()?,
                angle: body
                    .angle
                    .as_deref()
                    .map(|c| coordinate(&body.name, c))
                    .transpose()?,
            });
        }
        let mut loads = Vec::new();
        for load in &self.loads {
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
                | LoadKind::Friction { point: p, .. } => point(&load.name, p)?,
                LoadKind::Moment { coordinate: c, .. } => coordinate(&load.name, c)?,
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
            loads.push(ResolvedLoad {
                load,
                target,
                origin: Vector2::zeros(),
            });
        }
        // The cycle by continuation: the poses of the grid.
        let sweep = self.model.sweep(
            &self.guess,
            &Drive::Line {
                from: SVector::<f64, 1>::zeros(),
                to: SVector::<f64, 1>::from_element(TAU),
                steps: self.grid,
            },
            &SweepOptions {
                options: self.options,
                ..SweepOptions::default()
            },
        )?;
        if let Some(event) = sweep.events.first() {
            return Err(MachineError::Incomplete {
                phi: event.v[0],
                why: match event.kind {
                    linkage_runtime::EventKind::LimitPosition => "a limit position",
                    linkage_runtime::EventKind::BranchPoint => {
                        "a branch point, where the motion is not determined"
                    }
                },
            });
        }
        if !sweep.complete || sweep.poses.len() != self.grid + 1 {
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
        let grid: Vec<GridPose<M>> = sweep
            .poses
            .iter()
            .map(|p| GridPose {
                phi: p.v[0],
                u: p.u,
                u_phi: p.udot,
                u_phiphi: p.uddot,
            })
            .collect();
        let mut machine = Machine {
            model: self.model,
            bodies,
            loads,
            grid,
            options: self.options,
            kinks: Vec::new(),
            work: Vec::new(),
            moment_scale: 0.0,
            coordinates,
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

/// The unit vector of a process or friction load's direction, checked:
/// finite and nonzero.
fn unit_direction(direction: Vector2<f64>) -> Result<Vector2<f64>, MachineError> {
    let length = direction.x.hypot(direction.y);
    if length > 0.0 && length.is_finite() {
        Ok(direction / length)
    } else {
        Err(MachineError::BadSetting {
            what: "the direction of a process or friction load",
            must: "finite and nonzero",
            value: length,
        })
    }
}

pub(crate) struct ResolvedBody {
    pub(crate) name: String,
    pub(crate) mass: f64,
    pub(crate) inertia: f64,
    pub(crate) centre: Option<usize>,
    pub(crate) angle: Option<usize>,
    pub(crate) angle_factor: f64,
}

pub(crate) struct ResolvedLoad {
    pub(crate) load: Load,
    /// The point or coordinate index.
    pub(crate) target: usize,
    /// The point's position at φ = 0 (process loads).
    origin: Vector2<f64>,
}

#[derive(Clone, Copy, Debug)]
struct GridPose<const M: usize> {
    phi: f64,
    u: SVector<f64, M>,
    u_phi: SVector<f64, M>,
    u_phiphi: SVector<f64, M>,
}

/// A one-degree-of-freedom machine: a model, its bodies and loads, over
/// the cycle φ ∈ [0, 2π] (see the module documentation).
pub struct Machine<L, const M: usize> {
    model: L,
    pub(crate) bodies: Vec<ResolvedBody>,
    pub(crate) loads: Vec<ResolvedLoad>,
    grid: Vec<GridPose<M>>,
    options: Options,
    /// The loads' kinks in (0, 2π), ascending.
    kinks: Vec<f64>,
    /// (φ, A(φ)) at the grid poses and the kinks.
    work: Vec<(f64, f64)>,
    /// The largest |M| on the grid: the scale of the work's tolerance.
    moment_scale: f64,
    coordinates: Vec<&'static str>,
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

    pub fn model(&self) -> &L {
        &self.model
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
        let a = self.analysis(phi)?;
        let mut q: Vec<f64> = a.u.iter().copied().collect();
        q.push(phi);
        let mut q_phi: Vec<f64> = a.udot.iter().copied().collect();
        q_phi.push(1.0);
        let mut q_phiphi: Vec<f64> = a.uddot.iter().copied().collect();
        q_phiphi.push(0.0);
        Ok(Pose {
            phi,
            q,
            q_phi,
            q_phiphi,
            points: a.points.as_ref().to_vec(),
            points_phi: a.point_velocities.as_ref().to_vec(),
            points_phiphi: a.point_accelerations.as_ref().to_vec(),
            point_names: L::POINT_NAMES,
            coordinate_names: self.coordinates.clone(),
        })
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
                                    force: g * body.mass,
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

    fn reduced_at(&self, pose: &Pose) -> Result<Reduced, MachineError> {
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
    fn find_kinks(&self) -> Result<Vec<f64>, MachineError> {
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
    fn breaks(&self) -> Vec<f64> {
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
    fn integrate_work(&self) -> Result<Vec<(f64, f64)>, MachineError> {
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

/// The flywheel by the energy method (Merkalov's, as in the course
/// project): the kinetic energy of the variable part, T_II(φ) = ½ J(φ)ω_m²,
/// is taken at the mean speed, so that the constant part's energy varies
/// by ΔT_I(φ) = A(φ) + M_D·φ − T_II(φ); the flywheel that keeps the speed
/// within ω_m(1 ± δ/2) is J_I = (max ΔT_I − min ΔT_I)/(δ ω_m²), and
///
/// ```text
/// ω(φ) = ω_m + (ΔT_I(φ) − ½(max ΔT_I + min ΔT_I)) / (J_I ω_m)
/// ε(φ) = (M(φ) + M_D)/(J_I + J(φ)) − ω(φ)² J′(φ) / (2 (J_I + J(φ)))
/// ```
pub struct EnergyMethod<'m, L, const M: usize> {
    machine: &'m Machine<L, M>,
    pub omega_mean: f64,
    pub delta: f64,
    /// M_D = −A(2π)/2π
    pub driving_moment: f64,
    /// (φ, ΔT_I) at the minimum and the maximum of ΔT_I.
    pub minimum: (f64, f64),
    pub maximum: (f64, f64),
    /// J_I, the constant reduced inertia needed.
    pub flywheel: f64,
}

/// (φ, value) of an extremum.
pub type Extremum = (f64, f64);

impl<'m, L: Linkage<M, 1>, const M: usize> EnergyMethod<'m, L, M> {
    fn new(machine: &'m Machine<L, M>, omega_mean: f64, delta: f64) -> Result<Self, MachineError> {
        if !(omega_mean.is_finite() && omega_mean > 0.0) {
            return Err(MachineError::BadSetting {
                what: "the mean speed",
                must: "positive and finite",
                value: omega_mean,
            });
        }
        // ω_min = ω_m(1 − δ/2) must stay positive.
        if !(delta > 0.0 && delta < 2.0) {
            return Err(MachineError::BadSetting {
                what: "the coefficient of speed fluctuation δ",
                must: "between 0 and 2, exclusive",
                value: delta,
            });
        }
        let mut method = EnergyMethod {
            machine,
            omega_mean,
            delta,
            driving_moment: machine.mean_driving_moment(),
            minimum: (0.0, 0.0),
            maximum: (0.0, 0.0),
            flywheel: 0.0,
        };
        let phis: Vec<f64> = machine.grid().collect();
        let work = machine.work_along(&phis)?;
        let values: Vec<f64> = phis
            .iter()
            .zip(&work)
            .map(|(&phi, &a)| {
                machine.reduced(phi).map(|r| {
                    a + method.driving_moment * phi - 0.5 * r.inertia * omega_mean * omega_mean
                })
            })
            .collect::<Result<_, _>>()?;
        let refine = |k: usize, sign: f64| -> Result<Extremum, MachineError> {
            let lo = phis[k.saturating_sub(1)];
            let hi = phis[(k + 1).min(phis.len() - 1)];
            let mut f = |phi: f64| method.delta_t(phi).map(|v| sign * v);
            let (x, fx) = numerics::minimize(&mut f, lo, hi, 1e-11)?;
            // ΔT_I′ = M + M_D − ½ J′ ω_m² is known analytically: its root
            // places a smooth extremum to the precision of f64 (values only
            // place it to about the square root of that).
            let mut slope = |phi: f64| {
                method.machine.reduced(phi).map(|r| {
                    r.moment + method.driving_moment
                        - 0.5 * r.inertia_derivative * omega_mean * omega_mean
                })
            };
            let h = 1e-6;
            let (a, b) = (x - h, x + h);
            if slope(a)? * slope(b)? < 0.0 {
                let root = numerics::root(&mut slope, a, b)?;
                return Ok((root, method.delta_t(root)?));
            }
            Ok((x, sign * fx))
        };
        let argmin = (0..values.len())
            .min_by(|&a, &b| values[a].total_cmp(&values[b]))
            .unwrap_or(0);
        let argmax = (0..values.len())
            .max_by(|&a, &b| values[a].total_cmp(&values[b]))
            .unwrap_or(0);
        let (minimum, maximum) = (refine(argmin, 1.0)?, refine(argmax, -1.0)?);
        method.minimum = minimum;
        method.maximum = maximum;
        method.flywheel = (method.maximum.1 - method.minimum.1) / (delta * omega_mean * omega_mean);
        if !method.flywheel.is_finite() {
            return Err(MachineError::BadSetting {
                what: "the mean speed",
                must: "large enough that the flywheel J_I = ΔT/(δ·ω_m²) stays finite",
                value: omega_mean,
            });
        }
        Ok(method)
    }

    /// ΔT_I(φ) = A(φ) + M_D·φ − ½ J(φ) ω_m², periodic (M_D balances the
    /// work of a cycle): evaluated on φ wrapped to [0, 2π), so that a φ of
    /// many cycles loses no digits to the cancellation of A and M_D·φ.
    pub fn delta_t(&self, phi: f64) -> Result<f64, MachineError> {
        let r = self.machine.reduced(phi)?;
        let phi = phi.rem_euclid(TAU);
        Ok(self.machine.work(phi)? + self.driving_moment * phi
            - 0.5 * r.inertia * self.omega_mean * self.omega_mean)
    }

    /// ω(φ) (see the type's documentation).
    pub fn omega(&self, phi: f64) -> Result<f64, MachineError> {
        let middle = 0.5 * (self.maximum.1 + self.minimum.1);
        Ok(self.omega_mean + (self.delta_t(phi)? - middle) / (self.flywheel * self.omega_mean))
    }

    /// ε(φ) (see the type's documentation).
    pub fn epsilon(&self, phi: f64) -> Result<f64, MachineError> {
        let r = self.machine.reduced(phi)?;
        let omega = self.omega(phi)?;
        let total = self.flywheel + r.inertia;
        Ok((r.moment + self.driving_moment) / total
            - omega * omega * r.inertia_derivative / (2.0 * total))
    }

    /// The extremes of ω: at the extremes of ΔT_I, ω_m(1 ∓ δ/2).
    pub fn omega_extremes(&self) -> (Extremum, Extremum) {
        let half = 0.5 * self.delta * self.omega_mean;
        (
            (self.minimum.0, self.omega_mean - half),
            (self.maximum.0, self.omega_mean + half),
        )
    }

    /// The extremes of ε over the cycle: ε jumps where the loads do, so
    /// each kink-free segment is searched separately.
    pub fn epsilon_extremes(&self) -> Result<(Extremum, Extremum), MachineError> {
        let breaks = self.machine.breaks();
        let mut best_min = (0.0, f64::INFINITY);
        let mut best_max = (0.0, f64::NEG_INFINITY);
        for w in breaks.windows(2) {
            let (a, b) = (w[0], w[1]);
            let n = 64;
            let inset = 1e-9 * (b - a);
            let xs: Vec<f64> = (0..=n)
                .map(|i| (a + inset) + (b - a - 2.0 * inset) * i as f64 / n as f64)
                .collect();
            let ys: Vec<f64> = xs
                .iter()
                .map(|&x| self.epsilon(x))
                .collect::<Result<_, _>>()?;
            for (sign, best) in [(1.0, &mut best_min), (-1.0, &mut best_max)] {
                let k = (0..ys.len())
                    .min_by(|&p, &q| (sign * ys[p]).total_cmp(&(sign * ys[q])))
                    .unwrap_or(0);
                let (lo, hi) = (xs[k.saturating_sub(1)], xs[(k + 1).min(n)]);
                let mut f = |phi: f64| self.epsilon(phi).map(|v| sign * v);
                let (x, fx) = numerics::minimize(&mut f, lo, hi, 1e-10)?;
                let value = sign * fx;
                if sign * value < sign * best.1 {
                    *best = (x, value);
                }
            }
        }
        Ok((best_min, best_max))
    }
}

/// How the machine is driven.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Motor {
    /// A constant reduced driving moment.
    Constant { moment: f64 },
    /// A linear characteristic, reduced to φ: M_D(ω) = moment − slope·(ω −
    /// speed) (an induction motor near its working point).
    Linear { moment: f64, speed: f64, slope: f64 },
}

impl Motor {
    /// Every number finite, the working speed positive.
    fn check(&self) -> Result<(), MachineError> {
        let bad = |what, must, value| Err(MachineError::BadSetting { what, must, value });
        match *self {
            Motor::Constant { moment } if !moment.is_finite() => {
                bad("the driving moment", "finite", moment)
            }
            Motor::Linear { moment, .. } if !moment.is_finite() => {
                bad("the driving moment", "finite", moment)
            }
            Motor::Linear { speed, .. } if !(speed.is_finite() && speed > 0.0) => {
                bad("the motor's working speed", "positive and finite", speed)
            }
            Motor::Linear { slope, .. } if !slope.is_finite() => {
                bad("the motor characteristic's slope", "finite", slope)
            }
            _ => Ok(()),
        }
    }

    fn moment(&self, omega: f64) -> f64 {
        match *self {
            Motor::Constant { moment } => moment,
            Motor::Linear {
                moment,
                speed,
                slope,
            } => moment - slope * (omega - speed),
        }
    }
}

/// The machine's real periodic motion: d/dφ[½(J_I + J(φ))ω²] = M(φ) +
/// M_D(ω), integrated over a cycle (classical Runge–Kutta in the kinetic
/// energy, restarted at every kink) and shot on ω(0) until ω(2π) = ω(0).
/// With a constant driving moment every start is periodic (the energy
/// balances over a cycle); the shooting then fixes the mean speed,
/// ½(ω_max + ω_min) = ω_m, instead. The extremes of ω are located between
/// the grid's nodes, where ε = 0, on the Runge–Kutta solution continued
/// from the node before (or at a kink, where ε jumps through zero).
#[derive(Clone, Debug, PartialEq)]
pub struct SteadyMotion {
    /// The integration grid: about the requested number of steps, every
    /// kink a node.
    pub phi: Vec<f64>,
    pub omega: Vec<f64>,
    pub epsilon: Vec<f64>,
    /// (φ, ω) at the smallest and the largest ω, located.
    pub omega_min: Extremum,
    pub omega_max: Extremum,
    /// (ω_max − ω_min)/ω_m, ω_m = ½(ω_max + ω_min): the fluctuation achieved.
    pub delta: f64,
    /// The time of a cycle.
    pub period: f64,
}

impl SteadyMotion {
    fn find<L: Linkage<M, 1>, const M: usize>(
        machine: &Machine<L, M>,
        inertia: f64,
        motor: Motor,
        omega_mean: f64,
        steps: usize,
    ) -> Result<SteadyMotion, MachineError> {
        for (what, value) in [
            ("the constant inertia", inertia),
            ("the mean speed", omega_mean),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(MachineError::BadSetting {
                    what,
                    must: "positive and finite",
                    value,
                });
            }
        }
        motor.check()?;
        if !(10..=1_000_000).contains(&steps) {
            return Err(MachineError::BadSetting {
                what: "the number of integration steps",
                must: "from 10 to 10⁶",
                value: steps as f64,
            });
        }
        // The integration grid: about `steps` steps, every kink a node.
        let mut phis = Vec::new();
        for w in machine.breaks().windows(2) {
            let n = ((w[1] - w[0]) / TAU * steps as f64).ceil().max(2.0) as usize;
            for i in 0..n {
                phis.push(w[0] + (w[1] - w[0]) * i as f64 / n as f64);
            }
        }
        phis.push(TAU);
        let reduced: Vec<Reduced> = phis
            .iter()
            .map(|&p| machine.reduced(p))
            .collect::<Result<_, _>>()?;
        let grid = Step::along(machine, &phis)?;
        let accelerate = |r: &Reduced, w: f64| {
            (r.moment + motor.moment(w) - 0.5 * r.inertia_derivative * w * w)
                / (inertia + r.inertia)
        };
        // The motion from ω(0) = omega0: ω and ε at the nodes, and the
        // located extremes of ω.
        let run = |omega0: f64| -> Result<(Vec<f64>, Vec<f64>, Extremum, Extremum), MachineError> {
            let omega = integrate_energy(&grid, &phis, inertia, motor, omega0)?;
            let epsilon: Vec<f64> = reduced
                .iter()
                .zip(&omega)
                .map(|(r, &w)| accelerate(r, w))
                .collect();
            // (ω, ε) at φ between the nodes k and k + 1: one Runge–Kutta
            // step from node k, by the rule that made the grid.
            let continued = |k: usize, phi: f64| -> Result<(f64, f64), MachineError> {
                let h = phi - phis[k];
                if h == 0.0 {
                    return Ok((omega[k], epsilon[k]));
                }
                let at = |x: f64| machine.reduced(x).map(|r| (r.inertia, r.moment));
                let step = Step {
                    h,
                    nodes: [grid[k].nodes[0], at(phis[k] + 0.5 * h)?, at(phi)?],
                };
                let w = integrate_energy(&[step], &phis[k..], inertia, motor, omega[k])?[1];
                Ok((w, accelerate(&machine.reduced(phi)?, w)))
            };
            // An extreme of ω where ε changes sign next to the nodes'
            // extreme (from + to − at a maximum: `sign` = 1); at the node
            // itself if it does not (a kink, where ε jumps through zero).
            let locate = |k: usize, sign: f64| -> Result<Extremum, MachineError> {
                let before = k.checked_sub(1);
                let after = (k + 1 < phis.len()).then_some(k);
                for j in [before, after].into_iter().flatten() {
                    if sign * epsilon[j] > 0.0 && sign * epsilon[j + 1] < 0.0 {
                        let mut g = |phi: f64| continued(j, phi).map(|(_, e)| e);
                        let root = numerics::root(&mut g, phis[j], phis[j + 1])?;
                        return Ok((root, continued(j, root)?.0));
                    }
                }
                Ok((phis[k], omega[k]))
            };
            let kmin = (0..omega.len())
                .min_by(|&a, &b| omega[a].total_cmp(&omega[b]))
                .unwrap_or(0);
            let kmax = (0..omega.len())
                .max_by(|&a, &b| omega[a].total_cmp(&omega[b]))
                .unwrap_or(0);
            let (lo, hi) = (locate(kmin, -1.0)?, locate(kmax, 1.0)?);
            Ok((omega, epsilon, lo, hi))
        };
        let omega0 = match motor {
            Motor::Constant { .. } => {
                // ½(ω_max + ω_min) = ω_m.
                let mut g = |w0: f64| -> Result<f64, MachineError> {
                    let (_, _, lo, hi) = run(w0)?;
                    Ok(0.5 * (lo.1 + hi.1) - omega_mean)
                };
                bracket_root(&mut g, omega_mean)?
            }
            Motor::Linear { .. } => {
                let mut g = |w0: f64| -> Result<f64, MachineError> {
                    let w = integrate_energy(&grid, &phis, inertia, motor, w0)?;
                    Ok(w[w.len() - 1] - w0)
                };
                bracket_root(&mut g, omega_mean)?
            }
        };
        let (omega, epsilon, omega_min, omega_max) = run(omega0)?;
        let mean = 0.5 * (omega_min.1 + omega_max.1);
        // t = ∫ dφ/ω, by the trapezoid rule on the fine grid.
        let period = phis
            .windows(2)
            .zip(omega.windows(2))
            .map(|(p, w)| 0.5 * (p[1] - p[0]) * (1.0 / w[0] + 1.0 / w[1]))
            .sum();
        Ok(SteadyMotion {
            phi: phis,
            omega,
            epsilon,
            omega_min,
            omega_max,
            delta: (omega_max.1 - omega_min.1) / mean,
            period,
        })
    }
}

/// (J(φ), M(φ)) at the three points of one Runge–Kutta step: its start
/// and end taken just inside the step where they are kinks (one-sided),
/// and its middle.
struct Step {
    h: f64,
    nodes: [(f64, f64); 3],
}

impl Step {
    fn along<L: Linkage<M, 1>, const M: usize>(
        machine: &Machine<L, M>,
        phis: &[f64],
    ) -> Result<Vec<Step>, MachineError> {
        let is_kink = |x: f64| machine.kinks.contains(&x);
        let at = |phi: f64| machine.reduced(phi).map(|r| (r.inertia, r.moment));
        phis.windows(2)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                let h = b - a;
                let inside = 1e-12 * h;
                Ok(Step {
                    h,
                    nodes: [
                        at(if is_kink(a) { a + inside } else { a })?,
                        at(0.5 * (a + b))?,
                        at(if is_kink(b) { b - inside } else { b })?,
                    ],
                })
            })
            .collect()
    }
}

/// ω at the steps' ends from ω(0) = omega0: classical Runge–Kutta on the
/// kinetic energy T = ½(J_I + J)ω², dT/dφ = M(φ) + M_D(ω).
fn integrate_energy(
    steps: &[Step],
    phis: &[f64],
    inertia: f64,
    motor: Motor,
    omega0: f64,
) -> Result<Vec<f64>, MachineError> {
    let rate = |(j, m): (f64, f64), t: f64, phi: f64| -> Result<f64, MachineError> {
        if t <= 0.0 {
            return Err(MachineError::Stalls { phi });
        }
        Ok(m + motor.moment((2.0 * t / (inertia + j)).sqrt()))
    };
    let mut t = 0.5 * (inertia + steps[0].nodes[0].0) * omega0 * omega0;
    let mut omega = vec![omega0];
    for (k, step) in steps.iter().enumerate() {
        let (h, [a, mid, b]) = (step.h, step.nodes);
        let phi = phis[k];
        let k1 = rate(a, t, phi)?;
        let k2 = rate(mid, t + 0.5 * h * k1, phi)?;
        let k3 = rate(mid, t + 0.5 * h * k2, phi)?;
        let k4 = rate(b, t + h * k3, phi)?;
        t += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        if t <= 0.0 {
            return Err(MachineError::Stalls { phi: phis[k + 1] });
        }
        omega.push((2.0 * t / (inertia + b.0)).sqrt());
    }
    Ok(omega)
}

/// A root of g near x0 (> 0): bracketed by widening steps, then refined.
fn bracket_root(
    g: &mut impl FnMut(f64) -> Result<f64, MachineError>,
    x0: f64,
) -> Result<f64, MachineError> {
    let mut step = 0.02 * x0;
    let g0 = g(x0)?;
    if g0 == 0.0 {
        return Ok(x0);
    }
    for _ in 0..40 {
        for x in [x0 + step, (x0 - step).max(1e-9 * x0)] {
            let gx = match g(x) {
                Ok(v) => v,
                Err(MachineError::Stalls { .. }) => continue,
                Err(e) => return Err(e),
            };
            if gx == 0.0 {
                return Ok(x);
            }
            if (gx > 0.0) != (g0 > 0.0) {
                return numerics::root(g, x0, x);
            }
        }
        step *= 1.6;
    }
    Err(MachineError::NoSteadyState {
        omega: x0,
        why: "no sign change of the periodicity condition within a wide bracket",
    })
}

/// Reductions between shafts and the flywheel's rim, as in the course
/// project. Each checks its numbers: finite, and of the sign the formula
/// needs.
pub mod flywheel {
    use super::MachineError;

    fn check(
        what: &'static str,
        must: &'static str,
        value: f64,
        ok: bool,
    ) -> Result<f64, MachineError> {
        if ok && value.is_finite() {
            Ok(value)
        } else {
            Err(MachineError::BadSetting { what, must, value })
        }
    }

    /// J of a rotor from its mD² (kg·m², ≥ 0): J = mD²/4 (D its diameter).
    pub fn from_md2(md2: f64) -> Result<f64, MachineError> {
        Ok(check("mD²", "finite and ≥ 0", md2, md2 >= 0.0)? / 4.0)
    }

    /// The flywheel on the motor shaft for a constant reduced inertia
    /// `required` at the crank, a transmission ratio `ratio` (motor speed /
    /// crank speed, nonzero), the motor's rotor `motor` (at its shaft) and
    /// the gears `gears` (already reduced to the crank), inertias ≥ 0:
    /// J_fw = (J_required − J_motor·u² − J_gears)/u². Negative when the
    /// rotors already exceed what is required.
    pub fn on_motor_shaft(
        required: f64,
        ratio: f64,
        motor: f64,
        gears: f64,
    ) -> Result<f64, MachineError> {
        let must = "finite and ≥ 0";
        check("the required inertia", must, required, required >= 0.0)?;
        check("the motor rotor's inertia", must, motor, motor >= 0.0)?;
        check("the gears' inertia", must, gears, gears >= 0.0)?;
        check(
            "the transmission ratio",
            "finite and nonzero",
            ratio,
            ratio != 0.0,
        )?;
        let u2 = ratio * ratio;
        let flywheel = (required - motor * u2 - gears) / u2;
        check(
            "the flywheel's inertia",
            "finite (the numbers overflow)",
            flywheel,
            true,
        )
    }

    /// A rim flywheel by the course's rules of thumb: outer diameter D2 =
    /// 0.437·J^(1/5) (m, J in kg·m²), inner D1 = 0.8·D2, width b = 0.2·D2,
    /// mass m = 6123·(D2² − D1²)·b (6123 ≈ ρπ/4 for steel, ρ = 7.8 t/m³).
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Rim {
        pub outer: f64,
        pub inner: f64,
        pub width: f64,
        pub mass: f64,
    }

    impl Rim {
        /// The rim for a moment of inertia `inertia` (kg·m², finite and
        /// ≥ 0).
        pub fn course_rule(inertia: f64) -> Result<Rim, MachineError> {
            let inertia = check(
                "the flywheel's inertia",
                "finite and ≥ 0",
                inertia,
                inertia >= 0.0,
            )?;
            let outer = 0.437 * inertia.powf(0.2);
            let inner = 0.8 * outer;
            let width = 0.2 * outer;
            let rim = Rim {
                outer,
                inner,
                width,
                mass: 6123.0 * (outer * outer - inner * inner) * width,
            };
            check(
                "the flywheel's inertia",
                "small enough that the rim's mass and inertia stay finite",
                inertia,
                rim.mass.is_finite() && rim.inertia().is_finite(),
            )?;
            Ok(rim)
        }

        /// The rim's own moment of inertia, m(D2² + D1²)/8 (without hub
        /// and spokes, which the rule's coefficient allows for).
        pub fn inertia(&self) -> f64 {
            self.mass * (self.outer * self.outer + self.inner * self.inner) / 8.0
        }
    }
}
