//! A pose in motion, its numbers of any kind: plain, dual numbers that
//! carry a rate, dual vectors that carry a gradient.

use crate::runtime::{Linkage, Motion};
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
    /// The points' names ([`Kernels::point_names`](crate::Kernels::point_names)).
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

impl<N: Scalar + Copy, const M: usize, const F: usize> Pose<N, M, F> {
    /// The pose `motion` of `model`, each number made an `N` by `lift`.
    pub fn lifted<L: Linkage<M, F>>(
        model: &L,
        motion: &Motion<M, F>,
        lift: impl Fn(f64) -> N,
    ) -> Pose<N, M, F> {
        let zero = lift(0.0);
        let mut pose = Pose {
            v: SVector::from_element(zero),
            vdot: SVector::from_element(zero),
            vddot: SVector::from_element(zero),
            u: SVector::from_element(zero),
            udot: SVector::from_element(zero),
            uddot: SVector::from_element(zero),
            points: Vec::new(),
            point_velocities: Vec::new(),
            point_accelerations: Vec::new(),
            names: model.point_names(),
        };
        pose.set(model, motion, lift);
        pose
    }

    /// Makes this the pose `motion` of `model`, each number made an `N` by
    /// `lift`, in the memory it has.
    pub fn set<L: Linkage<M, F>>(
        &mut self,
        model: &L,
        motion: &Motion<M, F>,
        lift: impl Fn(f64) -> N,
    ) {
        let Motion {
            u,
            v,
            udot,
            vdot,
            uddot,
            vddot,
        } = motion;
        let points = |into: &mut Vec<Vector2<N>>, points: L::Points| {
            into.clear();
            into.extend(points.as_ref().iter().map(|p| p.map(&lift)));
        };
        points(&mut self.points, model.point_positions(u, v));
        points(
            &mut self.point_velocities,
            model.point_velocities(u, v, udot, vdot),
        );
        points(
            &mut self.point_accelerations,
            model.point_accelerations(u, v, udot, vdot, uddot, vddot),
        );
        self.v = v.map(&lift);
        self.vdot = vdot.map(&lift);
        self.vddot = vddot.map(&lift);
        self.u = u.map(&lift);
        self.udot = udot.map(&lift);
        self.uddot = uddot.map(&lift);
        self.names = model.point_names();
    }
}

impl<const M: usize, const F: usize> Pose<f64, M, F> {
    /// The pose `motion` of `model`, with its points.
    pub fn of<L: Linkage<M, F>>(model: &L, motion: &Motion<M, F>) -> Pose<f64, M, F> {
        Pose::lifted(model, motion, |x| x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanisms::FourBar;
    use nalgebra::{Vector1, Vector2};
    use num_dual::Dual64;

    #[test]
    fn a_pose_of_a_motion_holds_its_points_by_name_in_any_number() {
        let bar = FourBar::WORKSHEET;
        let motion = Motion {
            u: Vector2::new(1.2, -1.0),
            v: Vector1::new(0.3),
            udot: Vector2::new(0.5, -0.25),
            vdot: Vector1::new(2.0),
            uddot: Vector2::new(0.125, 4.0),
            vddot: Vector1::new(-1.0),
        };
        let plain = Pose::of(&bar, &motion);
        let (u, v) = (motion.u, motion.v);
        let c = bar.point_positions(&u, &v)[FourBar::C];
        assert_eq!(plain.point("C"), Some(c));
        let ddc = bar.point_accelerations(
            &u,
            &v,
            &motion.udot,
            &motion.vdot,
            &motion.uddot,
            &motion.vddot,
        )[FourBar::C];
        assert_eq!(plain.point_acceleration("C"), Some(ddc));
        assert_eq!(plain.point_velocity("Z"), None);
        assert_eq!((plain.vddot, plain.uddot), (motion.vddot, motion.uddot));
        let mut dual = Pose::lifted(&bar, &motion, Dual64::from);
        assert_eq!(dual.point("C"), Some(c.map(Dual64::from)));
        assert_eq!(dual.udot.map(|x| x.re), motion.udot);
        let moved = Motion {
            v: Vector1::new(0.4),
            ..motion
        };
        dual.set(&bar, &moved, Dual64::from);
        assert_eq!(dual.points.len(), plain.points.len());
        assert_eq!(
            dual.points[0].map(|x| x.re),
            Pose::of(&bar, &moved).points[0]
        );
        assert_ne!(dual.points[0].map(|x| x.re), plain.points[0]);
    }
}
