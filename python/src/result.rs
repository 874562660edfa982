//! `fisst.Result`: the one class every result is an instance of, made from the core's
//! `Serialize` (see [`crate::convert::result`]) rather than written per result.

use pyo3::exceptions::{PyAttributeError, PyKeyError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};

/// A result of a fisst function: the core's result type `name` (``GospaReport``,
/// ``OspaSeries``, …) with its fields as attributes under the core's names (``r.distance``,
/// ``r.false_targets``). Numeric arrays are numpy arrays; nested results are ``Result``\ s.
/// A ``Result`` is also a read-only mapping of its fields (``r["distance"]``, ``dict(r)``,
/// ``r.keys()``), compares equal to another with the same name and fields, and pickles.
#[pyclass(name = "Result", module = "fisst._fisst", frozen, mapping)]
pub struct FisstResult {
    name: String,
    fields: Py<PyDict>,
}

impl FisstResult {
    /// The result `name` with `fields`.
    pub fn from_fields(name: &str, fields: Py<PyDict>) -> Self {
        Self {
            name: name.to_string(),
            fields,
        }
    }
}

#[pymethods]
impl FisstResult {
    /// ``Result(name, fields)``: a result named ``name`` with the fields of the dict
    /// ``fields`` (what unpickling calls; results normally come from fisst's functions).
    #[new]
    fn new(name: String, fields: Bound<'_, PyDict>) -> Self {
        Self {
            name,
            fields: fields
                .copy()
                .map(Bound::unbind)
                .unwrap_or_else(|_| fields.unbind()),
        }
    }

    /// The core's name of this result's type (``"GospaReport"``).
    #[getter(type_name)]
    fn type_name(&self) -> &str {
        &self.name
    }

    fn __getattr__<'py>(&self, py: Python<'py>, attr: &str) -> PyResult<Bound<'py, PyAny>> {
        match self.fields.bind(py).get_item(attr)? {
            Some(v) => Ok(v),
            None => Err(PyAttributeError::new_err(format!(
                "{} has no field '{attr}'; its fields are {}",
                self.name,
                self.field_names(py)?.join(", ")
            ))),
        }
    }

    fn __getitem__<'py>(&self, py: Python<'py>, key: &str) -> PyResult<Bound<'py, PyAny>> {
        self.fields
            .bind(py)
            .get_item(key)?
            .ok_or_else(|| PyKeyError::new_err(key.to_string()))
    }

    fn __len__(&self, py: Python<'_>) -> usize {
        self.fields.bind(py).len()
    }

    fn __contains__(&self, py: Python<'_>, key: &str) -> PyResult<bool> {
        self.fields.bind(py).contains(key)
    }

    fn __iter__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.fields
            .bind(py)
            .keys()
            .into_any()
            .try_iter()
            .map(Bound::into_any)
    }

    /// The field names.
    fn keys<'py>(&self, py: Python<'py>) -> Bound<'py, PyList> {
        self.fields.bind(py).keys()
    }

    /// The field values.
    fn values<'py>(&self, py: Python<'py>) -> Bound<'py, PyList> {
        self.fields.bind(py).values()
    }

    /// The (name, value) pairs.
    fn items<'py>(&self, py: Python<'py>) -> Bound<'py, PyList> {
        self.fields.bind(py).items()
    }

    /// The fields as a plain ``dict`` (nested results stay ``Result``\ s).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.fields.bind(py).copy()
    }

    fn __dir__(&self, py: Python<'_>) -> PyResult<Vec<String>> {
        let mut names = self.field_names(py)?;
        names.extend(
            ["type_name", "keys", "values", "items", "to_dict"]
                .iter()
                .map(|s| s.to_string()),
        );
        Ok(names)
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let mut parts = Vec::new();
        for (k, v) in self.fields.bind(py).iter() {
            parts.push(format!("{}={}", k.cast::<PyString>()?.to_str()?, v.repr()?));
        }
        Ok(format!("{}({})", self.name, parts.join(", ")))
    }

    fn __eq__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<bool> {
        let Ok(other) = other.cast::<FisstResult>() else {
            return Ok(false);
        };
        let other = other.get();
        if other.name != self.name {
            return Ok(false);
        }
        let (a, b) = (self.fields.bind(py), other.fields.bind(py));
        if a.len() != b.len() {
            return Ok(false);
        }
        let numpy = py.import("numpy")?;
        for (k, v) in a.iter() {
            let Some(w) = b.get_item(&k)? else {
                return Ok(false);
            };
            let same = if v.hasattr("shape")? || w.hasattr("shape")? {
                numpy.call_method1("array_equal", (&v, &w))?.is_truthy()?
            } else {
                v.eq(&w)?
            };
            if !same {
                return Ok(false);
            }
        }
        Ok(true)
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let this = slf.get();
        let args = (this.name.clone(), this.fields.bind(py).clone());
        PyTuple::new(
            py,
            [
                slf.get_type().into_any(),
                args.into_pyobject(py)?.into_any(),
            ],
        )
    }
}

impl FisstResult {
    fn field_names(&self, py: Python<'_>) -> PyResult<Vec<String>> {
        self.fields
            .bind(py)
            .keys()
            .iter()
            .map(|k| k.extract::<String>())
            .collect()
    }
}
