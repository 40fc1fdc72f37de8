//! Derivatives along the path (Ψ_u, Ψ_t) and the bordered Newton system on them, for (u, t).

use super::tracker::Tracker;
use crate::runtime::kernels::Kernels;
use crate::runtime::sources;
use nalgebra::{DMatrix, DVector, SVector};

/// One row of a bordered system, g's: ∂g/∂u, ∂g/∂t, and the right-hand
/// side (−g, or the target less g).
pub(super) type Border<const M: usize> = (SVector<f64, M>, f64, f64);

impl<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize> Tracker<'_, L, M, F> {
    /// Ψ_t = Ψ_v · direction
    pub(super) fn psi_t(&self, u: &SVector<f64, M>, t: f64) -> SVector<f64, M> {
        sources::psi_v(self.model, self.options.options.jacobian, u, &self.v(t)) * self.dir
    }

    /// J = [Ψ_u Ψ_τ] at (u, t), Ψ_τ the derivative along the unit direction
    /// of the path: m × (m + 1).
    pub(super) fn path_jacobian(&self, u: &SVector<f64, M>, t: f64) -> DMatrix<f64> {
        let v = self.v(t);
        let jacobian = self.options.options.jacobian;
        let psi_u = sources::psi_and_psi_u(self.model, jacobian, u, &v).1;
        let psi_tau = self.psi_t(u, t) / self.step_length;
        DMatrix::from_fn(
            M,
            M + 1,
            |i, j| {
                if j < M { psi_u[(i, j)] } else { psi_tau[i] }
            },
        )
    }

    /// Newton on the bordered system Ψ(u, t) = 0, g(u, t) = 0 in the m + 1
    /// unknowns (u, t), from (u, t): each step solves
    /// [Ψ_u Ψ_t; ∂g/∂u ∂g/∂t]·(Δu, Δt) = (−Ψ, rhs) with `border(u, t)` giving
    /// g's row and its right-hand side; at most 50 steps, until a step is
    /// below 1e-14 of max(1, ‖u‖∞, |t|). `None` if the system is singular or
    /// a step is not finite.
    pub(super) fn bordered_newton(
        &self,
        u: &SVector<f64, M>,
        t: f64,
        border: impl Fn(&SVector<f64, M>, f64) -> Border<M>,
    ) -> Option<(SVector<f64, M>, f64)> {
        let (mut u, mut t) = (*u, t);
        let n = M + 1;
        for _ in 0..50 {
            let v = self.v(t);
            let psi = self.model.psi(&u, &v);
            let psi_u = sources::psi_and_psi_u(self.model, self.options.options.jacobian, &u, &v).1;
            let psi_t = self.psi_t(&u, t);
            let (border_u, border_t, border_rhs) = border(&u, t);
            let mut jac = DMatrix::<f64>::zeros(n, n);
            let mut rhs = DVector::<f64>::zeros(n);
            for i in 0..M {
                for j in 0..M {
                    jac[(i, j)] = psi_u[(i, j)];
                }
                jac[(i, M)] = psi_t[i];
                rhs[i] = -psi[i];
                jac[(M, i)] = border_u[i];
            }
            jac[(M, M)] = border_t;
            rhs[M] = border_rhs;
            let step = jac.lu().solve(&rhs)?;
            if !step.iter().all(|x| x.is_finite()) {
                return None;
            }
            for j in 0..M {
                u[j] += step[j];
            }
            t += step[M];
            if step.amax() <= 1e-14 * u.amax().max(t.abs()).max(1.0) {
                break;
            }
        }
        Some((u, t))
    }
}
