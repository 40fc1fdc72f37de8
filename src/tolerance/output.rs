//! What a tolerance analysis follows: an [`Output`] of the pose, and the
//! pose it reads, every number carrying its gradient by the parameters
//! ([`TolerancePose`]).

use super::{ToleranceError, with_gradient};
use crate::quantity::{self, Axis, Names, Of, Pose, Quantity};
use crate::runtime::{Motion, Sensitivities, Sensitivity};
use crate::watch::Watch;
use nalgebra::Vector2;
use num_dual::DualSVec64;

/// A pose in motion whose coordinates and points carry their gradients by
/// the k parameters (zero in a Monte Carlo sample, whose parameters are
/// numbers); the drivers, given, carry none.
pub type TolerancePose<const M: usize, const F: usize, const K: usize> = Pose<DualSVec64<K>, M, F>;

impl<const M: usize, const F: usize, const K: usize> Pose<DualSVec64<K>, M, F> {
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
        Pose::lifted(model, motion, DualSVec64::from_re)
    }

    /// Makes this the pose `motion` of `model`, its numbers carrying no
    /// gradient, in the memory it has (a Monte Carlo sample's poses, one
    /// after the other).
    pub fn set_plain<L: Sensitivities<M, F, K>>(&mut self, model: &L, motion: &Motion<M, F>) {
        self.set(model, motion, DualSVec64::from_re);
    }
}

/// An output of the pose whose spread the tolerances give.
pub struct Output<'a, const M: usize, const F: usize, const K: usize> {
    output: Outputs<'a, M, F, K>,
}

type PoseFunction<'a, const M: usize, const F: usize, const K: usize> =
    Box<dyn Fn(&TolerancePose<M, F, K>) -> DualSVec64<K> + Send + Sync + 'a>;

enum Outputs<'a, const M: usize, const F: usize, const K: usize> {
    Quantity(Quantity<PoseFunction<'a, M, F, K>>),
    /// The path of the point, so named.
    Path {
        name: String,
        point: String,
    },
}

impl<'a, const M: usize, const F: usize, const K: usize> Output<'a, M, F, K> {
    fn of(quantity: Quantity<PoseFunction<'a, M, F, K>>) -> Self {
        Output {
            output: Outputs::Quantity(quantity),
        }
    }

    /// A coordinate of u or v (its position, velocity or acceleration), by
    /// its name in the attribute.
    pub fn coordinate(name: &str, of: Of) -> Self {
        Output::of(Quantity::coordinate(name, of))
    }

    /// A component of a named point's position, velocity or acceleration.
    pub fn point(name: &str, axis: Axis, of: Of) -> Self {
        Output::of(Quantity::point(name, axis, of))
    }

    /// How far a named point's path moves normal to itself: n·(P − P₀),
    /// P₀ the nominal point at the same driver and n the left normal of its
    /// nominal velocity (the width of the band around a coupler curve). Not
    /// defined where the nominal point stands still.
    pub fn path(name: &str) -> Self {
        Output {
            output: Outputs::Path {
                name: format!("path of {name}"),
                point: name.into(),
            },
        }
    }

    /// A function of the pose on dual numbers, which carry the gradients:
    /// the transmission angle θ4 − θ3 of a four-bar is
    /// `|p| p.u[1] - p.u[0]`.
    pub fn function(
        name: &str,
        f: impl Fn(&TolerancePose<M, F, K>) -> DualSVec64<K> + Send + Sync + 'a,
    ) -> Self {
        Output::of(Quantity::function(name, Box::new(f)))
    }

    /// What it follows, for reports.
    pub fn name(&self) -> &str {
        match &self.output {
            Outputs::Quantity(quantity) => quantity.name(),
            Outputs::Path { name, .. } => name,
        }
    }

    /// The same quantity as a [`Watch`], for a coordinate or a point.
    pub(super) fn watch(&self) -> Option<Watch<'static, M, F>> {
        match &self.output {
            Outputs::Quantity(quantity) => Watch::named(quantity),
            Outputs::Path { .. } => None,
        }
    }

    /// The output on the model `L`: its names resolved to indices.
    pub(super) fn resolve<L: Sensitivities<M, F, K>>(
        &self,
        model: &L,
    ) -> Result<Resolved<'_, M, F, K>, ToleranceError> {
        let names = Names::of(model);
        Ok(match &self.output {
            Outputs::Quantity(quantity) => Resolved::Quantity(quantity.resolve(&names)?),
            Outputs::Path { name, point } => Resolved::Path(names.point(name, point)?),
        })
    }
}

/// An output with its names resolved to indices.
pub(super) enum Resolved<'o, const M: usize, const F: usize, const K: usize> {
    Quantity(quantity::Resolved<&'o PoseFunction<'o, M, F, K>>),
    /// The path of the point `points[i]`.
    Path(usize),
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
        match self {
            Resolved::Quantity(quantity) => quantity.at(pose),
            Resolved::Path(i) => {
                let i = *i;
                let velocity = nominal.point_velocities[i].map(|x| x.re);
                let normal = Vector2::new(-velocity.y, velocity.x) / velocity.norm();
                let offset = pose.points[i] - nominal.points[i].map(|x| DualSVec64::from_re(x.re));
                offset.x * normal.x + offset.y * normal.y
            }
        }
    }

    /// The output's rate along the drive and that rate's gradient, for a
    /// position-level coordinate or point: its velocity at the pose.
    pub(super) fn velocity(&self, pose: &TolerancePose<M, F, K>) -> Option<DualSVec64<K>> {
        match self {
            Resolved::Quantity(quantity) => quantity.velocity(pose),
            Resolved::Path(_) => None,
        }
    }

    /// Its acceleration at the pose (position-level coordinates and points).
    pub(super) fn acceleration(&self, pose: &TolerancePose<M, F, K>) -> Option<DualSVec64<K>> {
        match self {
            Resolved::Quantity(quantity) => quantity.acceleration(pose),
            Resolved::Path(_) => None,
        }
    }
}
