//! A mechanism file — or a topology file, through the mechanism file it
//! generates — loaded for analysis: its text, the file read from it, its
//! mechanism and the topology it came from; and what every front door
//! (the command-line tool, the bindings) does with it at the file's drive:
//! the assembly the file picks, the analysis at `at`, the sweep over the
//! drive range ([`drive`](self)). Every failure is a typed [`LoadError`],
//! its mistakes located in the text that holds them.
//!
//! ```
//! use linkage::file::Loaded;
//!
//! let text = std::fs::read_to_string("mechanisms/four_bar.toml")?;
//! let loaded = Loaded::from_text("four_bar.toml", &text)?;
//! assert_eq!(loaded.mechanism().name(), "FourBar");
//! let bar = loaded.mechanism().fixed::<2, 1>()?;
//! let (drives, pose) = loaded.analysed(&bar)?;
//! assert_eq!(drives.at[0], 20f64.to_radians());
//! assert!((pose.u[0].to_degrees() - 70.550_765_47).abs() < 1e-8);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod dead_centres;
mod drive;
mod dxf;
mod error;
mod picture;

pub use dead_centres::{DeadCentre, DeadCentreError};
pub use drive::{FixedAnalysis, FixedDrives, Swept, at_text};
pub use dxf::{DxfChoice, DxfError, Positions};
pub use error::{Cause, LoadError, Located};

use super::{MechanismFile, TopologyFile, is_topology};
use crate::mechanism::{Diagnostics, Mechanism, MechanismError};
use crate::topology::Topology;
use std::path::Path;

/// A mechanism file, read and made into its mechanism.
#[derive(Clone, Debug)]
pub struct Loaded {
    shown: String,
    text: String,
    file: MechanismFile,
    mechanism: Mechanism,
    topology: Option<Topology>,
}

impl Loaded {
    /// The mechanism file (or topology file) `text`, called `shown` in
    /// messages.
    pub fn from_text(shown: &str, text: &str) -> Result<Loaded, LoadError> {
        if is_topology(text) {
            return Ok(Loaded::from_topology(shown, text)?.1);
        }
        Loaded::from_mechanism_file(shown.to_owned(), text.to_owned(), None)
    }

    /// The file at `path`.
    pub fn read(path: &Path) -> Result<Loaded, LoadError> {
        let text = read_text(path)?;
        Loaded::from_text(&path.display().to_string(), &text)
    }

    /// The topology file `text` (joints and links), and the mechanism its
    /// generated mechanism file makes; that file is shown as
    /// "`shown` (its equations)" in later messages.
    pub fn from_topology(shown: &str, text: &str) -> Result<(TopologyFile, Loaded), LoadError> {
        if !is_topology(text) {
            return Err(LoadError::NotThisKind {
                why: format!(
                    "{shown} is not a topology file (it has no [joints], or it has equations): joints and links are needed here"
                ),
            });
        }
        let located = |errors: &super::FileErrors| {
            LoadError::Mistakes(Located {
                shown: shown.to_owned(),
                text: text.to_owned(),
                diagnostics: Diagnostics::from(errors),
            })
        };
        let topology = TopologyFile::parse(text).map_err(|e| located(&e))?;
        let (_, generated) = topology.mechanism_file().map_err(|e| located(&e))?;
        let made = topology.topology.clone();
        let loaded =
            Loaded::from_mechanism_file(format!("{shown} (its equations)"), generated, Some(made))?;
        Ok((topology, loaded))
    }

    /// A mechanism file's text, made into its mechanism.
    fn from_mechanism_file(
        shown: String,
        text: String,
        topology: Option<Topology>,
    ) -> Result<Loaded, LoadError> {
        let file = match MechanismFile::parse(&text) {
            Ok(file) => file,
            Err(errors) => {
                let diagnostics = Diagnostics::from(&errors);
                return Err(LoadError::Mistakes(Located {
                    shown,
                    text,
                    diagnostics,
                }));
            }
        };
        let mechanism = match file.mechanism() {
            Ok(mechanism) => mechanism,
            Err(MechanismError::Mistakes(diagnostics)) => {
                return Err(LoadError::Mistakes(Located {
                    shown,
                    text,
                    diagnostics,
                }));
            }
            Err(other) => return Err(LoadError::Mechanism(other)),
        };
        Ok(Loaded {
            shown,
            text,
            file,
            mechanism,
            topology,
        })
    }

    /// The text's name in messages.
    pub fn shown(&self) -> &str {
        &self.shown
    }

    /// The mechanism file's text (the generated one, for a topology).
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The mechanism file.
    pub fn file(&self) -> &MechanismFile {
        &self.file
    }

    /// Its mechanism.
    pub fn mechanism(&self) -> &Mechanism {
        &self.mechanism
    }

    /// Its mechanism, to set parameters on.
    pub fn mechanism_mut(&mut self) -> &mut Mechanism {
        &mut self.mechanism
    }

    /// The topology the file was generated from, if it was.
    pub fn topology(&self) -> Option<&Topology> {
        self.topology.as_ref()
    }

    /// `diagnostics`, located in the mechanism file's text.
    pub fn located(&self, diagnostics: Diagnostics) -> Located {
        Located {
            shown: self.shown.clone(),
            text: self.text.clone(),
            diagnostics,
        }
    }
}

/// The text of the file at `path`: a mechanism file is UTF-8 text.
pub fn read_text(path: &Path) -> Result<String, LoadError> {
    let bytes = std::fs::read(path).map_err(|e| LoadError::Read {
        why: format!("cannot read {}: {e}", path.display()),
        missing: e.kind() == std::io::ErrorKind::NotFound,
    })?;
    String::from_utf8(bytes).map_err(|e| LoadError::Read {
        why: format!(
            "{} is not UTF-8 text (byte {}): a mechanism file is text in UTF-8",
            path.display(),
            e.utf8_error().valid_up_to()
        ),
        missing: false,
    })
}
