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
//!
//! With X₀, X₁, X₂ = Ψ_u⁻¹ Ψ_p, Ψ_u⁻¹ Ψ̇_p, Ψ_u⁻¹ Ψ̈_p and the m × m
//! A = Ψ_u⁻¹ Ψ̇_u, B = Ψ_u⁻¹ Ψ̈_u, the same three read
//!
//! ```text
//! u_p = −X₀
//! u̇_p = A X₀ − X₁
//! ü_p = B X₀ − 2A u̇_p − X₂
//! ```
//!
//! which is how they are computed for m ≤ 3: the five products by Ψ_u⁻¹ do
//! not wait for one another, and the chain from Ψ_u⁻¹ to ü_p is three
//! products long instead of five (a four-bar's sensitivities at k = 4:
//! 108 → 88 ns, best of 5, 2026-11-23). For larger m the 2m³
//! multiplications of A and B cost more than the wait saves (the six-bar's
//! at k = 10: 692 ns in sequence against 860 ns), and the formulas are
//! computed as they read.

use super::Sensitivities;
use super::results::{Motion, Sensitivity, SensitivityTerms};
use crate::checks::{all_finite, check_input, check_value};
use crate::error::{Error, Stage};
use crate::linalg::factor;
use crate::options::Options;
use nalgebra::{SMatrix, Vector2};

/// [`Sensitivities::sensitivities`]: the inputs checked, the terms
/// generated, Ψ_u factored with the conditioning the sensitivities need,
/// then [`from_terms`].
#[inline(always)]
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
    // One pass over every number, and the arguments one by one (for the
    // error naming the first that is not finite) only if that fails.
    let finite = all_finite(motion.u.as_slice())
        & all_finite(motion.udot.as_slice())
        & all_finite(motion.uddot.as_slice())
        & all_finite(motion.v.as_slice())
        & all_finite(motion.vdot.as_slice())
        & all_finite(motion.vddot.as_slice());
    if !finite {
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
#[inline(always)]
pub(crate) fn from_terms<const M: usize, const K: usize, P>(
    terms: &SensitivityTerms<M, K, P>,
    options: &Options,
) -> Result<Sensitivity<M, K, P>, Error>
where
    P: Copy + AsRef<[Vector2<f64>]> + AsMut<[Vector2<f64>]>,
{
    let stage = Stage::Sensitivity;
    // The terms are not scanned up front: a NaN or an infinity in any of
    // them reaches u_p, u̇_p or ü_p (IEEE: ∞·0 is NaN, and Ψ_u's makes the
    // inverse fail), so only a failure scans them, in order, to name the
    // first — the errors of a scan up front, for one pass less.
    let inv = match factor(&terms.psi_u, stage, options) {
        Ok(inv) => inv,
        Err(singular) => {
            name_non_finite_term(*terms)?;
            return Err(singular);
        }
    };
    let (u, udot, uddot) = if M <= 3 {
        by_products_first(&inv.inverse, terms)
    } else {
        in_sequence(&inv.inverse, terms)
    };
    let finite =
        all_finite(u.as_slice()) & all_finite(udot.as_slice()) & all_finite(uddot.as_slice());
    if !finite {
        name_non_finite_term(*terms)?;
        for (quantity, values) in [
            ("u_p", u.as_slice()),
            ("u̇_p", udot.as_slice()),
            ("ü_p", uddot.as_slice()),
        ] {
            check_value(stage, quantity, values)?;
        }
    }
    // The result assembled first and its points summed where they lie
    // (no copies of them in between): each sum starts from the explicit
    // P_p, Ṗ_p or P̈_p, then, point by point, adds the terms of each
    // coordinate in turn, skipping a coordinate the point does not move with
    // (its P_u, Ṗ_u and P̈_u zero there: the crank pin by the coupler's
    // angle, say), which adds nothing.
    let mut out = Sensitivity {
        u,
        udot,
        uddot,
        points: terms.points_p,
        point_velocities: terms.point_velocities_p,
        point_accelerations: terms.point_accelerations_p,
        rcond: inv.rcond,
    };
    let count = terms.points_p.first().map_or(0, |p| p.as_ref().len());
    let zero = Vector2::zeros();
    for c in 0..count {
        for i in 0..M {
            let p_u = terms.points_u[i].as_ref()[c];
            let v_u = terms.point_velocities_u[i].as_ref()[c];
            let a_u = terms.point_accelerations_u[i].as_ref()[c];
            // (A NaN is not zero: it is added, and caught below.)
            if p_u == zero && v_u == zero && a_u == zero {
                continue;
            }
            for j in 0..K {
                let (x, x_dot, x_ddot) = (u[(i, j)], udot[(i, j)], uddot[(i, j)]);
                out.points[j].as_mut()[c] += p_u * x;
                let v = &mut out.point_velocities[j].as_mut()[c];
                *v += v_u * x;
                *v += p_u * x_dot;
                let a = &mut out.point_accelerations[j].as_mut()[c];
                *a += a_u * x;
                *a += v_u * (2.0 * x_dot);
                *a += p_u * x_ddot;
            }
        }
    }
    let finite = points_finite(&out.points)
        & points_finite(&out.point_velocities)
        & points_finite(&out.point_accelerations);
    if !finite {
        for (quantity, columns) in [
            ("dP/dp", &out.points),
            ("dṖ/dp", &out.point_velocities),
            ("dP̈/dp", &out.point_accelerations),
        ] {
            if !points_finite(columns) {
                return Err(Error::NonFiniteValue { stage, quantity });
            }
        }
    }
    Ok(out)
}

/// u_p, u̇_p, ü_p with the products by Ψ_u⁻¹ first (see the module's
/// documentation): the five do not wait for one another, and the chain from
/// Ψ_u⁻¹ to ü_p is three products long; 2A is exact.
#[inline(always)]
fn by_products_first<const M: usize, const K: usize, P>(
    inverse: &SMatrix<f64, M, M>,
    terms: &SensitivityTerms<M, K, P>,
) -> (SMatrix<f64, M, K>, SMatrix<f64, M, K>, SMatrix<f64, M, K>) {
    let a = product(inverse, &terms.psi_u_dot);
    let b = product(inverse, &terms.psi_u_ddot);
    let x0 = product(inverse, &terms.psi_p);
    let x1 = product(inverse, &terms.psi_p_dot);
    let x2 = product(inverse, &terms.psi_p_ddot);
    let udot = product(&a, &x0) - x1;
    let uddot = product(&b, &x0) - product(&(a * 2.0), &udot) - x2;
    (-x0, udot, uddot)
}

/// u_p, u̇_p, ü_p as the formulas read, each solve waiting for the one
/// before: 2m³ multiplications fewer than [`by_products_first`].
#[inline(always)]
fn in_sequence<const M: usize, const K: usize, P>(
    inverse: &SMatrix<f64, M, M>,
    terms: &SensitivityTerms<M, K, P>,
) -> (SMatrix<f64, M, K>, SMatrix<f64, M, K>, SMatrix<f64, M, K>) {
    let minus_inverse = -inverse;
    let u = product(&minus_inverse, &terms.psi_p);
    let udot = product(
        &minus_inverse,
        &(product(&terms.psi_u_dot, &u) + terms.psi_p_dot),
    );
    let twice = product(&terms.psi_u_dot, &udot) * 2.0;
    let uddot = product(
        &minus_inverse,
        &(product(&terms.psi_u_ddot, &u) + twice + terms.psi_p_ddot),
    );
    (u, udot, uddot)
}

/// `NonFiniteValue` naming the first of the matrix terms that is not
/// finite, in their order; `Ok` if all are.
#[cold]
fn name_non_finite_term<const M: usize, const K: usize, P>(
    terms: SensitivityTerms<M, K, P>,
) -> Result<(), Error> {
    for (quantity, values) in [
        ("Ψ_u", terms.psi_u.as_slice()),
        ("Ψ_p", terms.psi_p.as_slice()),
        ("Ψ̇_u", terms.psi_u_dot.as_slice()),
        ("Ψ̇_p", terms.psi_p_dot.as_slice()),
        ("Ψ̈_u", terms.psi_u_ddot.as_slice()),
        ("Ψ̈_p", terms.psi_p_ddot.as_slice()),
    ] {
        check_value(Stage::Sensitivity, quantity, values)?;
    }
    Ok(())
}

/// Whether every coordinate of every point of every column is finite,
/// without a branch per number.
#[inline(always)]
fn points_finite<const K: usize, P: AsRef<[Vector2<f64>]>>(columns: &[P; K]) -> bool {
    let mut finite = true;
    for column in columns {
        for point in column.as_ref() {
            finite &= point.x.is_finite() & point.y.is_finite();
        }
    }
    finite
}

/// The product a·b on fixed sizes, each entry summed in the order of
/// nalgebra's (over k = 0, 1, …), in loops the compiler unrolls and
/// vectorises down the columns.
#[inline(always)]
fn product<const R: usize, const N: usize, const C: usize>(
    a: &SMatrix<f64, R, N>,
    b: &SMatrix<f64, N, C>,
) -> SMatrix<f64, R, C> {
    let mut out = SMatrix::<f64, R, C>::zeros();
    for j in 0..C {
        for k in 0..N {
            let scale = b[(k, j)];
            for i in 0..R {
                out[(i, j)] += a[(i, k)] * scale;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Matrix2, Vector2};

    type Points = [Vector2<f64>; 3];

    /// Terms for m = 2, k = 2 and three points: the second point does not
    /// move with u₁, the third not at all (zero columns, skipped).
    fn terms() -> SensitivityTerms<2, 2, Points> {
        let v = |x: f64, y: f64| Vector2::new(x, y);
        let zero = Vector2::zeros();
        SensitivityTerms {
            psi_u: Matrix2::new(-0.7, 1.3, 0.4, 0.9),
            psi_p: Matrix2::new(-1.0, 0.3, 0.2, -0.6),
            psi_u_dot: Matrix2::new(0.11, -0.5, 0.8, 0.25),
            psi_p_dot: Matrix2::new(0.0, 0.7, -0.3, 0.05),
            psi_u_ddot: Matrix2::new(1.7, -0.2, 0.6, -1.1),
            psi_p_ddot: Matrix2::new(-0.4, 0.0, 0.9, 0.35),
            points_u: [
                [v(0.5, -0.2), zero, zero],
                [v(0.3, 0.1), v(-0.6, 0.8), zero],
            ],
            points_p: [
                [v(1.0, 0.0), v(0.2, 0.3), zero],
                [zero, v(-0.1, 0.4), v(0.5, 0.5)],
            ],
            point_velocities_u: [
                [v(-0.2, 0.9), zero, zero],
                [v(0.7, -0.3), v(0.1, 0.2), zero],
            ],
            point_velocities_p: [[v(0.3, 0.3), zero, zero], [v(0.0, -0.8), v(0.6, 0.1), zero]],
            point_accelerations_u: [
                [v(1.1, -0.4), zero, zero],
                [v(-0.5, 0.6), v(0.9, -1.2), zero],
            ],
            point_accelerations_p: [
                [v(0.2, -0.7), v(0.4, 0.0), zero],
                [zero, v(1.3, 0.2), v(-0.3, 0.1)],
            ],
        }
    }

    /// The formulas written plainly (in the module's X₀, A, B form):
    /// nalgebra's products, every term of every point added.
    fn plainly(t: &SensitivityTerms<2, 2, Points>) -> Sensitivity<2, 2, Points> {
        let inv = crate::linalg::invert(&t.psi_u);
        let inverse = inv.inverse;
        let (a, b) = (inverse * t.psi_u_dot, inverse * t.psi_u_ddot);
        let x0 = inverse * t.psi_p;
        let u = -x0;
        let udot = a * x0 - inverse * t.psi_p_dot;
        let uddot = b * x0 - (a * 2.0) * udot - inverse * t.psi_p_ddot;
        let (mut p, mut pv, mut pa) = (t.points_p, t.point_velocities_p, t.point_accelerations_p);
        for j in 0..2 {
            for i in 0..2 {
                for c in 0..3 {
                    p[j][c] += t.points_u[i][c] * u[(i, j)];
                    pv[j][c] += t.point_velocities_u[i][c] * u[(i, j)];
                    pv[j][c] += t.points_u[i][c] * udot[(i, j)];
                    pa[j][c] += t.point_accelerations_u[i][c] * u[(i, j)];
                    pa[j][c] += t.point_velocities_u[i][c] * (2.0 * udot[(i, j)]);
                    pa[j][c] += t.points_u[i][c] * uddot[(i, j)];
                }
            }
        }
        Sensitivity {
            u,
            udot,
            uddot,
            points: p,
            point_velocities: pv,
            point_accelerations: pa,
            rcond: inv.rcond,
        }
    }

    /// The fixed-size products, the points summed in place with the zero
    /// terms skipped: the very numbers of the formulas
    /// written plainly, in the same order (== on every entry, not a
    /// tolerance).
    #[test]
    fn from_terms_gives_the_formulas_numbers() {
        let t = terms();
        let ours = from_terms(&t, &Options::default()).expect("regular");
        assert_eq!(ours, plainly(&t));
    }

    /// The other order, the formulas as they read, gives the very numbers
    /// of nalgebra's products in that order.
    #[test]
    fn in_sequence_gives_the_formulas_numbers() {
        let t = terms();
        let inverse = crate::linalg::invert(&t.psi_u).inverse;
        let u = -(inverse * t.psi_p);
        let udot = -(inverse * (t.psi_u_dot * u + t.psi_p_dot));
        let uddot = -(inverse * (t.psi_u_ddot * u + t.psi_u_dot * udot * 2.0 + t.psi_p_ddot));
        assert_eq!(in_sequence(&inverse, &t), (u, udot, uddot));
        // Not the numbers of the other order (to rounding only).
        let first = by_products_first(&inverse, &t);
        assert_ne!(first, (u, udot, uddot));
        assert!((first.2 - uddot).amax() <= 1e-14 * uddot.amax());
    }

    fn error(t: &SensitivityTerms<2, 2, Points>) -> Option<&'static str> {
        match from_terms(t, &Options::default()) {
            Err(Error::NonFiniteValue {
                stage: Stage::Sensitivity,
                quantity,
            }) => Some(quantity),
            Err(e) => panic!("unexpected {e:?}"),
            Ok(_) => None,
        }
    }

    /// A NaN or an infinity in a term is named: the first of the matrices in
    /// their order, and for the points' terms the first result it reaches.
    #[test]
    fn a_non_finite_term_is_named() {
        let bad = [f64::NAN, f64::INFINITY];
        for x in bad {
            let mut t = terms();
            t.psi_p_ddot[(1, 0)] = x;
            assert_eq!(error(&t), Some("Ψ̈_p"));
            t.psi_u_dot[(0, 1)] = x;
            assert_eq!(error(&t), Some("Ψ̇_u"));
            t.psi_u[(1, 1)] = x;
            assert_eq!(error(&t), Some("Ψ_u"));
            for (field, expected) in [(0, "dP̈/dp"), (1, "dṖ/dp"), (2, "dP/dp")] {
                let mut t = terms();
                // The third point's zero terms, which would be skipped were
                // they zero.
                match field {
                    0 => t.point_accelerations_u[1][2].y = x,
                    1 => t.point_velocities_u[0][2].x = x,
                    _ => t.points_u[1][2].x = x,
                }
                assert_eq!(error(&t), Some(expected));
            }
            let mut t = terms();
            t.point_velocities_p[1][0].x = x;
            assert_eq!(error(&t), Some("dṖ/dp"));
        }
        assert_eq!(error(&terms()), None);
    }
}
