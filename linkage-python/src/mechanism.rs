//! `linkage.Mechanism`: a mechanism made at run time, from any of the
//! library's front ends, and the analyses Python calls on it.

use crate::design::{Designs, Synthesize};
use crate::errors::Failure;
use crate::extremes::Find;
use crate::interrupt::interruptible;
use crate::pose::{Analyze, Pose};
use crate::sensitivity::{Differentiate, Sensitivities};
use crate::source::Source;
use crate::sweep::{DriveArgs, Poses, Sweep};
use crate::tolerance::Spread;
use linkage::assembly::{Assemble, Search};
use linkage::draw::scene::Frame;
use linkage::file::{LoadError, Loaded, Located};
use linkage::mechanism::sizes::{Job, run, run_design, run_sensitive};
use linkage::mechanism::{Fixed, MechanismError};
use linkage::prelude::*;
use linkage::topology::Topology;
use numpy::PyArray2;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// A planar mechanism made at run time: its closure equations read,
/// checked and differentiated by linkage's own front end, its kernels
/// evaluated to the bits of the compiled code. Make one with
/// `Mechanism.from_file`, `from_toml`, `from_text`, `from_topology`,
/// `from_pyslvs` or `from_pylinkage`.
#[pyclass(module = "linkage", frozen)]
pub struct Mechanism {
    /// Locked only to copy it (cheap: the mechanism's program and the file
    /// are shared) or to set a parameter, never while an analysis runs:
    /// threads may share a mechanism.
    source: Mutex<Source>,
}

impl Mechanism {
    /// The mechanism of a source (a design's, say).
    pub(crate) fn of_source(source: Source) -> Mechanism {
        Mechanism {
            source: Mutex::new(source),
        }
    }

    /// A copy of its source, to run an analysis on without the lock.
    fn source(&self) -> Source {
        self.source
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .clone()
    }

    fn loaded(loaded: Loaded) -> Mechanism {
        Mechanism::of_source(Source {
            mechanism: loaded.mechanism().clone(),
            loaded: Some(Arc::new(loaded)),
            equations: None,
        })
    }

    /// A topology's mechanism, as its topology file makes it.
    fn of_topology(shown: &str, topology: &Topology) -> Result<Mechanism, Failure> {
        let text = topology.topology_text();
        Ok(Mechanism::loaded(Loaded::from_topology(shown, &text)?.1))
    }
}

/// Drawing the mechanism at its file's `at`, with its points' paths.
struct Picture<'a> {
    source: &'a Source,
    width: f64,
}

impl Job for Picture<'_> {
    type Output = String;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<String, Failure> {
        let Some(loaded) = &self.source.loaded else {
            return Err(Failure::BadInput(
                "a mechanism from its equations has no drive or drawing: draw one from a file"
                    .into(),
            ));
        };
        let (drives, pose) = loaded.analysed(&model)?;
        let frame = Frame::from_analysis(&model, &pose);
        let mut cycle = Vec::new();
        loaded.sweep_each(&model, drives.steps, &mut |_, p| {
            cycle.push(Frame::from_sweep_pose(&model, p))
        })?;
        loaded
            .scene_of(&model)
            .width(self.width)
            .render(&frame, &cycle)
            .map_err(|e| Failure::BadInput(format!("the drawing: {e}")))
    }
}

/// Every assembly mode at the drivers' values.
struct Modes<'a> {
    source: &'a Source,
    v: Option<Vec<f64>>,
}

impl Job for Modes<'_> {
    type Output = (usize, Vec<f64>);
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<(usize, Vec<f64>), Failure> {
        let drives = self.source.drives(&model)?;
        let v = Source::or_file(
            self.v.as_deref(),
            "v",
            &model.v_names(),
            drives.map(|d| d.at),
            None,
        )?;
        let modes = model.assembly_modes(&v, &Search::default())?;
        let flat = (modes.modes.iter())
            .flat_map(|mode| mode.u.iter().copied())
            .collect();
        Ok((modes.modes.len(), flat))
    }
}

#[pymethods]
impl Mechanism {
    /// The mechanism whose equations are `equations` — the attribute's
    /// text, `u = [...], v = [...], points = [...], closure = [...]` — with
    /// the parameters' values `parameters` (a dict, name to number) and
    /// the name `name` (an identifier). It has no drive: its analyses are
    /// given the drivers' values.
    #[staticmethod]
    #[pyo3(signature = (equations, parameters, name = "Mechanism"))]
    fn from_text(
        py: Python<'_>,
        equations: &str,
        parameters: &Bound<'_, PyDict>,
        name: &str,
    ) -> PyResult<Mechanism> {
        let mut values: Vec<(String, f64)> = Vec::new();
        for (key, value) in parameters.iter() {
            values.push((key.extract()?, value.extract()?));
        }
        let made = py.detach(|| {
            let pairs: Vec<(&str, f64)> = values.iter().map(|(n, x)| (n.as_str(), *x)).collect();
            linkage::mechanism::Mechanism::from_text(name, equations, &pairs)
        });
        let mechanism = made.map_err(|e| match e {
            MechanismError::Mistakes(diagnostics) => Failure::Load(LoadError::Mistakes(Located {
                shown: "<equations>".into(),
                text: equations.into(),
                diagnostics,
            })),
            other => Failure::Mechanism(other),
        })?;
        Ok(Mechanism::of_source(Source {
            mechanism,
            loaded: None,
            equations: Some(Arc::new((equations.to_owned(), name.to_owned()))),
        }))
    }

    /// The mechanism of the mechanism file (or topology file) at `path`.
    #[staticmethod]
    fn from_file(py: Python<'_>, path: PathBuf) -> PyResult<Mechanism> {
        let loaded = py.detach(|| Loaded::read(&path)).map_err(Failure::from)?;
        Ok(Mechanism::loaded(loaded))
    }

    /// The mechanism of a mechanism file's (or a topology file's) text,
    /// called `name` in messages.
    #[staticmethod]
    #[pyo3(signature = (text, name = "<text>"))]
    fn from_toml(py: Python<'_>, text: &str, name: &str) -> PyResult<Mechanism> {
        let loaded = py
            .detach(|| Loaded::from_text(name, text))
            .map_err(Failure::from)?;
        Ok(Mechanism::loaded(loaded))
    }

    /// The mechanism of a topology file's text (joints and links), called
    /// `name` in messages.
    #[staticmethod]
    #[pyo3(signature = (text, name = "<topology>"))]
    fn from_topology(py: Python<'_>, text: &str, name: &str) -> PyResult<Mechanism> {
        let loaded = py
            .detach(|| Loaded::from_topology(name, text))
            .map_err(Failure::from)?;
        Ok(Mechanism::loaded(loaded.1))
    }

    /// The mechanism of a pyslvs expression (`M[J[R, …], …]`), driven by
    /// `inputs`: pairs (base, drive) of joint numbers, the angle of the
    /// line base → drive, as pyslvs's own inputs.
    #[staticmethod]
    #[pyo3(signature = (expression, inputs, name = "Mechanism"))]
    fn from_pyslvs(
        py: Python<'_>,
        expression: &str,
        inputs: Vec<Vec<usize>>,
        name: &str,
    ) -> PyResult<Mechanism> {
        let mut pairs = Vec::new();
        for input in &inputs {
            let [base, drive] = input.as_slice() else {
                return Err(Failure::BadInput(format!(
                    "a pyslvs input is a pair (base, drive) of joint numbers, not {input:?}"
                ))
                .into());
            };
            pairs.push((*base, *drive));
        }
        let inputs = pairs;
        let made = py.detach(|| {
            let topology = linkage::topology::pyslvs::from_pyslvs(name, expression.trim(), &inputs)
                .map_err(|e| Failure::Format(e.to_string()))?;
            Mechanism::of_topology("<pyslvs>", &topology)
        });
        Ok(made?)
    }

    /// The mechanism of pylinkage's JSON (`Linkage.to_dict()` written by
    /// `json.dumps`, or that dict itself).
    #[staticmethod]
    fn from_pylinkage(py: Python<'_>, linkage: &Bound<'_, PyAny>) -> PyResult<Mechanism> {
        let json: String = if linkage.is_instance_of::<PyString>() {
            linkage.extract()?
        } else {
            py.import("json")?
                .call_method1("dumps", (linkage,))?
                .extract()?
        };
        let made = py.detach(|| {
            let (topology, _) = linkage::topology::pylinkage::from_pylinkage(&json)
                .map_err(|e| Failure::Format(e.to_string()))?;
            Mechanism::of_topology("<pylinkage>", &topology)
        });
        Ok(made?)
    }

    /// Its name.
    #[getter]
    fn name(&self) -> String {
        let source = self.source();
        source.mechanism.name().to_owned()
    }

    /// The number m of dependent coordinates u.
    #[getter]
    fn m(&self) -> usize {
        let source = self.source();
        source.mechanism.m()
    }

    /// The number f of driving coordinates v.
    #[getter]
    fn f(&self) -> usize {
        let source = self.source();
        source.mechanism.f()
    }

    /// The dependent coordinates u, in order.
    #[getter]
    fn u_names(&self) -> Vec<String> {
        let source = self.source();
        crate::pose::owned(source.mechanism.u_names())
    }

    /// The driving coordinates v, in order.
    #[getter]
    fn v_names(&self) -> Vec<String> {
        let source = self.source();
        crate::pose::owned(source.mechanism.v_names())
    }

    /// The named points, in order.
    #[getter]
    fn point_names(&self) -> Vec<String> {
        let source = self.source();
        crate::pose::owned(source.mechanism.point_names())
    }

    /// Every parameter and its value, in order.
    #[getter]
    fn parameters<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let source = self.source();
        let m = &source.mechanism;
        let dict = PyDict::new(py);
        for (name, value) in m.parameter_names().iter().zip(m.parameters()) {
            dict.set_item(name, value)?;
        }
        Ok(dict)
    }

    /// The mechanism file's text it was loaded from (generated, for a
    /// topology); `None` for a mechanism from its equations.
    #[getter]
    fn file_text(&self) -> Option<String> {
        let source = self.source();
        (source.loaded.as_ref()).map(|loaded| loaded.text().to_owned())
    }

    /// The topology file's text of a mechanism given by its joints and
    /// links (a topology, pyslvs, pylinkage); `None` otherwise.
    #[getter]
    fn topology_text(&self) -> Option<String> {
        let source = self.source();
        (source.loaded.as_ref())
            .and_then(|loaded| loaded.topology())
            .map(Topology::topology_text)
    }

    /// The file's drive: for each driving coordinate a dict of `at`,
    /// `start`, `stop`, `rate`, `acceleration` (in the engine's units), and
    /// `steps`; `None` for a mechanism from its equations.
    #[getter]
    fn drive<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let source = self.source();
        let Some(loaded) = &source.loaded else {
            return Ok(None);
        };
        let names = source.mechanism.v_names();
        let drives = (loaded.file())
            .drives(names)
            .map_err(|missing| Failure::Load(LoadError::Mistakes(loaded.located(missing))))?;
        let dict = PyDict::new(py);
        for (k, name) in names.iter().enumerate() {
            let driver = PyDict::new(py);
            driver.set_item("at", drives.at[k])?;
            driver.set_item("start", drives.from[k])?;
            driver.set_item("stop", drives.to[k])?;
            driver.set_item("rate", drives.rate[k])?;
            driver.set_item("acceleration", drives.acceleration[k])?;
            driver.set_item("steps", drives.steps)?;
            dict.set_item(name, driver)?;
        }
        Ok(Some(dict))
    }

    /// Sets the parameter `name` to `value`.
    fn set_parameter(&self, name: &str, value: f64) -> PyResult<()> {
        let mut source = self
            .source
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        Ok((source.mechanism)
            .set_parameter(name, value)
            .map_err(Failure::from)?)
    }

    /// A copy with the parameters given as keywords set.
    #[pyo3(signature = (**values))]
    fn with_parameters(&self, values: Option<&Bound<'_, PyDict>>) -> PyResult<Mechanism> {
        let copy = Mechanism::of_source(self.source());
        if let Some(values) = values {
            for (name, value) in values.iter() {
                copy.set_parameter(&name.extract::<String>()?, value.extract()?)?;
            }
        }
        Ok(copy)
    }

    /// The pose at the drivers' values `v` (default: the file's `at`),
    /// with velocities at the rates `vdot` (default: the file's rate, or 1)
    /// and accelerations at `vddot` (default: the file's, or 0). Newton
    /// starts from `u` if given; otherwise from the assembly the file picks
    /// (its first mode, for a mechanism without a file).
    #[pyo3(signature = (v = None, vdot = None, vddot = None, u = None))]
    fn analyze(
        &self,
        py: Python<'_>,
        v: Option<&Bound<'_, PyAny>>,
        vdot: Option<&Bound<'_, PyAny>>,
        vddot: Option<&Bound<'_, PyAny>>,
        u: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Pose> {
        let source = self.source();
        use crate::arrays::values;
        let job = Analyze {
            source: &source,
            v: values(v)?,
            vdot: values(vdot)?,
            vddot: values(vddot)?,
            u: values(u)?,
        };
        let analysed = py.detach(|| run(&source.mechanism, job))?;
        Ok(Pose::new(py, analysed))
    }

    /// The exact derivatives of the pose `analyze` would give (the same
    /// arguments) by the parameters `params` (default: every parameter the
    /// mechanism is differentiated by; at most 16), the drivers' motion
    /// held fixed.
    #[pyo3(signature = (v = None, vdot = None, vddot = None, u = None, params = None))]
    fn sensitivities(
        &self,
        py: Python<'_>,
        v: Option<&Bound<'_, PyAny>>,
        vdot: Option<&Bound<'_, PyAny>>,
        vddot: Option<&Bound<'_, PyAny>>,
        u: Option<&Bound<'_, PyAny>>,
        params: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Sensitivities> {
        let params = crate::arrays::names(params)?;
        let source = self.source();
        use crate::arrays::values;
        let job = Differentiate {
            analyze: Analyze {
                source: &source,
                v: values(v)?,
                vdot: values(vdot)?,
                vddot: values(vddot)?,
                u: values(u)?,
            },
        };
        let names = params.unwrap_or_default();
        let differentiated = py.detach(|| run_sensitive(&source.mechanism, &names, job))?;
        Ok(Sensitivities::new(py, differentiated))
    }

    /// Every pose as the drivers move from `start` to `stop` in `steps`
    /// equal steps (default: the file's drive, from its assembly at `at`),
    /// at the rate `rate`; Newton starts from `u` if given. Singular poses
    /// met are located and passed through (`Sweep.events`). Ctrl-C
    /// interrupts it.
    #[pyo3(signature = (steps = None, start = None, stop = None, rate = None, u = None))]
    fn sweep(
        &self,
        py: Python<'_>,
        steps: Option<usize>,
        start: Option<&Bound<'_, PyAny>>,
        stop: Option<&Bound<'_, PyAny>>,
        rate: Option<&Bound<'_, PyAny>>,
        u: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Sweep> {
        let source = self.source();
        use crate::arrays::values;
        let job = Poses {
            source: source.clone(),
            drive: DriveArgs {
                steps,
                start: values(start)?,
                stop: values(stop)?,
                rate: values(rate)?,
                u: values(u)?,
            },
        };
        let mechanism = source.mechanism.clone();
        let swept = interruptible(py, move |_| run(&mechanism, job))?;
        Sweep::new(py, swept?)
    }

    /// Dimensions that make the point `path` pass through `targets` (rows
    /// x, y), or the coordinate `function` take the targets' values (rows
    /// driver, value) — the parameters `free` (a dict, name to (lower,
    /// upper)) chosen, the others kept — from `starts` random starts
    /// (indices `first` on, from `random_state`: the same state and
    /// indices give the same designs). A path's `timing` is "free",
    /// "prescribed" or "relative" (then `drivers` gives the driver at each
    /// target). `precision_points` stops at exactly as many targets as the
    /// free parameters can meet. Every design returned is certified over
    /// the driver's range (a revolution for a path); `distinct=False`
    /// keeps designs found again from later starts (the rows of a shard);
    /// `enough=k` stops at the start (taken in order) that certifies the
    /// k-th design; `min_transmission` (radians) is the smallest
    /// transmission angle a design may have over its range (default 40°
    /// for a mechanism of two coordinates, 10° for more; 0 asks none).
    /// Raises `NoDesignError` when none is certified, unless
    /// `none_is_error=False`. Runs its starts in parallel, the GIL
    /// released; Ctrl-C interrupts it.
    #[pyo3(signature = (
        *, free, targets, path = None, function = None, timing = "free", drivers = None,
        precision_points = false, starts = 64, random_state = 1, first = 0, distinct = true,
        enough = None, min_transmission = None, at = None, none_is_error = true
    ))]
    #[allow(clippy::too_many_arguments)]
    fn synthesize(
        &self,
        py: Python<'_>,
        free: &Bound<'_, PyDict>,
        targets: &Bound<'_, PyAny>,
        path: Option<String>,
        function: Option<String>,
        timing: &str,
        drivers: Option<&Bound<'_, PyAny>>,
        precision_points: bool,
        starts: usize,
        random_state: u64,
        first: usize,
        distinct: bool,
        enough: Option<usize>,
        min_transmission: Option<f64>,
        at: Option<f64>,
        none_is_error: bool,
    ) -> PyResult<Designs> {
        let source = self.source();
        use linkage::mechanism::design::{DesignTask, Targets};
        use linkage::synthesis::{Search, Timing};
        let mut freed = Vec::new();
        for (name, bounds) in free.iter() {
            let name: String = name.extract()?;
            let bounds: Vec<f64> = bounds.extract()?;
            let [lower, upper] = bounds[..] else {
                return Err(Failure::BadInput(format!(
                    "the bounds of `{name}` are a pair (lower, upper), not {bounds:?}"
                ))
                .into());
            };
            freed.push((name, lower, upper));
        }
        if enough == Some(0) {
            return Err(Failure::BadInput("`enough` is at least 1 design".into()).into());
        }
        if first.checked_add(starts).is_none() {
            return Err(Failure::BadInput(format!(
                "`first` + `starts` = {first} + {starts} is past the largest start index"
            ))
            .into());
        }
        let bad = |why: String| PyErr::from(Failure::BadInput(why));
        let drivers = crate::arrays::values(drivers)?;
        let targets = match (path, function) {
            (Some(point), None) => {
                let points = crate::arrays::rows(targets, 2, "x, y")?;
                let timing = match (timing, drivers) {
                    ("free", None) => Timing::Free,
                    ("prescribed", Some(d)) => Timing::Prescribed(d),
                    ("relative", Some(d)) => Timing::Relative(d),
                    ("free", Some(_)) => {
                        return Err(bad(
                            "`drivers` are for a prescribed or relative timing".into()
                        ));
                    }
                    ("prescribed" | "relative", None) => {
                        return Err(bad(format!(
                            "a {timing} timing needs `drivers`, one for each target"
                        )));
                    }
                    (other, _) => {
                        return Err(bad(format!(
                            "`timing` is \"free\", \"prescribed\" or \"relative\", not {other:?}"
                        )));
                    }
                };
                Targets::Path {
                    point,
                    points: points.iter().map(|r| [r[0], r[1]]).collect(),
                    timing,
                }
            }
            (None, Some(coordinate)) => {
                if timing != "free" || drivers.is_some() {
                    return Err(bad(
                        "a function's targets give their drivers: `timing` and `drivers` are a path's".into(),
                    ));
                }
                let rows = crate::arrays::rows(targets, 2, "driver, value")?;
                Targets::Function {
                    coordinate,
                    pairs: rows.iter().map(|r| (r[0], r[1])).collect(),
                }
            }
            _ => {
                return Err(bad(
                    "give one of `path` (a point) and `function` (a coordinate)".into(),
                ));
            }
        };
        let names: Vec<String> = freed.iter().map(|(n, _, _)| n.clone()).collect();
        let job = Synthesize {
            source: source.clone(),
            task: DesignTask {
                targets,
                free: freed,
                precision_points,
                min_transmission,
            },
            search: Search {
                starts,
                random_state,
                first,
                distinct,
                enough,
                ..Search::default()
            },
            at,
            none_is_error,
            stop: Default::default(),
        };
        let mechanism = source.mechanism.clone();
        let free_names = names.clone();
        let designed = interruptible(py, move |stop| {
            let names: Vec<&str> = free_names.iter().map(String::as_str).collect();
            crate::pool::install(|| run_design(&mechanism, &names, Synthesize { stop, ..job }))
        })??;
        Ok(Designs::new(py, designed, names, source.clone()))
    }

    /// Where `quantities` (default: every dependent coordinate) are
    /// largest and smallest over a sweep — and zero, with `zeros=True` —
    /// located to rounding between its poses: a list of dicts of
    /// `quantity`, `kind` ("maximum", "minimum", "zero, rising", "zero,
    /// falling"), `v` (the drivers there) and `value`. A quantity is
    /// written as on the command line: `theta4`, `C.x`, `theta4'` (its
    /// velocity), `C.y''` (an acceleration). The sweep is `sweep`'s (the
    /// same keywords).
    #[pyo3(signature = (
        quantities = None, zeros = false, steps = None, start = None, stop = None, rate = None,
        u = None
    ))]
    #[allow(clippy::too_many_arguments)]
    fn extremes<'py>(
        &self,
        py: Python<'py>,
        quantities: Option<&Bound<'_, PyAny>>,
        zeros: bool,
        steps: Option<usize>,
        start: Option<&Bound<'_, PyAny>>,
        stop: Option<&Bound<'_, PyAny>>,
        rate: Option<&Bound<'_, PyAny>>,
        u: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Vec<Bound<'py, PyDict>>> {
        let source = self.source();
        use crate::arrays::values;
        let job = Find {
            source: source.clone(),
            drive: DriveArgs {
                steps,
                start: values(start)?,
                stop: values(stop)?,
                rate: values(rate)?,
                u: values(u)?,
            },
            quantities: crate::arrays::names(quantities)?.unwrap_or_default(),
            zeros,
        };
        let mechanism = source.mechanism.clone();
        let found = interruptible(py, move |_| run(&mechanism, job))??;
        let mut out = Vec::new();
        for extreme in found {
            let dict = PyDict::new(py);
            dict.set_item("quantity", extreme.quantity)?;
            dict.set_item("kind", extreme.kind)?;
            dict.set_item("v", crate::arrays::array1(py, extreme.v))?;
            dict.set_item("value", extreme.value)?;
            out.push(dict);
        }
        Ok(out)
    }

    /// How far the parameters' `tolerances` (a dict: name to a band's
    /// half-width t, or to ("normal", σ)) move `quantities` (default: every
    /// dependent coordinate; `C.path` is the point's deviation normal to
    /// its path) over a sweep (`sweep`'s keywords): a dict with
    /// `parameters` (those toleranced, in the library's order), `limit`
    /// (the drivers where, within the tolerances, the mechanism may reach
    /// a limit position — the linear spreads do not describe the band
    /// there — or None), `failed_samples`, and `bands`: for each quantity a
    /// dict of arrays over the poses — `v` (poses, f), `value`,
    /// `worst_case` (Σ|gᵢ|tᵢ), `rss`, `sigma`, `sigma_monte_carlo` (with
    /// `samples` > 0) — and `largest` (the pose where the worst case is
    /// largest) with `shares` (each parameter's part of it there).
    #[pyo3(signature = (
        tolerances, quantities = None, samples = 0, random_state = 1, steps = None,
        start = None, stop = None, rate = None, u = None
    ))]
    #[allow(clippy::too_many_arguments)]
    fn tolerance<'py>(
        &self,
        py: Python<'py>,
        tolerances: &Bound<'_, PyDict>,
        quantities: Option<&Bound<'_, PyAny>>,
        samples: usize,
        random_state: u64,
        steps: Option<usize>,
        start: Option<&Bound<'_, PyAny>>,
        stop: Option<&Bound<'_, PyAny>>,
        rate: Option<&Bound<'_, PyAny>>,
        u: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let source = self.source();
        use crate::arrays::{array1, array2, values};
        use linkage::tolerance::Tolerance;
        let mut given = Vec::new();
        for (name, value) in tolerances.iter() {
            let name: String = name.extract()?;
            let tolerance = if let Ok(t) = value.extract::<f64>() {
                Tolerance::Band(t)
            } else {
                let refused = || {
                    pyo3::exceptions::PyTypeError::new_err(format!(
                        "the tolerance of `{name}`: a half-width t, or (\"normal\", σ)"
                    ))
                };
                let pair: Vec<Bound<'_, PyAny>> = value.extract().map_err(|_| refused())?;
                let [kind, size] = &pair[..] else {
                    return Err(refused());
                };
                let (kind, size): (String, f64) = (
                    kind.extract().map_err(|_| refused())?,
                    size.extract().map_err(|_| refused())?,
                );
                match kind.as_str() {
                    "normal" => Tolerance::Normal(size),
                    "band" => Tolerance::Band(size),
                    other => {
                        return Err(Failure::BadInput(format!(
                            "the tolerance of `{name}`: \"normal\" or \"band\", not {other:?}"
                        ))
                        .into());
                    }
                }
            };
            given.push((name, tolerance));
        }
        if samples > 1_000_000 {
            return Err(Failure::BadInput(format!(
                "`samples` is {samples}: a Monte Carlo run here takes at most 1000000"
            ))
            .into());
        }
        let names: Vec<String> = given.iter().map(|(n, _)| n.clone()).collect();
        let job = Spread {
            source: source.clone(),
            drive: DriveArgs {
                steps,
                start: values(start)?,
                stop: values(stop)?,
                rate: values(rate)?,
                u: values(u)?,
            },
            tolerances: given,
            quantities: crate::arrays::names(quantities)?.unwrap_or_default(),
            samples,
            random_state,
        };
        let mechanism = source.mechanism.clone();
        let spreads = interruptible(py, move |_| {
            crate::pool::install(|| run_sensitive(&mechanism, &names, job))
        })??;
        let f = self.f();
        let out = PyDict::new(py);
        out.set_item("parameters", spreads.parameters.clone())?;
        out.set_item("limit", spreads.limit.map(|v| array1(py, v)))?;
        out.set_item("failed_samples", spreads.failed_samples)?;
        let bands = PyDict::new(py);
        for band in spreads.bands {
            let dict = PyDict::new(py);
            let poses = band.value.len();
            dict.set_item("v", array2(py, poses, f, band.v))?;
            dict.set_item("value", array1(py, band.value))?;
            dict.set_item("worst_case", array1(py, band.worst_case))?;
            dict.set_item("rss", array1(py, band.rss))?;
            dict.set_item("sigma", array1(py, band.sigma))?;
            dict.set_item(
                "sigma_monte_carlo",
                band.sigma_monte_carlo.map(|s| array1(py, s)),
            )?;
            dict.set_item("largest", band.largest)?;
            let shares = PyDict::new(py);
            for (name, share) in spreads.parameters.iter().zip(band.shares) {
                shares.set_item(name, share)?;
            }
            dict.set_item("shares", shares)?;
            bands.set_item(band.quantity, dict)?;
        }
        out.set_item("bands", bands)?;
        Ok(out)
    }

    /// Every assembly mode at the drivers' values `v` (default: the file's
    /// `at`), found without a guess: an array (modes, m).
    #[pyo3(signature = (v = None))]
    fn assemble<'py>(
        &self,
        py: Python<'py>,
        v: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let source = self.source();
        let job = Modes {
            source: &source,
            v: crate::arrays::values(v)?,
        };
        let (count, flat) = py.detach(|| run(&source.mechanism, job))?;
        Ok(crate::arrays::array2(py, count, self.m(), flat).into_bound(py))
    }

    /// The mechanism drawn at its file's `at`, with the paths its points
    /// trace over the drive range: SVG text, `width` pixels wide.
    #[pyo3(signature = (width = 640.0))]
    fn svg(&self, py: Python<'_>, width: f64) -> PyResult<String> {
        let source = self.source();
        if !(width.is_finite() && width > 0.0 && width <= 100_000.0) {
            return Err(Failure::BadInput(format!(
                "`width` is a number of pixels from 0 to 100000, not {width:e}"
            ))
            .into());
        }
        let job = Picture {
            source: &source,
            width,
        };
        Ok(py.detach(|| run(&source.mechanism, job))?)
    }

    /// Jupyter's picture of the mechanism: `svg()`, or none for a
    /// mechanism without a file (no drive, no drawing).
    fn _repr_svg_(&self, py: Python<'_>) -> PyResult<Option<String>> {
        let source = self.source();
        if source.loaded.is_none() {
            return Ok(None);
        }
        self.svg(py, 640.0).map(Some)
    }

    /// Pickled as the text it was made from and its parameters' values:
    /// a mechanism travels to another process (a Dask worker) whole.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
        let remake = py.import("linkage._linkage")?.getattr("_remake")?;
        let recipe = self.source().recipe().into_pyobject(py)?.into_any();
        Ok((remake, recipe))
    }

    fn __repr__(&self) -> String {
        let source = self.source();
        let m = &source.mechanism;
        format!(
            "Mechanism({}: u = [{}], v = [{}], {} point{})",
            m.name(),
            m.u_names().join(", "),
            m.v_names().join(", "),
            m.point_names().len(),
            if m.point_names().len() == 1 { "" } else { "s" }
        )
    }
}

/// A pickled mechanism made again (see `Mechanism.__reduce__`).
#[pyfunction]
pub fn _remake(
    py: Python<'_>,
    kind: &str,
    text: &str,
    name: &str,
    parameters: Vec<(String, f64)>,
) -> PyResult<Mechanism> {
    let made = match kind {
        "file" => Mechanism::from_toml(py, text, name)?,
        _ => {
            let values = PyDict::new(py);
            for (n, x) in &parameters {
                values.set_item(n, x)?;
            }
            Mechanism::from_text(py, text, &values, name)?
        }
    };
    for (n, x) in &parameters {
        made.set_parameter(n, *x)?;
    }
    Ok(made)
}
