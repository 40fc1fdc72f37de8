//! Continuation along the driver, the one way the search and the
//! certificate follow a design from pose to pose: a sweep of
//! [`Requirements::steps_per_radian`](super::Requirements::steps_per_radian)
//! steps a radian, and what "the same pose" means after it — equal up to
//! whole turns of the coordinates that are angles (those under a sine or
//! cosine, `TRIG_U`), a slider's length compared as it is.

use crate::runtime::{Drive, Error, Linkage, SweepOptions, SweepPose, SweepSummary};
use nalgebra::SVector;
use std::f64::consts::TAU;

/// Where a followed design ended, and what the sweep met on the way.
pub(crate) struct Followed<const M: usize> {
    /// The last pose reached, and its driver.
    pub u: SVector<f64, M>,
    pub v: f64,
    pub summary: SweepSummary<M, 1>,
}

/// Follows `model` from the pose `start` at the driver `from` to the
/// driver `to` (at least two steps), passing every pose to `on_pose`.
pub(crate) fn follow<L, const M: usize>(
    model: &L,
    start: &SVector<f64, M>,
    (from, to): (f64, f64),
    steps_per_radian: f64,
    options: &SweepOptions,
    mut on_pose: impl FnMut(&SweepPose<M, 1>),
) -> Result<Followed<M>, Error>
where
    L: Linkage<M, 1>,
{
    let drive = Drive::Line {
        from: SVector::from([from]),
        to: SVector::from([to]),
        steps: ((to - from).abs() * steps_per_radian).ceil().max(2.0) as usize,
    };
    let (mut u, mut v) = (*start, from);
    let summary = model.sweep_each(start, &drive, options, |pose| {
        u = pose.u;
        v = pose.v[0];
        on_pose(pose);
    })?;
    Ok(Followed { u, v, summary })
}

/// The poses at `drivers`, followed one after the other from `first` at
/// the first of them; `None` if a sweep stops or ends early.
pub(crate) fn through<L, const M: usize>(
    model: &L,
    first: SVector<f64, M>,
    drivers: &[f64],
    steps_per_radian: f64,
    options: &SweepOptions,
) -> Option<Vec<SVector<f64, M>>>
where
    L: Linkage<M, 1>,
{
    let mut u = vec![first];
    for pair in drivers.windows(2) {
        let from = *u.last()?;
        let followed = follow(
            model,
            &from,
            (pair[0], pair[1]),
            steps_per_radian,
            options,
            |_| {},
        )
        .ok()?;
        if !followed.summary.complete {
            return None;
        }
        u.push(followed.u);
    }
    Some(u)
}

/// Whether the poses `a` and `b` of `L` are the same to `tolerance`
/// (relative to |b|, at least absolute): its angles up to whole turns.
pub(crate) fn same_pose<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    a: &SVector<f64, M>,
    b: &SVector<f64, M>,
    tolerance: f64,
) -> bool {
    let angles = model.trig_u();
    (0..M).all(|i| {
        let d = a[i] - b[i];
        let d = if angles[i] { within_a_turn(d) } else { d };
        d.abs() <= tolerance * b[i].abs().max(1.0)
    })
}

/// Whether the drivers `a` and `b` of `L` are the same to `tolerance`:
/// up to whole turns if the driver is an angle.
pub(crate) fn same_driver<L: Linkage<M, 1>, const M: usize>(
    model: &L,
    a: f64,
    b: f64,
    tolerance: f64,
) -> bool {
    let d = a - b;
    let d = if model.trig_v()[0] {
        within_a_turn(d)
    } else {
        d
    };
    d.abs() <= tolerance
}

/// An angle's difference reduced to the nearest whole turn.
fn within_a_turn(d: f64) -> f64 {
    d - TAU * (d / TAU).round()
}
