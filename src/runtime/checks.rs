//! The checks every entry point makes: inputs finite, computed values
//! finite, and numbers in the normal range of f64 where relative precision
//! lives.

use crate::runtime::error::{Error, Stage};
use crate::runtime::powers_of_two::pow2;

/// Checks that every entry of `values` is finite.
#[inline]
pub(crate) fn check_input(argument: &'static str, values: &[f64]) -> Result<(), Error> {
    if all_finite(values) {
        return Ok(());
    }
    let index = values.iter().position(|x| !x.is_finite()).unwrap_or(0);
    Err(Error::NonFiniteInput {
        argument,
        index,
        value: values[index],
    })
}

/// Whether every entry is finite ([`all_finite_in`] of one slice).
#[inline(always)]
pub(crate) fn all_finite(values: &[f64]) -> bool {
    all_finite_in(&[values])
}

/// Whether every entry of every slice is finite, without a branch per
/// entry: x·0 is 0 for a finite x and NaN for an infinite or NaN one, and a
/// sum with a NaN is NaN. Four sums side by side, so that each addition
/// need not wait for the one before (a single running sum costs an
/// addition's latency per entry), and one set of them for all the slices
/// (one pass over a four-bar's six inputs to the sensitivities is faster
/// than slice by slice: docs/performance.md, "Measurements behind the
/// code").
#[inline(always)]
pub(crate) fn all_finite_in(slices: &[&[f64]]) -> bool {
    let mut lanes = [0.0_f64; 4];
    for values in slices {
        // Whole chunks of four, then the rest, into the same four sums: for
        // one slice the very code `all_finite` had before it was this.
        let mut chunks = values.chunks_exact(4);
        for chunk in &mut chunks {
            for (lane, x) in lanes.iter_mut().zip(chunk) {
                *lane += x * 0.0;
            }
        }
        for (lane, x) in lanes.iter_mut().zip(chunks.remainder()) {
            *lane += x * 0.0;
        }
    }
    (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]) == 0.0
}

/// The smallest scale of a nonzero column or row that keeps relative
/// precision: 2⁻⁹⁷⁰, 52 binary orders above the subnormal range.
const NORMAL_SCALE: f64 = pow2(-970);

/// Checks that no nonzero row or column of [Ψ_u Ψ_v] lives in the
/// subnormal range (see [`Error::Underflow`]), and returns the smallest
/// nonzero and the largest of the row and column scales (each the largest
/// |entry| of its row or column), found in one pass over the entries.
#[inline]
pub(crate) fn check_scale<const M: usize, const F: usize>(
    stage: Stage,
    psi_u: &nalgebra::SMatrix<f64, M, M>,
    psi_v: &nalgebra::SMatrix<f64, M, F>,
) -> Result<(f64, f64), Error> {
    // Plain comparisons (the entries are finite here): this runs in every
    // analysis, and f64::max's NaN handling costs more than the rest.
    let pick = |a: f64, b: f64| if b > a { b } else { a };
    let mut rows = [0.0_f64; M];
    let mut smallest = f64::INFINITY;
    let mut largest = 0.0_f64;
    let mut column = |entries: &[f64]| {
        let mut scale = 0.0_f64;
        for (row, x) in rows.iter_mut().zip(entries) {
            let x = x.abs();
            scale = pick(scale, x);
            *row = pick(*row, x);
        }
        if scale > 0.0 && scale < smallest {
            smallest = scale;
        }
        largest = pick(largest, scale);
    };
    for j in 0..M {
        column(psi_u.column(j).as_slice());
    }
    for j in 0..F {
        column(psi_v.column(j).as_slice());
    }
    for &scale in &rows {
        if scale > 0.0 && scale < smallest {
            smallest = scale;
        }
    }
    if smallest < NORMAL_SCALE {
        Err(Error::Underflow {
            stage,
            quantity: "[Ψ_u Ψ_v]",
            scale: smallest,
        })
    } else {
        Ok((smallest, largest))
    }
}

/// Checks that a computed result of size 2^`size_log2` (its largest
/// entry, found at unit scale and so without underflow) is a normal
/// number, which f64 holds to full relative precision; −∞ (an exactly
/// zero result) passes. Below 2⁻¹⁰²² it is an [`Error::Underflow`].
pub(crate) fn check_result(
    stage: Stage,
    quantity: &'static str,
    size_log2: f64,
) -> Result<(), Error> {
    if size_log2 > f64::NEG_INFINITY && size_log2 < f64::MIN_POSITIVE.log2() {
        Err(Error::Underflow {
            stage,
            quantity,
            scale: size_log2.exp2(),
        })
    } else {
        Ok(())
    }
}

/// Checks that a computed quantity is finite.
#[inline]
pub(crate) fn check_value(
    stage: Stage,
    quantity: &'static str,
    values: &[f64],
) -> Result<(), Error> {
    if all_finite(values) {
        Ok(())
    } else {
        Err(Error::NonFiniteValue { stage, quantity })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The branch-free test agrees with the plain one, whatever the length
    /// (the four lanes and the remainder) and wherever the bad number is.
    #[test]
    fn all_finite_agrees_with_is_finite() {
        for n in 0..=11 {
            let finite: Vec<f64> = (0..n)
                .map(|i| match i % 4 {
                    0 => -0.0,
                    1 => f64::MAX,
                    2 => -f64::MIN_POSITIVE / 2.0,
                    _ => i as f64,
                })
                .collect();
            assert!(all_finite(&finite), "{finite:?}");
            for at in 0..n {
                for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                    let mut values = finite.clone();
                    values[at] = bad;
                    assert!(!all_finite(&values), "{values:?}");
                }
            }
        }
    }
}
