//! A pose of the machine as loads see it.

use nalgebra::Vector2;

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
    pub(crate) point_names: &'static [&'static str],
    pub(crate) coordinate_names: Vec<&'static str>,
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
