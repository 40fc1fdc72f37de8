//! What `Pose` and `Sweep` share as mappings of a mechanism's names: the
//! names they take (u, then v, then the points), iteration over them, and
//! the error of a name they do not have.

use pyo3::exceptions::PyKeyError;
use pyo3::prelude::*;

/// The names of u, v and the points, in that order.
pub fn keys(u: &[String], v: &[String], points: &[String]) -> Vec<String> {
    u.iter().chain(v).chain(points).cloned().collect()
}

/// An iterator over `keys`, for `__iter__`.
pub fn iterate(py: Python<'_>, keys: Vec<String>) -> PyResult<Py<PyAny>> {
    Ok(keys.into_pyobject(py)?.try_iter()?.into_any().unbind())
}

/// The `KeyError` of a name that is none of them.
pub fn unknown(name: &str, u: &[String], v: &[String], points: &[String]) -> PyErr {
    PyKeyError::new_err(format!(
        "`{name}` is no coordinate or point of the mechanism (u: [{}], v: [{}], points: [{}])",
        u.join(", "),
        v.join(", "),
        points.join(", ")
    ))
}
