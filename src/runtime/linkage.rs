//! The [`Linkage`] trait: the analyses of a mechanism (its provided
//! methods, each delegating to the module that does the work: `newton.rs`
//! for positions, `solve.rs` for velocities and accelerations, `sweep/` for
//! continuation), on top of [`Kernels`], what `#[linkage::linkage]`
//! generates. Nothing below depends on this file: those modules take their
//! model as `Kernels`.

use crate::runtime::error::Error;
use crate::runtime::kernels::Kernels;
use crate::runtime::options::{AccelerationMethod, Options};
use crate::runtime::results::{Analysis, Iterate, Position, Velocity};
use crate::runtime::{newton, solve, sources};
use nalgebra::SVector;

/// A planar mechanism described by closure equations Ψ(u, v) = 0 with m
/// dependent coordinates u and f driving coordinates v: the analyses of
/// its poses, built on the generated [`Kernels`].
///
/// `#[linkage::linkage(...)]` implements [`Kernels`] with code generated
/// from the equations, and this trait (empty: every method is provided).
/// Every item of [`Kernels`] is reachable through a `Linkage<M, F>` bound.
pub trait Linkage<const M: usize, const F: usize>: Kernels<M, F> {
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
