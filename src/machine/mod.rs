//! Reduced dynamics of a one-degree-of-freedom machine: reduced moment of
//! inertia and reduced moment, work, the flywheel by the energy method, and
//! the machine's real motion.
//!
//! A machine is a `#[linkage::linkage]` model with one driver coordinate φ
//! (the generalized coordinate, usually the crank's angle), the **bodies**
//! that carry mass — each with its mass, its moment of inertia about its
//! centre of mass, the point that is its centre of mass and the coordinate
//! that is its angle, if it turns — and the **loads**: forces at points and
//! moments on coordinates, as functions of the pose, including the usual
//! kinds ready-made (a process-force diagram over a point's displacement,
//! Coulomb friction on a guide, gravity).
//!
//! Everything is reduced to φ with the kinematic analogs of the generated
//! code — v_q = dP/dφ, ω_q = dθ/dφ and their derivatives a_q, ε_q from the
//! generated second-order terms, no numerical differentiation:
//!
//! ```text
//! J(φ)   = Σ m·|v_q|² + I·ω_q²                       reduced moment of inertia
//! J′(φ)  = Σ 2m·v_q·a_q + 2I·ω_q·ε_q                 its derivative, analytic
//! M(φ)   = Σ F·v_q + Σ M·ω_q                          reduced moment of the loads
//! A(φ)   = ∫₀^φ M dφ                                   work, split at the loads' kinks
//! ```
//!
//! The equation of motion of the machine with a constant reduced inertia
//! J_I (flywheel, rotors) besides J(φ), driven by a moment M_D:
//! (J_I + J)·ε + ½·J′·ω² = M + M_D, i.e. d/dφ [½(J_I + J)ω²] = M + M_D.
//!
//! The area's files: [`Body`] and the weight (`body.rs`), [`Load`] and
//! what it applies (`load.rs`), the [`Pose`] loads see (`pose.rs`),
//! [`Table`] (`table.rs`), the [`MachineBuilder`] (`build.rs`), the
//! [`Machine`] over its cycle — reduced quantities and work
//! (`cycle.rs`), the [`EnergyMethod`] (`energy.rs`), the [`SteadyMotion`]
//! (`steady.rs`), the [`flywheel`] formulas, and the [`kinetostatics`],
//! which read the same bodies, weights and ground points.

mod body;
mod build;
mod cycle;
mod design;
mod energy;
pub mod flywheel;
pub mod kinetostatics;
mod load;
mod pose;
mod steady;
mod table;

pub use body::Body;
pub use build::MachineBuilder;
pub use cycle::{Machine, Reduced};
pub use design::{Design, ReducedGradient};
pub use energy::{EnergyMethod, Extremum};
pub use load::{Applied, Load};
pub use pose::Pose;
pub use steady::{Motor, SteadyMotion};
pub use table::Table;

use crate::error::UnknownName;
use crate::runtime::Error;

/// What went wrong setting up or analysing a machine.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum MachineError {
    /// A force table is not usable.
    BadTable { why: String },
    /// A number given is out of its range.
    BadSetting {
        what: &'static str,
        must: &'static str,
        value: f64,
    },
    /// The kinematics failed (the mechanism cannot be assembled, or meets a
    /// singular pose on its cycle).
    Kinematics(Error),
    /// The machine does not run a whole cycle.
    Incomplete { phi: f64, why: &'static str },
    /// The real motion stops: the kinetic energy would become negative.
    Stalls { phi: f64 },
    /// No periodic motion was found.
    NoSteadyState { omega: f64, why: &'static str },
    /// A load's value (a user's function of the pose, or a weight) is NaN
    /// or infinite at φ.
    NonFiniteLoad { load: String, phi: f64 },
    /// A reduced quantity leaves the range of f64 at φ: the masses,
    /// inertias or loads are too large for it.
    Overflow { what: &'static str, phi: f64 },
    /// A body or load names a point or a coordinate the model does not have.
    UnknownName(UnknownName),
    /// The dynamics cannot be differentiated by the design (see
    /// [`Machine::design`]).
    NotDifferentiable { what: String, why: &'static str },
}

crate::error::error_impls! {
    MachineError {
        Self::BadTable { why } => ("the table is not usable: {why}"),
        Self::BadSetting { must, value, what } => ("{what} must be {must}, got {value}"),
        Self::Kinematics(inner) => ("kinematics: {inner}"),
        Self::Incomplete { phi, why } => ("the mechanism does not complete its cycle: it stops at φ = {phi} ({why})"),
        Self::Stalls { phi } => ("the machine stalls at φ = {phi}: its kinetic energy runs out"),
        Self::NoSteadyState { omega, why } => ("no periodic steady state near ω = {omega}: {why}"),
        Self::NonFiniteLoad { load, phi } => ("the load `{load}` is not finite at φ = {phi}"),
        Self::Overflow { what, phi } => ("{what} leaves the range of f64 at φ = {phi}: the masses, inertias or loads are too large"),
            Self::UnknownName(inner) => ("{inner}"),
        Self::NotDifferentiable { what, why } => ("{what} cannot be differentiated by the design: {why}"),
    }
    wraps { Kinematics(Error), UnknownName(UnknownName) }
}
