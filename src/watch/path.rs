//! The pose along a drive with its derivatives: where the solution path
//! u(s) of Ψ(u(s), v(s)) = 0 goes as the driver moves along a direction e,
//! v(s) = v + s·e, to third order, and every quantity of the pose as a
//! dual number that carries its rate along the drive.
//!
//! The derivatives come from implicit differentiation, one order at a time,
//! on num-dual's third-order numbers: with u′ … u⁽ᵏ⁻¹⁾ known and u⁽ᵏ⁾ set to
//! 0, the k-th derivative of Ψ(u(s), v(s)) is everything but Ψ_u u⁽ᵏ⁾, so
//! u⁽ᵏ⁾ = −Ψ_u⁻¹ (that k-th derivative). Three evaluations of the generated
//! `psi_generic` give u′, u″, u‴, exact to rounding for any mechanism.

use crate::quantity::Pose;
use crate::runtime::{Factors, Linkage};
use nalgebra::{SVector, Vector2};
use num_dual::{Dual3_64, Dual64};

/// One pose of a drive at constant driver speed σ, each number with its
/// rate of change per unit of driver travel along the drive's direction:
/// `x.re` is the value, `x.eps` its derivative d/ds.
///
/// The velocities and accelerations are for the driver moving at the
/// sweep's speed σ with no driver acceleration: u̇ = u′σ, ü = u″σ²
/// (and so d/ds u̇ = u″σ, d/ds ü = u‴σ²), as in the sweep's poses; `vddot`
/// is zero.
pub type PathPose<const M: usize, const F: usize> = Pose<Dual64, M, F>;

/// Whether every number of the pose is finite.
pub(super) fn is_finite<const M: usize, const F: usize>(pose: &PathPose<M, F>) -> bool {
    let duals = pose
        .v
        .iter()
        .chain(&pose.vdot)
        .chain(&pose.vddot)
        .chain(&pose.u)
        .chain(&pose.udot)
        .chain(&pose.uddot);
    let points = pose
        .points
        .iter()
        .chain(&pose.point_velocities)
        .chain(&pose.point_accelerations)
        .flat_map(|p| p.iter());
    duals
        .chain(points)
        .all(|x| x.re.is_finite() && x.eps.is_finite())
}

/// The pose (u, v) of `model`, a solution of Ψ = 0 with Ψ_u factored in
/// `factors`, moving along the unit driver direction `direction` at
/// `speed`.
pub(super) fn path_pose<L: Linkage<M, F>, const M: usize, const F: usize>(
    model: &L,
    u: &SVector<f64, M>,
    v: &SVector<f64, F>,
    direction: &SVector<f64, F>,
    speed: f64,
    factors: &Factors<M>,
) -> PathPose<M, F> {
    let vj = SVector::<Dual3_64, F>::from_fn(|i, _| Dual3_64::new(v[i], direction[i], 0.0, 0.0));
    // d[k] = u⁽ᵏ⁾, the higher ones 0 until computed.
    let mut d = [SVector::<f64, M>::zeros(); 4];
    d[0] = *u;
    let jet = |d: &[SVector<f64, M>; 4]| {
        SVector::<Dual3_64, M>::from_fn(|i, _| Dual3_64::new(d[0][i], d[1][i], d[2][i], d[3][i]))
    };
    for k in 1..=3 {
        let residual = model.psi_generic(&jet(&d), &vj);
        let kth = residual.map(|x| [x.v1, x.v2, x.v3][k - 1]);
        d[k] = -factors.solve(&kth);
    }
    let s = speed;
    let dual = |re: f64, eps: f64| Dual64::new(re, eps);
    let coordinates = |order: usize, scale: f64| {
        SVector::<Dual64, M>::from_fn(|i, _| dual(d[order][i] * scale, d[order + 1][i] * scale))
    };
    let path = jet(&d);
    let p = model.point_positions_generic(&path, &vj);
    let p = p.as_ref();
    let points = |f: &dyn Fn(&Dual3_64) -> Dual64| -> Vec<Vector2<Dual64>> {
        p.iter().map(|q| Vector2::new(f(&q.x), f(&q.y))).collect()
    };
    PathPose {
        v: SVector::from_fn(|i, _| dual(v[i], direction[i])),
        vdot: SVector::from_fn(|i, _| dual(direction[i] * s, 0.0)),
        vddot: SVector::from_element(Dual64::from(0.0)),
        u: coordinates(0, 1.0),
        udot: coordinates(1, s),
        uddot: coordinates(2, s * s),
        points: points(&|x| dual(x.re, x.v1)),
        point_velocities: points(&|x| dual(x.v1 * s, x.v2 * s)),
        point_accelerations: points(&|x| dual(x.v2 * s * s, x.v3 * s * s)),
        names: model.point_names(),
    }
}
