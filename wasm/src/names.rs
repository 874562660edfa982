//! JavaScript names for the core's Rust names, in one place.
//!
//! The core's types serialise with their Rust field names (`future_scans`, `transition.f`); the
//! JavaScript binding shows them in camelCase (`futureScans`), with the transition and
//! measurement matrices in their papers' capitals (`F`, `Q`, `H`, `R`). [`js_name`] maps one
//! field, [`render_path`] a whole error path, and [`Renamed`] wraps a value so that any serde
//! `Serializer` writes its struct fields under their JavaScript names.

use std::boxed::Box;
use std::cell::RefCell;
use std::string::String;
use std::vec::Vec;

use serde::ser::{self, Serialize, Serializer};

// The rule itself (the exceptions and camelCase) is shared with `build.rs`, which writes the
// TypeScript declarations of the core's types under the same names.
#[path = "names_rule.rs"]
pub(crate) mod rule;
use crate::de::MAX_SAFE_INTEGER;
use rule::{EXCEPTIONS, camel_case};

/// The JavaScript name of the Rust field `field` of a value held in the field `parent` (`""`
/// at the top, either spelling: the parents of the exceptions are one word): camelCase
/// (`future_scans` → `futureScans`) unless it is one of the matrix exceptions (`transition.f`
/// → `F`). Each converted name is made once and kept for the life of the module (one small
/// string per distinct Rust field name), so serde can use it as a `&'static str` key.
pub fn js_name(parent: &str, field: &'static str) -> &'static str {
    if let Some((_, _, js)) = EXCEPTIONS
        .iter()
        .find(|(p, f, _)| *p == parent && *f == field)
    {
        return js;
    }
    if !field.contains('_') {
        return field;
    }
    INTERNED.with(|t| {
        let mut t = t.borrow_mut();
        if let Some((_, js)) = t.iter().find(|(rust, _)| *rust == field) {
            return *js;
        }
        let js: &'static str = Box::leak(camel_case(field).into_owned().into_boxed_str());
        t.push((field, js));
        js
    })
}

/// An error path in Rust names (`transition.f`, `components[2].mean`, `future_scans`) in
/// JavaScript names (`transition.F`, `components[2].mean`, `futureScans`).
pub fn render_path(rust_path: &str) -> String {
    render_path_in("", rust_path)
}

/// The JavaScript name of a Rust name as a value's variant key (`ball` → `disc`; the others
/// as they are), as [`Renamed`] writes it.
pub fn variant_name(rust: &'static str) -> &'static str {
    rule::ANY_PARENT
        .iter()
        .find(|(r, _)| *r == rust)
        .map_or(rust, |(_, js)| js)
}

/// [`render_path`] for a path below the field `parent` (`""` at the top): the exceptions of
/// `parent`'s fields apply to its first segment.
pub fn render_path_in(parent: &str, rust_path: &str) -> String {
    let mut out = String::with_capacity(rust_path.len());
    let mut parent = parent;
    // (split bytewise at ASCII '.': every part is UTF-8, and no character searcher)
    for (i, segment) in rust_path.as_bytes().split(|&b| b == b'.').enumerate() {
        if i > 0 {
            out.push('.');
        }
        // `name[3][1]`: the name, then its indices as they are
        let (name, indices) = crate::de::cut_at(std::str::from_utf8(segment).unwrap_or(""), b'[');
        out.push_str(&rule::js_name_of(parent, name));
        out.push_str(indices);
        parent = name;
    }
    out
}

thread_local! {
    /// The camelCase names given out by [`js_name`], by Rust name.
    /// (A list, not a map: a few dozen names, and no map code in every module.)
    static INTERNED: RefCell<Vec<(&'static str, &'static str)>> = const { RefCell::new(Vec::new()) };
}

/// A value that serialises with its struct fields under their JavaScript names.
pub struct Renamed<'a, T: ?Sized> {
    value: &'a T,
    parent: &'static str,
}

impl<'a, T: ?Sized> Renamed<'a, T> {
    /// Wraps `value`, a top-level argument or result.
    pub fn new(value: &'a T) -> Self {
        Self { value, parent: "" }
    }
}

impl<T: Serialize + ?Sized> Serialize for Renamed<'_, T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.value.serialize(Rename {
            inner: s,
            parent: self.parent,
        })
    }
}

/// The serializer behind [`Renamed`]: forwards everything to `inner`, renaming struct fields
/// and wrapping every nested value.
struct Rename<S> {
    inner: S,
    parent: &'static str,
}

/// serde-wasm-bindgen's error for an integer no JS number holds exactly.
fn unrepresentable<E: ser::Error>(negative: bool, magnitude: u64) -> E {
    E::custom(std::format!(
        "{} can't be represented as a JavaScript number",
        crate::de::integer_text(negative, magnitude)
    ))
}

/// A compound serializer of `inner` whose elements are wrapped in [`Renamed`].
struct Compound<C> {
    inner: C,
    parent: &'static str,
}

impl<C> Compound<C> {
    fn wrap<'a, T: ?Sized>(&self, value: &'a T) -> Renamed<'a, T> {
        Renamed {
            value,
            parent: self.parent,
        }
    }
}

macro_rules! forward {
    ($($method:ident($($arg:ident: $ty:ty),*);)*) => {
        $(fn $method(self, $($arg: $ty),*) -> Result<S::Ok, S::Error> {
            self.inner.$method($($arg),*)
        })*
    };
}

/// The compound `serialize_*` methods: the inner serialiser's, wrapped so that the elements
/// and fields written through it are renamed in turn.
macro_rules! compound {
    ($($method:ident($($arg:ident: $ty:ty),*) -> $out:ident;)*) => {
        $(fn $method(self, $($arg: $ty),*) -> Result<Self::$out, S::Error> {
            Ok(Compound {
                inner: self.inner.$method($($arg),*)?,
                parent: self.parent,
            })
        })*
    };
}

impl<S: Serializer> Serializer for Rename<S> {
    type Ok = S::Ok;
    type Error = S::Error;
    type SerializeSeq = Compound<S::SerializeSeq>;
    type SerializeTuple = Compound<S::SerializeTuple>;
    type SerializeTupleStruct = Compound<S::SerializeTupleStruct>;
    type SerializeTupleVariant = Compound<S::SerializeTupleVariant>;
    type SerializeMap = Compound<S::SerializeMap>;
    type SerializeStruct = Compound<S::SerializeStruct>;
    type SerializeStructVariant = Compound<S::SerializeStructVariant>;

    forward! {
        serialize_bool(v: bool);
        serialize_i8(v: i8);
        serialize_i16(v: i16);
        serialize_i32(v: i32);
        serialize_u8(v: u8);
        serialize_u16(v: u16);
        serialize_u32(v: u32);
        serialize_f32(v: f32);
        serialize_f64(v: f64);
        serialize_char(v: char);
        serialize_str(v: &str);
        serialize_bytes(v: &[u8]);
        serialize_none();
        serialize_unit();
        serialize_unit_struct(name: &'static str);
        serialize_unit_variant(name: &'static str, index: u32, variant: &'static str);
    }

    // 64-bit integers (counts, indices) as JS numbers, as serde-wasm-bindgen writes them, but
    // without its BigInt path and the standard library's 64-bit integer text in every module
    // (issue 25, wasm size); the message for one beyond 2^53 is serde-wasm-bindgen's.
    fn serialize_i64(self, v: i64) -> Result<S::Ok, S::Error> {
        if v.unsigned_abs() <= MAX_SAFE_INTEGER {
            self.inner.serialize_f64(v as f64)
        } else {
            Err(unrepresentable(v < 0, v.unsigned_abs()))
        }
    }

    fn serialize_u64(self, v: u64) -> Result<S::Ok, S::Error> {
        if v <= MAX_SAFE_INTEGER {
            self.inner.serialize_f64(v as f64)
        } else {
            Err(unrepresentable(false, v))
        }
    }

    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<S::Ok, S::Error> {
        let parent = self.parent;
        self.inner.serialize_some(&Renamed { value, parent })
    }

    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        name: &'static str,
        value: &T,
    ) -> Result<S::Ok, S::Error> {
        let parent = self.parent;
        self.inner
            .serialize_newtype_struct(name, &Renamed { value, parent })
    }

    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        name: &'static str,
        index: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<S::Ok, S::Error> {
        let parent = self.parent;
        // a variant holding a value is written as a one-key object: its key takes the
        // contract's name too (the core's `ball` region is `disc`)
        let variant = variant_name(variant);
        self.inner
            .serialize_newtype_variant(name, index, variant, &Renamed { value, parent })
    }

    compound! {
        serialize_seq(len: Option<usize>) -> SerializeSeq;
        serialize_tuple(len: usize) -> SerializeTuple;
        serialize_tuple_struct(name: &'static str, len: usize) -> SerializeTupleStruct;
        serialize_tuple_variant(name: &'static str, index: u32, variant: &'static str, len: usize)
            -> SerializeTupleVariant;
        serialize_map(len: Option<usize>) -> SerializeMap;
        serialize_struct(name: &'static str, len: usize) -> SerializeStruct;
        serialize_struct_variant(name: &'static str, index: u32, variant: &'static str, len: usize)
            -> SerializeStructVariant;
    }

    fn is_human_readable(&self) -> bool {
        self.inner.is_human_readable()
    }
}

macro_rules! elements {
    ($($trait:ident :: $method:ident;)*) => {
        $(impl<C: ser::$trait> ser::$trait for Compound<C> {
            type Ok = C::Ok;
            type Error = C::Error;
            fn $method<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), C::Error> {
                let wrapped = self.wrap(value);
                self.inner.$method(&wrapped)
            }
            fn end(self) -> Result<C::Ok, C::Error> {
                self.inner.end()
            }
        })*
    };
}

elements! {
    SerializeSeq::serialize_element;
    SerializeTuple::serialize_element;
    SerializeTupleStruct::serialize_field;
    SerializeTupleVariant::serialize_field;
}

impl<C: ser::SerializeMap> ser::SerializeMap for Compound<C> {
    type Ok = C::Ok;
    type Error = C::Error;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), C::Error> {
        self.inner.serialize_key(key)
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), C::Error> {
        let wrapped = self.wrap(value);
        self.inner.serialize_value(&wrapped)
    }
    fn end(self) -> Result<C::Ok, C::Error> {
        self.inner.end()
    }
}

macro_rules! fields {
    ($($trait:ident;)*) => {
        $(impl<C: ser::$trait> ser::$trait for Compound<C> {
            type Ok = C::Ok;
            type Error = C::Error;
            fn serialize_field<T: Serialize + ?Sized>(
                &mut self,
                key: &'static str,
                value: &T,
            ) -> Result<(), C::Error> {
                let js = js_name(self.parent, key);
                self.inner.serialize_field(js, &Renamed { value, parent: key })
            }
            fn skip_field(&mut self, key: &'static str) -> Result<(), C::Error> {
                self.inner.skip_field(js_name(self.parent, key))
            }
            fn end(self) -> Result<C::Ok, C::Error> {
                self.inner.end()
            }
        })*
    };
}

fields! {
    SerializeStruct;
    SerializeStructVariant;
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec;
    use std::vec::Vec;

    #[test]
    fn js_name_camel_cases_and_keeps_the_matrix_capitals() {
        assert_eq!(js_name("", "future_scans"), "futureScans");
        assert_eq!(js_name("", "alpha"), "alpha");
        assert_eq!(js_name("", "detection_probability"), "detectionProbability");
        assert_eq!(js_name("transition", "f"), "F");
        assert_eq!(js_name("likelihood", "r"), "R");
        // `r` elsewhere is just `r`
        assert_eq!(js_name("", "r"), "r");
        assert_eq!(js_name("options", "r"), "r");
    }

    #[test]
    fn render_path_renames_each_segment_and_keeps_indices() {
        assert_eq!(render_path("future_scans"), "futureScans");
        assert_eq!(render_path("transition.f"), "transition.F");
        assert_eq!(
            render_path("mixture[2].mean_vector[1]"),
            "mixture[2].meanVector[1]"
        );
        assert_eq!(render_path("likelihood.r[0][1]"), "likelihood.R[0][1]");
        assert_eq!(
            render_path("rfs.iid_cluster.cardinality"),
            "rfs.iidCluster.cardinality"
        );
        assert_eq!(
            render_path("detection.fov.complement.union[0].ball.center"),
            "detection.fov.complement.union[0].disc.center"
        );
        assert_eq!(render_path(""), "");
    }

    #[test]
    fn render_path_in_applies_the_parents_exceptions_and_variant_names() {
        // a relative part of an error below `transition` (the core's `.q` of a transition)
        assert_eq!(render_path_in("transition", "q"), "Q");
        assert_eq!(render_path_in("", "q"), "q");
        // a region's part: the core's `ball` is the contract's `disc`
        assert_eq!(render_path_in("fov", "ball.radius"), "disc.radius");
        assert_eq!(
            render_path_in("fov", "union[1].ball.center"),
            "union[1].disc.center"
        );
        assert_eq!(render_path_in("mixture", "[2].cov"), "[2].cov");
        assert_eq!(variant_name("ball"), "disc");
        assert_eq!(variant_name("polygon"), "polygon");
    }

    #[derive(serde::Serialize)]
    struct Transition {
        f: Vec<f64>,
        q: f64,
        survival_probability: f64,
    }

    #[derive(serde::Serialize)]
    struct Config {
        transition: Transition,
        future_scans: Option<usize>,
        per_step: Vec<Step>,
        kind: Kind,
    }

    #[derive(serde::Serialize)]
    struct Step {
        mean_distance: f64,
    }

    #[derive(serde::Serialize)]
    enum Kind {
        Particle { sample_count: usize },
    }

    /// `value` as JSON, through the renaming wrapper.
    fn json(value: &impl Serialize) -> String {
        serde_json::to_string(&Renamed::new(value)).unwrap()
    }

    /// The keys a value writes, in order (the quoted parts of its JSON, which has no strings).
    fn keys(value: &impl Serialize) -> String {
        let text = json(value);
        let keys: Vec<&str> = text.split('"').skip(1).step_by(2).collect();
        keys.join(",")
    }

    #[test]
    fn renamed_writes_a_core_ball_region_as_a_disc() {
        let disc = fisst::regions::Region::ball(&[1.0, 2.0], 3.0, "r").unwrap();
        let both = fisst::regions::Region::union(vec![disc.clone(), disc], "r").unwrap();
        assert_eq!(
            json(&both),
            r#"{"union":[{"disc":{"center":[1.0,2.0],"radius":3.0}},{"disc":{"center":[1.0,2.0],"radius":3.0}}]}"#
        );
    }

    #[test]
    fn renamed_writes_every_nested_field_in_javascript_names() {
        let c = Config {
            transition: Transition {
                f: vec![1.0],
                q: 0.5,
                survival_probability: 0.99,
            },
            future_scans: Some(3),
            per_step: vec![Step { mean_distance: 1.5 }],
            kind: Kind::Particle { sample_count: 10 },
        };
        assert_eq!(
            keys(&c),
            "transition,F,Q,survivalProbability,futureScans,perStep,meanDistance,kind,Particle,sampleCount"
        );
        // the values pass through unchanged
        assert!(json(&c).contains("\"survivalProbability\":0.99}"));
        // a name is converted once: the same string on every call
        assert!(core::ptr::eq(
            js_name("", "future_scans"),
            js_name("x", "future_scans")
        ));
    }
}
