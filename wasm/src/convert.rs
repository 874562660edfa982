//! JavaScript ⇄ Rust conversions with errors that name the offending field.
//!
//! Type problems (a string where a number belongs, a missing option, a non-array) throw a
//! `TypeError`; value problems (NaN, infinity, out-of-range numbers, ragged points, and every
//! error `fisst` itself reports) throw a `RangeError` whose message is the Rust error's
//! message. Nothing here panics: every JS call that could throw goes through a `catch`
//! binding.

use std::format;
use std::string::{String, ToString};
use std::vec::Vec;

use js_sys::{Array, Float32Array, Float64Array, Object, Reflect};
use wasm_bindgen::{JsCast, JsValue};

/// Result of a binding: the error is the JS exception to throw.
pub type JsResult<T> = Result<T, JsValue>;

/// A `TypeError` with `message`.
pub fn type_error(message: impl AsRef<str>) -> JsValue {
    js_sys::TypeError::new(message.as_ref()).into()
}

/// A `RangeError` with `message`.
pub fn range_error(message: impl AsRef<str>) -> JsValue {
    js_sys::RangeError::new(message.as_ref()).into()
}

/// The JS exception for a `fisst` error: a `RangeError` carrying its message.
pub fn core_error(e: fisst::Error) -> JsValue {
    range_error(e.to_string())
}

/// `?`-friendly conversion of `fisst` results.
pub trait OrThrow<T> {
    /// Maps the error to [`core_error`].
    fn or_throw(self) -> JsResult<T>;
}

impl<T> OrThrow<T> for fisst::Result<T> {
    fn or_throw(self) -> JsResult<T> {
        self.map_err(core_error)
    }
}

fn describe(v: &JsValue) -> String {
    if v.is_undefined() {
        "undefined".into()
    } else if v.is_null() {
        "null".into()
    } else if let Some(s) = v.as_string() {
        format!("the string {s:?}")
    } else if Array::is_array(v) {
        "an array".into()
    } else {
        v.js_typeof()
            .as_string()
            .unwrap_or_else(|| "a value".into())
    }
}

fn js_number_text(x: f64) -> String {
    if x.is_nan() {
        "NaN".into()
    } else if x == f64::INFINITY {
        "Infinity".into()
    } else if x == f64::NEG_INFINITY {
        "-Infinity".into()
    } else {
        x.to_string()
    }
}

/// A finite number.
pub fn number(v: &JsValue, field: &str) -> JsResult<f64> {
    let Some(x) = v.as_f64() else {
        return Err(type_error(format!(
            "{field} must be a number, got {}",
            describe(v)
        )));
    };
    if !x.is_finite() {
        return Err(range_error(format!(
            "{field} must be a finite number, got {}",
            js_number_text(x)
        )));
    }
    Ok(x)
}

/// A string.
pub fn string(v: &JsValue, field: &str) -> JsResult<String> {
    v.as_string()
        .ok_or_else(|| type_error(format!("{field} must be a string, got {}", describe(v))))
}

/// A boolean (or 0/1).
pub fn boolean(v: &JsValue, field: &str) -> JsResult<bool> {
    if let Some(b) = v.as_bool() {
        return Ok(b);
    }
    match v.as_f64() {
        Some(0.0) => Ok(false),
        Some(1.0) => Ok(true),
        _ => Err(type_error(format!(
            "{field} must be a boolean, got {}",
            describe(v)
        ))),
    }
}

/// An array (a JS `Array`).
pub fn array(v: &JsValue, field: &str, what: &str) -> JsResult<Array> {
    if Array::is_array(v) {
        Ok(v.clone().unchecked_into())
    } else {
        Err(type_error(format!(
            "{field} must be {what}, got {}",
            describe(v)
        )))
    }
}

/// Finite numbers from an `Array`, a `Float64Array` or a `Float32Array`.
pub fn numbers(v: &JsValue, field: &str) -> JsResult<Vec<f64>> {
    let values = if let Some(a) = v.dyn_ref::<Float64Array>() {
        a.to_vec()
    } else if let Some(a) = v.dyn_ref::<Float32Array>() {
        a.to_vec().into_iter().map(f64::from).collect()
    } else {
        let arr = array(v, field, "an array of numbers")?;
        let mut out = Vec::with_capacity(arr.length() as usize);
        for (i, x) in arr.iter().enumerate() {
            out.push(number(&x, &format!("{field}[{i}]"))?);
        }
        return Ok(out);
    };
    if let Some(i) = values.iter().position(|x| !x.is_finite()) {
        return Err(range_error(format!(
            "{field}[{i}] must be a finite number, got {}",
            js_number_text(values[i])
        )));
    }
    Ok(values)
}

/// An array of points (each an array of finite numbers). Equal dimensions are checked by the
/// metric that uses them, so that the message can name truth or estimate.
pub fn points(v: &JsValue, field: &str) -> JsResult<Vec<Vec<f64>>> {
    let arr = array(v, field, "an array of points (arrays of numbers)")?;
    let mut out = Vec::with_capacity(arr.length() as usize);
    for (i, p) in arr.iter().enumerate() {
        out.push(numbers(&p, &format!("{field}[{i}]"))?);
    }
    Ok(out)
}

/// Booleans from an array.
pub fn booleans(v: &JsValue, field: &str) -> JsResult<Vec<bool>> {
    let arr = array(v, field, "an array of booleans")?;
    arr.iter()
        .enumerate()
        .map(|(i, b)| boolean(&b, &format!("{field}[{i}]")))
        .collect()
}

/// An options object: `undefined`/`null` reads as empty unless it is required.
pub struct Options {
    obj: Option<JsValue>,
}

impl Options {
    /// Reads `v` as the options object called `name`.
    pub fn new(v: &JsValue, name: &str, required: bool) -> JsResult<Self> {
        if v.is_undefined() || v.is_null() {
            if required {
                return Err(type_error(format!("{name} must be an object")));
            }
            return Ok(Self { obj: None });
        }
        if !v.is_object() || Array::is_array(v) {
            return Err(type_error(format!(
                "{name} must be an object, got {}",
                describe(v)
            )));
        }
        Ok(Self {
            obj: Some(v.clone()),
        })
    }

    /// The value of `key`, `None` when absent or `undefined`.
    pub fn get(&self, key: &str) -> JsResult<Option<JsValue>> {
        let Some(obj) = &self.obj else {
            return Ok(None);
        };
        let v = Reflect::get(obj, &JsValue::from_str(key))?;
        Ok(if v.is_undefined() { None } else { Some(v) })
    }

    /// The value of `key`, or a `TypeError` saying it is required.
    pub fn require(&self, key: &str) -> JsResult<JsValue> {
        self.get(key)?
            .ok_or_else(|| type_error(format!("{key} is required")))
    }

    /// A finite number, or `default` when absent.
    pub fn number_or(&self, key: &str, default: f64) -> JsResult<f64> {
        match self.get(key)? {
            Some(v) => number(&v, key),
            None => Ok(default),
        }
    }

    /// An integer in `[min, max]`, or `default` when absent.
    pub fn integer_or(&self, key: &str, default: usize, min: usize, max: usize) -> JsResult<usize> {
        let x = self.number_or(key, default as f64)?;
        if x.fract() != 0.0 || x < min as f64 || x > max as f64 {
            return Err(range_error(format!(
                "{key} must be an integer in [{min}, {max}], got {x}"
            )));
        }
        Ok(x as usize)
    }

    /// A required finite number.
    pub fn number(&self, key: &str) -> JsResult<f64> {
        number(&self.require(key)?, key)
    }
}

/// A plain JS object from `(key, value)` pairs.
pub fn object(entries: &[(&str, JsValue)]) -> JsValue {
    let obj = Object::new();
    for (k, v) in entries {
        // Setting a data property on a fresh plain object cannot fail.
        let _ = Reflect::set(&obj, &JsValue::from_str(k), v);
    }
    obj.into()
}

/// A JS `Array` of numbers.
pub fn number_array(values: &[f64]) -> JsValue {
    values
        .iter()
        .map(|&x| JsValue::from_f64(x))
        .collect::<Array>()
        .into()
}

/// A JS `Array` of booleans.
pub fn boolean_array(values: &[bool]) -> JsValue {
    values
        .iter()
        .map(|&b| JsValue::from_bool(b))
        .collect::<Array>()
        .into()
}

/// A JS `Array` of `[i, j]` pairs.
pub fn pair_array(pairs: &[(usize, usize)]) -> JsValue {
    pairs
        .iter()
        .map(|&(i, j)| -> JsValue {
            [JsValue::from_f64(i as f64), JsValue::from_f64(j as f64)]
                .into_iter()
                .collect::<Array>()
                .into()
        })
        .collect::<Array>()
        .into()
}
