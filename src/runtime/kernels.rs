//! The [`Kernels`] trait: what `#[linkage::linkage]` generates from the
//! closure equations (the names, the points' type, Ψ, its Jacobians, the
//! second-order terms and the points' kinematics), which the runtime's
//! analyses call. The analyses themselves are the provided methods of
//! [`Linkage`](crate::runtime::Linkage), a trait on top of this one.

use crate::runtime::blocks::PsiUBlocks;
use crate::runtime::results::Kinematics;
use nalgebra::{SMatrix, SVector, Vector2};
use num_dual::DualNum;

/// The generated part of a mechanism: Ψ(u, v) with m dependent coordinates
/// u and f driving coordinates v, its Jacobians, the second-order terms of
/// the accelerations and the kinematics of the named points, as
/// straight-line code.
///
/// `#[linkage::linkage(...)]` implements it (each method delegating to the
/// struct's inherent function of the same name), together with
/// [`Linkage`](crate::runtime::Linkage), the analyses built on it. Users
/// rarely name it: a `Linkage<M, F>` bound reaches every item of this
/// trait (`model.point_names()`, `model.psi(&u, &v)`), and on a generated
/// struct the inherent functions and constants answer first. Name it in a
/// fully qualified path (`<FourBar as Kernels<2, 1>>::psi`) or in a bound
/// that needs no analysis.
pub trait Kernels<const M: usize, const F: usize> {
    /// The points' positions, velocities or accelerations: one 2-vector per
    /// named point, in the order of [`Kernels::point_names`].
    type Points: Copy + core::fmt::Debug + PartialEq + AsRef<[Vector2<f64>]> + AsMut<[Vector2<f64>]>;

    /// The names of the dependent coordinates u, in order (a generated
    /// struct also has them as the constant `U_NAMES`).
    fn u_names(&self) -> [&'static str; M];
    /// The names of the driving coordinates v, in order (`V_NAMES`).
    fn v_names(&self) -> [&'static str; F];
    /// The names of the points, in the order of [`Kernels::Points`]
    /// (`POINT_NAMES`).
    fn point_names(&self) -> &'static [&'static str];
    /// The index of a named point, found at run time (the generated
    /// constants, `FourBar::C`, give it at compile time).
    fn point_index(&self, name: &str) -> Option<usize> {
        self.point_names().iter().position(|n| *n == name)
    }

    /// Ψ_u's diagonal blocks in the order they are solved: the generated
    /// constant `PSI_U_BLOCKS` where Ψ_u is block lower triangular, one
    /// dense block (the default) where it is not. The analyses factor and
    /// solve with Ψ_u block by block in this order
    /// ([`Factors::of`](crate::runtime::Factors::of)), which must be Ψ_u's
    /// structure: entries outside the blocks' reach are never read.
    fn psi_u_blocks(&self) -> PsiUBlocks<'_> {
        PsiUBlocks::DENSE
    }

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
    /// by [`Kernels::kinematics_with_trig`] (none by default).
    #[doc(hidden)]
    fn trig_u(&self) -> [bool; M] {
        [false; M]
    }
    /// Which coordinates of v have their sine and cosine read from `trig_v`.
    #[doc(hidden)]
    fn trig_v(&self) -> [bool; F] {
        [false; F]
    }
    /// [`Kernels::kinematics`] with the sines and cosines of the coordinates
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
    /// Whether [`Kernels::kinematics_with_trig_into`] spares a sweep's
    /// evaluations a copy (a run-time mechanism's: a result returned
    /// through its register file would be copied whole on the way).
    #[doc(hidden)]
    #[inline(always)]
    fn evaluates_in_place(&self) -> bool {
        false
    }
    /// [`Kernels::kinematics_with_trig`] written over `out`. The same
    /// numbers, bit for bit.
    #[doc(hidden)]
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn kinematics_with_trig_into(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        trig_u: &[(f64, f64); M],
        trig_v: &[(f64, f64); F],
        vdot: &SVector<f64, F>,
        vddot: &SVector<f64, F>,
        out: &mut Kinematics<M, F>,
    ) {
        *out = self.kinematics_with_trig(u, v, trig_u, trig_v, vdot, vddot);
    }
    /// [`Kernels::kinematics_with_trig_into`] over an `out` whose Ψ_u is
    /// already zero wherever this model's Ψ_u is zero at every pose: one
    /// that an evaluation of this model wrote, or [`Kinematics::blank`]. A
    /// model may leave those entries alone; the generated code of more
    /// than four coordinates does (zeroing them was the one part of its
    /// evaluation that grows as m²). The same numbers, bit for bit.
    #[doc(hidden)]
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn kinematics_with_trig_over(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        trig_u: &[(f64, f64); M],
        trig_v: &[(f64, f64); F],
        vdot: &SVector<f64, F>,
        vddot: &SVector<f64, F>,
        out: &mut Kinematics<M, F>,
    ) {
        self.kinematics_with_trig_into(u, v, trig_u, trig_v, vdot, vddot, out);
    }
    /// Whether [`Kernels::kinematics_with_trig_each`] makes its requests
    /// together faster than one after the other: a batch then runs its
    /// analyses side by side (else each alone, as `analyze` does).
    #[doc(hidden)]
    fn evaluates_together() -> bool
    where
        Self: Sized,
    {
        false
    }
    /// [`Kernels::kinematics_with_trig`] at many poses, each of its own
    /// model, each into its slot of `out` (as many as the requests; the
    /// slots beyond them are left alone): in slot k, bit for bit what
    /// `requests[k].model.kinematics_with_trig(…)` gives, but u̇ and ü,
    /// which may be NaN where the request does not ask for its rates
    /// ([`FusedRequest::rates`]). A batch of
    /// analyses asks for its poses' evaluations together; the default
    /// makes them one after the other, and a run-time mechanism runs the
    /// requests of one program together on its tapes' lanes.
    #[doc(hidden)]
    fn kinematics_with_trig_each(
        requests: &[FusedRequest<'_, Self, M, F>],
        out: &mut [Kinematics<M, F>],
    ) where
        Self: Sized,
    {
        for (r, out) in requests.iter().zip(out) {
            (r.model).kinematics_with_trig_into(r.u, r.v, r.trig_u, r.trig_v, r.vdot, r.vddot, out);
        }
    }
    /// Which coordinates of u have their sine and cosine read from
    /// `trig_u` by [`Kernels::point_motion_with_trig`] (none by default).
    #[doc(hidden)]
    fn point_trig_u(&self) -> [bool; M] {
        [false; M]
    }
    /// Which coordinates of v have their sine and cosine read from `trig_v`.
    #[doc(hidden)]
    fn point_trig_v(&self) -> [bool; F] {
        [false; F]
    }
    /// The points' positions, velocities and accelerations at one pose,
    /// the sines and cosines of the coordinates of
    /// [`Kernels::point_trig_u`] and [`Kernels::point_trig_v`] supplied
    /// (`trig_u[k]` = (sin uₖ, cos uₖ), exactly): bit for bit
    /// [`Kernels::point_positions`], [`Kernels::point_velocities`] and
    /// [`Kernels::point_accelerations`], which the default calls. A
    /// run-time mechanism evaluates the three in one pass of its tapes.
    #[doc(hidden)]
    #[allow(clippy::too_many_arguments)]
    fn point_motion_with_trig(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        udot: &SVector<f64, M>,
        vdot: &SVector<f64, F>,
        uddot: &SVector<f64, M>,
        vddot: &SVector<f64, F>,
        trig_u: &[(f64, f64); M],
        trig_v: &[(f64, f64); F],
    ) -> [Self::Points; 3] {
        let _ = (trig_u, trig_v);
        [
            self.point_positions(u, v),
            self.point_velocities(u, v, udot, vdot),
            self.point_accelerations(u, v, udot, vdot, uddot, vddot),
        ]
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
}

/// One evaluation of a batch's fused kernels
/// ([`Kernels::kinematics_with_trig_each`]): the arguments of
/// [`Kernels::kinematics_with_trig`], and the model to evaluate.
#[doc(hidden)]
pub struct FusedRequest<'a, L, const M: usize, const F: usize> {
    pub model: &'a L,
    pub u: &'a SVector<f64, M>,
    pub v: &'a SVector<f64, F>,
    pub trig_u: &'a [(f64, f64); M],
    pub trig_v: &'a [(f64, f64); F],
    pub vdot: &'a SVector<f64, F>,
    pub vddot: &'a SVector<f64, F>,
    /// Whether u̇ and ü are wanted (a Newton iterate that cannot end its
    /// iteration needs only Ψ, Ψ_u and its factors).
    pub rates: bool,
}
