//! Synthesis from Python: `Mechanism.synthesize` and its result,
//! `Designs` — every design certified over the driver's range.

use crate::arrays::{array1, array2, array3};
use crate::errors::Failure;
use crate::source::Source;
use linkage::mechanism::design::{DesignTask, DesignView, NoDesign, design};
use linkage::mechanism::sizes::DesignJob;
use linkage::synthesis::Search;
use numpy::{PyArray1, PyArray2, PyArray3};
use pyo3::prelude::*;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// The certified designs of a synthesis, one row per design, best first
/// (smallest RMS miss): `parameters` (designs, parameters) in the order
/// of `parameter_names` (the free ones chosen, the others as they were),
/// `rms_error`, `largest_error`, `start` (the start each came from),
/// `drivers` and `errors` (designs, targets): the driver at each target
/// and the miss there, `poses` (designs, targets, m) the pose there; the certificate: the range swept `certified_from`
/// to `certified_to`, the worst transmission angle `transmission` (rad)
/// and the driver there `transmission_at`. `starts` were run, of which
/// `failed_starts` could not be assembled and `refused` candidates failed
/// their certificate. `design(k)` is the k-th design as a `Mechanism`.
#[pyclass(module = "linkage", frozen)]
pub struct Designs {
    #[pyo3(get)]
    parameters: Py<PyArray2<f64>>,
    #[pyo3(get)]
    parameter_names: Vec<String>,
    #[pyo3(get)]
    free: Vec<String>,
    #[pyo3(get)]
    rms_error: Py<PyArray1<f64>>,
    #[pyo3(get)]
    largest_error: Py<PyArray1<f64>>,
    #[pyo3(get)]
    start: Vec<usize>,
    #[pyo3(get)]
    drivers: Py<PyArray2<f64>>,
    #[pyo3(get)]
    errors: Py<PyArray2<f64>>,
    #[pyo3(get)]
    poses: Py<PyArray3<f64>>,
    #[pyo3(get)]
    certified_from: Py<PyArray1<f64>>,
    #[pyo3(get)]
    certified_to: Py<PyArray1<f64>>,
    #[pyo3(get)]
    transmission: Py<PyArray1<f64>>,
    #[pyo3(get)]
    transmission_at: Py<PyArray1<f64>>,
    #[pyo3(get)]
    starts: usize,
    #[pyo3(get)]
    failed_starts: usize,
    #[pyo3(get)]
    refused: usize,
    count: usize,
    rows: Vec<Vec<f64>>,
    source: Source,
}

/// The numbers of a synthesis's designs.
#[derive(Clone, Debug, Default)]
pub struct Designed {
    names: Vec<String>,
    parameters: Vec<Vec<f64>>,
    rms_error: Vec<f64>,
    largest_error: Vec<f64>,
    start: Vec<usize>,
    drivers: Vec<f64>,
    errors: Vec<f64>,
    /// u at each target, design after design.
    poses: Vec<f64>,
    m: usize,
    targets: usize,
    certificate: [Vec<f64>; 4],
    starts: usize,
    failed_starts: usize,
    refused: usize,
}

/// A synthesis: the task, the search, the assembly to start from.
pub struct Synthesize {
    pub source: Source,
    pub task: DesignTask,
    pub search: Search,
    /// The driver at which the guess is assembled (default: the file's
    /// `at`; without a file, no guess).
    pub at: Option<f64>,
    pub none_is_error: bool,
    /// Raised when the caller is interrupted: the search stops within the
    /// starts under way and starts no more.
    pub stop: Arc<AtomicBool>,
}

impl DesignJob for Synthesize {
    type Output = Designed;
    type Error = Failure;
    fn run<const M: usize, const P: usize>(
        self,
        model: DesignView<M, P>,
    ) -> Result<Designed, Failure> {
        let drives = self.source.drives(&model)?;
        let at = self.at.map(|x| [x].into()).or(drives.map(|d| d.at));
        let guess = match at {
            Some(at) => Some(self.source.assembled(&model, &at)?),
            None => None,
        };
        let stop = &self.stop;
        let found = design(&model, guess, &self.task, &self.search, &|| {}, &|| {
            stop.load(Ordering::Relaxed)
        })?;
        if self.none_is_error
            && let Some(none) = NoDesign::of(&found)
        {
            return Err(Failure::NoDesign(none));
        }
        let targets = found.designs.first().map_or(0, |d| d.drivers.len());
        let mut out = Designed {
            names: crate::pose::owned(model.parameter_names()),
            targets,
            m: M,
            starts: found.starts,
            failed_starts: found.failed_starts,
            refused: found.refused.len(),
            ..Designed::default()
        };
        for d in &found.designs {
            out.parameters.push(d.model.parameters().to_vec());
            out.rms_error.push(d.rms_error);
            out.largest_error.push(d.largest_error().1);
            out.start.push(d.start);
            out.drivers.extend(&d.drivers);
            out.errors.extend(&d.errors);
            out.poses
                .extend(d.poses.iter().flat_map(|u| u.iter().copied()));
            let c = d.certificate.as_ref();
            let values = [
                c.map_or(f64::NAN, |c| c.from),
                c.map_or(f64::NAN, |c| c.to),
                c.map_or(f64::NAN, |c| c.transmission),
                c.map_or(f64::NAN, |c| c.transmission_at),
            ];
            for (column, value) in out.certificate.iter_mut().zip(values) {
                column.push(value);
            }
        }
        Ok(out)
    }
}

impl Designs {
    pub fn new(py: Python<'_>, d: Designed, free: Vec<String>, source: Source) -> Designs {
        let n = d.rms_error.len();
        let k = d.names.len();
        let flat: Vec<f64> = d.parameters.iter().flatten().copied().collect();
        let [from, to, transmission, transmission_at] = d.certificate;
        Designs {
            parameters: array2(py, n, k, flat),
            parameter_names: d.names,
            free,
            rms_error: array1(py, d.rms_error),
            largest_error: array1(py, d.largest_error),
            start: d.start,
            drivers: array2(py, n, d.targets, d.drivers),
            errors: array2(py, n, d.targets, d.errors),
            poses: array3(py, (n, d.targets, d.m), d.poses),
            certified_from: array1(py, from),
            certified_to: array1(py, to),
            transmission: array1(py, transmission),
            transmission_at: array1(py, transmission_at),
            starts: d.starts,
            failed_starts: d.failed_starts,
            refused: d.refused,
            count: n,
            rows: d.parameters,
            source,
        }
    }
}

#[pymethods]
impl Designs {
    fn __len__(&self) -> usize {
        self.count
    }

    /// The `k`-th design (best first) as a mechanism: the one synthesized
    /// on, with the design's parameters.
    fn design(&self, k: isize) -> PyResult<crate::mechanism::Mechanism> {
        // From the end for a negative k, as Python indexes.
        let index = if k < 0 {
            (self.count as isize).checked_add(k)
        } else {
            Some(k)
        };
        let Some(row) = index.and_then(|i| self.rows.get(i as usize)) else {
            return Err(pyo3::exceptions::PyIndexError::new_err(format!(
                "design {k} of {}",
                self.count
            )));
        };
        let mut source = self.source.clone();
        for (name, value) in self.parameter_names.iter().zip(row) {
            source
                .mechanism
                .set_parameter(name, *value)
                .map_err(Failure::from)?;
        }
        Ok(crate::mechanism::Mechanism::of_source(source))
    }

    fn __repr__(&self) -> String {
        format!(
            "Designs({} certified from {} starts, {} refused, {} failed; free: [{}])",
            self.count,
            self.starts,
            self.refused,
            self.failed_starts,
            self.free.join(", ")
        )
    }
}
