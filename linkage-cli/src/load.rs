//! Reading the mechanism file named on the command line (or standard
//! input) into its file and its run-time mechanism, every mistake written
//! to standard error as a compiler writes them.

use crate::failure::Failure;
use linkage::file::{MechanismFile, TopologyFile, is_topology};
use linkage::mechanism::{Diagnostics, Mechanism, MechanismError};
use linkage::topology::Topology;
use std::io::{IsTerminal, Read};
use std::path::Path;

/// A mechanism file, read and made into its mechanism.
pub struct Loaded {
    /// The name to show in messages: the path, or `<stdin>`.
    pub shown: String,
    pub text: String,
    pub file: MechanismFile,
    pub mechanism: Mechanism,
    /// The topology the file was generated from, if it was.
    pub topology: Option<Topology>,
}

/// Writes `diagnostics` against the file's text to standard error.
pub fn report(diagnostics: &Diagnostics, shown: &str, text: &str) {
    let colour = std::io::stderr().is_terminal();
    eprint!("{}", diagnostics.render(shown, text, colour));
}

/// The file's text: the file at `path`, or standard input for `-`.
pub fn text_of(path: &Path) -> Result<(String, String), Failure> {
    if path.as_os_str() == "-" {
        let mut text = String::new();
        std::io::stdin()
            .read_to_string(&mut text)
            .map_err(|e| Failure::Io(format!("cannot read standard input: {e}")))?;
        return Ok(("<stdin>".to_owned(), text));
    }
    let bytes = std::fs::read(path)
        .map_err(|e| Failure::Io(format!("cannot read {}: {e}", path.display())))?;
    let text = String::from_utf8(bytes).map_err(|e| {
        Failure::Io(format!(
            "{} is not UTF-8 text (byte {}): a mechanism file is text in UTF-8",
            path.display(),
            e.utf8_error().valid_up_to()
        ))
    })?;
    Ok((path.display().to_string(), text))
}

/// The mechanism file a topology file generates, shown as such in later
/// messages; the topology's mistakes written against its own text.
pub fn generated(shown: &str, text: &str) -> Result<(String, String, Topology), Failure> {
    let topology = TopologyFile::parse(text).map_err(|errors| {
        report(&Diagnostics::from(&errors), shown, text);
        Failure::Mistakes
    })?;
    match topology.mechanism_file() {
        Ok((_, generated)) => Ok((
            format!("{shown} (its equations)"),
            generated,
            topology.topology,
        )),
        Err(errors) => {
            report(&Diagnostics::from(&errors), shown, text);
            Err(Failure::Mistakes)
        }
    }
}

/// Reads the mechanism file at `path` (or the one a topology file
/// generates) and makes its mechanism; every mistake is written to
/// standard error.
pub fn load(path: &Path) -> Result<Loaded, Failure> {
    let (shown, text) = text_of(path)?;
    if is_topology(&text) {
        let (shown, text, topology) = generated(&shown, &text)?;
        let mut loaded = loaded(shown, text)?;
        loaded.topology = Some(topology);
        return Ok(loaded);
    }
    loaded(shown, text)
}

/// Reads the topology file at `path`, and makes the mechanism it generates.
pub fn load_topology(path: &Path) -> Result<(TopologyFile, Loaded), Failure> {
    let (shown, text) = text_of(path)?;
    if !is_topology(&text) {
        return Err(Failure::Malformed(format!(
            "{shown} is not a topology file (it has no [joints], or it has equations): joints and links are needed here"
        )));
    }
    let topology = TopologyFile::parse(&text).map_err(|errors| {
        report(&Diagnostics::from(&errors), &shown, &text);
        Failure::Mistakes
    })?;
    let (shown, generated, made) = generated(&shown, &text)?;
    let mut loaded = loaded(shown, generated)?;
    loaded.topology = Some(made);
    Ok((topology, loaded))
}

/// A mechanism file's text, read and made into its mechanism.
fn loaded(shown: String, text: String) -> Result<Loaded, Failure> {
    let file = match MechanismFile::parse(&text) {
        Ok(file) => file,
        Err(errors) => {
            report(&Diagnostics::from(&errors), &shown, &text);
            return Err(Failure::Mistakes);
        }
    };
    let mechanism = match file.mechanism() {
        Ok(mechanism) => mechanism,
        Err(MechanismError::Mistakes(diagnostics)) => {
            report(&diagnostics, &shown, &text);
            return Err(Failure::Mistakes);
        }
        Err(other) => return Err(Failure::Analysis(other.to_string())),
    };
    Ok(Loaded {
        shown,
        text,
        file,
        mechanism,
        topology: None,
    })
}
