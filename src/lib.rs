//! # linkage
//!
//! Planar mechanisms from their loop-closure equations. Write the equations
//! Ψ(u, v) = 0 as Rust expressions in an attribute on a struct of
//! parameters; the `#[linkage::linkage(...)]` macro differentiates them
//! symbolically at compile time and emits straight-line Rust for Ψ, its
//! Jacobians Ψ_q, Ψ_u, Ψ_v, the second-order terms of both acceleration
//! methods and the kinematics of named points. The runtime solves positions
//! by Newton–Raphson, then velocities and accelerations.
//!
//! ```
//! use linkage::prelude::*;
//!
//! /// The four-bar of the Maple worksheet.
//! #[linkage::linkage(
//!     u = [theta3, theta4],
//!     v = [theta2],
//!     points = [
//!         B = (l2 * theta2.cos(), l2 * theta2.sin()),
//!         C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
//!     ],
//!     closure = [
//!         l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
//!         l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
//!     ],
//! )]
//! #[derive(Clone, Debug)]
//! pub struct FourBar { pub l1: f64, pub l2: f64, pub l3: f64, pub l4: f64 }
//!
//! let bar = FourBar { l1: 80.0, l2: 20.0, l3: 50.0, l4: 70.0 };
//! let guess = vector![70f64.to_radians(), -50f64.to_radians()];
//! let pose = bar.analyze(
//!     &guess,
//!     &vector![20f64.to_radians()],  // θ2
//!     &vector![41.88790204786391],   // ω2 = 400 rpm
//!     &vector![0.0],                 // α2
//!     &Options::default(),
//! )?;
//! assert!((pose.u[0].to_degrees() - 70.55076547).abs() < 1e-8);
//! # Ok::<(), linkage::Error>(())
//! ```
//!
//! The attribute must be written with its path, `#[linkage::linkage(...)]`:
//! rustc has a built-in attribute named `linkage`, so a bare `#[linkage]`
//! is ambiguous (error E0659).
#![forbid(unsafe_code)]

extern crate self as linkage;

pub mod batch;
pub mod cam;
pub mod closed_form;
#[cfg(feature = "draw")]
pub mod draw;
pub mod error;
pub mod ground;
pub mod machine;
pub mod mechanisms;
mod numerics;
mod vectors;
pub mod watch;

pub use linkage_macros::linkage;
pub use linkage_runtime::*;
pub use nalgebra;
pub use num_dual;

/// Everything a user of the attribute needs: the runtime's types, the
/// `Linkage` trait (for the analyses), nalgebra's vector and matrix types,
/// and [`vector!`](crate::vector) and [`matrix!`](crate::matrix), which
/// resolve through linkage (no direct nalgebra dependency needed).
pub mod prelude {
    pub use crate::linkage;
    pub use crate::{matrix, vector};
    pub use linkage_runtime::{
        AccelerationMethod, Analysis, Drive, Error, Event, EventKind, Iterate, JacobianSource,
        Kinematics, Linkage, Options, Position, Stage, Sweep, SweepOptions, SweepPose,
        SweepSummary, SymbolicMatrix, SymbolicTable, Velocity,
    };
    pub use nalgebra::{Matrix2, SMatrix, SVector, Vector1, Vector2, Vector3, Vector4};
}
