//! Why a search for the assemblies, or the pick of one, failed.

use crate::error::UnknownName;
use crate::runtime::Error;

/// Why the assemblies could not be found, or no single one picked.
///
/// ```
/// use linkage::assembly::{AssemblyError, Search, modes};
/// use linkage::mechanisms::FourBar;
/// use linkage::prelude::*;
///
/// // Coupler and rocker together reach 30; B is at least 60 from D.
/// let short = FourBar { l1: 80.0, l2: 20.0, l3: 10.0, l4: 20.0 };
/// let error = modes(&short, &vector![0.3], &Search::default()).unwrap_err();
/// assert!(matches!(error, AssemblyError::NoAssembly { .. }));
/// assert!(error.to_string().starts_with("the mechanism cannot be assembled"));
/// ```
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum AssemblyError {
    /// An argument is not finite, or a setting of the [`Search`](super::Search)
    /// is out of its range.
    Input(Error),
    /// The search met no real solution of Ψ(u, v) = 0: the mechanism
    /// cannot be assembled at this driver value (its links cannot close).
    /// The angles were searched over a whole turn, the lengths between
    /// `lower` and `upper` (the angles' entries there are −π and π);
    /// `least_residual` is the smallest scale-free residual
    /// max |Ψᵢ|/sᵢ that Newton's runs reached (sᵢ the size of equation i,
    /// [`Modes::equation_sizes`](super::Modes::equation_sizes)): how far
    /// from closing the mechanism came.
    NoAssembly {
        v: Vec<f64>,
        lower: Vec<f64>,
        upper: Vec<f64>,
        least_residual: f64,
        /// Whether every grid's (empty) set of roots stood its refinements;
        /// false if the search stopped at
        /// [`Search::max_cells`](super::Search::max_cells) first, when an
        /// assembly may have been missed.
        stable: bool,
    },
    /// Ψ_u is singular at every pose the search samples (its pattern
    /// there, the entries not 0 at one pose or another, has no perfect
    /// matching): no assembly can be regular, and none is searched for.
    /// `idle` are the coordinates no equation moves, if any — a coordinate
    /// whose every term has a factor 0, such as a link of length 0.
    SingularEverywhere { idle: Vec<usize> },
    /// A pick among assemblies none of which is regular: the mechanism is
    /// at a dead centre (Ψ_u singular), where two assemblies meet and
    /// cannot be told apart.
    AtDeadCentre { dead_centres: usize },
    /// [`Pick::Index`](super::Pick::Index) beyond the modes found.
    IndexOutOfRange { index: usize, modes: usize },
    /// No mode satisfies the pick (`pick` says which, in words).
    NoMatch { pick: String },
    /// More than one mode satisfies the pick, or two are equally near the
    /// sketch: `modes` are their indices.
    Ambiguous { pick: String, modes: Vec<usize> },
    /// A point the model does not have.
    UnknownName(UnknownName),
}

crate::error::error_impls! {
    AssemblyError {
        Self::Input(inner) => ("{inner}"),
        Self::NoAssembly { v, lower, upper, least_residual, stable: true } => (
            "the mechanism cannot be assembled at v = {v:?}: no real solution of Ψ(u, v) = 0 \
             with the angles over a whole turn and the lengths in [{lower:?}, {upper:?}] \
             (the closest it came leaves a scale-free residual of {least_residual:.3e})"
        ),
        Self::NoAssembly { v, lower, upper, least_residual, stable: false } => (
            "no assembly found at v = {v:?} with the angles over a whole turn and the lengths \
             in [{lower:?}, {upper:?}] (the closest it came leaves a scale-free residual of \
             {least_residual:.3e}), but the search stopped at Search::max_cells before its \
             grids stabilised: raise it to search further"
        ),
        Self::SingularEverywhere { idle } => (
            "Ψ_u is singular at every pose tried, so no assembly can be regular{}",
            if idle.is_empty() {
                String::new()
            } else {
                format!(
                    ": no equation moves the coordinates {idle:?} of u (a link of length 0?)"
                )
            }
        ),
        Self::AtDeadCentre { dead_centres } => (
            "the mechanism is at a dead centre: {dead_centres} singular assemblies (Ψ_u singular) \
             and no regular one, so no mode can be picked"
        ),
        Self::IndexOutOfRange { index, modes } => ("mode {index} asked for, but there are {modes} modes"),
        Self::NoMatch { pick } => ("no mode is {pick}"),
        Self::Ambiguous { pick, modes } => ("the modes {modes:?} are all {pick}: say which"),
        Self::UnknownName(inner) => ("{inner}"),
    }
    wraps { UnknownName(UnknownName) }
    sources { Input(Error) }
}
