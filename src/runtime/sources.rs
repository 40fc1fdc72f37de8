//! Where the derivatives come from: the generated code, automatic
//! differentiation of `psi_generic` with num-dual, or central finite
//! differences of `psi`. The generated code is the fast and exact one; the
//! other two are for cross-checks and for the speed-against-accuracy chart.

use crate::runtime::kernels::Kernels;
use crate::runtime::options::{AccelerationMethod, JacobianSource};
use nalgebra::{SMatrix, SVector};
use num_dual::{Dual2_64, DualSVec64, DualVec, jacobian};

/// Ψ and Ψ_u at (u, v).
pub(crate) fn psi_and_psi_u<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    source: JacobianSource,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
) -> (SVector<f64, M>, SMatrix<f64, M, M>) {
    match source {
        JacobianSource::Generated => model.psi_and_psi_u(u, v),
        JacobianSource::Dual => {
            let vd: SVector<DualSVec64<M>, F> = v.map(DualVec::from_re);
            jacobian(
                |ud: SVector<DualSVec64<M>, M>| model.psi_generic(&ud, &vd),
                u,
            )
        }
        JacobianSource::FiniteDifference => {
            let psi = model.psi(u, v);
            let mut jac = SMatrix::<f64, M, M>::zeros();
            for k in 0..M {
                let h = fd_step(u[k]);
                let (mut up, mut um) = (*u, *u);
                up[k] += h;
                um[k] -= h;
                let column = (model.psi(&up, v) - model.psi(&um, v)) / (up[k] - um[k]);
                jac.set_column(k, &column);
            }
            (psi, jac)
        }
    }
}

/// γ from the generated code by `method` (see [`AccelerationMethod`]); the
/// body of `Linkage::gamma_by`.
pub(crate) fn generated_gamma<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    method: AccelerationMethod,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    udot: &SVector<f64, M>,
    vdot: &SVector<f64, F>,
) -> SVector<f64, M> {
    match method {
        AccelerationMethod::A => {
            model.psi_u_dot(u, v, udot, vdot) * udot + model.psi_v_dot(u, v, udot, vdot) * vdot
        }
        AccelerationMethod::B => {
            model.psi_u_udot_u(u, v, udot) * udot
                + model.psi_u_udot_v(u, v, udot) * vdot
                + model.psi_v_vdot_u(u, v, vdot) * udot
                + model.psi_v_vdot_v(u, v, vdot) * vdot
        }
        AccelerationMethod::Fused => model.gamma(u, v, udot, vdot),
    }
}

/// Ψ_v at (u, v).
pub(crate) fn psi_v<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    source: JacobianSource,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
) -> SMatrix<f64, M, F> {
    match source {
        JacobianSource::Generated => model.psi_v(u, v),
        JacobianSource::Dual => {
            let ud: SVector<DualSVec64<F>, M> = u.map(DualVec::from_re);
            jacobian(
                |vd: SVector<DualSVec64<F>, F>| model.psi_generic(&ud, &vd),
                v,
            )
            .1
        }
        JacobianSource::FiniteDifference => {
            let mut jac = SMatrix::<f64, M, F>::zeros();
            for k in 0..F {
                let h = fd_step(v[k]);
                let (mut vp, mut vm) = (*v, *v);
                vp[k] += h;
                vm[k] -= h;
                let column = (model.psi(u, &vp) - model.psi(u, &vm)) / (vp[k] - vm[k]);
                jac.set_column(k, &column);
            }
            jac
        }
    }
}

/// γ = (Ψ_q q̇)_q q̇ at (u, v) with velocities (u̇, v̇); `generated` is the
/// generated code's choice of form (methods A, B or fused).
pub(crate) fn gamma<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize>(
    model: &L,
    source: JacobianSource,
    generated: impl FnOnce() -> SVector<f64, M>,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    udot: &SVector<f64, M>,
    vdot: &SVector<f64, F>,
) -> SVector<f64, M> {
    match source {
        JacobianSource::Generated => generated(),
        // d²/ds² Ψ(u + s u̇, v + s v̇) at s = 0
        JacobianSource::Dual => {
            let ud = SVector::<Dual2_64, M>::from_fn(|i, _| Dual2_64::new(u[i], udot[i], 0.0));
            let vd = SVector::<Dual2_64, F>::from_fn(|i, _| Dual2_64::new(v[i], vdot[i], 0.0));
            model.psi_generic(&ud, &vd).map(|x| x.v2)
        }
        JacobianSource::FiniteDifference => {
            let q_norm = u.amax().max(v.amax()).max(1.0);
            let speed = udot.amax().max(vdot.amax());
            if speed == 0.0 {
                return SVector::zeros();
            }
            let h = f64::EPSILON.powf(0.25) * q_norm / speed;
            let psi = |s: f64| model.psi(&(u + udot * s), &(v + vdot * s));
            (psi(h) - psi(0.0) * 2.0 + psi(-h)) / (h * h)
        }
    }
}

/// The central-difference step for a coordinate of size `x`.
fn fd_step(x: f64) -> f64 {
    f64::EPSILON.cbrt() * x.abs().max(1.0)
}
