//! The transmission angle: how well a mechanism passes motion on, the
//! textbook quality measure of a four-bar (the angle between coupler and
//! rocker) and of a slider-crank (between the rod and the normal to the
//! slide), and its generalisation to any mechanism.
//!
//! The general measure reads Ψ_u alone. Scale each of its columns to unit
//! length (so that neither the units of a coordinate, an angle or a
//! slider's length, nor the size of the links count) and take the
//! smallest singular value σ of the result: 1 when the columns are
//! orthogonal, 0 at a singular pose (a dead point, a branch point). The
//! *equivalent transmission angle* is μ = arccos(1 − σ²). For one loop of
//! two coordinates the two unit columns make the angle between the two
//! links they move, the Gram matrix [[1, c], [c, 1]] has eigenvalues
//! 1 ± c, so σ² = 1 − |cos μ|: μ is then exactly the four-bar's (acute)
//! transmission angle, and the slider-crank's. For several loops it is
//! governed by the worst-conditioned loop.

use nalgebra::SMatrix;

/// The equivalent transmission angle of a pose whose Jacobian by the
/// dependent coordinates is `psi_u` (radians, in [0, π/2]; see the
/// module's documentation). A zero column (a coordinate no equation
/// moves) gives 0, as does anything not finite.
pub fn equivalent_angle<const M: usize>(psi_u: &SMatrix<f64, M, M>) -> f64 {
    let mut unit = *psi_u;
    for mut column in unit.column_iter_mut() {
        let norm = column.norm();
        if !(norm > 0.0 && norm.is_finite()) {
            return 0.0;
        }
        column /= norm;
    }
    if M == 2 {
        // σ² = 1 − |c|, c the cosine between the two unit columns.
        let cosine = unit.column(0).dot(&unit.column(1));
        return acute_from_cosine(cosine);
    }
    let gram = unit.transpose() * unit;
    let gram = nalgebra::DMatrix::from_column_slice(M, M, gram.as_slice());
    let smallest: f64 = gram.symmetric_eigenvalues().min().clamp(0.0, 1.0);
    if smallest.is_nan() {
        return 0.0;
    }
    (1.0 - smallest).acos()
}

/// The acute angle whose cosine is `cosine` in absolute value (radians,
/// in [0, π/2]): an angle beyond 90° counts as its supplement. Anything
/// not finite gives 0.
pub fn acute_from_cosine(cosine: f64) -> f64 {
    if cosine.is_finite() {
        cosine.abs().min(1.0).acos()
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::closed_form;
    use nalgebra::matrix;

    /// On a four-bar the equivalent angle is the transmission angle, at
    /// every crank angle, on both branches.
    #[test]
    fn is_the_four_bars_transmission_angle() {
        let bar = closed_form::FourBar {
            l1: 80.0,
            l2: 20.0,
            l3: 50.0,
            l4: 70.0,
        };
        for k in 0..72 {
            let theta2 = k as f64 * 5f64.to_radians();
            for sigma in [1.0, -1.0] {
                let [t3, t4] = bar.position(theta2, sigma).unwrap();
                let psi_u = matrix![
                    -bar.l3 * t3.sin(), -bar.l4 * t4.sin();
                    bar.l3 * t3.cos(), bar.l4 * t4.cos()
                ];
                // The angle between C→B and C→D.
                let mu = acute_from_cosine(-(t4 - t3).cos());
                assert!((equivalent_angle(&psi_u) - mu).abs() < 1e-7, "{theta2}");
            }
        }
    }

    #[test]
    fn is_zero_at_a_singular_pose_and_right_for_orthogonal_columns() {
        let singular = matrix![1.0, 2.0; 2.0, 4.0];
        assert!(equivalent_angle(&singular) < 1e-7);
        let orthogonal = matrix![0.0, -3.0, 0.0; 5.0, 0.0, 0.0; 0.0, 0.0, 1e-6];
        assert_eq!(equivalent_angle(&orthogonal), std::f64::consts::FRAC_PI_2);
        let no_column = matrix![0.0, 1.0; 0.0, 1.0];
        assert_eq!(equivalent_angle(&no_column), 0.0);
        assert_eq!(equivalent_angle(&matrix![f64::NAN, 1.0; 0.0, 1.0]), 0.0);
    }

    #[test]
    fn an_obtuse_angle_counts_as_its_supplement() {
        let mu = 100f64.to_radians();
        assert!((acute_from_cosine(mu.cos()) - 80f64.to_radians()).abs() < 1e-15);
        assert_eq!(acute_from_cosine(f64::NAN), 0.0);
    }
}
