//! One pose analysed: `Mechanism.analyze` and its result, `Pose`.

use crate::arrays::{array1, array2};
use crate::errors::Failure;
use crate::source::Source;
use linkage::file::FixedAnalysis;
use linkage::mechanism::Fixed;
use linkage::mechanism::sizes::Job;
use linkage::prelude::*;
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;

/// A pose with its velocities and accelerations: the coordinates u, u̇, ü
/// (arrays of m values, in the order of `u_names`), the drivers v, v̇, v̈,
/// and the named points' positions, velocities and accelerations (arrays
/// of shape (points, 2), in the order of `point_names`).
/// `pose["theta3"]` is one coordinate's value, `pose["C"]` one point's
/// position.
#[pyclass(module = "linkage", frozen)]
pub struct Pose {
    #[pyo3(get)]
    u: Py<PyArray1<f64>>,
    #[pyo3(get)]
    udot: Py<PyArray1<f64>>,
    #[pyo3(get)]
    uddot: Py<PyArray1<f64>>,
    #[pyo3(get)]
    v: Py<PyArray1<f64>>,
    #[pyo3(get)]
    vdot: Py<PyArray1<f64>>,
    #[pyo3(get)]
    vddot: Py<PyArray1<f64>>,
    #[pyo3(get)]
    points: Py<PyArray2<f64>>,
    #[pyo3(get)]
    point_velocities: Py<PyArray2<f64>>,
    #[pyo3(get)]
    point_accelerations: Py<PyArray2<f64>>,
    /// ‖Ψ‖∞ at the pose.
    #[pyo3(get)]
    residual: f64,
    /// The reciprocal condition number of Ψ_u at the pose.
    #[pyo3(get)]
    rcond: f64,
    /// Newton's steps to the pose.
    #[pyo3(get)]
    iterations: usize,
    #[pyo3(get)]
    u_names: Vec<String>,
    #[pyo3(get)]
    v_names: Vec<String>,
    #[pyo3(get)]
    point_names: Vec<String>,
    values: Analysed,
}

/// A pose's numbers, as the analysis gave them.
#[derive(Clone, Debug)]
pub struct Analysed {
    u: Vec<f64>,
    udot: Vec<f64>,
    uddot: Vec<f64>,
    v: Vec<f64>,
    vdot: Vec<f64>,
    vddot: Vec<f64>,
    /// x, y of each point.
    points: Vec<f64>,
    point_velocities: Vec<f64>,
    point_accelerations: Vec<f64>,
    residual: f64,
    rcond: f64,
    iterations: usize,
    u_names: Vec<String>,
    v_names: Vec<String>,
    point_names: Vec<String>,
}

/// The analysis of one pose: the drivers' values given, or the file's.
pub struct Analyze<'a> {
    pub source: &'a Source,
    pub v: Option<Vec<f64>>,
    pub vdot: Option<Vec<f64>>,
    pub vddot: Option<Vec<f64>>,
    pub u: Option<Vec<f64>>,
}

/// x, y of each point of a set, in order.
pub fn flat(points: &[Vector2<f64>]) -> Vec<f64> {
    points.iter().flat_map(|p| [p.x, p.y]).collect()
}

pub fn owned(names: &[&str]) -> Vec<String> {
    names.iter().map(|n| (*n).to_owned()).collect()
}

impl Analyze<'_> {
    /// The pose these arguments ask of `model`: the drivers' values given
    /// or the file's, Newton from `u` or from the file's assembly.
    pub fn pose<const M: usize, const F: usize, const N: usize, const K: usize>(
        &self,
        model: &Fixed<M, F, N, K>,
    ) -> Result<PoseOf<M, F, N, K>, Failure> {
        let v_names = model.v_names();
        let drives = self.source.drives(model)?;
        let v = Source::or_file(self.v.as_deref(), "v", &v_names, drives.map(|d| d.at), None)?;
        let vdot = Source::or_file(
            self.vdot.as_deref(),
            "vdot",
            &v_names,
            drives.map(|d| d.rate),
            Some(1.0),
        )?;
        let vddot = Source::or_file(
            self.vddot.as_deref(),
            "vddot",
            &v_names,
            drives.map(|d| d.acceleration),
            Some(0.0),
        )?;
        // Inputs checked before an assembly is searched for at them.
        for (argument, values) in [("v", &v), ("vdot", &vdot), ("vddot", &vddot)] {
            if let Some(index) = values.iter().position(|x| !x.is_finite()) {
                return Err(Failure::Analysis(linkage::Error::NonFiniteInput {
                    argument,
                    index,
                    value: values[index],
                }));
            }
        }
        let u = match &self.u {
            Some(u) => crate::arrays::fixed::<M>(u, "u", &model.u_names())?,
            None => self.source.assembled(model, &v)?,
        };
        let pose = model.analyze(&u, &v, &vdot, &vddot, &Options::default())?;
        Ok(PoseOf {
            pose,
            v,
            vdot,
            vddot,
        })
    }
}

/// A pose of a view of a run-time mechanism, with the drivers' motion it
/// was analysed at.
pub struct PoseOf<const M: usize, const F: usize, const N: usize, const K: usize> {
    pub pose: FixedAnalysis<M, F, N, K>,
    pub v: SVector<f64, F>,
    pub vdot: SVector<f64, F>,
    pub vddot: SVector<f64, F>,
}

impl Job for Analyze<'_> {
    type Output = Analysed;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<Analysed, Failure> {
        let PoseOf {
            pose,
            v,
            vdot,
            vddot,
        } = self.pose(&model)?;
        Ok(Analysed {
            u: pose.u.as_slice().to_vec(),
            udot: pose.udot.as_slice().to_vec(),
            uddot: pose.uddot.as_slice().to_vec(),
            v: v.as_slice().to_vec(),
            vdot: vdot.as_slice().to_vec(),
            vddot: vddot.as_slice().to_vec(),
            points: flat(pose.points.as_ref()),
            point_velocities: flat(pose.point_velocities.as_ref()),
            point_accelerations: flat(pose.point_accelerations.as_ref()),
            residual: pose.residual,
            rcond: pose.rcond,
            iterations: pose.iterations,
            u_names: owned(&model.u_names()),
            v_names: owned(&model.v_names()),
            point_names: owned(model.point_names()),
        })
    }
}

impl Pose {
    pub fn new(py: Python<'_>, values: Analysed) -> Pose {
        let n = values.point_names.len();
        let a = values.clone();
        Pose {
            u: array1(py, a.u),
            udot: array1(py, a.udot),
            uddot: array1(py, a.uddot),
            v: array1(py, a.v),
            vdot: array1(py, a.vdot),
            vddot: array1(py, a.vddot),
            points: array2(py, n, 2, a.points),
            point_velocities: array2(py, n, 2, a.point_velocities),
            point_accelerations: array2(py, n, 2, a.point_accelerations),
            residual: a.residual,
            rcond: a.rcond,
            iterations: a.iterations,
            u_names: a.u_names,
            v_names: a.v_names,
            point_names: a.point_names,
            values,
        }
    }
}

#[pymethods]
impl Pose {
    /// A coordinate's value (u or v) by its name, or a named point's
    /// position as an array [x, y].
    fn __getitem__<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        let a = &self.values;
        if let Some(k) = a.u_names.iter().position(|n| n == name) {
            return Ok(a.u[k].into_pyobject(py)?.into_any());
        }
        if let Some(k) = a.v_names.iter().position(|n| n == name) {
            return Ok(a.v[k].into_pyobject(py)?.into_any());
        }
        if let Some(k) = a.point_names.iter().position(|n| n == name) {
            let xy = a.points[2 * k..2 * k + 2].to_vec();
            return Ok(array1(py, xy).into_bound(py).into_any());
        }
        Err(crate::names::unknown(
            name,
            &a.u_names,
            &a.v_names,
            &a.point_names,
        ))
    }

    /// The names `pose[name]` takes: the coordinates u and v, the points.
    fn keys(&self) -> Vec<String> {
        let a = &self.values;
        crate::names::keys(&a.u_names, &a.v_names, &a.point_names)
    }

    fn __contains__(&self, name: &str) -> bool {
        self.keys().iter().any(|n| n == name)
    }

    fn __iter__(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        crate::names::iterate(py, self.keys())
    }

    fn __repr__(&self) -> String {
        let a = &self.values;
        let pairs = |names: &[String], values: &[f64]| {
            (names.iter().zip(values))
                .map(|(n, x)| format!("{n}={x}"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        format!(
            "Pose({}; {})",
            pairs(&a.v_names, &a.v),
            pairs(&a.u_names, &a.u)
        )
    }
}
