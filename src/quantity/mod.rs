//! Named quantities of a pose, for every analysis that reads one: the
//! lookup of a model's names ([`Names`]), each failing with the one
//! [`UnknownName`](crate::error::UnknownName) error, and the selector of a
//! quantity of a pose ([`Quantity`]: a coordinate, a point's x or y, at
//! position, velocity or acceleration level, or a function of the pose),
//! which reads a [`Pose`] whose numbers are plain (`f64`), dual numbers
//! that carry a rate ([`watch`](crate::watch)) or dual vectors that carry a
//! gradient ([`tolerance`](crate::tolerance)).
//!
//! ```
//! use linkage::prelude::*;
//! use linkage::quantity::{Axis, Names, Of, Pose, Quantity};
//!
//! #[linkage::linkage(
//!     u = [theta3, s],
//!     v = [theta2],
//!     points = [B = (r * theta2.cos(), r * theta2.sin())],
//!     closure = [
//!         r * theta2.cos() + l * theta3.cos() - s,
//!         r * theta2.sin() + l * theta3.sin() - e,
//!     ],
//! )]
//! struct SliderCrank { r: f64, l: f64, e: f64 }
//!
//! let crank = SliderCrank { r: 0.05, l: 0.2, e: 0.0 };
//! let pose = crank.analyze(&vector![-0.1, 0.25], &vector![0.0], &vector![10.0], &vector![0.0], &Options::default())?;
//! let motion = Motion::of_analysis(&pose);
//! let pose = Pose::of(&crank, &motion);
//! let names = Names::of(&SliderCrank { r: 1.0, l: 2.0, e: 0.0 });
//! // The crank pin's velocity is r·ω upwards at θ2 = 0.
//! let up = Quantity::<fn(&Pose<f64, 2, 1>) -> f64>::point("B", Axis::Y, Of::Velocity);
//! assert_eq!(up.name(), "velocity of B.y");
//! assert!((up.resolve(&names)?.at(&pose) - 0.5).abs() < 1e-12);
//! // A name the model does not have.
//! let bad = Quantity::<fn(&Pose<f64, 2, 1>) -> f64>::coordinate("x", Of::Position);
//! assert!(bad.resolve(&names).is_err());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod names;
mod pose;
mod selector;
mod written;

pub use names::Names;
pub(crate) use names::{body, find, parameter};
pub use pose::Pose;
pub use selector::{Quantity, Resolved};
pub use written::{Written, written};

/// Which derivative in time of a coordinate or a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Of {
    Position,
    Velocity,
    Acceleration,
}

/// A component of a point's position, velocity or acceleration.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    X,
    Y,
}
