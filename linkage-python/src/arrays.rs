//! Values between Python and the library: numbers and sequences in, as the
//! vectors of a mechanism's sizes (their lengths checked against its
//! names), and NumPy arrays out.

use crate::errors::Failure;
use linkage::prelude::SVector;
use numpy::ndarray::{Array1, Array2, Array3};
use numpy::{AllowTypeChange, IntoPyArray, PyArray1, PyArray2, PyArray3, PyArrayLike1};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyFloat, PyInt, PyString};

/// The values of an argument: a number, or a one-dimensional sequence or
/// array of numbers; `None` when not given.
pub fn values(argument: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<f64>>> {
    let Some(argument) = argument else {
        return Ok(None);
    };
    if argument.is_none() {
        return Ok(None);
    }
    let refused = || {
        let mut shown = (argument.repr()).map_or_else(|_| "this".to_owned(), |r| r.to_string());
        if shown.chars().count() > 60 {
            shown = shown.chars().take(57).collect::<String>() + "...";
        }
        PyTypeError::new_err(format!(
            "expected a number or a sequence of numbers, not {shown}"
        ))
    };
    if argument.is_instance_of::<PyFloat>()
        || (argument.is_instance_of::<PyInt>() && !argument.is_instance_of::<PyBool>())
    {
        return Ok(Some(vec![argument.extract::<f64>()?]));
    }
    let (shape, values) = numbers(argument).ok_or_else(refused)?;
    if shape.len() > 1 {
        return Err(refused());
    }
    Ok(Some(values))
}

/// The numbers of an argument NumPy reads as an array of integers or
/// reals (not complex numbers, not booleans, not text), with its shape;
/// `None` for anything else.
fn numbers(argument: &Bound<'_, PyAny>) -> Option<(Vec<usize>, Vec<f64>)> {
    if argument.is_instance_of::<PyString>() || argument.is_instance_of::<PyBytes>() {
        return None;
    }
    let numpy = argument.py().import("numpy").ok()?;
    let array = numpy.call_method1("asarray", (argument,)).ok()?;
    let kind: String = array
        .getattr("dtype")
        .ok()?
        .getattr("kind")
        .ok()?
        .extract()
        .ok()?;
    if !matches!(kind.as_str(), "i" | "u" | "f") {
        return None;
    }
    let shape: Vec<usize> = array.getattr("shape").ok()?.extract().ok()?;
    let flat: PyArrayLike1<'_, f64, AllowTypeChange> =
        array.call_method1("reshape", (-1,)).ok()?.extract().ok()?;
    Some((shape, flat.as_array().to_vec()))
}

/// `values` as a vector of `N`: one value for each of `names` (what the
/// argument `argument` gives values of).
pub fn fixed<const N: usize>(
    values: &[f64],
    argument: &str,
    names: &[&str],
) -> Result<SVector<f64, N>, Failure> {
    if values.len() != N {
        return Err(Failure::BadInput(format!(
            "`{argument}` has {} value{}; it takes {N}, one for each of [{}]",
            values.len(),
            if values.len() == 1 { "" } else { "s" },
            names.join(", ")
        )));
    }
    Ok(SVector::from_fn(|k, _| values[k]))
}

/// `array`, read-only: a result's arrays are its own numbers, which the
/// result's other accessors read too.
fn frozen<T>(array: Bound<'_, T>) -> Py<T> {
    // Setting a flag of an array just made cannot fail.
    let _ = (array.as_any().getattr("flags")).and_then(|f| f.setattr("writeable", false));
    array.unbind()
}

/// A one-dimensional array.
pub fn array1(py: Python<'_>, values: Vec<f64>) -> Py<PyArray1<f64>> {
    frozen(Array1::from_vec(values).into_pyarray(py))
}

/// A two-dimensional array of `rows` × `columns`, from its values row by
/// row.
pub fn array2(py: Python<'_>, rows: usize, columns: usize, values: Vec<f64>) -> Py<PyArray2<f64>> {
    frozen(
        Array2::from_shape_vec((rows, columns), values)
            .expect("rows × columns values")
            .into_pyarray(py),
    )
}

/// A three-dimensional array of `shape`, from its values in C order.
pub fn array3(py: Python<'_>, shape: (usize, usize, usize), values: Vec<f64>) -> Py<PyArray3<f64>> {
    frozen(
        Array3::from_shape_vec(shape, values)
            .expect("the shape's count of values")
            .into_pyarray(py),
    )
}

/// The rows of a two-dimensional argument of `width` numbers each
/// (`what` says what they are, for the message).
pub fn rows(argument: &Bound<'_, PyAny>, width: usize, what: &str) -> PyResult<Vec<Vec<f64>>> {
    let refused = || {
        PyTypeError::new_err(format!(
            "expected rows of {width} numbers ({what}), as a sequence of sequences or an array of shape (n, {width})"
        ))
    };
    let (shape, flat) = numbers(argument).ok_or_else(refused)?;
    if shape.len() != 2 || shape[1] != width {
        return Err(refused());
    }
    Ok(flat.chunks(width).map(<[f64]>::to_vec).collect())
}

/// Names: one name, or a sequence of them; `None` when not given.
pub fn names(argument: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<String>>> {
    match argument {
        None => Ok(None),
        Some(a) if a.is_none() => Ok(None),
        Some(a) if a.is_instance_of::<PyString>() => Ok(Some(vec![a.extract()?])),
        Some(a) => Ok(Some(a.extract()?)),
    }
}
