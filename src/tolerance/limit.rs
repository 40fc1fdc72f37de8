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

use super::{Spread, Tolerances, distance, gradient, with_gradient};
use crate::numerics::minimize;
use crate::runtime::{Factors, Options, Sensitivities, Sweep, determinant};
use nalgebra::{ComplexField, DMatrix, SMatrix, SVector};
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
    /// margin is (infinite where q does not depend on the dimensions, 0
    /// where its change is not known: Ψ_u exactly singular).
    pub distance: f64,
}

impl<const M: usize, const F: usize, const K: usize> LimitMargin<M, F, K> {
    /// Whether the tolerance band reaches a limit position: distance < 1
    /// (which includes a change not known, distance 0).
    pub fn reaches_limit(&self) -> bool {
        self.distance < 1.0
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
    let mut worst = WorstPose::default();
    for pose in &sweep.poses {
        worst.push(model, &pose.u, &pose.v, None, tolerances);
    }
    worst.refine(model, tolerances, options)
}

/// A pose (u, v).
type Pose<const M: usize, const F: usize> = (SVector<f64, M>, SVector<f64, F>);

/// The worst pose of a sweep so far, pose by pose in its order, with its
/// neighbours: [`limit_margin`] as the sweep goes.
pub(super) struct WorstPose<const M: usize, const F: usize, const K: usize> {
    /// The pose before the one pushed next.
    previous: Option<Pose<M, F>>,
    /// The smallest margin (the first of equals), the pose before it and
    /// the pose after it.
    worst: Option<(LimitMargin<M, F, K>, Option<Pose<M, F>>, Option<Pose<M, F>>)>,
}

impl<const M: usize, const F: usize, const K: usize> Default for WorstPose<M, F, K> {
    fn default() -> Self {
        WorstPose {
            previous: None,
            worst: None,
        }
    }
}

impl<const M: usize, const F: usize, const K: usize> WorstPose<M, F, K> {
    /// The next pose (u, v) of the sweep, with u_p there if it is known
    /// (a sweep's sensitivities), else computed here.
    pub(super) fn push<L>(
        &mut self,
        model: &L,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        u_p: Option<&SMatrix<f64, M, K>>,
        tolerances: &Tolerances<K>,
    ) where
        L: Sensitivities<M, F, K>,
    {
        let u_p = u_p.copied().or_else(|| position_sensitivity(model, u, v));
        let margin = margin_at(model, u, v, u_p.as_ref(), tolerances);
        // The pose after the worst so far, if the worst was the last.
        if let Some((_, _, after)) = &mut self.worst
            && after.is_none()
        {
            *after = Some((*u, *v));
        }
        let previous = self.previous.replace((*u, *v));
        match &self.worst {
            Some((worst, _, _)) if margin.distance >= worst.distance => {}
            _ => self.worst = Some((margin, previous, None)),
        }
    }

    /// The smallest margin, refined between the neighbours of the worst
    /// pose (on its branch) by Brent's method along the straight path
    /// through them, poses solved with `options`; `None` if no pose was
    /// pushed.
    pub(super) fn refine<L>(
        self,
        model: &L,
        tolerances: &Tolerances<K>,
        options: &Options,
    ) -> Option<LimitMargin<M, F, K>>
    where
        L: Sensitivities<M, F, K>,
    {
        let (worst, before, after) = self.worst?;
        let branch =
            |u: &SVector<f64, M>, v: &SVector<f64, F>| determinant(&model.psi_u(u, v)) > 0.0;
        let here = branch(&worst.u, &worst.v);
        let side = |pose: Option<Pose<M, F>>| pose.filter(|(u, v)| branch(u, v) == here);
        let (before, after) = (side(before), side(after));
        // t in [−1, 1]: t < 0 towards the pose before, t > 0 towards the
        // one after.
        let mut best = worst;
        let mut distance = |t: f64| -> Result<f64, std::convert::Infallible> {
            let towards = if t < 0.0 {
                before.map(|p| (p, -t))
            } else {
                after.map(|p| (p, t))
            };
            let Some(((u_other, v_other), w)) = towards else {
                return Ok(f64::INFINITY);
            };
            let guess = worst.u * (1.0 - w) + u_other * w;
            let v = worst.v * (1.0 - w) + v_other * w;
            let Ok(solved) = model.solve_position(&guess, &v, options) else {
                return Ok(f64::INFINITY);
            };
            if branch(&solved.u, &v) != here {
                return Ok(f64::INFINITY);
            }
            let u_p = position_sensitivity(model, &solved.u, &v);
            let margin = margin_at(model, &solved.u, &v, u_p.as_ref(), tolerances);
            if margin.distance < best.distance {
                best = margin;
            }
            Ok(margin.distance)
        };
        let lo = if before.is_some() { -1.0 } else { 0.0 };
        let hi = if after.is_some() { 1.0 } else { 0.0 };
        // The minimum is flat (quadratic): t to √ε, beyond which the
        // distance no longer changes in f64.
        let Ok(_) = minimize(&mut distance, lo, hi, f64::EPSILON.sqrt());
        Some(best)
    }
}

/// The margin at one pose, u_p = −Ψ_u⁻¹Ψ_p there (`None` where Ψ_u is
/// exactly singular: q = 0, its change unknown).
fn margin_at<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    u_p: Option<&SMatrix<f64, M, K>>,
    tolerances: &Tolerances<K>,
) -> LimitMargin<M, F, K>
where
    L: Sensitivities<M, F, K>,
{
    let q = match u_p {
        Some(u_p) => {
            let (p, u) = moving_with_params(model, u, u_p);
            measure::<L, DualSVec64<K>, M, F, K>(model, &p, &u, &v.map(DualSVec64::from_re))
        }
        None => with_gradient(0.0, SVector::repeat(f64::NAN)),
    };
    let g = gradient(&q);
    let spread = tolerances.spread(&g);
    LimitMargin {
        v: *v,
        u: *u,
        measure: q.re,
        gradient: g,
        spread,
        distance: distance(q.re, &spread),
    }
}

/// u_p = −Ψ_u⁻¹Ψ_p at the pose (u, v), the driver fixed; `None` where
/// Ψ_u is exactly singular. Its accuracy is ε·κ, what the position has.
pub(super) fn position_sensitivity<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
) -> Option<SMatrix<f64, M, K>>
where
    L: Sensitivities<M, F, K>,
{
    let factors = Factors::of(&model.psi_u(u, v), model.psi_u_blocks());
    (factors.rcond() > 0.0).then(|| -factors.solve_columns(&model.psi_p(u, v)))
}

/// The parameters p and the pose u on dual numbers carrying their
/// gradients by p, u moving with them at a fixed driver (`u_p`, from
/// [`position_sensitivity`] or a sweep's sensitivities).
pub(super) fn moving_with_params<L, const M: usize, const F: usize, const K: usize>(
    model: &L,
    u: &SVector<f64, M>,
    u_p: &SMatrix<f64, M, K>,
) -> (SVector<DualSVec64<K>, K>, SVector<DualSVec64<K>, M>)
where
    L: Sensitivities<M, F, K>,
{
    // (SVector::ith needs a typenum for K; the identity's columns do not.)
    let (params, identity) = (model.params(), SMatrix::<f64, K, K>::identity());
    let p = SVector::from_fn(|i, _| with_gradient(params[i], identity.column(i).into_owned()));
    let u = SVector::from_fn(|i, _| with_gradient(u[i], u_p.row(i).transpose()));
    (p, u)
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
    D: DualNum<Primitive = f64> + ComplexField + Copy,
{
    let zero = D::from(0.0);
    let lift = |x: &D| Dual::new(*x, zero);
    let (p, v) = (params.map(|x| lift(&x)), v.map(|x| lift(&x)));
    // Dynamically sized: nalgebra's determinant needs a typenum for a
    // const size, which a generic M has not.
    let mut psi_u = DMatrix::<D>::from_element(M, M, zero);
    let mut norms = D::from(1.0);
    for j in 0..M {
        let u = SVector::<Dual<D>, M>::from_fn(|i, _| {
            Dual::new(u[i], D::from(if i == j { 1.0 } else { 0.0 }))
        });
        let psi = model.psi_generic_params(&p, &u, &v);
        let mut norm = zero;
        for (i, x) in psi.iter().enumerate() {
            psi_u[(i, j)] = x.eps;
            norm += x.eps * x.eps;
        }
        norms *= norm;
    }
    let det = psi_u.determinant();
    det * det / norms
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
        // det [[0, 2, 1], [1, 1, 0], [3, 0, 1]] = 0·1 − 2·1 + 1·(−3) = −5.
        let a = SMatrix::<f64, 3, 3>::new(0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 3.0, 0.0, 1.0);
        assert_eq!(a.map(d).determinant().re, -5.0);
        // Every entry scaled by (1 + ε): det scales by (1 + ε)³, so its ε-part is 3·det.
        assert_eq!(gradient(&a.map(d).determinant())[0], -15.0);
        // Four by four, by nalgebra's LU with pivoting (a zero first pivot):
        // det = −(1·2·3·4) after swapping the first two rows of diag(…).
        let b = SMatrix::<f64, 4, 4>::new(
            0.0, 2.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 4.0,
        );
        let det = b.map(d).determinant();
        assert!((det.re + 24.0).abs() < 1e-13 && (gradient(&det)[0] + 96.0).abs() < 1e-12);
    }
}
