//! The fast run: grid steps by fused evaluations only, while every pose is regular and continuous.

use super::SweepPose;
use super::state::{Progress, REGULAR_RCOND, State, Track};
use super::substep::tangent_continues;
use super::tracker::{FAST_ACCEPT, Tracker};
use crate::runtime::error::Error;
use crate::runtime::kernels::Kernels;
use crate::runtime::results::Kinematics;
use crate::runtime::trig::TrigCarrier;
use nalgebra::{SMatrix, SVector};

/// The most Newton iterations a step of the fast run may take before the
/// general machinery takes over.
const FAST_ITERATIONS: usize = 4;

/// Whether every |xᵢ| ≤ bound (false if any is NaN), without branches.
#[inline(always)]
fn within<const N: usize>(x: &SVector<f64, N>, bound: f64) -> bool {
    x.iter().fold(true, |ok, xi| ok & (xi.abs() <= bound))
}

/// Whether every entry of `a` and `b` is finite, without branches: x·0
/// is 0 for a finite x and NaN otherwise.
#[inline(always)]
fn finite<const N: usize>(a: &SVector<f64, N>, b: &SVector<f64, N>) -> bool {
    let probe = a.iter().chain(b.iter()).fold(0.0, |sum, x| sum + x * 0.0);
    probe == 0.0
}

impl<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize> Tracker<'_, L, M, F> {
    /// Whether the fast run's evaluations are written in place: where the
    /// sines and cosines are carried and the model evaluates in place
    /// ([`Kernels::evaluates_in_place`]).
    #[inline(always)]
    fn writes_in_place(&self, carries: bool) -> bool {
        carries && self.model.evaluates_in_place()
    }

    /// The fused kernel at (x, v) written over `k` (a blank one, or the
    /// run's last evaluation: Ψ_u's zeros are kept), with the sines and
    /// cosines carried by `trig` when the model reads them: in place where
    /// the run writes in place ([`Tracker::writes_in_place`]), so that
    /// nothing is copied out of the evaluation (whether a value returned
    /// is copied is the optimiser's to decide, and it has decided both
    /// ways), else as the value [`Tracker::evaluated`] returns. The same
    /// numbers, bit for bit.
    #[inline(always)]
    fn evaluate(
        &self,
        x: &SVector<f64, M>,
        v: &SVector<f64, F>,
        carries: bool,
        trig: &mut TrigCarrier<M, F>,
        k: &mut Kinematics<M, F>,
    ) {
        if !self.writes_in_place(carries) {
            *k = self.evaluated(x, v, carries, trig);
            return;
        }
        let zero = SVector::<f64, F>::zeros();
        let (trig_u, trig_v) = trig.at(&self.model.trig_u(), &self.model.trig_v(), x, v);
        (self.model).kinematics_with_trig_over(x, v, &trig_u, &trig_v, &self.dir, &zero, k);
    }

    /// The fused kernel at (x, v), with the sines and cosines carried by
    /// `trig` when the model reads them, returned.
    #[inline(always)]
    fn evaluated(
        &self,
        x: &SVector<f64, M>,
        v: &SVector<f64, F>,
        carries: bool,
        trig: &mut TrigCarrier<M, F>,
    ) -> Kinematics<M, F> {
        let zero = SVector::<f64, F>::zeros();
        if !carries {
            return self.model.kinematics(x, v, &self.dir, &zero);
        }
        let (trig_u, trig_v) = trig.at(&self.model.trig_u(), &self.model.trig_v(), x, v);
        (self.model).kinematics_with_trig(x, v, &trig_u, &trig_v, &self.dir, &zero)
    }

    /// The common case, as a tight loop: grid steps each taken by fused
    /// evaluations only (one at the prediction on a dense grid, up to
    /// [`FAST_ITERATIONS`] Newton steps on a coarse one), for as long as
    /// every pose is regular, on the branch, continuous with its prediction,
    /// converged to rounding level, and keeps the requested accuracy. Each pose goes to `on_pose`. Stops before the
    /// first step that does not qualify (the general machinery takes that
    /// one), after `steps`, or on reaching the grid index `stop`.
    ///
    /// Within a run the predictor uses the analogs one step back,
    /// u + (u′ₖ₋₁ + 1.5·u″ₖ₋₁·h)·h (the same second order, as u′ₖ ≈ u′ₖ₋₁ +
    /// u″ₖ₋₁·h), and Newton the previous pose's Ψ_u⁻¹ (a chord step): both
    /// take the inversion of Ψ_u off the chain from one pose to the next,
    /// which is what bounds the speed of a sweep.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(super) fn run_fast<P: FnMut(&SweepPose<M, F>)>(
        &self,
        at: &mut Progress<M, F>,
        direction: f64,
        steps: usize,
        stop: Option<i64>,
        carries: bool,
        trig: &mut TrigCarrier<M, F>,
        on_pose: &mut P,
    ) -> Result<(), Error> {
        if !self.fused() || at.track.state.rcond < REGULAR_RCOND {
            return Ok(());
        }
        let options = &self.options;
        let min_rcond = self
            .min_rcond_acceleration
            .max(self.min_rcond_velocity)
            .max(REGULAR_RCOND);
        let sign = at.track.sign;
        let (h, stride) = (direction, direction as i64);
        let (mut state, mut previous) = (at.track.state, at.previous_grid);
        // Where the model evaluates in place, each pose's evaluations are
        // written over one kept for the run; else each pose's first is the
        // value returned (an evaluation m × m wide made for nothing each
        // pose costs a large m dearly).
        let mut kept = self.writes_in_place(carries).then(Kinematics::blank);
        // Ψ_u's factors one step back (the matrix alone: the block order
        // is the mechanism's), valid once the run has taken a step
        // (`previous` then holds the analogs one step back): copied into
        // this one matrix for the run, never moved (at a large m each move
        // is m² numbers).
        let mut lag = SMatrix::<f64, M, M>::zeros();
        let mut lagging = false;
        let mut taken = 0;
        while at.step < steps {
            let index = at.index + stride;
            let t = index as f64;
            let predicted = if lagging && options.second_order {
                state.u + (previous.du + previous.ddu * (1.5 * h)) * h
            } else {
                self.predict(&state, t)
            };
            // The tests below are branch-free folds, and NaN fails each.
            let scale = state
                .u
                .iter()
                .fold(1.0, |m: f64, x| if x.abs() > m { x.abs() } else { m });
            if !within(&(predicted - state.u), options.max_move * scale) {
                break;
            }
            let v = self.v(t);
            // Newton from the prediction: usually one evaluation, whose
            // correction is at rounding level already; a few more where the
            // steps are coarse.
            let mut x = predicted;
            let mut fresh;
            let k = match kept.as_mut() {
                Some(kept) => {
                    self.evaluate(&x, &v, carries, trig, kept);
                    kept
                }
                None => {
                    fresh = self.evaluated(&x, &v, carries, trig);
                    &mut fresh
                }
            };
            // The first correction by the lagging factors (a chord step),
            // later ones by the current pose's.
            let mut chord = lagging;
            let mut iterations = 1;
            let converged = loop {
                let regular = (k.rcond >= min_rcond) & (k.det * sign > 0.0);
                if !regular {
                    break false;
                }
                let newton = if chord {
                    k.factors.solve_by(&lag, &k.psi)
                } else {
                    k.factors.solve(&k.psi)
                };
                x -= newton;
                if within(&newton, FAST_ACCEPT * scale) {
                    break within(&k.psi, options.options.residual_tol);
                }
                if iterations == FAST_ITERATIONS {
                    break false;
                }
                self.evaluate(&x, &v, carries, trig, k);
                chord = false;
                iterations += 1;
            };
            if !converged {
                break;
            }
            if iterations > 1 {
                // Continuous with the prediction, as in `attempt`.
                let step = (predicted - state.u).amax();
                let floor = 1e-9 * scale;
                if !within(
                    &(x - predicted),
                    options.continuity * step.max(floor) + floor,
                ) {
                    break;
                }
            }
            // Finite analogs (else the general machinery takes the step),
            // and the tangent continuous with the last pose's: not a pose
            // on a branch that crosses this one.
            if !finite(&k.udot, &k.uddot)
                || !tangent_continues(
                    &state.du,
                    &state.ddu,
                    state.rcond,
                    &k.udot,
                    &k.uddot,
                    k.rcond,
                    h,
                )
            {
                break;
            }
            let next = State {
                t,
                u: x,
                du: k.udot,
                ddu: k.uddot,
                det: k.det,
                rcond: k.rcond,
                iterations,
                solved: true,
                analogs: true,
            };
            // Where one evaluation was not enough (a coarse grid), the next
            // step starts with a fresh inverse and the current analogs: a
            // chord step would only cost another evaluation there.
            lagging = iterations == 1;
            if lagging {
                k.factors.keep_in(&mut lag);
            }
            previous = state;
            state = next;
            taken += 1;
            at.index = index;
            at.step += 1;
            on_pose(&self.pose(&state, at.step, direction)?);
            at.recorded += 1;
            if stop == Some(index) {
                break;
            }
        }
        if taken > 0 {
            at.track = Track::new(state);
            at.last_grid = state;
            at.previous_grid = previous;
        }
        Ok(())
    }
}
