//! linkage for Python: the library's run-time mechanisms — a mechanism
//! file, a topology, the attribute's text, pyslvs's expression or
//! pylinkage's JSON — and their analyses, with NumPy arrays in and out and
//! the library's errors as typed Python exceptions (`linkage.errors`).
//!
//! Every analysis is the library's own, run on the mechanism at its sizes
//! through `linkage::mechanism::sizes`, with the GIL released.

mod arrays;
mod design;
mod errors;
mod extremes;
mod interrupt;
mod mechanism;
mod names;
mod pool;
mod pose;
mod sensitivity;
mod source;
mod sweep;
mod tolerance;

use pyo3::prelude::*;

/// The extension module `linkage._linkage`; `linkage` re-exports it.
#[pymodule]
fn _linkage(module: &Bound<'_, PyModule>) -> PyResult<()> {
    module.add_class::<mechanism::Mechanism>()?;
    module.add_class::<pose::Pose>()?;
    module.add_class::<design::Designs>()?;
    module.add_class::<sensitivity::Sensitivities>()?;
    module.add_class::<sweep::Sweep>()?;
    module.add_function(wrap_pyfunction!(mechanism::_remake, module)?)?;
    module.add("SIZES", linkage::mechanism::sizes::SIZES.to_vec())?;
    Ok(())
}
