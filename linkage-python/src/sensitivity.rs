//! Sensitivities from Python: `Mechanism.sensitivities` and its result,
//! `Sensitivities` — the exact derivatives of a pose by the parameters.

use crate::arrays::{array2, array3};
use crate::errors::Failure;
use crate::pose::{Analyze, PoseOf, owned};
use linkage::Sensitivities as _;
use linkage::mechanism::Fixed;
use linkage::mechanism::sizes::{PARAMETERS, SensitivityJob};
use linkage::prelude::*;
use numpy::{PyArray2, PyArray3};
use pyo3::prelude::*;

/// The derivatives of a pose by each parameter of `parameter_names`, the
/// drivers' motion held fixed: `u`, `udot`, `uddot` (m, parameters) and
/// the points' `points`, `point_velocities`, `point_accelerations`
/// (points, 2, parameters). Exact: differentiated symbolically, not by
/// finite differences.
#[pyclass(module = "linkage", frozen)]
pub struct Sensitivities {
    #[pyo3(get)]
    u: Py<PyArray2<f64>>,
    #[pyo3(get)]
    udot: Py<PyArray2<f64>>,
    #[pyo3(get)]
    uddot: Py<PyArray2<f64>>,
    #[pyo3(get)]
    points: Py<PyArray3<f64>>,
    #[pyo3(get)]
    point_velocities: Py<PyArray3<f64>>,
    #[pyo3(get)]
    point_accelerations: Py<PyArray3<f64>>,
    #[pyo3(get)]
    parameter_names: Vec<String>,
    #[pyo3(get)]
    u_names: Vec<String>,
    #[pyo3(get)]
    point_names: Vec<String>,
}

/// The numbers of the sensitivities, row by row.
pub struct Differentiated {
    m: usize,
    points: usize,
    columns: usize,
    u: [Vec<f64>; 3],
    p: [Vec<f64>; 3],
    parameter_names: Vec<String>,
    u_names: Vec<String>,
    point_names: Vec<String>,
}

/// The sensitivities at the pose `analyze` asks for.
pub struct Differentiate<'a> {
    pub analyze: Analyze<'a>,
}

impl SensitivityJob for Differentiate<'_> {
    type Output = Differentiated;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P, PARAMETERS>,
    ) -> Result<Differentiated, Failure> {
        let PoseOf { pose, .. } = self.analyze.pose(&model)?;
        let s = model.sensitivities_of(&pose, &Options::default())?;
        // The chosen parameters' columns (those after them are zero).
        let names: Vec<&str> = (model.param_names().into_iter())
            .filter(|n| !n.is_empty())
            .collect();
        let k = names.len();
        let point_count = model.point_names().len();
        let by_row = |matrix: &SMatrix<f64, M, PARAMETERS>| -> Vec<f64> {
            (0..M)
                .flat_map(|i| (0..k).map(move |j| matrix[(i, j)]))
                .collect()
        };
        let by_point = |columns: &[<Fixed<M, F, P, PARAMETERS> as Kernels<M, F>>::Points;
                             PARAMETERS]|
         -> Vec<f64> {
            let mut out = Vec::with_capacity(point_count * 2 * k);
            for p in 0..point_count {
                for axis in 0..2 {
                    out.extend((0..k).map(|j| columns[j].as_ref()[p][axis]));
                }
            }
            out
        };
        Ok(Differentiated {
            m: M,
            points: point_count,
            columns: k,
            u: [by_row(&s.u), by_row(&s.udot), by_row(&s.uddot)],
            p: [
                by_point(&s.points),
                by_point(&s.point_velocities),
                by_point(&s.point_accelerations),
            ],
            parameter_names: names.iter().map(|n| (*n).to_owned()).collect(),
            u_names: owned(&model.u_names()),
            point_names: owned(model.point_names()),
        })
    }
}

impl Sensitivities {
    pub fn new(py: Python<'_>, d: Differentiated) -> Sensitivities {
        let (m, n, k) = (d.m, d.points, d.columns);
        let [u, udot, uddot] = d.u;
        let [p, pv, pa] = d.p;
        Sensitivities {
            u: array2(py, m, k, u),
            udot: array2(py, m, k, udot),
            uddot: array2(py, m, k, uddot),
            points: array3(py, (n, 2, k), p),
            point_velocities: array3(py, (n, 2, k), pv),
            point_accelerations: array3(py, (n, 2, k), pa),
            parameter_names: d.parameter_names,
            u_names: d.u_names,
            point_names: d.point_names,
        }
    }
}

#[pymethods]
impl Sensitivities {
    fn __repr__(&self) -> String {
        format!(
            "Sensitivities(d[{}] by [{}])",
            self.u_names.join(", "),
            self.parameter_names.join(", ")
        )
    }
}
