//! What can go wrong in making a run-time mechanism or a view of it.

use linkage_symbolic::diagnostics::Diagnostics;
use std::fmt;

/// Why a run-time mechanism could not be made, or viewed at given sizes.
#[derive(Debug)]
#[non_exhaustive]
pub enum MechanismError {
    /// The text (or the file) has mistakes: every one of them, located.
    Mistakes(Diagnostics),
    /// A view was asked for at sizes that are not the mechanism's.
    Sizes {
        /// (m, f) asked for.
        asked: (usize, usize),
        /// (m, f) of the mechanism.
        has: (usize, usize),
    },
    /// A view can hold at most `most` named points.
    TooManyPoints { points: usize, most: usize },
    /// A view with k parameters asked of a mechanism with another number.
    Parameters { asked: usize, has: usize },
    /// A view with room for `most` parameters asked to differentiate by
    /// more.
    TooManyParameters { parameters: usize, most: usize },
    /// A parameter the mechanism has but is not differentiated by (not in
    /// its `params = [...]`).
    NotDifferentiated {
        name: String,
        differentiated: Vec<String>,
    },
    /// A parameter named twice.
    RepeatedParameter { name: String },
    /// A parameter the mechanism does not have.
    UnknownParameter { name: String, known: Vec<String> },
    /// A parameter's value is not a finite number.
    NotFinite { name: String, value: f64 },
    /// Something that should not happen did: the message says what.
    Internal { what: String },
}

impl fmt::Display for MechanismError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MechanismError::Mistakes(d) => write!(f, "{d}"),
            MechanismError::Sizes { asked, has } => write!(
                f,
                "the mechanism has m = {} dependent and f = {} driving coordinates, not m = {}, f = {}",
                has.0, has.1, asked.0, asked.1
            ),
            MechanismError::TooManyPoints { points, most } => write!(
                f,
                "the mechanism has {points} named points; this view holds at most {most} \
                 (choose a larger capacity, or promote the mechanism to Rust with `linkage expand`)"
            ),
            MechanismError::Parameters { asked, has } => write!(
                f,
                "the mechanism is differentiated by {has} parameters, not {asked}"
            ),
            MechanismError::TooManyParameters { parameters, most } => write!(
                f,
                "{parameters} parameters asked for; this view holds at most {most}"
            ),
            MechanismError::NotDifferentiated {
                name,
                differentiated,
            } => write!(
                f,
                "the mechanism is not differentiated by `{name}` (it is not in its `params`); \
                 it is differentiated by: {}",
                differentiated.join(", ")
            ),
            MechanismError::RepeatedParameter { name } => {
                write!(f, "the parameter `{name}` is named twice")
            }
            MechanismError::UnknownParameter { name, known } => write!(
                f,
                "the mechanism has no parameter `{name}`; its parameters: {}",
                known.join(", ")
            ),
            MechanismError::NotFinite { name, value } => {
                write!(f, "the parameter `{name}` is {value}, not a finite number")
            }
            MechanismError::Internal { what } => write!(
                f,
                "{what} (an internal error: please report it with the mechanism)"
            ),
        }
    }
}

impl std::error::Error for MechanismError {}

impl From<Diagnostics> for MechanismError {
    fn from(d: Diagnostics) -> Self {
        MechanismError::Mistakes(d)
    }
}
