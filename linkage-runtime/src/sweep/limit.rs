//! Limit positions: where the driver cannot go on (det Ψ_u = 0 with
//! [Ψ_u Ψ_v] of full rank), located exactly, and the mirror pose on the
//! other branch from which a rocking drive goes back.

use super::tracker::{State, Tracker};
use crate::linalg::determinant;
use crate::linkage::Linkage;
use crate::sources;
use nalgebra::{DMatrix, DVector, SVector};

impl<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize> Tracker<'_, L, M, F> {
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
}
