//! Small dense linear algebra without allocation: the inverse of Ψ_u with its
//! reciprocal condition number, in closed form for m ≤ 3.

use crate::runtime::powers_of_two::{pow2, power_of_two_near};
use nalgebra::{SMatrix, SVector};

/// An inverted square matrix, its determinant and its conditioning.
#[derive(Clone, Copy, Debug)]
pub struct Inverse<const M: usize> {
    pub inverse: SMatrix<f64, M, M>,
    /// The reciprocal condition number 1/(‖B‖₁‖B⁻¹‖₁) in [0, 1] of the
    /// column-equilibrated matrix B = A D_c (each column scaled to unit
    /// 1-norm), so that it does not depend on the units of the coordinates;
    /// 0 if A is exactly singular.
    pub rcond: f64,
    /// det A (its sign tells the assembly branch).
    pub det: f64,
}

/// Inverts `a`; `rcond` is 0 when `a` is singular or the inverse is not
/// finite (the returned inverse is then meaningless). Closed forms for
/// m ≤ 3: the adjugate, whose norms give rcond = |det A| / ‖D_c adj A‖₁
/// without a second division, and A⁻¹ = adj A / det A. Gauss–Jordan
/// elimination with partial pivoting above.
///
/// A matrix whose largest entry lies outside [2⁻³⁰⁰, 2³⁰⁰] (a mechanism
/// measured in units far too small or large for it) is scaled by a power
/// of two first, exactly, so that the determinant and the adjugate neither
/// underflow nor overflow; det A is then scaled back, and keeps its sign
/// even where its magnitude leaves the range of f64.
#[inline(always)]
pub fn invert<const M: usize>(a: &SMatrix<f64, M, M>) -> Inverse<M> {
    let (scale, ordinary) = scale_of(a);
    let extreme = !ordinary && scale > 0.0 && scale.is_finite();
    if M > 3 {
        return if extreme {
            invert_scaled(a, scale)
        } else {
            invert_at_scale(a)
        };
    }
    // m ≤ 3: scaled by 1 but at an extreme scale, so that one inversion, in
    // line, serves both. The result of an out-of-line inversion merged with
    // the ordinary one's stayed in memory, which slowed a four-bar's fused
    // kinematics kernel (docs/performance.md, "Measurements behind the
    // code").
    let (p, reciprocal) = if extreme {
        power_of_two_and_reciprocal(scale)
    } else {
        (1.0, 1.0)
    };
    let inner = invert_at_scale(&(a * reciprocal));
    Inverse {
        inverse: inner.inverse * reciprocal,
        rcond: inner.rcond,
        det: if extreme {
            scaled_determinant::<M>(inner.det, p)
        } else {
            inner.det
        },
    }
}

/// The largest magnitude of `a`'s entries, and whether it lies in the
/// ordinary range [2⁻³⁰⁰, 2³⁰⁰] where no scaling is needed. Plain
/// comparisons (a NaN entry is skipped here and caught by the inversion):
/// this runs at every evaluation of a sweep.
#[inline(always)]
pub(crate) fn scale_of<const M: usize>(a: &SMatrix<f64, M, M>) -> (f64, bool) {
    let mut scale = 0.0_f64;
    for x in a.iter() {
        let x = x.abs();
        if x > scale {
            scale = x;
        }
    }
    (scale, ordinary_scale(scale))
}

/// Whether a matrix whose largest entry is `scale` needs no scaling by a
/// power of two before it is inverted: `scale` in [2⁻³⁰⁰, 2³⁰⁰].
#[inline(always)]
pub(crate) fn ordinary_scale(scale: f64) -> bool {
    const LOW: f64 = pow2(-300);
    const HIGH: f64 = pow2(300);
    (LOW..=HIGH).contains(&scale)
}

/// [`invert`] for m > 3 at an extreme scale, out of line: Gauss–Jordan
/// elimination costs enough that the merged result's round trip through
/// memory does not show, and in line the six-bar's fused kernel was slower
/// (docs/performance.md, "Measurements behind the code").
#[cold]
#[inline(never)]
fn invert_scaled<const M: usize>(a: &SMatrix<f64, M, M>, scale: f64) -> Inverse<M> {
    let (p, reciprocal) = power_of_two_and_reciprocal(scale);
    let inner = invert_at_scale(&(a * reciprocal));
    Inverse {
        inverse: inner.inverse * reciprocal,
        rcond: inner.rcond,
        det: scaled_determinant::<M>(inner.det, p),
    }
}

/// p, the power of two near `scale` ([`power_of_two_near`]), and 1/p, both
/// exact: A·(1/p) and A₁⁻¹·(1/p) are the very numbers of A/p and A₁⁻¹/p.
#[cold]
#[inline(never)]
pub(crate) fn power_of_two_and_reciprocal(scale: f64) -> (f64, f64) {
    let p = power_of_two_near(scale);
    (p, 1.0 / p)
}

/// det A = pᴹ·det A₁ for A = p·A₁, keeping its sign where its magnitude
/// leaves the range of f64 (the smallest subnormal then).
#[cold]
#[inline(never)]
pub(crate) fn scaled_determinant<const M: usize>(inner: f64, p: f64) -> f64 {
    let mut det = inner;
    for _ in 0..M {
        det *= p;
    }
    if det == 0.0 && inner != 0.0 {
        det = f64::from_bits(1).copysign(inner);
    }
    det
}

#[inline(always)]
fn invert_at_scale<const M: usize>(a: &SMatrix<f64, M, M>) -> Inverse<M> {
    let singular = |det: f64| Inverse {
        inverse: SMatrix::zeros(),
        rcond: 0.0,
        det,
    };
    if M > 3 {
        return match gauss_jordan(a) {
            (Some(inv), det) if inv.iter().all(|x| x.is_finite()) => {
                let norm = equilibrated_norm(a, &inv);
                if norm.is_finite() && norm > 0.0 {
                    Inverse {
                        inverse: inv,
                        rcond: (1.0 / norm).min(1.0),
                        det,
                    }
                } else {
                    singular(det)
                }
            }
            (_, det) => singular(det),
        };
    }
    let (adjugate, det) = adjugate(a);
    let rcond = det.abs() / equilibrated_norm(a, &adjugate);
    let inverse = adjugate * (1.0 / det);
    // rcond is NaN for a non-finite A (and ≤ 1 but for rounding); a NaN or
    // infinite entry of the inverse (an overflow) makes the sum non-finite.
    let regular = (rcond > 0.0) & (rcond <= 2.0) & (inverse.sum().abs() <= f64::MAX);
    if regular {
        Inverse {
            inverse,
            rcond: if rcond < 1.0 { rcond } else { 1.0 },
            det,
        }
    } else {
        singular(det)
    }
}

/// adj A and det A for m ≤ 3 (the adjugate is the transpose of the
/// cofactors).
#[inline(always)]
pub(crate) fn adjugate<const M: usize>(a: &SMatrix<f64, M, M>) -> (SMatrix<f64, M, M>, f64) {
    let mut adj = SMatrix::<f64, M, M>::zeros();
    let det = match M {
        1 => {
            adj[(0, 0)] = 1.0;
            a[(0, 0)]
        }
        2 => {
            adj[(0, 0)] = a[(1, 1)];
            adj[(0, 1)] = -a[(0, 1)];
            adj[(1, 0)] = -a[(1, 0)];
            adj[(1, 1)] = a[(0, 0)];
            a[(0, 0)] * a[(1, 1)] - a[(0, 1)] * a[(1, 0)]
        }
        3 => {
            let c = |i: usize, j: usize| {
                let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
                let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
                a[(i1, j1)] * a[(i2, j2)] - a[(i1, j2)] * a[(i2, j1)]
            };
            for i in 0..3 {
                for j in 0..3 {
                    adj[(j, i)] = c(i, j);
                }
            }
            a[(0, 0)] * adj[(0, 0)] + a[(0, 1)] * adj[(1, 0)] + a[(0, 2)] * adj[(2, 0)]
        }
        _ => f64::NAN,
    };
    (adj, det)
}

/// ‖D_c B‖₁ = max_j Σ_i |B_ij|·‖A_:i‖₁, D_c the 1-norms of A's columns.
/// With B = A⁻¹ this is ‖(A D_c⁻¹)⁻¹‖₁, and as ‖A D_c⁻¹‖₁ = 1 its
/// reciprocal is the reciprocal condition number of A with its columns
/// scaled to unit 1-norm (rows are not scaled: a row that shrinks is how a
/// singular pose shows itself). With B = adj A it is that times |det A|.
#[inline(always)]
pub(crate) fn equilibrated_norm<const M: usize>(
    a: &SMatrix<f64, M, M>,
    b: &SMatrix<f64, M, M>,
) -> f64 {
    let mut col = [0.0; M];
    for (j, c) in col.iter_mut().enumerate() {
        *c = a.column(j).iter().map(|x| x.abs()).sum::<f64>();
    }
    let mut norm = 0.0_f64;
    for j in 0..M {
        let sum: f64 = (0..M).map(|i| b[(i, j)].abs() * col[i]).sum();
        // (A NaN sum is dropped here and caught by the caller's checks.)
        norm = if sum > norm { sum } else { norm };
    }
    norm
}

/// The determinant, by Gaussian elimination with partial pivoting (closed
/// form for m ≤ 2).
pub fn determinant<const M: usize>(a: &SMatrix<f64, M, M>) -> f64 {
    match M {
        0 => 1.0,
        1 => a[(0, 0)],
        2 => a[(0, 0)] * a[(1, 1)] - a[(0, 1)] * a[(1, 0)],
        _ => {
            let mut work = *a;
            let mut det = 1.0;
            for col in 0..M {
                let pivot = (col..M)
                    .max_by(|&i, &j| work[(i, col)].abs().total_cmp(&work[(j, col)].abs()))
                    .unwrap_or(col);
                let p = work[(pivot, col)];
                if p == 0.0 {
                    return 0.0;
                }
                if pivot != col {
                    work.swap_rows(col, pivot);
                    det = -det;
                }
                det *= p;
                for row in col + 1..M {
                    let factor = work[(row, col)] / p;
                    for j in col..M {
                        work[(row, j)] -= factor * work[(col, j)];
                    }
                }
            }
            det
        }
    }
}

/// Gauss–Jordan elimination with partial pivoting, and the determinant as
/// the signed product of the pivots; `None` (and det 0) on a zero pivot.
fn gauss_jordan<const M: usize>(a: &SMatrix<f64, M, M>) -> (Option<SMatrix<f64, M, M>>, f64) {
    let mut work = *a;
    let mut inv = SMatrix::<f64, M, M>::identity();
    let mut det = 1.0;
    for col in 0..M {
        let pivot = (col..M)
            .max_by(|&i, &j| work[(i, col)].abs().total_cmp(&work[(j, col)].abs()))
            .unwrap_or(col);
        let p = work[(pivot, col)];
        if p == 0.0 || !p.is_finite() {
            return (None, if p == 0.0 { 0.0 } else { f64::NAN });
        }
        if pivot != col {
            work.swap_rows(col, pivot);
            inv.swap_rows(col, pivot);
            det = -det;
        }
        det *= p;
        let r = 1.0 / p;
        for j in 0..M {
            work[(col, j)] *= r;
            inv[(col, j)] *= r;
        }
        for row in 0..M {
            if row != col {
                let factor = work[(row, col)];
                if factor != 0.0 {
                    for j in 0..M {
                        work[(row, j)] -= factor * work[(col, j)];
                        inv[(row, j)] -= factor * inv[(col, j)];
                    }
                }
            }
        }
    }
    (Some(inv), det)
}

/// The singular value decomposition of a small dynamic matrix, of the matrix
/// scaled by a power of two near its largest entry (exact) so that the
/// iteration neither overflows nor underflows: its singular values are
/// those of `q` divided by that power, and its vectors are `q`'s. `None`
/// for a matrix with a NaN or an infinity, or if the iteration does not
/// converge. (nalgebra's plain `svd` panics on a NaN singular value.)
pub fn scaled_svd(
    q: &nalgebra::DMatrix<f64>,
    compute_v: bool,
) -> Option<nalgebra::linalg::SVD<f64, nalgebra::Dyn, nalgebra::Dyn>> {
    if !q.iter().all(|x| x.is_finite()) {
        return None;
    }
    let scaled = q / power_of_two_near(q.amax());
    let svd = scaled.try_svd(false, compute_v, f64::EPSILON, 10_000)?;
    svd.singular_values
        .iter()
        .all(|s| s.is_finite())
        .then_some(svd)
}

/// σ_max/σ_min of [Ψ_u Ψ_v] with its columns scaled to unit length.
pub(crate) fn augmented_condition<const M: usize, const F: usize>(
    psi_u: &SMatrix<f64, M, M>,
    psi_v: &SMatrix<f64, M, F>,
) -> f64 {
    let mut q = nalgebra::DMatrix::<f64>::zeros(M, M + F);
    for j in 0..M + F {
        let column: Vec<f64> = (0..M)
            .map(|i| {
                if j < M {
                    psi_u[(i, j)]
                } else {
                    psi_v[(i, j - M)]
                }
            })
            .collect();
        let norm = column.iter().map(|x| x * x).sum::<f64>().sqrt();
        if norm > 0.0 {
            for (i, x) in column.iter().enumerate() {
                q[(i, j)] = x / norm;
            }
        }
    }
    // A decomposition that fails (only for extreme numbers) counts as
    // ill-conditioned: the cautious reading.
    let Some(svd) = scaled_svd(&q, false) else {
        return f64::INFINITY;
    };
    let (max, min) = svd
        .singular_values
        .iter()
        .fold((0.0_f64, f64::INFINITY), |(a, b), &x| (a.max(x), b.min(x)));
    if min > 0.0 { max / min } else { f64::INFINITY }
}

/// The Euclidean norm of x without overflow or underflow on the way (x
/// scaled by its largest entry first): finite for every finite x.
pub(crate) fn scaled_norm<const N: usize>(x: &SVector<f64, N>) -> f64 {
    let max = x.amax();
    if max > 0.0 && max.is_finite() {
        max * (x / max).norm()
    } else {
        max
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Matrix2, Matrix3, Matrix4};

    fn check<const M: usize>(a: SMatrix<f64, M, M>) {
        let inv = invert(&a);
        let err = (a * inv.inverse - SMatrix::<f64, M, M>::identity())
            .abs()
            .max();
        assert!(err < 1e-14, "‖A·A⁻¹ − I‖ = {err}");
        assert!(inv.rcond > 0.0 && inv.rcond <= 1.0);
        let det = determinant(&a);
        assert!(
            (inv.det - det).abs() <= 1e-14 * det.abs(),
            "{} vs {det}",
            inv.det
        );
    }

    #[test]
    fn inverses_of_every_size() {
        check(SMatrix::<f64, 1, 1>::new(4.0));
        check(Matrix2::new(2.0, 1.0, -1.0, 3.0));
        check(Matrix3::new(2.0, 1.0, 0.5, -1.0, 3.0, 0.0, 0.2, 0.1, 1.0));
        check(Matrix4::new(
            0.0, 1.0, 0.5, 2.0, //
            -1.0, 3.0, 0.0, 0.1, //
            0.2, 0.1, 1.0, 0.0, //
            1.0, 0.0, 0.0, 1.0,
        ));
    }

    #[test]
    fn determinants() {
        let a = Matrix3::new(2.0, 1.0, 0.5, -1.0, 3.0, 0.0, 0.2, 0.1, 1.0);
        assert!((determinant(&a) - a.determinant()).abs() < 1e-14);
        let b = Matrix4::new(
            0.0, 1.0, 0.5, 2.0, //
            -1.0, 3.0, 0.0, 0.1, //
            0.2, 0.1, 1.0, 0.0, //
            1.0, 0.0, 0.0, 1.0,
        );
        assert!((determinant(&b) - b.determinant()).abs() < 1e-14);
        assert_eq!(determinant(&Matrix2::new(1.0, 2.0, 2.0, 4.0)), 0.0);
    }

    #[test]
    fn singular_matrices_have_zero_rcond() {
        assert_eq!(invert(&Matrix2::new(1.0, 2.0, 2.0, 4.0)).rcond, 0.0);
        assert_eq!(invert(&Matrix3::<f64>::zeros()).rcond, 0.0);
        assert_eq!(invert(&Matrix4::<f64>::zeros()).rcond, 0.0);
        assert_eq!(invert(&Matrix2::new(1.0, 2.0, 2.0, 4.0)).det, 0.0);
        assert_eq!(invert(&Matrix4::<f64>::zeros()).det, 0.0);
    }

    #[test]
    fn rcond_measures_conditioning() {
        let eps = 1e-9;
        let r = invert(&Matrix2::new(1.0, 1.0, 1.0, 1.0 + eps)).rcond;
        assert!(r > 1e-10 && r < 1e-9, "rcond = {r}");
        assert_eq!(invert(&Matrix2::<f64>::identity()).rcond, 1.0);
    }
}
