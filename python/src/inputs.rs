//! Reading numpy inputs: one state `(n,)` or a batch `(N, n)`, real numbers only, finite, and
//! returning results in the matching shape. Every refusal is a `ValueError` naming the argument.

use numpy::ndarray::{ArrayD, ArrayViewD, IxDyn};
use numpy::{IntoPyArray, PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods, ToPyArray};

/// Outputs of at most this many numbers are copied into a new numpy array; larger ones hand
/// their buffer over.
const SMALL_OUTPUT: usize = 4096;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

/// States read from one argument: `rows` states of `width` numbers each, row after row.
#[derive(Clone, Debug)]
pub struct States {
    /// The numbers, row-major.
    pub data: Vec<f64>,
    /// How many states.
    pub rows: usize,
    /// Whether the argument was a batch `(N, width)` (else one state `(width,)`).
    pub batched: bool,
}

/// `obj` as `float64` numbers: any real (integer or floating) array or sequence; a clear
/// `ValueError` naming `name` for anything else.
fn as_float_array<'py>(
    obj: &Bound<'py, PyAny>,
    name: &str,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    // A float64 array as it is (the common case: no call into numpy).
    if let Ok(a) = obj.cast::<PyArrayDyn<f64>>() {
        return Ok(a.clone());
    }
    let py = obj.py();
    let np = py.import("numpy")?;
    let array = np
        .call_method1("asarray", (obj,))
        .map_err(|e| PyValueError::new_err(format!("{name}: cannot be read as an array ({e})")))?;
    let dtype = array.getattr("dtype")?;
    let kind: String = dtype.getattr("kind")?.extract()?;
    if !matches!(kind.as_str(), "i" | "u" | "f") {
        return Err(PyValueError::new_err(format!(
            "{name}: dtype {} is not a real number type (expected float64, or integer or float numbers)",
            dtype.str()?
        )));
    }
    let floats = array.call_method1("astype", ("float64",))?;
    floats
        .cast_into::<PyArrayDyn<f64>>()
        .map_err(|e| PyValueError::new_err(format!("{name}: {e}")))
}

/// Reads `obj` as one state of `width` numbers or a batch of them; every value finite.
///
/// # Errors
///
/// `ValueError` naming `name`: not real numbers, a shape other than `(width,)` or
/// `(N, width)`, an empty batch, a NaN or infinite value (with its index).
pub fn states(obj: &Bound<'_, PyAny>, name: &str, width: usize) -> PyResult<States> {
    let array = as_float_array(obj, name)?;
    let shape = array.shape().to_vec();
    let (rows, batched) = match shape.as_slice() {
        [w] if *w == width => (1, false),
        [r, w] if *w == width => (*r, true),
        _ => {
            return Err(PyValueError::new_err(format!(
                "{name}: shape {} does not fit: expected ({width},) for one state or (N, {width}) for N states",
                shape_text(&shape)
            )))
        }
    };
    if batched && rows == 0 {
        return Err(PyValueError::new_err(format!(
            "{name}: an empty batch (0, {width}): give at least one state"
        )));
    }
    // A contiguous array is copied in one go (no borrow bookkeeping); any other through a view.
    let data: Vec<f64> = match array.to_vec() {
        Ok(v) => v,
        Err(_) => array.readonly().as_array().iter().copied().collect(),
    };
    if let Some(k) = data.iter().position(|x| !x.is_finite()) {
        let at = if batched {
            format!("[{}, {}]", k / width, k % width)
        } else {
            format!("[{k}]")
        };
        return Err(PyValueError::new_err(format!(
            "{name}{at} is {}: every value must be finite",
            data[k]
        )));
    }
    Ok(States {
        data,
        rows,
        batched,
    })
}

/// Reads a vector of exactly `len` finite numbers (parameters, limits).
///
/// # Errors
///
/// `ValueError` naming `name`.
pub fn vector(obj: &Bound<'_, PyAny>, name: &str, len: usize) -> PyResult<Vec<f64>> {
    let s = states(obj, name, len)?;
    if s.batched {
        return Err(PyValueError::new_err(format!(
            "{name}: expected one vector of shape ({len},), not a batch"
        )));
    }
    Ok(s.data)
}

/// Checks that every batch argument has as many states as the first and that they are all
/// batches or all single states.
///
/// # Errors
///
/// `ValueError` naming the argument that differs.
pub fn same_rows(args: &[(&str, &States)]) -> PyResult<(usize, bool)> {
    let (first, s0) = args[0];
    for (name, s) in &args[1..] {
        if s.batched != s0.batched || s.rows != s0.rows {
            return Err(PyValueError::new_err(format!(
                "{name}: {} where {first} has {}: give both as single states or as batches of equal length",
                count_text(s),
                count_text(s0)
            )));
        }
    }
    Ok((s0.rows, s0.batched))
}

fn count_text(s: &States) -> String {
    if s.batched {
        format!("{} states", s.rows)
    } else {
        "one state".to_string()
    }
}

fn shape_text(shape: &[usize]) -> String {
    match shape {
        [one] => format!("({one},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// `data` (`rows` results of shape `each`, row-major) as a numpy array: `(rows, *each)` for a
/// batch, `each` for one state.
pub fn output<'py>(
    py: Python<'py>,
    data: Vec<f64>,
    rows: usize,
    batched: bool,
    each: &[usize],
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let mut shape = Vec::with_capacity(each.len() + 1);
    if batched {
        shape.push(rows);
    }
    shape.extend_from_slice(each);
    let error =
        |e: numpy::ndarray::ShapeError| PyValueError::new_err(format!("internal shape error: {e}"));
    if data.len() <= SMALL_OUTPUT {
        // Copied into an array numpy owns: cheaper to make than one that owns Rust's buffer.
        let view = ArrayViewD::from_shape(IxDyn(&shape), &data).map_err(error)?;
        return Ok(view.to_pyarray(py));
    }
    Ok(ArrayD::from_shape_vec(IxDyn(&shape), data)
        .map_err(error)?
        .into_pyarray(py))
}
