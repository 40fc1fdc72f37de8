//! Ψ_u factored for solving, with no explicit inverse where it has more than
//! one diagonal block. In its block lower triangular order ([`PsiUBlocks`])
//! only each diagonal block is inverted; a solve then runs block by block,
//! each block's right-hand side reduced by the coordinates already found
//! through the entries that couple it to them (block forward
//! substitution). Each block's equations over its reach are kept side by
//! side as one small panel (the common small blocks solved unrolled), so
//! that work and memory traffic grow with the entries inside the blocks'
//! reach, not with m²: for a chain of loops, linearly in m. The reciprocal
//! condition number is estimated from a few such solves, as LAPACK's
//! `xGECON` does ([`condition`]). Up to m = 4, and for a Ψ_u of one
//! block, the whole matrix is inverted by [`invert`], as before: the same
//! numbers, to the bit.

mod condition;
mod diagonal;
mod structured;

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
#[derive(Clone, Copy, Debug)]
pub struct Factors<const M: usize> {
    /// Whole: Ψ_u⁻¹. In blocks: one panel a block, the panels one after
    /// the other from the start of the storage ([`Order::panel`]); the
    /// rest of the storage is never read.
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
    /// Where block b's panel begins in the storage.
    panels: [u32; M],
    blocks: u16,
    /// The sign of the two orders as permutations: det Ψ_u is it times
    /// the product of the blocks' determinants.
    sign: f64,
}

/// Block b's panel: the entries of Ψ_u on the block's equations (rows, in
/// the block's order) and the coordinates of its reach (columns, in the
/// solve order), row by row, `width` = end − reach to a row. The last
/// `end − start` columns, the diagonal block D, hold D⁻¹ transposed once
/// factored: the entry of D⁻¹ for coordinate t and equation s at equation
/// s's row and coordinate t's column, D's own place.
#[derive(Clone, Copy)]
struct Panel {
    offset: usize,
    start: usize,
    end: usize,
    reach: usize,
}

impl Panel {
    fn width(&self) -> usize {
        self.end - self.reach
    }

    fn len(&self) -> usize {
        (self.end - self.start) * self.width()
    }

    fn range(&self) -> std::ops::Range<usize> {
        self.offset..self.offset + self.len()
    }
}

impl<const M: usize> Order<M> {
    const WHOLE: Order<M> = Order {
        equations: [0; M],
        coordinates: [0; M],
        ends: [0; M],
        reach: [0; M],
        panels: [0; M],
        blocks: 0,
        sign: 1.0,
    };

    /// Block b as (start, end, reach), positions in the solve order.
    #[inline(always)]
    fn block(&self, b: usize) -> (usize, usize, usize) {
        let start = if b == 0 { 0 } else { self.ends[b - 1] as usize };
        (start, self.ends[b] as usize, self.reach[b] as usize)
    }

    /// Block b's panel.
    #[inline(always)]
    fn panel(&self, b: usize) -> Panel {
        let (start, end, reach) = self.block(b);
        Panel {
            offset: self.panels[b] as usize,
            start,
            end,
            reach,
        }
    }

    /// How much of the storage the panels take.
    fn stored(&self) -> usize {
        match self.blocks as usize {
            0 => M * M,
            blocks => self.panel(blocks - 1).range().end,
        }
    }

    #[inline(always)]
    fn equation(&self, position: usize) -> usize {
        self.equations[position] as usize
    }

    /// The block that holds `position`.
    #[inline(always)]
    fn block_of(&self, position: usize) -> usize {
        let ends = &self.ends[..self.blocks as usize];
        ends.iter()
            .position(|&end| position < end as usize)
            .unwrap_or(0)
    }

    /// Values by position in the solve order, by coordinate.
    #[inline(always)]
    fn by_coordinates(&self, found: &[f64; M]) -> SVector<f64, M> {
        let mut x = SVector::<f64, M>::zeros();
        for (&c, &found) in self.coordinates.iter().zip(found) {
            x[c as usize] = found;
        }
        x
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
        let mut factors = Factors::unfactored();
        factors.of_into(a, blocks);
        factors
    }

    /// [`Factors::of`] written over `self`: where Ψ_u is factored in
    /// blocks, the entries inside the blocks' reach are gathered into the
    /// factors' own panels and the blocks inverted there, so that an
    /// evaluation that keeps its results in place (a large m, whose m × m
    /// matrices are costly to move) builds no factors elsewhere to move
    /// in. The same numbers, bit for bit.
    #[inline]
    pub fn of_into(&mut self, a: &SMatrix<f64, M, M>, blocks: PsiUBlocks<'_>) {
        if inverted_whole::<M>(blocks) {
            *self = Factors::whole(a);
            return;
        }
        self.order = Order::of(blocks);
        let (scale, columns) = self.gather(a);
        if !ordinary(scale) {
            self.factor_scaled(&columns, scale);
            return;
        }
        self.factor(&columns);
    }

    /// The panels gathered from `a` factored: the diagonal blocks
    /// inverted, det their determinants' product, rcond estimated from
    /// A's column norms `columns` (0 if a block is singular).
    #[inline(always)]
    fn factor(&mut self, columns: &[f64; M]) {
        self.rcond = 0.0;
        self.det = self.order.sign;
        if self.invert_diagonal_blocks() {
            self.rcond = condition::estimate(self, columns);
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
        let mut factors = Factors::unfactored();
        factors.order = Order::of(blocks);
        if !ordinary(factors.gather(a).0) {
            let factors = Factors::of(a, blocks);
            return (factors, Some(factors.inverse()));
        }
        factors.det = factors.order.sign;
        if !factors.invert_diagonal_blocks() {
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

    /// The factors themselves copied into `kept`, for [`Factors::solve_by`]
    /// at another pose: the inverse, or the panels (what they take of the
    /// storage only).
    #[inline(always)]
    pub(crate) fn keep_in(&self, kept: &mut SMatrix<f64, M, M>) {
        if self.is_whole() {
            kept.copy_from(&self.packed);
            return;
        }
        let stored = self.order.stored();
        kept.as_mut_slice()[..stored].copy_from_slice(&self.packed.as_slice()[..stored]);
    }

    /// The part of the storage the factors take: the inverse, or the
    /// panels.
    fn stored(&self) -> &[f64] {
        &self.packed.as_slice()[..self.order.stored()]
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
        let mut size = 0.0_f64;
        for block in 0..self.order.blocks as usize {
            let panel = self.order.panel(block);
            let diagonal = panel.start - panel.reach;
            for row in self.packed.as_slice()[panel.range()].chunks_exact(panel.width()) {
                for x in &row[diagonal..] {
                    size = size.max(x.abs());
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
        let mut inverse = SMatrix::<f64, M, M>::zeros();
        for block in 0..self.order.blocks as usize {
            let (start, end, _) = self.order.block(block);
            for s in start..end {
                let e = self.order.equation(s);
                inverse.set_column(e, &self.unit_forward_from(e, block));
            }
        }
        inverse
    }

    /// Ψ_u⁻¹'s column for equation `e`, the solve with the unit vector
    /// there, in blocks: zero on the blocks before e's, so the solve
    /// starts at e's block (the same numbers as from the first block,
    /// where nothing is added to a zero but zeros).
    fn unit_forward(&self, e: usize) -> SVector<f64, M> {
        let position = self.order.equations.iter().position(|&q| q as usize == e);
        self.unit_forward_from(e, self.order.block_of(position.unwrap_or(0)))
    }

    /// [`Factors::unit_forward`] for equation `e` of block `block`.
    fn unit_forward_from(&self, e: usize, block: usize) -> SVector<f64, M> {
        let unit = SVector::<f64, M>::from_fn(|i, _| f64::from(u8::from(i == e)));
        self.forward_from(&self.packed, &unit, block)
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
        // x by position in the solve order, each block's from the block
        // before it; by coordinate at the end.
        let mut found = [0.0; M];
        for block in first..order.blocks as usize {
            forward_step(order, a, block, b, &mut found);
        }
        order.by_coordinates(&found)
    }

    /// [`Factors::forward`] of two right-hand sides, their steps block by
    /// block in turn: the same numbers, but the two chains of blocks, which
    /// do not wait for each other, overlap.
    fn forward_pair(
        &self,
        b: &SVector<f64, M>,
        c: &SVector<f64, M>,
    ) -> (SVector<f64, M>, SVector<f64, M>) {
        let order = &self.order;
        let (mut found_b, mut found_c) = ([0.0; M], [0.0; M]);
        for block in 0..order.blocks as usize {
            forward_step(order, &self.packed, block, b, &mut found_b);
            forward_step(order, &self.packed, block, c, &mut found_c);
        }
        (
            order.by_coordinates(&found_b),
            order.by_coordinates(&found_c),
        )
    }

    /// y = Ψ_u⁻ᵀ c (y by equations, c by coordinates), by block backward
    /// substitution: for each block from the last, y on its equations from
    /// the block's inverse transposed, then its contribution taken from
    /// the coordinates it reaches. Only factored in blocks.
    fn backward(&self, c: &SVector<f64, M>) -> SVector<f64, M> {
        let order = &self.order;
        // c by position in the solve order.
        let mut left = [0.0; M];
        for (left, &k) in left.iter_mut().zip(&order.coordinates) {
            *left = c[k as usize];
        }
        let mut y = SVector::<f64, M>::zeros();
        let mut found = [0.0; M];
        for block in (0..order.blocks as usize).rev() {
            let panel = order.panel(block);
            let (start, end, reach) = (panel.start, panel.end, panel.reach);
            let entries = &self.packed.as_slice()[panel.range()];
            let (reached, this) = left.split_at_mut(start);
            let found = &mut found[..end - start];
            backward_block(entries, &this[..end - start], found, &mut reached[reach..]);
            for (&e, &y_s) in order.equations[start..end].iter().zip(found.iter()) {
                y[e as usize] = y_s;
            }
        }
        y
    }

    /// The entries of `a` inside the blocks' reach gathered into the
    /// panels of `self.order`, with the largest magnitude among them and
    /// the 1-norm of each of A's columns, in one pass over the entries
    /// that can be nonzero. (A NaN entry is skipped by the largest and
    /// makes its column's norm NaN, which the estimate catches.)
    #[inline(always)]
    fn gather(&mut self, a: &SMatrix<f64, M, M>) -> (f64, [f64; M]) {
        let (order, packed) = (&self.order, self.packed.as_mut_slice());
        let mut columns = [0.0; M];
        let mut scale = 0.0_f64;
        for block in 0..order.blocks as usize {
            let panel = order.panel(block);
            let rows = packed[panel.range()].chunks_exact_mut(panel.width());
            let coordinates = &order.coordinates[panel.reach..panel.end];
            for (row, &e) in rows.zip(&order.equations[panel.start..panel.end]) {
                for (entry, &k) in row.iter_mut().zip(coordinates) {
                    let x = a[(e as usize, k as usize)];
                    *entry = x;
                    let x = x.abs();
                    columns[k as usize] += x;
                    if x > scale {
                        scale = x;
                    }
                }
            }
        }
        (scale, columns)
    }

    /// Each diagonal block of the panels inverted in place, `det` (the
    /// orders' sign) multiplied by the blocks' determinants; whether every
    /// block is regular (the first singular one ends the work).
    #[inline]
    fn invert_diagonal_blocks(&mut self) -> bool {
        let (packed, order, det) = (self.packed.as_mut_slice(), &self.order, &mut self.det);
        for block in 0..order.blocks as usize {
            let panel = order.panel(block);
            let (ok, block_det) = diagonal::invert_in_panel(
                &mut packed[panel.range()],
                panel.width(),
                panel.start - panel.reach,
            );
            *det *= block_det;
            if !ok {
                return false;
            }
        }
        true
    }

    /// [`Factors::factor`] for panels at an extreme scale: factored as
    /// A·(1/p) (exact), whose rcond is A's, then the blocks' inverses
    /// scaled back by 1/p, the couplings A's own; det = pᴹ·det(A/p).
    #[cold]
    #[inline(never)]
    fn factor_scaled(&mut self, columns: &[f64; M], scale: f64) {
        let (p, reciprocal) = power_of_two_and_reciprocal(scale);
        let columns = columns.map(|c| c * reciprocal);
        let mut inner = *self;
        let stored = self.order.stored();
        for x in &mut inner.packed.as_mut_slice()[..stored] {
            *x *= reciprocal;
        }
        inner.factor(&columns);
        for block in 0..self.order.blocks as usize {
            let panel = self.order.panel(block);
            let diagonal = panel.start - panel.reach;
            let rows = self.packed.as_mut_slice()[panel.range()].chunks_exact_mut(panel.width());
            let inner_rows = inner.packed.as_slice()[panel.range()].chunks_exact(panel.width());
            for (row, inner_row) in rows.zip(inner_rows) {
                for (x, y) in row[diagonal..].iter_mut().zip(&inner_row[diagonal..]) {
                    *x = y * reciprocal;
                }
            }
        }
        self.rcond = inner.rcond;
        self.det = scaled_determinant::<M>(inner.det, p);
    }
}

/// The same factors: the same order, rcond and det, and the same numbers
/// in the part of the storage they take.
impl<const M: usize> PartialEq for Factors<M> {
    fn eq(&self, other: &Self) -> bool {
        self.order == other.order
            && self.rcond == other.rcond
            && self.det == other.det
            && self.stored() == other.stored()
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
        let mut offset = 0;
        for b in 0..ends.len() {
            order.panels[b] = offset as u32;
            offset = order.panel(b).range().end;
        }
        order
    }
}

/// The blocks solved by unrolled code, as (K, D): K×K blocks reaching D
/// coordinates back, up to 3×3 and 4 back (the common ones), given to the
/// macro `$then`.
macro_rules! unrolled_sizes {
    ($then:ident) => {
        $then!(
            (1, 0),
            (1, 1),
            (1, 2),
            (1, 3),
            (1, 4),
            (2, 0),
            (2, 1),
            (2, 2),
            (2, 3),
            (2, 4),
            (3, 0),
            (3, 1),
            (3, 2),
            (3, 3),
            (3, 4)
        )
    };
}

/// Block `block`'s step of the forward substitution with the factors
/// `a` in `order`: its coordinates, by position, into `found`.
#[inline(always)]
fn forward_step<const M: usize>(
    order: &Order<M>,
    a: &SMatrix<f64, M, M>,
    block: usize,
    b: &SVector<f64, M>,
    found: &mut [f64; M],
) {
    let panel = order.panel(block);
    let (start, end, reach) = (panel.start, panel.end, panel.reach);
    let entries = &a.as_slice()[panel.range()];
    let equations = &order.equations[start..end];
    let (before, this) = found.split_at_mut(start);
    let (known, this) = (&before[reach..], &mut this[..end - start]);
    forward_block::<M>(entries, b.as_slice(), equations, known, this);
}

/// One block's step of the forward substitution: its equations' right-hand
/// sides (`b` at `equations`) less its panel's couplings (`entries`, a row
/// an equation) times the coordinates `known` already found, times its
/// inverse (the panel's last columns, transposed), into `found`. The
/// blocks of `unrolled_sizes` run unrolled; the same operations in the
/// same order as any other.
#[inline(always)]
fn forward_block<const M: usize>(
    entries: &[f64],
    b: &[f64],
    equations: &[u16],
    known: &[f64],
    found: &mut [f64],
) {
    macro_rules! unrolled {
        ($(($k:literal, $d:literal)),*) => {
            match (found.len(), known.len()) {
                $(($k, $d) => {
                    if let (Ok(known), Ok(found)) = (known.try_into(), found.try_into()) {
                        return forward_unrolled::<$k, $d>(entries, b, equations, known, found);
                    }
                })*
                _ => {}
            }
        };
    }
    unrolled_sizes!(unrolled);
    forward_general::<M>(entries, b, equations, known, found);
}

/// [`forward_block`] for a block of any size, by loops.
#[inline(always)]
fn forward_general<const M: usize>(
    entries: &[f64],
    b: &[f64],
    equations: &[u16],
    known: &[f64],
    found: &mut [f64],
) {
    let (k, diagonal) = (found.len(), known.len());
    let width = k + diagonal;
    // (A block has at most M equations.)
    let mut reduced = [0.0; M];
    let reduced = &mut reduced[..k];
    for ((r, row), &e) in reduced
        .iter_mut()
        .zip(entries.chunks_exact(width))
        .zip(equations)
    {
        let mut sum = b[e as usize];
        for (entry, x) in row.iter().zip(known) {
            sum -= entry * x;
        }
        *r = sum;
    }
    for (t, x) in found.iter_mut().enumerate() {
        let rows = entries.chunks_exact(width).zip(reduced.iter());
        *x = summed(rows.map(|(row, r)| row[diagonal + t] * r));
    }
}

/// [`forward_block`] for a K×K block reaching D coordinates back.
#[inline(always)]
fn forward_unrolled<const K: usize, const D: usize>(
    entries: &[f64],
    b: &[f64],
    equations: &[u16],
    known: &[f64; D],
    found: &mut [f64; K],
) {
    let width = K + D;
    let mut reduced = [0.0; K];
    for (i, r) in reduced.iter_mut().enumerate() {
        let row = &entries[i * width..(i + 1) * width];
        let mut sum = b[equations[i] as usize];
        for j in 0..D {
            sum -= row[j] * known[j];
        }
        *r = sum;
    }
    for (t, x) in found.iter_mut().enumerate() {
        let rows = reduced.iter().enumerate();
        *x = summed(rows.map(|(i, r)| entries[i * width + D + t] * r));
    }
}

/// One block's step of the backward substitution (with Ψ_u transposed):
/// y on its equations, `found`, from its inverse transposed times what is
/// `left` of c on its coordinates; then its couplings' part taken from
/// what is left of c on the coordinates it reaches, `reached`.
#[inline(always)]
fn backward_block(entries: &[f64], left: &[f64], found: &mut [f64], reached: &mut [f64]) {
    macro_rules! unrolled {
        ($(($k:literal, $d:literal)),*) => {
            match (found.len(), reached.len()) {
                $(($k, $d) => {
                    if let (Ok(left), Ok(found), Ok(reached)) =
                        (left.try_into(), found.try_into(), reached.try_into())
                    {
                        return backward_unrolled::<$k, $d>(entries, left, found, reached);
                    }
                })*
                _ => {}
            }
        };
    }
    unrolled_sizes!(unrolled);
    backward_general(entries, left, found, reached);
}

/// [`backward_block`] for a block of any size, by loops.
#[inline(always)]
fn backward_general(entries: &[f64], left: &[f64], found: &mut [f64], reached: &mut [f64]) {
    let (k, diagonal) = (found.len(), reached.len());
    let width = k + diagonal;
    for (y, row) in found.iter_mut().zip(entries.chunks_exact(width)) {
        *y = summed(row[diagonal..].iter().zip(left).map(|(entry, c)| entry * c));
    }
    for (j, c) in reached.iter_mut().enumerate() {
        let rows = entries.chunks_exact(width).zip(found.iter());
        *c -= summed(rows.map(|(row, y)| row[j] * y));
    }
}

/// [`backward_block`] for a K×K block reaching D coordinates back.
#[inline(always)]
fn backward_unrolled<const K: usize, const D: usize>(
    entries: &[f64],
    left: &[f64; K],
    found: &mut [f64; K],
    reached: &mut [f64; D],
) {
    let width = K + D;
    for (i, y) in found.iter_mut().enumerate() {
        let row = &entries[i * width..(i + 1) * width];
        *y = summed((0..K).map(|t| row[D + t] * left[t]));
    }
    for (j, c) in reached.iter_mut().enumerate() {
        let rows = found.iter().enumerate();
        *c -= summed(rows.map(|(i, y)| entries[i * width + j] * y));
    }
}

/// The products summed in order from the first, not from 0.0: adding a
/// zero first would lengthen each block's chain of dependent operations
/// by an addition, and change nothing but a −0 result into +0.
#[inline(always)]
fn summed(mut products: impl Iterator<Item = f64>) -> f64 {
    let first = products.next().unwrap_or(0.0);
    products.fold(first, |sum, p| sum + p)
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
