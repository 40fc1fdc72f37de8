//! The [`Linkage`] trait: what `#[linkage::linkage]` generates, and the
//! analyses the runtime builds on it.

use crate::error::{Error, Stage, check_input, check_value};
use crate::linalg::{Inverse, invert};
use crate::sources::{self, JacobianSource};
use crate::symbolic::SymbolicTable;
use nalgebra::{SMatrix, SVector, Vector2};
use num_dual::DualNum;

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

/// Tolerances and choices of the solvers.
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
    /// see [`crate::Inverse::rcond`]) once in the positions, twice in the
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
    /// > 0 (∞ allowed), nothing NaN.
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
    /// positions, 2 for velocities, 3 for accelerations and points.
    pub fn min_rcond(&self, stage: Stage) -> f64 {
        let ratio = f64::EPSILON / self.accuracy;
        match stage {
            Stage::Position => ratio,
            Stage::Velocity => ratio.sqrt(),
            Stage::Acceleration | Stage::Points => ratio.cbrt(),
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

/// An assembled pose found by Newton–Raphson.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Position<const M: usize> {
    pub u: SVector<f64, M>,
    /// Newton steps taken.
    pub iterations: usize,
    /// ‖Ψ(u, v)‖∞ at the solution.
    pub residual: f64,
    /// Ψ_u at the solution (reused by the velocity solve).
    pub psi_u: SMatrix<f64, M, M>,
}

/// One Newton–Raphson iterate, as reported to an observer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Iterate<const M: usize> {
    /// 0 for the initial guess.
    pub iteration: usize,
    pub u: SVector<f64, M>,
    /// ‖Ψ(u, v)‖∞
    pub residual: f64,
    /// ‖Δu‖∞ of the step that led here (0 for the initial guess).
    pub step: f64,
}

/// The velocity solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Velocity<const M: usize, const F: usize> {
    /// u̇ = −R v̇
    pub udot: SVector<f64, M>,
    /// The velocity ratios R = Ψ_u⁻¹Ψ_v (the worksheet's `Rap`); for one
    /// degree of freedom, −R is the column of first kinematic analogs du/dv.
    pub ratios: SMatrix<f64, M, F>,
    /// The reciprocal condition number of Ψ_u.
    pub rcond: f64,
}

/// Everything at one pose, from one pass of generated code
/// ([`Linkage::kinematics`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kinematics<const M: usize, const F: usize> {
    /// Ψ (the residual of the pose).
    pub psi: SVector<f64, M>,
    pub psi_u: SMatrix<f64, M, M>,
    pub psi_v: SMatrix<f64, M, F>,
    /// Ψ_u⁻¹ (meaningless if `rcond` is 0).
    pub inverse: SMatrix<f64, M, M>,
    /// The column-equilibrated reciprocal condition number of Ψ_u.
    pub rcond: f64,
    /// det Ψ_u
    pub det: f64,
    /// u̇ = −Ψ_u⁻¹Ψ_v v̇
    pub udot: SVector<f64, M>,
    /// ü = −Ψ_u⁻¹(Ψ_v v̈ + γ)
    pub uddot: SVector<f64, M>,
}

/// Positions, velocities and accelerations of a pose, of the coordinates
/// and of the points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Analysis<const M: usize, const F: usize, P> {
    pub u: SVector<f64, M>,
    pub udot: SVector<f64, M>,
    pub uddot: SVector<f64, M>,
    /// R = Ψ_u⁻¹Ψ_v
    pub ratios: SMatrix<f64, M, F>,
    pub points: P,
    pub point_velocities: P,
    pub point_accelerations: P,
    /// Newton steps taken.
    pub iterations: usize,
    /// ‖Ψ‖∞ at the solution.
    pub residual: f64,
    /// The reciprocal condition number of Ψ_u at the solution.
    pub rcond: f64,
}

/// A planar mechanism described by closure equations Ψ(u, v) = 0 with m
/// dependent coordinates u and f driving coordinates v.
///
/// `#[linkage::linkage(...)]` implements the required methods with code
/// generated from the equations; the provided methods are the analyses.
pub trait Linkage<const M: usize, const F: usize> {
    /// The points' positions, velocities or accelerations: one 2-vector per
    /// named point, in the order of [`Linkage::POINT_NAMES`].
    type Points: Copy + core::fmt::Debug + PartialEq + AsRef<[Vector2<f64>]>;
    const U_NAMES: [&'static str; M];
    const V_NAMES: [&'static str; F];
    const POINT_NAMES: &'static [&'static str];
    const SYMBOLIC: SymbolicTable;

    /// Ψ
    fn psi(&self, u: &SVector<f64, M>, v: &SVector<f64, F>) -> SVector<f64, M>;
    /// Ψ_u = ∂Ψ/∂u
    fn psi_u(&self, u: &SVector<f64, M>, v: &SVector<f64, F>) -> SMatrix<f64, M, M>;
    /// Ψ_v = ∂Ψ/∂v
    fn psi_v(&self, u: &SVector<f64, M>, v: &SVector<f64, F>) -> SMatrix<f64, M, F>;
    /// Ψ and Ψ_u in one evaluation.
    fn psi_and_psi_u(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
    ) -> (SVector<f64, M>, SMatrix<f64, M, M>);
    /// (\[Ψ_u\]u̇)_u
    fn psi_u_udot_u(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
    ) -> SMatrix<f64, M, M>;
    /// (\[Ψ_u\]u̇)_v
    fn psi_u_udot_v(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
    ) -> SMatrix<f64, M, F>;
    /// (\[Ψ_v\]v̇)_u
    fn psi_v_vdot_u(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        vdot: &SVector<f64, F>,
    ) -> SMatrix<f64, M, M>;
    /// (\[Ψ_v\]v̇)_v
    fn psi_v_vdot_v(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        vdot: &SVector<f64, F>,
    ) -> SMatrix<f64, M, F>;
    /// Ψ̇_u
    fn psi_u_dot(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
    ) -> SMatrix<f64, M, M>;
    /// Ψ̇_v
    fn psi_v_dot(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
    ) -> SMatrix<f64, M, F>;
    /// γ = (Ψ_q q̇)_q q̇
    fn gamma(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
    ) -> SVector<f64, M>;
    /// Ψ, Ψ_u, Ψ_v, u̇ and ü in one pass (no conditioning check: the
    /// caller judges `rcond`).
    fn kinematics(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        vdot: &SVector<f64, F>,
        vddot: &SVector<f64, F>,
    ) -> Kinematics<M, F>;
    /// Which coordinates of u have their sine and cosine read from `trig_u`
    /// by [`Linkage::kinematics_with_trig`] (none by default).
    const TRIG_U: [bool; M] = [false; M];
    /// Which coordinates of v have their sine and cosine read from `trig_v`.
    const TRIG_V: [bool; F] = [false; F];
    /// [`Linkage::kinematics`] with the sines and cosines of the coordinates
    /// supplied: `trig_u[k]` = (sin uₖ, cos uₖ), likewise `trig_v`. A sweep
    /// carries them from pose to pose by the angle-addition formulas. The
    /// generated code reads only the entries of coordinates that appear under
    /// `sin`/`cos`; the default ignores them and calls `kinematics`.
    #[allow(clippy::too_many_arguments)]
    fn kinematics_with_trig(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        trig_u: &[(f64, f64); M],
        trig_v: &[(f64, f64); F],
        vdot: &SVector<f64, F>,
        vddot: &SVector<f64, F>,
    ) -> Kinematics<M, F> {
        let _ = (trig_u, trig_v);
        self.kinematics(u, v, vdot, vddot)
    }
    /// P(q)
    fn point_positions(&self, u: &SVector<f64, M>, v: &SVector<f64, F>) -> Self::Points;
    /// Ṗ = P_q q̇
    fn point_velocities(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
    ) -> Self::Points;
    /// P̈ = P_q q̈ + (P_q q̇)_q q̇
    #[allow(clippy::too_many_arguments)]
    fn point_accelerations(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
        uddot: &SVector<f64, M>,
        vddot: &SVector<f64, F>,
    ) -> Self::Points;
    /// Ψ on dual numbers.
    fn psi_generic<D: DualNum<Primitive = f64> + Copy>(
        &self,
        u: &SVector<D, M>,
        v: &SVector<D, F>,
    ) -> SVector<D, M>;
    /// P(q) on dual numbers.
    fn point_positions_generic<D: DualNum<Primitive = f64> + Copy>(
        &self,
        u: &SVector<D, M>,
        v: &SVector<D, F>,
    ) -> impl AsRef<[Vector2<D>]>;

    /// The index of a named point.
    fn point_index(name: &str) -> Option<usize> {
        Self::POINT_NAMES.iter().position(|n| *n == name)
    }

    /// Solves Ψ(u, v) = 0 for u by Newton–Raphson from the guess `u0`.
    fn solve_position(
        &self,
        u0: &SVector<f64, M>,
        v: &SVector<f64, F>,
        options: &Options,
    ) -> Result<Position<M>, Error> {
        self.solve_position_observed(u0, v, options, |_| {})
    }

    /// [`Linkage::solve_position`], reporting every iterate (the initial
    /// guess first) to `observe`.
    fn solve_position_observed(
        &self,
        u0: &SVector<f64, M>,
        v: &SVector<f64, F>,
        options: &Options,
        mut observe: impl FnMut(&Iterate<M>),
    ) -> Result<Position<M>, Error> {
        crate::newton::solve(self, u0, v, options, &mut observe)
    }

    /// The velocity u̇ = −Ψ_u⁻¹Ψ_v v̇ and the ratio matrix R = Ψ_u⁻¹Ψ_v at an
    /// assembled pose.
    fn velocity(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        vdot: &SVector<f64, F>,
        options: &Options,
    ) -> Result<Velocity<M, F>, Error> {
        check_input("u", u.as_slice())?;
        check_input("v", v.as_slice())?;
        check_input("vdot", vdot.as_slice())?;
        options.check()?;
        let psi_u = sources::psi_and_psi_u(self, options.jacobian, u, v).1;
        velocity_with(self, &psi_u, u, v, vdot, options)
    }

    /// γ by the chosen method (no solve).
    fn gamma_by(
        &self,
        method: AccelerationMethod,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
    ) -> SVector<f64, M> {
        match method {
            AccelerationMethod::A => {
                self.psi_u_dot(u, v, udot, vdot) * udot + self.psi_v_dot(u, v, udot, vdot) * vdot
            }
            AccelerationMethod::B => {
                self.psi_u_udot_u(u, v, udot) * udot
                    + self.psi_u_udot_v(u, v, udot) * vdot
                    + self.psi_v_vdot_u(u, v, vdot) * udot
                    + self.psi_v_vdot_v(u, v, vdot) * vdot
            }
            AccelerationMethod::Fused => self.gamma(u, v, udot, vdot),
        }
    }

    /// The acceleration ü = −Ψ_u⁻¹(Ψ_v v̈ + γ) at an assembled pose with
    /// velocities `udot`, `vdot`, with γ by `options.method`.
    #[allow(clippy::too_many_arguments)]
    fn acceleration(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
        vddot: &SVector<f64, F>,
        options: &Options,
    ) -> Result<SVector<f64, M>, Error> {
        for (name, values) in [("u", u.as_slice()), ("udot", udot.as_slice())] {
            check_input(name, values)?;
        }
        for (name, values) in [
            ("v", v.as_slice()),
            ("vdot", vdot.as_slice()),
            ("vddot", vddot.as_slice()),
        ] {
            check_input(name, values)?;
        }
        options.check()?;
        let psi_u = sources::psi_and_psi_u(self, options.jacobian, u, v).1;
        acceleration_with(self, &psi_u, u, v, udot, vdot, vddot, options)
    }

    /// Drives the mechanism along `drive` from the pose near `u0`, by
    /// continuation: every pose with its velocities and accelerations, and
    /// every singular pose met, located and classified (see
    /// [`crate::Drive`]).
    fn sweep(
        &self,
        u0: &SVector<f64, M>,
        drive: &crate::sweep::Drive<F>,
        options: &crate::sweep::SweepOptions,
    ) -> Result<crate::sweep::Sweep<M, F>, Error> {
        let mut poses = Vec::new();
        let summary = crate::sweep::sweep(self, u0, drive, options, &mut |p| poses.push(*p))?;
        Ok(crate::sweep::Sweep {
            poses,
            events: summary.events,
            complete: summary.complete,
        })
    }

    /// [`Linkage::sweep`], passing each pose to `on_pose` instead of
    /// storing it: a sweep of millions of poses in constant memory.
    fn sweep_each(
        &self,
        u0: &SVector<f64, M>,
        drive: &crate::sweep::Drive<F>,
        options: &crate::sweep::SweepOptions,
        mut on_pose: impl FnMut(&crate::sweep::SweepPose<M, F>),
    ) -> Result<crate::sweep::SweepSummary<M, F>, Error> {
        crate::sweep::sweep(self, u0, drive, options, &mut on_pose)
    }

    /// The whole analysis of one pose: Newton–Raphson from `u_guess`, then
    /// velocities and accelerations of the coordinates and the points.
    fn analyze(
        &self,
        u_guess: &SVector<f64, M>,
        v: &SVector<f64, F>,
        vdot: &SVector<f64, F>,
        vddot: &SVector<f64, F>,
        options: &Options,
    ) -> Result<Analysis<M, F, Self::Points>, Error> {
        check_input("vdot", vdot.as_slice())?;
        check_input("vddot", vddot.as_slice())?;
        let position = self.solve_position(u_guess, v, options)?;
        let u = position.u;
        // The fused kernel where its numbers are ordinary; the separate
        // solves, which scale γ and check for underflow, at the extremes.
        let fused = if options.jacobian == JacobianSource::Generated
            && options.method == AccelerationMethod::Fused
            && ordinary(vdot.amax(), true)
            && ordinary(vddot.amax(), true)
        {
            fused_kinematics(self, &u, v, vdot, vddot, options)?
        } else {
            None
        };
        let (velocity, uddot) = if let Some(fused) = fused {
            fused
        } else {
            let velocity = velocity_with(self, &position.psi_u, &u, v, vdot, options)?;
            let uddot = acceleration_with(
                self,
                &position.psi_u,
                &u,
                v,
                &velocity.udot,
                vdot,
                vddot,
                options,
            )?;
            (velocity, uddot)
        };
        let points = self.point_positions(&u, v);
        let point_velocities = self.point_velocities(&u, v, &velocity.udot, vdot);
        let point_accelerations =
            self.point_accelerations(&u, v, &velocity.udot, vdot, &uddot, vddot);
        for (quantity, p) in [
            ("P", &points),
            ("Ṗ", &point_velocities),
            ("P̈", &point_accelerations),
        ] {
            if !p.as_ref().iter().all(|x| x.iter().all(|c| c.is_finite())) {
                return Err(Error::NonFiniteValue {
                    stage: Stage::Points,
                    quantity,
                });
            }
        }
        Ok(Analysis {
            u,
            udot: velocity.udot,
            uddot,
            ratios: velocity.ratios,
            points,
            point_velocities,
            point_accelerations,
            iterations: position.iterations,
            residual: position.residual,
            rcond: velocity.rcond,
        })
    }
}

/// Ψ_u inverted, or [`Error::Singular`] if its conditioning is below what
/// `stage` needs to keep the requested accuracy.
fn factor<const M: usize>(
    psi_u: &SMatrix<f64, M, M>,
    stage: Stage,
    options: &Options,
) -> Result<Inverse<M>, Error> {
    let inv = invert(psi_u);
    let min_rcond = options.min_rcond(stage);
    if inv.rcond > 0.0 && inv.rcond >= min_rcond {
        Ok(inv)
    } else {
        Err(Error::Singular {
            stage,
            rcond: inv.rcond,
            min_rcond,
        })
    }
}

fn velocity_with<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    psi_u: &SMatrix<f64, M, M>,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    vdot: &SVector<f64, F>,
    options: &Options,
) -> Result<Velocity<M, F>, Error> {
    let psi_v = sources::psi_v(model, options.jacobian, u, v);
    check_value(Stage::Velocity, "Ψ_v", psi_v.as_slice())?;
    crate::error::check_scale(Stage::Velocity, psi_u, &psi_v)?;
    let inv = factor(psi_u, Stage::Velocity, options)?;
    let ratios = inv.inverse * psi_v;
    let udot = -(ratios * vdot);
    check_value(Stage::Velocity, "u̇", udot.as_slice())?;
    // The size of the terms of u̇ = −R v̇, ‖R‖·|v̇| (as log₂, which cannot
    // underflow), must be a normal number.
    let terms = if ratios.amax() > 0.0 && vdot.amax() > 0.0 {
        ratios.amax().log2() + vdot.amax().log2()
    } else {
        f64::NEG_INFINITY
    };
    crate::error::check_result(Stage::Velocity, "u̇", terms)?;
    Ok(Velocity {
        udot,
        ratios,
        rcond: inv.rcond,
    })
}

/// A magnitude the fused kernel handles with full precision: within
/// 10^±60, or zero where `zero_ok`.
fn ordinary(x: f64, zero_ok: bool) -> bool {
    (zero_ok && x == 0.0) || (1e-60..=1e60).contains(&x)
}

/// Velocities and accelerations from one fused generated evaluation, with
/// the same conditioning checks as the separate solves; `None` where the
/// results are extreme (nonzero and outside 10^±100), which the separate
/// solves handle with their scaling and underflow checks.
fn fused_kinematics<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    vdot: &SVector<f64, F>,
    vddot: &SVector<f64, F>,
    options: &Options,
) -> Result<Option<(Velocity<M, F>, SVector<f64, M>)>, Error> {
    let k = model.kinematics(u, v, vdot, vddot);
    check_value(Stage::Velocity, "Ψ_v", k.psi_v.as_slice())?;
    let (smallest, largest) = crate::error::check_scale(Stage::Velocity, &k.psi_u, &k.psi_v)?;
    let min_rcond = options.min_rcond(Stage::Velocity);
    if !(k.rcond > 0.0 && k.rcond >= min_rcond) {
        return Err(Error::Singular {
            stage: Stage::Velocity,
            rcond: k.rcond,
            min_rcond,
        });
    }
    check_value(Stage::Velocity, "u̇", k.udot.as_slice())?;
    acceleration_conditioning(&k.psi_u, &k.psi_v, k.rcond, options)?;
    check_value(Stage::Acceleration, "ü", k.uddot.as_slice())?;
    // Every row and column of [Ψ_u Ψ_v], and u̇ and ü, within 10^±60 (zero
    // only where the drivers are at rest): then no product in the kernel,
    // of at most a few such factors, comes near the subnormal range, and
    // the result keeps its precision. Anything else goes to the separate
    // solves, which scale and check.
    let at_rest = vdot.amax() == 0.0;
    let geometry = ordinary(smallest, false) && ordinary(largest, false);
    let still = at_rest && vddot.amax() == 0.0;
    if !(geometry && ordinary(k.udot.amax(), at_rest) && ordinary(k.uddot.amax(), still)) {
        return Ok(None);
    }
    let velocity = Velocity {
        udot: k.udot,
        ratios: k.inverse * k.psi_v,
        rcond: k.rcond,
    };
    Ok(Some((velocity, k.uddot)))
}

#[allow(clippy::too_many_arguments)]
fn acceleration_with<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    psi_u: &SMatrix<f64, M, M>,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    udot: &SVector<f64, M>,
    vdot: &SVector<f64, F>,
    vddot: &SVector<f64, F>,
    options: &Options,
) -> Result<SVector<f64, M>, Error> {
    let inv = invert(psi_u);
    let psi_v = sources::psi_v(model, options.jacobian, u, v);
    check_value(Stage::Acceleration, "Ψ_v", psi_v.as_slice())?;
    crate::error::check_scale(Stage::Acceleration, psi_u, &psi_v)?;
    acceleration_conditioning(psi_u, &psi_v, inv.rcond, options)?;
    // ü = −Ψ_u⁻¹Ψ_v v̈ − Ψ_u⁻¹γ, each part computed at unit scale and
    // scaled back by powers of two (exact): γ is quadratic in the
    // velocities, γ(q̇) = s²·γ(q̇/s), and the v̈ part linear in v̈, so that
    // no intermediate underflows or overflows however small or large the
    // velocities, the accelerations or the mechanism. In the normal range
    // every scaling is exact and the result is the plain formula's, bit for
    // bit up to the order of the sums.
    let s = crate::linalg::power_of_two_near(udot.amax().max(vdot.amax()));
    let (udot, vdot) = (udot / s, vdot / s);
    let generated = || model.gamma_by(options.method, u, v, &udot, &vdot);
    let gamma_unit = sources::gamma(model, options.jacobian, generated, u, v, &udot, &vdot);
    check_value(Stage::Acceleration, "γ", gamma_unit.as_slice())?;
    let t = crate::linalg::power_of_two_near(vddot.amax());
    let from_gamma = inv.inverse * gamma_unit;
    let from_vddot = inv.inverse * (psi_v * (vddot / t));
    check_value(Stage::Acceleration, "ü", from_gamma.as_slice())?;
    check_value(Stage::Acceleration, "ü", from_vddot.as_slice())?;
    // The size of the terms ü is made of, as log₂ (no underflow): ‖Ψ_u⁻¹‖
    // times ‖Ψ_v‖·|v̈| and times γ's terms, second derivatives of Ψ (sized
    // by its first, ‖[Ψ_u Ψ_v]‖) times |q̇|². Not ü's own size: γ's terms
    // may cancel (a rhombus's do, exactly), and ü with them, to far less
    // than the precision they leave; what must be a normal number is the
    // scale of that precision.
    let inverse_log2 = inv.inverse.amax().log2();
    let vddot_terms = if from_vddot.amax() > 0.0 {
        inverse_log2 + psi_v.amax().log2() + vddot.amax().log2()
    } else {
        f64::NEG_INFINITY
    };
    let gamma_terms = if udot.amax().max(vdot.amax()) > 0.0 {
        inverse_log2
            + psi_u.amax().max(psi_v.amax()).log2()
            + 2.0 * (udot.amax().max(vdot.amax()).log2() + s.log2())
    } else {
        f64::NEG_INFINITY
    };
    crate::error::check_result(Stage::Acceleration, "ü", vddot_terms.max(gamma_terms))?;
    let uddot = -(from_vddot * t + from_gamma * s * s);
    check_value(Stage::Acceleration, "ü", uddot.as_slice())?;
    Ok(uddot)
}

/// Whether an acceleration solve keeps [`Options::accuracy`]. Far from
/// singular poses ε·κ³ ≤ accuracy settles it. Nearer, the amplification is
/// ε·κ²·κ_q, with κ_q the condition number of [Ψ_u Ψ_v]: about 1 at a limit
/// position (where accelerations stay accurate as long as velocities do)
/// and about κ at a branch point (where they degrade first).
pub(crate) fn acceleration_conditioning<const M: usize, const F: usize>(
    psi_u: &SMatrix<f64, M, M>,
    psi_v: &SMatrix<f64, M, F>,
    rcond: f64,
    options: &Options,
) -> Result<(), Error> {
    acceleration_conditioning_with(
        psi_u,
        psi_v,
        rcond,
        options.min_rcond(Stage::Acceleration),
        options,
    )
}

/// [`acceleration_conditioning`] with the threshold ε·κ³ ≤ accuracy already
/// worked out (`fast`).
pub(crate) fn acceleration_conditioning_with<const M: usize, const F: usize>(
    psi_u: &SMatrix<f64, M, M>,
    psi_v: &SMatrix<f64, M, F>,
    rcond: f64,
    fast: f64,
    options: &Options,
) -> Result<(), Error> {
    if rcond > 0.0 && rcond >= fast {
        return Ok(());
    }
    let needed = if rcond > 0.0 {
        (f64::EPSILON * augmented_condition(psi_u, psi_v) / options.accuracy)
            .sqrt()
            .min(fast)
    } else {
        fast
    };
    if rcond > 0.0 && rcond >= needed {
        Ok(())
    } else {
        Err(Error::Singular {
            stage: Stage::Acceleration,
            rcond,
            min_rcond: needed,
        })
    }
}

/// σ_max/σ_min of [Ψ_u Ψ_v] with its columns scaled to unit length.
fn augmented_condition<const M: usize, const F: usize>(
    psi_u: &SMatrix<f64, M, M>,
    psi_v: &SMatrix<f64, M, F>,
) -> f64 {
    let mut q = nalgebra::DMatrix::<f64>::zeros(M, M + F);
    for j in 0..M + F {
        let column: Vec<f64> = (0..M)
            .map(|i| {
                if j < M {
                    psi_u[(i, j)]
                } else {
                    psi_v[(i, j - M)]
                }
            })
            .collect();
        let norm = column.iter().map(|x| x * x).sum::<f64>().sqrt();
        if norm > 0.0 {
            for (i, x) in column.iter().enumerate() {
                q[(i, j)] = x / norm;
            }
        }
    }
    // A decomposition that fails (only for extreme numbers) counts as
    // ill-conditioned: the cautious reading.
    let Some(svd) = crate::linalg::scaled_svd(&q, false) else {
        return f64::INFINITY;
    };
    let (max, min) = svd
        .singular_values
        .iter()
        .fold((0.0_f64, f64::INFINITY), |(a, b), &x| (a.max(x), b.min(x)));
    if min > 0.0 { max / min } else { f64::INFINITY }
}
