//! Sub-stepping between driver values, and the singular-pose judgement of each sub-step.

use super::Event;
use super::state::{Passage, REGULAR_RCOND, State, Track};
use super::tracker::{Rejection, Tracker};
use crate::runtime::error::Error;
use crate::runtime::kernels::Kernels;
use nalgebra::SVector;

/// Whether the analogs at b continue those at a, h further along the path:
/// |u′_b − u′_a| no more than u″ allows over h (twice the larger end's, a
/// margin over the mean value theorem), plus the rounding of u′ near a
/// singular pose (ε·κ² relative, κ = 1/rcond). A jump beyond that is the
/// mark of a pose on another branch that crosses this one: at a branch point
/// the tangent of each branch is continuous, and the two differ.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) fn tangent_continues<const M: usize>(
    du_a: &SVector<f64, M>,
    ddu_a: &SVector<f64, M>,
    rcond_a: f64,
    du_b: &SVector<f64, M>,
    ddu_b: &SVector<f64, M>,
    rcond_b: f64,
    h: f64,
) -> bool {
    let jump = (du_b - du_a).amax();
    let curvature = ddu_a.amax().max(ddu_b.amax());
    let size = du_a.amax().max(du_b.amax());
    let rounding = 1e-9 + 4.0 * f64::EPSILON / (rcond_a * rcond_b);
    jump <= 2.0 * curvature * h.abs() + rounding * size
}

/// The verdict on a sub-step.
pub(super) enum Step<const M: usize, const F: usize> {
    /// The pose continues the tracked branch (or stands next to a singular
    /// pose).
    Accept(State<M, F>),
    /// A branch point was passed.
    Pass(Passage<M, F>),
    /// No acceptable pose: halve the step.
    Retry,
}

pub(super) enum Advance<const M: usize, const F: usize> {
    Reached(Track<M, F>),
    /// The driver cannot pass beyond this track.
    Blocked(Track<M, F>),
}

impl<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize> Tracker<'_, L, M, F> {
    /// Advances from `from` to the path parameter `target`, sub-stepping as
    /// needed; returns the reached track, or the last one before a limit the
    /// driver cannot pass, with the events met on the way.
    pub(super) fn advance(
        &self,
        from: Track<M, F>,
        target: f64,
        events: &mut Vec<Event<M, F>>,
        recorded: usize,
    ) -> Result<Advance<M, F>, Error> {
        let mut track = from;
        let mut delta = target - track.state.t;
        let min_delta = self.options.min_substep * (target - from.state.t).abs().max(1e-300);
        let mut substeps = 0;
        while track.state.t != target {
            substeps += 1;
            if substeps > self.options.max_substeps {
                return Err(Error::SubstepLimit {
                    step: recorded,
                    limit: self.options.max_substeps,
                });
            }
            let t_try = if (target - track.state.t).abs() <= delta.abs() {
                target
            } else {
                track.state.t + delta
            };
            // Predict from a well-conditioned state: at a singular pose the
            // tangent is undefined.
            let step = match self.attempt(&track.source(), t_try) {
                Ok(next) => self.judge(&track, next, t_try),
                Err(Rejection::Fatal(e)) => return Err(e),
                Err(Rejection::Retry) => Step::Retry,
            };
            match step {
                Step::Accept(next) => {
                    track.accept(next);
                    // Grow back towards the full step after a success.
                    let remaining = target - track.state.t;
                    delta = (delta * 2.0).abs().min(remaining.abs()) * remaining.signum();
                }
                Step::Pass(passage) => {
                    events.push(Event {
                        after: recorded,
                        ..passage.event
                    });
                    track.pass(&passage);
                    delta = target - track.state.t;
                }
                Step::Retry => {
                    delta *= 0.5;
                    if delta.abs() < min_delta {
                        // The sub-steps cannot get on: a branch point to step
                        // over, or a limit the driver cannot pass.
                        let near = track.state;
                        let Some(passage) =
                            self.pass_branch_point(&track.regular, &near.u, near.t, target)
                        else {
                            return Ok(Advance::Blocked(track));
                        };
                        events.push(Event {
                            after: recorded,
                            ..passage.event
                        });
                        track.pass(&passage);
                        delta = target - track.state.t;
                    }
                }
            }
        }
        Ok(Advance::Reached(track))
    }

    /// What to do with a pose the corrector reached at `t_try`.
    ///
    /// A pose next to a singular one is taken for its position only: neither
    /// its det's sign nor its tangent is trusted. A regular pose continues
    /// the tracked branch if its det has the branch's sign and its tangent
    /// continues the last regular pose's. Otherwise the sweep has passed a
    /// branch point — its det flipped on the smooth continuation, or the
    /// corrector fell onto the other branch, whose tangent differs — or the
    /// corrector jumped to another branch: a branch point between the two is
    /// located and passed on the smooth continuation; failing that, the step
    /// is halved. One exception: after a stretch of poses next to a singular
    /// one with no branch point in it (the branches come close and turn
    /// sharply, but do not cross), a tangent that turned is the branch's own.
    fn judge(&self, track: &Track<M, F>, next: State<M, F>, t_try: f64) -> Step<M, F> {
        if next.rcond < REGULAR_RCOND {
            return Step::Accept(next);
        }
        let before = &track.regular;
        let flipped = next.det.signum() != track.sign;
        let continuous = tangent_continues(
            &before.du,
            &before.ddu,
            before.rcond,
            &next.du,
            &next.ddu,
            next.rcond,
            next.t - before.t,
        );
        if !flipped && continuous {
            return Step::Accept(next);
        }
        // The poses since `before` were next to a singular one.
        let through_singular = track.state.rcond < REGULAR_RCOND;
        if flipped || through_singular {
            // Where to look for the branch point: the pose nearest the
            // singular one, or where det Ψ_u, linear through a transversal
            // crossing, vanishes between the two.
            let (guess_u, guess_t) = if through_singular {
                (track.state.u, track.state.t)
            } else {
                let w = before.det / (before.det - next.det);
                (
                    before.u + (next.u - before.u) * w,
                    before.t + (next.t - before.t) * w,
                )
            };
            if let Some(passage) = self.pass_branch_point(before, &guess_u, guess_t, t_try) {
                return Step::Pass(passage);
            }
            if !flipped {
                return Step::Accept(next);
            }
        }
        Step::Retry
    }
}
