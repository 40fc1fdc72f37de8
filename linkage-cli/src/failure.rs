//! Why a command failed, and the exit status that says so.

use std::fmt;

/// A command's failure: the message has been written, or is here.
#[derive(Debug)]
pub enum Failure {
    /// The mechanism file has mistakes (already written to standard error).
    Mistakes,
    /// A file other than the mechanism's (a synthesis's targets) has a
    /// mistake, located in the message.
    Malformed(String),
    /// The analysis failed.
    Analysis(String),
    /// The analysis failed at a place in the file (already written to
    /// standard error, located there).
    AnalysisAt,
    /// A file could not be read or written (or the page served: its port).
    Io(String),
}

impl Failure {
    /// The exit status: 1 mistakes in a file, 3 the analysis, 4 a file.
    pub fn code(&self) -> u8 {
        match self {
            Failure::Mistakes | Failure::Malformed(_) => 1,
            Failure::Analysis(_) | Failure::AnalysisAt => 3,
            Failure::Io(_) => 4,
        }
    }
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Failure::Mistakes => f.write_str("the mechanism file has mistakes"),
            Failure::Analysis(why) | Failure::Malformed(why) => write!(f, "{why}"),
            Failure::AnalysisAt => f.write_str("the analysis failed"),
            Failure::Io(why) => write!(f, "{why}"),
        }
    }
}
