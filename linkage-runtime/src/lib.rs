//! The numeric runtime of `linkage`: Newton–Raphson for positions, then the
//! linear velocity and acceleration solves, on the code `#[linkage::linkage]`
//! generates.
//!
//! Notation (the Maple worksheet's): q = [u; v] with u the m dependent
//! coordinates and v the f driving ones; Ψ(u, v) = 0 the closure equations;
//! Ψ_u u̇ = −Ψ_v v̇ and Ψ_u ü = −Ψ_v v̈ − γ.
//!
//! Every entry point checks its inputs and outputs: it returns a typed
//! [`Error`] rather than panic, and never a NaN or an infinity inside `Ok`.
#![forbid(unsafe_code)]

mod error;
mod linalg;
mod model;
mod newton;
mod sources;
mod sweep;
mod symbolic;

pub use error::{Error, Stage};
pub use linalg::{Inverse, determinant, invert, scaled_svd};
pub use model::{
    AccelerationMethod, Analysis, Iterate, Kinematics, Linkage, Options, Position, Velocity,
};
pub use sources::JacobianSource;
pub use sweep::{Drive, Event, EventKind, Sweep, SweepOptions, SweepPose, SweepSummary};
pub use symbolic::{SymbolicMatrix, SymbolicTable};
