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

// The modules in layers, each using only those before it.
//   error     the typed errors
//   powers_of_two  exact scale factors
//   options   the solvers' settings
//   linalg    small matrices: inversion, factorisation, conditioning
//   blocks    the structure of Ψ_u: its block triangular order
//   factors   Ψ_u factored for solving, block by block in that order
//   checks    finite inputs and outputs, numbers in the normal range
//   trig      sines and cosines carried from pose to pose
//   results   what the analyses return
//   symbolic  the generated formulas as text
//   kernels   the trait of what the macro generates: names, Ψ, Jacobians,
//             second-order terms, points (the modules below take their
//             model through it)
//   sources   where Ψ_u, Ψ_v and γ come from
//   newton    positions: Newton–Raphson
//   solve     velocities and accelerations
//   sweep     continuation along a drive
//   linkage   the trait of the analyses, on top of Kernels: its provided
//             methods are the entry points, delegating to the modules above
//   sensitivities  the derivatives by the parameters: a trait on top of
//             Linkage, its provided methods delegating to its own solve
mod blocks;
mod checks;
mod error;
mod factors;
mod kernels;
mod linalg;
mod linkage;
mod newton;
mod options;
mod powers_of_two;
mod results;
mod sensitivities;
mod solve;
mod sources;
mod sweep;
mod symbolic;
mod trig;

pub use blocks::PsiUBlocks;
#[cfg(feature = "files")]
pub(crate) use blocks::PsiUBlocksBuf;
pub use error::{Error, Stage};
pub use factors::Factors;
pub use kernels::{FusedRequest, Kernels};
pub use linalg::{Inverse, determinant, invert, scaled_svd};
pub use linkage::Linkage;
pub use options::{AccelerationMethod, JacobianSource, Options};
pub use results::{Analysis, AnalysisJob, Iterate, Kinematics, Position, Velocity};
#[doc(hidden)]
pub use sensitivities::SensitivityKernel;
pub use sensitivities::{
    Motion, PositionSensitivity, PositionTerms, Sensitivities, Sensitivity, SensitivityTerms,
};
pub(crate) use solve::analyze_together;
pub use sweep::{Drive, Event, EventKind, Sweep, SweepOptions, SweepPose, SweepSummary};
pub use symbolic::{SymbolicMatrix, SymbolicTable};
