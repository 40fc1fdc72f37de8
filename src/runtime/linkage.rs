//! The [`Linkage`] trait: what `#[linkage::linkage]` generates (the
//! required methods), and the analyses built on it (the provided methods,
//! each delegating to the module that does the work: `newton.rs` for
//! positions, `solve.rs` for velocities and accelerations,
//! `sweep/` for continuation).

use crate::runtime::error::Error;
use crate::runtime::options::{AccelerationMethod, Options};
use crate::runtime::results::{Analysis, Iterate, Kinematics, Position, Velocity};
use crate::runtime::symbolic::SymbolicTable;
use crate::runtime::{newton, solve, sources};
use nalgebra::{SMatrix, SVector, Vector2};
use num_dual::DualNum;

/// A planar mechanism described by closure equations Ψ(u, v) = 0 with m
/// dependent coordinates u and f driving coordinates v.
///
/// `#[linkage::linkage(...)]` implements the required methods with code
/// generated from the equations; the provided methods are the analyses.
pub trait Linkage<const M: usize, const F: usize> {
    /// The points' positions, velocities or accelerations: one 2-vector per
    /// named point, in the order of [`Linkage::POINT_NAMES`].
    type Points: Copy + core::fmt::Debug + PartialEq + AsRef<[Vector2<f64>]> + AsMut<[Vector2<f64>]>;
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
    // The speed machinery of a sweep (generated; hidden from the API): the
    // sines and cosines of the coordinates carried from pose to pose.
    /// Which coordinates of u have their sine and cosine read from `trig_u`
    /// by [`Linkage::kinematics_with_trig`] (none by default).
    #[doc(hidden)]
    const TRIG_U: [bool; M] = [false; M];
    /// Which coordinates of v have their sine and cosine read from `trig_v`.
    #[doc(hidden)]
    const TRIG_V: [bool; F] = [false; F];
    /// [`Linkage::kinematics`] with the sines and cosines of the coordinates
    /// supplied: `trig_u[k]` = (sin uₖ, cos uₖ), likewise `trig_v`. A sweep
    /// carries them from pose to pose by the angle-addition formulas. The
    /// generated code reads only the entries of coordinates that appear under
    /// `sin`/`cos`; the default ignores them and calls `kinematics`.
    #[doc(hidden)]
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

    /// The index of a named point, found at run time (the generated
    /// constants, `FourBar::C`, give it at compile time).
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
        newton::solve(self, u0, v, options, &mut observe)
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
        solve::velocity(self, u, v, vdot, options)
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
        sources::generated_gamma(self, method, u, v, udot, vdot)
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
        solve::acceleration(self, u, v, udot, vdot, vddot, options)
    }

    /// Drives the mechanism along `drive` from the pose near `u0`, by
    /// continuation: every pose with its velocities and accelerations, and
    /// every singular pose met, located and classified (see
    /// [`crate::runtime::Drive`]).
    fn sweep(
        &self,
        u0: &SVector<f64, M>,
        drive: &crate::runtime::sweep::Drive<F>,
        options: &crate::runtime::sweep::SweepOptions,
    ) -> Result<crate::runtime::sweep::Sweep<M, F>, Error> {
        let mut poses = Vec::new();
        let summary =
            crate::runtime::sweep::sweep(self, u0, drive, options, &mut |p| poses.push(*p))?;
        Ok(crate::runtime::sweep::Sweep {
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
        drive: &crate::runtime::sweep::Drive<F>,
        options: &crate::runtime::sweep::SweepOptions,
        mut on_pose: impl FnMut(&crate::runtime::sweep::SweepPose<M, F>),
    ) -> Result<crate::runtime::sweep::SweepSummary<M, F>, Error> {
        crate::runtime::sweep::sweep(self, u0, drive, options, &mut on_pose)
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
        solve::analyze(self, u_guess, v, vdot, vddot, options)
    }
}
