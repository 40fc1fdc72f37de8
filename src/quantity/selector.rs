//! A quantity of a pose chosen by name: what it is called in reports, how
//! its names resolve on a model, and its value at a pose.

use super::{Axis, Names, Of, Pose};
use crate::error::UnknownName;
use nalgebra::{Scalar, Vector2};

/// A quantity of a pose: a coordinate of u or v or a component of a named
/// point, at position, velocity or acceleration level, or a function `G`
/// of the pose; with the name reports give it.
pub struct Quantity<G> {
    name: String,
    selects: Selects<G>,
}

enum Selects<G> {
    Coordinate(String, Of),
    Point(String, Axis, Of),
    Function(G),
}

impl<G> Quantity<G> {
    /// A coordinate of u or v, by its name in the attribute: reported as
    /// "s", "velocity of s" or "acceleration of s".
    pub fn coordinate(name: &str, of: Of) -> Self {
        Quantity {
            name: describe(name, of),
            selects: Selects::Coordinate(name.into(), of),
        }
    }

    /// A component of a named point: reported as "P.x", "velocity of P.x",
    /// ….
    pub fn point(name: &str, axis: Axis, of: Of) -> Self {
        let component = match axis {
            Axis::X => "x",
            Axis::Y => "y",
        };
        Quantity {
            name: describe(&format!("{name}.{component}"), of),
            selects: Selects::Point(name.into(), axis, of),
        }
    }

    /// A function of the pose, reported by `name`.
    pub fn function(name: &str, f: G) -> Self {
        Quantity {
            name: name.into(),
            selects: Selects::Function(f),
        }
    }

    /// What it is, for reports.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The same coordinate or point with another type of function; `None`
    /// for a function.
    pub fn named<H>(&self) -> Option<Quantity<H>> {
        let selects = match &self.selects {
            Selects::Coordinate(name, of) => Selects::Coordinate(name.clone(), *of),
            Selects::Point(name, axis, of) => Selects::Point(name.clone(), *axis, *of),
            Selects::Function(_) => return None,
        };
        Some(Quantity {
            name: self.name.clone(),
            selects,
        })
    }

    /// The quantity on the model of `names`: its names resolved to
    /// indices; a name the model does not have is an error that names
    /// this quantity.
    pub fn resolve(&self, names: &Names) -> Result<Resolved<&G>, UnknownName> {
        Ok(match &self.selects {
            Selects::Coordinate(name, of) => match names.split(names.coordinate(&self.name, name)?)
            {
                (false, i) => Resolved::U(i, *of),
                (true, i) => Resolved::V(i, *of),
            },
            Selects::Point(name, axis, of) => {
                Resolved::Point(names.point(&self.name, name)?, *axis, *of)
            }
            Selects::Function(f) => Resolved::Function(f),
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

/// A quantity with its names resolved to indices into a [`Pose`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Resolved<G> {
    /// The coordinate `u[i]`.
    U(usize, Of),
    /// The driver `v[i]`.
    V(usize, Of),
    /// The point `points[i]`.
    Point(usize, Axis, Of),
    Function(G),
}

fn pick<N: Scalar + Copy>(x: &Vector2<N>, axis: Axis) -> N {
    match axis {
        Axis::X => x.x,
        Axis::Y => x.y,
    }
}

impl<G> Resolved<G> {
    /// The quantity at `pose`.
    pub fn at<N, const M: usize, const F: usize>(&self, pose: &Pose<N, M, F>) -> N
    where
        N: Scalar + Copy,
        G: Fn(&Pose<N, M, F>) -> N,
    {
        match self {
            Resolved::U(i, Of::Position) => pose.u[*i],
            Resolved::U(i, Of::Velocity) => pose.udot[*i],
            Resolved::U(i, Of::Acceleration) => pose.uddot[*i],
            Resolved::V(i, Of::Position) => pose.v[*i],
            Resolved::V(i, Of::Velocity) => pose.vdot[*i],
            Resolved::V(i, Of::Acceleration) => pose.vddot[*i],
            Resolved::Point(i, axis, Of::Position) => pick(&pose.points[*i], *axis),
            Resolved::Point(i, axis, Of::Velocity) => pick(&pose.point_velocities[*i], *axis),
            Resolved::Point(i, axis, Of::Acceleration) => {
                pick(&pose.point_accelerations[*i], *axis)
            }
            Resolved::Function(f) => f(pose),
        }
    }

    /// The velocity at `pose` of a position-level coordinate of u or
    /// point (the rate of the quantity in time); `None` for any other.
    pub fn velocity<N, const M: usize, const F: usize>(&self, pose: &Pose<N, M, F>) -> Option<N>
    where
        N: Scalar + Copy,
    {
        match self {
            Resolved::U(i, Of::Position) => Some(pose.udot[*i]),
            Resolved::Point(i, axis, Of::Position) => Some(pick(&pose.point_velocities[*i], *axis)),
            _ => None,
        }
    }

    /// The acceleration at `pose` of a position-level coordinate of u or
    /// point; `None` for any other.
    pub fn acceleration<N, const M: usize, const F: usize>(&self, pose: &Pose<N, M, F>) -> Option<N>
    where
        N: Scalar + Copy,
    {
        match self {
            Resolved::U(i, Of::Position) => Some(pose.uddot[*i]),
            Resolved::Point(i, axis, Of::Position) => {
                Some(pick(&pose.point_accelerations[*i], *axis))
            }
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::NameKind;
    use nalgebra::{Vector1, Vector2};
    use num_dual::Dual64;

    type Plain = Pose<f64, 2, 1>;
    type Fun = fn(&Plain) -> f64;

    fn names() -> Names {
        Names::of(&crate::mechanisms::FourBar::WORKSHEET)
    }

    fn pose() -> Plain {
        let p = |x: f64, y: f64| vec![Vector2::new(x, y), Vector2::new(x + 10.0, y + 20.0)];
        Pose {
            v: Vector1::new(1.0),
            vdot: Vector1::new(2.0),
            vddot: Vector1::new(3.0),
            u: Vector2::new(4.0, 5.0),
            udot: Vector2::new(6.0, 7.0),
            uddot: Vector2::new(8.0, 9.0),
            points: p(10.0, 11.0),
            point_velocities: p(12.0, 13.0),
            point_accelerations: p(14.0, 15.0),
            names: &["B", "C"],
        }
    }

    #[test]
    fn reports_name_what_is_followed() {
        assert_eq!(Quantity::<Fun>::coordinate("s", Of::Position).name(), "s");
        assert_eq!(
            Quantity::<Fun>::coordinate("s", Of::Velocity).name(),
            "velocity of s"
        );
        assert_eq!(
            Quantity::<Fun>::point("P", Axis::Y, Of::Acceleration).name(),
            "acceleration of P.y"
        );
        let f: Fun = |p| p.u[0];
        assert_eq!(Quantity::function("θ3", f).name(), "θ3");
        assert!(Quantity::function("θ3", f).named::<Fun>().is_none());
        let point = Quantity::<Fun>::point("P", Axis::X, Of::Velocity);
        assert_eq!(point.named::<()>().unwrap().name(), "velocity of P.x");
    }

    #[test]
    fn names_resolve_to_u_v_and_points_and_read_the_pose() {
        let names = names();
        let (u, v) = (names.coordinates()[1], names.coordinates()[2]);
        let point = names.points()[0];
        let pose = pose();
        let at = |q: Quantity<Fun>| q.resolve(&names).unwrap().at(&pose);
        assert_eq!(at(Quantity::coordinate(u, Of::Position)), 5.0);
        assert_eq!(at(Quantity::coordinate(u, Of::Acceleration)), 9.0);
        assert_eq!(at(Quantity::coordinate(v, Of::Position)), 1.0);
        assert_eq!(at(Quantity::coordinate(v, Of::Velocity)), 2.0);
        assert_eq!(at(Quantity::coordinate(v, Of::Acceleration)), 3.0);
        assert_eq!(at(Quantity::point(point, Axis::Y, Of::Position)), 11.0);
        assert_eq!(at(Quantity::point(point, Axis::X, Of::Velocity)), 12.0);
        assert_eq!(at(Quantity::point(point, Axis::Y, Of::Acceleration)), 15.0);
        assert_eq!(at(Quantity::function("sum", |p| p.u[0] + p.v[0])), 5.0);
        let theta = Quantity::<Fun>::coordinate(u, Of::Position);
        let theta = theta.resolve(&names).unwrap();
        assert_eq!(theta.velocity(&pose), Some(7.0));
        assert_eq!(theta.acceleration(&pose), Some(9.0));
        let driver = Quantity::<Fun>::coordinate(v, Of::Position);
        assert_eq!(driver.resolve(&names).unwrap().velocity(&pose), None);
        let x = Quantity::<Fun>::point(point, Axis::X, Of::Position);
        let x = x.resolve(&names).unwrap();
        assert_eq!(
            (x.velocity(&pose), x.acceleration(&pose)),
            (Some(12.0), Some(14.0))
        );
    }

    #[test]
    fn an_unknown_name_is_the_quantitys_error() {
        let names = names();
        let e = Quantity::<Fun>::point("Q", Axis::X, Of::Velocity)
            .resolve(&names)
            .unwrap_err();
        assert_eq!(
            (e.kind, e.owner.as_str(), e.name.as_str()),
            (NameKind::Point, "velocity of Q.x", "Q")
        );
        let e = Quantity::<Fun>::coordinate("x", Of::Position)
            .resolve(&names)
            .unwrap_err();
        assert_eq!(e.kind, NameKind::Coordinate);
        assert_eq!(e.known, names.coordinates().join(", "));
    }

    #[test]
    fn a_dual_pose_carries_the_rate_through() {
        let plain = pose();
        let dual = |x: f64| Dual64::new(x, 2.0 * x);
        let pose = Pose {
            v: plain.v.map(dual),
            vdot: plain.vdot.map(dual),
            vddot: plain.vddot.map(dual),
            u: plain.u.map(dual),
            udot: plain.udot.map(dual),
            uddot: plain.uddot.map(dual),
            points: plain.points.iter().map(|p| p.map(dual)).collect(),
            point_velocities: plain.point_velocities.iter().map(|p| p.map(dual)).collect(),
            point_accelerations: plain
                .point_accelerations
                .iter()
                .map(|p| p.map(dual))
                .collect(),
            names: plain.names,
        };
        let names = names();
        let q = Quantity::<fn(&Pose<Dual64, 2, 1>) -> Dual64>::point(
            names.points()[1],
            Axis::X,
            Of::Acceleration,
        );
        assert_eq!(
            q.resolve(&names).unwrap().at(&pose),
            Dual64::new(24.0, 48.0)
        );
        assert_eq!(
            pose.point_acceleration("C"),
            Some(Vector2::new(dual(24.0), dual(35.0)))
        );
        assert_eq!(pose.point("D"), None);
    }
}
