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
    // B x by coordinates, and Bᵀ z by equations.
    let times = |x: &SVector<f64, M>| {
        let mut y = factors.forward(x);
        for (v, c) in y.iter_mut().zip(columns) {
            *v *= c;
        }
        y
    };
    let transposed = |z: &SVector<f64, M>| {
        let scaled = SVector::<f64, M>::from_fn(|k, _| z[k] * columns[k]);
        factors.backward(&scaled)
    };
    let signs = |y: &SVector<f64, M>| y.map(|v| if v < 0.0 { -1.0 } else { 1.0 });
    let largest = |z: &SVector<f64, M>| {
        let mut j = 0;
        for (i, v) in z.iter().enumerate() {
            if v.abs() > z[j].abs() {
                j = i;
            }
        }
        j
    };
    let y = times(&SVector::<f64, M>::repeat(1.0 / M as f64));
    let mut norm = y.abs().sum();
    let mut sign = signs(&y);
    let mut j = largest(&transposed(&sign));
    for step in 2..=STEPS {
        let y = times(&SVector::<f64, M>::from_fn(|i, _| {
            f64::from(u8::from(i == j))
        }));
        let previous = norm;
        norm = y.abs().sum();
        let next_sign = signs(&y);
        if next_sign == sign || norm <= previous {
            norm = norm.max(previous);
            break;
        }
        sign = next_sign;
        let z = transposed(&sign);
        let last = j;
        j = largest(&z);
        if z[last].abs() == z[j].abs() || step == STEPS {
            break;
        }
    }
    // A last vector of alternating signs and growing size catches what the
    // iteration can miss.
    let alternating = SVector::<f64, M>::from_fn(|i, _| {
        let size = 1.0 + i as f64 / (M - 1) as f64;
        if i % 2 == 0 { size } else { -size }
    });
    let other = 2.0 * times(&alternating).abs().sum() / (3.0 * M as f64);
    if other > norm {
        norm = other;
    }
    if norm.is_finite() && norm > 0.0 {
        (1.0 / norm).min(1.0)
    } else {
        0.0
    }
}
