//! The solvers' settings: tolerances, the accuracy a result must keep, and
//! where the derivatives come from.

use crate::runtime::error::{Error, Stage};

/// Which of the two equivalent forms of γ an acceleration solve uses; all
/// three give the same ü (the tests show they differ by rounding only).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum AccelerationMethod {
    /// Method A, the time derivative: γ = Ψ̇_u u̇ + Ψ̇_v v̇
    /// (the worksheet's H0 = H1 + H2 + H3).
    A,
    /// Method B, the Jacobian of \[Ψ_u\]u̇: γ = (Ψ_u u̇)_u u̇ + (Ψ_u u̇)_v v̇ +
    /// (Ψ_v v̇)_u u̇ + (Ψ_v v̇)_v v̇ (the worksheet's γ0).
    B,
    /// γ = (Ψ_q q̇)_q q̇ in one fused generated expression: the fastest.
    #[default]
    Fused,
}

/// The source of Ψ_u, Ψ_v and γ used by the solvers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum JacobianSource {
    /// The code the macro generated (symbolic derivatives).
    #[default]
    Generated,
    /// Forward-mode automatic differentiation of `psi_generic`: Ψ_u and Ψ_v
    /// with vector dual numbers, γ with a second-order dual number along q̇.
    Dual,
    /// Central finite differences of `psi`: steps ε^(1/3)·max(1, |qₖ|) for
    /// the Jacobians (error ~1e-10) and ε^(1/4) along q̇ for γ (~1e-8).
    FiniteDifference,
}

/// Tolerances and choices of the solvers. The defaults: `residual_tol`
/// 1e-9, `step_tol` 1e-10, `max_iterations` 50, `accuracy` 1e-6, `method`
/// [`AccelerationMethod::Fused`], `jacobian` [`JacobianSource::Generated`],
/// `damped` false.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Newton–Raphson stops when ‖Ψ‖∞ ≤ `residual_tol` (in the units of the
    /// equations) and the last step met `step_tol`.
    pub residual_tol: f64,
    /// ... and the last step ‖Δu‖∞ ≤ `step_tol`·max(1, ‖u‖∞). Newton
    /// converges quadratically, so after a step this small the error left is
    /// of the order of its square: the default leaves u exact to rounding.
    pub step_tol: f64,
    /// The most Newton steps taken.
    pub max_iterations: usize,
    /// The relative accuracy a result must keep, or the solve fails with
    /// [`Error::Singular`] instead of returning it. Near a singular pose
    /// rounding is amplified by the condition number κ of Ψ_u (equilibrated,
    /// see [`crate::runtime::Inverse::rcond`]) once in the positions, twice in the
    /// velocities and three times in the accelerations; so positions are
    /// refused where ε·κ exceeds `accuracy`, velocities where ε·κ² does and
    /// accelerations where ε·κ³ does ([`Options::min_rcond`]). The default
    /// 1e-6 refuses accelerations within about 1e-3 rad of a change point,
    /// and velocities within about 1e-8 rad of a limit position.
    /// `f64::INFINITY` switches the check off.
    pub accuracy: f64,
    /// The form of γ used by the acceleration solves (generated code only).
    pub method: AccelerationMethod,
    /// Where Ψ_u, Ψ_v and γ come from: the generated code (default),
    /// automatic differentiation or finite differences.
    pub jacobian: JacobianSource,
    /// Damped Newton: backtracking on ½‖Ψ‖², with Levenberg–Marquardt steps
    /// where Ψ_u is singular. Slower per step, but it converges from poor
    /// guesses and tells a pose that cannot be assembled
    /// ([`Error::CannotAssemble`]) from one that merely did not converge.
    pub damped: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            residual_tol: 1e-9,
            step_tol: 1e-10,
            max_iterations: 50,
            accuracy: 1e-6,
            method: AccelerationMethod::Fused,
            jacobian: JacobianSource::Generated,
            damped: false,
        }
    }
}

impl Options {
    /// That every setting is in its range: tolerances ≥ 0, the accuracy
    /// positive (∞ allowed), nothing NaN.
    pub fn check(&self) -> Result<(), Error> {
        let invalid = |argument, value, why| {
            Err(Error::InvalidInput {
                argument,
                value,
                why,
            })
        };
        let residual_tol_ok = self.residual_tol >= 0.0; // false for NaN too
        if !residual_tol_ok {
            return invalid("residual_tol", self.residual_tol, "a tolerance must be ≥ 0");
        }
        let step_tol_ok = self.step_tol >= 0.0; // false for NaN too
        if !step_tol_ok {
            return invalid("step_tol", self.step_tol, "a tolerance must be ≥ 0");
        }
        let accuracy_ok = self.accuracy > 0.0; // false for NaN too
        if !accuracy_ok {
            return invalid(
                "accuracy",
                self.accuracy,
                "the accuracy must be > 0 (∞: no check)",
            );
        }
        Ok(())
    }

    /// The smallest reciprocal condition number of Ψ_u with which `stage`
    /// keeps [`Options::accuracy`]: (ε/accuracy)^(1/k) with k = 1 for
    /// positions, 2 for velocities, 3 for accelerations and points, 4 for
    /// the sensitivities to the parameters (ü_p holds Ψ_u⁻¹ once more than ü).
    pub fn min_rcond(&self, stage: Stage) -> f64 {
        let ratio = f64::EPSILON / self.accuracy;
        match stage {
            Stage::Position => ratio,
            Stage::Velocity => ratio.sqrt(),
            Stage::Acceleration | Stage::Points => ratio.cbrt(),
            Stage::Sensitivity => ratio.sqrt().sqrt(),
        }
    }

    /// Whether a reciprocal condition number `rcond` of Ψ_u keeps
    /// [`Options::accuracy`] in `stage`: rcond ≥ [`Options::min_rcond`],
    /// decided as rcondᵏ ≥ ε/accuracy without taking the root (a cube root
    /// costs more than the rest of an analysis's checks). The same test to
    /// rounding; an exactly singular Ψ_u (rcond = 0) never passes.
    #[inline]
    pub fn keeps_accuracy(&self, stage: Stage, rcond: f64) -> bool {
        // Below 2⁻³⁰⁰ a cube would leave the normal range: the root decides.
        const SMALL: f64 = crate::runtime::powers_of_two::pow2(-300);
        let ordinary = rcond >= SMALL; // false for NaN too
        if !ordinary {
            return rcond > 0.0 && rcond >= self.min_rcond(stage);
        }
        let ratio = f64::EPSILON / self.accuracy;
        let power = match stage {
            Stage::Position => rcond,
            Stage::Velocity => rcond * rcond,
            Stage::Acceleration | Stage::Points => rcond * rcond * rcond,
            Stage::Sensitivity => (rcond * rcond) * (rcond * rcond),
        };
        power >= ratio
    }

    /// [`Error::Singular`] in `stage` unless `rcond` keeps the accuracy
    /// there ([`Options::keeps_accuracy`]).
    #[inline]
    pub(crate) fn require_accuracy(&self, stage: Stage, rcond: f64) -> Result<(), Error> {
        if self.keeps_accuracy(stage, rcond) {
            Ok(())
        } else {
            Err(Error::Singular {
                stage,
                rcond,
                min_rcond: self.min_rcond(stage),
            })
        }
    }

    /// The defaults with the damped Newton method.
    pub fn damped() -> Options {
        Options {
            damped: true,
            ..Options::default()
        }
    }
}
