//! A Python mechanism's run-time mechanism, and the file it was loaded
//! from if it was: the file gives the drive and the assembly to start
//! from; a mechanism from the attribute's text has neither, so its calls
//! name the drivers' values and its first assembly mode is taken.

use crate::errors::Failure;
use linkage::assembly::{Assemble, Pick};
use linkage::file::{FixedDrives, Loaded};
use linkage::mechanism::{Fixed, Mechanism};
use linkage::prelude::SVector;
use std::sync::Arc;

#[derive(Clone, Debug)]
pub struct Source {
    /// The mechanism, with the parameters set from Python.
    pub mechanism: Mechanism,
    pub loaded: Option<Arc<Loaded>>,
    /// The equations and name of a mechanism made from them (none for a
    /// file's): what remakes it in another process.
    pub equations: Option<Arc<(String, String)>>,
}

impl Source {
    /// How to make this mechanism again (in another process: a pickle):
    /// the kind of text (`"equations"` or `"file"`: a mechanism file's or
    /// a topology's), the text, the name, and every parameter's value.
    pub fn recipe(&self) -> (&'static str, String, String, Vec<(String, f64)>) {
        let m = &self.mechanism;
        let parameters = (m.parameter_names().iter())
            .zip(m.parameters())
            .map(|(n, x)| ((*n).to_owned(), *x))
            .collect();
        match (&self.loaded, &self.equations) {
            (Some(loaded), _) => {
                let text = match loaded.topology() {
                    Some(topology) => topology.topology_text(),
                    None => loaded.text().to_owned(),
                };
                ("file", text, loaded.shown().to_owned(), parameters)
            }
            (None, Some(equations)) => (
                "equations",
                equations.0.clone(),
                equations.1.clone(),
                parameters,
            ),
            (None, None) => ("equations", String::new(), m.name().to_owned(), parameters),
        }
    }

    /// The file's drive for `model`; none without a file.
    pub fn drives<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
    ) -> Result<Option<FixedDrives<F>>, Failure> {
        match &self.loaded {
            Some(loaded) => Ok(Some(loaded.drives(model)?)),
            None => Ok(None),
        }
    }

    /// The assembly at the drivers' `at`: the file's pick, or the first
    /// mode found.
    pub fn assembled<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
        at: &SVector<f64, F>,
    ) -> Result<SVector<f64, M>, Failure> {
        match &self.loaded {
            Some(loaded) => Ok(loaded.assembled(model, at)?),
            None => Ok(model.assemble(at, &Pick::Index(0))?.u),
        }
    }

    /// The drive's value of one argument: the one given, or the file's, or
    /// `default` for a mechanism without a file (`None`: it must be
    /// given).
    pub fn or_file<const F: usize>(
        given: Option<&[f64]>,
        argument: &str,
        names: &[&str],
        file: Option<SVector<f64, F>>,
        default: Option<f64>,
    ) -> Result<SVector<f64, F>, Failure> {
        if let Some(values) = given {
            return crate::arrays::fixed::<F>(values, argument, names);
        }
        if let Some(value) = file {
            return Ok(value);
        }
        match default {
            Some(x) => Ok(SVector::repeat(x)),
            None => Err(Failure::BadInput(format!(
                "give `{argument}` (one value for each of [{}]): a mechanism from its equations has no drive of its own",
                names.join(", ")
            ))),
        }
    }
}
