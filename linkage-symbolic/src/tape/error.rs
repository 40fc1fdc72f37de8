//! What can go wrong when a tape runs: inputs, outputs, phases or
//! registers that do not fit it.

use super::slots::Input;
use std::fmt;

/// A call of a tape that does not fit it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TapeError {
    /// An input given with the wrong number of values.
    InputLength {
        input: Input,
        expected: usize,
        found: usize,
    },
    /// A lane past the register file's lanes.
    Lane { lane: usize, lanes: usize },
    /// A phase the tape does not have.
    Phase { phase: usize, phases: usize },
    /// An output buffer of the wrong length.
    OutputLength {
        phase: usize,
        expected: usize,
        found: usize,
    },
    /// A register file made for another tape.
    ForeignRegisters,
    /// A tape whose parts do not fit together (see `Tape::new`).
    Invalid(&'static str),
}

impl fmt::Display for TapeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TapeError::InputLength {
                input,
                expected,
                found,
            } => write!(
                f,
                "the input {input:?} has {expected} values here, {found} were given"
            ),
            TapeError::Lane { lane, lanes } => {
                write!(f, "lane {lane} of a register file with {lanes} lanes")
            }
            TapeError::Phase { phase, phases } => {
                write!(f, "phase {phase} of a tape with {phases} phases")
            }
            TapeError::OutputLength {
                phase,
                expected,
                found,
            } => write!(
                f,
                "phase {phase} has {expected} outputs, the buffer holds {found}"
            ),
            TapeError::ForeignRegisters => {
                write!(f, "the register file was made for another tape")
            }
            TapeError::Invalid(why) => write!(f, "not a tape: {why}"),
        }
    }
}

impl std::error::Error for TapeError {}
