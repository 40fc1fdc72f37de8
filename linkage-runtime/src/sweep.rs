//! Continuation sweeps: the mechanism driven along a path, pose after pose,
//! without ever jumping silently to another assembly branch, and with every
//! singular pose on the way located and classified.
//!
//! Between two requested driver values the sweep takes as many sub-steps as
//! it needs. Each sub-step predicts the next pose from the velocity ratios
//! (first order, u + u′Δt) and, by default, the second-order analog
//! (+ ½u″Δt²), then corrects it with Newton. A corrected pose is accepted
//! only if it lies close to the prediction (the continuity of u), and a
//! change of sign of det Ψ_u between accepted poses is examined: where the
//! branch truly passes through a singular pose (a *branch point*, e.g. the
//! change-point four-bar at its collinear pose) the crossing is located and
//! reported; a jump to the mirror branch is refused and the step halved.
//!
//! Where the driver cannot advance any further, the pose is a *limit
//! position*: it is located exactly as the solution of Ψ = 0, det Ψ_u = 0,
//! and, when the drive rocks, the sweep passes onto the other branch and
//! reverses the driver — the full rocking motion of a non-Grashof four-bar.

use crate::error::{Error, Stage, check_input};
use crate::linalg::{determinant, invert};
use crate::model::{AccelerationMethod, Linkage, Options};
use crate::sources;
use nalgebra::{DMatrix, DVector, SMatrix, SVector};

/// How the driver moves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Drive<const F: usize> {
    /// From `from` to `to` along a straight line of driver space, in `steps`
    /// equal steps. A limit position on the way ends the sweep (the path
    /// cannot be followed further).
    Line {
        from: SVector<f64, F>,
        to: SVector<f64, F>,
        steps: usize,
    },
    /// Steps of `step` from `from`, reversing at every limit position, until
    /// the mechanism is back at `from` moving the way it started after two
    /// reversals (one full rocking cycle), or after `max_steps` steps.
    Rocking {
        from: SVector<f64, F>,
        step: SVector<f64, F>,
        max_steps: usize,
    },
}

/// The choices of a sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepOptions {
    /// Newton's tolerances and the other solver choices.
    pub options: Options,
    /// The driver's speed along the path (driver units per second): the
    /// poses' velocities and accelerations are for this speed with no
    /// driver acceleration. 1 gives the kinematic analogs du/dv, d²u/dv².
    pub speed: f64,
    /// Predict with the second-order analog as well as the first.
    pub second_order: bool,
    /// A corrected pose farther from its prediction than this fraction of
    /// the predicted step is taken for a jump to another branch.
    pub continuity: f64,
    /// Singular poses are located to this precision in the path parameter
    /// (the driver, for f = 1).
    pub locate_tolerance: f64,
    /// The largest predicted change of u in one sub-step, relative to
    /// max(1, ‖u‖∞): near a singular pose the velocity ratios blow up, and
    /// this keeps the predictor from throwing Newton onto a far branch.
    pub max_move: f64,
    /// The most sub-steps one step of the drive may take (halvings at
    /// singular poses included): a drive too long for its number of steps
    /// (a crank turned through 10⁹ revolutions in ten steps) is an
    /// [`Error::SubstepLimit`] rather than an endless loop.
    pub max_substeps: usize,
}

impl SweepOptions {
    /// That every setting is in its range.
    pub fn check(&self) -> Result<(), Error> {
        self.options.check()?;
        let invalid = |argument, value, why| {
            Err(Error::InvalidInput {
                argument,
                value,
                why,
            })
        };
        if !self.speed.is_finite() {
            return invalid("speed", self.speed, "the driver's speed must be finite");
        }
        for (argument, value) in [
            ("continuity", self.continuity),
            ("locate_tolerance", self.locate_tolerance),
            ("max_move", self.max_move),
        ] {
            if !(value > 0.0 && value.is_finite()) {
                return invalid(argument, value, "must be positive and finite");
            }
        }
        if self.max_substeps == 0 {
            return invalid("max_substeps", 0.0, "a step needs at least one sub-step");
        }
        Ok(())
    }
}

impl Default for SweepOptions {
    fn default() -> Self {
        SweepOptions {
            options: Options::default(),
            speed: 1.0,
            second_order: true,
            continuity: 0.5,
            locate_tolerance: 1e-12,
            max_move: 0.1,
            max_substeps: 100_000,
        }
    }
}

/// One pose of a sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepPose<const M: usize, const F: usize> {
    /// The sequence number of the driver step that reached this pose (0 for
    /// the start).
    pub step: usize,
    pub v: SVector<f64, F>,
    pub u: SVector<f64, M>,
    /// Velocities for the driver moving at `speed` in its current direction.
    pub vdot: SVector<f64, F>,
    pub udot: SVector<f64, M>,
    pub uddot: SVector<f64, M>,
    /// det Ψ_u: its sign is the assembly branch.
    pub det: f64,
    /// The reciprocal condition number of Ψ_u.
    pub rcond: f64,
    /// Newton iterations of the last corrector.
    pub iterations: usize,
}

/// What kind of singular pose the sweep met.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventKind {
    /// The driver cannot go further: det Ψ_u = 0 with [Ψ_u Ψ_v] of full
    /// rank; the mechanism must reverse (a dead centre for this driver).
    LimitPosition,
    /// Two branches cross: det Ψ_u = 0 and [Ψ_u Ψ_v] rank-deficient (the
    /// change-point linkage's collinear pose); the sweep went straight on.
    BranchPoint,
}

/// A singular pose met by a sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Event<const M: usize, const F: usize> {
    pub kind: EventKind,
    pub v: SVector<f64, F>,
    pub u: SVector<f64, M>,
    /// The path parameter t of the event (v = from + t·direction).
    pub t: f64,
    /// The number of poses recorded before the event.
    pub after: usize,
    /// The smallest singular value of [Ψ_u Ψ_v] relative to the largest:
    /// about 0 at a branch point.
    pub rank_measure: f64,
}

/// The poses and events of a sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep<const M: usize, const F: usize> {
    /// One pose per driver step, except where the velocities and
    /// accelerations would not keep [`Options::accuracy`] (at or next to a
    /// singular pose, which the events report): `step` numbers them.
    pub poses: Vec<SweepPose<M, F>>,
    pub events: Vec<Event<M, F>>,
    /// Whether the whole drive was followed (false: a limit position ended
    /// a line, or `max_steps` ended a rocking drive before it closed).
    pub complete: bool,
}

/// The outcome of a streamed sweep ([`Linkage::sweep_each`]).
#[derive(Clone, Debug, PartialEq)]
pub struct SweepSummary<const M: usize, const F: usize> {
    pub events: Vec<Event<M, F>>,
    /// As [`Sweep::complete`].
    pub complete: bool,
    /// The number of poses passed on.
    pub poses: usize,
}

/// A solved state on the path: t is the path parameter.
#[derive(Clone, Copy, Debug)]
struct State<const M: usize, const F: usize> {
    t: f64,
    u: SVector<f64, M>,
    /// du/dt and d²u/dt² (zero where they cannot be computed).
    du: SVector<f64, M>,
    ddu: SVector<f64, M>,
    det: f64,
    rcond: f64,
    iterations: usize,
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

/// Below this, [Ψ_u Ψ_v] is rank-deficient: a branch point.
const BRANCH_RANK: f64 = 1e-6;

/// The sines and cosines of the coordinates a model reads from its caller
/// ([`Linkage::kinematics_with_trig`]), carried from an anchor angle a by
/// the angle-addition formulas
///
/// ```text
/// sin(a + δ) = sin a + (sin a·(cos δ − 1) + cos a·sin δ)
/// cos(a + δ) = cos a + (cos a·(cos δ − 1) − sin a·sin δ)
/// ```
///
/// with sin δ and cos δ − 1 from their Taylor series: to δ⁵ for
/// |δ| ≤ 2⁻⁹, to δ⁹ for |δ| ≤ 1/16 (the truncation is below 10⁻¹⁸ either
/// way), `sin_cos` beyond. The correction is small against the anchor's
/// value, so the result is rounded about once: as accurate as a direct
/// `sin_cos`, for a handful of multiplications. Once a coordinate has moved
/// 2⁻¹⁰ from its anchor it is re-anchored where it is, the `sin_cos` of the
/// new anchor running beside the current step (the current value still
/// comes from the old anchor), so a dense sweep stays on the short series.
struct TrigCarrier<const M: usize, const F: usize> {
    anchor_u: [f64; M],
    trig_u: [(f64, f64); M],
    anchor_v: [f64; F],
    trig_v: [(f64, f64); F],
}

/// (sin, cos) of n angles.
type SinCos<const N: usize> = [(f64, f64); N];

/// The ranges of |δ| carried by the short and the long series.
const SHORT_RANGE: f64 = 1.0 / 512.0;
const LONG_RANGE: f64 = 1.0 / 16.0;

impl<const M: usize, const F: usize> TrigCarrier<M, F> {
    /// Anchored nowhere: the first use anchors each coordinate it needs.
    fn new() -> Self {
        TrigCarrier {
            anchor_u: [f64::NAN; M],
            trig_u: [(0.0, 1.0); M],
            anchor_v: [f64::NAN; F],
            trig_v: [(0.0, 1.0); F],
        }
    }

    /// (sin, cos) of the masked coordinates of u and v (unspecified
    /// elsewhere).
    #[inline(always)]
    fn at(
        &mut self,
        mask_u: &[bool; M],
        mask_v: &[bool; F],
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
    ) -> (SinCos<M>, SinCos<F>) {
        (
            carry_all(mask_u, &mut self.anchor_u, &mut self.trig_u, u.as_slice()),
            carry_all(mask_v, &mut self.anchor_v, &mut self.trig_v, v.as_slice()),
        )
    }
}

/// [`carry`] for every masked x[k]. The common case, every one within half
/// the short range of its anchor, is done lane by lane without branches
/// (all lanes, masked or not: the others' values are not read).
#[inline(always)]
fn carry_all<const N: usize>(
    mask: &[bool; N],
    anchor: &mut [f64; N],
    trig: &mut SinCos<N>,
    x: &[f64],
) -> SinCos<N> {
    let mut d = [0.0; N];
    let mut near = true;
    for k in 0..N {
        d[k] = x[k] - anchor[k];
        near &= !mask[k] | (d[k].abs() <= 0.5 * SHORT_RANGE);
    }
    let mut out = [(0.0, 1.0); N];
    if near {
        for k in 0..N {
            let d2 = d[k] * d[k];
            let sin_d = d[k] + d[k] * d2 * (SIN_1 + d2 * SIN_2);
            let cos_d_minus_1 = d2 * (COS_1 + d2 * COS_2);
            let (s, c) = trig[k];
            out[k] = (
                s + (s * cos_d_minus_1 + c * sin_d),
                c + (c * cos_d_minus_1 - s * sin_d),
            );
        }
    } else {
        for k in 0..N {
            if mask[k] {
                out[k] = carry(&mut anchor[k], &mut trig[k], x[k]);
            }
        }
    }
    out
}

/// The Taylor coefficients of sin δ − δ and cos δ − 1.
const SIN_1: f64 = -1.0 / 6.0;
const SIN_2: f64 = 1.0 / 120.0;
const SIN_3: f64 = -1.0 / 5040.0;
const SIN_4: f64 = 1.0 / 362_880.0;
const COS_1: f64 = -0.5;
const COS_2: f64 = 1.0 / 24.0;
const COS_3: f64 = -1.0 / 720.0;
const COS_4: f64 = 1.0 / 40_320.0;

/// (sin x, cos x) carried from the anchor (see [`TrigCarrier`]).
#[inline(always)]
fn carry(anchor: &mut f64, trig: &mut (f64, f64), x: f64) -> (f64, f64) {
    let d = x - *anchor;
    let distance = d.abs();
    // NaN (no anchor yet, or x not finite) takes the last branch.
    let (sin_d, cos_d_minus_1) = if distance <= SHORT_RANGE {
        let d2 = d * d;
        // sin δ = δ − δ³/3! + δ⁵/5!,  cos δ − 1 = −δ²/2! + δ⁴/4!
        (d + d * d2 * (SIN_1 + d2 * SIN_2), d2 * (COS_1 + d2 * COS_2))
    } else if distance <= LONG_RANGE {
        let d2 = d * d;
        // … to δ⁹ and δ⁸
        (
            d + d * d2 * (SIN_1 + d2 * (SIN_2 + d2 * (SIN_3 + d2 * SIN_4))),
            d2 * (COS_1 + d2 * (COS_2 + d2 * (COS_3 + d2 * COS_4))),
        )
    } else {
        return reanchor(anchor, trig, x);
    };
    let (s, c) = *trig;
    let carried = (
        s + (s * cos_d_minus_1 + c * sin_d),
        c + (c * cos_d_minus_1 - s * sin_d),
    );
    if distance > 0.5 * SHORT_RANGE {
        reanchor(anchor, trig, x);
    }
    carried
}

/// Anchors at x. Out of line, so that the compiler does not compute the
/// `sin_cos` at every call to turn the rare branch into a select.
#[cold]
#[inline(never)]
fn reanchor(anchor: &mut f64, trig: &mut (f64, f64), x: f64) -> (f64, f64) {
    *anchor = x;
    *trig = x.sin_cos();
    *trig
}

/// Why a sub-step failed.
enum Rejection {
    /// No acceptable pose: halve the step.
    Retry,
    /// A hard error (non-finite values).
    Fatal(Error),
}

struct Tracker<'a, L: ?Sized, const M: usize, const F: usize> {
    model: &'a L,
    options: SweepOptions,
    base: SVector<f64, F>,
    dir: SVector<f64, F>,
    /// The conditioning the velocities and the accelerations need.
    min_rcond_velocity: f64,
    min_rcond_acceleration: f64,
    /// dt/dτ at the sweep's speed (one unit of t is one step of length |dir|).
    rate: f64,
}

impl<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize> Tracker<'_, L, M, F> {
    fn v(&self, t: f64) -> SVector<f64, F> {
        self.base + self.dir * t
    }

    /// Ψ_t = Ψ_v · direction
    fn psi_t(&self, u: &SVector<f64, M>, t: f64) -> SVector<f64, M> {
        sources::psi_v(self.model, self.options.options.jacobian, u, &self.v(t)) * self.dir
    }

    /// Newton at t from `guess`, without the conditioning threshold (the
    /// continuity test and the event logic judge the result).
    fn correct(&self, guess: &SVector<f64, M>, t: f64) -> Result<(SVector<f64, M>, usize), Error> {
        let options = Options {
            accuracy: f64::INFINITY,
            damped: false,
            ..self.options.options
        };
        let p = self.model.solve_position(guess, &self.v(t), &options)?;
        Ok((p.u, p.iterations))
    }

    /// The state at (u, t): det, conditioning and the analogs along the path.
    /// Whether the fused generated kernel can serve (generated Jacobians,
    /// fused γ).
    fn fused(&self) -> bool {
        let o = &self.options.options;
        o.jacobian == sources::JacobianSource::Generated && o.method == AccelerationMethod::Fused
    }

    /// The state at (u, t): det, conditioning and the analogs along the path.
    fn state(&self, u: SVector<f64, M>, t: f64, iterations: usize) -> State<M, F> {
        let v = self.v(t);
        if self.fused() {
            let k = self.model.kinematics(&u, &v, &self.dir, &SVector::zeros());
            return self.state_from(u, t, iterations, &k);
        }
        let jacobian = self.options.options.jacobian;
        let psi_u = sources::psi_and_psi_u(self.model, jacobian, &u, &v).1;
        let psi_v = sources::psi_v(self.model, jacobian, &u, &v);
        let inv = invert(&psi_u);
        let det = inv.det;
        let (mut du, mut ddu) = (SVector::zeros(), SVector::zeros());
        if inv.rcond > 0.0 {
            du = -(inv.inverse * (psi_v * self.dir));
            let generated = || {
                self.model
                    .gamma_by(self.options.options.method, &u, &v, &du, &self.dir)
            };
            let gamma = sources::gamma(self.model, jacobian, generated, &u, &v, &du, &self.dir);
            ddu = -(inv.inverse * gamma);
            if !du.iter().chain(ddu.iter()).all(|x| x.is_finite()) {
                du = SVector::zeros();
                ddu = SVector::zeros();
            }
        }
        State {
            t,
            u,
            du,
            ddu,
            det,
            rcond: inv.rcond,
            iterations,
        }
    }

    /// The state from a fused evaluation (du/dt = u̇ for v̇ = dir, v̈ = 0).
    fn state_from(
        &self,
        u: SVector<f64, M>,
        t: f64,
        iterations: usize,
        k: &crate::model::Kinematics<M, F>,
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
        }
    }

    fn predict(&self, from: &State<M, F>, t: f64) -> SVector<f64, M> {
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
    fn attempt_fast(&self, from: &State<M, F>, t: f64) -> Option<State<M, F>> {
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
    fn evaluate(
        &self,
        x: &SVector<f64, M>,
        v: &SVector<f64, F>,
        carries: bool,
        trig: &mut TrigCarrier<M, F>,
    ) -> crate::model::Kinematics<M, F> {
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
    fn run_fast<P: FnMut(&SweepPose<M, F>)>(
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
            let next = State {
                t,
                u: x,
                du: k.udot,
                ddu: k.uddot,
                det: k.det,
                rcond: k.rcond,
                iterations,
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

    fn attempt(&self, from: &State<M, F>, t: f64) -> Result<State<M, F>, Rejection> {
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
    fn advance(
        &self,
        from: Track<M, F>,
        target: f64,
        events: &mut Vec<Event<M, F>>,
        recorded: usize,
    ) -> Result<Advance<M, F>, Error> {
        let mut track = from;
        let mut delta = target - track.state.t;
        let min_delta = self.options.locate_tolerance * (target - from.state.t).abs().max(1e-300);
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
            let source = track.source();
            match self.attempt(&source, t_try) {
                Ok(next) => {
                    let regular = track.regular;
                    if next.det != 0.0 && next.det.signum() != track.sign {
                        match self.locate_crossing(&regular, &next) {
                            Some(event) => {
                                events.push(Event {
                                    after: recorded,
                                    ..event
                                });
                                // Crossed: the branch goes on with the other
                                // sign, even if `next` is too singular to
                                // show it.
                                track.sign = -track.sign;
                            }
                            None => {
                                // A jump to the mirror branch, not a crossing.
                                delta *= 0.5;
                                if delta.abs() < min_delta {
                                    return Ok(Advance::Blocked(track));
                                }
                                continue;
                            }
                        }
                    }
                    track.accept(next);
                    // Grow back towards the full step after a success.
                    let remaining = target - track.state.t;
                    delta = (delta * 2.0).abs().min(remaining.abs()) * remaining.signum();
                }
                Err(Rejection::Fatal(e)) => return Err(e),
                Err(Rejection::Retry) => {
                    delta *= 0.5;
                    if delta.abs() < min_delta {
                        // Try to jump over a branch point before calling it
                        // a limit.
                        if let Some((next, event)) = self.jump_branch_point(&track, target) {
                            events.push(Event {
                                after: recorded,
                                ..event
                            });
                            track.sign = -track.sign;
                            track.accept(next);
                            delta = target - track.state.t;
                            continue;
                        }
                        return Ok(Advance::Blocked(track));
                    }
                }
            }
        }
        Ok(Advance::Reached(track))
    }

    /// Where det Ψ_u changed sign between two accepted states, finds the
    /// crossing by bisection on the tracked branch; `None` if the branch
    /// does not continue through it (the second state was on another branch).
    fn locate_crossing(&self, a: &State<M, F>, b: &State<M, F>) -> Option<Event<M, F>> {
        let (mut lo, mut hi) = (*a, *b);
        for _ in 0..200 {
            if (hi.t - lo.t).abs() <= self.options.locate_tolerance * hi.t.abs().max(1.0) {
                break;
            }
            let mid = 0.5 * (lo.t + hi.t);
            if mid == lo.t || mid == hi.t {
                break;
            }
            // The secant through the bracket predicts well on both sides of a
            // transversal crossing, where the tangent is ill-conditioned.
            let guess = lo.u + (hi.u - lo.u) * ((mid - lo.t) / (hi.t - lo.t));
            let Ok((u, iterations)) = self.correct(&guess, mid) else {
                break;
            };
            let span = (hi.u - lo.u).amax();
            if (u - guess).amax() > self.options.continuity * span + 1e-12 * u.amax().max(1.0) {
                // Newton left the bracket's branch: not a crossing.
                return None;
            }
            let m = self.state(u, mid, iterations);
            if m.det == 0.0 {
                lo = m;
                hi = m;
                break;
            }
            if m.det.signum() == lo.det.signum() {
                lo = m;
            } else {
                hi = m;
            }
        }
        // det is linear through a transversal crossing.
        let w = if lo.t == hi.t {
            0.0
        } else {
            lo.det / (lo.det - hi.det)
        };
        if !(0.0..=1.0).contains(&w) {
            return None;
        }
        let t = lo.t + w * (hi.t - lo.t);
        let u = lo.u + (hi.u - lo.u) * w;
        // Two branches cross only where [Ψ_u Ψ_v] loses rank; elsewhere the
        // sign change was a jump across a limit position's fold.
        let rank_measure = self.rank_measure(&u, t);
        (rank_measure < BRANCH_RANK).then(|| Event {
            kind: EventKind::BranchPoint,
            v: self.v(t),
            u,
            t,
            after: 0,
            rank_measure,
        })
    }

    /// Near a pose where Newton fails, tries to step over a branch point
    /// with the tangent predictor: success with det of the other sign means
    /// the branch crosses another one there.
    fn jump_branch_point(
        &self,
        track: &Track<M, F>,
        target: f64,
    ) -> Option<(State<M, F>, Event<M, F>)> {
        let (from, regular) = (track.source(), track.regular);
        let direction = (target - track.state.t).signum();
        let mut h = self.options.locate_tolerance * track.state.t.abs().max(1.0) * 4.0;
        let limit = (target - track.state.t).abs();
        while h <= limit {
            let t = track.state.t + direction * h;
            if let Ok(next) = self.attempt(&from, t) {
                if next.det != 0.0 && next.det.signum() != track.sign {
                    return self
                        .locate_crossing(&regular, &next)
                        .map(|event| (next, event));
                }
                return None;
            }
            h *= 4.0;
        }
        None
    }

    /// σ_min/σ_max of [Ψ_u Ψ_t].
    fn rank_measure(&self, u: &SVector<f64, M>, t: f64) -> f64 {
        let v = self.v(t);
        let psi_u = sources::psi_and_psi_u(self.model, self.options.options.jacobian, u, &v).1;
        // Ψ_v along the unit direction of the path: the measure must not
        // depend on the step length.
        let psi_t = self.psi_t(u, t) / self.dir.norm().max(f64::MIN_POSITIVE);
        let mut q = DMatrix::<f64>::zeros(M, M + 1);
        for i in 0..M {
            for j in 0..M {
                q[(i, j)] = psi_u[(i, j)];
            }
            q[(i, M)] = psi_t[i];
        }
        // A decomposition that fails (only for extreme numbers) is taken
        // for rank-deficient: the cautious reading.
        let Some(svd) = crate::linalg::scaled_svd(&q, false) else {
            return 0.0;
        };
        let (max, min) = svd
            .singular_values
            .iter()
            .fold((0.0_f64, f64::INFINITY), |(a, b), &x| (a.max(x), b.min(x)));
        if max > 0.0 { min / max } else { 0.0 }
    }

    /// det Ψ_u relative to the product of its column norms (|·| ≤ 1).
    fn normalized_det(&self, u: &SVector<f64, M>, t: f64) -> f64 {
        let psi_u =
            sources::psi_and_psi_u(self.model, self.options.options.jacobian, u, &self.v(t)).1;
        let scale: f64 = psi_u
            .column_iter()
            .map(|c| c.norm().max(f64::MIN_POSITIVE))
            .product();
        determinant(&psi_u) / scale
    }

    /// The limit position near `near`: Newton on Ψ(u, t) = 0, det Ψ_u = 0
    /// for (u, t), with the gradient of det by central differences.
    fn locate_limit(&self, near: &State<M, F>) -> Option<(SVector<f64, M>, f64)> {
        let (mut u, mut t) = (near.u, near.t);
        let n = M + 1;
        for _ in 0..50 {
            let v = self.v(t);
            let psi = self.model.psi(&u, &v);
            let psi_u = sources::psi_and_psi_u(self.model, self.options.options.jacobian, &u, &v).1;
            let psi_t = self.psi_t(&u, t);
            let d = self.normalized_det(&u, t);
            let mut jac = DMatrix::<f64>::zeros(n, n);
            let mut rhs = DVector::<f64>::zeros(n);
            for i in 0..M {
                for j in 0..M {
                    jac[(i, j)] = psi_u[(i, j)];
                }
                jac[(i, M)] = psi_t[i];
                rhs[i] = -psi[i];
            }
            rhs[M] = -d;
            for j in 0..n {
                let x = if j < M { u[j] } else { t };
                let h = 1e-7 * x.abs().max(1.0);
                let (mut up, mut um, mut tp, mut tm) = (u, u, t, t);
                if j < M {
                    up[j] += h;
                    um[j] -= h;
                } else {
                    tp += h;
                    tm -= h;
                }
                jac[(M, j)] =
                    (self.normalized_det(&up, tp) - self.normalized_det(&um, tm)) / (2.0 * h);
            }
            let step = jac.lu().solve(&rhs)?;
            if !step.iter().all(|x| x.is_finite()) {
                return None;
            }
            for j in 0..M {
                u[j] += step[j];
            }
            t += step[M];
            let size = step.amax();
            if size <= 1e-14 * u.amax().max(t.abs()).max(1.0) {
                break;
            }
        }
        let residual = self.model.psi(&u, &self.v(t)).amax();
        let scale =
            sources::psi_and_psi_u(self.model, self.options.options.jacobian, &u, &self.v(t))
                .1
                .amax()
                .max(1.0);
        (residual <= 1e-9 * scale && self.normalized_det(&u, t).abs() <= 1e-6).then_some((u, t))
    }

    /// From a limit position, the state on the other branch mirroring
    /// `came_from` (the same distance along the null direction of Ψ_u, on
    /// the other side), found with the component along that direction held.
    fn mirror(
        &self,
        limit_u: &SVector<f64, M>,
        limit_t: f64,
        came_from: &State<M, F>,
    ) -> Option<State<M, F>> {
        let v = self.v(limit_t);
        let psi_u =
            sources::psi_and_psi_u(self.model, self.options.options.jacobian, limit_u, &v).1;
        let dyn_u = DMatrix::<f64>::from_fn(M, M, |i, j| psi_u[(i, j)]);
        let svd = crate::linalg::scaled_svd(&dyn_u, true)?;
        let v_t = svd.v_t?;
        let k = svd
            .singular_values
            .iter()
            .enumerate()
            .min_by(|a, b| a.1.total_cmp(b.1))
            .map(|(k, _)| k)?;
        let null = SVector::<f64, M>::from_fn(|i, _| v_t[(k, i)]);
        let s = null.dot(&(came_from.u - limit_u));
        if s == 0.0 {
            return None;
        }
        // Solve Ψ(u, t) = 0 with null·(u − u*) = −s: (m+1) unknowns (u, t).
        let target = -s;
        let (mut u, mut t) = (limit_u - null * s, came_from.t);
        let n = M + 1;
        for _ in 0..50 {
            let vt = self.v(t);
            let psi = self.model.psi(&u, &vt);
            let psi_u =
                sources::psi_and_psi_u(self.model, self.options.options.jacobian, &u, &vt).1;
            let psi_t = self.psi_t(&u, t);
            let mut jac = DMatrix::<f64>::zeros(n, n);
            let mut rhs = DVector::<f64>::zeros(n);
            for i in 0..M {
                for j in 0..M {
                    jac[(i, j)] = psi_u[(i, j)];
                }
                jac[(i, M)] = psi_t[i];
                rhs[i] = -psi[i];
                jac[(M, i)] = null[i];
            }
            rhs[M] = target - null.dot(&(u - limit_u));
            let step = jac.lu().solve(&rhs)?;
            for j in 0..M {
                u[j] += step[j];
            }
            t += step[M];
            if step.amax() <= 1e-14 * u.amax().max(t.abs()).max(1.0) {
                break;
            }
        }
        let (u, iterations) = self.correct(&u, t).ok()?;
        let state = self.state(u, t, iterations);
        (state.det.signum() != came_from.det.signum()).then_some(state)
    }

    /// Whether the pose's velocities and accelerations keep the requested
    /// accuracy (see [`Options::accuracy`]).
    fn keeps_accuracy(&self, state: &State<M, F>) -> bool {
        let options = &self.options.options;
        if state.rcond < self.min_rcond_velocity {
            return false;
        }
        if state.rcond >= self.min_rcond_acceleration {
            return true;
        }
        // Near a singular pose: the finer test needs Ψ_u and Ψ_v.
        let (jacobian, v) = (options.jacobian, self.v(state.t));
        let psi_u = sources::psi_and_psi_u(self.model, jacobian, &state.u, &v).1;
        let psi_v = sources::psi_v(self.model, jacobian, &state.u, &v);
        crate::model::acceleration_conditioning_with(
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
    fn pose(
        &self,
        state: &State<M, F>,
        step: usize,
        direction: f64,
    ) -> Result<SweepPose<M, F>, Error> {
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

    /// The careful tests of [`Self::pose`], for a pose with a non-finite
    /// entry or at a tiny speed.
    #[cold]
    #[inline(never)]
    fn unusual_pose(state: &State<M, F>, rate: f64, pose: &SweepPose<M, F>) -> Result<(), Error> {
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
        crate::error::check_result(
            Stage::Velocity,
            "the sweep's u̇ at its speed",
            state.du.amax().log2() + log_rate,
        )?;
        crate::error::check_result(
            Stage::Acceleration,
            "the sweep's ü at its speed",
            state.ddu.amax().log2() + 2.0 * log_rate,
        )
    }
}

/// Below this reciprocal condition number a state's tangent is not trusted
/// for prediction, nor its det's sign for the branch.
const REGULAR_RCOND: f64 = 1e-8;

/// The current state, the last well-conditioned one (the predictor near
/// singular poses) and the sign of det Ψ_u on the branch: that of the last
/// well-conditioned state, flipped at each located branch-point crossing.
#[derive(Clone, Copy, Debug)]
struct Track<const M: usize, const F: usize> {
    state: State<M, F>,
    regular: State<M, F>,
    sign: f64,
}

impl<const M: usize, const F: usize> Track<M, F> {
    fn new(state: State<M, F>) -> Track<M, F> {
        Track {
            state,
            regular: state,
            sign: state.det.signum(),
        }
    }

    fn accept(&mut self, next: State<M, F>) {
        self.state = next;
        if next.rcond >= REGULAR_RCOND {
            self.regular = next;
            self.sign = next.det.signum();
        }
    }

    /// Where to predict from.
    fn source(&self) -> State<M, F> {
        if self.state.rcond >= REGULAR_RCOND {
            self.state
        } else {
            self.regular
        }
    }
}

enum Advance<const M: usize, const F: usize> {
    Reached(Track<M, F>),
    /// The driver cannot pass beyond this track.
    Blocked(Track<M, F>),
}

/// Runs a sweep (see [`Linkage::sweep`]).
pub(crate) fn sweep<L, P, const M: usize, const F: usize>(
    model: &L,
    u0: &SVector<f64, M>,
    drive: &Drive<F>,
    options: &SweepOptions,
    on_pose: &mut P,
) -> Result<SweepSummary<M, F>, Error>
where
    L: Linkage<M, F> + ?Sized,
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
    let moves = dir.norm() > 0.0; // false for NaN too
    if !moves {
        return Err(Error::InvalidInput {
            argument: "drive",
            value: dir.norm(),
            why: "the drive does not move (from = to, or a zero step): no direction to follow",
        });
    }
    let tracker = Tracker {
        model,
        options: *options,
        base,
        dir,
        min_rcond_velocity: options.options.min_rcond(Stage::Velocity),
        min_rcond_acceleration: options.options.min_rcond(Stage::Acceleration),
        rate: options.speed / dir.norm(),
    };
    let start = model.solve_position(u0, &base, &options.options)?;
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
    let carries = L::TRIG_U.iter().chain(L::TRIG_V.iter()).any(|&b| b);
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

/// Where a sweep stands.
struct Progress<const M: usize, const F: usize> {
    track: Track<M, F>,
    /// The grid index of the current state.
    index: i64,
    /// The driver steps taken.
    step: usize,
    /// The poses passed on.
    recorded: usize,
    /// The states at the last two grid indices (the source of a mirror).
    last_grid: State<M, F>,
    previous_grid: State<M, F>,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Carried sines and cosines agree with `sin_cos` to about an ulp on
    /// every tier: the short series, the long one, and re-anchoring.
    #[test]
    fn carried_trig_is_as_accurate_as_sin_cos() {
        let mut worst: f64 = 0.0;
        for &step in &[1e-7_f64, 6.2e-6, 3e-4, 1.5e-3, 0.01, 0.05, 0.3] {
            let (mut anchor, mut trig) = (f64::NAN, (0.0, 1.0));
            let mut x = -2.9_f64;
            for _ in 0..(6.2_f64 / step).min(200_000.0) as usize {
                let (s, c) = carry(&mut anchor, &mut trig, x);
                let (es, ec) = x.sin_cos();
                worst = worst.max((s - es).abs()).max((c - ec).abs());
                x += step;
            }
        }
        // Two coordinates at once, one of them not read.
        for &step in &[6.2e-6_f64, 1e-3, 0.04] {
            let (mut anchor, mut trig) = ([f64::NAN; 2], [(0.0, 1.0); 2]);
            let mut x = [-2.9_f64, 7.0];
            for _ in 0..(6.2 / step).min(200_000.0) as usize {
                let out = carry_all(&[true, false], &mut anchor, &mut trig, &x);
                let (es, ec) = x[0].sin_cos();
                worst = worst.max((out[0].0 - es).abs()).max((out[0].1 - ec).abs());
                x[0] += step;
                x[1] += 1.0;
            }
            assert!(
                anchor[1].is_nan(),
                "the coordinate not read is never anchored"
            );
        }
        eprintln!("worst absolute error of the carried sin and cos: {worst:e}");
        assert!(worst <= 2.5e-16, "worst absolute error {worst:e}");
    }
}
