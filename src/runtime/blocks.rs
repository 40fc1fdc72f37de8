//! Ψ_u inverted block by block. The symbolic engine finds, from which
//! entries of Ψ_u are not identically zero, an order of its equations and
//! coordinates in which it is block lower triangular ([`PsiUBlocks`]):
//! each block's equations involve only its own coordinates and those of
//! the blocks before it. Its inverse is then block lower triangular in the
//! same order, and [`invert_in_blocks`] builds it a block row at a time —
//! each diagonal block inverted alone, the rows below it from the rows
//! already found — in place of a Gauss–Jordan elimination of the whole
//! matrix: for a chain of loops, work that grows as m² instead of m³. The
//! result means what [`invert`]'s does: the same inverse (to rounding),
//! the same determinant and the same reciprocal condition number.

use crate::runtime::error::{Error, Stage};
use crate::runtime::linalg::{
    Inverse, equilibrated_norm, invert, invert_at_scale, power_of_two_and_reciprocal, scale_of,
    scaled_determinant,
};
use crate::runtime::options::Options;
use nalgebra::{SMatrix, SVector};

/// Ψ_u's diagonal blocks in the order they are solved: `equations` and
/// `coordinates` list every equation and every coordinate, block after
/// block, and `ends` where each block ends in both lists. The generated
/// code has them as a constant (`PSI_U_BLOCKS`) where Ψ_u has more than one
/// block; a run-time mechanism from its program.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PsiUBlocks<'a> {
    equations: &'a [usize],
    coordinates: &'a [usize],
    ends: &'a [usize],
    /// The sign of the two orders as permutations: det Ψ_u is it times the
    /// product of the diagonal blocks' determinants.
    sign: f64,
}

impl PsiUBlocks<'static> {
    /// One block: Ψ_u is dense, inverted whole.
    pub const DENSE: PsiUBlocks<'static> = PsiUBlocks {
        equations: &[],
        coordinates: &[],
        ends: &[],
        sign: 1.0,
    };
}

impl<'a> PsiUBlocks<'a> {
    /// The blocks, if `equations` and `coordinates` both order 0 … n − 1
    /// and `ends` rises to n; [`PsiUBlocks::DENSE`] otherwise.
    pub const fn new(equations: &'a [usize], coordinates: &'a [usize], ends: &'a [usize]) -> Self {
        let n = equations.len();
        let mut rising = !ends.is_empty() && ends[ends.len() - 1] == n && ends[0] > 0;
        let mut b = 1;
        while b < ends.len() {
            rising &= ends[b] > ends[b - 1];
            b += 1;
        }
        if coordinates.len() != n || !rising {
            return PsiUBlocks::DENSE;
        }
        match (parity(equations), parity(coordinates)) {
            (Some(a), Some(b)) => PsiUBlocks {
                equations,
                coordinates,
                ends,
                sign: if a == b { 1.0 } else { -1.0 },
            },
            _ => PsiUBlocks::DENSE,
        }
    }

    /// How many blocks (1 for [`PsiUBlocks::DENSE`]).
    pub fn len(&self) -> usize {
        self.ends.len().max(1)
    }

    /// Never: there is at least the one dense block.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The equations and the coordinates of each block, in solve order
    /// (nothing for [`PsiUBlocks::DENSE`]).
    pub fn blocks(&self) -> impl Iterator<Item = (&'a [usize], &'a [usize])> + 'a {
        let (equations, coordinates, ends) = (self.equations, self.coordinates, self.ends);
        (0..ends.len()).map(move |b| {
            let start = if b == 0 { 0 } else { ends[b - 1] };
            (&equations[start..ends[b]], &coordinates[start..ends[b]])
        })
    }
}

/// [`PsiUBlocks`] that owns its lists: a run-time mechanism's, checked and
/// its sign found once, when its program is built.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PsiUBlocksBuf {
    equations: Vec<usize>,
    coordinates: Vec<usize>,
    ends: Vec<usize>,
    sign: f64,
}

impl PsiUBlocksBuf {
    /// The lists as [`PsiUBlocks::new`] takes them (dense where it would
    /// be).
    pub(crate) fn new(equations: Vec<usize>, coordinates: Vec<usize>, ends: Vec<usize>) -> Self {
        let blocks = PsiUBlocks::new(&equations, &coordinates, &ends);
        let (dense, sign) = (blocks == PsiUBlocks::DENSE, blocks.sign);
        if dense {
            return PsiUBlocksBuf {
                equations: Vec::new(),
                coordinates: Vec::new(),
                ends: Vec::new(),
                sign,
            };
        }
        PsiUBlocksBuf {
            equations,
            coordinates,
            ends,
            sign,
        }
    }

    pub(crate) fn borrow(&self) -> PsiUBlocks<'_> {
        PsiUBlocks {
            equations: &self.equations,
            coordinates: &self.coordinates,
            ends: &self.ends,
            sign: self.sign,
        }
    }
}

/// Whether `order` is a permutation of 0 … n − 1 that is odd (`Some(true)`)
/// or even; `None` if it is no permutation. Counted by inversions: n² steps,
/// once per mechanism.
const fn parity(order: &[usize]) -> Option<bool> {
    let n = order.len();
    let mut odd = false;
    let mut i = 0;
    while i < n {
        if order[i] >= n {
            return None;
        }
        let mut j = i + 1;
        while j < n {
            if order[i] == order[j] {
                return None;
            }
            odd ^= order[i] > order[j];
            j += 1;
        }
        i += 1;
    }
    Some(odd)
}

/// `a` (Ψ_u) inverted block by block in the order of `blocks`: [`invert`]
/// itself for one block or blocks of another size. As [`invert`] does, a
/// matrix at an extreme scale is scaled by a power of two first, exactly,
/// and `rcond` is 0 (the inverse meaningless) when a diagonal block is
/// singular or the inverse is not finite.
pub fn invert_in_blocks<const M: usize>(
    a: &SMatrix<f64, M, M>,
    blocks: PsiUBlocks<'_>,
) -> Inverse<M> {
    if blocks.ends.len() <= 1 || blocks.equations.len() != M {
        return invert(a);
    }
    let (scale, ordinary) = scale_of(a);
    if ordinary || !(scale > 0.0 && scale.is_finite()) {
        return in_blocks_at_scale(a, blocks);
    }
    let (p, reciprocal) = power_of_two_and_reciprocal(scale);
    let inner = in_blocks_at_scale(&(a * reciprocal), blocks);
    Inverse {
        inverse: inner.inverse * reciprocal,
        rcond: inner.rcond,
        det: scaled_determinant::<M>(inner.det, p),
    }
}

/// Ψ_u inverted in the order of `blocks`, or [`Error::Singular`] in
/// `stage` if its reciprocal condition number is 0 or does not keep the
/// requested accuracy there ([`Options::keeps_accuracy`]).
#[inline(always)]
pub(crate) fn factor<const M: usize>(
    a: &SMatrix<f64, M, M>,
    blocks: PsiUBlocks<'_>,
    stage: Stage,
    options: &Options,
) -> Result<Inverse<M>, Error> {
    let inv = invert_in_blocks(a, blocks);
    options.require_accuracy(stage, inv.rcond)?;
    Ok(inv)
}

fn in_blocks_at_scale<const M: usize>(
    a: &SMatrix<f64, M, M>,
    blocks: PsiUBlocks<'_>,
) -> Inverse<M> {
    let singular = |det: f64| Inverse {
        inverse: SMatrix::zeros(),
        rcond: 0.0,
        det,
    };
    // X = A⁻¹ maps equations to coordinates: its block (i, j) is
    // X[coordinates of i, equations of j], zero above the diagonal.
    let mut x = SMatrix::<f64, M, M>::zeros();
    let mut det = blocks.sign;
    let mut column = SVector::<f64, M>::zeros();
    let mut start = 0;
    for (equations, coordinates) in blocks.blocks() {
        let (regular, block_det) = invert_diagonal_block(a, equations, coordinates, &mut x);
        det *= block_det;
        if !regular {
            return singular(det);
        }
        let (earlier_equations, earlier_coordinates) =
            (&blocks.equations[..start], &blocks.coordinates[..start]);
        start += equations.len();
        if earlier_equations.is_empty() {
            continue;
        }
        // T = Σ_l A[block's equations, coordinates of l] X[coordinates of
        // l, earlier equations] over the earlier blocks l, row t of T (of
        // the block's equation t) kept for now in X's row of the block's
        // coordinate t: only the entries of A that are not zero count.
        for (&equation, &row) in equations.iter().zip(coordinates) {
            for &q in earlier_coordinates {
                let coupling = a[(equation, q)];
                if coupling != 0.0 {
                    for &c in earlier_equations {
                        x[(row, c)] += coupling * x[(q, c)];
                    }
                }
            }
        }
        // X[block's coordinates, c] = −D⁻¹ T[·, c], D⁻¹ in X's diagonal block.
        for &c in earlier_equations {
            for (t, &row) in coordinates.iter().enumerate() {
                column[t] = x[(row, c)];
            }
            for &row in coordinates {
                let mut sum = 0.0;
                for (t, &equation) in equations.iter().enumerate() {
                    sum += x[(row, equation)] * column[t];
                }
                x[(row, c)] = -sum;
            }
        }
    }
    if !x.iter().all(|v| v.is_finite()) {
        return singular(det);
    }
    let norm = equilibrated_norm(a, &x);
    if norm.is_finite() && norm > 0.0 {
        Inverse {
            inverse: x,
            rcond: (1.0 / norm).min(1.0),
            det,
        }
    } else {
        singular(det)
    }
}

/// D = A[equations, coordinates] inverted into X[coordinates, equations]
/// (closed forms up to 3×3, Gauss–Jordan with partial pivoting above):
/// whether D is regular with a finite inverse, and det D.
fn invert_diagonal_block<const M: usize>(
    a: &SMatrix<f64, M, M>,
    equations: &[usize],
    coordinates: &[usize],
    x: &mut SMatrix<f64, M, M>,
) -> (bool, f64) {
    fn small<const K: usize, const M: usize>(
        a: &SMatrix<f64, M, M>,
        equations: &[usize],
        coordinates: &[usize],
        x: &mut SMatrix<f64, M, M>,
    ) -> (bool, f64) {
        let d = SMatrix::<f64, K, K>::from_fn(|r, s| a[(equations[r], coordinates[s])]);
        let inverse = invert_at_scale(&d);
        if inverse.rcond == 0.0 {
            return (false, inverse.det);
        }
        for (s, &row) in coordinates.iter().enumerate() {
            for (t, &c) in equations.iter().enumerate() {
                x[(row, c)] = inverse.inverse[(s, t)];
            }
        }
        (true, inverse.det)
    }
    match equations.len() {
        1 => small::<1, M>(a, equations, coordinates, x),
        2 => small::<2, M>(a, equations, coordinates, x),
        3 => small::<3, M>(a, equations, coordinates, x),
        k => {
            let mut work: Vec<f64> = (0..k * k)
                .map(|i| a[(equations[i / k], coordinates[i % k])])
                .collect();
            let (inverse, det) = gauss_jordan_rows(&mut work, k);
            let Some(inverse) = inverse else {
                return (false, det);
            };
            for (s, &row) in coordinates.iter().enumerate() {
                for (t, &c) in equations.iter().enumerate() {
                    x[(row, c)] = inverse[s * k + t];
                }
            }
            (inverse.iter().all(|v| v.is_finite()), det)
        }
    }
}

/// The inverse of the k×k matrix `work` (row by row) and its determinant,
/// by Gauss–Jordan elimination with partial pivoting; no inverse (and det
/// 0, or NaN) on a zero or non-finite pivot. `work` is spent.
fn gauss_jordan_rows(work: &mut [f64], k: usize) -> (Option<Vec<f64>>, f64) {
    let mut inverse = vec![0.0; k * k];
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
            return (None, if p == 0.0 { 0.0 } else { f64::NAN });
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
    (Some(inverse), det)
}

#[cfg(test)]
mod tests;
