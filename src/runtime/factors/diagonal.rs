//! A diagonal block of Ψ_u inverted where it lies: closed forms up to 3×3,
//! Gauss–Jordan elimination with partial pivoting above.

use crate::runtime::linalg::adjugate;
use nalgebra::SMatrix;

/// D, the last k columns of a block's panel (`width` columns to a row, k
/// rows, D from column `diagonal`), replaced by its inverse transposed: the
/// entry of D⁻¹ for coordinate t and equation s put at row s, column
/// `diagonal` + t. Whether D is regular with a finite inverse, and det D.
pub(super) fn invert_in_panel(panel: &mut [f64], width: usize, diagonal: usize) -> (bool, f64) {
    match width - diagonal {
        1 => small::<1>(panel, width, diagonal),
        2 => small::<2>(panel, width, diagonal),
        3 => small::<3>(panel, width, diagonal),
        _ => large(panel, width, diagonal),
    }
}

/// Up to 3×3: the adjugate over the determinant.
fn small<const K: usize>(panel: &mut [f64], width: usize, diagonal: usize) -> (bool, f64) {
    let at = |s: usize, t: usize| s * width + diagonal + t;
    let d = SMatrix::<f64, K, K>::from_fn(|s, t| panel[at(s, t)]);
    let (adjugate, det) = adjugate(&d);
    let inverse = adjugate * (1.0 / det);
    // A zero or non-finite det, or an overflow, makes the sum non-finite.
    if inverse.sum().abs() > f64::MAX || inverse.sum().is_nan() {
        return (false, det);
    }
    for s in 0..K {
        for t in 0..K {
            panel[at(s, t)] = inverse[(t, s)];
        }
    }
    (true, det)
}

/// Above 3×3: Gauss–Jordan elimination, on the stack up to 8×8 (a larger
/// block is dense work that a heap allocation does not weigh on).
fn large(panel: &mut [f64], width: usize, diagonal: usize) -> (bool, f64) {
    let k = width - diagonal;
    let at = |s: usize, t: usize| s * width + diagonal + t;
    let (mut small_work, mut small_inverse) = ([0.0; 64], [0.0; 64]);
    let (mut large_work, mut large_inverse) = (Vec::new(), Vec::new());
    let (work, inverse) = if k * k <= 64 {
        (&mut small_work[..k * k], &mut small_inverse[..k * k])
    } else {
        large_work.resize(k * k, 0.0);
        large_inverse.resize(k * k, 0.0);
        (&mut large_work[..], &mut large_inverse[..])
    };
    for (i, w) in work.iter_mut().enumerate() {
        *w = panel[at(i / k, i % k)];
    }
    let (regular, det) = gauss_jordan_rows(work, inverse, k);
    if !regular || !inverse.iter().all(|v| v.is_finite()) {
        return (false, det);
    }
    // inverse[t·k + s] is D⁻¹'s entry for coordinate t and equation s.
    for s in 0..k {
        for t in 0..k {
            panel[at(s, t)] = inverse[t * k + s];
        }
    }
    (true, det)
}

/// The inverse of the k×k matrix `work` (row by row) into `inverse`, and
/// its determinant, by Gauss–Jordan elimination with partial pivoting;
/// false (and det 0, or NaN) on a zero or non-finite pivot. `work` is
/// spent.
fn gauss_jordan_rows(work: &mut [f64], inverse: &mut [f64], k: usize) -> (bool, f64) {
    inverse.fill(0.0);
    for i in 0..k {
        inverse[i * k + i] = 1.0;
    }
    let mut det = 1.0;
    for col in 0..k {
        let pivot = (col..k)
            .max_by(|&i, &j| work[i * k + col].abs().total_cmp(&work[j * k + col].abs()))
            .unwrap_or(col);
        let p = work[pivot * k + col];
        if p == 0.0 || !p.is_finite() {
            return (false, if p == 0.0 { 0.0 } else { f64::NAN });
        }
        if pivot != col {
            for j in 0..k {
                work.swap(col * k + j, pivot * k + j);
                inverse.swap(col * k + j, pivot * k + j);
            }
            det = -det;
        }
        det *= p;
        let r = 1.0 / p;
        for j in 0..k {
            work[col * k + j] *= r;
            inverse[col * k + j] *= r;
        }
        for row in 0..k {
            let factor = work[row * k + col];
            if row != col && factor != 0.0 {
                for j in 0..k {
                    work[row * k + j] -= factor * work[col * k + j];
                    inverse[row * k + j] -= factor * inverse[col * k + j];
                }
            }
        }
    }
    (true, det)
}
