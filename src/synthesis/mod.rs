//! Synthesis: mechanisms designed by exact gradients, for any mechanism
//! written with the attribute.
//!
//! A [`Problem`] says what is matched — a point's path through target
//! points ([`Problem::path`]) or close to a closed curve
//! ([`Problem::curve`]), a coordinate as a function of the driver
//! ([`Problem::function`]), a body's position and angle
//! ([`Problem::motion`]) — which parameters are free and within which
//! bounds ([`Problem::free`]), whether the driver at each target is
//! prescribed or free ([`Timing`]), and the designer's own terms
//! ([`Problem::term`], written on dual numbers). Its residuals have exact Jacobians:
//! each target's pose is solved by Newton, and the sensitivities of the
//! positions ([`Sensitivities::position_sensitivities_of`](crate::Sensitivities::position_sensitivities_of))
//! give the columns of the free parameters, the velocity at unit driver
//! speed the column of a free driver.
//!
//! [`synthesize`] solves it from many random starts in parallel (through
//! [`batch`](crate::batch)) with a bounded Levenberg–Marquardt solver —
//! each start's design assembled from the problem's guess
//! ([`Problem::guess`]) or, without one, by the search for its assembly
//! modes ([`crate::assembly`]) — and
//! returns only **certified** designs: a continuation sweep over the whole
//! driver range ([`Requirements`]: a revolution, or the task's range
//! stated in the problem) must assemble everywhere, meet no singular pose,
//! reach every target on the branch it was designed on and in the
//! targets' order, keep the transmission angle (a four-bar's 40° unless
//! asked otherwise) and pass the designer's checks (a Grashof type). Each
//! design comes with its [`Certificate`]: the range swept, the worst
//! transmission angle and where. A candidate that fails is reported with
//! its [`Defect`], never returned as a design.

mod certify;
mod continuation;
mod problem;
mod residuals;
mod search;
mod terms;

pub use crate::least_squares::Stopping;
pub use certify::{
    Certificate, DEFAULT_MIN_EQUIVALENT_ANGLE, DEFAULT_MIN_TRANSMISSION, Defect, DesignCheck,
    Range, Requirements, Transmission, TransmissionAngle, certify,
};
pub use problem::{Problem, Timing};
pub use residuals::Evaluated;
pub use search::{
    Candidate, Closest, Search, Synthesis, synthesize, synthesize_cancellable, synthesize_observed,
};

use crate::error::UnknownName;
use crate::runtime::Error;

/// A synthesis problem that cannot be posed or solved.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SynthesisError {
    /// A parameter, point or coordinate the model does not have.
    UnknownName(UnknownName),
    /// A free parameter's bounds are empty or not finite.
    EmptyBounds {
        parameter: String,
        lower: f64,
        upper: f64,
    },
    /// No targets.
    NoTargets,
    /// A target curve that cannot be sampled ([`Problem::curve`]).
    Curve(&'static str),
    /// A function's range that cannot be sampled
    /// ([`Problem::function_over`]).
    FunctionRange(&'static str),
    /// A target or a prescribed driver is not finite.
    NonFiniteTarget,
    /// Prescribed drivers and targets differ in number.
    Timing { targets: usize, drivers: usize },
    /// A driver range that is empty or not finite (or, with relative
    /// timing, shorter than the drivers' spread).
    EmptyRange { from: f64, to: f64 },
    /// A prescribed driver outside the problem's driver range.
    OutsideRange {
        target: usize,
        driver: f64,
        from: f64,
        to: f64,
    },
    /// [`Range::Task`] asked of a problem that states no driver range.
    NoRange,
    /// No parameter is free.
    NothingFree,
    /// The solver's options are not usable.
    Options(Error),
    /// Every candidate missed target `target`: it is out of the design's
    /// reach (the closest any came is `error`).
    Unreachable { target: usize, error: f64 },
    /// No certified design: `refused` candidates (the one closest to the
    /// targets, and why it was refused) and `failed_starts` starts that
    /// could not be assembled.
    NoDesign {
        refused: usize,
        failed_starts: usize,
        closest: Option<Closest>,
    },
    /// The caller asked the search to stop ([`synthesize_cancellable`]).
    Cancelled,
}

crate::error::error_impls! {
    SynthesisError {
        Self::UnknownName(inner) => ("{inner}"),
        Self::EmptyBounds { parameter, lower, upper } => ("the bounds [{lower}, {upper}] of `{parameter}` are empty or not finite"),
        Self::NoTargets => ("a synthesis problem needs at least one target"),
        Self::Curve(why) => ("the target curve: {why}"),
        Self::FunctionRange(why) => ("the function's range: {why}"),
        Self::NonFiniteTarget => ("a target or a prescribed driver is not finite"),
        Self::Timing { targets, drivers } => ("{targets} targets but {drivers} prescribed drivers"),
        Self::EmptyRange { from, to } => ("the driver range from {from} to {to} is empty, not finite, or shorter than the drivers' spread"),
        Self::OutsideRange { target, driver, from, to } => ("target {target}'s driver {driver} lies outside the driver range from {from} to {to}"),
        Self::NoRange => ("Range::Task needs the task's driver range: state it with Problem::driver_range"),
        Self::NothingFree => ("no parameter is free: free at least one with Problem::free"),
        Self::Options(inner) => ("the search's options: {inner}"),
        Self::Unreachable { target, error } => ("target {target} is out of reach: every candidate missed it, the closest by {error}"),
        Self::NoDesign { refused, failed_starts, closest: Some(closest) } => ("no certified design: {refused} candidates refused, {failed_starts} starts could not be assembled; {closest}"),
        Self::NoDesign { refused, failed_starts, closest: None } => ("no certified design: {refused} candidates refused, {failed_starts} starts could not be assembled"),
        Self::Cancelled => ("the search was stopped before its end"),
    }
    wraps { UnknownName(UnknownName) }
    sources { Options(Error) }
}
