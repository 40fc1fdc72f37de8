//! Branch points: where two branches of the mechanism's motion cross and
//! [Ψ_u Ψ_t] loses rank. A sweep that reaches one locates it to rounding,
//! works out the two branches through it, and leaves it on the smooth
//! continuation of the branch it arrived on — whatever Newton would have
//! done near it, and wherever the grid falls.
//!
//! In floating point a branch point is fuzzy: within about √ε of it the two
//! crossing solutions cannot be told apart, and Newton at a driver value
//! there converges slowly to either, or to neither. So it is not found by
//! bisection on the path, which would have to evaluate poses inside that
//! zone, but as the regular solution of the extended system of the standard
//! bifurcation literature (Govaerts, *Numerical Methods for Bifurcations of
//! Dynamical Equilibria*, 2000, §4.2; the BP system of MATCONT), in the
//! unknowns x = (u, τ) (τ the distance along the path in driver units), a
//! scalar b and a unit vector ψ:
//!
//! ```text
//! Ψ(x) + b·ψ = 0        ψ: the left null vector of J = [Ψ_u Ψ_τ]
//!      Jᵀ·ψ = 0         b: the unfolding parameter, 0 at a true branch point
//!   ψᵀψ − 1 = 0
//! ```
//!
//! 2m + 2 equations in 2m + 2 unknowns, whose Jacobian is regular at a
//! simple branch point, so that Newton converges quadratically to it even
//! though Newton on Ψ alone does not. Its second derivatives, Σ ψᵢ∇²Ψᵢ, come
//! from the generic Ψ on hyper-dual numbers: exact. The crossing branches'
//! tangents are the two null directions of J on which the quadratic form
//! ψᵀ∇²Ψ[ξ, ξ] vanishes.

use super::state::{Passage, REGULAR_RCOND, State};
use super::tracker::Tracker;
use super::{Event, EventKind};
use crate::runtime::kernels::Kernels;
use crate::runtime::linalg::scaled_svd;
use nalgebra::{DMatrix, DVector, SVector};
use num_dual::HyperDual64;

/// Below this, [Ψ_u Ψ_v] is rank-deficient: a branch point.
pub(super) const BRANCH_RANK: f64 = 1e-6;

/// The most Newton iterations on the extended system (it converges
/// quadratically from the guesses a sweep gives it, in 3 to 6).
const MAX_ITERATIONS: usize = 40;

/// A branch point, located.
#[derive(Clone, Copy, Debug)]
pub(super) struct BranchPoint<const M: usize> {
    pub(super) u: SVector<f64, M>,
    /// The path parameter.
    pub(super) t: f64,
    /// du/dt along each of the two branches that cross there.
    pub(super) slopes: [SVector<f64, M>; 2],
    /// σ_min/σ_max of [Ψ_u Ψ_t] there.
    pub(super) rank_measure: f64,
}

impl<L: Kernels<M, F> + ?Sized, const M: usize, const F: usize> Tracker<'_, L, M, F> {
    /// σ_min/σ_max of [Ψ_u Ψ_τ]: about 0 at a branch point. A
    /// decomposition that fails (only for extreme numbers) is taken for
    /// rank-deficient: the cautious reading.
    pub(super) fn rank_measure(&self, u: &SVector<f64, M>, t: f64) -> f64 {
        let Some(svd) = scaled_svd(&self.path_jacobian(u, t), false) else {
            return 0.0;
        };
        let (max, min) = svd
            .singular_values
            .iter()
            .fold((0.0_f64, f64::INFINITY), |(a, b), &x| (a.max(x), b.min(x)));
        if max > 0.0 { min / max } else { 0.0 }
    }

    /// Σᵢ ψᵢ ∂²Ψᵢ/∂x∂x at x = (u, τ), exactly, from Ψ on hyper-dual numbers:
    /// (m + 1) × (m + 1).
    fn contracted_hessian(&self, u: &SVector<f64, M>, t: f64, psi: &DVector<f64>) -> DMatrix<f64> {
        let n = M + 1;
        let v = self.v(t);
        let along = self.dir / self.step_length;
        let mut hessian = DMatrix::zeros(n, n);
        for j in 0..n {
            for k in j..n {
                // Give x_j the ε₁ part and x_k the ε₂ part: the ε₁ε₂ part of Ψ is
                // ∂²Ψ/∂x_j∂x_k.
                let unit = |index: usize, c: usize| if index == c { 1.0 } else { 0.0 };
                let uh = SVector::<HyperDual64, M>::from_fn(|c, _| {
                    HyperDual64::new(u[c], unit(j, c), unit(k, c), 0.0)
                });
                let vh = SVector::<HyperDual64, F>::from_fn(|c, _| {
                    let e1 = if j == M { along[c] } else { 0.0 };
                    let e2 = if k == M { along[c] } else { 0.0 };
                    HyperDual64::new(v[c], e1, e2, 0.0)
                });
                let psi_h = self.model.psi_generic(&uh, &vh);
                let value: f64 = (0..M).map(|i| psi[i] * psi_h[i].eps1eps2).sum();
                hessian[(j, k)] = value;
                hessian[(k, j)] = value;
            }
        }
        hessian
    }

    /// The branch point nearest the guess (u, t), by Newton on the extended
    /// system (see the module's text); `None` if Newton does not converge,
    /// or converges to a point that is not a branch point of this mechanism
    /// (|b| above the residual tolerance: the nearest problem that has one
    /// differs from this one by more than the tolerance), or to one whose
    /// two branches do not cross transversally.
    pub(super) fn locate_branch_point(
        &self,
        guess_u: &SVector<f64, M>,
        guess_t: f64,
    ) -> Option<BranchPoint<M>> {
        let length = self.step_length;
        let n = M + 1;
        let size = 2 * M + 2;
        let (mut u, mut t) = (*guess_u, guess_t);
        // ψ: the left singular vector of J for its smallest singular value,
        // i.e. the right one of Jᵀ.
        let j = self.path_jacobian(&u, t);
        let svd = scaled_svd(&j.transpose(), true)?;
        let v_t = svd.v_t?;
        let smallest =
            (0..M).min_by(|&a, &b| svd.singular_values[a].total_cmp(&svd.singular_values[b]))?;
        let mut psi = DVector::from_fn(M, |i, _| v_t[(smallest, i)]);
        let residual = self.model.psi(&u, &self.v(t));
        let mut b = -(0..M).map(|i| psi[i] * residual[i]).sum::<f64>();
        let mut converged = false;
        for _ in 0..MAX_ITERATIONS {
            let h = self.model.psi(&u, &self.v(t));
            let j = self.path_jacobian(&u, t);
            let s = self.contracted_hessian(&u, t, &psi);
            let mut rhs = DVector::<f64>::zeros(size);
            let mut a = DMatrix::<f64>::zeros(size, size);
            let jt_psi = j.transpose() * &psi;
            for i in 0..M {
                rhs[i] = -(h[i] + b * psi[i]);
                for c in 0..n {
                    a[(i, c)] = j[(i, c)];
                }
                a[(i, n)] = psi[i];
                a[(i, n + 1 + i)] = b;
            }
            for r in 0..n {
                rhs[M + r] = -jt_psi[r];
                for c in 0..n {
                    a[(M + r, c)] = s[(r, c)];
                }
                for i in 0..M {
                    a[(M + r, n + 1 + i)] = j[(i, r)];
                }
            }
            rhs[size - 1] = -0.5 * (psi.dot(&psi) - 1.0);
            for i in 0..M {
                a[(size - 1, n + 1 + i)] = psi[i];
            }
            let step = a.lu().solve(&rhs)?;
            if !step.iter().all(|x| x.is_finite()) {
                return None;
            }
            for c in 0..M {
                u[c] += step[c];
            }
            t += step[M] / length;
            b += step[n];
            for i in 0..M {
                psi[i] += step[n + 1 + i];
            }
            let scale = u.amax().max((t * length).abs()).max(1.0);
            let moved = step.rows(0, n).amax();
            if moved <= 4.0 * f64::EPSILON * scale {
                converged = true;
                break;
            }
        }
        if !converged || !t.is_finite() || b.abs() > self.options.options.residual_tol {
            return None;
        }
        let rank_measure = self.rank_measure(&u, t);
        if rank_measure >= BRANCH_RANK {
            return None;
        }
        let psi = psi.normalize();
        let slopes = self.branch_slopes(&u, t, &psi)?;
        Some(BranchPoint {
            u,
            t,
            slopes,
            rank_measure,
        })
    }

    /// du/dt along the two branches through the branch point (u, t) with
    /// left null vector ψ: the null space of J is two-dimensional, and the
    /// branches' tangents are its directions ξ with ψᵀ∇²Ψ[ξ, ξ] = 0.
    fn branch_slopes(
        &self,
        u: &SVector<f64, M>,
        t: f64,
        psi: &DVector<f64>,
    ) -> Option<[SVector<f64, M>; 2]> {
        let n = M + 1;
        // The null space of J: the right singular vectors of J padded to a
        // square with a zero row, for its two smallest singular values.
        let j = self.path_jacobian(u, t);
        let padded = DMatrix::from_fn(n, n, |i, c| if i < M { j[(i, c)] } else { 0.0 });
        let svd = scaled_svd(&padded, true)?;
        let v_t = svd.v_t?;
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&a, &b| svd.singular_values[a].total_cmp(&svd.singular_values[b]));
        let basis = DMatrix::from_fn(n, 2, |i, k| v_t[(order[k], i)]);
        // The quadratic form on the null space: [[a, β], [β, c]].
        let q = basis.transpose() * self.contracted_hessian(u, t, psi) * &basis;
        let (a, beta, c) = (q[(0, 0)], 0.5 * (q[(0, 1)] + q[(1, 0)]), q[(1, 1)]);
        // a·cos²φ + 2β·cosφ·sinφ + c·sin²φ = ½(a + c) + R·cos(2φ − φ₀).
        let radius = (0.5 * (a - c)).hypot(beta);
        let mean = 0.5 * (a + c);
        let crossing = radius > 0.0 && mean.abs() < radius; // false for NaN too
        if !crossing {
            // The branches do not cross transversally (an isolated point, or
            // a degenerate crossing).
            return None;
        }
        let phase = beta.atan2(0.5 * (a - c));
        let opening = (-mean / radius).acos();
        let slope = |twice_phi: f64| -> SVector<f64, M> {
            let phi = 0.5 * twice_phi;
            let xi = &basis * nalgebra::Vector2::new(phi.cos(), phi.sin());
            // du/dτ = ξ_u/ξ_τ, and dτ/dt = |dir|.
            SVector::<f64, M>::from_fn(|i, _| xi[i] / xi[M] * self.step_length)
        };
        Some([slope(phase + opening), slope(phase - opening)])
    }

    /// Passes a branch point on the way from `before` (a regular state on
    /// the tracked branch) to the sub-step target `target`, located from the
    /// guess (u, t); `None` if there is no branch point there: ahead of
    /// `before`, and not beyond the target — or beyond it, but so close that
    /// the target is next to it (rcond below the regular threshold) — or if
    /// the tracked branch cannot be followed through it.
    ///
    /// The branch the sweep arrived on is the one of the two whose tangent at
    /// the branch point `before`'s analogs point to; its smooth continuation
    /// is left along that tangent (with `before`'s curvature), to the
    /// nearest distance where the pose is regular again and has the tangent
    /// of that branch rather than of the other.
    pub(super) fn pass_branch_point(
        &self,
        before: &State<M, F>,
        guess_u: &SVector<f64, M>,
        guess_t: f64,
        target: f64,
    ) -> Option<Passage<M, F>> {
        let travel = (target - before.t).signum();
        let bp = self.locate_branch_point(guess_u, guess_t)?;
        let ahead = (bp.t - before.t) * travel;
        let short_of_target = (target - bp.t) * travel;
        // rcond grows about linearly with the distance from the branch point:
        // below the regular threshold within `next_to` of it.
        let rcond_per_step = before.rcond / ahead;
        let next_to = REGULAR_RCOND / rcond_per_step;
        if !(ahead > 0.0 && short_of_target >= -next_to) {
            return None;
        }
        // The tangent `before` predicts at the branch point.
        let arriving = before.du + before.ddu * (bp.t - before.t);
        let distance = |slope: &SVector<f64, M>| (slope - arriving).amax();
        let (d0, d1) = (distance(&bp.slopes[0]), distance(&bp.slopes[1]));
        let (slope, other) = match (d0 < d1, d1 < d0) {
            (true, _) => (bp.slopes[0], bp.slopes[1]),
            (_, true) => (bp.slopes[1], bp.slopes[0]),
            _ => return None,
        };
        let curvature = before.ddu;
        let predict =
            |dt: f64| -> SVector<f64, M> { bp.u + slope * dt + curvature * (0.5 * dt * dt) };
        // Solved at `dt` from the branch point: closer to the arriving
        // branch's continuation than halfway to the other branch.
        let solve = |dt: f64| -> Option<State<M, F>> {
            let t = bp.t + dt;
            let guess = predict(dt);
            let (u, iterations) = self.correct(&guess, t).ok()?;
            let separation = ((slope - other) * dt).amax();
            let continuous = (u - guess).amax() <= 0.5 * separation + 1e-12 * u.amax().max(1.0);
            continuous.then(|| self.state(u, t, iterations))
        };
        // The distances tried: from where rcond should be a few times the
        // regular threshold, by factors of 4, with the target itself among
        // them, up to a step beyond the target.
        let floor = 1e-12 * bp.t.abs().max(1.0);
        let limit = short_of_target.max(1.0);
        let mut reach = (4.0 * next_to).min(short_of_target).max(floor);
        let beyond = loop {
            let within_limit = reach <= limit; // false for NaN too
            if !within_limit {
                return None;
            }
            let dt = reach * travel;
            if let Some(state) = solve(dt) {
                let on_branch =
                    (state.du - (slope + curvature * dt)).amax() < (state.du - other).amax();
                if state.rcond >= REGULAR_RCOND && on_branch {
                    break state;
                }
            }
            let next = reach * 4.0;
            reach = if reach < short_of_target && next > short_of_target {
                short_of_target
            } else {
                next
            };
        };
        // A target short of the regular state beyond the branch point lies
        // next to it, where the branches can hardly be told apart: its pose
        // comes from the smooth continuation, or, where Newton cannot
        // resolve it, is the continuation's prediction, never recorded.
        // Short of the branch point itself it is never recorded either: the
        // event, reported with this sub-step, would otherwise come before it.
        let at_target = ((beyond.t - target) * travel > 0.0).then(|| {
            let dt = target - bp.t;
            match solve(dt) {
                Some(state) if dt * travel >= 0.0 => state,
                Some(state) => State {
                    solved: false,
                    ..state
                },
                None => State::unresolved(predict(dt), target),
            }
        });
        Some(Passage {
            event: Event {
                kind: EventKind::BranchPoint,
                v: self.v(bp.t),
                u: bp.u,
                t: bp.t,
                after: 0,
                rank_measure: bp.rank_measure,
            },
            beyond,
            at_target,
        })
    }
}
