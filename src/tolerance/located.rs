//! Located extremes and zeros under the tolerances: the stroke, the dead
//! centres that set a quick-return ratio.
//!
//! At an extremum of y(s, p) along the drive (s the distance along it),
//! y_s = 0, so the extreme value moves by its partial derivative alone —
//! the envelope theorem: d y*/dp = y_p. Where it is moves by implicit
//! differentiation of y_s(s*, p) = 0: ds*/dp = −y_sp / y_ss, with
//! y_sp = ẏ_p / |v̇| and y_ss = ÿ / |v̇|² at the sweep's constant speed (so
//! for coordinates and points at position level, whose velocity and
//! acceleration sensitivities are known). At a zero, ds*/dp = −y_p / y_s.

use super::output::TolerancePose;
use super::{Output, ToleranceError, gradient, with_gradient};
use crate::runtime::{Motion, Options, Sensitivities, Sweep};
use crate::watch::{Found, FoundKind, Watch, locate};
use nalgebra::SVector;
use num_dual::DualSVec64;

/// A located zero or extremum, and how it moves with the parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Located<const K: usize> {
    pub kind: FoundKind,
    /// The output there, with its gradient: y_p at an extremum (the
    /// envelope theorem), zero at a zero.
    pub value: DualSVec64<K>,
    /// The driver where it is, with its gradient; `None` for an extremum
    /// of an output other than a coordinate or point at position level.
    pub v: Option<DualSVec64<K>>,
}

/// The extrema of a coordinate or a point's coordinate along `sweep`
/// (located by [`locate`]), each with the gradients of its value and its
/// place.
pub fn extremes<L, const M: usize, const K: usize>(
    model: &L,
    sweep: &Sweep<M, 1>,
    output: &Output<'_, M, 1, K>,
    options: &Options,
) -> Result<Vec<Located<K>>, ToleranceError>
where
    L: Sensitivities<M, 1, K>,
{
    let Some(watch) = output.watch() else {
        return Err(ToleranceError::Unsupported {
            output: output.name().to_owned(),
            why: "only coordinates and points are located here; locate a function's extremes with watch::locate and Watch::function, then use at_found",
        });
    };
    locate(model, sweep, &[watch.extrema()], options)?
        .iter()
        .map(|found| at_found(model, sweep, found, output, options))
        .collect()
}

/// The extrema of a coordinate or a point's coordinate along `sweep`,
/// values and places alone: what a Monte Carlo sample needs. Unlike
/// [`extremes`] it asks for no sensitivities, so it also serves a sample
/// whose cycle passes close to a singular pose, where they are refused.
pub fn extreme_values<L, const M: usize, const K: usize>(
    model: &L,
    sweep: &Sweep<M, 1>,
    output: &Output<'_, M, 1, K>,
    options: &Options,
) -> Result<Vec<Found<M, 1>>, ToleranceError>
where
    L: Sensitivities<M, 1, K>,
{
    Ok(locate(model, sweep, &[watch_of(output)?], options)?)
}

/// The watch of the extrema of a coordinate or a point's coordinate.
pub(super) fn watch_of<const M: usize, const K: usize>(
    output: &Output<'_, M, 1, K>,
) -> Result<Watch<'static, M, 1>, ToleranceError> {
    match output.watch() {
        Some(watch) => Ok(watch.extrema()),
        None => Err(ToleranceError::Unsupported {
            output: output.name().to_owned(),
            why: "only coordinates and points are located here; locate a function's extremes with watch::locate and Watch::function",
        }),
    }
}

/// How the zero or extremum `found` of `output` (located along `sweep`
/// by [`locate`], watching the same quantity) moves with the parameters.
pub fn at_found<L, const M: usize, const K: usize>(
    model: &L,
    sweep: &Sweep<M, 1>,
    found: &Found<M, 1>,
    output: &Output<'_, M, 1, K>,
    options: &Options,
) -> Result<Located<K>, ToleranceError>
where
    L: Sensitivities<M, 1, K>,
{
    let resolved = output.resolve(model)?;
    let vdot = sweep.poses[found.between.0].vdot;
    let speed = vdot[0].abs();
    let direction = vdot[0].signum();
    let motion = Motion {
        u: found.u,
        v: found.v,
        udot: found.udot,
        vdot,
        uddot: found.uddot,
        vddot: SVector::zeros(),
    };
    let sensitivity = model.sensitivities(&motion, options)?;
    let pose = TolerancePose::with_gradients(model, &motion, &sensitivity);
    let y = resolved.at(&pose, &pose);
    let moved = |along: SVector<f64, K>| with_gradient(found.v[0], along * direction);
    let located = match found.kind {
        FoundKind::Zero { .. } => Located {
            kind: found.kind,
            value: with_gradient(y.re, SVector::zeros()),
            v: Some(moved(-gradient(&y) / found.rate)),
        },
        FoundKind::Maximum | FoundKind::Minimum => {
            let place = resolved
                .velocity(&pose)
                .zip(resolved.acceleration(&pose))
                .map(|(rate, curvature)| {
                    let y_sp = gradient(&rate) / speed;
                    let y_ss = curvature.re / (speed * speed);
                    moved(-y_sp / y_ss)
                });
            Located {
                kind: found.kind,
                value: y,
                v: place,
            }
        }
    };
    let finite = |x: &DualSVec64<K>| x.re.is_finite() && gradient(x).iter().all(|g| g.is_finite());
    if finite(&located.value) && located.v.as_ref().is_none_or(finite) {
        Ok(located)
    } else {
        Err(ToleranceError::Unsupported {
            output: output.name().to_owned(),
            why: "its gradient is not finite here (a degenerate extremum, where the quantity's second derivative vanishes)",
        })
    }
}
