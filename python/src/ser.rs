//! The one mechanism that turns the core's results into Python objects: a serde `Serializer`
//! over the core's own `Serialize` impls. A struct becomes a [`FisstResult`] (its Rust field
//! names as attributes), a sequence of numbers a numpy array built straight from a Rust
//! vector (no Python object per element), a sequence of equal-length numeric sequences a 2-D
//! array, bytes a uint8 array, `None` `None`, a unit enum variant its name, anything else the
//! plain Python value (a list, a dict).

use numpy::ToPyArray;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString};
use serde::ser::{self, Serialize};

use crate::result::FisstResult;

/// The error of the serializer: a Python exception, or serde's message.
#[derive(Debug)]
pub struct Error(pub PyErr);

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.0)
    }
}

impl std::error::Error for Error {}

impl ser::Error for Error {
    fn custom<T: std::fmt::Display>(msg: T) -> Self {
        Error(PyValueError::new_err(msg.to_string()))
    }
}

impl From<PyErr> for Error {
    fn from(e: PyErr) -> Self {
        Error(e)
    }
}

type Result<T> = std::result::Result<T, Error>;

/// A value on its way to Python: numbers stay Rust values until their sequence is known, so
/// that a sequence of them becomes one numpy array.
enum Value<'py> {
    Float(f64),
    Int(i64),
    Bool(bool),
    /// A numeric sequence not yet made an array: its elements (all numbers).
    Numbers(Vec<Value<'py>>),
    Object(Bound<'py, PyAny>),
}

impl<'py> Value<'py> {
    fn number(&self) -> Option<Kind> {
        match self {
            Value::Float(_) => Some(Kind::Float),
            Value::Int(_) => Some(Kind::Int),
            Value::Bool(_) => Some(Kind::Bool),
            _ => None,
        }
    }

    /// The Python object.
    fn into_py(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(match self {
            Value::Float(x) => PyFloat::new(py, x).into_any(),
            Value::Int(i) => PyInt::new(py, i).into_any(),
            Value::Bool(b) => PyBool::new(py, b).to_owned().into_any(),
            Value::Numbers(items) => array(py, &items, items.len(), 0)?,
            Value::Object(o) => o,
        })
    }
}

#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Float,
    Int,
    Bool,
}

/// The common kind of numbers (ints and floats together are floats), or `None`.
fn kind_of<'a, 'py: 'a>(items: impl Iterator<Item = &'a Value<'py>>) -> Option<Kind> {
    let mut kind = None;
    for v in items {
        let k = v.number()?;
        kind = match (kind, k) {
            (None, k) => Some(k),
            (Some(a), b) if a == b => Some(a),
            (Some(Kind::Int), Kind::Float) | (Some(Kind::Float), Kind::Int) => Some(Kind::Float),
            _ => return None,
        };
    }
    kind
}

/// `items` (numbers) as a numpy array: 1-D when `d` is 0, else `n × d`.
fn array<'py>(
    py: Python<'py>,
    items: &[Value<'py>],
    n: usize,
    d: usize,
) -> PyResult<Bound<'py, PyAny>> {
    let kind = kind_of(items.iter()).unwrap_or(Kind::Float);
    let a = match kind {
        Kind::Float => items
            .iter()
            .map(|v| match v {
                Value::Float(x) => *x,
                Value::Int(i) => *i as f64,
                _ => f64::NAN,
            })
            .collect::<Vec<f64>>()
            .to_pyarray(py)
            .into_any(),
        Kind::Int => items
            .iter()
            .map(|v| if let Value::Int(i) = v { *i } else { 0 })
            .collect::<Vec<i64>>()
            .to_pyarray(py)
            .into_any(),
        Kind::Bool => items
            .iter()
            .map(|v| matches!(v, Value::Bool(true)))
            .collect::<Vec<bool>>()
            .to_pyarray(py)
            .into_any(),
    };
    if d == 0 {
        Ok(a)
    } else {
        a.call_method1("reshape", ((n, d),))
    }
}

/// A finished sequence: numbers stay [`Value::Numbers`] (made an array by the container, or at
/// the top); rows of numbers of one length become a 2-D array; anything else a list.
fn sequence<'py>(py: Python<'py>, items: Vec<Value<'py>>) -> Result<Value<'py>> {
    if items.is_empty() || kind_of(items.iter()).is_some() {
        return Ok(Value::Numbers(items));
    }
    if let Some(Value::Numbers(first)) = items.first() {
        let d = first.len();
        let rows_ok = d > 0
            && items
                .iter()
                .all(|r| matches!(r, Value::Numbers(row) if row.len() == d))
            && kind_of(items.iter().flat_map(|r| match r {
                Value::Numbers(row) => row.iter(),
                _ => [].iter(),
            }))
            .is_some();
        if rows_ok {
            let n = items.len();
            let flat: Vec<Value<'py>> = items
                .into_iter()
                .flat_map(|r| match r {
                    Value::Numbers(row) => row,
                    _ => Vec::new(),
                })
                .collect();
            return Ok(Value::Object(array(py, &flat, n, d)?));
        }
    }
    let objects = items
        .into_iter()
        .map(|v| v.into_py(py))
        .collect::<PyResult<Vec<_>>>()?;
    Ok(Value::Object(PyList::new(py, objects)?.into_any()))
}

/// The core's `value` as Python objects (see the module docs).
pub fn to_python<'py, T: Serialize + ?Sized>(
    py: Python<'py>,
    value: &T,
) -> PyResult<Bound<'py, PyAny>> {
    let v = value
        .serialize(Serializer { py, field: "" })
        .map_err(|e| e.0)?;
    v.into_py(py)
}

#[derive(Clone, Copy)]
struct Serializer<'py> {
    py: Python<'py>,
    /// The struct field whose value this serializes ("" elsewhere): a struct under it names
    /// its fields by [`crate::names::rule::EXCEPTIONS`] (`transition.f` is `F`).
    field: &'static str,
}

struct Seq<'py> {
    py: Python<'py>,
    items: Vec<Value<'py>>,
}

struct Map<'py> {
    py: Python<'py>,
    dict: Bound<'py, PyDict>,
    key: Option<Bound<'py, PyAny>>,
}

struct Struct<'py> {
    py: Python<'py>,
    /// The field this struct is the value of (see [`Serializer::field`]).
    parent: &'static str,
    name: &'static str,
    dict: Bound<'py, PyDict>,
    /// For a struct variant: the variant's name (the result is `{variant: Result}`).
    variant: Option<&'static str>,
}

struct TupleVariant<'py> {
    variant: &'static str,
    seq: Seq<'py>,
}

impl<'py> ser::Serializer for Serializer<'py> {
    type Ok = Value<'py>;
    type Error = Error;
    type SerializeSeq = Seq<'py>;
    type SerializeTuple = Seq<'py>;
    type SerializeTupleStruct = Seq<'py>;
    type SerializeTupleVariant = TupleVariant<'py>;
    type SerializeMap = Map<'py>;
    type SerializeStruct = Struct<'py>;
    type SerializeStructVariant = Struct<'py>;

    fn serialize_bool(self, v: bool) -> Result<Value<'py>> {
        Ok(Value::Bool(v))
    }
    fn serialize_i8(self, v: i8) -> Result<Value<'py>> {
        Ok(Value::Int(v.into()))
    }
    fn serialize_i16(self, v: i16) -> Result<Value<'py>> {
        Ok(Value::Int(v.into()))
    }
    fn serialize_i32(self, v: i32) -> Result<Value<'py>> {
        Ok(Value::Int(v.into()))
    }
    fn serialize_i64(self, v: i64) -> Result<Value<'py>> {
        Ok(Value::Int(v))
    }
    fn serialize_u8(self, v: u8) -> Result<Value<'py>> {
        Ok(Value::Int(v.into()))
    }
    fn serialize_u16(self, v: u16) -> Result<Value<'py>> {
        Ok(Value::Int(v.into()))
    }
    fn serialize_u32(self, v: u32) -> Result<Value<'py>> {
        Ok(Value::Int(v.into()))
    }
    fn serialize_u64(self, v: u64) -> Result<Value<'py>> {
        match i64::try_from(v) {
            Ok(i) => Ok(Value::Int(i)),
            Err(_) => Ok(Value::Object(
                v.into_pyobject(self.py)
                    .map(Bound::into_any)
                    .unwrap_or_else(|e| match e {}),
            )),
        }
    }
    fn serialize_f32(self, v: f32) -> Result<Value<'py>> {
        Ok(Value::Float(v.into()))
    }
    fn serialize_f64(self, v: f64) -> Result<Value<'py>> {
        Ok(Value::Float(v))
    }
    fn serialize_char(self, v: char) -> Result<Value<'py>> {
        Ok(Value::Object(
            PyString::new(self.py, &v.to_string()).into_any(),
        ))
    }
    fn serialize_str(self, v: &str) -> Result<Value<'py>> {
        Ok(Value::Object(PyString::new(self.py, v).into_any()))
    }
    fn serialize_bytes(self, v: &[u8]) -> Result<Value<'py>> {
        Ok(Value::Object(v.to_pyarray(self.py).into_any()))
    }
    fn serialize_none(self) -> Result<Value<'py>> {
        Ok(Value::Object(self.py.None().into_bound(self.py)))
    }
    fn serialize_some<T: ?Sized + Serialize>(self, value: &T) -> Result<Value<'py>> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<Value<'py>> {
        self.serialize_none()
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<Value<'py>> {
        self.serialize_none()
    }
    fn serialize_unit_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
    ) -> Result<Value<'py>> {
        self.serialize_str(variant)
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<Value<'py>> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<Value<'py>> {
        let dict = PyDict::new(self.py);
        dict.set_item(variant, value.serialize(self)?.into_py(self.py)?)?;
        Ok(Value::Object(dict.into_any()))
    }
    fn serialize_seq(self, len: Option<usize>) -> Result<Seq<'py>> {
        Ok(Seq {
            py: self.py,
            items: Vec::with_capacity(len.unwrap_or(0)),
        })
    }
    fn serialize_tuple(self, len: usize) -> Result<Seq<'py>> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_struct(self, _: &'static str, len: usize) -> Result<Seq<'py>> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        len: usize,
    ) -> Result<TupleVariant<'py>> {
        Ok(TupleVariant {
            variant,
            seq: self.serialize_seq(Some(len))?,
        })
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Map<'py>> {
        Ok(Map {
            py: self.py,
            dict: PyDict::new(self.py),
            key: None,
        })
    }
    fn serialize_struct(self, name: &'static str, _: usize) -> Result<Struct<'py>> {
        Ok(Struct {
            py: self.py,
            parent: self.field,
            name,
            dict: PyDict::new(self.py),
            variant: None,
        })
    }
    fn serialize_struct_variant(
        self,
        name: &'static str,
        _: u32,
        variant: &'static str,
        _: usize,
    ) -> Result<Struct<'py>> {
        Ok(Struct {
            py: self.py,
            parent: self.field,
            name,
            dict: PyDict::new(self.py),
            variant: Some(variant),
        })
    }
}

impl<'py> ser::SerializeSeq for Seq<'py> {
    type Ok = Value<'py>;
    type Error = Error;
    fn serialize_element<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        self.items.push(value.serialize(Serializer {
            py: self.py,
            field: "",
        })?);
        Ok(())
    }
    fn end(self) -> Result<Value<'py>> {
        sequence(self.py, self.items)
    }
}

impl<'py> ser::SerializeTuple for Seq<'py> {
    type Ok = Value<'py>;
    type Error = Error;
    fn serialize_element<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        ser::SerializeSeq::serialize_element(self, value)
    }
    fn end(self) -> Result<Value<'py>> {
        ser::SerializeSeq::end(self)
    }
}

impl<'py> ser::SerializeTupleStruct for Seq<'py> {
    type Ok = Value<'py>;
    type Error = Error;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        ser::SerializeSeq::serialize_element(self, value)
    }
    fn end(self) -> Result<Value<'py>> {
        ser::SerializeSeq::end(self)
    }
}

impl<'py> ser::SerializeTupleVariant for TupleVariant<'py> {
    type Ok = Value<'py>;
    type Error = Error;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        ser::SerializeSeq::serialize_element(&mut self.seq, value)
    }
    fn end(self) -> Result<Value<'py>> {
        let py = self.seq.py;
        let inner = ser::SerializeSeq::end(self.seq)?.into_py(py)?;
        let dict = PyDict::new(py);
        dict.set_item(self.variant, inner)?;
        Ok(Value::Object(dict.into_any()))
    }
}

impl<'py> ser::SerializeMap for Map<'py> {
    type Ok = Value<'py>;
    type Error = Error;
    fn serialize_key<T: ?Sized + Serialize>(&mut self, key: &T) -> Result<()> {
        self.key = Some(
            key.serialize(Serializer {
                py: self.py,
                field: "",
            })?
            .into_py(self.py)?,
        );
        Ok(())
    }
    fn serialize_value<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        let key = self
            .key
            .take()
            .ok_or_else(|| Error(PyValueError::new_err("a map value without a key")))?;
        let value = value
            .serialize(Serializer {
                py: self.py,
                field: "",
            })?
            .into_py(self.py)?;
        self.dict.set_item(key, value)?;
        Ok(())
    }
    fn end(self) -> Result<Value<'py>> {
        Ok(Value::Object(self.dict.into_any()))
    }
}

impl<'py> ser::SerializeStruct for Struct<'py> {
    type Ok = Value<'py>;
    type Error = Error;
    fn serialize_field<T: ?Sized + Serialize>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<()> {
        let value = value
            .serialize(Serializer {
                py: self.py,
                field: key,
            })?
            .into_py(self.py)?;
        let name = crate::names::rule::EXCEPTIONS
            .iter()
            .find(|(p, f, _)| *p == self.parent && *f == key)
            .map_or(key, |(_, _, py_name)| py_name);
        self.dict.set_item(name, value)?;
        Ok(())
    }
    fn end(self) -> Result<Value<'py>> {
        let name = self.variant.unwrap_or(self.name);
        let result = Bound::new(
            self.py,
            FisstResult::from_fields(name, self.dict.clone().unbind()),
        )?
        .into_any();
        match self.variant {
            None => Ok(Value::Object(result)),
            Some(variant) => {
                let dict = PyDict::new(self.py);
                dict.set_item(variant, result)?;
                Ok(Value::Object(dict.into_any()))
            }
        }
    }
}

impl<'py> ser::SerializeStructVariant for Struct<'py> {
    type Ok = Value<'py>;
    type Error = Error;
    fn serialize_field<T: ?Sized + Serialize>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<()> {
        ser::SerializeStruct::serialize_field(self, key, value)
    }
    fn end(self) -> Result<Value<'py>> {
        ser::SerializeStruct::end(self)
    }
}
