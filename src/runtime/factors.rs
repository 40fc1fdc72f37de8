//! Ψ_u factored for solving, with no explicit inverse where it has more than
//! one diagonal block. In its block lower triangular order ([`PsiUBlocks`])
//! only each diagonal block is inverted; a solve then runs block by block,
//! each block's right-hand side reduced by the coordinates already found
//! through the entries that couple it to them (block forward
//! substitution). Work and memory traffic grow with the entries inside the
//! blocks' reach, not with m²: for a chain of loops, linearly in m. The
//! reciprocal condition number is estimated from a few such solves, as
//! LAPACK's `xGECON` does ([`condition`]). Up to m = 4, and for a Ψ_u of one
//! block, the whole matrix is inverted by [`invert`], as before: the same
//! numbers, to the bit.

mod condition;
mod diagonal;

use crate::runtime::blocks::PsiUBlocks;
use crate::runtime::error::{Error, Stage};
use crate::runtime::linalg::{
    equilibrated_norm, invert, ordinary_scale, power_of_two_and_reciprocal, scaled_determinant,
};
use crate::runtime::options::Options;
use nalgebra::{SMatrix, SVector};

/// Up to this size Ψ_u is inverted whole.
const SMALL: usize = 4;

/// Ψ_u, factored for solving Ψ_u x = b ([`Factors::solve`]): its inverse
/// when inverted whole, its diagonal blocks' inverses in its block order
/// otherwise. `rcond` and `det` mean what [`Inverse`](crate::Inverse)'s do,
/// but for the estimate (see [`Factors::rcond`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Factors<const M: usize> {
    /// Whole: Ψ_u⁻¹. In blocks: Ψ_u with each diagonal block D replaced by
    /// D⁻¹, the entry of D⁻¹ for the block's coordinate t and equation s
    /// kept at (equation s, coordinate t): D's own place, transposed.
    packed: SMatrix<f64, M, M>,
    order: Order<M>,
    rcond: f64,
    det: f64,
}

/// The block order that [`Factors`] solves in, copied from [`PsiUBlocks`]
/// (O(m)): positions in the solve order, `blocks` 0 when inverted whole.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Order<const M: usize> {
    equations: [u16; M],
    coordinates: [u16; M],
    /// Where block b ends, and where its reach begins (the first position
    /// of a coordinate its equations involve).
    ends: [u16; M],
    reach: [u16; M],
    blocks: u16,
    /// The sign of the two orders as permutations: det Ψ_u is it times
    /// the product of the blocks' determinants.
    sign: f64,
}

impl<const M: usize> Order<M> {
    const WHOLE: Order<M> = Order {
        equations: [0; M],
        coordinates: [0; M],
        ends: [0; M],
        reach: [0; M],
        blocks: 0,
        sign: 1.0,
    };

    /// Block b as (start, end, reach), positions in the solve order.
    #[inline(always)]
    fn block(&self, b: usize) -> (usize, usize, usize) {
        let start = if b == 0 { 0 } else { self.ends[b - 1] as usize };
        (start, self.ends[b] as usize, self.reach[b] as usize)
    }

    #[inline(always)]
    fn equation(&self, position: usize) -> usize {
        self.equations[position] as usize
    }

    #[inline(always)]
    fn coordinate(&self, position: usize) -> usize {
        self.coordinates[position] as usize
    }
}

impl<const M: usize> Factors<M> {
    /// Ψ_u inverted whole ([`invert`]).
    #[inline(always)]
    pub fn whole(a: &SMatrix<f64, M, M>) -> Factors<M> {
        let inverse = invert(a);
        Factors {
            packed: inverse.inverse,
            order: Order::WHOLE,
            rcond: inverse.rcond,
            det: inverse.det,
        }
    }

    /// What an evaluation that could not run gives: the factors of a
    /// matrix of NaN, as [`Factors::whole`] makes them (singular: rcond 0,
    /// the packed factors zero), without the work.
    #[inline(always)]
    pub(crate) fn unfactored() -> Factors<M> {
        Factors {
            packed: SMatrix::zeros(),
            order: Order::WHOLE,
            rcond: 0.0,
            det: f64::NAN,
        }
    }

    /// Ψ_u factored in the order of `blocks`; inverted whole up to m = 4,
    /// for one block, or for blocks of another size.
    ///
    /// `blocks` must be Ψ_u's structure: every entry outside the blocks'
    /// reach (what [`PsiUBlocks::fits`] checks) is zero and never read,
    /// as the generated `PSI_U_BLOCKS` and a run-time mechanism's blocks
    /// are by construction. As [`invert`] does, a matrix at an extreme
    /// scale is scaled by a power of two first, exactly, and `rcond` is 0
    /// (the solves meaningless) when a diagonal block is singular or the
    /// estimate is not finite.
    #[inline(always)]
    pub fn of(a: &SMatrix<f64, M, M>, blocks: PsiUBlocks<'_>) -> Factors<M> {
        if inverted_whole::<M>(blocks) {
            return Factors::whole(a);
        }
        let order = Order::of(blocks);
        let (scale, columns) = order.scale_and_column_norms(a);
        if ordinary(scale) {
            return Factors::by_blocks(a, order, &columns);
        }
        Factors::scaled_by_blocks(a, order, &columns, scale)
    }

    /// [`Factors::of`] written over `self`: where Ψ_u is factored in
    /// blocks, `a` is copied once into the factors' own matrix and its
    /// blocks inverted there, so that an evaluation that keeps its
    /// results in place (a large m, whose m × m matrices are costly to
    /// move) builds no factors elsewhere to move in. The same numbers, bit
    /// for bit.
    #[inline]
    pub fn of_into(&mut self, a: &SMatrix<f64, M, M>, blocks: PsiUBlocks<'_>) {
        if inverted_whole::<M>(blocks) {
            *self = Factors::whole(a);
            return;
        }
        let order = Order::of(blocks);
        let (scale, columns) = order.scale_and_column_norms(a);
        if !ordinary(scale) {
            *self = Factors::scaled_by_blocks(a, order, &columns, scale);
            return;
        }
        self.packed.copy_from(a);
        self.order = order;
        self.rcond = 0.0;
        self.det = order.sign;
        if self.invert_diagonal_blocks() {
            self.rcond = condition::estimate(self, &columns);
        }
    }

    /// [`Factors::of`] and, where it factors in blocks, Ψ_u⁻¹ formed from
    /// the factors (one solve per column), for a caller that needs the
    /// whole inverse: rcond is then read from the inverse, exactly, as
    /// [`invert`] does, in place of the estimate. (At an extreme scale: the
    /// estimate. Inverted whole, the inverse is
    /// [`Factors::whole_inverse`].)
    pub(crate) fn of_with_inverse(
        a: &SMatrix<f64, M, M>,
        blocks: PsiUBlocks<'_>,
    ) -> (Factors<M>, Option<SMatrix<f64, M, M>>) {
        if inverted_whole::<M>(blocks) {
            return (Factors::whole(a), None);
        }
        let order = Order::of(blocks);
        if !ordinary(order.scale_and_column_norms(a).0) {
            let factors = Factors::of(a, blocks);
            return (factors, Some(factors.inverse()));
        }
        let (mut factors, regular) = Factors::factored(a, order);
        if !regular {
            return (factors, Some(SMatrix::zeros()));
        }
        let inverse = factors.inverse();
        let norm = equilibrated_norm(a, &inverse);
        if norm.is_finite() && norm > 0.0 && inverse.iter().all(|x| x.is_finite()) {
            factors.rcond = (1.0 / norm).min(1.0);
        }
        (factors, Some(inverse))
    }

    /// The column-equilibrated reciprocal condition number of Ψ_u in
    /// [0, 1], 0 if it is singular. Exact when inverted whole; in blocks
    /// the reciprocal of Hager and Higham's estimate of ‖D_c Ψ_u⁻¹‖₁
    /// (LAPACK's `xLACN2`), which never exceeds the norm: never smaller
    /// than the exact value, and in practice equal to it or within a small
    /// factor.
    pub fn rcond(&self) -> f64 {
        self.rcond
    }

    /// det Ψ_u (its sign tells the assembly branch).
    pub fn det(&self) -> f64 {
        self.det
    }

    /// Whether Ψ_u was factored block by block (not inverted whole).
    pub fn in_blocks(&self) -> bool {
        !self.is_whole()
    }

    /// Whether Ψ_u was inverted whole: always up to m = 4, known as the
    /// code is compiled, so that small mechanisms carry no branch for the
    /// blocks.
    #[inline(always)]
    fn is_whole(&self) -> bool {
        M <= SMALL || self.order.blocks == 0
    }

    /// x = Ψ_u⁻¹ b (meaningless if `rcond` is 0).
    #[inline(always)]
    pub fn solve(&self, b: &SVector<f64, M>) -> SVector<f64, M> {
        if self.is_whole() {
            return self.packed * b;
        }
        self.forward(b)
    }

    /// The factors themselves ([`Factors::solve_by`]): the inverse, or Ψ_u
    /// with its blocks inverted in place.
    #[inline(always)]
    pub(crate) fn packed(&self) -> &SMatrix<f64, M, M> {
        &self.packed
    }

    /// x = Ψ_u⁻¹ b with the factors `packed` of another pose of the same
    /// mechanism (a chord step, whose block order is this one's): what
    /// [`Factors::solve`] of that pose gives. Only the matrix is kept from
    /// pose to pose, which a small mechanism holds in registers.
    #[inline(always)]
    pub(crate) fn solve_by(
        &self,
        packed: &SMatrix<f64, M, M>,
        b: &SVector<f64, M>,
    ) -> SVector<f64, M> {
        if self.is_whole() {
            return packed * b;
        }
        self.forward_by(packed, b)
    }

    /// X = Ψ_u⁻¹ B, column by column.
    #[inline(always)]
    pub fn solve_columns<const C: usize>(&self, b: &SMatrix<f64, M, C>) -> SMatrix<f64, M, C> {
        if self.is_whole() {
            return self.packed * b;
        }
        let mut x = SMatrix::<f64, M, C>::zeros();
        for j in 0..C {
            x.set_column(j, &self.forward(&b.column(j).into_owned()));
        }
        x
    }

    /// The largest magnitude of an entry of Ψ_u⁻¹ when inverted whole; in
    /// blocks, of the inverses of its diagonal blocks (which are Ψ_u⁻¹'s
    /// own diagonal blocks: a lower bound, without the inverse).
    pub fn inverse_size(&self) -> f64 {
        if self.is_whole() {
            return self.packed.amax();
        }
        let order = &self.order;
        let mut size = 0.0_f64;
        for block in 0..order.blocks as usize {
            let (start, end, _) = order.block(block);
            for s in start..end {
                for t in start..end {
                    size = size.max(self.packed[(order.equation(s), order.coordinate(t))].abs());
                }
            }
        }
        size
    }

    /// Ψ_u⁻¹ when it was inverted whole (`None` in blocks).
    pub(crate) fn whole_inverse(&self) -> Option<&SMatrix<f64, M, M>> {
        self.is_whole().then_some(&self.packed)
    }

    /// Ψ_u⁻¹ itself: one solve per column when factored in blocks (O(m)
    /// solves), for those who need the whole inverse.
    pub fn inverse(&self) -> SMatrix<f64, M, M> {
        if self.is_whole() {
            return self.packed;
        }
        // Column e, for equation e of block f, is zero on the blocks before
        // f: each solve starts at its own block.
        let mut inverse = SMatrix::<f64, M, M>::zeros();
        for block in 0..self.order.blocks as usize {
            let (start, end, _) = self.order.block(block);
            for s in start..end {
                let e = self.order.equation(s);
                let unit = SVector::<f64, M>::from_fn(|i, _| f64::from(u8::from(i == e)));
                inverse.set_column(e, &self.forward_from(&self.packed, &unit, block));
            }
        }
        inverse
    }

    /// Block forward substitution: for each block in order, its equations'
    /// right-hand sides less what the coordinates already found contribute,
    /// times the block's inverse.
    fn forward(&self, b: &SVector<f64, M>) -> SVector<f64, M> {
        self.forward_by(&self.packed, b)
    }

    /// [`Factors::forward`] with another pose's packed factors in this
    /// order.
    fn forward_by(&self, a: &SMatrix<f64, M, M>, b: &SVector<f64, M>) -> SVector<f64, M> {
        self.forward_from(a, b, 0)
    }

    /// [`Factors::forward_by`] for a `b` that is zero on the equations of
    /// the blocks before `first`, whose coordinates then stay zero.
    fn forward_from(
        &self,
        a: &SMatrix<f64, M, M>,
        b: &SVector<f64, M>,
        first: usize,
    ) -> SVector<f64, M> {
        let order = &self.order;
        let mut x = SVector::<f64, M>::zeros();
        let mut reduced = [0.0; M];
        for block in first..order.blocks as usize {
            let (start, end, reach) = order.block(block);
            for (s, r) in (start..end).zip(&mut reduced[start..end]) {
                let e = order.equation(s);
                let mut sum = b[e];
                for p in reach..start {
                    let q = order.coordinate(p);
                    sum -= a[(e, q)] * x[q];
                }
                *r = sum;
            }
            for t in start..end {
                let c = order.coordinate(t);
                let mut sum = 0.0;
                for (s, r) in (start..end).zip(&reduced[start..end]) {
                    sum += a[(order.equation(s), c)] * r;
                }
                x[c] = sum;
            }
        }
        x
    }

    /// y = Ψ_u⁻ᵀ c (y by equations, c by coordinates), by block backward
    /// substitution: for each block from the last, y on its equations from
    /// the block's inverse transposed, then its contribution taken from
    /// the coordinates it reaches. Only factored in blocks.
    fn backward(&self, c: &SVector<f64, M>) -> SVector<f64, M> {
        let (a, order) = (&self.packed, &self.order);
        let mut c = *c;
        let mut y = SVector::<f64, M>::zeros();
        for block in (0..order.blocks as usize).rev() {
            let (start, end, reach) = order.block(block);
            for s in start..end {
                let e = order.equation(s);
                let mut sum = 0.0;
                for t in start..end {
                    let k = order.coordinate(t);
                    sum += a[(e, k)] * c[k];
                }
                y[e] = sum;
            }
            for p in reach..start {
                let q = order.coordinate(p);
                let mut sum = 0.0;
                for s in start..end {
                    let e = order.equation(s);
                    sum += a[(e, q)] * y[e];
                }
                c[q] -= sum;
            }
        }
        y
    }

    /// Factors at an ordinary scale: [`Factors::factored`], rcond
    /// estimated.
    #[inline(always)]
    fn by_blocks(a: &SMatrix<f64, M, M>, order: Order<M>, columns: &[f64; M]) -> Self {
        let (mut factors, regular) = Factors::factored(a, order);
        if regular {
            factors.rcond = condition::estimate(&factors, columns);
        }
        factors
    }

    /// The diagonal blocks inverted in place and the determinant as their
    /// product (rcond 0 for now), and whether every block is regular.
    /// Built where it is returned (a copy of a large Ψ_u less).
    #[inline(always)]
    fn factored(a: &SMatrix<f64, M, M>, order: Order<M>) -> (Self, bool) {
        let mut factors = Factors {
            packed: *a,
            order,
            rcond: 0.0,
            det: order.sign,
        };
        let regular = factors.invert_diagonal_blocks();
        (factors, regular)
    }

    /// Each diagonal block of `packed` (Ψ_u, in `order`) inverted in
    /// place, `det` (the orders' sign) multiplied by the blocks'
    /// determinants; whether every block is regular (the first singular
    /// one ends the work).
    #[inline]
    fn invert_diagonal_blocks(&mut self) -> bool {
        let (packed, order, det) = (&mut self.packed, &self.order, &mut self.det);
        for block in 0..order.blocks as usize {
            let (start, end, _) = order.block(block);
            let (ok, block_det) = diagonal::invert_in_place(
                packed,
                &order.equations[start..end],
                &order.coordinates[start..end],
            );
            *det *= block_det;
            if !ok {
                return false;
            }
        }
        true
    }

    /// [`Factors::by_blocks`] for a matrix at an extreme scale: factored
    /// as A·(1/p) (exact), whose rcond is A's, then the blocks' inverses
    /// scaled back by 1/p and the couplings restored; det = pᴹ·det(A/p).
    #[cold]
    #[inline(never)]
    fn scaled_by_blocks(
        a: &SMatrix<f64, M, M>,
        order: Order<M>,
        columns: &[f64; M],
        scale: f64,
    ) -> Self {
        let (p, reciprocal) = power_of_two_and_reciprocal(scale);
        let columns = columns.map(|c| c * reciprocal);
        let inner = Factors::by_blocks(&(a * reciprocal), order, &columns);
        let mut packed = *a;
        for block in 0..order.blocks as usize {
            let (start, end, _) = order.block(block);
            for s in start..end {
                for t in start..end {
                    let (e, k) = (order.equation(s), order.coordinate(t));
                    packed[(e, k)] = inner.packed[(e, k)] * reciprocal;
                }
            }
        }
        Factors {
            packed,
            order,
            rcond: inner.rcond,
            det: scaled_determinant::<M>(inner.det, p),
        }
    }
}

impl<const M: usize> Order<M> {
    /// The order of `blocks` (which has M positions and more than one
    /// block).
    fn of(blocks: PsiUBlocks<'_>) -> Order<M> {
        let mut order = Order::WHOLE;
        let (equations, coordinates, ends, reach) = blocks.lists();
        order.sign = blocks.sign();
        for p in 0..M {
            order.equations[p] = equations[p] as u16;
            order.coordinates[p] = coordinates[p] as u16;
        }
        for (b, (&end, &first)) in ends.iter().zip(reach).enumerate() {
            order.ends[b] = end as u16;
            order.reach[b] = first as u16;
        }
        order.blocks = ends.len() as u16;
        order
    }

    /// The largest magnitude of an entry inside the blocks' reach, and
    /// the 1-norm of each of A's columns, in one pass over the entries
    /// that can be nonzero. (A NaN entry is skipped by the largest and
    /// makes its column's norm NaN, which the estimate catches.)
    fn scale_and_column_norms(&self, a: &SMatrix<f64, M, M>) -> (f64, [f64; M]) {
        let mut columns = [0.0; M];
        let mut scale = 0.0_f64;
        for block in 0..self.blocks as usize {
            let (start, end, reach) = self.block(block);
            for s in start..end {
                let e = self.equation(s);
                for p in reach..end {
                    let k = self.coordinate(p);
                    let x = a[(e, k)].abs();
                    columns[k] += x;
                    if x > scale {
                        scale = x;
                    }
                }
            }
        }
        (scale, columns)
    }
}

/// Whether [`Factors::of`] inverts Ψ_u whole: up to m = 4, for one block,
/// for blocks of another size, and beyond the u16 positions are kept in.
fn inverted_whole<const M: usize>(blocks: PsiUBlocks<'_>) -> bool {
    M <= SMALL || M > u16::MAX as usize || blocks.len() <= 1 || blocks.positions() != M
}

/// Whether the largest entry `scale` needs no scaling ([`ordinary_scale`]),
/// or is zero or not finite (which the factors catch).
fn ordinary(scale: f64) -> bool {
    ordinary_scale(scale) || !(scale > 0.0 && scale.is_finite())
}

/// Ψ_u factored in the order of `blocks`, or [`Error::Singular`] in `stage`
/// if its reciprocal condition number is 0 or does not keep the requested
/// accuracy there ([`Options::keeps_accuracy`]).
#[inline(always)]
pub(crate) fn factor<const M: usize>(
    a: &SMatrix<f64, M, M>,
    blocks: PsiUBlocks<'_>,
    stage: Stage,
    options: &Options,
) -> Result<Factors<M>, Error> {
    let factors = Factors::of(a, blocks);
    options.require_accuracy(stage, factors.rcond)?;
    Ok(factors)
}

#[cfg(test)]
mod tests;
