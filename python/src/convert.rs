//! The conversions every export shares: point sets in (numpy arrays and array-likes), the
//! core's results out (one mechanism: its `Serialize` → a [`FisstResult`] per struct, numpy
//! arrays for numeric arrays), and the core's errors as Python exceptions naming the argument.

use numpy::{AllowTypeChange, PyArrayLikeDyn, PyUntypedArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyString;
use serde::Serialize;

/// The Python exception for a core error: a `ValueError` whose message starts with the path
/// of the offending argument in Python's names (the core's Rust names, with the matrix names
/// `F`, `Q`, `H`, `R` in their papers' capitals), as numpy does for a wrong length, shape or
/// value; a `TypeError` for a value of the wrong kind for the other arguments
/// ([`fisst::Error::is_wrong_kind`]: rows where a 1D prior takes a number, two alternatives
/// both given).
pub fn to_py(e: fisst::Error) -> PyErr {
    let e = e.map_paths(crate::names::render_path);
    if e.is_wrong_kind() {
        PyTypeError::new_err(e.to_string())
    } else {
        PyValueError::new_err(e.to_string())
    }
}

/// A point set read from Python: an `(n, d)` array-like of numbers (a numpy array of any
/// numeric dtype and layout, a list of lists, a pandas `DataFrame`; converted once to
/// float64 by numpy). An empty sequence is the empty set.
pub fn points(value: &Bound<'_, PyAny>, name: &str) -> PyResult<Points> {
    if value.is_instance_of::<PyString>() || value.is_none() {
        return Err(PyTypeError::new_err(format!(
            "{name} must be an (n, d) array of numbers, got {}",
            value.get_type().name()?
        )));
    }
    let array: PyArrayLikeDyn<'_, f64, AllowTypeChange> = value.extract().map_err(|e: PyErr| {
        PyTypeError::new_err(format!(
            "{name} must be an (n, d) array of numbers: {}",
            e.value(value.py())
        ))
    })?;
    let dims = array.shape().to_vec();
    match dims.as_slice() {
        [0] => Ok(Points {
            flat: Vec::new(),
            n: 0,
            d: 0,
        }),
        &[n, d] => {
            // one copy into a flat buffer: a memcpy for a C-contiguous float64 array
            let view = array.as_array();
            let flat = match view.as_slice() {
                Some(s) => s.to_vec(),                  // C order
                None => view.iter().copied().collect(), // any other layout, in logical order
            };
            Ok(Points { flat, n, d })
        }
        _ => Err(PyValueError::new_err(format!(
            "{name} must be an (n, d) array (one row per point), got shape {}",
            shape(&dims)
        ))),
    }
}

/// A point set read by [`points`]: n points of dimension d, row-major in one buffer.
pub struct Points {
    flat: Vec<f64>,
    n: usize,
    d: usize,
}

impl Points {
    /// The number of points n.
    #[allow(clippy::len_without_is_empty)]
    pub fn len(&self) -> usize {
        self.n
    }

    /// The dimension d.
    pub fn dim(&self) -> usize {
        self.d
    }

    /// The coordinates, row-major.
    pub fn flat(&self) -> &[f64] {
        &self.flat
    }

    /// The points, one slice each (borrowed from the buffer).
    pub fn rows(&self) -> Vec<&[f64]> {
        if self.d == 0 {
            // (n, 0): n points of dimension 0 (the core says what it makes of them)
            return vec![&[][..]; self.n];
        }
        self.flat.chunks(self.d).collect()
    }
}

/// A function of point sets generic over the point type, so that [`with_points`] can call it
/// with fixed-size points.
pub trait OnPoints {
    /// What the function returns.
    type Output;
    /// Calls the function with `sets` (each a point set), all of one point type.
    fn call<P: AsRef<[f64]> + Sync>(self, sets: &[Vec<P>]) -> Self::Output;
}

/// Calls `f` with the point sets `sets` as `[f64; 2]` or `[f64; 3]` points when every
/// non-empty set has that dimension, else as slices. The core's metrics are generic over the
/// point type: with a dimension the compiler knows, the distance loop is unrolled, which makes
/// `gospa` at n = 1,000 on the sparse scene about as fast as the native call on `[f64; 2]`
/// points (the same arithmetic in the same order: the same bits).
pub fn with_points<F: OnPoints>(sets: &[&Points], f: F) -> F::Output {
    let mut dims = sets.iter().filter(|p| p.n > 0).map(|p| p.d);
    let d = dims.next();
    let one = d.is_some_and(|d| dims.all(|e| e == d));
    fn fixed<const D: usize>(p: &Points) -> Vec<[f64; D]> {
        if p.n == 0 {
            return Vec::new();
        }
        p.flat
            .chunks_exact(D)
            .map(|c| core::array::from_fn(|i| c[i]))
            .collect()
    }
    match (one, d) {
        (true, Some(2)) => f.call(&sets.iter().map(|p| fixed::<2>(p)).collect::<Vec<_>>()),
        (true, Some(3)) => f.call(&sets.iter().map(|p| fixed::<3>(p)).collect::<Vec<_>>()),
        _ => f.call(&sets.iter().map(|p| p.rows()).collect::<Vec<_>>()),
    }
}

/// A shape as Python writes it: `(2,)`, `(3, 2)`.
fn shape(dims: &[usize]) -> String {
    match dims {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            dims.iter()
                .map(|d| d.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// A real number read from Python (a float, an int or a numpy scalar), named `name` in the
/// `TypeError` for anything else.
pub fn number(value: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    if value.is_instance_of::<PyString>() || value.is_none() {
        return Err(PyTypeError::new_err(format!(
            "{name} must be a real number, got {}",
            value.get_type().name()?
        )));
    }
    value.extract::<f64>().map_err(|_| {
        PyTypeError::new_err(format!(
            "{name} must be a real number, got {}",
            value
                .get_type()
                .name()
                .map(|n| n.to_string())
                .unwrap_or_default()
        ))
    })
}

/// [`number`] for an optional argument: `default` when it is omitted or `None`.
pub fn number_or(value: Option<&Bound<'_, PyAny>>, name: &str, default: f64) -> PyResult<f64> {
    match value {
        Some(v) if !v.is_none() => number(v, name),
        _ => Ok(default),
    }
}

/// A sequence of point sets (`truths[t]`): a list (or tuple) of [`points`], each named
/// `name[t]`.
pub fn point_sets(value: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<Points>> {
    if value.is_instance_of::<PyString>() || value.is_none() {
        return Err(PyTypeError::new_err(format!(
            "{name} must be a sequence of (n, d) arrays, got {}",
            value.get_type().name()?
        )));
    }
    let items = value.try_iter().map_err(|_| {
        PyTypeError::new_err(format!(
            "{name} must be a sequence of (n, d) arrays, got {}",
            value
                .get_type()
                .name()
                .map(|n| n.to_string())
                .unwrap_or_default()
        ))
    })?;
    let mut out = Vec::new();
    for (t, item) in items.enumerate() {
        out.push(points(&item?, &format!("{name}[{t}]"))?);
    }
    Ok(out)
}

/// The core's value `value` as Python objects: every struct a `fisst.Result` (attributes
/// under the Rust field names, a readable `repr`, picklable), every array of numbers a numpy
/// array (float64, int64 or bool; an array of equal-length numeric rows a 2-D array),
/// `None` as `None`, a unit enum variant as its name ([`crate::ser`]).
pub fn result<'py, T: Serialize + ?Sized>(
    py: Python<'py>,
    value: &T,
) -> PyResult<Bound<'py, PyAny>> {
    crate::ser::to_python(py, value)
}

/// The seed given, or fresh entropy from the operating system (reported back by the caller,
/// so that the run can be reproduced).
pub fn seed_or_entropy(seed: Option<u64>) -> PyResult<u64> {
    match seed {
        Some(s) => Ok(s),
        None => fisst::math::rng::entropy_seed().map_err(to_py),
    }
}
