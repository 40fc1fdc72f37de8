//! Newton–Raphson on Ψ(u, v) = 0, plain or damped.
//!
//! The plain method takes full steps Δu = −Ψ_u⁻¹Ψ. The damped method
//! backtracks along the Newton step until ½‖Ψ‖² decreases enough (Armijo),
//! and where Ψ_u is singular or the Newton step does not descend it takes a
//! Levenberg–Marquardt step −(Ψ_uᵀΨ_u + μI)⁻¹Ψ_uᵀΨ instead. It therefore
//! ends either at a root or at a least-squares minimum of ‖Ψ‖ with
//! Ψ_uᵀΨ ≈ 0 and ‖Ψ‖ > 0. A stationary point that is a saddle (a dyad
//! stretched straight where it could bend to close) is left along the null
//! vector of Ψ_u; at a minimum the mechanism cannot be assembled, and the
//! error says how far it is from closing.

use crate::runtime::checks::{check_input, check_value};
use crate::runtime::error::{Error, Stage};
use crate::runtime::factors::factor;
use crate::runtime::kernels::Kernels;
use crate::runtime::linalg::invert;
use crate::runtime::options::Options;
use crate::runtime::results::{Iterate, Kinematics, Position};
use crate::runtime::sources::psi_and_psi_u;
use crate::runtime::trig::{PoseTrig, SinCos, TrigCarrier};
use nalgebra::{SMatrix, SVector};

/// Ψ_uᵀΨ below this fraction of ‖Ψ_u‖·‖Ψ‖ is a stationary point of ‖Ψ‖².
const STATIONARY: f64 = 1e-9;
/// Where no step descends any more (rounding limits ½‖Ψ‖² to about ε of its
/// value, so a minimum is located only to about √ε), a relative gradient
/// below this is a minimum.
const STATIONARY_AT_ROUNDING: f64 = 1e-6;
/// Saddles of ½‖Ψ‖² left by second-order steps before a stationary point
/// is taken for a minimum.
const MAX_ESCAPES: usize = 4;
/// The Armijo constant of the line search.
const ARMIJO: f64 = 1e-4;

/// Ψ and Ψ_u at a pose.
type Evaluation<const M: usize> = (SVector<f64, M>, SMatrix<f64, M, M>);

pub(crate) fn solve<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    u0: &SVector<f64, M>,
    v: &SVector<f64, F>,
    options: &Options,
    observe: &mut dyn FnMut(&Iterate<M>),
) -> Result<Position<M>, Error> {
    check_input("u0", u0.as_slice())?;
    check_input("v", v.as_slice())?;
    options.check()?;
    let evaluate = |u: &SVector<f64, M>| -> Result<Evaluation<M>, Error> {
        let (psi, psi_u) = psi_and_psi_u(model, options.jacobian, u, v);
        check_value(Stage::Position, "Ψ", psi.as_slice())?;
        check_value(Stage::Position, "Ψ_u", psi_u.as_slice())?;
        Ok((psi, psi_u))
    };
    let mut u = *u0;
    let (mut psi, mut psi_u) = evaluate(&u)?;
    let mut residual = psi.amax();
    observe(&Iterate {
        iteration: 0,
        u,
        residual,
        step: 0.0,
    });
    let mut step = f64::INFINITY;
    let mut previous_step = f64::INFINITY;
    // The Levenberg–Marquardt parameter, relative to ‖Ψ_uᵀΨ_u‖.
    let mut mu = 1e-3;
    let mut escapes = 0;
    for iteration in 1..=options.max_iterations {
        let delta = if options.damped {
            let gradient = relative_gradient(&psi_u, &psi);
            // A stationary point of ½‖Ψ‖² that is not a root: a saddle if a
            // second-order step descends (left, at most MAX_ESCAPES times),
            // else a minimum, and the mechanism cannot be assembled.
            let stationary = |escapes: &mut usize| -> Result<SVector<f64, M>, Error> {
                if *escapes < MAX_ESCAPES {
                    if let Some(d) = escape_saddle(&evaluate, &u, &psi, &psi_u)? {
                        *escapes += 1;
                        return Ok(d);
                    }
                }
                Err(Error::CannotAssemble {
                    residual,
                    closest: u.as_slice().to_vec(),
                    gradient,
                })
            };
            if residual > options.residual_tol && gradient <= STATIONARY {
                stationary(&mut escapes)?
            } else {
                match damped_step(&evaluate, &u, &psi, &psi_u, options, &mut mu)? {
                    Some(delta) => delta,
                    None if residual > options.residual_tol
                        && gradient <= STATIONARY_AT_ROUNDING =>
                    {
                        stationary(&mut escapes)?
                    }
                    None => {
                        return Err(Error::NotConverged {
                            iterations: iteration - 1,
                            residual,
                            step: 0.0,
                        });
                    }
                }
            }
        } else {
            let factors = factor(&psi_u, model.psi_u_blocks(), Stage::Position, options)?;
            -factors.solve(&psi)
        };
        u += delta;
        step = delta.amax();
        check_value(Stage::Position, "u", u.as_slice())?;
        (psi, psi_u) = evaluate(&u)?;
        residual = psi.amax();
        observe(&Iterate {
            iteration,
            u,
            residual,
            step,
        });
        if converged(&u, step, previous_step, residual, options) {
            return Ok(Position {
                u,
                iterations: iteration,
                residual,
                psi_u,
            });
        }
        previous_step = step;
    }
    Err(Error::NotConverged {
        iterations: options.max_iterations,
        residual,
        step,
    })
}

/// What [`FusedNewton`] ends with: the pose and the sines and cosines of
/// the evaluation there (exact at the pose). The evaluation itself is the
/// last one the caller gave [`FusedNewton::advance`], which it keeps:
/// for a large mechanism it is tens of kilobytes, not moved.
pub(crate) type Converged<const M: usize, const F: usize> = (Position<M>, PoseTrig<M, F>);

/// Plain Newton–Raphson whose every evaluation is the fused kernel
/// ([`Kernels::kinematics_with_trig`]): Ψ, Ψ_u and its factors for the steps and,
/// at the iterate that converges, the velocities and accelerations too. So
/// an analysis evaluates the mechanism once more than it takes steps (the
/// evaluation that confirms convergence is the one that gives the
/// kinematics), and the drivers' sines and cosines once. The same iterates,
/// tests and errors as [`solve`] without damping, bit for bit.
///
/// One evaluation at a time: the iteration asks for the
/// fused kernel at a pose ([`FusedNewton::pose`]), is given it
/// ([`FusedNewton::advance`]), and says whether it wants another. A batch
/// runs many at once, each pose's evaluations made together with the
/// others' (on a run-time mechanism's lanes), each ending as it would
/// alone.
pub(crate) struct FusedNewton<const M: usize, const F: usize> {
    v: SVector<f64, F>,
    /// The iterate the evaluation asked for is at.
    u: SVector<f64, M>,
    /// The sines and cosines carried from iterate to iterate, but computed
    /// exactly where the evaluation may confirm convergence: a returned
    /// pose closes to its residual as `psi` computes it, to the bit.
    trig: TrigCarrier<M, F>,
    /// Those of the evaluation asked for.
    trig_u: SinCos<M>,
    trig_v: SinCos<F>,
    /// The steps taken.
    iteration: usize,
    step: f64,
    previous_step: f64,
    asked: Asked,
}

/// Why the evaluation was asked for.
#[derive(Clone, Copy)]
enum Asked {
    /// At the first guess.
    Start,
    /// After a step; `last` if the step passed the step test.
    Step { last: bool },
    /// Again, on exact sines, at an iterate where Ψ is exactly 0.
    Exactly,
}

/// What the iteration wants after an evaluation.
pub(crate) enum Progress<const M: usize, const F: usize> {
    /// The fused kernel at its new [`FusedNewton::pose`].
    Evaluate,
    /// Nothing more: it ended, so.
    Done(Result<Converged<M, F>, Error>),
}

impl<const M: usize, const F: usize> FusedNewton<M, F> {
    /// The iteration from `u0`, its inputs checked, asking for its first
    /// evaluation.
    #[inline]
    pub(crate) fn start<L: Kernels<M, F> + ?Sized>(
        model: &L,
        u0: &SVector<f64, M>,
        v: &SVector<f64, F>,
        options: &Options,
    ) -> Result<Self, Error> {
        check_input("u0", u0.as_slice())?;
        check_input("v", v.as_slice())?;
        options.check()?;
        let mut newton = FusedNewton {
            v: *v,
            u: *u0,
            trig: TrigCarrier::new(),
            trig_u: [(0.0, 1.0); M],
            trig_v: [(0.0, 1.0); F],
            iteration: 0,
            step: f64::INFINITY,
            previous_step: f64::INFINITY,
            asked: Asked::Start,
        };
        newton.ask(model, true);
        Ok(newton)
    }

    /// Where the evaluation asked for is: u and the sines and cosines of u
    /// and v to give the fused kernel.
    #[inline]
    pub(crate) fn pose(&self) -> (&SVector<f64, M>, &SinCos<M>, &SinCos<F>) {
        (&self.u, &self.trig_u, &self.trig_v)
    }

    /// Whether the evaluation asked for may end the iteration, and so give
    /// the analysis its velocities and accelerations: one after a step
    /// that passes the step test, or on exact sines. (At the first guess
    /// or after any other step, the iteration goes on, or asks again on
    /// exact sines.)
    #[inline]
    pub(crate) fn may_end(&self) -> bool {
        matches!(self.asked, Asked::Step { last: true } | Asked::Exactly)
    }

    /// The sines and cosines for an evaluation at `self.u`.
    #[inline(always)]
    fn ask<L: Kernels<M, F> + ?Sized>(&mut self, model: &L, exact: bool) {
        (self.trig_u, self.trig_v) = if exact {
            (self.trig).exactly_at(&model.trig_u(), &model.trig_v(), &self.u, &self.v)
        } else {
            (self.trig).at(&model.trig_u(), &model.trig_v(), &self.u, &self.v)
        };
    }

    /// Takes the fused kernel's evaluation `k` at [`FusedNewton::pose`]:
    /// the iteration ends there, or takes its next step and asks for the
    /// evaluation there.
    #[inline]
    pub(crate) fn advance<L: Kernels<M, F> + ?Sized>(
        &mut self,
        model: &L,
        k: &Kinematics<M, F>,
        options: &Options,
    ) -> Progress<M, F> {
        match self.advance_or_fail(model, k, options) {
            Ok(progress) => progress,
            Err(error) => Progress::Done(Err(error)),
        }
    }

    #[inline(always)]
    fn advance_or_fail<L: Kernels<M, F> + ?Sized>(
        &mut self,
        model: &L,
        k: &Kinematics<M, F>,
        options: &Options,
    ) -> Result<Progress<M, F>, Error> {
        check_value(Stage::Position, "Ψ", k.psi.as_slice())?;
        check_value(Stage::Position, "Ψ_u", k.psi_u.as_slice())?;
        let residual = k.psi.amax();
        let stepped = match self.asked {
            Asked::Start => false,
            // Only a step that passes the step test, or an exact zero of
            // Ψ, ends the iteration; the latter is confirmed on exact
            // sines.
            Asked::Step { last: false } if residual == 0.0 => {
                self.ask(model, true);
                self.asked = Asked::Exactly;
                return Ok(Progress::Evaluate);
            }
            Asked::Step { .. } | Asked::Exactly => true,
        };
        if stepped {
            let (u, step, previous_step) = (&self.u, self.step, self.previous_step);
            if converged(u, step, previous_step, residual, options) {
                let position = Position {
                    u: *u,
                    iterations: self.iteration,
                    residual,
                    psi_u: k.psi_u,
                };
                // Those of the evaluation that confirmed convergence, exact.
                let (sin_cos_u, sin_cos_v) = self.trig.anchored();
                let pose_trig = PoseTrig {
                    u: *u,
                    sin_cos_u,
                    sin_cos_v,
                };
                return Ok(Progress::Done(Ok((position, pose_trig))));
            }
            self.previous_step = step;
        }
        if self.iteration >= options.max_iterations {
            return Err(Error::NotConverged {
                iterations: options.max_iterations,
                residual,
                step: self.step,
            });
        }
        self.iteration += 1;
        options.require_accuracy(Stage::Position, k.rcond)?;
        let delta = -k.factors.solve(&k.psi);
        self.u += delta;
        self.step = delta.amax();
        check_value(Stage::Position, "u", self.u.as_slice())?;
        let last = step_is_final(&self.u, self.step, self.previous_step, options);
        self.ask(model, last);
        self.asked = Asked::Step { last };
        Ok(Progress::Evaluate)
    }
}

/// Whether the iterate `u`, reached by a step of size `step` after one of
/// `previous_step`, with ‖Ψ‖∞ = `residual`, is a solution: the residual
/// within tolerance, and the step final ([`step_is_final`]) or the residual
/// exactly 0.
#[inline]
fn converged<const M: usize>(
    u: &SVector<f64, M>,
    step: f64,
    previous_step: f64,
    residual: f64,
    options: &Options,
) -> bool {
    (step_is_final(u, step, previous_step, options) || residual == 0.0)
        && residual <= options.residual_tol
}

/// Whether a step ends Newton's iteration if the residual is within
/// tolerance: it is small, or no longer shrinking at rounding level (which
/// is convergence too, whatever the step tolerance asked for).
#[inline]
fn step_is_final<const M: usize>(
    u: &SVector<f64, M>,
    step: f64,
    previous_step: f64,
    options: &Options,
) -> bool {
    let scale = u.amax().max(1.0);
    let small_step = step <= options.step_tol * scale;
    let stagnated = step >= previous_step && step <= 64.0 * f64::EPSILON * scale;
    small_step || stagnated
}

/// How far from a least-squares minimum of ½‖Ψ‖²: the largest |cos| of
/// the angle between Ψ and a column of Ψ_u, max_j |Ψ_u,jᵀΨ| / (‖Ψ_u,j‖‖Ψ‖)
/// (0 at a stationary point). Column by column, so that a coordinate whose
/// column is huge does not hide one that can still reduce Ψ; each factor
/// scaled first, so that nothing overflows or underflows.
fn relative_gradient<const M: usize>(psi_u: &SMatrix<f64, M, M>, psi: &SVector<f64, M>) -> f64 {
    let size = psi.amax();
    let nonzero = size > 0.0; // false for NaN too
    if !nonzero {
        return 0.0;
    }
    let psi = psi / size;
    let mut worst: f64 = 0.0;
    for j in 0..M {
        let column = psi_u.column(j);
        let scale = column.amax();
        if scale > 0.0 {
            let c = column / scale;
            worst = worst.max(c.dot(&psi).abs() / c.norm() / psi.norm());
        }
    }
    worst
}

/// A step off a stationary point of ½‖Ψ‖² that is not a root, if it is a
/// saddle. There Ψ_uᵀΨ = 0 with Ψ ≠ 0, so Ψ_u is singular and Ψ is
/// orthogonal to its range; along the null vector n of Ψ_u the first-order
/// change vanishes and only the curvature of Ψ decides. The trial steps
/// ±t·n, t from 10⁻⁶ to 1 of the pose's scale, are evaluated and the one
/// with the smallest ½‖Ψ‖² taken if it is below the current value. (A
/// four-bar's dyad stretched straight while the pivots are a little closer
/// than its length is such a saddle: bending it either way closes the loop.)
fn escape_saddle<const M: usize>(
    evaluate: &dyn Fn(&SVector<f64, M>) -> Result<Evaluation<M>, Error>,
    u: &SVector<f64, M>,
    psi: &SVector<f64, M>,
    psi_u: &SMatrix<f64, M, M>,
) -> Result<Option<SVector<f64, M>>, Error> {
    let Some(n) = null_vector(psi_u) else {
        return Ok(None);
    };
    // ½‖Ψ/σ‖², σ = ‖Ψ(u)‖∞: the merit at unit scale, so that it neither
    // underflows for a tiny mechanism nor overflows for a huge one.
    let sigma = psi.amax();
    let merit = |r: &SVector<f64, M>| 0.5 * (r / sigma).norm_squared();
    let mut best = (merit(psi), None);
    let scale = u.amax().max(1.0);
    for decade in -6..=0 {
        let t = scale * 10f64.powi(decade);
        for sign in [1.0, -1.0] {
            let d = n * (sign * t);
            let trial = u + d;
            if !trial.iter().all(|x| x.is_finite()) {
                continue;
            }
            // Outside the domain of Ψ is simply not a way out.
            let Ok((r, _)) = evaluate(&trial) else {
                continue;
            };
            let value = merit(&r);
            if value < best.0 {
                best = (value, Some(d));
            }
        }
    }
    Ok(best.1)
}

/// A unit vector x with A·x ≈ 0: with the columns of A equilibrated
/// (B = A·D, each column of B of largest entry 1, so that coordinates in
/// different units weigh alike), the right singular vector y of B's
/// smallest singular value by inverse iteration on BᵀB + 10⁻¹⁰·I — the
/// largest column of the inverse, where the null direction dominates,
/// refined three times — and x = D·y normalised. A zero column is its own
/// null vector.
fn null_vector<const M: usize>(a: &SMatrix<f64, M, M>) -> Option<SVector<f64, M>> {
    let mut scales = SVector::<f64, M>::zeros();
    for j in 0..M {
        let scale = a.column(j).amax();
        if !scale.is_finite() {
            return None;
        }
        if scale == 0.0 {
            return Some(SVector::<f64, M>::from_fn(|i, _| {
                f64::from(u8::from(i == j))
            }));
        }
        scales[j] = scale;
    }
    let b = SMatrix::<f64, M, M>::from_fn(|i, j| a[(i, j)] / scales[j]);
    let shifted = b.transpose() * b + SMatrix::<f64, M, M>::identity() * 1e-10;
    let inv = invert(&shifted);
    if inv.rcond <= 0.0 {
        return None;
    }
    let mut y = inv
        .inverse
        .column_iter()
        .max_by(|p, q| p.norm().total_cmp(&q.norm()))?
        .into_owned();
    for _ in 0..3 {
        let norm = y.norm();
        if !(norm.is_finite() && norm > 0.0) {
            return None;
        }
        y = inv.inverse * (y / norm);
    }
    // D·y may be far from 1 (the columns' scales): brought near 1 by its
    // largest entry first, so that the norm's squares stay in range.
    let x = y.component_div(&scales);
    let size = x.amax();
    if !(size > 0.0 && size.is_finite()) {
        return None;
    }
    let x = x / size;
    Some(x / x.norm())
}

/// One damped step: the Newton step shortened until ½‖Ψ‖² decreases enough,
/// or, where that fails, a Levenberg–Marquardt step with μ adapted.
fn damped_step<const M: usize>(
    evaluate: &dyn Fn(&SVector<f64, M>) -> Result<Evaluation<M>, Error>,
    u: &SVector<f64, M>,
    psi: &SVector<f64, M>,
    psi_u: &SMatrix<f64, M, M>,
    options: &Options,
    mu: &mut f64,
) -> Result<Option<SVector<f64, M>>, Error> {
    // ½‖Ψ/σ‖² with σ = ‖Ψ(u)‖∞ (σ > 0 here, or the residual would be
    // within tolerance): the merit at unit scale, which neither underflows
    // for a tiny mechanism nor overflows for a huge one; its gradient is
    // Ψ_uᵀ(Ψ/σ)/σ, and a step d solving for Ψ/σ is scaled back by σ.
    let sigma = psi.amax().max(f64::MIN_POSITIVE);
    let unit = psi / sigma;
    let merit = |r: &SVector<f64, M>| 0.5 * (r / sigma).norm_squared();
    let phi = merit(psi);
    let trial = |d: &SVector<f64, M>| -> Result<f64, Error> { Ok(merit(&evaluate(&(u + d))?.0)) };

    // The Newton direction with backtracking; full steps once the residual
    // is within tolerance, where ½‖Ψ‖² is at rounding level and can no longer
    // decide between steps.
    let inv = invert(psi_u);
    if inv.rcond > 0.0 && inv.rcond >= options.min_rcond(Stage::Position) {
        let newton = -(inv.inverse * psi);
        if psi.amax() <= options.residual_tol {
            return Ok(Some(newton));
        }
        // ∇φ·d = (Ψ/σ)ᵀ(Ψ_u d)/σ, at unit scale.
        let slope = unit.dot(&(psi_u * (newton / sigma)));
        let mut lambda = 1.0;
        while lambda >= 1e-4 {
            let d = newton * lambda;
            if trial(&d)? <= phi + ARMIJO * lambda * slope {
                *mu = (*mu / 3.0).max(1e-12);
                return Ok(Some(d));
            }
            lambda *= 0.5;
        }
    }
    // Levenberg–Marquardt: (JᵀJ + μ·s·I) d = −Jᵀr, μ raised until it
    // descends; at unit scale, J = ρ·J₁ and r = σ·r₁ with ρ = ‖Ψ_u‖∞, so
    // that JᵀJ neither underflows for a tiny mechanism nor overflows for a
    // huge one: (J₁ᵀJ₁ + μ·s₁·I) d₁ = −J₁ᵀr₁ and d = d₁·σ/ρ, the same step.
    let rho = psi_u.amax();
    if !(rho > 0.0 && rho.is_finite()) {
        return Ok(None);
    }
    let j1 = psi_u / rho;
    let jtj = j1.transpose() * j1;
    let gradient_1 = j1.transpose() * unit;
    let s = jtj.amax().max(f64::MIN_POSITIVE);
    for _ in 0..60 {
        let a = jtj + SMatrix::<f64, M, M>::identity() * (*mu * s);
        let inv = invert(&a);
        if inv.rcond > 0.0 {
            let d = -(inv.inverse * gradient_1) * (sigma / rho);
            if trial(&d)? < phi {
                *mu = (*mu / 3.0).max(1e-12);
                return Ok(Some(d));
            }
        }
        *mu *= 4.0;
    }
    // No descent even with tiny steps: a minimum, to rounding.
    Ok(None)
}
