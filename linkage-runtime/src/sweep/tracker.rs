//! The tracker: one sub-step of the continuation (predict, correct, accept
//! only if continuous), the fast run over a regular stretch, and the
//! sub-stepping between two driver values.

use super::branch_point::Passage;
use super::trig::TrigCarrier;
use super::{Event, SweepOptions, SweepPose};
use crate::checks::check_result;
use crate::error::{Error, Stage};
use crate::linalg::invert;
use crate::linkage::Linkage;
use crate::options::{AccelerationMethod, JacobianSource, Options};
use crate::results::Kinematics;
use crate::solve::acceleration_conditioning_with;
use crate::{newton, sources};
use nalgebra::{SMatrix, SVector};

/// A solved state on the path: t is the path parameter.
#[derive(Clone, Copy, Debug)]
pub(super) struct State<const M: usize, const F: usize> {
    pub(super) t: f64,
    pub(super) u: SVector<f64, M>,
    /// du/dt and d²u/dt² (zero where they cannot be computed).
    pub(super) du: SVector<f64, M>,
    pub(super) ddu: SVector<f64, M>,
    pub(super) det: f64,
    pub(super) rcond: f64,
    pub(super) iterations: usize,
    /// False for a pose that Newton could not resolve because it lies within
    /// rounding of a branch point (its u is the smooth continuation's
    /// prediction): never recorded.
    pub(super) solved: bool,
    /// Whether `du` and `ddu` hold the analogs (zero where they could not
    /// be computed per unit of t: Ψ_u singular, or so long a step that
    /// they overflow).
    pub(super) analogs: bool,
}

impl<const M: usize, const F: usize> State<M, F> {
    /// A pose at a branch point that Newton cannot resolve, taken from the
    /// prediction `u`: no tangent, no conditioning.
    pub(super) fn unresolved(u: SVector<f64, M>, t: f64) -> State<M, F> {
        State {
            t,
            u,
            du: SVector::zeros(),
            ddu: SVector::zeros(),
            det: 0.0,
            rcond: 0.0,
            iterations: 0,
            solved: false,
            analogs: false,
        }
    }
}

/// u̇ and ü.
type Motion<const M: usize> = (SVector<f64, M>, SVector<f64, M>);

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

/// A Newton correction below this (relative to max(1, ‖u‖∞)) at the
/// prediction is accepted without a second evaluation: the pose is then
/// exact to rounding, and the analogs evaluated at the prediction differ from
/// those at the pose by about this much.
const FAST_ACCEPT: f64 = 1e-14;

/// The most Newton iterations a step of the fast run may take before the
/// general machinery takes over.
const FAST_ITERATIONS: usize = 4;

/// Whether every |xᵢ| ≤ bound (false if any is NaN), without branches.
#[inline(always)]
fn within<const N: usize>(x: &SVector<f64, N>, bound: f64) -> bool {
    x.iter().fold(true, |ok, xi| ok & (xi.abs() <= bound))
}

/// Why a sub-step failed.
pub(super) enum Rejection {
    /// No acceptable pose: halve the step.
    Retry,
    /// A hard error (non-finite values).
    Fatal(Error),
}

pub(super) struct Tracker<'a, L: ?Sized, const M: usize, const F: usize> {
    pub(super) model: &'a L,
    pub(super) options: SweepOptions,
    pub(super) base: SVector<f64, F>,
    pub(super) dir: SVector<f64, F>,
    /// |dir|: the length of one unit of the path parameter, in driver units.
    pub(super) step_length: f64,
    /// The conditioning the velocities and the accelerations need.
    pub(super) min_rcond_velocity: f64,
    pub(super) min_rcond_acceleration: f64,
    /// dt/dτ at the sweep's speed (one unit of t is one step of length |dir|).
    pub(super) rate: f64,
}

impl<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize> Tracker<'_, L, M, F> {
    pub(super) fn v(&self, t: f64) -> SVector<f64, F> {
        self.base + self.dir * t
    }

    /// Ψ_t = Ψ_v · direction
    pub(super) fn psi_t(&self, u: &SVector<f64, M>, t: f64) -> SVector<f64, M> {
        sources::psi_v(self.model, self.options.options.jacobian, u, &self.v(t)) * self.dir
    }

    /// Newton at t from `guess`, without the conditioning threshold (the
    /// continuity test and the event logic judge the result).
    pub(super) fn correct(
        &self,
        guess: &SVector<f64, M>,
        t: f64,
    ) -> Result<(SVector<f64, M>, usize), Error> {
        let options = Options {
            accuracy: f64::INFINITY,
            damped: false,
            ..self.options.options
        };
        let p = newton::solve(self.model, guess, &self.v(t), &options, &mut |_| {})?;
        Ok((p.u, p.iterations))
    }

    /// Whether the fused generated kernel can serve (generated Jacobians,
    /// fused γ).
    pub(super) fn fused(&self) -> bool {
        let o = &self.options.options;
        o.jacobian == JacobianSource::Generated && o.method == AccelerationMethod::Fused
    }

    /// u̇ and ü for the driver moving at `vdot` (no driver acceleration) at
    /// (u, v), with det Ψ_u and its rcond, by the options' Jacobians and γ;
    /// u̇, ü `None` where they cannot be computed (Ψ_u singular, or not
    /// finite).
    fn motion(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        vdot: &SVector<f64, F>,
    ) -> (Option<Motion<M>>, f64, f64) {
        let finite = |a: &SVector<f64, M>, b: &SVector<f64, M>| {
            a.iter().chain(b.iter()).all(|x| x.is_finite())
        };
        if self.fused() {
            let k = self.model.kinematics(u, v, vdot, &SVector::zeros());
            let known = k.rcond > 0.0 && finite(&k.udot, &k.uddot);
            return (known.then_some((k.udot, k.uddot)), k.det, k.rcond);
        }
        let jacobian = self.options.options.jacobian;
        let psi_u = sources::psi_and_psi_u(self.model, jacobian, u, v).1;
        let psi_v = sources::psi_v(self.model, jacobian, u, v);
        let inv = invert(&psi_u);
        if inv.rcond <= 0.0 {
            return (None, inv.det, inv.rcond);
        }
        let udot = -(inv.inverse * (psi_v * vdot));
        let generated =
            || sources::generated_gamma(self.model, self.options.options.method, u, v, &udot, vdot);
        let gamma = sources::gamma(self.model, jacobian, generated, u, v, &udot, vdot);
        let uddot = -(inv.inverse * gamma);
        let known = finite(&udot, &uddot);
        (known.then_some((udot, uddot)), inv.det, inv.rcond)
    }

    /// The state at (u, t): det, conditioning and the analogs along the path.
    pub(super) fn state(&self, u: SVector<f64, M>, t: f64, iterations: usize) -> State<M, F> {
        let (analogs, det, rcond) = self.motion(&u, &self.v(t), &self.dir);
        let (du, ddu) = analogs.unwrap_or((SVector::zeros(), SVector::zeros()));
        State {
            t,
            u,
            du,
            ddu,
            det,
            rcond,
            iterations,
            solved: true,
            analogs: analogs.is_some(),
        }
    }

    /// The state from a fused evaluation (du/dt = u̇ for v̇ = dir, v̈ = 0).
    pub(super) fn state_from(
        &self,
        u: SVector<f64, M>,
        t: f64,
        iterations: usize,
        k: &Kinematics<M, F>,
    ) -> State<M, F> {
        let finite = k.rcond > 0.0 && k.udot.iter().chain(k.uddot.iter()).all(|x| x.is_finite());
        State {
            t,
            u,
            du: if finite { k.udot } else { SVector::zeros() },
            ddu: if finite { k.uddot } else { SVector::zeros() },
            det: k.det,
            rcond: k.rcond,
            iterations,
            solved: true,
            analogs: finite,
        }
    }

    pub(super) fn predict(&self, from: &State<M, F>, t: f64) -> SVector<f64, M> {
        let h = t - from.t;
        let mut u = from.u + from.du * h;
        if self.options.second_order {
            u += from.ddu * (0.5 * h * h);
        }
        u
    }

    /// One sub-step from `from` to t: predicted, corrected, and accepted
    /// only if continuous with the prediction.
    /// The fast path: one fused evaluation at the prediction gives Ψ and
    /// the Newton correction, and, when that correction is at rounding level,
    /// the velocities and accelerations too. `None` if it does not apply.
    #[inline]
    pub(super) fn attempt_fast(&self, from: &State<M, F>, t: f64) -> Option<State<M, F>> {
        if !self.fused() {
            return None;
        }
        let predicted = self.predict(from, t);
        let scale = from.u.amax().max(1.0);
        let moved = (predicted - from.u).amax();
        if moved.is_nan() || moved > self.options.max_move * scale {
            return None;
        }
        let k = self
            .model
            .kinematics(&predicted, &self.v(t), &self.dir, &SVector::zeros());
        let residual = k.psi.amax();
        if k.rcond <= 0.0 || residual.is_nan() || residual > self.options.options.residual_tol {
            return None;
        }
        let delta = -(k.inverse * k.psi);
        (delta.amax() <= FAST_ACCEPT * scale).then(|| self.state_from(predicted + delta, t, 1, &k))
    }

    /// The fused kernel at (x, v), with the sines and cosines carried by
    /// `trig` when the model reads them.
    #[inline(always)]
    pub(super) fn evaluate(
        &self,
        x: &SVector<f64, M>,
        v: &SVector<f64, F>,
        carries: bool,
        trig: &mut TrigCarrier<M, F>,
    ) -> Kinematics<M, F> {
        let zero = SVector::<f64, F>::zeros();
        if carries {
            let (trig_u, trig_v) = trig.at(&L::TRIG_U, &L::TRIG_V, x, v);
            self.model
                .kinematics_with_trig(x, v, &trig_u, &trig_v, &self.dir, &zero)
        } else {
            self.model.kinematics(x, v, &self.dir, &zero)
        }
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
        // Ψ_u⁻¹ one step back, once the run has taken a step (`previous` then
        // holds the analogs one step back).
        let mut lag: Option<SMatrix<f64, M, M>> = None;
        let mut taken = 0;
        while at.step < steps {
            let index = at.index + stride;
            let t = index as f64;
            let predicted = if lag.is_some() && options.second_order {
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
            let mut k = self.evaluate(&x, &v, carries, trig);
            let mut inverse = lag.unwrap_or(k.inverse);
            let mut iterations = 1;
            let converged = loop {
                let regular = (k.rcond >= min_rcond)
                    & (k.det * sign > 0.0)
                    & ((k.udot.sum() + k.uddot.sum()).abs() <= f64::MAX);
                if !regular {
                    break false;
                }
                let newton = inverse * k.psi;
                x -= newton;
                if within(&newton, FAST_ACCEPT * scale) {
                    break within(&k.psi, options.options.residual_tol);
                }
                if iterations == FAST_ITERATIONS {
                    break false;
                }
                k = self.evaluate(&x, &v, carries, trig);
                inverse = k.inverse;
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
            // The tangent continuous with the last pose's: not a pose on a
            // branch that crosses this one.
            if !tangent_continues(
                &state.du,
                &state.ddu,
                state.rcond,
                &k.udot,
                &k.uddot,
                k.rcond,
                h,
            ) {
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
            lag = (iterations == 1).then_some(k.inverse);
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

    pub(super) fn attempt(&self, from: &State<M, F>, t: f64) -> Result<State<M, F>, Rejection> {
        if let Some(state) = self.attempt_fast(from, t) {
            return Ok(state);
        }
        let predicted = self.predict(from, t);
        let scale = from.u.amax().max(1.0);
        let moved = (predicted - from.u).amax();
        if moved.is_nan() || moved > self.options.max_move * scale {
            return Err(Rejection::Retry);
        }
        let (u, iterations) = match self.correct(&predicted, t) {
            Ok(x) => x,
            Err(Error::NonFiniteInput { .. }) | Err(Error::NonFiniteValue { .. }) => {
                return Err(Rejection::Retry);
            }
            Err(_) => return Err(Rejection::Retry),
        };
        let step = (predicted - from.u).amax();
        let correction = (u - predicted).amax();
        let floor = 1e-9 * from.u.amax().max(1.0);
        if correction > self.options.continuity * step.max(floor) + floor {
            return Err(Rejection::Retry);
        }
        let state = self.state(u, t, iterations);
        if !state.det.is_finite() {
            return Err(Rejection::Fatal(Error::NonFiniteValue {
                stage: Stage::Position,
                quantity: "det Ψ_u",
            }));
        }
        Ok(state)
    }

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

    /// Whether the pose's velocities and accelerations keep the requested
    /// accuracy (see [`Options::accuracy`]).
    pub(super) fn keeps_accuracy(&self, state: &State<M, F>) -> bool {
        let options = &self.options.options;
        // An exactly singular pose has no velocities, whatever the accuracy.
        if !state.solved || state.rcond <= 0.0 || state.rcond < self.min_rcond_velocity {
            return false;
        }
        if state.rcond >= self.min_rcond_acceleration {
            return true;
        }
        // Near a singular pose: the finer test needs Ψ_u and Ψ_v.
        let (jacobian, v) = (options.jacobian, self.v(state.t));
        let psi_u = sources::psi_and_psi_u(self.model, jacobian, &state.u, &v).1;
        let psi_v = sources::psi_v(self.model, jacobian, &state.u, &v);
        acceleration_conditioning_with(
            &psi_u,
            &psi_v,
            state.rcond,
            self.min_rcond_acceleration,
            options,
        )
        .is_ok()
    }

    /// The pose at the sweep's speed; an error if scaling to that speed
    /// overflows (an absurd speed for the step).
    #[inline(always)]
    pub(super) fn pose(
        &self,
        state: &State<M, F>,
        step: usize,
        direction: f64,
    ) -> Result<SweepPose<M, F>, Error> {
        if !state.analogs {
            return self.pose_at_unit_scale(state, step, direction);
        }
        let rate = self.rate * direction;
        let pose = SweepPose {
            step,
            v: self.v(state.t),
            u: state.u,
            vdot: self.dir * rate,
            udot: state.du * rate,
            uddot: state.ddu * rate * rate,
            det: state.det,
            rcond: state.rcond,
            iterations: state.iterations,
        };
        // x·0 is 0 for a finite x and NaN otherwise: one cheap test of every
        // entry, which finite values far apart cannot fool (their sum could
        // overflow).
        let probe = |x: &[f64]| x.iter().fold(0.0, |acc, &x| acc + x * 0.0);
        let probes = probe(pose.v.as_slice())
            + probe(pose.vdot.as_slice())
            + probe(pose.udot.as_slice())
            + probe(pose.uddot.as_slice());
        // A non-finite entry, or a tiny speed at which the velocities and
        // accelerations may fall below the normal range: the careful tests,
        // out of line.
        let unusual = (probes != 0.0) | ((rate != 0.0) & (rate.abs() < 1e-100));
        if unusual {
            Self::unusual_pose(state, rate, &pose)?;
        }
        Ok(pose)
    }

    /// [`Self::pose`] for a state whose analogs per unit of t could not be
    /// computed (they overflow for a step of 1e160): the analogs per unit
    /// of driver length instead, at the sweep's speed.
    #[cold]
    #[inline(never)]
    fn pose_at_unit_scale(
        &self,
        state: &State<M, F>,
        step: usize,
        direction: f64,
    ) -> Result<SweepPose<M, F>, Error> {
        let along = self.dir / self.step_length;
        let v = self.v(state.t);
        let (Some((du, ddu)), _, _) = self.motion(&state.u, &v, &along) else {
            return Err(Error::NonFiniteValue {
                stage: Stage::Velocity,
                quantity: "the sweep's analogs along its path",
            });
        };
        let speed = self.options.speed * direction;
        let pose = SweepPose {
            step,
            v,
            u: state.u,
            vdot: along * speed,
            udot: du * speed,
            uddot: ddu * (speed * speed),
            det: state.det,
            rcond: state.rcond,
            iterations: state.iterations,
        };
        let unit = State { du, ddu, ..*state };
        if speed != 0.0 {
            Self::unusual_pose(&unit, speed, &pose)?;
        }
        Ok(pose)
    }

    /// The careful tests of [`Self::pose`], for a pose with a non-finite
    /// entry or at a tiny speed.
    #[cold]
    #[inline(never)]
    pub(super) fn unusual_pose(
        state: &State<M, F>,
        rate: f64,
        pose: &SweepPose<M, F>,
    ) -> Result<(), Error> {
        let finite = |x: &[f64]| x.iter().all(|v| v.is_finite());
        if !(finite(pose.v.as_slice())
            && finite(pose.vdot.as_slice())
            && finite(pose.udot.as_slice())
            && finite(pose.uddot.as_slice()))
        {
            return Err(Error::NonFiniteValue {
                stage: if finite(pose.udot.as_slice()) {
                    Stage::Acceleration
                } else {
                    Stage::Velocity
                },
                quantity: "the sweep's velocities and accelerations at its speed",
            });
        }
        let log_rate = rate.abs().log2();
        check_result(
            Stage::Velocity,
            "the sweep's u̇ at its speed",
            state.du.amax().log2() + log_rate,
        )?;
        check_result(
            Stage::Acceleration,
            "the sweep's ü at its speed",
            state.ddu.amax().log2() + 2.0 * log_rate,
        )
    }
}

/// Below this reciprocal condition number a state's tangent is not trusted
/// for prediction, nor its det's sign for the branch. Within about √ε of a
/// branch point rounding alone decides which of the crossing solutions
/// Newton finds, and rcond there is about 1e-8; a tangent computed at rcond
/// r is off by about ε/r² relative (2e-4 at this threshold), still a fine
/// predictor.
pub(super) const REGULAR_RCOND: f64 = 1e-6;

/// The current state, the last well-conditioned one (the predictor near
/// singular poses) and the sign of det Ψ_u on the branch: that of the last
/// well-conditioned state, flipped at each located branch-point crossing.
#[derive(Clone, Copy, Debug)]
pub(super) struct Track<const M: usize, const F: usize> {
    pub(super) state: State<M, F>,
    pub(super) regular: State<M, F>,
    pub(super) sign: f64,
}

impl<const M: usize, const F: usize> Track<M, F> {
    pub(super) fn new(state: State<M, F>) -> Track<M, F> {
        Track {
            state,
            regular: state,
            sign: state.det.signum(),
        }
    }

    pub(super) fn accept(&mut self, next: State<M, F>) {
        self.state = next;
        if next.rcond >= REGULAR_RCOND {
            self.regular = next;
            self.sign = next.det.signum();
        }
    }

    /// Past a branch point: on the smooth continuation, the sign of the
    /// regular pose beyond it (which may lie ahead of the pose at the
    /// target, when the target is next to the branch point).
    pub(super) fn pass(&mut self, passage: &Passage<M, F>) {
        self.state = passage.at_target.unwrap_or(passage.beyond);
        self.regular = passage.beyond;
        self.sign = passage.beyond.det.signum();
    }

    /// Where to predict from.
    pub(super) fn source(&self) -> State<M, F> {
        if self.state.rcond >= REGULAR_RCOND {
            self.state
        } else {
            self.regular
        }
    }
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

/// Where a sweep stands.
pub(super) struct Progress<const M: usize, const F: usize> {
    pub(super) track: Track<M, F>,
    /// The grid index of the current state.
    pub(super) index: i64,
    /// The driver steps taken.
    pub(super) step: usize,
    /// The poses passed on.
    pub(super) recorded: usize,
    /// The states at the last two grid indices (the source of a mirror).
    pub(super) last_grid: State<M, F>,
    pub(super) previous_grid: State<M, F>,
}
