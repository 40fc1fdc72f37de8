//! A pose in motion, its numbers of any kind: plain, dual numbers that
//! carry a rate, dual vectors that carry a gradient.

use linkage_runtime::{Linkage, Motion};
use nalgebra::{SVector, Scalar, Vector2};

/// A pose of a model with its velocities and accelerations, every number
/// an `N`: `f64` ([`Pose::of`]), a dual number that carries the rate along
/// a drive ([`PathPose`](crate::watch::PathPose)) or a dual vector that
/// carries the gradient by the parameters
/// ([`TolerancePose`](crate::tolerance::TolerancePose)).
#[derive(Clone, Debug, PartialEq)]
pub struct Pose<N: Scalar, const M: usize, const F: usize> {
    pub v: SVector<N, F>,
    pub vdot: SVector<N, F>,
    pub vddot: SVector<N, F>,
    pub u: SVector<N, M>,
    pub udot: SVector<N, M>,
    pub uddot: SVector<N, M>,
    /// The named points, in the order of `names`.
    pub points: Vec<Vector2<N>>,
    pub point_velocities: Vec<Vector2<N>>,
    pub point_accelerations: Vec<Vector2<N>>,
    /// The points' names ([`Linkage::POINT_NAMES`]).
    pub names: &'static [&'static str],
}

impl<N: Scalar + Copy, const M: usize, const F: usize> Pose<N, M, F> {
    /// The position of the point `name`, if the model has it.
    pub fn point(&self, name: &str) -> Option<Vector2<N>> {
        self.index(name).map(|i| self.points[i])
    }

    /// The velocity of the point `name`, if the model has it.
    pub fn point_velocity(&self, name: &str) -> Option<Vector2<N>> {
        self.index(name).map(|i| self.point_velocities[i])
    }

    /// The acceleration of the point `name`, if the model has it.
    pub fn point_acceleration(&self, name: &str) -> Option<Vector2<N>> {
        self.index(name).map(|i| self.point_accelerations[i])
    }

    fn index(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| *n == name)
    }
}

impl<const M: usize, const F: usize> Pose<f64, M, F> {
    /// The pose `motion` of `model`, with its points.
    pub fn of<L: Linkage<M, F>>(model: &L, motion: &Motion<M, F>) -> Pose<f64, M, F> {
        let Motion {
            u,
            v,
            udot,
            vdot,
            uddot,
            vddot,
        } = motion;
        Pose {
            v: *v,
            vdot: *vdot,
            vddot: *vddot,
            u: *u,
            udot: *udot,
            uddot: *uddot,
            points: model.point_positions(u, v).as_ref().to_vec(),
            point_velocities: model.point_velocities(u, v, udot, vdot).as_ref().to_vec(),
            point_accelerations: model
                .point_accelerations(u, v, udot, vdot, uddot, vddot)
                .as_ref()
                .to_vec(),
            names: L::POINT_NAMES,
        }
    }
}
