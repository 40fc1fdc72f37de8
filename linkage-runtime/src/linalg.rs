//! Small dense linear algebra without allocation: the inverse of Ψ_u with its
//! reciprocal condition number, in closed form for m ≤ 3.

use nalgebra::SMatrix;

/// An inverted square matrix and its conditioning.
#[derive(Clone, Copy, Debug)]
pub struct Inverse<const M: usize> {
    pub inverse: SMatrix<f64, M, M>,
    /// The reciprocal condition number 1/(‖B‖₁‖B⁻¹‖₁) in [0, 1] of the
    /// column-equilibrated matrix B = A D_c (each column scaled to unit
    /// 1-norm), so that it does not depend on the units of the coordinates;
    /// 0 if A is exactly singular.
    pub rcond: f64,
}

/// Inverts `a`; `rcond` is 0 when `a` is singular or the inverse is not
/// finite (the returned inverse is then meaningless).
#[inline]
pub fn invert<const M: usize>(a: &SMatrix<f64, M, M>) -> Inverse<M> {
    let inverse = match M {
        1 => {
            let mut inv = SMatrix::<f64, M, M>::zeros();
            inv[(0, 0)] = 1.0 / a[(0, 0)];
            Some(inv)
        }
        2 => {
            let r = 1.0 / (a[(0, 0)] * a[(1, 1)] - a[(0, 1)] * a[(1, 0)]);
            let mut inv = SMatrix::<f64, M, M>::zeros();
            inv[(0, 0)] = a[(1, 1)] * r;
            inv[(0, 1)] = -a[(0, 1)] * r;
            inv[(1, 0)] = -a[(1, 0)] * r;
            inv[(1, 1)] = a[(0, 0)] * r;
            Some(inv)
        }
        3 => {
            let c = |i: usize, j: usize| {
                let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
                let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
                a[(i1, j1)] * a[(i2, j2)] - a[(i1, j2)] * a[(i2, j1)]
            };
            let r = 1.0 / (a[(0, 0)] * c(0, 0) + a[(0, 1)] * c(0, 1) + a[(0, 2)] * c(0, 2));
            let mut inv = SMatrix::<f64, M, M>::zeros();
            for i in 0..3 {
                for j in 0..3 {
                    // adjugate: transpose of the cofactors
                    inv[(j, i)] = c(i, j) * r;
                }
            }
            Some(inv)
        }
        _ => gauss_jordan(a),
    };
    match inverse {
        Some(inv) if inv.iter().all(|x| x.is_finite()) => Inverse {
            inverse: inv,
            rcond: equilibrated_rcond(a, &inv),
        },
        _ => Inverse {
            inverse: SMatrix::zeros(),
            rcond: 0.0,
        },
    }
}

/// 1/(‖B‖₁‖B⁻¹‖₁) for B = A D_c, the columns of A scaled to unit 1-norm:
/// ‖B‖₁ = 1, and B⁻¹ = D_c⁻¹ A⁻¹ is row i of A⁻¹ times the 1-norm of
/// column i of A. (Rows are not scaled: a row that shrinks is how a
/// singular pose shows itself.)
#[inline]
fn equilibrated_rcond<const M: usize>(a: &SMatrix<f64, M, M>, inv: &SMatrix<f64, M, M>) -> f64 {
    let mut col = [0.0; M];
    for (j, c) in col.iter_mut().enumerate() {
        *c = a.column(j).iter().map(|x| x.abs()).sum::<f64>();
    }
    let mut norm = 0.0_f64;
    for j in 0..M {
        let sum: f64 = (0..M).map(|i| inv[(i, j)].abs() * col[i]).sum();
        norm = norm.max(sum);
    }
    if norm.is_finite() && norm > 0.0 {
        (1.0 / norm).min(1.0)
    } else {
        0.0
    }
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

/// Gauss–Jordan elimination with partial pivoting; `None` on a zero pivot.
fn gauss_jordan<const M: usize>(a: &SMatrix<f64, M, M>) -> Option<SMatrix<f64, M, M>> {
    let mut work = *a;
    let mut inv = SMatrix::<f64, M, M>::identity();
    for col in 0..M {
        let pivot =
            (col..M).max_by(|&i, &j| work[(i, col)].abs().total_cmp(&work[(j, col)].abs()))?;
        let p = work[(pivot, col)];
        if p == 0.0 || !p.is_finite() {
            return None;
        }
        work.swap_rows(col, pivot);
        inv.swap_rows(col, pivot);
        for j in 0..M {
            work[(col, j)] /= p;
            inv[(col, j)] /= p;
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
    Some(inv)
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
    }

    #[test]
    fn rcond_measures_conditioning() {
        let eps = 1e-9;
        let r = invert(&Matrix2::new(1.0, 1.0, 1.0, 1.0 + eps)).rcond;
        assert!(r > 1e-10 && r < 1e-9, "rcond = {r}");
        assert_eq!(invert(&Matrix2::<f64>::identity()).rcond, 1.0);
    }
}
