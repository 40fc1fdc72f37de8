//! The tracker: the path v(t), the corrector, the analogs, one predictor–corrector sub-step.

use super::SweepOptions;
use super::state::State;
use crate::runtime::error::{Error, Stage};
use crate::runtime::factors::Factors;
use crate::runtime::kernels::Kernels;
use crate::runtime::options::{AccelerationMethod, JacobianSource, Options};
use crate::runtime::results::Kinematics;
use crate::runtime::{newton, sources};
use nalgebra::SVector;

/// u̇ and ü.
type Motion<const M: usize> = (SVector<f64, M>, SVector<f64, M>);

/// A Newton correction below this (relative to max(1, ‖u‖∞)) at the
/// prediction is accepted without a second evaluation: the pose is then
/// exact to rounding, and the analogs evaluated at the prediction differ from
/// those at the pose by about this much.
pub(super) const FAST_ACCEPT: f64 = 1e-14;

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

impl<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize> Tracker<'_, L, M, F> {
    pub(super) fn v(&self, t: f64) -> SVector<f64, F> {
        self.base + self.dir * t
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
    pub(super) fn motion(
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
        let factors = Factors::of(&psi_u, self.model.psi_u_blocks());
        let (det, rcond) = (factors.det(), factors.rcond());
        if rcond <= 0.0 {
            return (None, det, rcond);
        }
        let udot = -factors.solve(&(psi_v * vdot));
        let generated =
            || sources::generated_gamma(self.model, self.options.options.method, u, v, &udot, vdot);
        let gamma = sources::gamma(self.model, jacobian, generated, u, v, &udot, vdot);
        let uddot = -factors.solve(&gamma);
        let known = finite(&udot, &uddot);
        (known.then_some((udot, uddot)), det, rcond)
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
        let delta = -k.factors.solve(&k.psi);
        (delta.amax() <= FAST_ACCEPT * scale).then(|| self.state_from(predicted + delta, t, 1, &k))
    }

    /// One sub-step from `from` to t: predicted, corrected, and accepted
    /// only if continuous with the prediction.
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
}
