//! How the assemblies are searched: the box of the lengths, the grids.

use super::error::AssemblyError;
use crate::runtime::Error;

/// Where the coordinates that are lengths (not angles) are searched.
///
/// ```
/// use linkage::assembly::{Lengths, Search, modes};
/// use linkage::mechanisms::OffsetSliderCrank;
/// use linkage::prelude::*;
///
/// let crank = OffsetSliderCrank { r: 0.05, l: 0.2, e: 0.01 };
/// // u = (θ3, s): the slider between 0 and 0.3 (θ3's entry is not read).
/// let right = Search { lengths: Lengths::Bounds(vec![(0.0, 0.0), (0.0, 0.3)]), ..Search::default() };
/// let found = modes(&crank, &vector![1.0], &right)?;
/// assert_eq!((found.lower[1], found.upper[1]), (0.0, 0.3));
/// # Ok::<(), linkage::assembly::AssemblyError>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Lengths {
    /// From the mechanism's own size (the default): each length within
    /// ±2·Σᵢ sᵢ / cⱼ, sᵢ the size of equation i and cⱼ the largest
    /// coefficient of the length in the equations — a box that holds every
    /// assembly of a mechanism written as vector loops
    /// ([`crate::assembly`] says why).
    #[default]
    FromScale,
    /// Every length within ±this.
    Within(f64),
    /// Each coordinate of u between its bounds (lower, upper), in u's
    /// order; an angle's entry is not read (angles range over a turn).
    Bounds(Vec<(f64, f64)>),
}

/// How to search for the assemblies ([`modes`](super::modes)).
///
/// [`Search::default`]: lengths from the mechanism's scale, a first grid
/// of 3 cells a coordinate, refined (one cell a coordinate more each
/// time) until two refinements in a row find no new assembly, grids of at
/// most 20 000 cells.
///
/// ```
/// use linkage::assembly::{Lengths, Search};
/// let search = Search { lengths: Lengths::Within(0.5), ..Search::default() };
/// assert_eq!(search.first_cells, 3);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Search {
    /// The box of the coordinates that are lengths.
    pub lengths: Lengths,
    /// Cells a coordinate on the first grid (at least 1); each refinement
    /// adds one.
    pub first_cells: usize,
    /// Refinements in a row that must find no new assembly before the set
    /// found is taken as complete (at least 1).
    pub confirmations: usize,
    /// The most cells (Newton starts) of a grid: a search that would need
    /// a larger one stops, and says it is not
    /// [`stable`](super::Modes::stable). A first grid larger than this
    /// (`first_cells`ᵈ for a block of d coordinates: 3¹⁰ = 59 049) is made
    /// coarser until it fits, down to one cell, and the search is not
    /// stable either.
    pub max_cells: usize,
}

impl Default for Search {
    fn default() -> Search {
        Search {
            lengths: Lengths::FromScale,
            first_cells: 3,
            confirmations: 2,
            max_cells: 20_000,
        }
    }
}

impl Search {
    /// The settings checked: counts at least 1, one pair of bounds per
    /// coordinate (the lengths' are checked with the angles known).
    pub(crate) fn check<const M: usize>(&self) -> Result<(), AssemblyError> {
        let invalid = |argument, value: f64, why| {
            Err(AssemblyError::Input(Error::InvalidInput {
                argument,
                value,
                why,
            }))
        };
        if self.first_cells == 0 {
            return invalid("Search::first_cells", 0.0, "a grid needs a cell");
        }
        if self.confirmations == 0 {
            return invalid("Search::confirmations", 0.0, "at least one refinement");
        }
        if self.max_cells < self.first_cells {
            return invalid(
                "Search::max_cells",
                self.max_cells as f64,
                "fewer cells than the first grid's",
            );
        }
        match &self.lengths {
            Lengths::FromScale => {}
            Lengths::Within(r) => {
                if !(r.is_finite() && *r > 0.0) {
                    return invalid("Lengths::Within", *r, "a positive, finite half-width");
                }
            }
            Lengths::Bounds(bounds) => {
                if bounds.len() != M {
                    return invalid(
                        "Lengths::Bounds",
                        bounds.len() as f64,
                        "one (lower, upper) per coordinate of u",
                    );
                }
            }
        }
        Ok(())
    }
}
