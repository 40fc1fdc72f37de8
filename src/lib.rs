//! # linkage
//!
//! Planar mechanisms from their loop-closure equations. Write the equations
//! Ψ(u, v) = 0 as Rust expressions in an attribute on a struct of
//! parameters; the [`#[linkage::linkage(...)]`](macro@linkage) macro
//! differentiates them symbolically at compile time and emits straight-line
//! Rust for Ψ, its Jacobians Ψ_q, Ψ_u, Ψ_v, the second-order terms of both
//! acceleration methods and the kinematics of named points. The runtime
//! solves positions by Newton–Raphson, then velocities and accelerations.
//!
//! ## A first mechanism
//!
//! In `Cargo.toml`, `linkage` is the only dependency needed (nalgebra's
//! types and the [`vector!`] and [`matrix!`] macros come through it).
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
//! let c = pose.points[FourBar::C]; // each named point's index, generated
//! assert!((c.x - 35.44242865).abs() < 1e-8);
//! # Ok::<(), linkage::Error>(())
//! ```
//!
//! The attribute's grammar — its keys, what an expression may use, the
//! notation — is documented on [the attribute itself](macro@linkage).
//!
//! ## What you get
//!
//! - On the struct: the generated functions (`psi`, `psi_u`, `gamma`,
//!   `point_positions`, …, each documented with its formula), one
//!   constant per named point (its index: `pose.points[FourBar::C]`), an
//!   implementation of [`Kernels`] (those functions, for the runtime) and
//!   one of [`Linkage`], whose provided methods are the analyses:
//!   [`Linkage::solve_position`], [`Linkage::velocity`],
//!   [`Linkage::acceleration`], [`Linkage::analyze`] (all of one pose),
//!   [`Linkage::sweep`] and [`Linkage::sweep_each`] (continuation along a
//!   drive, through singular poses).
//! - An implementation of [`Sensitivities`]: the exact derivatives of
//!   every position, velocity and acceleration, of the coordinates and of
//!   the points, by each parameter (the struct's `f64` fields, or those
//!   named by `params = [...]`), at a pose or along a sweep.
//! - [`assembly`]: every assembly mode at a driver value without a guess
//!   (a deterministic grid search with deflation, each mode with its
//!   branch signs, dead centres apart), and one picked by index, by a
//!   point's side of a line or as the one nearest a sketch; a mechanism
//!   that cannot close is a typed error.
//! - [`watch`]: the dead centres, strokes and extremes along a sweep,
//!   located in the driver to rounding.
//! - [`tolerance`]: how the dimensions' tolerances spread into any
//!   quantity over the cycle — linear (worst case and RSS, exact
//!   gradients), the range of a quantity in one call, the distance to a
//!   limit position, and Monte Carlo beside it.
//! - [`synthesis`]: dimensions from a task — path, function or motion
//!   generation through precision points or by least squares — each design
//!   returned with a certificate over the task's whole range (assembly,
//!   branch, order, transmission angle, Grashof type); without a guess of
//!   the first pose, each start is assembled by [`assembly`].
//! - [`batch`]: many designs or drives at once, in parallel.
//! - `file` (feature `files`, default): mechanism files — a mechanism's
//!   equations, parameters with units, drive, assembly and drawing as
//!   TOML, read at run time with every mistake located in the file; the
//!   repository's `mechanisms/` is a library of them.
//! - [`quantity`]: a model's names and the quantities of a pose (a
//!   coordinate, a point's x or y, their rates, a function of the pose)
//!   that every analysis names and reads.
//! - `draw` (feature, default): pictures of poses, animations, motion
//!   diagrams, and charts fit to print (`draw::chart`); [`machine`] and [`cam`]: reduced dynamics, flywheel, joint
//!   reactions, cam design; [`mechanisms`]: the worksheet's four-bar and a
//!   four-bar for path generation, ready.
//!
//! ## The defaults
//!
//! [`Options::default`] (one pose): Newton stops at ‖Ψ‖∞ ≤ 1e-9 and a step
//! ‖Δu‖∞ ≤ 1e-10·max(1, ‖u‖∞), at most 50 steps; a result must keep a
//! relative accuracy of 1e-6 or the solve returns [`Error::Singular`]; γ in
//! fused form, Jacobians from the generated code, plain (undamped) Newton.
//!
//! [`SweepOptions::default`] (a sweep): those options, and **`speed` 1**:
//! the poses' `udot` and `uddot` are then the kinematic analogs du/dv and
//! d²u/dv², not velocities — set `speed` to the driver's speed (ω2 in rad/s)
//! for velocities and accelerations in time.
//!
//! Every analysis returns a typed [`Error`] rather than panic, and never a
//! NaN or an infinity inside `Ok`.
//!
//! ## Where to go next
//!
//! The repository's `docs/guide.md` walks through the generated code
//! (`cargo expand`), compile-time mistakes, sweeps and singular poses,
//! extremes and pictures; `cargo run --release --example fourbar`
//! reproduces the Maple worksheet, `--example shaper` and `--example cam`
//! the Mathcad course project of a shaping machine.
#![forbid(unsafe_code)]

extern crate self as linkage;

pub mod assembly;
pub mod batch;
pub mod cam;
pub mod closed_form;
#[cfg(feature = "draw")]
pub mod draw;
pub mod error;
#[cfg(feature = "files")]
pub mod file;
pub mod ground;
pub mod least_squares;
pub mod machine;
#[cfg(feature = "files")]
pub mod mechanism;
pub mod mechanisms;
mod numerics;
pub mod quantity;
mod random;
pub mod synthesis;
pub mod tolerance;
#[cfg(feature = "files")]
pub mod topology;
pub mod transmission;
mod vectors;
pub mod watch;

#[doc(inline)]
#[doc = include_str!("../docs/attribute.md")]
pub use linkage_macros::linkage;
mod runtime;
pub use nalgebra;
pub use num_dual;
pub use runtime::*;

/// The code blocks of the README and of the pages in docs/, compiled and
/// run with the doctests, so that what they show cannot rot.
#[cfg(doctest)]
mod documentation {
    #[doc = include_str!("../README.md")]
    struct Readme;
    #[doc = include_str!("../docs/attribute.md")]
    struct Attribute;
    #[cfg(feature = "draw")]
    #[doc = include_str!("../docs/guide.md")]
    struct Guide;
    #[doc = include_str!("../docs/reproductions.md")]
    struct Reproductions;
    #[doc = include_str!("../docs/performance.md")]
    struct Performance;
    #[doc = include_str!("../docs/reliability.md")]
    struct Reliability;
}

/// Everything a user of the attribute needs: the runtime's types, the
/// `Linkage` trait (for the analyses), the `Kernels` trait under it (the
/// generated functions) and `Assemble` (every assembly mode without a
/// guess), nalgebra's vector and matrix types,
/// and [`vector!`](crate::vector) and [`matrix!`](crate::matrix), which
/// resolve through linkage (no direct nalgebra dependency needed).
pub mod prelude {
    #[doc(no_inline)]
    pub use crate::assembly::Assemble;
    #[doc(no_inline)]
    pub use crate::linkage;
    #[doc(no_inline)]
    pub use crate::runtime::{
        AccelerationMethod, Analysis, Drive, Error, Event, EventKind, Iterate, JacobianSource,
        Kernels, Kinematics, Linkage, Motion, Options, Position, Sensitivities, Sensitivity, Stage,
        Sweep, SweepOptions, SweepPose, SweepSummary, SymbolicMatrix, SymbolicTable, Velocity,
    };
    pub use crate::{matrix, vector};
    pub use nalgebra::{Matrix2, SMatrix, SVector, Vector1, Vector2, Vector3, Vector4};
}
