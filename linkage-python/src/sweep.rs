//! A sweep through the drive range: `Mechanism.sweep` and its result,
//! `Sweep`.

use crate::arrays::{array1, array2, array3};
use crate::errors::Failure;
use crate::pose::{flat, owned};
use crate::source::Source;
use linkage::file::MOST_STEPS;
use linkage::mechanism::Fixed;
use linkage::mechanism::sizes::Job;
use linkage::prelude::*;
use numpy::ndarray::Axis;
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The poses of a sweep, one row per pose: `v`, `vdot` (poses, f), `u`,
/// `udot`, `uddot` (poses, m), `rcond` (poses,), and the named points'
/// `points`, `point_velocities`, `point_accelerations` (poses, points, 2).
/// `events` are the singular poses met, located; `complete` says whether
/// the sweep reached the end of its drive. `sweep["theta3"]` is one
/// coordinate's column, `sweep["C"]` one point's path (poses, 2).
#[pyclass(module = "linkage", frozen)]
pub struct Sweep {
    #[pyo3(get)]
    v: Py<PyArray2<f64>>,
    #[pyo3(get)]
    vdot: Py<PyArray2<f64>>,
    #[pyo3(get)]
    u: Py<PyArray2<f64>>,
    #[pyo3(get)]
    udot: Py<PyArray2<f64>>,
    #[pyo3(get)]
    uddot: Py<PyArray2<f64>>,
    #[pyo3(get)]
    rcond: Py<PyArray1<f64>>,
    #[pyo3(get)]
    points: Py<PyArray3<f64>>,
    #[pyo3(get)]
    point_velocities: Py<PyArray3<f64>>,
    #[pyo3(get)]
    point_accelerations: Py<PyArray3<f64>>,
    /// Each singular pose met: a dict of `kind` ("limit position" or
    /// "branch point"), `v`, `u`, `after` (the poses recorded before it).
    #[pyo3(get)]
    events: Vec<Py<PyDict>>,
    #[pyo3(get)]
    complete: bool,
    poses: usize,
    #[pyo3(get)]
    u_names: Vec<String>,
    #[pyo3(get)]
    v_names: Vec<String>,
    #[pyo3(get)]
    point_names: Vec<String>,
}

/// A singular pose met.
#[derive(Clone, Debug)]
pub struct Met {
    kind: &'static str,
    v: Vec<f64>,
    u: Vec<f64>,
    after: usize,
}

/// The numbers of a sweep, row by row.
#[derive(Clone, Debug, Default)]
pub struct Swept {
    poses: usize,
    v: Vec<f64>,
    vdot: Vec<f64>,
    u: Vec<f64>,
    udot: Vec<f64>,
    uddot: Vec<f64>,
    rcond: Vec<f64>,
    points: Vec<f64>,
    point_velocities: Vec<f64>,
    point_accelerations: Vec<f64>,
    events: Vec<Met>,
    complete: bool,
    u_names: Vec<String>,
    v_names: Vec<String>,
    point_names: Vec<String>,
}

/// Where a sweep goes: the file's drive, or the range, steps and rate
/// given (what is not given taken from the file); Newton starts from `u`
/// if given.
#[derive(Clone, Debug, Default)]
pub struct DriveArgs {
    pub steps: Option<usize>,
    pub start: Option<Vec<f64>>,
    pub stop: Option<Vec<f64>>,
    pub rate: Option<Vec<f64>>,
    pub u: Option<Vec<f64>>,
}

/// A sweep's start, drive and options, at a mechanism's sizes.
pub type Resolved<const M: usize, const F: usize> = (SVector<f64, M>, Drive<F>, SweepOptions);

impl DriveArgs {
    /// The sweep these arguments ask of `model`.
    pub fn resolve<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        source: &Source,
        model: &Fixed<M, F, N, K>,
    ) -> Result<Resolved<M, F>, Failure> {
        let v_names = model.v_names();
        let drives = source.drives(model)?;
        if let Some(steps) = self.steps
            && !(1..=MOST_STEPS).contains(&steps)
        {
            return Err(Failure::BadInput(format!(
                "`steps` is {steps}: a sweep takes 1 to {MOST_STEPS} steps"
            )));
        }
        let steps = (self.steps).or(drives.map(|d| d.steps)).unwrap_or(STEPS);
        let as_file =
            self.start.is_none() && self.stop.is_none() && self.rate.is_none() && self.u.is_none();
        if let Some(loaded) = &source.loaded
            && as_file
        {
            let swept = loaded.swept(model, steps)?;
            return Ok((swept.start, swept.drive, swept.options));
        }
        let from = Source::or_file(
            self.start.as_deref(),
            "start",
            &v_names,
            drives.map(|d| d.from),
            None,
        )?;
        let to = Source::or_file(
            self.stop.as_deref(),
            "stop",
            &v_names,
            drives.map(|d| d.to),
            None,
        )?;
        let rate = Source::or_file(
            self.rate.as_deref(),
            "rate",
            &v_names,
            drives.map(|d| d.rate),
            Some(1.0),
        )?;
        if F > 1 && self.rate.is_some() {
            return Err(Failure::BadInput(format!(
                "`rate` is for one driving coordinate: a sweep of several ([{}]) moves them along \
                 the line from `start` to `stop` at unit speed",
                v_names.join(", ")
            )));
        }
        let mut options = SweepOptions::default();
        if F == 1 {
            options.speed = rate[0];
        }
        for (argument, values) in [("start", &from), ("stop", &to), ("rate", &rate)] {
            if let Some(index) = values.iter().position(|x| !x.is_finite()) {
                return Err(Failure::Analysis(linkage::Error::NonFiniteInput {
                    argument,
                    index,
                    value: values[index],
                }));
            }
        }
        if let Some(index) = from.iter().position(|x| !x.is_finite()) {
            return Err(Failure::Analysis(linkage::Error::NonFiniteInput {
                argument: "start",
                index,
                value: from[index],
            }));
        }
        let u0 = match &self.u {
            Some(u) => crate::arrays::fixed::<M>(u, "u", &model.u_names())?,
            None => source.assembled(model, &from)?,
        };
        Ok((u0, Drive::Line { from, to, steps }, options))
    }
}

/// A sweep's poses.
pub struct Poses {
    pub source: Source,
    pub drive: DriveArgs,
}

/// Steps a sweep takes when neither the call nor a file says.
const STEPS: usize = 360;

impl Job for Poses {
    type Output = Swept;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<Swept, Failure> {
        let v_names = model.v_names();
        let (u0, drive, options) = self.drive.resolve(&self.source, &model)?;
        let mut out = Swept::default();
        let points = !model.point_names().is_empty();
        let summary = model.sweep_each(&u0, &drive, &options, |pose| {
            out.poses += 1;
            out.v.extend(pose.v.iter());
            out.vdot.extend(pose.vdot.iter());
            out.u.extend(pose.u.iter());
            out.udot.extend(pose.udot.iter());
            out.uddot.extend(pose.uddot.iter());
            out.rcond.push(pose.rcond);
            if points {
                let p = model.point_positions(&pose.u, &pose.v);
                let pv = model.point_velocities(&pose.u, &pose.v, &pose.udot, &pose.vdot);
                let pa = model.point_accelerations(
                    &pose.u,
                    &pose.v,
                    &pose.udot,
                    &pose.vdot,
                    &pose.uddot,
                    &SVector::zeros(),
                );
                out.points.extend(flat(p.as_ref()));
                out.point_velocities.extend(flat(pv.as_ref()));
                out.point_accelerations.extend(flat(pa.as_ref()));
            }
        })?;
        out.events = (summary.events.iter())
            .map(|event| Met {
                kind: match event.kind {
                    EventKind::LimitPosition => "limit position",
                    EventKind::BranchPoint => "branch point",
                },
                v: event.v.as_slice().to_vec(),
                u: event.u.as_slice().to_vec(),
                after: event.after,
            })
            .collect();
        out.complete = summary.complete;
        out.u_names = owned(&model.u_names());
        out.v_names = owned(&v_names);
        out.point_names = owned(model.point_names());
        Ok(out)
    }
}

impl Sweep {
    pub fn new(py: Python<'_>, s: Swept) -> PyResult<Sweep> {
        let (n, m, f, p) = (
            s.poses,
            s.u_names.len(),
            s.v_names.len(),
            s.point_names.len(),
        );
        let mut events = Vec::new();
        for event in &s.events {
            let dict = PyDict::new(py);
            dict.set_item("kind", event.kind)?;
            dict.set_item("v", array1(py, event.v.clone()))?;
            dict.set_item("u", array1(py, event.u.clone()))?;
            dict.set_item("after", event.after)?;
            events.push(dict.unbind());
        }
        Ok(Sweep {
            v: array2(py, n, f, s.v),
            vdot: array2(py, n, f, s.vdot),
            u: array2(py, n, m, s.u),
            udot: array2(py, n, m, s.udot),
            uddot: array2(py, n, m, s.uddot),
            rcond: array1(py, s.rcond),
            points: array3(py, (n, p, 2), s.points),
            point_velocities: array3(py, (n, p, 2), s.point_velocities),
            point_accelerations: array3(py, (n, p, 2), s.point_accelerations),
            events,
            complete: s.complete,
            poses: n,
            u_names: s.u_names,
            v_names: s.v_names,
            point_names: s.point_names,
        })
    }
}

#[pymethods]
impl Sweep {
    /// The names `sweep[name]` takes: the coordinates u and v, the points.
    fn keys(&self) -> Vec<String> {
        crate::names::keys(&self.u_names, &self.v_names, &self.point_names)
    }

    fn __contains__(&self, name: &str) -> bool {
        self.keys().iter().any(|n| n == name)
    }

    /// Its names, as a mapping's keys (not its poses: `len` counts those).
    fn __iter__(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        crate::names::iterate(py, self.keys())
    }

    /// The number of poses.
    fn __len__(&self) -> usize {
        self.poses
    }

    /// A coordinate's column (u or v) by its name, or a named point's
    /// path, shape (poses, 2).
    fn __getitem__<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        let index = |names: &[String]| names.iter().position(|n| n == name);
        let column = |array: &Py<PyArray2<f64>>, k: usize| {
            let column = array.bind(py).readonly().as_array().column(k).to_owned();
            column.into_pyarray(py).into_any()
        };
        if let Some(k) = index(&self.u_names) {
            return Ok(column(&self.u, k));
        }
        if let Some(k) = index(&self.v_names) {
            return Ok(column(&self.v, k));
        }
        if let Some(k) = index(&self.point_names) {
            let points = self.points.bind(py).readonly();
            let path = points.as_array().index_axis(Axis(1), k).to_owned();
            return Ok(path.into_pyarray(py).into_any());
        }
        Err(crate::names::unknown(
            name,
            &self.u_names,
            &self.v_names,
            &self.point_names,
        ))
    }

    fn __repr__(&self) -> String {
        format!(
            "Sweep({} poses of [{}] against [{}], {} singular pose{} met{})",
            self.poses,
            self.u_names.join(", "),
            self.v_names.join(", "),
            self.events.len(),
            if self.events.len() == 1 { "" } else { "s" },
            if self.complete { "" } else { ", stopped early" }
        )
    }
}
