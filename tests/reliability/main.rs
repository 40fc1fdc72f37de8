//! Reliability: random worlds and garbage, and the library never lies.
//!
//! Random four-bars, slider-cranks and six-bars — link lengths over six
//! orders of magnitude, zero-length links, coincident pivots, equal
//! lengths, negative and non-finite ones — at random driver values,
//! velocities and accelerations (NaN, ±∞, huge and subnormal included),
//! from random initial guesses, through every entry point of the runtime.
//! The properties:
//!
//! - nothing panics;
//! - no NaN or ∞ inside an `Ok`;
//! - an `Ok` is right: ‖Ψ‖∞ meets the tolerance, Ψ_u u̇ + Ψ_v v̇ = 0 and
//!   method A = method B to the accuracy promised, the sensitivities to the
//!   parameters agree with num-dual's (parameters as dual numbers) to it
//!   too, and a four-bar or
//!   slider-crank the law of cosines says cannot be assembled is never
//!   `Ok`;
//! - an `Err` is of the right kind: `NonFiniteInput` exactly when an input
//!   is not finite, `CannotAssemble` never where the closed form says the
//!   mechanism assembles.
//!
//! The number of cases per mechanism is `LINKAGE_CASES` (default 2000, what
//! CI runs); the long run, 10⁶ per mechanism:
//!
//!     LINKAGE_CASES=1000000 cargo test --release --test reliability -- --nocapture
//!
//! A failure is shrunk by proptest to the smallest world that shows it.

#[path = "../common/mod.rs"]
mod common;
#[path = "../models/mod.rs"]
mod models;

/// Assembly without a guess on random four-bars and Watt six-bars.
mod assembly;
mod bit_patterns;
/// The same through the machine, the cam, the diagrams and the scenes.
#[cfg(feature = "draw")]
mod facade;
/// Mechanism texts and files, mutated and made up, read and run.
#[cfg(feature = "files")]
mod files;
mod four_bar_sweeps;
mod four_bars;
mod harness;
mod regressions;
mod six_bars;
mod slider_cranks;
/// The watchdog of the campaigns over the facade and over files.
#[cfg(any(feature = "draw", feature = "files"))]
mod watchdog;
