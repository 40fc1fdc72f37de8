//! Limit positions: where the driver cannot go on (det Ψ_u = 0 with
//! [Ψ_u Ψ_v] of full rank), located exactly, and the mirror pose on the
//! other branch from which a rocking drive goes back.

use super::bordered::Border;
use super::state::State;
use super::tracker::Tracker;
use crate::runtime::kernels::Kernels;
use crate::runtime::linalg::determinant;
use crate::runtime::sources;
use nalgebra::{DMatrix, SVector};

impl<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize> Tracker<'_, L, M, F> {
    /// det Ψ_u relative to the product of its column norms (|·| ≤ 1).
    pub(super) fn normalized_det(&self, u: &SVector<f64, M>, t: f64) -> f64 {
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
    pub(super) fn locate_limit(&self, near: &State<M, F>) -> Option<(SVector<f64, M>, f64)> {
        // det Ψ_u's row: its gradient in (u, t) by central differences.
        let det_row = |u: &SVector<f64, M>, t: f64| -> Border<M> {
            let u = *u;
            let derivative = |j: usize| {
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
                (self.normalized_det(&up, tp) - self.normalized_det(&um, tm)) / (2.0 * h)
            };
            let gradient_u = SVector::<f64, M>::from_fn(|j, _| derivative(j));
            (gradient_u, derivative(M), -self.normalized_det(&u, t))
        };
        let (u, t) = self.bordered_newton(&near.u, near.t, det_row)?;
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
    pub(super) fn mirror(
        &self,
        limit_u: &SVector<f64, M>,
        limit_t: f64,
        came_from: &State<M, F>,
    ) -> Option<State<M, F>> {
        let v = self.v(limit_t);
        let psi_u =
            sources::psi_and_psi_u(self.model, self.options.options.jacobian, limit_u, &v).1;
        let dyn_u = DMatrix::<f64>::from_fn(M, M, |i, j| psi_u[(i, j)]);
        let svd = crate::runtime::linalg::scaled_svd(&dyn_u, true)?;
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
        let held = |u: &SVector<f64, M>, _t: f64| -> Border<M> {
            (null, 0.0, target - null.dot(&(u - limit_u)))
        };
        let (u, t) = self.bordered_newton(&(limit_u - null * s), came_from.t, held)?;
        let (u, iterations) = self.correct(&u, t).ok()?;
        let state = self.state(u, t, iterations);
        (state.det.signum() != came_from.det.signum()).then_some(state)
    }
}
