//! The driver loop: grid step after grid step, the fast run where it
//! applies and the general machinery elsewhere, limit positions and the
//! reversal of a rocking drive.

use super::branch_point::BRANCH_RANK;
use super::state::{Progress, Track};
use super::substep::Advance;
use super::tracker::Tracker;
use super::{Drive, Event, EventKind, SweepOptions, SweepPose, SweepSummary};
use crate::runtime::checks::check_input;
use crate::runtime::error::{Error, Stage};
use crate::runtime::kernels::Kernels;
use crate::runtime::linalg::scaled_norm;
use crate::runtime::newton;
use crate::runtime::trig::TrigCarrier;
use nalgebra::SVector;

/// Runs a sweep (see `Linkage::sweep`).
pub(crate) fn sweep<L, P, const M: usize, const F: usize>(
    model: &L,
    u0: &SVector<f64, M>,
    drive: &Drive<F>,
    options: &SweepOptions,
    on_pose: &mut P,
) -> Result<SweepSummary<M, F>, Error>
where
    L: Kernels<M, F> + ?Sized,
    P: FnMut(&SweepPose<M, F>),
{
    let (base, dir, steps, rocking) = match *drive {
        Drive::Line { from, to, steps } => {
            let steps = steps.max(1);
            (from, (to - from) / steps as f64, steps, false)
        }
        Drive::Rocking {
            from,
            step,
            max_steps,
        } => (from, step, max_steps, true),
    };
    check_input("from", base.as_slice())?;
    check_input("step", dir.as_slice())?;
    options.check()?;
    let length = scaled_norm(&dir);
    let moves = length > 0.0; // false for NaN too
    if !moves {
        return Err(Error::InvalidInput {
            argument: "drive",
            value: length,
            why: "the drive does not move (from = to, or a zero step): no direction to follow",
        });
    }
    let tracker = Tracker {
        model,
        options: *options,
        base,
        dir,
        step_length: length,
        min_rcond_velocity: options.options.min_rcond(Stage::Velocity),
        min_rcond_acceleration: options.options.min_rcond(Stage::Acceleration),
        rate: options.speed / length,
    };
    let start = newton::solve(model, u0, &base, &options.options, &mut |_| {})?;
    let state = tracker.state(start.u, 0.0, start.iterations);
    if !tracker.keeps_accuracy(&state) {
        let min_rcond = options.options.min_rcond(Stage::Velocity);
        return Err(Error::Singular {
            stage: Stage::Velocity,
            rcond: state.rcond,
            min_rcond,
        });
    }
    on_pose(&tracker.pose(&state, 0, 1.0)?);
    let mut at = Progress {
        track: Track::new(state),
        index: 0,
        step: 0,
        recorded: 1,
        last_grid: state,
        previous_grid: state,
    };
    let mut events = Vec::new();
    // The direction of travel, and the number of reversals.
    let mut direction = 1.0;
    let mut reversals = 0;
    let mut complete = true;
    // The fast path carries the sines and cosines the model reads.
    let carries = model
        .trig_u()
        .iter()
        .chain(model.trig_v().iter())
        .any(|&b| b);
    let mut trig = TrigCarrier::new();
    // A rocking drive ends back at the start after two reversals.
    let closes = |reversals: usize, direction: f64| rocking && reversals >= 2 && direction > 0.0;
    while at.step < steps {
        let stop = closes(reversals, direction).then_some(0);
        tracker.run_fast(&mut at, direction, steps, stop, carries, &mut trig, on_pose)?;
        if closes(reversals, direction) && at.index == 0 && at.step > 0 {
            return Ok(SweepSummary {
                events,
                complete: true,
                poses: at.recorded,
            });
        }
        if at.step >= steps {
            break;
        }
        // The general case: sub-steps, branch crossings, limit positions.
        at.step += 1;
        let next_index = at.index + direction as i64;
        let target = next_index as f64;
        match tracker.advance(at.track, target, &mut events, at.recorded)? {
            Advance::Reached(t) => {
                at.track = t;
                at.index = next_index;
            }
            Advance::Blocked(near) => {
                let near = near.state;
                let Some((u_star, t_star)) = tracker.locate_limit(&near) else {
                    return Err(Error::NotConverged {
                        iterations: options.options.max_iterations,
                        residual: model.psi(&near.u, &tracker.v(near.t)).amax(),
                        step: 0.0,
                    });
                };
                let rank_measure = tracker.rank_measure(&u_star, t_star);
                let kind = if rank_measure < BRANCH_RANK {
                    // A branch point the sweep could not step across.
                    EventKind::BranchPoint
                } else {
                    EventKind::LimitPosition
                };
                events.push(Event {
                    kind,
                    v: tracker.v(t_star),
                    u: u_star,
                    t: t_star,
                    after: at.recorded,
                    rank_measure,
                });
                if !rocking || kind == EventKind::BranchPoint {
                    complete = false;
                    break;
                }
                // Onto the other branch, mirroring the last grid pose at
                // least half a step from the limit, the driver reversed.
                let source = if (at.last_grid.t - t_star).abs() >= 0.5 {
                    at.last_grid
                } else {
                    at.previous_grid
                };
                let Some(mirrored) = tracker.mirror(&u_star, t_star, &source) else {
                    complete = false;
                    break;
                };
                direction = -direction;
                reversals += 1;
                at.index = mirrored.t.round() as i64;
                at.track = match tracker.advance(
                    Track::new(mirrored),
                    at.index as f64,
                    &mut events,
                    at.recorded,
                )? {
                    Advance::Reached(t) => t,
                    Advance::Blocked(_) => {
                        complete = false;
                        break;
                    }
                };
            }
        }
        let state = at.track.state;
        if tracker.keeps_accuracy(&state) {
            on_pose(&tracker.pose(&state, at.step, direction)?);
            at.recorded += 1;
        }
        at.previous_grid = at.last_grid;
        at.last_grid = state;
        if closes(reversals, direction) && at.index == 0 {
            return Ok(SweepSummary {
                events,
                complete: true,
                poses: at.recorded,
            });
        }
    }
    if rocking {
        complete = false;
    }
    Ok(SweepSummary {
        events,
        complete,
        poses: at.recorded,
    })
}
