//! The boundary itself: reading options ([`read`]), writing results ([`write()`]), turning core
//! errors into JS exceptions, and seeds.
//!
//! Every exported function follows one shape:
//!
//! ```text
//! let opts: GospaOptions = read(options, "options")?;        // TypeError/RangeError with a path
//! let g = Gospa::new(opts.c, opts.p, opts.alpha).or_throw_in("options")?;   // core checks
//! write(&GospaResult { … })                                  // serde-wasm-bindgen
//! ```

use serde::Serialize;
use serde::de::DeserializeOwned;
use wasm_bindgen::JsValue;

use crate::de::{self, ErrorClass};
use crate::names::Renamed;

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

/// The JS exception for a deserialization error.
pub fn de_error(e: de::Error) -> JsValue {
    match e.class {
        ErrorClass::Type => type_error(&e.message),
        ErrorClass::Range => range_error(&e.message),
    }
}

/// Reads the argument `value`, named `root` in errors, as a `T` (see [`crate::de`]).
pub fn read<T: DeserializeOwned>(value: JsValue, root: &str) -> JsResult<T> {
    de::from_js(value, root).map_err(de_error)
}

/// Writes `value` as a plain JS value: structs become objects with their fields under their
/// JavaScript names ([`Renamed`]), `Vec`s arrays, `None` `null` (fields that are absent when
/// unset say so with `skip_serializing_if`).
pub fn write<T: Serialize + ?Sized>(value: &T) -> JsResult<JsValue> {
    let serializer = serde_wasm_bindgen::Serializer::new()
        .serialize_missing_as_null(true)
        .serialize_maps_as_objects(true);
    Renamed::new(value)
        .serialize(&serializer)
        .map_err(|e| js_sys::Error::new(&std::format!("{e}")).into())
}

/// The JS exception for a `fisst` error: a `RangeError` carrying its message.
pub fn core_error(e: fisst::Error) -> JsValue {
    range_error(std::format!("{e}"))
}

/// The JS exception for a `fisst` error whose field is a Rust path under `prefix`, naming the
/// path (and the other fields its sentence names) in this binding's names
/// ([`crate::names::render_path`]): a `TypeError` for a value of the wrong kind
/// ([`fisst::Error::is_wrong_kind`]), else a `RangeError`.
pub fn core_error_rendered(e: fisst::Error, prefix: &str) -> JsValue {
    let e = e
        .within(prefix)
        .map_paths(crate::names::render_path)
        .map_names(crate::names::render_path);
    if e.is_wrong_kind() {
        type_error(std::format!("{e}"))
    } else {
        core_error(e)
    }
}

/// `?`-friendly conversion of `fisst` results.
pub trait OrThrow<T> {
    /// Maps the error to [`core_error`]; its field is already a full path.
    fn or_throw(self) -> JsResult<T>;
    /// Maps the error to [`core_error`] with its field under `prefix` (`c` → `options.c`).
    fn or_throw_in(self, prefix: &str) -> JsResult<T>;
    /// Maps the error to [`core_error_rendered`]: its Rust field path rendered in JavaScript names,
    /// under `prefix` (`max_components` → `options.maxComponents`).
    fn or_throw_rendered(self, prefix: &str) -> JsResult<T>;
}

impl<T> OrThrow<T> for fisst::Result<T> {
    fn or_throw(self) -> JsResult<T> {
        self.map_err(core_error)
    }

    fn or_throw_in(self, prefix: &str) -> JsResult<T> {
        self.map_err(|e| core_error(e.within(prefix)))
    }

    fn or_throw_rendered(self, prefix: &str) -> JsResult<T> {
        self.map_err(|e| core_error_rendered(e, prefix))
    }
}

pub use crate::names::render_path;

/// The seed of a seeded function: the caller's, or fresh platform entropy when omitted
/// (`crypto.getRandomValues` through getrandom). Either way the result reports the seed
/// used, so every run can be reproduced exactly.
pub fn seed_or_entropy(seed: Option<u64>) -> JsResult<u64> {
    match seed {
        Some(s) => Ok(s),
        None => fisst::math::rng::entropy_seed().or_throw_in("options"),
    }
}
