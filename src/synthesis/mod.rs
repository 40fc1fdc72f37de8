//! Synthesis: mechanisms designed by exact gradients.

mod least_squares;

pub use least_squares::Stopping;
