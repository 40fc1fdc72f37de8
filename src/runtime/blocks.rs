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
    Inverse, adjugate, equilibrated_norm, invert, power_of_two_and_reciprocal, scale_of,
    scaled_determinant,
};
use crate::runtime::options::Options;
use nalgebra::SMatrix;

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
    /// and `ends` rises to n in more than one step; [`PsiUBlocks::DENSE`]
    /// otherwise (one block is the dense matrix).
    pub const fn new(equations: &'a [usize], coordinates: &'a [usize], ends: &'a [usize]) -> Self {
        let n = equations.len();
        let mut rising = ends.len() > 1 && ends[ends.len() - 1] == n && ends[0] > 0;
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

/// Up to this size Ψ_u is inverted whole ([`invert_in_blocks`]).
const SMALL: usize = 4;

/// `a` (Ψ_u) inverted block by block in the order of `blocks`: [`invert`]
/// itself up to m = 4, for one block, blocks of another size, or a matrix
/// that is not block lower triangular in their order (checked: every entry
/// of a block's equations beyond its own coordinates must be zero). As
/// [`invert`] does, a matrix at an extreme scale is scaled by a power of
/// two first, exactly, and `rcond` is 0 (the inverse meaningless) when a
/// diagonal block is singular or the inverse is not finite.
pub fn invert_in_blocks<const M: usize>(
    a: &SMatrix<f64, M, M>,
    blocks: PsiUBlocks<'_>,
) -> Inverse<M> {
    // Up to 4×4 the whole matrix is inverted as before: no faster by
    // blocks within the noise, and the numbers of the mechanisms of the
    // accuracy tables (m ≤ 4) stay the very numbers they were.
    if blocks.ends.len() <= 1 || blocks.equations.len() != M || M <= SMALL {
        return invert(a);
    }
    let (scale, ordinary) = scale_of(a);
    if ordinary || !(scale > 0.0 && scale.is_finite()) {
        return in_blocks_at_scale(a, blocks).unwrap_or_else(|| invert(a));
    }
    let (p, reciprocal) = power_of_two_and_reciprocal(scale);
    let Some(inner) = in_blocks_at_scale(&(a * reciprocal), blocks) else {
        return invert(a);
    };
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

/// [`invert_in_blocks`] at an ordinary scale; `None` if `a` is not block
/// lower triangular in the order of `blocks` (an entry of a block's
/// equations outside its own and the earlier blocks' coordinates is not
/// zero: blocks that are not this matrix's), which is then inverted whole.
fn in_blocks_at_scale<const M: usize>(
    a: &SMatrix<f64, M, M>,
    blocks: PsiUBlocks<'_>,
) -> Option<Inverse<M>> {
    let singular = |det: f64| Inverse {
        inverse: SMatrix::zeros(),
        rcond: 0.0,
        det,
    };
    // X = A⁻¹ maps equations to coordinates: its block (i, j) is
    // X[coordinates of i, equations of j], zero above the diagonal.
    let mut x = SMatrix::<f64, M, M>::zeros();
    let mut det = blocks.sign;
    // The entries of A that couple a block to the blocks before it, as
    // (row of the block, coordinate, value), at most M at a time.
    let mut couplings = [(0_usize, 0_usize, 0.0_f64); M];
    let mut start = 0;
    for (equations, coordinates) in blocks.blocks() {
        let (earlier_equations, earlier_coordinates) =
            (&blocks.equations[..start], &blocks.coordinates[..start]);
        start += equations.len();
        let later_coordinates = &blocks.coordinates[start..];
        for &equation in equations {
            // (A NaN is not zero either: inverted whole, it is singular.)
            if later_coordinates.iter().any(|&q| a[(equation, q)] != 0.0) {
                return None;
            }
        }
        let (regular, block_det) = invert_diagonal_block(a, equations, coordinates, &mut x);
        det *= block_det;
        if !regular {
            return Some(singular(det));
        }
        if earlier_equations.is_empty() {
            continue;
        }
        // T = Σ A[block's equations, q] X[q, earlier equations] over the
        // earlier coordinates q whose entry is not zero, row t of T (the
        // block's equation t) kept for now in X's row of its coordinate t;
        // column by column of X, which is contiguous.
        let flush = |couplings: &[(usize, usize, f64)], x: &mut SMatrix<f64, M, M>| {
            for &c in earlier_equations {
                let column = &mut x.as_mut_slice()[c * M..(c + 1) * M];
                for &(t, q, value) in couplings {
                    column[coordinates[t]] += value * column[q];
                }
            }
        };
        let mut found = 0;
        for (t, &equation) in equations.iter().enumerate() {
            for &q in earlier_coordinates {
                let value = a[(equation, q)];
                if value != 0.0 {
                    couplings[found] = (t, q, value);
                    found += 1;
                    if found == M {
                        flush(&couplings, &mut x);
                        found = 0;
                    }
                }
            }
        }
        flush(&couplings[..found], &mut x);
        // X[block's coordinates, c] = −D⁻¹ T[·, c], D⁻¹ in X's diagonal block.
        apply_inverse(&mut x, equations, coordinates, earlier_equations);
    }
    if !x.iter().all(|v| v.is_finite()) {
        return Some(singular(det));
    }
    let norm = equilibrated_norm(a, &x);
    Some(if norm.is_finite() && norm > 0.0 {
        Inverse {
            inverse: x,
            rcond: (1.0 / norm).min(1.0),
            det,
        }
    } else {
        singular(det)
    })
}

/// X[coordinates, c] = −D⁻¹ X[coordinates, c] for each column c of
/// `columns`, D⁻¹ = X[coordinates, equations] (the block's inverse, in
/// place): fixed sizes for blocks of up to 3, which are most.
fn apply_inverse<const M: usize>(
    x: &mut SMatrix<f64, M, M>,
    equations: &[usize],
    coordinates: &[usize],
    columns: &[usize],
) {
    fn fixed<const K: usize, const M: usize>(
        x: &mut SMatrix<f64, M, M>,
        equations: &[usize],
        coordinates: &[usize],
        columns: &[usize],
    ) {
        let mut inverse = [[0.0; K]; K];
        for (s, row) in inverse.iter_mut().enumerate() {
            for (t, entry) in row.iter_mut().enumerate() {
                *entry = x[(coordinates[s], equations[t])];
            }
        }
        let rows: [usize; K] = std::array::from_fn(|s| coordinates[s]);
        for &c in columns {
            let column = &mut x.as_mut_slice()[c * M..(c + 1) * M];
            let t: [f64; K] = std::array::from_fn(|s| column[rows[s]]);
            for (s, &row) in rows.iter().enumerate() {
                let mut sum = 0.0;
                for (d, value) in inverse[s].iter().zip(&t) {
                    sum += d * value;
                }
                column[row] = -sum;
            }
        }
    }
    match equations.len() {
        1 => fixed::<1, M>(x, equations, coordinates, columns),
        2 => fixed::<2, M>(x, equations, coordinates, columns),
        3 => fixed::<3, M>(x, equations, coordinates, columns),
        k => {
            // D⁻¹ read in place (its columns are not the earlier ones).
            let mut t = nalgebra::SVector::<f64, M>::zeros();
            for &c in columns {
                for (value, &row) in t.iter_mut().zip(coordinates) {
                    *value = x[(row, c)];
                }
                for &row in coordinates {
                    let mut sum = 0.0;
                    for (&equation, value) in equations.iter().zip(&t.as_slice()[..k]) {
                        sum += x[(row, equation)] * value;
                    }
                    x[(row, c)] = -sum;
                }
            }
        }
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
        let (adjugate, det) = adjugate(&d);
        let inverse = adjugate * (1.0 / det);
        // A zero or non-finite det, or an overflow, makes the sum non-finite.
        let finite = inverse.sum().abs() <= f64::MAX;
        if !finite {
            return (false, det);
        }
        for (s, &row) in coordinates.iter().enumerate() {
            for (t, &c) in equations.iter().enumerate() {
                x[(row, c)] = inverse[(s, t)];
            }
        }
        (true, det)
    }
    match equations.len() {
        1 => small::<1, M>(a, equations, coordinates, x),
        2 => small::<2, M>(a, equations, coordinates, x),
        3 => small::<3, M>(a, equations, coordinates, x),
        k => {
            // On the stack up to 8×8; a larger block is dense work that a
            // heap allocation does not weigh on.
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
                *w = a[(equations[i / k], coordinates[i % k])];
            }
            let (regular, det) = gauss_jordan_rows(work, inverse, k);
            if !regular {
                return (false, det);
            }
            for (s, &row) in coordinates.iter().enumerate() {
                for (t, &c) in equations.iter().enumerate() {
                    x[(row, c)] = inverse[s * k + t];
                }
            }
            (inverse.iter().all(|v| v.is_finite()), det)
        }
    }
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

#[cfg(test)]
mod tests;
