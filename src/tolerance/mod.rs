//! Tolerance analysis: how far the manufacturing tolerances of the
//! dimensions move any result of a mechanism, over its whole cycle.
//!
//! The linear estimate comes from the exact sensitivities
//! ([`Sensitivities`](crate::Sensitivities)): an output y with gradient
//! g = ∂y/∂p, under tolerances ±tᵢ on the parameters, spreads by
//!
//! ```text
//! worst case   Σ |gᵢ| tᵢ            every dimension at the end of its band that hurts
//! RSS          √ Σ (gᵢ tᵢ)²         the root-sum-square stack
//! σ            √ Σ (gᵢ σᵢ)²         the standard deviation, σᵢ = tᵢ/√3 (uniform) or the given σᵢ (normal)
//! ```
//!
//! [`cycle`] gives them at every pose of a sweep, for any [`Output`]: a
//! coordinate, a point's coordinate, a velocity, an acceleration, the
//! deviation of a point's path normal to itself, or any function of the
//! pose written on dual numbers (the transmission angle θ4 − θ3). A located
//! extreme (the stroke, the dead centres that set the quick-return ratio)
//! moves with the dimensions too; [`extremes`] and [`at_found`] give its
//! value's gradient by the envelope theorem and its place's by implicit
//! differentiation.
//!
//! The linear estimate is exact to first order. [`monte_carlo`] and
//! [`monte_carlo_cycle`] check it: they draw designs within the tolerances
//! (reproducibly: each sample is a function of its run's random state and its index
//! alone) and analyse them in parallel through [`batch`](crate::batch).
//! Where the two disagree, the response is not linear — next to a limit
//! position, where sensitivities grow without bound and some designs of
//! the band no longer pass. The result says when: [`Cycle::limit`] is the
//! margin to the nearest limit position in units of the tolerances
//! ([`limit_margin`]; [`LimitMargin::reaches_limit`] below 1), a four-bar's
//! margin to a change of Grashof type is [`grashof_margin`], and a Monte
//! Carlo run reports the fraction of samples that do not run the cycle,
//! with their reasons ([`CycleSamples::failed_fraction`]).
//!
//! [`range`] gives the spread of a quantity's range over the cycle (the
//! stroke) in one call, and [`monte_carlo_range`] checks it.
//!
//! ```
//! use linkage::prelude::*;
//! use linkage::mechanisms::FourBar;
//! use linkage::tolerance::{self, Output, Tolerance, Tolerances};
//! use linkage::watch::Of;
//!
//! // ±0.05 mm on every length of the Maple worksheet's four-bar.
//! let tolerances = Tolerances::new([Tolerance::Band(0.05); 4])?;
//! let drive = Drive::Line { from: vector![0.0], to: vector![std::f64::consts::TAU], steps: 72 };
//! let outputs = [Output::coordinate("theta4", Of::Position)];
//! let cycle = tolerance::cycle(
//!     &FourBar::WORKSHEET,
//!     &vector![1.2, -1.0],
//!     &drive,
//!     &SweepOptions::default(),
//!     &outputs,
//!     &tolerances,
//! )?;
//! let (pose, spread) = cycle.bands[0].largest().expect("sensitivities along the cycle");
//! // The rocker's angle moves by at most this much, at this crank angle.
//! assert!(spread.worst_case > 0.0 && spread.worst_case < 0.01);
//! assert!(spread.rss <= spread.worst_case && spread.sigma < spread.rss);
//! # let _ = pose;
//! # Ok::<(), linkage::tolerance::ToleranceError>(())
//! ```

mod cycle;
mod grashof;
mod limit;
mod located;
mod monte_carlo;
mod output;
mod range;
mod samples;
mod statistics;

pub use cycle::{Band, Cycle, cycle};
pub use grashof::{GrashofMargin, grashof_margin};
pub use limit::{LimitMargin, limit_margin, limit_measure};
pub use located::{Located, at_found, extreme_values, extremes};
pub use monte_carlo::{
    CycleSamples, Failure, MonteCarlo, monte_carlo, monte_carlo_cycle, monte_carlo_cycle_observed,
};
pub use output::{Output, TolerancePose};
pub use range::{Range, RangeSamples, monte_carlo_range, range};
pub use statistics::Statistics;

use crate::error::UnknownName;
use crate::quantity;
use crate::runtime::Error;
use crate::watch::WatchError;
use nalgebra::SVector;
use num_dual::{Derivative, DualSVec64};

/// A dimension's tolerance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Tolerance {
    /// ± this half-width; a Monte Carlo sample is uniform within it.
    Band(f64),
    /// Normal with this standard deviation; its band (for the worst case
    /// and the RSS stack) is ±3σ.
    Normal(f64),
}

impl Tolerance {
    /// No tolerance: the dimension is exact.
    pub const EXACT: Tolerance = Tolerance::Band(0.0);

    /// The half-width of the band: t, or 3σ.
    pub fn half_width(self) -> f64 {
        match self {
            Tolerance::Band(t) => t,
            Tolerance::Normal(sigma) => 3.0 * sigma,
        }
    }

    /// The standard deviation: t/√3 for a uniform band, or σ.
    pub fn sigma(self) -> f64 {
        match self {
            Tolerance::Band(t) => t / 3f64.sqrt(),
            Tolerance::Normal(sigma) => sigma,
        }
    }

    fn size(self) -> f64 {
        match self {
            Tolerance::Band(t) | Tolerance::Normal(t) => t,
        }
    }
}

/// The tolerance of each of a model's k parameters, in the order of its
/// `PARAM_NAMES`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances<const K: usize> {
    each: [Tolerance; K],
}

impl<const K: usize> Tolerances<K> {
    /// The tolerances in the order of the parameters; each must be finite
    /// and not negative.
    pub fn new(each: [Tolerance; K]) -> Result<Tolerances<K>, ToleranceError> {
        for (i, t) in each.iter().enumerate() {
            let size = t.size();
            if !(size.is_finite() && size >= 0.0) {
                return Err(ToleranceError::BadTolerance {
                    parameter: i,
                    value: size,
                });
            }
        }
        Ok(Tolerances { each })
    }

    /// The tolerances of the parameters named (by `names`, the model's
    /// `PARAM_NAMES`); those not named are exact.
    pub fn by_name(
        names: &[&'static str; K],
        given: &[(&str, Tolerance)],
    ) -> Result<Tolerances<K>, ToleranceError> {
        let mut each = [Tolerance::EXACT; K];
        for (name, tolerance) in given {
            each[quantity::parameter(names, "the tolerances", name)?] = *tolerance;
        }
        Tolerances::new(each)
    }

    /// The tolerance of the parameter `i`.
    pub fn get(&self, i: usize) -> Tolerance {
        self.each[i]
    }

    /// The spread of an output whose gradient by the parameters is
    /// `gradient`.
    pub fn spread(&self, gradient: &SVector<f64, K>) -> Spread {
        let mut spread = Spread::default();
        let (mut rss, mut variance) = (0.0, 0.0);
        for (g, t) in gradient.iter().zip(&self.each) {
            let share = g.abs() * t.half_width();
            spread.worst_case += share;
            rss += share * share;
            variance += (g * t.sigma()).powi(2);
        }
        spread.rss = rss.sqrt();
        spread.sigma = variance.sqrt();
        spread
    }

    /// What each dimension adds to the worst case: |gᵢ| tᵢ.
    pub fn contributions(&self, gradient: &SVector<f64, K>) -> SVector<f64, K> {
        SVector::from_fn(|i, _| gradient[i].abs() * self.each[i].half_width())
    }
}

/// How far an output spreads under the tolerances, to first order.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Spread {
    /// Σ |gᵢ| tᵢ: the output stays within ± this.
    pub worst_case: f64,
    /// √ Σ (gᵢ tᵢ)²: the root-sum-square stack of the bands.
    pub rss: f64,
    /// √ Σ (gᵢ σᵢ)²: the output's standard deviation.
    pub sigma: f64,
}

/// The gradient carried by a value of [`DualSVec64`] (zero if it carries
/// none).
pub fn gradient<const K: usize>(x: &DualSVec64<K>) -> SVector<f64, K> {
    x.eps.unwrap_generic(nalgebra::Const::<K>, nalgebra::U1)
}

/// How many times the worst-case change of a result its margin (≥ 0) is:
/// margin / Σ |gᵢ| tᵢ; infinite where the result does not depend on the
/// dimensions and the margin is positive; 0 where the margin is 0 or its
/// change is not known.
pub(super) fn distance(margin: f64, spread: &Spread) -> f64 {
    match spread.worst_case {
        w if w > 0.0 && margin >= 0.0 => margin / w,
        w if w == 0.0 && margin > 0.0 => f64::INFINITY,
        _ => 0.0,
    }
}

/// A value with the gradient `gradient`.
pub fn with_gradient<const K: usize>(value: f64, gradient: SVector<f64, K>) -> DualSVec64<K> {
    DualSVec64::new(value, Derivative::some(gradient))
}

/// Which design an error is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Design {
    /// The design passed to the call (the nominal one, unless a Monte
    /// Carlo sample was passed).
    Given,
    /// The nominal design of a Monte Carlo run.
    Nominal,
    /// Monte Carlo sample `index` ([`MonteCarlo::sample`]).
    Sample(usize),
}

impl std::fmt::Display for Design {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Design::Given => write!(f, "the design"),
            Design::Nominal => write!(f, "the nominal design"),
            Design::Sample(index) => write!(f, "Monte Carlo sample {index}"),
        }
    }
}

/// What went wrong in a tolerance analysis.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ToleranceError {
    /// A tolerance names a parameter the model does not have, or an output
    /// a coordinate or point it does not have.
    UnknownName(UnknownName),
    /// The tolerance of parameter `parameter` is negative or not finite.
    BadTolerance { parameter: usize, value: f64 },
    /// `design` cannot be analysed.
    Kinematics { design: Design, error: Error },
    /// Its extremes cannot be located.
    Watch(WatchError),
    /// The output cannot be analysed this way.
    Unsupported { output: String, why: &'static str },
    /// A Monte Carlo run of no samples.
    NoSamples,
}

impl ToleranceError {
    /// The same error, said of Monte Carlo sample `index` (for a quantity
    /// of your own computed in [`monte_carlo`]'s closure).
    pub fn in_sample(self, index: usize) -> ToleranceError {
        match self {
            ToleranceError::Kinematics { error, .. } => ToleranceError::Kinematics {
                design: Design::Sample(index),
                error,
            },
            other => other,
        }
    }
}

/// A kinematic error of the design given (not of a Monte Carlo sample:
/// [`ToleranceError::in_sample`] says which).
impl From<Error> for ToleranceError {
    fn from(error: Error) -> Self {
        ToleranceError::Kinematics {
            design: Design::Given,
            error,
        }
    }
}

crate::error::error_impls! {
    ToleranceError {
        Self::UnknownName(inner) => ("{inner}"),
        Self::BadTolerance { parameter, value } => (
            "the tolerance of parameter {parameter} is {value}; it must be finite and not negative"
        ),
        Self::Kinematics { design, error } => ("{design}: {error}"),
        Self::Watch(inner) => ("locating the extremes: {inner}"),
        Self::Unsupported { output, why } => ("the output `{output}`: {why}"),
        Self::NoSamples => ("a Monte Carlo run needs at least one sample"),
    }
    wraps { UnknownName(UnknownName), Watch(WatchError) }
    field_sources { Kinematics.error }
}
