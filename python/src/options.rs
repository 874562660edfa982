//! Keyword arguments (and nested dicts) read into the core's own option types, through their
//! `Deserialize` (pythonize), with the path of every error in Python's names: an unknown
//! keyword or key, a missing one or a wrong kind of value is a `TypeError`, a bad value a
//! `ValueError` (the core's own checks, [`crate::convert::to_py`]).

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyMapping, PyString, PyTuple};
use serde::de::DeserializeOwned;

use crate::names::rule;

/// The keyword arguments `kwargs` of the function `function` as the core's `T`.
pub fn from_kwargs<T: DeserializeOwned>(
    py: Python<'_>,
    function: &str,
    kwargs: Option<&Bound<'_, PyDict>>,
) -> PyResult<T> {
    let empty = PyDict::new(py);
    let kwargs = kwargs.unwrap_or(&empty);
    let plain = plain(kwargs.as_any(), "", "")?;
    read(&plain, function, "")
}

/// The value `value` (a dict, a list, …) given as the argument `root` as the core's `T`.
pub fn from_value<T: DeserializeOwned>(value: &Bound<'_, PyAny>, root: &str) -> PyResult<T> {
    let plain = plain(value, root, "")?;
    read(&plain, "", root)
}

fn read<T: DeserializeOwned>(plain: &Bound<'_, PyAny>, function: &str, root: &str) -> PyResult<T> {
    let mut unknown: Vec<String> = Vec::new();
    let mut de = pythonize::Depythonizer::from_object(plain);
    let mut note = |path: serde_ignored::Path<'_>| unknown.push(path.to_string());
    let outcome: Result<T, _> =
        serde_path_to_error::deserialize(serde_ignored::Deserializer::new(&mut de, &mut note));
    let join = |path: &str| match (root.is_empty(), path.is_empty() || path == ".") {
        (_, true) => root.to_string(),
        (true, false) => path.to_string(),
        (false, false) if path.starts_with('[') => format!("{root}{path}"),
        (false, false) => format!("{root}.{path}"),
    };
    match outcome {
        Ok(v) => {
            if let Some(path) = unknown.first() {
                let (parent, key) = match path.rsplit_once('.') {
                    Some((p, k)) => (join(p), k.to_string()),
                    None => (root.to_string(), path.clone()),
                };
                let key = python_name(&parent, &key);
                return Err(PyTypeError::new_err(
                    if parent.is_empty() && !function.is_empty() {
                        format!("{function}() got an unexpected keyword argument '{key}'")
                    } else {
                        format!("{parent} has no key '{key}'")
                    },
                ));
            }
            Ok(v)
        }
        Err(e) => {
            let path = crate::names::render_path(&join(&e.path().to_string()));
            let message = e.inner().to_string();
            if let Some(field) = between(&message, "missing field `", "`") {
                let field = python_name(&path, field);
                return Err(PyTypeError::new_err(
                    if path.is_empty() && !function.is_empty() {
                        format!("{function}() missing required keyword argument '{field}'")
                    } else {
                        format!("{path} is missing the key '{field}'")
                    },
                ));
            }
            // a message that continues the path (a mixture's `[2].cov …`) joins it
            let at = if path.is_empty() {
                String::new()
            } else if message.starts_with('[') || message.starts_with('.') {
                path.clone()
            } else {
                format!("{path}: ")
            };
            // a Python exception raised while reading (a `float()` of a str): its own class
            if let Some(rest) = message.strip_prefix("TypeError: ") {
                let what = if path.is_empty() {
                    "the value"
                } else {
                    path.as_str()
                };
                return Err(PyTypeError::new_err(format!("{what} {rest}")));
            }
            if let Some(rest) = message.strip_prefix("ValueError: ") {
                return Err(PyValueError::new_err(format!("{at}{rest}")));
            }
            if message.starts_with("invalid type")
                || message.starts_with("unknown variant")
                || message.contains("unexpected type")
                || message.contains("unsupported type")
            {
                Err(PyTypeError::new_err(format!("{at}{message}")))
            } else {
                Err(PyValueError::new_err(format!("{at}{message}")))
            }
        }
    }
}

/// The text of `s` between `open` and the next `close`.
fn between<'a>(s: &'a str, open: &str, close: &str) -> Option<&'a str> {
    let start = s.find(open)? + open.len();
    let end = s[start..].find(close)? + start;
    Some(&s[start..end])
}

/// The Python name of the Rust field `field` in `parent` (a path): the matrix exceptions.
fn python_name(parent: &str, field: &str) -> String {
    let last = parent.rsplit('.').next().unwrap_or("");
    let last = last.split('[').next().unwrap_or("");
    rule::EXCEPTIONS
        .iter()
        .find(|(p, f, _)| *p == last && *f == field)
        .map_or_else(|| field.to_string(), |(_, _, m)| m.to_string())
}

/// The Rust name of the Python key `key` in the field `parent`: the matrix exceptions.
fn rust_name<'a>(parent: &str, key: &'a str) -> &'a str {
    rule::EXCEPTIONS
        .iter()
        .find(|(p, _, m)| *p == parent && *m == key)
        .map_or(key, |(_, f, _)| f)
}

/// `value` as plain Python data that pythonize reads: numpy arrays and pandas objects as
/// (nested) lists, other mappings (a `fisst.Result`) as dicts, numpy scalars as Python
/// numbers, tuples as lists, dict keys in the core's names (`F` → `f` under `transition`). `name` is the key holding `value` (for the renames).
fn plain<'py>(value: &Bound<'py, PyAny>, path: &str, name: &str) -> PyResult<Bound<'py, PyAny>> {
    let py = value.py();
    if value.is_none()
        || value.is_instance_of::<PyBool>()
        || value.is_instance_of::<PyInt>()
        || value.is_instance_of::<PyFloat>()
        || value.is_instance_of::<PyString>()
    {
        return Ok(value.clone());
    }
    if let Ok(d) = value.cast::<PyDict>() {
        let out = PyDict::new(py);
        for (k, v) in d.iter() {
            let Ok(key) = k.cast::<PyString>() else {
                return Err(PyTypeError::new_err(format!(
                    "{} keys must be strings, got {}",
                    if path.is_empty() {
                        "the options'"
                    } else {
                        path
                    },
                    k.get_type().name()?
                )));
            };
            let key = key.to_str()?;
            let inner = if path.is_empty() {
                key.to_string()
            } else {
                format!("{path}.{key}")
            };
            out.set_item(rust_name(name, key), plain(&v, &inner, key)?)?;
        }
        return Ok(out.into_any());
    }
    if let Ok(l) = value.cast::<PyList>() {
        let items = l
            .iter()
            .enumerate()
            .map(|(i, v)| plain(&v, &format!("{path}[{i}]"), name))
            .collect::<PyResult<Vec<_>>>()?;
        return Ok(PyList::new(py, items)?.into_any());
    }
    if let Ok(t) = value.cast::<PyTuple>() {
        let items = t
            .iter()
            .enumerate()
            .map(|(i, v)| plain(&v, &format!("{path}[{i}]"), name))
            .collect::<PyResult<Vec<_>>>()?;
        return Ok(PyList::new(py, items)?.into_any());
    }
    // any other mapping (a `fisst.Result` given back, e.g. `placement_scene().multi_bernoulli`
    // into `fov_variance_map`): as a dict, its numpy arrays as lists
    if let Ok(m) = value.cast::<PyMapping>() {
        let d = PyDict::new(py);
        for item in m.items()?.iter() {
            let (k, v): (Bound<'py, PyAny>, Bound<'py, PyAny>) = item.extract()?;
            d.set_item(k, v)?;
        }
        return plain(d.as_any(), path, name);
    }
    // numpy arrays and scalars, pandas objects: through `tolist()` / `item()`
    if value.hasattr("to_numpy")? {
        return plain(&value.call_method0("to_numpy")?, path, name);
    }
    if value.hasattr("tolist")? {
        return plain(&value.call_method0("tolist")?, path, name);
    }
    Ok(value.clone())
}
