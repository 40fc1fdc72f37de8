//! Assembly without a guess: every real solution u of Ψ(u, v) = 0 at a
//! driver value, found by a deterministic search, each regular one an
//! assembly [`Mode`] with its branch signs, and one picked by index, by a
//! point's side of a line, or as the one nearest a sketch.
//!
//! ```
//! use linkage::assembly::{Assemble, Pick, Search};
//! use linkage::mechanisms::FourBar;
//! use linkage::prelude::*;
//!
//! let bar = FourBar::WORKSHEET;
//! let theta2 = vector![20f64.to_radians()];
//! let found = bar.assembly_modes(&theta2, &Search::default())?;
//! assert_eq!(found.modes.len(), 2);
//! // The mode with C to the left of B → D, then analysed as usual.
//! let mode = bar.assemble(&theta2, &Pick::left_of("C", "B", vector![80.0, 0.0]))?;
//! let pose = bar.analyze(&mode.u, &theta2, &vector![1.0], &vector![0.0], &Options::default())?;
//! assert_eq!(pose.iterations, 1); // the mode is a root already
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! ## The method
//!
//! 1. **The mechanism's size, from its equations.** The coordinates that
//!    are angles are those under a sine or cosine (`theta.cos()`, or
//!    `(theta + beta).cos()`) of which Ψ is 2π-periodic (checked at sample
//!    poses); the others are lengths. Each equation's size
//!    sᵢ is the largest, over eight sample poses (angles spread over a
//!    turn, lengths 0), of |Ψᵢ| + Σ_(j angle) |∂Ψᵢ/∂uⱼ|, and residuals are
//!    judged scale-free, as max |Ψᵢ|/sᵢ.
//! 2. **The box.** Angles range over one turn. Lengths range over
//!    ±2·Σᵢ sᵢ / cⱼ (cⱼ the largest coefficient of the length in the
//!    equations), or over the box of [`Search::lengths`].
//! 3. **The loops.** The pattern of Ψ_u is ordered block-triangularly
//!    ([`Block`]): each block of equations involves only its own
//!    coordinates and those of earlier blocks, so the blocks are solved
//!    one after the other, each for every root of those before it. A Watt
//!    six-bar is searched as two problems of two coordinates each, not one
//!    of four.
//! 4. **The grid.** For a block, Newton's method (damped, scale-free) runs
//!    from the centre of every cell of a grid of n cells a coordinate
//!    (n = 3 first), then again from the start that first reached each
//!    root, with every root found deflated (Newton on
//!    Πₖ(1/‖u − uₖ‖² + 1)·Ψ, whose roots are Ψ's but the uₖ, so that known
//!    roots repel: a root whose basin a neighbour's swallows is found
//!    there). The grid is refined (n + 1) until two refinements in a row
//!    find no new root ([`Search::confirmations`]). A run may end at a
//!    root outside the box: it is an assembly, and kept.
//!
//!    The work is bounded whatever the equations: no grid has more than
//!    [`Search::max_cells`] cells (a block of many coordinates starts on a
//!    coarser grid), a block keeps at most 64 roots from one pose of the
//!    blocks before it and the next block is searched from at most 256;
//!    a search cut short so says it is not [`Modes::stable`].
//! 5. **The roots.** Each is polished by plain Newton steps to full
//!    precision and kept if its scale-free residual is below 1e-12; two
//!    are one if they differ by less than 1e-8 (angles up to whole turns
//!    only, lengths in units of their box). A root whose Ψ_u is singular
//!    (scale-free reciprocal condition number below 1e-6: the mechanism
//!    at a dead centre) is a [`DeadCentre`], reported once, not as two
//!    modes.
//! 6. **The order.** Modes are ordered by their signs (the determinant of
//!    each block of Ψ_u: for a four-bar, the side of BD its joint C is on),
//!    then by their coordinates: the same mechanism and driver give the
//!    same modes in the same order.
//!
//! ## What is proved, and what is not
//!
//! - Every mode returned **is** an assembly: Ψ(u, v) = 0 to a scale-free
//!   residual below 1e-12, with Ψ_u regular (so an isolated solution, on a
//!   branch a sweep can follow).
//! - The default box **holds every assembly** of a mechanism written as
//!   vector loops: each pair of equations a sum of constant vectors, the
//!   drivers' terms, rigid vectors turning with one angle coordinate each
//!   (lₖ(cos θₖ, sin θₖ), or any sum of such on one body), and lengths
//!   along unit vectors (one per loop, or along orthogonal ones, as a
//!   point's x and y). Then a length times its coefficient κ is at most
//!   |c| + Σₖ|lₖ| in size (c the loop's constant vector), and the sizes
//!   bound that: at any sample pose sₓ + s_y ≥ Σₖ|lₖ|(|sin θₖ| + |cos θₖ|)
//!   ≥ Σₖ|lₖ| and sₓ + s_y ≥ |cₓ| + |c_y| ≥ |c|, so 2·Σᵢ sᵢ / cⱼ ≥
//!   (|c| + Σₖ|lₖ|)/|κ| (as cⱼ ≤ |κ|).
//! - That **every** assembly in the box is found is **not** proved: it is
//!   a search. A root whose every basin of attraction falls between the
//!   grid's centres on three grids in a row, and that deflation from its
//!   neighbours' starts does not reach, is missed. Nothing here uses
//!   interval arithmetic (a Krawczyk test would prove a box free of roots;
//!   the generated code is generic over dual numbers, not intervals).
//!   [`Modes::stable`] says whether the set stood the refinements; the
//!   tests compare the counts and the coordinates with an independent
//!   elimination to a univariate polynomial at 50 digits.
//! - Two distinct assemblies closer than about 1e-6 (a mechanism within
//!   about 1e-12 of a dead centre in its driver) may be reported as one
//!   dead centre.
//!
//! ## Cost
//!
//! A four-bar takes about 60 Newton runs, a Watt six-bar 170, a
//! Stephenson III six-bar (one block of four) about a thousand ([`Modes::runs`]
//! counts them): measured with `cargo run --release --example assembly` on
//! a two-core machine busy with other builds, 0.12–0.16 ms, 0.75–1.0 ms
//! and 5.5–7.7 ms.

mod error;
mod grid;
mod modes;
mod newton;
mod pick;
mod scale;
mod search;
mod settings;
mod structure;

pub use error::AssemblyError;
pub use modes::{DeadCentre, Mode, Modes, Sign};
pub use pick::{Pick, Side, Spot};
pub use search::modes;
pub use settings::{Lengths, Search};
pub use structure::Block;

use crate::runtime::Linkage;
use nalgebra::SVector;

/// The search as methods of every mechanism: `model.assembly_modes(&v,
/// &search)` and `model.assemble(&v, &pick)`.
///
/// ```
/// use linkage::assembly::{Assemble, Pick, Search};
/// use linkage::mechanisms::OffsetSliderCrank;
/// use linkage::prelude::*;
///
/// let crank = OffsetSliderCrank { r: 0.05, l: 0.2, e: 0.01 };
/// // The slider to the right of the crank's pivot: s > 0.
/// let mode = crank.assemble(&vector![1.0], &Pick::nearest(vector![0.0, 0.2]))?;
/// assert!(mode.u[1] > 0.0);
/// # Ok::<(), linkage::assembly::AssemblyError>(())
/// ```
pub trait Assemble<const M: usize, const F: usize>: Linkage<M, F> {
    /// [`modes`]: every assembly found at `v`.
    fn assembly_modes(
        &self,
        v: &SVector<f64, F>,
        search: &Search,
    ) -> Result<Modes<M, F>, AssemblyError>;

    /// The mode `pick` chooses among those the default search finds at
    /// `v` ([`modes`], then [`Modes::pick`]).
    fn assemble(&self, v: &SVector<f64, F>, pick: &Pick<M>) -> Result<Mode<M>, AssemblyError>;
}

impl<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize> Assemble<M, F> for L {
    fn assembly_modes(
        &self,
        v: &SVector<f64, F>,
        search: &Search,
    ) -> Result<Modes<M, F>, AssemblyError> {
        modes(self, v, search)
    }

    fn assemble(&self, v: &SVector<f64, F>, pick: &Pick<M>) -> Result<Mode<M>, AssemblyError> {
        modes(self, v, &Search::default())?.pick(pick).cloned()
    }
}
