//! Reading JavaScript values into `#[derive(Deserialize)]` types, with errors that name the
//! full path of the offending field.
//!
//! [`De`] is a serde `Deserializer` over a `JsValue` that walks arrays and objects itself and
//! reads each leaf (number, string, boolean) with its own type check. Why not
//! `serde_wasm_bindgen::from_value`, which the results do use (see [`crate::boundary`])? It
//! reads only the fields a struct names, so a misspelt option would be silently ignored
//! (serde-wasm-bindgen #39: `deny_unknown_fields` has no effect there); its errors carry no
//! path and no JS error class; it reads typed arrays through the JS iterator protocol, one
//! boundary crossing and one iterator object per element; and it follows a cyclic object until
//! the wasm stack overflows, which kills the module. [`De`]:
//!
//! - names every error by its path (`options.multiBernoulli[3].cov[1]`), built lazily from a
//!   chain of borrowed [`Path`] links, so a valid input allocates no path text at all;
//! - throws a `TypeError` for a type or presence problem (a string where a number belongs, a
//!   missing required field, an unknown key) and a `RangeError` for a bad value (NaN, ±∞, a
//!   fractional count, an unknown name, a wrong length);
//! - rejects unknown object keys, with a suggestion for a near miss (`aplha` → `alpha`);
//! - treats a key whose value is `undefined` or `null` as absent (so `{ p: undefined }` and a
//!   JSON `null` both take the default, and a required field reports "is required");
//! - reads a `Float64Array` or `Float32Array` in one copy;
//! - stops at [`MAX_DEPTH`] levels of nesting with a `RangeError`, so a cyclic or absurdly deep
//!   object is an error, not a stack overflow.
//!
//! Value checks beyond "a finite number" (ranges, probabilities, positive definiteness) stay in
//! the core's `Result`s; [`crate::boundary`] maps those to `RangeError`s with the same paths.

use fisst::error::Quoted;
use fisst::math::decimal::Decimal;
use std::borrow::Cow;
use std::fmt::{self, Display};
use std::string::{String, ToString};
use std::vec::Vec;

use js_sys::{Array, Float32Array, Float64Array, Reflect};
use serde::de::{self, DeserializeSeed, IntoDeserializer, Visitor};
use wasm_bindgen::{JsCast, JsValue};

use crate::names::{js_name, render_path_in, rule, variant_name};

/// The deepest nesting of arrays and objects read (a `Region` union of unions, a GLMB of
/// Gaussians, … never comes near it; a cyclic object reaches it at once).
pub const MAX_DEPTH: usize = 48;

/// Where a value sits in the arguments: a chain of links from the value up to the argument.
#[derive(Clone, Copy, Debug)]
pub enum Path<'a> {
    /// An argument (`options`, `truth`) or a sub-path given as text.
    Root(&'a str),
    /// `parent.key`.
    Key(&'a Path<'a>, &'a str),
    /// `parent[index]`.
    Index(&'a Path<'a>, usize),
}

impl Path<'_> {
    /// The nearest object key above this value (`""` at an argument): the parent that decides
    /// a field's JavaScript name ([`crate::names::js_name`]).
    pub fn parent_key(&self) -> &str {
        match self {
            Path::Root(_) => "",
            Path::Key(_, key) => key,
            Path::Index(parent, _) => parent.parent_key(),
        }
    }
}

impl Display for Path<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Path::Root(s) => f.write_str(s),
            Path::Key(parent, key) => {
                parent.fmt(f)?;
                if matches!(parent, Path::Root("")) {
                    f.write_str(key)
                } else {
                    write!(f, ".{key}")
                }
            }
            Path::Index(parent, i) => {
                parent.fmt(f)?;
                write!(f, "[{i}]")
            }
        }
    }
}

/// The JS error class an [`Error`] becomes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorClass {
    /// Wrong type, missing field, unknown key, malformed shape.
    Type,
    /// A value outside its domain.
    Range,
}

/// A deserialization error: its class and a message that starts with the path.
#[derive(Clone, Debug, PartialEq)]
pub struct Error {
    /// TypeError or RangeError.
    pub class: ErrorClass,
    /// The message; until [`Error::at`] gives it a path, the part after the path.
    pub message: String,
    /// Whether `message` already starts with the path.
    located: bool,
    /// A missing field's name, for "{path}.{field} is required".
    missing: Option<&'static str>,
}

impl Error {
    /// An error whose message already names its path.
    pub fn located(class: ErrorClass, message: String) -> Self {
        Self {
            class,
            message,
            located: true,
            missing: None,
        }
    }

    fn type_error(path: &Path<'_>, what: impl Display) -> Self {
        Self::located(ErrorClass::Type, std::format!("{path} {what}"))
    }

    fn range_error(path: &Path<'_>, what: impl Display) -> Self {
        Self::located(ErrorClass::Range, std::format!("{path} {what}"))
    }

    /// Gives an error raised below this level without a path (serde's "missing field",
    /// a `custom` message) the path `path`; a located error passes through unchanged.
    pub fn at(mut self, path: &Path<'_>) -> Self {
        if !self.located {
            self.message = match self.missing {
                Some(field) => std::format!(
                    "{} is required",
                    Path::Key(path, js_name(path.parent_key(), field))
                ),
                // A message about a part of this value ("[2] must be …", ".cov must be …",
                // ".ball.radius must be …", as the core's Gaussian and region types write
                // them, in Rust names) continues the path, its part rendered in JavaScript
                // names (`.disc.radius`); any other continues the sentence ("… must be …").
                None if matches!(self.message.as_bytes().first(), Some(b'[' | b'.')) => {
                    let (part, rest) = cut_at(&self.message, b' ');
                    let part = match part.strip_prefix('.') {
                        Some(p) => std::format!(".{}", render_path_in(path.parent_key(), p)),
                        None => render_path_in(path.parent_key(), part),
                    };
                    std::format!("{path}{part}{rest}")
                }
                None => std::format!("{path} {}", self.message),
            };
            self.located = true;
        }
        self
    }
}

impl Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Error {}

impl de::Error for Error {
    fn custom<T: Display>(msg: T) -> Self {
        Self {
            class: ErrorClass::Range,
            message: std::format!("{msg}"),
            located: false,
            missing: None,
        }
    }

    fn missing_field(field: &'static str) -> Self {
        Self {
            class: ErrorClass::Type,
            message: String::new(),
            located: false,
            missing: Some(field),
        }
    }

    fn invalid_type(unexp: de::Unexpected<'_>, exp: &dyn de::Expected) -> Self {
        // a number as JavaScript prints it (`got 1`, not serde's "floating point `1.0`")
        let unexp = match unexp {
            de::Unexpected::Float(x) => number_text(x),
            other => unexpected_text(other),
        };
        Self {
            class: ErrorClass::Type,
            message: std::format!("must be {exp}, got {unexp}"),
            located: false,
            missing: None,
        }
    }

    fn invalid_value(unexp: de::Unexpected<'_>, exp: &dyn de::Expected) -> Self {
        Self::custom(std::format!(
            "must be {exp}, got {}",
            unexpected_text(unexp)
        ))
    }

    fn invalid_length(len: usize, exp: &dyn de::Expected) -> Self {
        Self::custom(std::format!("has length {len}, expected {exp}"))
    }

    fn unknown_field(field: &str, expected: &'static [&'static str]) -> Self {
        let hint = match suggestion(field, expected) {
            Some(f) => std::format!(" (did you mean {f}?)"),
            None => String::new(),
        };
        Self {
            class: ErrorClass::Type,
            message: std::format!(
                "has an unknown key {}{hint}; its keys are {}",
                Quoted(field),
                expected.join(", ")
            ),
            located: false,
            missing: None,
        }
    }

    fn unknown_variant(variant: &str, expected: &'static [&'static str]) -> Self {
        let listed: Vec<String> = expected.iter().map(|v| std::format!("'{v}'")).collect();
        Self::custom(std::format!(
            "must be one of {}, got {}",
            listed.join(", "),
            Quoted(variant)
        ))
    }

    fn duplicate_field(field: &'static str) -> Self {
        Self::custom(std::format!("has the field {field} twice"))
    }
}

type Result<T, E = Error> = std::result::Result<T, E>;

/// How a value is described in a message: "the string \"2\"", "an array", "null", "NaN".
pub fn describe(v: &JsValue) -> Cow<'static, str> {
    if v.is_undefined() {
        "undefined".into()
    } else if v.is_null() {
        "null".into()
    } else if let Some(s) = v.as_string() {
        let shown: String = s.chars().take(40).collect();
        let more = if shown.len() < s.len() { "…" } else { "" };
        std::format!("the string {}{more}", Quoted(&shown)).into()
    } else if let Some(x) = v.as_f64() {
        number_text(x)
    } else if let Some(b) = v.as_bool() {
        (if b { "true" } else { "false" }).into()
    } else if Array::is_array(v) {
        "an array".into()
    } else if v.is_instance_of::<Float64Array>() {
        "a Float64Array".into()
    } else if v.is_function() {
        "a function".into()
    } else if v.is_bigint() {
        "a BigInt".into()
    } else if v.is_symbol() {
        "a symbol".into()
    } else {
        "an object".into()
    }
}

/// A number as JavaScript prints it (`NaN`, `Infinity`, `2.5`).
pub fn number_text(x: f64) -> Cow<'static, str> {
    if x.is_nan() {
        "NaN".into()
    } else if x == f64::INFINITY {
        "Infinity".into()
    } else if x == f64::NEG_INFINITY {
        "-Infinity".into()
    } else {
        std::format!("{}", Decimal(x)).into()
    }
}

/// serde's `Display` of an [`de::Unexpected`], word for word, with the float written by the
/// core's [`Decimal`]: serde's own prints it through the standard library's float formatting,
/// which is about 19 KB of every wasm module (issue 25, wasm size). The test
/// `unexpected_text_is_serdes` compares the two.
pub fn unexpected_text(unexp: de::Unexpected<'_>) -> Cow<'_, str> {
    use de::Unexpected as U;
    match unexp {
        U::Bool(b) => std::format!("boolean `{b}`").into(),
        U::Unsigned(i) => std::format!("integer `{}`", integer_text(false, i)).into(),
        U::Signed(i) => std::format!("integer `{}`", integer_text(i < 0, i.unsigned_abs())).into(),
        U::Float(x) => {
            // serde's `WithDecimalPoint`: a finite number without a point gets ".0"
            let mut t = std::format!("{}", Decimal(x));
            if x.is_finite() && !t.contains('.') {
                t.push_str(".0");
            }
            std::format!("floating point `{t}`").into()
        }
        U::Char(c) => {
            let mut t = String::from("character `");
            t.push(c);
            t.push('`');
            t.into()
        }
        U::Str(s) => std::format!("string {}", Quoted(s)).into(),
        U::Bytes(_) => "byte array".into(),
        U::Unit => "unit value".into(),
        U::Option => "Option value".into(),
        U::NewtypeStruct => "newtype struct".into(),
        U::Seq => "sequence".into(),
        U::Map => "map".into(),
        U::Enum => "enum".into(),
        U::UnitVariant => "unit variant".into(),
        U::NewtypeVariant => "newtype variant".into(),
        U::TupleVariant => "tuple variant".into(),
        U::StructVariant => "struct variant".into(),
        U::Other(other) => other.into(),
    }
}

/// 2^53 − 1, JavaScript's `Number.MAX_SAFE_INTEGER`: the largest integer read or written.
pub const MAX_SAFE_INTEGER: u64 = (1 << 53) - 1;

/// An integer as `{}` writes it (`-12`), from its sign and magnitude: one small loop instead of
/// the standard library's `u64` and `i64` `Display` (about 1.8 KB each in every module).
pub fn integer_text(negative: bool, mut magnitude: u64) -> String {
    let mut digits = [0u8; 21];
    let mut at = digits.len();
    loop {
        at -= 1;
        digits[at] = b'0' + (magnitude % 10) as u8;
        magnitude /= 10;
        if magnitude == 0 {
            break;
        }
    }
    if negative {
        at -= 1;
        digits[at] = b'-';
    }
    digits[at..].iter().map(|&b| char::from(b)).collect()
}

/// `s` split before the first byte `b` (an ASCII byte), or all of `s` and "" without one:
/// `str::find` and `split_at` would bring in the character searcher and the string slicing
/// panic (with its `Debug` code) into every module.
pub fn cut_at(s: &str, b: u8) -> (&str, &str) {
    let i = s.bytes().position(|c| c == b).unwrap_or(s.len());
    s.split_at_checked(i).unwrap_or((s, ""))
}

/// The value a [`De`] reads: a JS value, or one number of a typed array already copied out.
enum Value {
    Js(JsValue),
    Number(f64),
}

/// A serde `Deserializer` over one JS value at `path` (see the module docs).
pub struct De<'a> {
    value: Value,
    path: Path<'a>,
    depth: usize,
}

impl<'a> De<'a> {
    /// A deserializer for the argument `value` named `root` (`"options"`, `"truth"`).
    pub fn new(value: JsValue, path: Path<'a>) -> Self {
        Self {
            value: Value::Js(value),
            path,
            depth: 0,
        }
    }

    fn child<'b>(value: Value, path: Path<'b>, depth: usize) -> De<'b> {
        De { value, path, depth }
    }

    fn js(&self) -> Option<&JsValue> {
        match &self.value {
            Value::Js(v) => Some(v),
            Value::Number(_) => None,
        }
    }

    fn describe(&self) -> Cow<'static, str> {
        match &self.value {
            Value::Js(v) => describe(v),
            Value::Number(x) => number_text(*x),
        }
    }

    #[inline(never)]
    fn wrong_type(&self, expected: &str) -> Error {
        Error::type_error(
            &self.path,
            std::format!("must be {expected}, got {}", self.describe()),
        )
    }

    #[inline(never)]
    fn deeper(&self) -> Result<usize> {
        if self.depth >= MAX_DEPTH {
            return Err(Error::range_error(
                &self.path,
                std::format!("is nested more than {MAX_DEPTH} levels deep (a cyclic object?)"),
            ));
        }
        Ok(self.depth + 1)
    }

    fn as_number(&self) -> Option<f64> {
        match &self.value {
            Value::Js(v) => v.as_f64(),
            Value::Number(x) => Some(*x),
        }
    }

    /// A finite number, or the right error.
    #[inline(never)]
    fn finite(&self) -> Result<f64> {
        let Some(x) = self.as_number() else {
            return Err(self.wrong_type("a number"));
        };
        if !x.is_finite() {
            return Err(Error::range_error(
                &self.path,
                std::format!("must be a finite number, got {}", number_text(x)),
            ));
        }
        Ok(x)
    }

    /// An integer in `[min, max]` (exact in a JS number).
    #[inline(never)]
    fn integer(&self, min: f64, max: f64) -> Result<f64> {
        let x = self.finite()?;
        if x.fract() != 0.0 || x < min || x > max {
            let what = if min == 0.0 {
                "a non-negative integer".to_string()
            } else {
                std::format!("an integer in [{}, {}]", Decimal(min), Decimal(max))
            };
            return Err(Error::range_error(
                &self.path,
                std::format!("must be {what}, got {}", number_text(x)),
            ));
        }
        Ok(x)
    }

    /// The value as an object (not null, not an array, not a typed array), or a TypeError.
    #[inline(never)]
    fn object(&self) -> Result<&JsValue> {
        match self.js() {
            Some(v)
                if v.is_object()
                    && !Array::is_array(v)
                    && !v.is_function()
                    && !v.is_instance_of::<Float64Array>() =>
            {
                Ok(v)
            }
            _ => Err(self.wrong_type("an object")),
        }
    }

    /// The own enumerable keys of `obj` whose values are neither `undefined` nor `null`, with
    /// their values.
    #[inline(never)]
    fn present_entries(&self, obj: &JsValue) -> Result<Vec<(String, JsValue)>> {
        let keys = object_keys(obj).map_err(|_| self.wrong_type("a plain object"))?;
        let mut out = Vec::with_capacity(keys.length() as usize);
        for k in keys.iter() {
            let Some(name) = k.as_string() else { continue };
            let v = Reflect::get(obj, &k).map_err(|_| {
                Error::type_error(&Path::Key(&self.path, &name), "could not be read")
            })?;
            if !v.is_undefined() && !v.is_null() {
                out.push((name, v));
            }
        }
        Ok(out)
    }
}

// The non-generic halves of the compound reads: one copy each, whatever the visitor (the
// generic `deserialize_*` methods above are instantiated once per Rust type read).
impl<'a> De<'a> {
    /// The elements of an array or typed array.
    #[inline(never)]
    fn seq(&self) -> Result<Seq<'a>> {
        let depth = self.deeper()?;
        let Some(v) = self.js() else {
            return Err(self.wrong_type("an array"));
        };
        let items = if let Some(values) = typed_array_values(v) {
            Items::Numbers(values.into_iter())
        } else if Array::is_array(v) {
            let array: Array = v.clone().unchecked_into();
            let len = array.length();
            Items::Array(array, len)
        } else {
            return Err(self.wrong_type("an array"));
        };
        Ok(Seq {
            items,
            next: 0,
            path: self.path,
            depth,
        })
    }

    /// Every present key of an object, for a map.
    #[inline(never)]
    fn map_entries(&self) -> Result<Entries<'a>> {
        let depth = self.deeper()?;
        let obj = self.object()?;
        let entries: Vec<Entry> = self
            .present_entries(obj)?
            .into_iter()
            .map(|(k, v)| (Cow::Owned(k), None, v))
            .collect();
        Ok(Entries {
            entries: entries.into_iter(),
            pending: None,
            path: self.path,
            depth,
        })
    }

    /// The present keys of an object for a struct with `fields`; an unknown key is an error.
    #[inline(never)]
    fn struct_entries(&self, fields: &'static [&'static str]) -> Result<Entries<'a>> {
        let depth = self.deeper()?;
        let parent = self.path.parent_key();
        // a variant JavaScript gives bare (`{ polygon: [[x, y], …] }`): the value is that of
        // the struct's one field, at the variant's own path
        if let ([field], Value::Js(v)) = (fields, &self.value)
            && rule::BARE.iter().any(|(p, f)| *p == parent && f == field)
        {
            return Ok(Entries {
                entries: std::vec![(Cow::Borrowed(*field), Some(SAME_PATH), v.clone())].into_iter(),
                pending: None,
                path: self.path,
                depth,
            });
        }
        let obj = self.object()?;
        // the object's keys are the fields' JavaScript names (`futureScans` for the Rust field
        // `future_scans`); serde is given the Rust name, paths show the JavaScript one
        // a callback the binding reads itself (`onProgress`), at the top level only
        let callback = match self.depth {
            0 => CALLBACK.with(|c| c.borrow().as_ref().map(|(key, _)| *key)),
            _ => None,
        };
        let mut known = Vec::with_capacity(fields.len());
        for (key, value) in self.present_entries(obj)? {
            match fields
                .iter()
                .map(|f| (*f, js_name(parent, f)))
                .find(|(_, js)| *js == key)
            {
                Some((f, js)) => known.push((Cow::Borrowed(f), Some(js), value)),
                None if callback == Some(key.as_str()) => {
                    known.push((Cow::Borrowed(CALLBACK_ENTRY), callback, value));
                }
                None => {
                    let mut names: Vec<&'static str> =
                        fields.iter().map(|f| js_name(parent, f)).collect();
                    names.extend(callback);
                    return Err(unknown_key(&self.path, &key, &names));
                }
            }
        }
        Ok(Entries {
            entries: known.into_iter(),
            pending: None,
            path: self.path,
            depth,
        })
    }

    /// The variant named by a string, or by the one key of an object (with its payload).
    /// The names are the variants' JavaScript names (`multivariateGaussian` for the Rust
    /// `multivariate_gaussian`, [`js_name`]); serde is given the Rust one.
    #[inline(never)]
    fn variant(&self, rust_variants: &'static [&'static str]) -> Result<Variant<'a>> {
        let depth = self.deeper()?;
        // the keys are the variants' JavaScript names: a renamed variant (`disc` for the Rust
        // `ball`), else the camelCase name (`multivariateGaussian`)
        let js_names: Vec<&'static str> = rust_variants
            .iter()
            .map(|v| match variant_name(v) {
                renamed if renamed != *v => renamed,
                _ => js_name("", v),
            })
            .collect();
        let variants = js_names.as_slice();
        let rust = |i: usize| rust_variants[i];
        let listed = || {
            js_names
                .iter()
                .map(|v| std::format!("'{v}'"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let Some(v) = self.js() else {
            return Err(self.wrong_type(&std::format!("one of {}", listed())));
        };
        if let Some(s) = v.as_string() {
            let Some(i) = variants.iter().position(|n| *n == s) else {
                let shown: String = s.chars().take(40).collect();
                return Err(Error::range_error(
                    &self.path,
                    std::format!("must be one of {}, got {}", listed(), Quoted(&shown)),
                ));
            };
            return Ok(Variant {
                name: rust(i),
                js: variants[i],
                payload: None,
                path: self.path,
                depth,
            });
        }
        let Ok(obj) = self.object() else {
            // Serde does not say which variants carry data, so the hint covers both forms
            // without offering a string where only objects are accepted.
            return Err(self.wrong_type(&std::format!(
                "an object with one of the keys {} (or, for a choice that takes no value, its name)",
                listed()
            )));
        };
        let entries = self.present_entries(obj)?;
        let [(key, payload)] = entries.as_slice() else {
            let found: Vec<&str> = entries.iter().map(|(k, _)| k.as_str()).collect();
            return Err(Error::type_error(
                &self.path,
                std::format!(
                    "must have exactly one of the keys {} (found {}{})",
                    js_names.join(", "),
                    found.len(),
                    if found.is_empty() {
                        String::new()
                    } else {
                        std::format!(": {}", found.join(", "))
                    }
                ),
            ));
        };
        let Some(i) = variants.iter().position(|n| n == key) else {
            return Err(unknown_key(&self.path, key, variants));
        };
        Ok(Variant {
            name: rust(i),
            js: variants[i],
            payload: Some(payload.clone()),
            path: self.path,
            depth,
        })
    }
}

#[wasm_bindgen::prelude::wasm_bindgen]
extern "C" {
    /// `Object.keys`, catching what a hostile object (a Proxy) might throw.
    #[wasm_bindgen(catch, js_namespace = Object, js_name = keys)]
    fn object_keys(obj: &JsValue) -> Result<Array, JsValue>;
}

/// The closest of `fields` to `key` by edit distance, when it is close enough to be a typo.
fn suggestion(key: &str, fields: &[&'static str]) -> Option<&'static str> {
    fn distance(a: &str, b: &str) -> usize {
        let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
        let mut prev: Vec<usize> = (0..=b.len()).collect();
        for (i, ca) in a.iter().enumerate() {
            let mut cur = std::vec![i + 1];
            for (j, cb) in b.iter().enumerate() {
                let sub = prev[j] + usize::from(!ca.eq_ignore_ascii_case(cb));
                cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
            }
            prev = cur;
        }
        prev[b.len()]
    }
    fields
        .iter()
        .map(|f| (distance(key, f), *f))
        .filter(|&(d, f)| d <= 2.max(f.len() / 4) && d < f.len())
        .min_by_key(|&(d, _)| d)
        .map(|(_, f)| f)
}

fn unknown_key(path: &Path<'_>, key: &str, fields: &[&'static str]) -> Error {
    let hint = match suggestion(key, fields) {
        Some(f) => std::format!(" (did you mean {f}?)"),
        None => String::new(),
    };
    let shown: String = key.chars().take(40).collect();
    Error::type_error(
        path,
        std::format!(
            "has an unknown key {}{hint}; its keys are {}",
            Quoted(&shown),
            fields.join(", ")
        ),
    )
}

/// Where a sequence's elements come from.
enum Items {
    /// A JS `Array` of `len` elements, read one at a time.
    Array(Array, u32),
    /// The numbers of a typed array, copied out in one call.
    Numbers(std::vec::IntoIter<f64>),
}

/// `SeqAccess` over an array or typed array (one type, so every `Vec<T>` visitor is
/// instantiated once).
struct Seq<'a> {
    items: Items,
    next: u32,
    path: Path<'a>,
    depth: usize,
}

impl<'de> de::SeqAccess<'de> for Seq<'_> {
    type Error = Error;

    fn next_element_seed<T: DeserializeSeed<'de>>(&mut self, seed: T) -> Result<Option<T::Value>> {
        let value = match &mut self.items {
            Items::Array(array, len) => {
                if self.next >= *len {
                    return Ok(None);
                }
                Value::Js(array.get(self.next))
            }
            Items::Numbers(values) => match values.next() {
                Some(x) => Value::Number(x),
                None => return Ok(None),
            },
        };
        let i = self.next as usize;
        self.next += 1;
        let path = Path::Index(&self.path, i);
        seed.deserialize(De::child(value, path, self.depth))
            .map(Some)
            .map_err(|e| e.at(&path))
    }

    fn size_hint(&self) -> Option<usize> {
        Some(match &self.items {
            Items::Array(_, len) => (len - self.next) as usize,
            Items::Numbers(values) => values.len(),
        })
    }
}

/// The spelling of an [`Entry`] whose value stands at its object's own path (the one field of
/// a variant JavaScript gives bare, [`rule::BARE`]).
const SAME_PATH: &str = "";

/// One present key of an object: the key serde sees (a struct's Rust field name, a map's
/// key), the key as the object spells it when that differs (a field's JavaScript name), and
/// the value.
type Entry = (Cow<'static, str>, Option<&'static str>, JsValue);

/// `MapAccess` over the present keys of an object: for a struct the known ones (each
/// `&'static str` from the struct's field list), for a map all of them.
struct Entries<'a> {
    entries: std::vec::IntoIter<Entry>,
    pending: Option<Entry>,
    path: Path<'a>,
    depth: usize,
}

impl<'de> de::MapAccess<'de> for Entries<'_> {
    type Error = Error;

    fn next_key_seed<K: DeserializeSeed<'de>>(&mut self, seed: K) -> Result<Option<K::Value>> {
        let Some((mut key, mut js, mut value)) = self.entries.next() else {
            return Ok(None);
        };
        // the callback is checked in its place among the keys, and kept for the binding
        while key == CALLBACK_ENTRY {
            let name = js.unwrap_or_default();
            let Some(f) = value.dyn_ref::<js_sys::Function>().cloned() else {
                let path = Path::Key(&self.path, name);
                let e = std::format!("must be a function, got {}", describe(&value));
                return Err(Error::type_error(&path, e));
            };
            CALLBACK.with(|c| *c.borrow_mut() = Some((name, Some(f))));
            let Some(next) = self.entries.next() else {
                return Ok(None);
            };
            (key, js, value) = next;
        }
        let out = seed.deserialize(key.as_ref().into_deserializer());
        self.pending = Some((key, js, value));
        out.map(Some)
    }

    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value> {
        let Some((key, js, value)) = self.pending.take() else {
            return Err(de::Error::custom("a value was read before its key"));
        };
        // an error the value's own `Deserialize` raises after reading it (a core type's check,
        // "[1] has length 1, expected 2") is about the value: it gets the value's path
        let path = match js {
            Some(SAME_PATH) => self.path,
            _ => Path::Key(&self.path, js.unwrap_or(&key)),
        };
        seed.deserialize(De::child(Value::Js(value), path, self.depth))
            .map_err(|e| e.at(&path))
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.entries.len())
    }
}

/// `EnumAccess` for a string (a unit variant) or a one-key object (`{ box: { … } }`).
struct Variant<'a> {
    /// The variant's Rust name, for serde.
    name: &'static str,
    /// Its JavaScript name, for paths and messages.
    js: &'static str,
    payload: Option<JsValue>,
    path: Path<'a>,
    depth: usize,
}

impl<'de, 'a> de::EnumAccess<'de> for Variant<'a> {
    type Error = Error;
    type Variant = Self;

    fn variant_seed<V: DeserializeSeed<'de>>(self, seed: V) -> Result<(V::Value, Self)> {
        let v = seed.deserialize(self.name.into_deserializer())?;
        Ok((v, self))
    }
}

impl<'de> de::VariantAccess<'de> for Variant<'_> {
    type Error = Error;

    fn unit_variant(self) -> Result<()> {
        match self.payload {
            None => Ok(()),
            Some(_) => Err(Error::type_error(
                &self.path,
                std::format!("must be the string '{}', not an object", self.js),
            )),
        }
    }

    fn newtype_variant_seed<T: DeserializeSeed<'de>>(self, seed: T) -> Result<T::Value> {
        let path = Path::Key(&self.path, self.js);
        match self.payload {
            Some(v) => seed
                .deserialize(De::child(Value::Js(v), path, self.depth))
                .map_err(|e| e.at(&path)),
            None => Err(Error::type_error(
                &self.path,
                std::format!("must be an object {{ {}: … }}, not a string", self.js),
            )),
        }
    }

    fn tuple_variant<V: Visitor<'de>>(self, len: usize, visitor: V) -> Result<V::Value> {
        let path = Path::Key(&self.path, self.js);
        match self.payload {
            Some(v) => de::Deserializer::deserialize_tuple(
                De::child(Value::Js(v), path, self.depth),
                len,
                visitor,
            ),
            None => Err(Error::type_error(
                &self.path,
                std::format!("must be an object {{ {}: [...] }}, not a string", self.js),
            )),
        }
    }

    fn struct_variant<V: Visitor<'de>>(
        self,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value> {
        let path = Path::Key(&self.path, self.js);
        match self.payload {
            Some(v) => de::Deserializer::deserialize_struct(
                De::child(Value::Js(v), path, self.depth),
                "",
                fields,
                visitor,
            ),
            None => Err(Error::type_error(
                &self.path,
                std::format!("must be an object {{ {}: {{ … }} }}, not a string", self.js),
            )),
        }
    }
}

/// `deserialize_*` methods for integer types: [`De::integer`] in `[min, max]`, then the visit.
macro_rules! integers {
    ($($method:ident => $visit:ident as $t:ident in $min:expr, $max:expr;)*) => {$(
        fn $method<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
            let x = self.integer($min, $max)?;
            visitor.$visit::<Error>(x as $t).map_err(|e| e.at(&self.path))
        }
    )*};
}

impl<'de> de::Deserializer<'de> for De<'_> {
    type Error = Error;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        let path = self.path;
        let out = match &self.value {
            Value::Number(x) => visitor.visit_f64::<Error>(*x),
            Value::Js(v) if v.is_undefined() || v.is_null() => visitor.visit_unit::<Error>(),
            Value::Js(v) if v.as_bool().is_some() => {
                visitor.visit_bool::<Error>(v.as_bool() == Some(true))
            }
            Value::Js(v) if v.as_f64().is_some() => return self.deserialize_f64(visitor),
            Value::Js(v) if v.is_string() => {
                visitor.visit_string::<Error>(v.as_string().unwrap_or_default())
            }
            Value::Js(v) if Array::is_array(v) || is_typed_array(v) => {
                return self.deserialize_seq(visitor);
            }
            Value::Js(v) if v.is_object() => return self.deserialize_map(visitor),
            Value::Js(_) => Err(self.wrong_type("a number, string, boolean, array or object")),
        };
        out.map_err(|e| e.at(&path))
    }

    fn deserialize_bool<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        let b = match &self.value {
            Value::Js(v) if v.as_bool().is_some() => v.as_bool() == Some(true),
            _ => match self.as_number() {
                Some(0.0) => false,
                Some(1.0) => true,
                _ => return Err(self.wrong_type("a boolean")),
            },
        };
        visitor.visit_bool::<Error>(b).map_err(|e| e.at(&self.path))
    }

    fn deserialize_f64<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        let x = self.finite()?;
        visitor.visit_f64::<Error>(x).map_err(|e| e.at(&self.path))
    }

    fn deserialize_f32<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        self.deserialize_f64(visitor)
    }

    // An integer: a finite number with no fraction within the type's range (integers beyond
    // ±(2^53 − 1) are not exact in a JS number, so u64 and i64 stop there).
    integers! {
        deserialize_u64 => visit_u64 as u64 in 0.0, MAX_SAFE_INTEGER as f64;
        deserialize_u32 => visit_u64 as u64 in 0.0, f64::from(u32::MAX);
        deserialize_u16 => visit_u64 as u64 in 0.0, f64::from(u16::MAX);
        deserialize_u8 => visit_u64 as u64 in 0.0, f64::from(u8::MAX);
        deserialize_i64 => visit_i64 as i64 in -(MAX_SAFE_INTEGER as f64), MAX_SAFE_INTEGER as f64;
        deserialize_i32 => visit_i64 as i64 in f64::from(i32::MIN), f64::from(i32::MAX);
        deserialize_i16 => visit_i64 as i64 in f64::from(i16::MIN), f64::from(i16::MAX);
        deserialize_i8 => visit_i64 as i64 in f64::from(i8::MIN), f64::from(i8::MAX);
    }

    fn deserialize_char<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        let s = self.js().and_then(JsValue::as_string);
        let mut chars = s.as_deref().unwrap_or("").chars();
        match (chars.next(), chars.next()) {
            (Some(c), None) => visitor.visit_char::<Error>(c).map_err(|e| e.at(&self.path)),
            _ => Err(self.wrong_type("a one-character string")),
        }
    }

    fn deserialize_str<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        self.deserialize_string(visitor)
    }

    fn deserialize_string<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        match self.js().and_then(JsValue::as_string) {
            Some(s) => visitor
                .visit_string::<Error>(s)
                .map_err(|e| e.at(&self.path)),
            None => Err(self.wrong_type("a string")),
        }
    }

    fn deserialize_bytes<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        self.deserialize_seq(visitor)
    }

    fn deserialize_byte_buf<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        self.deserialize_seq(visitor)
    }

    fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        let path = self.path;
        match self.js() {
            Some(v) if v.is_undefined() || v.is_null() => {
                visitor.visit_none::<Error>().map_err(|e| e.at(&path))
            }
            _ => visitor.visit_some(self),
        }
    }

    fn deserialize_unit<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        match self.js() {
            Some(v) if v.is_undefined() || v.is_null() => {
                visitor.visit_unit::<Error>().map_err(|e| e.at(&self.path))
            }
            _ => Err(self.wrong_type("undefined or null")),
        }
    }

    fn deserialize_unit_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        visitor: V,
    ) -> Result<V::Value> {
        self.deserialize_unit(visitor)
    }

    fn deserialize_newtype_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        visitor: V,
    ) -> Result<V::Value> {
        let path = self.path;
        visitor.visit_newtype_struct(self).map_err(|e| e.at(&path))
    }

    fn deserialize_seq<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        let seq = self.seq()?;
        visitor.visit_seq(seq).map_err(|e| e.at(&self.path))
    }

    fn deserialize_tuple<V: Visitor<'de>>(self, len: usize, visitor: V) -> Result<V::Value> {
        if let Some(v) = self.js() {
            let found = if Array::is_array(v) {
                Some(v.unchecked_ref::<Array>().length() as usize)
            } else {
                typed_array_len(v)
            };
            if let Some(found) = found
                && found != len
            {
                return Err(Error::range_error(
                    &self.path,
                    std::format!("has length {found}, expected {len}"),
                ));
            }
        }
        self.deserialize_seq(visitor)
    }

    fn deserialize_tuple_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        len: usize,
        visitor: V,
    ) -> Result<V::Value> {
        self.deserialize_tuple(len, visitor)
    }

    fn deserialize_map<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        let access = self.map_entries()?;
        visitor.visit_map(access).map_err(|e| e.at(&self.path))
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value> {
        let access = self.struct_entries(fields)?;
        visitor.visit_map(access).map_err(|e| e.at(&self.path))
    }

    fn deserialize_enum<V: Visitor<'de>>(
        self,
        _name: &'static str,
        variants: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value> {
        let access = self.variant(variants)?;
        visitor.visit_enum(access).map_err(|e| e.at(&self.path))
    }

    fn deserialize_identifier<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        self.deserialize_string(visitor)
    }

    fn deserialize_ignored_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        visitor.visit_unit::<Error>()
    }

    fn is_human_readable(&self) -> bool {
        true
    }
}

/// Whether `v` is a `Float64Array` or `Float32Array`.
fn is_typed_array(v: &JsValue) -> bool {
    v.is_instance_of::<Float64Array>() || v.is_instance_of::<Float32Array>()
}

fn typed_array_len(v: &JsValue) -> Option<usize> {
    if let Some(a) = v.dyn_ref::<Float64Array>() {
        Some(a.length() as usize)
    } else {
        v.dyn_ref::<Float32Array>().map(|a| a.length() as usize)
    }
}

/// The numbers of a `Float64Array` or `Float32Array`, copied out in one call.
fn typed_array_values(v: &JsValue) -> Option<Vec<f64>> {
    if let Some(a) = v.dyn_ref::<Float64Array>() {
        Some(a.to_vec())
    } else {
        v.dyn_ref::<Float32Array>()
            .map(|a| a.to_vec().into_iter().map(f64::from).collect())
    }
}

/// The entry name that marks the callback of [`from_js_with_callback`] among an object's keys.
const CALLBACK_ENTRY: &str = "\0callback";

thread_local! {
    /// The callback key being read by [`from_js_with_callback`], and the function found.
    static CALLBACK: std::cell::RefCell<Option<(&'static str, Option<js_sys::Function>)>> =
        const { std::cell::RefCell::new(None) };
}

/// Reads `value` (the argument `root`) as a `T` whose object may also hold the JavaScript
/// callback `key` (`onProgress`: a function, which the core's option types cannot hold). The
/// key is checked in its place among the object's keys (anything but a function is a
/// `TypeError` naming it) and listed after `T`'s own in an unknown-key error.
pub fn from_js_with_callback<T: de::DeserializeOwned>(
    value: JsValue,
    root: &str,
    key: &'static str,
) -> Result<(T, Option<js_sys::Function>)> {
    CALLBACK.with(|c| *c.borrow_mut() = Some((key, None)));
    let out = from_js(value, root);
    let f = CALLBACK
        .with(|c| c.borrow_mut().take())
        .and_then(|(_, f)| f);
    out.map(|t| (t, f))
}

/// Reads `value` (the argument `root`) as a `T`.
pub fn from_js<T: de::DeserializeOwned>(value: JsValue, root: &str) -> Result<T> {
    let path = Path::Root(root);
    T::deserialize(De::new(value, path)).map_err(|e| e.at(&path))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_render_like_js() {
        let root = Path::Root("options");
        let a = Path::Key(&root, "multiBernoulli");
        let b = Path::Index(&a, 3);
        let c = Path::Key(&b, "cov");
        let d = Path::Index(&c, 1);
        assert_eq!(d.to_string(), "options.multiBernoulli[3].cov[1]");
        let t = Path::Index(&Path::Root("truth"), 2);
        assert_eq!(t.to_string(), "truth[2]");
    }

    #[test]
    fn typos_get_a_suggestion() {
        let fields = &["c", "p", "alpha"];
        assert_eq!(suggestion("aplha", fields), Some("alpha"));
        assert_eq!(suggestion("Alpha", fields), Some("alpha"));
        assert_eq!(suggestion("zzzzzzz", fields), None);
        assert_eq!(suggestion("q", fields), None);
        let fields = &["detectionProbability", "rfs", "fov"];
        assert_eq!(suggestion("detectionProb", fields), None);
        assert_eq!(
            suggestion("detectionProbabilty", fields),
            Some("detectionProbability")
        );
    }

    #[test]
    fn unlocated_errors_get_the_path() {
        let root = Path::Root("options");
        let e = <Error as de::Error>::missing_field("c").at(&root);
        assert_eq!(e.message, "options.c is required");
        assert_eq!(e.class, ErrorClass::Type);
        let e = <Error as de::Error>::custom("must be bad").at(&root);
        assert_eq!(e.message, "options must be bad");
        let inner = <Error as de::Error>::custom("[2] has length 1, expected 2").at(&root);
        assert_eq!(inner.message, "options[2] has length 1, expected 2");
        let again = e.clone().at(&Path::Root("other"));
        assert_eq!(again, e);
    }

    #[test]
    fn unexpected_text_is_serdes() {
        use de::Unexpected as U;
        let all = [
            U::Bool(true),
            U::Unsigned(7),
            U::Signed(-3),
            U::Float(1.0),
            U::Float(-0.0),
            U::Float(1.5e-7),
            U::Float(1e21),
            U::Float(f64::NAN),
            U::Float(f64::NEG_INFINITY),
            U::Char('x'),
            U::Str("a \"b\"\n"),
            U::Bytes(b"ab"),
            U::Unit,
            U::Option,
            U::NewtypeStruct,
            U::Seq,
            U::Map,
            U::Enum,
            U::UnitVariant,
            U::NewtypeVariant,
            U::TupleVariant,
            U::StructVariant,
            U::Other("something else"),
        ];
        for u in all {
            assert_eq!(unexpected_text(u), u.to_string());
        }
        for i in [0, 9, 10, 99, 100, 4_294_967_296, u64::MAX] {
            assert_eq!(unexpected_text(U::Unsigned(i)), U::Unsigned(i).to_string());
        }
        for i in [i64::MIN, -10, -1, 0, 1, 12_345, i64::MAX] {
            assert_eq!(unexpected_text(U::Signed(i)), U::Signed(i).to_string());
        }
        for c in ['\'', '"', 'é', '日'] {
            assert_eq!(unexpected_text(U::Char(c)), U::Char(c).to_string());
        }
    }

    #[test]
    fn cut_at_splits_before_the_first_byte() {
        assert_eq!(cut_at("a.b.c", b'.'), ("a", ".b.c"));
        assert_eq!(cut_at("abc", b'.'), ("abc", ""));
        assert_eq!(cut_at("", b'.'), ("", ""));
        assert_eq!(cut_at("é[2]", b'['), ("é", "[2]"));
    }
}
