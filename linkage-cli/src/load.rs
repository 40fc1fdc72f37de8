//! Reading the mechanism file named on the command line (or standard
//! input) into the library's [`Loaded`]; every mistake written to standard
//! error as a compiler writes them.

use crate::failure::Failure;
use linkage::file::{LoadError, Located, TopologyFile, read_text};
use linkage::mechanism::Diagnostics;
use std::io::{IsTerminal, Read};
use std::path::Path;

pub use linkage::file::Loaded;

/// Writes `diagnostics` against the file's text to standard error.
pub fn report(diagnostics: &Diagnostics, shown: &str, text: &str) {
    let colour = std::io::stderr().is_terminal();
    eprint!("{}", diagnostics.render(shown, text, colour));
}

/// Writes located mistakes to standard error.
fn report_located(located: &Located) {
    eprint!("{}", located.render(std::io::stderr().is_terminal()));
}

impl From<LoadError> for Failure {
    /// The tool's failure for a loaded file's: mistakes and failures
    /// located in the file are written to standard error here.
    fn from(error: LoadError) -> Failure {
        match error {
            LoadError::Read { why, .. } => Failure::Io(why),
            LoadError::NotThisKind { why } => Failure::Malformed(why),
            LoadError::Mistakes(located) => {
                report_located(&located);
                Failure::Mistakes
            }
            LoadError::Mechanism(error) => Failure::Analysis(error.to_string()),
            LoadError::Analysis {
                located: Some(located),
                ..
            } => {
                report_located(&located);
                Failure::AnalysisAt
            }
            LoadError::Analysis { why, .. } => Failure::Analysis(why),
            _ => Failure::Analysis(error.to_string()),
        }
    }
}

/// The file's text: the file at `path`, or standard input for `-`; and its
/// name in messages.
pub fn text_of(path: &Path) -> Result<(String, String), Failure> {
    if path.as_os_str() == "-" {
        let mut text = String::new();
        std::io::stdin()
            .read_to_string(&mut text)
            .map_err(|e| Failure::Io(format!("cannot read standard input: {e}")))?;
        return Ok(("<stdin>".to_owned(), text));
    }
    Ok((path.display().to_string(), read_text(path)?))
}

/// The mechanism file a topology file generates; the topology's mistakes
/// written against its own text.
pub fn generated(shown: &str, text: &str) -> Result<String, Failure> {
    let topology = TopologyFile::parse(text).map_err(|errors| {
        report(&Diagnostics::from(&errors), shown, text);
        Failure::Mistakes
    })?;
    match topology.mechanism_file() {
        Ok((_, generated)) => Ok(generated),
        Err(errors) => {
            report(&Diagnostics::from(&errors), shown, text);
            Err(Failure::Mistakes)
        }
    }
}

/// Reads the mechanism file at `path` (or the one a topology file
/// generates) and makes its mechanism.
pub fn load(path: &Path) -> Result<Loaded, Failure> {
    let (shown, text) = text_of(path)?;
    Ok(Loaded::from_text(&shown, &text)?)
}

/// Reads the topology file at `path`, and makes the mechanism it generates.
pub fn load_topology(path: &Path) -> Result<(TopologyFile, Loaded), Failure> {
    let (shown, text) = text_of(path)?;
    Ok(Loaded::from_topology(&shown, &text)?)
}
