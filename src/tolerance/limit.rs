//! How far the tolerance band is from a limit position: the distance, in
//! units of the tolerances, from the nominal design to the nearest design
//! of the band whose cycle meets a singular pose.
//!
//! The measure of a pose is scale-free,
//!
//! ```text
//! q = (det Ψ_u / Π ‖Ψ_u eⱼ‖)²        sin²μ for a four-bar (μ its transmission angle)
//! ```
//!
//! 1 where the columns of Ψ_u are orthogonal, 0 at a singular pose. It is
//! squared because at a limit position (a fold of the closure equations)
//! det Ψ_u vanishes as the square root of the distance in the dimensions,
//! so that q, not √q, is linear in them there: the first-order change of
//! √q would put the limit twice as far as it is.
//!
//! Its total derivative by the dimensions, u moving with them at a fixed
//! driver (u_p = −Ψ_u⁻¹Ψ_p, which needs only Ψ_u to be invertible, not the
//! accuracy the sensitivities of velocities ask for), is evaluated on
//! dual numbers nested in dual numbers: Ψ_u's columns are Ψ's derivatives
//! along u, each carrying its gradient by p. Under tolerances ±tᵢ, q
//! moves by at most Σ |∂q/∂pᵢ| tᵢ; the distance is q over that, at the
//! pose of the cycle where it is smallest (the sweep's poses, then the
//! smallest refined between its neighbours). Below 1, some designs of the
//! band reach a limit position: they cannot be assembled over the whole
//! cycle, or they lock.

use super::{Spread, Tolerances, gradient, with_gradient};
use linkage_runtime::invert;
use linkage_runtime::{Options, Sensitivities, Sweep};
use nalgebra::SVector;
use num_dual::{Dual, DualNum, DualSVec64};

/// The margin of a cycle to the nearest limit position, at its worst pose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LimitMargin<const M: usize, const F: usize, const K: usize> {
    /// The driver at the worst pose.
    pub v: SVector<f64, F>,
    /// The pose there.
    pub u: SVector<f64, M>,
    /// q = (det Ψ_u / Π ‖Ψ_u eⱼ‖)² there ([`limit_measure`]).
    pub measure: f64,
    /// Its total derivative by the parameters at that driver.
    pub gradient: SVector<f64, K>,
    /// Its spread under the tolerances.
    pub spread: Spread,
    /// q / Σ |∂q/∂pᵢ| tᵢ: how many times the worst-case change of q the
    /// margin is (infinite where q does not depend on the dimensions).
    pub distance: f64,
}

impl<const M: usize, const F: usize, const K: usize> LimitMargin<M, F, K> {
    /// Whether the tolerance band reaches a limit position: distance < 1
    /// (or not known).
    pub fn reaches_limit(&self) -> bool {
        self.distance.is_nan() || self.distance < 1.0
    }

    /// The linear estimate of the fraction of designs that reach the limit
    /// at this pose: the probability that q falls below zero, q taken as
    /// normal with the linear σ (a sum of several dimensions' deviations
    /// is nearly normal).
    pub fn failing_fraction(&self) -> f64 {
        if self.spread.sigma > 0.0 {
            0.5 * erfc(self.measure / self.spread.sigma / std::f64::consts::SQRT_2)
        } else if self.measure > 0.0 {
            0.0
        } else {
            1.0
        }
    }
}

/// q = (det Ψ_u / Π ‖Ψ_u eⱼ‖)² at the pose (u, v) of `model`: 1 where the
/// columns of Ψ_u are orthogonal, 0 at a singular pose.
pub fn limit_measure<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
) -> f64
where
    L: Sensitivities<M, F, K>,
{
    measure(model, &model.params(), u, v)
}

/// The margin of the cycle `sweep` of `model` to the nearest limit
/// position under `tolerances` (see the module's documentation); `None`
/// if the sweep has no pose. Poses between the sweep's are solved with
/// `options`.
pub fn limit_margin<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    sweep: &Sweep<M, F>,
    tolerances: &Tolerances<K>,
    options: &Options,
) -> Option<LimitMargin<M, F, K>>
where
    L: Sensitivities<M, F, K>,
{
    let poses: Vec<_> = sweep.poses.iter().map(|p| (p.u, p.v)).collect();
    margin_along(model, &poses, tolerances, options)
}

/// [`limit_margin`] along the poses (u, v) of a sweep, in its order.
pub(super) fn margin_along<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    poses: &[(SVector<f64, M>, SVector<f64, F>)],
    tolerances: &Tolerances<K>,
    options: &Options,
) -> Option<LimitMargin<M, F, K>>
where
    L: Sensitivities<M, F, K>,
{
    let at = |u: &SVector<f64, M>, v: &SVector<f64, F>| margin_at(model, u, v, tolerances);
    let (k, worst) = poses
        .iter()
        .enumerate()
        .map(|(k, (u, v))| (k, at(u, v)))
        .min_by(|a, b| a.1.distance.total_cmp(&b.1.distance))?;
    let branch = |u: &SVector<f64, M>, v: &SVector<f64, F>| invert(&model.psi_u(u, v)).det > 0.0;
    let here = branch(&poses[k].0, &poses[k].1);
    // Golden-section search on the path through the neighbours, t in
    // [−1, 1]: t < 0 towards the pose before, t > 0 towards the one after.
    let side = |j: Option<usize>| {
        j.and_then(|j| poses.get(j))
            .filter(|(u, v)| branch(u, v) == here)
    };
    let (before, after) = (side(k.checked_sub(1)), side(Some(k + 1)));
    let trial = |t: f64| -> Option<LimitMargin<M, F, K>> {
        let (other, w) = if t < 0.0 { (before?, -t) } else { (after?, t) };
        let guess = poses[k].0 * (1.0 - w) + other.0 * w;
        let v = poses[k].1 * (1.0 - w) + other.1 * w;
        let u = model.solve_position(&guess, &v, options).ok()?.u;
        (branch(&u, &v) == here).then(|| at(&u, &v))
    };
    let distance = |t: f64| trial(t).map_or(f64::INFINITY, |m| m.distance);
    let (mut lo, mut hi) = (
        if before.is_some() { -1.0 } else { 0.0 },
        if after.is_some() { 1.0 } else { 0.0 },
    );
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
    let (mut da, mut db) = (distance(a), distance(b));
    for _ in 0..80 {
        if hi - lo <= 1e-12 {
            break;
        }
        if da < db {
            (hi, b, db) = (b, a, da);
            a = hi - ratio * (hi - lo);
            da = distance(a);
        } else {
            (lo, a, da) = (a, b, db);
            b = lo + ratio * (hi - lo);
            db = distance(b);
        }
    }
    let refined = trial(0.5 * (lo + hi)).filter(|m| m.distance < worst.distance);
    Some(refined.unwrap_or(worst))
}

/// The margin at one pose.
fn margin_at<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    tolerances: &Tolerances<K>,
) -> LimitMargin<M, F, K>
where
    L: Sensitivities<M, F, K>,
{
    let params = model.params();
    let q = match position_sensitivity(model, u, v) {
        Some(u_p) => {
            let u = SVector::from_fn(|i, _| with_gradient(u[i], u_p.row(i).transpose()));
            let p = SVector::from_fn(|i, _| with_gradient(params[i], unit(i)));
            measure::<L, DualSVec64<K>, M, F, K>(model, &p, &u, &v.map(DualSVec64::from_re))
        }
        // Ψ_u exactly singular: q = 0, its change unknown.
        None => with_gradient(0.0, SVector::repeat(f64::NAN)),
    };
    let g = gradient(&q);
    let spread = tolerances.spread(&g);
    let distance = if spread.worst_case > 0.0 {
        q.re / spread.worst_case
    } else if spread.worst_case == 0.0 && q.re > 0.0 {
        f64::INFINITY
    } else {
        f64::NAN
    };
    LimitMargin {
        v: *v,
        u: *u,
        measure: q.re,
        gradient: g,
        spread,
        distance: if distance.is_nan() { 0.0 } else { distance },
    }
}

/// u_p = −Ψ_u⁻¹Ψ_p at the pose (u, v), the driver fixed; `None` where
/// Ψ_u is exactly singular. Its accuracy is ε·κ, what the position has.
pub(super) fn position_sensitivity<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
) -> Option<nalgebra::SMatrix<f64, M, K>>
where
    L: Sensitivities<M, F, K>,
{
    let inverse = invert(&model.psi_u(u, v));
    (inverse.rcond > 0.0).then(|| -(inverse.inverse * model.psi_p(u, v)))
}

/// The unit vector along parameter `i`.
pub(super) fn unit<const K: usize>(i: usize) -> SVector<f64, K> {
    SVector::from_fn(|j, _| if j == i { 1.0 } else { 0.0 })
}

/// q on dual numbers D (which carry any derivatives of u, v and p): Ψ_u's
/// columns are the derivatives of Ψ along each uⱼ, on Dual<D>.
fn measure<L, D, const M: usize, const F: usize, const K: usize>(
    model: &L,
    params: &SVector<D, K>,
    u: &SVector<D, M>,
    v: &SVector<D, F>,
) -> D
where
    L: Sensitivities<M, F, K>,
    D: DualNum<Primitive = f64> + Copy,
{
    let zero = D::from(0.0);
    let lift = |x: &D| Dual::new(*x, zero);
    let (p, v) = (params.map(|x| lift(&x)), v.map(|x| lift(&x)));
    let mut columns = [[zero; M]; M];
    let mut norms = D::from(1.0);
    for (j, column) in columns.iter_mut().enumerate() {
        let u = SVector::<Dual<D>, M>::from_fn(|i, _| {
            Dual::new(u[i], D::from(if i == j { 1.0 } else { 0.0 }))
        });
        let psi = model.psi_generic_params(&p, &u, &v);
        let mut norm = zero;
        for (c, x) in column.iter_mut().zip(psi.iter()) {
            *c = x.eps;
            norm += x.eps * x.eps;
        }
        norms *= norm;
    }
    let det = determinant(columns);
    det * det / norms
}

/// The determinant of a small matrix on dual numbers, by elimination with
/// partial pivoting on the real parts.
fn determinant<D: DualNum<Primitive = f64> + Copy, const M: usize>(mut a: [[D; M]; M]) -> D {
    let mut det = D::from(1.0);
    for c in 0..M {
        let pivot = (c..M)
            .max_by(|&i, &j| a[i][c].re().abs().total_cmp(&a[j][c].re().abs()))
            .unwrap_or(c);
        if a[pivot][c].re() == 0.0 {
            return D::from(0.0);
        }
        if pivot != c {
            a.swap(pivot, c);
            det = -det;
        }
        det *= a[c][c];
        let (upper, lower) = a.split_at_mut(c + 1);
        let pivot_row = &upper[c];
        for row in lower.iter_mut() {
            let factor = row[c] / pivot_row[c];
            for (x, above) in row.iter_mut().zip(pivot_row).skip(c + 1) {
                *x -= factor * *above;
            }
        }
    }
    det
}

/// The complementary error function, to 1.2e-7 relative (Numerical
/// Recipes' erfcc, a Chebyshev fit).
fn erfc(x: f64) -> f64 {
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let poly = -z * z - 1.265_512_23
        + t * (1.000_023_68
            + t * (0.374_091_96
                + t * (0.096_784_18
                    + t * (-0.186_288_06
                        + t * (0.278_868_07
                            + t * (-1.135_203_98
                                + t * (1.488_515_87 + t * (-0.822_152_23 + t * 0.170_872_77))))))));
    let r = t * poly.exp();
    if x >= 0.0 { r } else { 2.0 - r }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn erfc_matches_known_values() {
        // erfc(0) = 1, erfc(1) = 0.157299207050285, erfc(−0.5) = 1.520499877813047.
        assert!((erfc(0.0) - 1.0).abs() < 2e-7);
        assert!((erfc(1.0) / 0.157_299_207_050_285 - 1.0).abs() < 2e-7);
        assert!((erfc(-0.5) / 1.520_499_877_813_047 - 1.0).abs() < 2e-7);
    }

    #[test]
    fn the_determinant_of_dual_matrices() {
        let d = |x: f64| DualSVec64::<1>::new(x, num_dual::Derivative::some(SVector::repeat(x)));
        // det [[0, 2, 1], [1, 1, 0], [3, 0, 1]] = 0·1 − 2·1 + 1·(−3) = −5, pivoting needed.
        let a = [[0.0, 2.0, 1.0], [1.0, 1.0, 0.0], [3.0, 0.0, 1.0]].map(|r| r.map(d));
        let det = determinant(a);
        assert!((det.re + 5.0).abs() < 1e-15);
        // Every entry scaled by (1 + ε): det scales by (1 + ε)³, so its ε-part is 3·det.
        assert!((gradient(&det)[0] + 15.0).abs() < 1e-14);
    }
}
