//! What a tolerance analysis follows: an [`Output`] of the pose, and the
//! pose it reads, every number carrying its gradient by the parameters
//! ([`TolerancePose`]).

use super::{ToleranceError, with_gradient};
use crate::error::{NameKind, UnknownName};
use crate::watch::{Axis, Of, Watch};
use linkage_runtime::{Motion, Sensitivities, Sensitivity};
use nalgebra::{SVector, Vector2};
use num_dual::DualSVec64;

/// A pose in motion whose coordinates and points carry their gradients by
/// the k parameters (zero in a Monte Carlo sample, whose parameters are
/// numbers).
#[derive(Clone, Debug, PartialEq)]
pub struct TolerancePose<const M: usize, const F: usize, const K: usize> {
    pub v: SVector<f64, F>,
    pub vdot: SVector<f64, F>,
    pub vddot: SVector<f64, F>,
    pub u: SVector<DualSVec64<K>, M>,
    pub udot: SVector<DualSVec64<K>, M>,
    pub uddot: SVector<DualSVec64<K>, M>,
    /// The named points, in the order of `POINT_NAMES`.
    pub points: Vec<Vector2<DualSVec64<K>>>,
    pub point_velocities: Vec<Vector2<DualSVec64<K>>>,
    pub point_accelerations: Vec<Vector2<DualSVec64<K>>>,
}

impl<const M: usize, const F: usize, const K: usize> TolerancePose<M, F, K> {
    /// The pose `motion` of `model` with its sensitivities.
    pub fn with_gradients<L: Sensitivities<M, F, K>>(
        model: &L,
        motion: &Motion<M, F>,
        sensitivity: &Sensitivity<M, K, L::Points>,
    ) -> TolerancePose<M, F, K> {
        let mut pose = TolerancePose::plain(model, motion);
        for i in 0..M {
            pose.u[i] = with_gradient(motion.u[i], sensitivity.u.row(i).transpose());
            pose.udot[i] = with_gradient(motion.udot[i], sensitivity.udot.row(i).transpose());
            pose.uddot[i] = with_gradient(motion.uddot[i], sensitivity.uddot.row(i).transpose());
        }
        let graded = |values: &mut Vec<Vector2<DualSVec64<K>>>,
                      by: fn(
            &Sensitivity<M, K, L::Points>,
            usize,
        ) -> nalgebra::SMatrix<f64, 2, K>| {
            for (i, p) in values.iter_mut().enumerate() {
                let g = by(sensitivity, i);
                *p = Vector2::new(
                    with_gradient(p.x.re, g.row(0).transpose()),
                    with_gradient(p.y.re, g.row(1).transpose()),
                );
            }
        };
        graded(&mut pose.points, Sensitivity::point);
        graded(&mut pose.point_velocities, Sensitivity::point_velocity);
        graded(
            &mut pose.point_accelerations,
            Sensitivity::point_acceleration,
        );
        pose
    }

    /// The pose `motion` of `model`, its numbers carrying no gradient.
    pub fn plain<L: Sensitivities<M, F, K>>(
        model: &L,
        motion: &Motion<M, F>,
    ) -> TolerancePose<M, F, K> {
        let zero = SVector::zeros();
        let mut pose = TolerancePose {
            v: zero,
            vdot: zero,
            vddot: zero,
            u: SVector::from_element(DualSVec64::from_re(0.0)),
            udot: SVector::from_element(DualSVec64::from_re(0.0)),
            uddot: SVector::from_element(DualSVec64::from_re(0.0)),
            points: Vec::new(),
            point_velocities: Vec::new(),
            point_accelerations: Vec::new(),
        };
        pose.set_plain(model, motion);
        pose
    }

    /// Makes this the pose `motion` of `model`, its numbers carrying no
    /// gradient, in the memory it has (a Monte Carlo sample's poses, one
    /// after the other).
    pub fn set_plain<L: Sensitivities<M, F, K>>(&mut self, model: &L, motion: &Motion<M, F>) {
        let Motion {
            u,
            v,
            udot,
            vdot,
            uddot,
            vddot,
        } = motion;
        let lift = |into: &mut Vec<Vector2<DualSVec64<K>>>, points: L::Points| {
            into.clear();
            into.extend(points.as_ref().iter().map(|p| p.map(DualSVec64::from_re)));
        };
        self.v = *v;
        self.vdot = *vdot;
        self.vddot = *vddot;
        self.u = u.map(DualSVec64::from_re);
        self.udot = udot.map(DualSVec64::from_re);
        self.uddot = uddot.map(DualSVec64::from_re);
        lift(&mut self.points, model.point_positions(u, v));
        lift(
            &mut self.point_velocities,
            model.point_velocities(u, v, udot, vdot),
        );
        lift(
            &mut self.point_accelerations,
            model.point_accelerations(u, v, udot, vdot, uddot, vddot),
        );
    }
}

/// An output of the pose whose spread the tolerances give.
pub struct Output<'a, const M: usize, const F: usize, const K: usize> {
    name: String,
    quantity: Quantity<'a, M, F, K>,
}

type PoseFunction<'a, const M: usize, const F: usize, const K: usize> =
    Box<dyn Fn(&TolerancePose<M, F, K>) -> DualSVec64<K> + Send + Sync + 'a>;

enum Quantity<'a, const M: usize, const F: usize, const K: usize> {
    Coordinate(String, Of),
    Point(String, Axis, Of),
    Path(String),
    Function(PoseFunction<'a, M, F, K>),
}

impl<'a, const M: usize, const F: usize, const K: usize> Output<'a, M, F, K> {
    /// A coordinate of u or v (its position, velocity or acceleration), by
    /// its name in the attribute.
    pub fn coordinate(name: &str, of: Of) -> Self {
        Output {
            name: describe(name, of),
            quantity: Quantity::Coordinate(name.into(), of),
        }
    }

    /// A component of a named point's position, velocity or acceleration.
    pub fn point(name: &str, axis: Axis, of: Of) -> Self {
        let component = match axis {
            Axis::X => "x",
            Axis::Y => "y",
        };
        Output {
            name: describe(&format!("{name}.{component}"), of),
            quantity: Quantity::Point(name.into(), axis, of),
        }
    }

    /// How far a named point's path moves normal to itself: n·(P − P₀),
    /// P₀ the nominal point at the same driver and n the left normal of its
    /// nominal velocity (the width of the band around a coupler curve). Not
    /// defined where the nominal point stands still.
    pub fn path(name: &str) -> Self {
        Output {
            name: format!("path of {name}"),
            quantity: Quantity::Path(name.into()),
        }
    }

    /// A function of the pose on dual numbers, which carry the gradients:
    /// the transmission angle θ4 − θ3 of a four-bar is
    /// `|p| p.u[1] - p.u[0]`.
    pub fn function(
        name: &str,
        f: impl Fn(&TolerancePose<M, F, K>) -> DualSVec64<K> + Send + Sync + 'a,
    ) -> Self {
        Output {
            name: name.into(),
            quantity: Quantity::Function(Box::new(f)),
        }
    }

    /// What it follows, for reports.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The same quantity as a [`Watch`], for a coordinate or a point.
    pub(super) fn watch(&self) -> Option<Watch<'static, M, F>> {
        match &self.quantity {
            Quantity::Coordinate(name, of) => Some(Watch::coordinate(name, *of)),
            Quantity::Point(name, axis, of) => Some(Watch::point(name, *axis, *of)),
            Quantity::Path(_) | Quantity::Function(_) => None,
        }
    }

    /// The output on the model `L`: its names resolved to indices.
    pub(super) fn resolve<L: Sensitivities<M, F, K>>(
        &self,
    ) -> Result<Resolved<'_, M, F, K>, ToleranceError> {
        let unknown = |kind, name: &str, known: Vec<&'static str>| {
            ToleranceError::UnknownName(UnknownName::new(kind, &self.name, name, known))
        };
        let point = |name: &str| {
            L::point_index(name)
                .ok_or_else(|| unknown(NameKind::Point, name, L::POINT_NAMES.to_vec()))
        };
        Ok(match &self.quantity {
            Quantity::Coordinate(name, of) => {
                if let Some(i) = L::U_NAMES.iter().position(|n| n == name) {
                    Resolved::U(i, *of)
                } else if let Some(i) = L::V_NAMES.iter().position(|n| n == name) {
                    Resolved::V(i, *of)
                } else {
                    let known = L::U_NAMES.iter().chain(&L::V_NAMES).copied().collect();
                    return Err(unknown(NameKind::Coordinate, name, known));
                }
            }
            Quantity::Point(name, axis, of) => Resolved::Point(point(name)?, *axis, *of),
            Quantity::Path(name) => Resolved::Path(point(name)?),
            Quantity::Function(f) => Resolved::Function(f.as_ref()),
        })
    }
}

fn describe(name: &str, of: Of) -> String {
    match of {
        Of::Position => name.to_owned(),
        Of::Velocity => format!("velocity of {name}"),
        Of::Acceleration => format!("acceleration of {name}"),
    }
}

/// An output with its names resolved to indices.
pub(super) enum Resolved<'o, const M: usize, const F: usize, const K: usize> {
    U(usize, Of),
    V(usize, Of),
    Point(usize, Axis, Of),
    Path(usize),
    Function(&'o (dyn Fn(&TolerancePose<M, F, K>) -> DualSVec64<K> + Send + Sync)),
}

impl<const M: usize, const F: usize, const K: usize> Resolved<'_, M, F, K> {
    /// The output at `pose`; `nominal` is the nominal design's pose at the
    /// same driver (the pose itself for the linear estimate), which a
    /// path's deviation is measured from.
    pub(super) fn at(
        &self,
        pose: &TolerancePose<M, F, K>,
        nominal: &TolerancePose<M, F, K>,
    ) -> DualSVec64<K> {
        let pick = |x: &Vector2<DualSVec64<K>>, axis: Axis| match axis {
            Axis::X => x.x,
            Axis::Y => x.y,
        };
        match *self {
            Resolved::U(i, Of::Position) => pose.u[i],
            Resolved::U(i, Of::Velocity) => pose.udot[i],
            Resolved::U(i, Of::Acceleration) => pose.uddot[i],
            Resolved::V(i, Of::Position) => DualSVec64::from_re(pose.v[i]),
            Resolved::V(i, Of::Velocity) => DualSVec64::from_re(pose.vdot[i]),
            Resolved::V(i, Of::Acceleration) => DualSVec64::from_re(pose.vddot[i]),
            Resolved::Point(i, axis, Of::Position) => pick(&pose.points[i], axis),
            Resolved::Point(i, axis, Of::Velocity) => pick(&pose.point_velocities[i], axis),
            Resolved::Point(i, axis, Of::Acceleration) => pick(&pose.point_accelerations[i], axis),
            Resolved::Path(i) => {
                let velocity = nominal.point_velocities[i].map(|x| x.re);
                let normal = Vector2::new(-velocity.y, velocity.x) / velocity.norm();
                let offset = pose.points[i] - nominal.points[i].map(|x| DualSVec64::from_re(x.re));
                offset.x * normal.x + offset.y * normal.y
            }
            Resolved::Function(f) => f(pose),
        }
    }

    /// The output's rate along the drive and that rate's gradient, for a
    /// position-level coordinate or point: its velocity at the pose.
    pub(super) fn velocity(&self, pose: &TolerancePose<M, F, K>) -> Option<DualSVec64<K>> {
        match *self {
            Resolved::U(i, Of::Position) => Some(pose.udot[i]),
            Resolved::Point(i, Axis::X, Of::Position) => Some(pose.point_velocities[i].x),
            Resolved::Point(i, Axis::Y, Of::Position) => Some(pose.point_velocities[i].y),
            _ => None,
        }
    }

    /// Its acceleration at the pose (position-level coordinates and points).
    pub(super) fn acceleration(&self, pose: &TolerancePose<M, F, K>) -> Option<DualSVec64<K>> {
        match *self {
            Resolved::U(i, Of::Position) => Some(pose.uddot[i]),
            Resolved::Point(i, Axis::X, Of::Position) => Some(pose.point_accelerations[i].x),
            Resolved::Point(i, Axis::Y, Of::Position) => Some(pose.point_accelerations[i].y),
            _ => None,
        }
    }
}
