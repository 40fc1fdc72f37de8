//! Why a loaded mechanism file could not be read, made or analysed: each
//! failure typed, the mistakes located in the text that holds them.

use crate::assembly::AssemblyError;
use crate::mechanism::{Diagnostics, MechanismError};
use std::fmt;

/// Mistakes located in a text: what a front door shows its user, rendered
/// as a compiler writes them.
#[derive(Clone, Debug)]
pub struct Located {
    /// The text's name in messages: a path, `<stdin>`, or a name the
    /// caller chose.
    pub shown: String,
    /// The text the mistakes are located in.
    pub text: String,
    pub diagnostics: Diagnostics,
}

impl Located {
    /// The mistakes written against the text, with colour for a terminal.
    pub fn render(&self, colour: bool) -> String {
        self.diagnostics.render(&self.shown, &self.text, colour)
    }
}

/// Why a mechanism file could not be loaded or analysed.
#[derive(Debug)]
#[non_exhaustive]
pub enum LoadError {
    /// The file could not be read (or is not UTF-8 text); `missing` says
    /// it is not there.
    Read { why: String, missing: bool },
    /// The text is not the file asked for (a topology where joints and
    /// links are needed, say).
    NotThisKind { why: String },
    /// The text has mistakes, every one of them located.
    Mistakes(Located),
    /// The mechanism could not be made or set (other than mistakes in its
    /// text: a parameter's value, its sizes).
    Mechanism(MechanismError),
    /// The analysis failed: `cause` says what failed, `why` the sentence
    /// that says where; `located` marks the place in the file that gave
    /// the input, when the file gave it.
    Analysis {
        cause: Cause,
        why: String,
        located: Option<Box<Located>>,
    },
}

/// What failed in an analysis of a loaded file.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum Cause {
    /// The analysis itself (a singular pose, no convergence, …).
    Analysis(crate::Error),
    /// The search for the file's assembly.
    Assembly(AssemblyError),
    /// The assembly picked at the drivers' `at` does not reach the sweep's
    /// `from`: a limit position lies between them.
    LimitBeforeStart,
}

impl LoadError {
    /// A failure of the analysis, not located.
    pub(crate) fn analysis(error: crate::Error) -> LoadError {
        LoadError::Analysis {
            why: error.to_string(),
            cause: Cause::Analysis(error),
            located: None,
        }
    }
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LoadError::Read { why, .. } | LoadError::NotThisKind { why } => f.write_str(why),
            LoadError::Mistakes(located) => f.write_str(located.render(false).trim_end()),
            LoadError::Mechanism(error) => write!(f, "{error}"),
            LoadError::Analysis { why, .. } => f.write_str(why),
        }
    }
}

impl std::error::Error for LoadError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            LoadError::Mechanism(error) => Some(error),
            LoadError::Analysis { cause, .. } => match cause {
                Cause::Analysis(error) => Some(error),
                Cause::Assembly(error) => Some(error),
                Cause::LimitBeforeStart => None,
            },
            _ => None,
        }
    }
}
