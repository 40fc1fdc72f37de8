//! Tapes: the straight-line code the attribute emits for a kernel,
//! compiled into a flat register program and evaluated without a
//! compiler, giving the compiled code's numbers to the bit.
//!
//! A tape is a list of [`Op`]s over f64 registers, run phase by phase on a
//! register file ([`Registers`]) made once and reused: the caller writes
//! the inputs into their slots ([`Input`], laid out by [`Slots`]), runs a
//! phase and reads its outputs, which fill the [`Part`]s of the kernel's
//! result in order. `kinematics` runs in two phases: Ψ, Ψ_u and Ψ_v, then —
//! after the caller has solved for u̇ and written it to [`Input::Udot`] —
//! γ, with every register of the first phase still live. A register file
//! of L lanes evaluates the same tape at L inputs in one pass.
//!
//! The interpreter needs nothing but `std`; compiling a kernel into a tape
//! (`compile`, [`Tapes`]) reads the emitted tokens and needs the `syntax`
//! feature.

#[cfg(feature = "syntax")]
mod compile;
mod error;
mod op;
mod part;
mod program;
mod slots;

#[cfg(feature = "syntax")]
pub use compile::{CompileError, Tapes, compile};
pub use error::TapeError;
pub use op::{Code, Op};
pub use part::{Form, Part};
pub use program::{Phase, Registers, Tape};
pub use slots::{Input, Slots};
