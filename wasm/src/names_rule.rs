//! The naming rule, without dependencies: used by [`super`] and by `wasm/build.rs` (which
//! includes this file), so the TypeScript declarations and the values agree.

use std::borrow::Cow;
use std::string::String;
use std::vec::Vec;

/// Fields whose JavaScript name is not their camelCase: `(parent field, Rust field, JS name)`.
/// The matrices of a linear-Gaussian transition and measurement model keep the papers' capitals.
pub const EXCEPTIONS: &[(&str, &str, &str)] = &[
    ("transition", "f", "F"),
    ("transition", "q", "Q"),
    ("likelihood", "h", "H"),
    ("likelihood", "r", "R"),
];

/// Parts of a value whose JavaScript name is not their camelCase whatever holds them:
/// `(Rust name, JS name)`. The core's `ball` region is the contract's `disc` (`{ disc: { center,
/// radius } }`), so an error path `reports[0].ball.center` reads `reports[0].disc.center`.
pub const ANY_PARENT: &[(&str, &str)] = &[("ball", "disc")];

/// Variants that JavaScript gives bare, as the value of their one field: `(variant, field)`.
/// The contract's polygon is `{ polygon: [[x, y], …] }`, the core's `{ polygon: { vertices } }`.
pub const BARE: &[(&str, &str)] = &[("polygon", "vertices")];

/// The JavaScript name of a Rust name that is not one of the exceptions: camelCase
/// (`future_scans` → `futureScans`); a name without an underscore comes back borrowed. Rust
/// field names are ASCII, so the ASCII case map is enough (and keeps Unicode's tables out of
/// the module).
pub fn camel_case(field: &str) -> Cow<'_, str> {
    if !field.contains('_') {
        return Cow::Borrowed(field);
    }
    // Bytewise (ASCII changes only, so the text stays UTF-8): no character encoding code in
    // every wasm module.
    let mut out = Vec::with_capacity(field.len());
    let mut upper = false;
    for &b in field.as_bytes() {
        if b == b'_' {
            upper = !out.is_empty();
        } else if upper {
            out.push(b.to_ascii_uppercase());
            upper = false;
        } else {
            out.push(b);
        }
    }
    Cow::Owned(String::from_utf8(out).unwrap_or_default())
}

/// The JavaScript name of `field` held in `parent`, as text (the exceptions, then
/// [`ANY_PARENT`], else camelCase).
pub fn js_name_of(parent: &str, field: &str) -> String {
    let exception = EXCEPTIONS
        .iter()
        .find(|(p, f, _)| *p == parent && *f == field)
        .map(|(_, _, js)| js);
    let any = ANY_PARENT
        .iter()
        .find(|(f, _)| *f == field)
        .map(|(_, js)| js);
    match exception.or(any) {
        Some(js) => String::from(*js),
        None => camel_case(field).into_owned(),
    }
}
