//! The two kinds of arrow, velocity and acceleration: their names, colours
//! and the vectors of a frame they draw.

use super::style;
use super::{Frame, SceneError};
use nalgebra::Vector2;

/// The two kinds of arrow.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    Velocity,
    Acceleration,
}

impl Kind {
    pub(super) fn name(self) -> &'static str {
        match self {
            Kind::Velocity => "velocity",
            Kind::Acceleration => "acceleration",
        }
    }

    pub(super) fn plural(self) -> &'static str {
        match self {
            Kind::Velocity => "velocities",
            Kind::Acceleration => "accelerations",
        }
    }

    pub(super) fn colour(self) -> &'static str {
        match self {
            Kind::Velocity => style::VELOCITY,
            Kind::Acceleration => style::ACCELERATION,
        }
    }

    /// The frame's vectors of this kind (an error if it has none).
    pub(super) fn vectors(self, frame: &Frame) -> Result<&[Vector2<f64>], SceneError> {
        match self {
            Kind::Velocity => frame.velocities.as_deref(),
            Kind::Acceleration => frame.accelerations.as_deref(),
        }
        .ok_or(SceneError::MissingKinematics {
            what: self.plural(),
        })
    }
}
