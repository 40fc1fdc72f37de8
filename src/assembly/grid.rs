//! The roots of one block, the other coordinates held: Newton from the
//! centre of every cell of a grid over the block's coordinates (angles
//! over a turn, lengths over their box), then again from the start that
//! first reached each root with every root found deflated, on grids one
//! cell a coordinate finer each time, until `confirmations` refinements
//! in a row find no new root.

use super::newton::{BlockSystem, Run};
use super::settings::Search;
use crate::runtime::{Linkage, invert};
use nalgebra::SVector;
use std::f64::consts::{PI, TAU};

/// Two roots are one if their coordinates differ by less than this (in
/// the search's units, angles up to whole turns)...
const SAME_ROOT: f64 = 1e-8;
/// ... or by less than this where either is singular: a double root is
/// located only to about √ε, from either side.
const SAME_SINGULAR_ROOT: f64 = 1e-5;
/// A root of a block whose Jacobian (scale-free, its columns equilibrated)
/// has a reciprocal condition number below this is singular: a dead
/// centre, or within about this of one.
pub(crate) const SINGULAR_RCOND: f64 = 1e-6;
/// The most roots a block's search keeps from one pose of the blocks
/// before it: then it stops, and says it is not stable. A loop has a
/// handful; more are a coordinate that turns but is not 2π-periodic
/// (`(theta / 2).cos()`, searched as a length: a root every turn of its
/// box), whose every root deflation would slow the search of the next.
pub(crate) const MOST_ROOTS: usize = 64;

/// The roots of a block, and how the search for them went.
pub(crate) struct BlockRoots<const M: usize> {
    /// Each root's whole pose: the block's coordinates found, the others
    /// those held.
    pub roots: Vec<SVector<f64, M>>,
    /// Whether the set stood `confirmations` refinements.
    pub stable: bool,
    /// Newton's runs.
    pub runs: usize,
    /// The least scale-free residual any run met.
    pub least_residual: f64,
}

/// A root found, and whether its block is singular there.
struct Found<const M: usize> {
    u: SVector<f64, M>,
    singular: bool,
}

impl<L: Linkage<M, F> + ?Sized, const M: usize, const F: usize> BlockSystem<'_, L, M, F> {
    /// Every root of the block found from `held` (whose other coordinates
    /// are kept), by the refinements of `search`.
    pub fn roots(&self, held: &SVector<f64, M>, search: &Search) -> BlockRoots<M> {
        let d = self.block.coordinates.len();
        let mut found: Vec<Found<M>> = Vec::new();
        let mut runs = 0;
        let mut least = f64::INFINITY;
        let mut quiet = 0;
        let grid = |cells: usize| {
            u32::try_from(d)
                .ok()
                .and_then(|d| cells.checked_pow(d))
                .filter(|&count| count <= search.max_cells)
        };
        // The first grid as asked, or as fine as `max_cells` allows (at
        // least one cell: 3¹⁶ starts would take hours): then the search
        // is not what was asked, and not stable.
        let mut cells = (1..=search.first_cells)
            .rev()
            .find(|&n| grid(n).is_some())
            .unwrap_or(1);
        let coarser = cells < search.first_cells;
        let first = cells;
        let stable = loop {
            let Some(count) = grid(cells) else {
                break false;
            };
            let before = found.len();
            // Each root's first start on this grid.
            let mut first_start: Vec<Option<SVector<f64, M>>> = vec![None; found.len()];
            for cell in 0..count {
                let start = self.centre(held, cells, cell);
                let run = self.solve(&start, &[]);
                runs += 1;
                least = least.min(run.least_residual);
                if let Some(index) = self.record(&mut found, run) {
                    first_start.resize(found.len(), None);
                    first_start[index].get_or_insert(start);
                }
                if found.len() >= MOST_ROOTS {
                    break;
                }
            }
            // Deflation: from each root's first start, the roots found so
            // far pushed away, while it finds new ones.
            let mut k = 0;
            while k < first_start.len() && found.len() < MOST_ROOTS {
                if let Some(start) = first_start[k] {
                    while found.len() < MOST_ROOTS {
                        let known: Vec<SVector<f64, M>> = found.iter().map(|f| f.u).collect();
                        let run = self.solve(&start, &known);
                        runs += 1;
                        least = least.min(run.least_residual);
                        let count = found.len();
                        let index = self.record(&mut found, run);
                        if found.len() == count {
                            break;
                        }
                        first_start.resize(found.len(), None);
                        if let Some(index) = index {
                            first_start[index].get_or_insert(start);
                        }
                    }
                }
                k += 1;
            }
            if found.len() >= MOST_ROOTS {
                break false;
            }
            // Only a refinement that finds nothing new confirms the set.
            let refinement = cells > first;
            quiet = if found.len() > before || !refinement {
                0
            } else {
                quiet + 1
            };
            if quiet >= search.confirmations {
                break true;
            }
            cells += 1;
        };
        BlockRoots {
            roots: found.into_iter().map(|f| f.u).collect(),
            stable: stable && !coarser,
            runs,
            least_residual: least,
        }
    }

    /// The centre of cell `cell` (numbered with the block's first
    /// coordinate slowest) of the grid of `cells` cells a coordinate, the
    /// other coordinates those of `held`.
    fn centre(&self, held: &SVector<f64, M>, cells: usize, cell: usize) -> SVector<f64, M> {
        let mut u = *held;
        let mut rest = cell;
        for &j in self.block.coordinates.iter().rev() {
            let i = rest % cells;
            rest /= cells;
            let t = (i as f64 + 0.5) / cells as f64;
            u[j] = if self.scale.angle[j] {
                -PI + TAU * t
            } else {
                self.scale.lower[j] + (self.scale.upper[j] - self.scale.lower[j]) * t
            };
        }
        u
    }

    /// Adds the root of `run` to `found` unless it is there already;
    /// returns its index among them.
    fn record(&self, found: &mut Vec<Found<M>>, run: Run<M>) -> Option<usize> {
        let u = run.root?;
        let (_, j) = self.evaluate(&u)?;
        let singular = invert(&j).rcond < SINGULAR_RCOND;
        let close = |f: &Found<M>| {
            let tolerance = if singular || f.singular {
                SAME_SINGULAR_ROOT
            } else {
                SAME_ROOT
            };
            self.block
                .coordinates
                .iter()
                .all(|&j| self.scale.difference(j, u[j], f.u[j]).abs() <= tolerance)
        };
        if let Some(index) = found.iter().position(close) {
            return Some(index);
        }
        found.push(Found { u, singular });
        Some(found.len() - 1)
    }
}
