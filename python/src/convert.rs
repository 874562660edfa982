//! The conversions every export shares: point sets in (numpy arrays and array-likes), the
//! core's results out (one mechanism: its `Serialize` → a [`FisstResult`] per struct, numpy
//! arrays for numeric arrays), and the core's errors as Python exceptions naming the argument.

use numpy::{AllowTypeChange, PyArrayLikeDyn, PyUntypedArrayMethods, ToPyArray};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyDict, PyFloat, PyInt, PyList, PyMapping, PyString, PyTuple};
use pythonize::{PythonizeMappingType, PythonizeNamedMappingType, PythonizeTypes};
use serde::Serialize;

use crate::result::FisstResult;

/// The Python exception for a core error: a `ValueError` whose message starts with the path
/// of the offending argument in Python's names (the core's Rust names, with the matrix names
/// `F`, `Q`, `H`, `R` in their papers' capitals), as numpy does for a wrong length, shape or
/// value.
pub fn to_py(e: fisst::Error) -> PyErr {
    PyValueError::new_err(e.map_paths(crate::names::render_path).to_string())
}

/// A point set read from Python: an `(n, d)` array-like of numbers (a numpy array of any
/// numeric dtype and layout, a list of lists, a pandas `DataFrame`; converted once to
/// float64 by numpy). An empty sequence is the empty set.
pub fn points(value: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<Vec<f64>>> {
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
    let view = array.as_array();
    match view.ndim() {
        1 if view.is_empty() => Ok(Vec::new()),
        2 => Ok(view.rows().into_iter().map(|r| r.to_vec()).collect()),
        _ => Err(PyValueError::new_err(format!(
            "{name} must be an (n, d) array (one row per point), got shape {}",
            shape(array.shape())
        ))),
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
pub fn point_sets(value: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<Vec<Vec<f64>>>> {
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

/// The core's value `value` as Python objects: every struct a [`FisstResult`] (attributes
/// under the Rust field names, a readable `repr`, picklable), every array of numbers a numpy
/// array (float64, int64 or bool; an array of equal-length numeric rows a 2-D array),
/// `None` as `None`, a unit enum variant as its name.
pub fn result<'py, T: Serialize + ?Sized>(
    py: Python<'py>,
    value: &T,
) -> PyResult<Bound<'py, PyAny>> {
    let out = pythonize::pythonize_custom::<Types, _>(py, value)
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    arrays(py, out)
}

/// A list of numbers as a numpy array, a list of equal-length numeric rows (tuples or 1-D
/// arrays of one dtype) as a 2-D one, bottom-up through nested lists; anything else as it is.
/// Structs convert their own fields as they are built.
fn arrays<'py>(py: Python<'py>, value: Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    if let Ok(bytes) = value.cast::<PyBytes>() {
        // a `Vec<u8>` the core writes as bytes: a uint8 array
        return Ok(bytes.as_bytes().to_pyarray(py).into_any());
    }
    let Ok(list) = value.cast::<PyList>() else {
        return Ok(value);
    };
    let items = list
        .iter()
        .map(|x| arrays(py, x))
        .collect::<PyResult<Vec<Bound<'py, PyAny>>>>()?;
    if items.is_empty() {
        return Ok(Vec::<f64>::new().to_pyarray(py).into_any());
    }
    if let Some(kind) = kind_of(&items) {
        return reshape(py, kind, &items, items.len(), 0);
    }
    // rows of equal length: tuples of numbers
    let rows: Option<Vec<Vec<Bound<'py, PyAny>>>> = items
        .iter()
        .map(|r| r.cast::<PyTuple>().ok().map(|t| t.iter().collect()))
        .collect();
    if let Some(rows) = rows
        && rows.iter().all(|r| r.len() == rows[0].len())
    {
        let flat: Vec<Bound<'py, PyAny>> = rows.concat();
        if let Some(kind) = kind_of(&flat) {
            return reshape(py, kind, &flat, rows.len(), rows[0].len());
        }
    }
    // rows of equal length: 1-D arrays of one dtype
    let first = items[0].cast::<numpy::PyUntypedArray>().ok();
    if let Some(a) = first
        && a.ndim() == 1
        && items.iter().all(|x| {
            x.cast::<numpy::PyUntypedArray>()
                .is_ok_and(|b| b.ndim() == 1 && b.shape() == a.shape() && b.dtype().is(a.dtype()))
        })
    {
        return py.import("numpy")?.call_method1("stack", (items,));
    }
    Ok(PyList::new(py, items)?.into_any())
}

/// The kind of numbers a list holds, if it holds only numbers of one kind.
#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Float,
    Int,
    Bool,
}

fn kind_of(items: &[Bound<'_, PyAny>]) -> Option<Kind> {
    let mut kind = None;
    for x in items {
        let k = if x.is_instance_of::<PyBool>() {
            Kind::Bool
        } else if x.is_instance_of::<PyInt>() {
            Kind::Int
        } else if x.is_instance_of::<PyFloat>() {
            Kind::Float
        } else {
            return None;
        };
        kind = match (kind, k) {
            (None, k) => Some(k),
            (Some(a), b) if a == b => Some(a),
            (Some(Kind::Int), Kind::Float) | (Some(Kind::Float), Kind::Int) => Some(Kind::Float),
            _ => return None,
        };
    }
    kind
}

/// `items` as a numpy array of `kind`: 1-D when `d` is 0, else `n × d`.
fn reshape<'py>(
    py: Python<'py>,
    kind: Kind,
    items: &[Bound<'py, PyAny>],
    n: usize,
    d: usize,
) -> PyResult<Bound<'py, PyAny>> {
    let array = match kind {
        Kind::Float => items
            .iter()
            .map(|x| x.extract::<f64>())
            .collect::<PyResult<Vec<_>>>()?
            .to_pyarray(py)
            .into_any(),
        Kind::Int => items
            .iter()
            .map(|x| x.extract::<i64>())
            .collect::<PyResult<Vec<_>>>()?
            .to_pyarray(py)
            .into_any(),
        Kind::Bool => items
            .iter()
            .map(|x| x.extract::<bool>())
            .collect::<PyResult<Vec<_>>>()?
            .to_pyarray(py)
            .into_any(),
    };
    if d == 0 {
        Ok(array)
    } else {
        array.call_method1("reshape", ((n, d),))
    }
}

/// pythonize's types: plain dicts for maps, [`FisstResult`] for structs, lists (made into
/// arrays by [`arrays`]) for sequences.
pub struct Types;

impl PythonizeTypes for Types {
    type Map = PyDict;
    type NamedMap = Named;
    type List = PyList;
}

/// Builds a [`FisstResult`] from a struct's fields.
pub struct Named;

impl PythonizeNamedMappingType for Named {
    type Builder<'py> = (&'static str, Bound<'py, PyDict>);

    fn builder<'py>(
        py: Python<'py>,
        _len: usize,
        name: &'static str,
    ) -> PyResult<Self::Builder<'py>> {
        Ok((name, PyDict::new(py)))
    }

    fn push_field<'py>(
        builder: &mut Self::Builder<'py>,
        name: Bound<'py, PyString>,
        value: Bound<'py, PyAny>,
    ) -> PyResult<()> {
        let py = name.py();
        builder.1.set_item(name, arrays(py, value)?)
    }

    fn finish<'py>(builder: Self::Builder<'py>) -> PyResult<Bound<'py, PyMapping>> {
        let (name, fields) = builder;
        let py = fields.py();
        let r = Bound::new(py, FisstResult::from_fields(name, fields.unbind()))?;
        Ok(r.into_any().cast_into::<PyMapping>()?)
    }
}

// pythonize's `Map` must be a mapping type; a dict is.
const _: fn() = || {
    fn is_mapping<T: PythonizeMappingType>() {}
    is_mapping::<PyDict>();
};
