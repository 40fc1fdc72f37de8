//! The reciprocal condition number of Ψ_u factored in blocks, estimated
//! without its inverse: Hager's method as Higham refined it (LAPACK's
//! `xLACN2`, behind `xGECON`), on B = D_c Ψ_u⁻¹, D_c the 1-norms of Ψ_u's
//! columns, so that 1/‖B‖₁ is the reciprocal condition number of Ψ_u with
//! its columns scaled to unit 1-norm — what [`invert`](crate::invert)
//! computes exactly from the inverse. Each step is one solve with Ψ_u or
//! with its transpose; the estimate is ‖B x‖₁ for some ‖x‖₁ = 1, never
//! more than ‖B‖₁, so the rcond it gives is never less than the exact one.

use super::Factors;
use nalgebra::SVector;

/// Steps of the power-like iteration at most (LAPACK's ITMAX).
const STEPS: usize = 5;

/// 1/est(‖D_c Ψ_u⁻¹‖₁) clamped to [0, 1]; 0 when the estimate is not
/// finite (a non-finite entry, or a solve that overflows) or not positive.
pub(super) fn estimate<const M: usize>(factors: &Factors<M>, columns: &[f64; M]) -> f64 {
    // B x = D_c Ψ_u⁻¹ x from Ψ_u⁻¹ x, as ‖B x‖₁ and the signs of B x, in
    // one pass (the norm summed in order, as nalgebra's `sum` does).
    let measured = |y: SVector<f64, M>| {
        let (mut norm, mut signs) = (0.0, [1.0; M]);
        for ((v, c), sign) in y.as_slice().iter().zip(columns).zip(&mut signs) {
            let v = v * c;
            norm += v.abs();
            if v < 0.0 {
                *sign = -1.0;
            }
        }
        (norm, signs)
    };
    // The equation where Bᵀ z is largest, Bᵀ z = Ψ_u⁻ᵀ D_c z, and how
    // large it is there and at equation `at`.
    let largest = |z: &[f64; M], at: usize| {
        let scaled = SVector::<f64, M>::from_fn(|k, _| z[k] * columns[k]);
        let y = factors.backward(&scaled);
        // The first of the largest (the largest so far kept at hand, not
        // read again through j).
        let y = y.as_slice();
        let (mut j, mut most) = (0, y[0].abs());
        for (i, v) in y.iter().enumerate().skip(1) {
            if v.abs() > most {
                (j, most) = (i, v.abs());
            }
        }
        (j, y[at].abs() == most)
    };
    // A last vector of alternating signs and growing size catches what the
    // iteration can miss; its solve, which needs no other, runs beside the
    // first.
    let alternating = SVector::<f64, M>::from_fn(|i, _| {
        let size = 1.0 + i as f64 / (M - 1) as f64;
        if i % 2 == 0 { size } else { -size }
    });
    let (first, last) =
        factors.forward_pair(&SVector::<f64, M>::repeat(1.0 / M as f64), &alternating);
    let (mut norm, mut sign) = measured(first);
    let (mut j, _) = largest(&sign, 0);
    for step in 2..=STEPS {
        // B e_j, from the solve with e_j, which starts at j's block.
        let (next, next_sign) = measured(factors.unit_forward(j));
        let previous = norm;
        norm = next;
        if next_sign == sign || norm <= previous {
            norm = norm.max(previous);
            break;
        }
        sign = next_sign;
        let last = j;
        let (found, tied) = largest(&sign, last);
        j = found;
        if tied || step == STEPS {
            break;
        }
    }
    let other = 2.0 * measured(last).0 / (3.0 * M as f64);
    if other > norm {
        norm = other;
    }
    if norm.is_finite() && norm > 0.0 {
        (1.0 / norm).min(1.0)
    } else {
        0.0
    }
}
