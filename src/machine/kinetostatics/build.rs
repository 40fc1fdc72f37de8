//! Describing a force analysis: the bodies, joints, guides, ground points,
//! loads' bodies, rotors and the driver, and `build`, which resolves and
//! checks them all.

use super::{
    Kinetostatics, KinetostaticsError, PointRef, ResolvedGuide, ResolvedJoint, StaticBody,
};
use crate::error::NameKind;
use crate::ground::Ground;
use crate::machine::Machine;
use crate::machine::load::LoadKind;
use crate::quantity::{self, Names};
use crate::runtime::Linkage;
use nalgebra::Vector2;

/// How a prismatic joint's guide is directed.
#[derive(Clone, Debug, PartialEq)]
pub enum Guide {
    /// At a fixed angle (rad) from the x axis.
    Fixed(f64),
    /// Along a coordinate that is an angle: (cos q, sin q).
    Angle(String),
    /// Along the line from one point to another.
    Line(String, String),
}

#[derive(Clone, Debug, PartialEq)]
enum Kind {
    Revolute,
    Prismatic(Guide),
}

#[derive(Clone, Debug, PartialEq)]
struct Joint {
    name: String,
    bodies: (String, String),
    point: String,
    kind: Kind,
}

/// A [`Kinetostatics`] being described.
pub struct KinetostaticsBuilder<'m, L, const M: usize> {
    machine: &'m Machine<L, M>,
    ground_points: Vec<(String, Vector2<f64>)>,
    bodies: Vec<String>,
    joints: Vec<Joint>,
    load_bodies: Vec<(String, String)>,
    driver: Option<(String, f64)>,
    rotors: Vec<(String, f64, f64)>,
}

impl<'m, L: Linkage<M, 1>, const M: usize> Kinetostatics<'m, L, M> {
    /// A force analysis of `machine`, to be described.
    #[allow(clippy::new_ret_no_self)]
    pub fn new(machine: &'m Machine<L, M>) -> KinetostaticsBuilder<'m, L, M> {
        KinetostaticsBuilder {
            machine,
            ground_points: Vec::new(),
            bodies: Vec::new(),
            joints: Vec::new(),
            load_bodies: Vec::new(),
            driver: None,
            rotors: Vec::new(),
        }
    }
}

impl<'m, L: Linkage<M, 1>, const M: usize> KinetostaticsBuilder<'m, L, M> {
    /// A fixed point of the ground, for joints with the ground.
    pub fn ground_point(mut self, name: &str, at: [f64; 2]) -> Self {
        self.ground_points
            .push((name.into(), Vector2::new(at[0], at[1])));
        self
    }

    /// Every point of `ground` as a ground point (as
    /// [`KinetostaticsBuilder::ground_point`] each): the same description a
    /// scene takes.
    pub fn with_ground(mut self, ground: &Ground) -> Self {
        for (name, at) in ground.points() {
            self.ground_points.push((name.into(), at));
        }
        self
    }

    /// The next body (1, 2, …). A body of the machine keeps its mass,
    /// inertia, centre and angle; another is massless.
    pub fn body(mut self, name: &str) -> Self {
        self.bodies.push(name.into());
        self
    }

    /// A revolute joint at `point` between bodies `i` and `j` ("ground" for
    /// body 0): the reaction F_ij on i from j.
    pub fn revolute(mut self, name: &str, i: &str, j: &str, point: &str) -> Self {
        self.joints.push(Joint {
            name: name.into(),
            bodies: (i.into(), j.into()),
            point: point.into(),
            kind: Kind::Revolute,
        });
        self
    }

    /// A prismatic joint between bodies `i` and `j`, its reaction's line
    /// through `point`, sliding along `guide`: the force normal to the
    /// guide and the moment M_ij (on i, about `point`).
    pub fn prismatic(mut self, name: &str, i: &str, j: &str, point: &str, guide: Guide) -> Self {
        self.joints.push(Joint {
            name: name.into(),
            bodies: (i.into(), j.into()),
            point: point.into(),
            kind: Kind::Prismatic(guide),
        });
        self
    }

    /// The machine's load `load` acts on `body` (gravity needs no
    /// assignment: each body carries its own weight).
    pub fn load_on(mut self, load: &str, body: &str) -> Self {
        self.load_bodies.push((load.into(), body.into()));
        self
    }

    /// The body that carries the unknown balancing moment; its angle is
    /// `factor` × φ + a constant (−1 for a crank turning clockwise).
    pub fn driver(mut self, body: &str, factor: f64) -> Self {
        self.driver = Some((body.into(), factor));
        self
    }

    /// A rotor of moment of inertia `inertia` on `body`, turning at
    /// `factor` × φ̇ (a flywheel reduced to the crank): it adds the
    /// inertia moment −inertia·factor·φ̈.
    pub fn rotor(mut self, body: &str, inertia: f64, factor: f64) -> Self {
        self.rotors.push((body.into(), inertia, factor));
        self
    }

    /// Resolves every name, checks every number (finite ground points and
    /// guide angles, rotors of finite inertia ≥ 0 and finite factor, a
    /// driver factor finite and nonzero), and checks that the system is
    /// square and regular at a pose of the cycle.
    pub fn build(self) -> Result<Kinetostatics<'m, L, M>, KinetostaticsError> {
        let setting = |what, must, value: f64, ok: bool| {
            if ok && value.is_finite() {
                Ok(())
            } else {
                Err(KinetostaticsError::BadSetting { what, must, value })
            }
        };
        for (_, at) in &self.ground_points {
            for x in [at.x, at.y] {
                setting("a ground point's coordinate", "finite", x, true)?;
            }
        }
        for joint in &self.joints {
            if let Kind::Prismatic(Guide::Fixed(angle)) = joint.kind {
                setting("a fixed guide's angle", "finite", angle, true)?;
            }
        }
        for &(_, inertia, factor) in &self.rotors {
            setting(
                "a rotor's inertia",
                "finite and ≥ 0",
                inertia,
                inertia >= 0.0,
            )?;
            setting("a rotor's speed factor", "finite", factor, true)?;
        }
        if let Some((_, factor)) = self.driver {
            setting(
                "the driver's factor",
                "finite and nonzero",
                factor,
                factor != 0.0,
            )?;
        }
        let body_index = |owner: &str, name: &str| -> Result<usize, KinetostaticsError> {
            Ok(quantity::body(
                self.bodies.iter().map(String::as_str),
                owner,
                name,
            )?)
        };
        let point_names = self.machine.model().point_names();
        let point_ref = |owner: &str, name: &str| -> Result<PointRef, KinetostaticsError> {
            let known = point_names
                .iter()
                .copied()
                .chain(self.ground_points.iter().map(|(n, _)| n.as_str()));
            let k = quantity::find(NameKind::Point, owner, name, known)?;
            Ok(match k.checked_sub(point_names.len()) {
                None => PointRef::Model(k),
                Some(g) => PointRef::Ground(self.ground_points[g].1),
            })
        };
        let names = Names::of(self.machine.model());
        let mut joints = Vec::new();
        for joint in &self.joints {
            let guide = match &joint.kind {
                Kind::Revolute => None,
                Kind::Prismatic(Guide::Fixed(angle)) => {
                    Some(ResolvedGuide::Fixed(Vector2::new(angle.cos(), angle.sin())))
                }
                Kind::Prismatic(Guide::Angle(c)) => {
                    Some(ResolvedGuide::Angle(names.coordinate(&joint.name, c)?))
                }
                Kind::Prismatic(Guide::Line(a, b)) => Some(ResolvedGuide::Line(
                    point_ref(&joint.name, a)?,
                    point_ref(&joint.name, b)?,
                )),
            };
            joints.push(ResolvedJoint {
                name: joint.name.clone(),
                names: joint.bodies.clone(),
                bodies: (
                    body_index(&joint.name, &joint.bodies.0)?,
                    body_index(&joint.name, &joint.bodies.1)?,
                ),
                point: point_ref(&joint.name, &joint.point)?,
                guide,
            });
        }
        // The machine's bodies keep their masses.
        let mut bodies: Vec<StaticBody> = self
            .bodies
            .iter()
            .map(|name| StaticBody {
                name: name.clone(),
                machine_body: self.machine.bodies().iter().position(|b| &b.name == name),
                rotors: Vec::new(),
            })
            .collect();
        for (body, inertia, factor) in &self.rotors {
            let k = body_index("a rotor", body)?;
            if k == 0 {
                continue;
            }
            bodies[k - 1].rotors.push((*inertia, *factor));
        }
        // Every load of the machine but gravity acts on a named body.
        let mut load_bodies = Vec::new();
        for load in self.machine.loads() {
            if let LoadKind::Gravity { .. } = load.load.kind {
                load_bodies.push(None);
                continue;
            }
            let body = self
                .load_bodies
                .iter()
                .find(|(l, _)| *l == load.load.name)
                .ok_or_else(|| KinetostaticsError::UnassignedLoad {
                    load: load.load.name.clone(),
                })?;
            load_bodies.push(Some(body_index(&body.0, &body.1)?));
        }
        let (driver_name, driver_factor) =
            self.driver.clone().ok_or(KinetostaticsError::NoDriver)?;
        let driver = body_index("the driver", &driver_name)?;
        let prismatic = joints.iter().filter(|j| j.guide.is_some()).count();
        let unknowns = 2 * joints.len() + prismatic + 1;
        let equations = 3 * bodies.len() + prismatic;
        if unknowns != equations {
            return Err(KinetostaticsError::NotSquare {
                unknowns,
                equations,
                why: if unknowns > equations {
                    "more reactions than the equilibrium of the bodies can fix: statically indeterminate"
                } else {
                    "fewer reactions than equations: the bodies could move under the loads"
                },
            });
        }
        let statics = Kinetostatics {
            machine: self.machine,
            bodies,
            joints,
            load_bodies,
            driver,
            driver_factor,
        };
        // Regular at a generic pose of the cycle.
        statics.solve(1.0, 1.0, 0.0)?;
        Ok(statics)
    }
}
