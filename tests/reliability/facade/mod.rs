//! Garbage into every public entry point of the facade's areas — cams,
//! machine dynamics, kinetostatics, scenes and diagrams — as
//! `tests/reliability/` does for the runtime.
//!
//! Every number is an awkward one: an arbitrary bit pattern, a special
//! value (NaN, ±∞, ±0, the extremes, subnormals), or an ordinary number
//! that may be negative or zero; counts range from 0 to usize::MAX. The
//! properties, for every case:
//!
//! - it ends within a time limit (a watchdog thread: no hang);
//! - it does not panic;
//! - an `Ok` holds no NaN or infinity (an SVG none written as "NaN" or
//!   "inf").
//!
//! The number of cases per area is `LINKAGE_CASES` (default 300, what CI
//! runs, a tenth of that for the sizing of cams and the machines' real
//! motion, which are slow when their inputs happen to be valid); the long
//! run:
//!
//!     LINKAGE_CASES=20000 cargo test --release --test reliability facade -- --nocapture

mod cam_sizing;
mod cams;
mod diagrams;
mod harness;
mod kinetostatics;
mod machines;
mod real_motion;
mod scenes;
