//! The spread of the range of a quantity over the cycle, in one call: the
//! stroke of a slider or a ram, the swing of a rocker.
//!
//! The range is y_max − y_min over the cycle, both located to rounding
//! ([`extreme_values`]); by the envelope theorem each moves with the
//! dimensions by its partial derivative at its place, so the range's
//! gradient is y_p(max) − y_p(min), and its spread follows
//! ([`Tolerances::spread`]). For a position-level coordinate or point
//! y_p needs only u_p = −Ψ_u⁻¹Ψ_p, so the range is given also where an
//! extreme lies close to a singular pose (a slider's inner dead centre
//! when the rod is barely longer than crank plus offset), where the
//! sensitivities of velocity and acceleration — and so the places' gradients
//! ([`at_found`]) — are refused.
//! [`monte_carlo_range`] measures the same range on designs drawn within
//! the tolerances, values alone ([`extreme_values`]), and says which
//! samples have none and why.

use super::limit::{moving_with_params, position_sensitivity};
use super::located::{Located, at_found, extreme_values, watch_of};
use super::monte_carlo::{Failure, MonteCarlo, cannot_run_fraction, failed_fraction, monte_carlo};
use super::output::Resolved;
use super::{Design, Output, Spread, Statistics, ToleranceError, Tolerances, gradient};
use crate::quantity::Resolved as Named;
use crate::runtime::{Drive, Sensitivities, SweepOptions};
use crate::watch::{Axis, Found, FoundKind, Of};
use nalgebra::SVector;
use num_dual::DualSVec64;

/// The range of an output over the cycle and its spread.
#[derive(Clone, Debug, PartialEq)]
pub struct Range<const K: usize> {
    /// The smallest of the located minima, with its gradient and place.
    pub min: Located<K>,
    /// The largest of the located maxima.
    pub max: Located<K>,
    /// max − min, with its gradient.
    pub value: DualSVec64<K>,
    /// Its spread under the tolerances.
    pub spread: Spread,
}

impl<const K: usize> Range<K> {
    /// The range's gradient by the parameters.
    pub fn gradient(&self) -> SVector<f64, K> {
        gradient(&self.value)
    }
}

/// The range over the cycle of a coordinate or a point's coordinate at
/// position level (`output`): the sweep of `model` from `u0` along
/// `drive`, its extremes located, the largest maximum less the smallest
/// minimum, its gradient and its spread under `tolerances`. An error if
/// the output has no located maximum or no minimum (a sweep that starts
/// exactly at one: start it elsewhere).
pub fn range<L, const M: usize, const K: usize>(
    model: &L,
    u0: &SVector<f64, M>,
    drive: &Drive<1>,
    options: &SweepOptions,
    output: &Output<'_, M, 1, K>,
    tolerances: &Tolerances<K>,
) -> Result<Range<K>, ToleranceError>
where
    L: Sensitivities<M, 1, K>,
{
    let sweep = model.sweep(u0, drive, options)?;
    let resolved = output.resolve(model)?;
    let found = extreme_values(model, &sweep, output, &options.options)?;
    let located = |f: &Found<M, 1>| -> Result<Located<K>, ToleranceError> {
        // The value's gradient needs u_p alone at position level; the
        // place's needs the sensitivities of velocity and acceleration,
        // which are refused close to a singular pose: then it is not given.
        let at = at_found(model, &sweep, f, output, &options.options);
        let value = match position_value(model, &f.u, &f.v, &resolved) {
            Some(value) => value,
            None => at.clone()?.value,
        };
        Ok(Located {
            kind: f.kind,
            value,
            v: at.ok().and_then(|a| a.v),
        })
    };
    let (Some(min), Some(max)) = (
        widest(&found, FoundKind::Minimum).map(located),
        widest(&found, FoundKind::Maximum).map(located),
    ) else {
        return Err(no_extremes(output));
    };
    let (min, max) = (min?, max?);
    let value = max.value - min.value;
    let g = gradient(&value);
    if !(value.re.is_finite() && g.iter().all(|x| x.is_finite())) {
        return Err(ToleranceError::Unsupported {
            output: output.name().to_owned(),
            why: "its range's gradient is not finite (an extreme at a singular pose)",
        });
    }
    Ok(Range {
        spread: tolerances.spread(&g),
        min,
        max,
        value,
    })
}

/// A position-level coordinate or point at the pose (u, v) with its
/// gradient by the parameters, u moving with them (u_p = −Ψ_u⁻¹Ψ_p);
/// `None` for other outputs, or where Ψ_u is singular.
fn position_value<L, const M: usize, const K: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, 1>,
    output: &Resolved<'_, M, 1, K>,
) -> Option<DualSVec64<K>>
where
    L: Sensitivities<M, 1, K>,
{
    let Resolved::Quantity(output) = output else {
        return None;
    };
    let at_position = matches!(
        *output,
        Named::U(_, Of::Position) | Named::V(_, Of::Position) | Named::Point(_, _, Of::Position)
    );
    if !at_position {
        return None;
    }
    let u_p = position_sensitivity(model, u, v)?;
    let (p, u) = moving_with_params(model, u, &u_p);
    match *output {
        Named::U(i, _) => Some(u[i]),
        Named::V(i, _) => Some(DualSVec64::from_re(v[i])),
        Named::Point(i, axis, _) => {
            let v = v.map(DualSVec64::from_re);
            let points = model.point_positions_generic_params(&p, &u, &v);
            let point = points.as_ref()[i];
            Some(match axis {
                Axis::X => point.x,
                Axis::Y => point.y,
            })
        }
        _ => None,
    }
}

/// The smallest minimum or the largest maximum of those found.
fn widest<const M: usize>(found: &[Found<M, 1>], wanted: FoundKind) -> Option<&Found<M, 1>> {
    let of_kind = found.iter().filter(|f| f.kind == wanted);
    match wanted {
        FoundKind::Minimum => of_kind.min_by(|a, b| a.value.total_cmp(&b.value)),
        _ => of_kind.max_by(|a, b| a.value.total_cmp(&b.value)),
    }
}

/// The error of an output without a located maximum or minimum.
fn no_extremes<const M: usize, const K: usize>(output: &Output<'_, M, 1, K>) -> ToleranceError {
    ToleranceError::Unsupported {
        output: output.name().to_owned(),
        why: "it has no located maximum or no located minimum over the cycle",
    }
}

/// The Monte Carlo range of an output over the cycle.
#[derive(Clone, Debug, PartialEq)]
pub struct RangeSamples<const M: usize> {
    /// The ranges of the samples that run the cycle.
    pub statistics: Statistics,
    /// The samples drawn.
    pub samples: usize,
    /// The samples left out, by index, and why.
    pub failures: Vec<(usize, Failure<M, 1>)>,
}

impl<const M: usize> RangeSamples<M> {
    /// The fraction of the samples left out: those that cannot be
    /// assembled, do not run the cycle as the nominal design does, or
    /// whose extremes cannot be located.
    pub fn failed_fraction(&self) -> f64 {
        failed_fraction(&self.failures, self.samples)
    }

    /// The fraction of the samples that cannot run the cycle
    /// ([`Failure::cannot_run`]): [`RangeSamples::failed_fraction`] less
    /// those that run it but pass so close to a limit position that their
    /// extremes are not located.
    pub fn cannot_run_fraction(&self) -> f64 {
        cannot_run_fraction(&self.failures, self.samples)
    }
}

/// [`range`] on every sample of the run (values alone, in parallel): the
/// statistics of the ranges, and the samples left out with their reasons.
/// A sample is left out if its sweep fails, does not run the whole drive,
/// or meets singular poses the nominal design does not.
pub fn monte_carlo_range<L, const M: usize, const K: usize>(
    model: &L,
    u0: &SVector<f64, M>,
    drive: &Drive<1>,
    options: &SweepOptions,
    output: &Output<'_, M, 1, K>,
    tolerances: &Tolerances<K>,
    run: &MonteCarlo,
) -> Result<RangeSamples<M>, ToleranceError>
where
    L: Sensitivities<M, 1, K> + Clone + Sync,
{
    let nominal = model
        .sweep(u0, drive, options)
        .map_err(|error| ToleranceError::Kinematics {
            design: Design::Nominal,
            error,
        })?;
    // The output is checked once: its names, and that it can be located.
    output.resolve(model)?;
    watch_of(output)?;
    let events = nominal.events.len();
    let ranges = monte_carlo(model, tolerances, run, |sample: &L| {
        let sweep = sample
            .sweep(u0, drive, options)
            .map_err(Failure::Kinematics)?;
        if !sweep.complete || sweep.events.len() != events {
            return Err(Failure::Singular(sweep.events.first().cloned()));
        }
        let found =
            extreme_values(sample, &sweep, output, &options.options).map_err(Failure::Extremes)?;
        match (
            widest(&found, FoundKind::Minimum),
            widest(&found, FoundKind::Maximum),
        ) {
            (Some(min), Some(max)) => Ok(max.value - min.value),
            _ => Err(Failure::Extremes(no_extremes(output))),
        }
    })?;
    let mut statistics = Statistics::default();
    let mut failures = Vec::new();
    for (i, range) in ranges.into_iter().enumerate() {
        match range {
            Ok(range) => statistics.push(range),
            Err(why) => failures.push((i, why)),
        }
    }
    Ok(RangeSamples {
        statistics,
        samples: run.samples,
        failures,
    })
}
