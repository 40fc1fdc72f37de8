//! The sensitivities at a pose in motion, from the generated terms:
//! differentiating Ψ_u u_p + Ψ_p = 0 in time twice (Leibniz) gives
//!
//! ```text
//! u_p = −Ψ_u⁻¹ Ψ_p
//! u̇_p = −Ψ_u⁻¹ (Ψ̇_u u_p + Ψ̇_p)
//! ü_p = −Ψ_u⁻¹ (Ψ̈_u u_p + 2 Ψ̇_u u̇_p + Ψ̈_p)
//! ```
//!
//! and each point likewise:
//!
//! ```text
//! dP/dp = P_u u_p + P_p
//! dṖ/dp = Ṗ_u u_p + P_u u̇_p + Ṗ_p
//! dP̈/dp = P̈_u u_p + 2 Ṗ_u u̇_p + P_u ü_p + P̈_p
//! ```
//!
//! (The time derivative of u_p is the derivative by p of u̇, the driver's
//! motion being independent of p.)

use super::Sensitivities;
use super::results::{Motion, Sensitivity, SensitivityTerms};
use crate::checks::{check_input, check_value};
use crate::error::{Error, Stage};
use crate::linalg::factor;
use crate::options::Options;
use nalgebra::Vector2;

/// [`Sensitivities::sensitivities`]: the inputs checked, the terms
/// generated, Ψ_u factored with the conditioning the sensitivities need,
/// then [`from_terms`].
pub(crate) fn sensitivities<
    L: Sensitivities<M, F, K> + ?Sized,
    const M: usize,
    const F: usize,
    const K: usize,
>(
    model: &L,
    motion: &Motion<M, F>,
    options: &Options,
) -> Result<Sensitivity<M, K, L::Points>, Error> {
    for (name, values) in [
        ("u", motion.u.as_slice()),
        ("udot", motion.udot.as_slice()),
        ("uddot", motion.uddot.as_slice()),
    ] {
        check_input(name, values)?;
    }
    for (name, values) in [
        ("v", motion.v.as_slice()),
        ("vdot", motion.vdot.as_slice()),
        ("vddot", motion.vddot.as_slice()),
    ] {
        check_input(name, values)?;
    }
    options.check()?;
    let terms = model.sensitivity_terms(
        &motion.u,
        &motion.v,
        &motion.udot,
        &motion.vdot,
        &motion.uddot,
        &motion.vddot,
    );
    from_terms(&terms, options)
}

/// The sensitivities from the generated terms at a pose: `Singular` where
/// Ψ_u is too ill-conditioned for them to keep [`Options::accuracy`],
/// `NonFiniteValue` where a term or a result is not finite.
pub(crate) fn from_terms<const M: usize, const K: usize, P>(
    terms: &SensitivityTerms<M, K, P>,
    options: &Options,
) -> Result<Sensitivity<M, K, P>, Error>
where
    P: Copy + AsRef<[Vector2<f64>]> + AsMut<[Vector2<f64>]>,
{
    let stage = Stage::Sensitivity;
    for (quantity, values) in [
        ("Ψ_u", terms.psi_u.as_slice()),
        ("Ψ_p", terms.psi_p.as_slice()),
        ("Ψ̇_u", terms.psi_u_dot.as_slice()),
        ("Ψ̇_p", terms.psi_p_dot.as_slice()),
        ("Ψ̈_u", terms.psi_u_ddot.as_slice()),
        ("Ψ̈_p", terms.psi_p_ddot.as_slice()),
    ] {
        check_value(stage, quantity, values)?;
    }
    let inv = factor(&terms.psi_u, stage, options)?;
    let inverse = &inv.inverse;
    let u = -(inverse * terms.psi_p);
    let udot = -(inverse * (terms.psi_u_dot * u + terms.psi_p_dot));
    let uddot =
        -(inverse * (terms.psi_u_ddot * u + terms.psi_u_dot * udot * 2.0 + terms.psi_p_ddot));
    for (quantity, values) in [
        ("u_p", u.as_slice()),
        ("u̇_p", udot.as_slice()),
        ("ü_p", uddot.as_slice()),
    ] {
        check_value(stage, quantity, values)?;
    }
    let mut points = terms.points_p;
    let mut point_velocities = terms.point_velocities_p;
    let mut point_accelerations = terms.point_accelerations_p;
    for j in 0..K {
        for i in 0..M {
            accumulate(&mut points[j], &terms.points_u[i], u[(i, j)]);
            accumulate(
                &mut point_velocities[j],
                &terms.point_velocities_u[i],
                u[(i, j)],
            );
            accumulate(&mut point_velocities[j], &terms.points_u[i], udot[(i, j)]);
            accumulate(
                &mut point_accelerations[j],
                &terms.point_accelerations_u[i],
                u[(i, j)],
            );
            accumulate(
                &mut point_accelerations[j],
                &terms.point_velocities_u[i],
                2.0 * udot[(i, j)],
            );
            accumulate(
                &mut point_accelerations[j],
                &terms.points_u[i],
                uddot[(i, j)],
            );
        }
    }
    for (quantity, columns) in [
        ("dP/dp", &points),
        ("dṖ/dp", &point_velocities),
        ("dP̈/dp", &point_accelerations),
    ] {
        let finite = columns
            .iter()
            .all(|c| c.as_ref().iter().all(|x| x.iter().all(|v| v.is_finite())));
        if !finite {
            return Err(Error::NonFiniteValue { stage, quantity });
        }
    }
    Ok(Sensitivity {
        u,
        udot,
        uddot,
        points,
        point_velocities,
        point_accelerations,
        rcond: inv.rcond,
    })
}

/// `target += scale · source`, point by point.
#[inline(always)]
fn accumulate<P: AsRef<[Vector2<f64>]> + AsMut<[Vector2<f64>]>>(
    target: &mut P,
    source: &P,
    scale: f64,
) {
    for (t, s) in target.as_mut().iter_mut().zip(source.as_ref()) {
        *t += s * scale;
    }
}
