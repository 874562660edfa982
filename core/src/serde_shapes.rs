//! The `serde` shapes of nalgebra values (feature `serde`): a vector is `[x, …]`, a matrix a
//! row-major array of rows `[[a, b], [c, d]]` (nalgebra's own format, a column-major `data`
//! array with its dimensions, is not what a user writes). Use them with
//! `#[serde(with = "fisst::serde_shapes::matrix")]`.
//!
//! No paper: these are data formats only.

use alloc::vec::Vec;

use nalgebra::{DMatrix, DVector};
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// At most this many Gaussians in one mixture read (a `GaussianMixture`, a
/// `SpatialDensity`'s `mixture`): a longer array is an error naming it ("has 10001 entries, at
/// most 10000 are supported"). The one cap of [`crate::gaussian::MAX_GAUSSIANS`].
pub use crate::gaussian::MAX_GAUSSIANS;

/// A multi-Bernoulli of Gaussians, `Vec<(f64, Gaussian)>` (existence, density), as
/// `[{existence, mean, cov}, …]`: `cov` in any [`Covariance`] form, at most [`MAX_GAUSSIANS`]
/// components; errors relative to the array (`[2].cov`, `[0].mean[1]`). Use it with
/// `#[serde(with = "fisst::serde_shapes::bernoullis")]`.
pub mod bernoullis {
    use super::*;
    use crate::gaussian::Gaussian;

    /// Writes `[{existence, mean, cov}, …]`, `cov` as rows.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<S: Serializer>(v: &[(f64, Gaussian)], s: S) -> Result<S::Ok, S::Error> {
        crate::serde_valid::write_bernoullis(v, s)
    }

    /// Reads `[{existence, mean, cov}, …]` (the existences are not checked).
    ///
    /// # Errors
    /// The deserializer's; a type error (`invalid_type`) for a bare-number `cov` when the mean
    /// has more than one entry; a custom error for more than [`MAX_GAUSSIANS`] components or a
    /// covariance that does not fit its mean or is not positive definite.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<(f64, Gaussian)>, D::Error> {
        crate::serde_valid::read_bernoullis(d)
    }
}

/// `DVector<f64>` as `[x, …]`.
pub mod vector {
    use super::*;

    /// Writes the entries in order.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<S: Serializer>(v: &DVector<f64>, s: S) -> Result<S::Ok, S::Error> {
        v.as_slice().serialize(s)
    }

    /// Reads `[x, …]` (any length, including 0).
    ///
    /// # Errors
    /// The deserializer's, for anything but an array of numbers.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<DVector<f64>, D::Error> {
        Vec::<f64>::deserialize(d).map(DVector::from_vec)
    }
}

/// `DMatrix<f64>` as a row-major array of rows `[[…], …]`.
pub mod matrix {
    use super::*;

    /// Writes the rows in order.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<S: Serializer>(m: &DMatrix<f64>, s: S) -> Result<S::Ok, S::Error> {
        let rows: Vec<Vec<f64>> = m.row_iter().map(|r| r.iter().copied().collect()).collect();
        rows.serialize(s)
    }

    /// Reads an array of rows of equal length (`[]` is the 0 × 0 matrix).
    ///
    /// # Errors
    /// The deserializer's, or a custom error naming the first row whose length differs
    /// from row 0's.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<DMatrix<f64>, D::Error> {
        let rows = Vec::<Vec<f64>>::deserialize(d)?;
        let ncols = rows.first().map_or(0, Vec::len);
        if let Some(i) = rows.iter().position(|r| r.len() != ncols) {
            return Err(D::Error::custom(alloc::format!(
                "row {i} has length {}, expected {ncols}",
                rows[i].len()
            )));
        }
        let nrows = rows.len();
        let flat: Vec<f64> = rows.into_iter().flatten().collect();
        Ok(DMatrix::from_row_slice(nrows, ncols, &flat))
    }
}

/// `Vec<Vec<f64>>` as `[[x, …], …]`, each row a [`numbers`] (rows may differ in length);
/// also for an `Option<Vec<Vec<f64>>>`.
pub mod rows_of_numbers {
    use super::*;

    /// Writes the rows in order (or an `Option` of them: null for `None`).
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<T: Serialize + ?Sized, S: Serializer>(v: &T, s: S) -> Result<S::Ok, S::Error> {
        v.serialize(s)
    }

    /// Reads `[[x, …], …]` (or an `Option` of them, for a field with `default`).
    ///
    /// # Errors
    /// The deserializer's.
    pub fn deserialize<'de, T: Deserialize<'de>, D: Deserializer<'de>>(
        d: D,
    ) -> Result<T, D::Error> {
        T::deserialize(d)
    }
}

/// `Vec<Vec<Vec<f64>>>`, one point set per time step, as `[[[x, …], …], …]`: the serde shape
/// is the plain nested arrays; the module marks the field for the bindings' type generators
/// (a point may be given as a typed array where the binding reads one).
pub mod point_sets {
    use super::*;

    /// Writes the sets in order.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<S: Serializer>(v: &[Vec<Vec<f64>>], s: S) -> Result<S::Ok, S::Error> {
        v.serialize(s)
    }

    /// Reads the nested arrays.
    ///
    /// # Errors
    /// The deserializer's, for anything but arrays of arrays of numbers.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<Vec<Vec<f64>>>, D::Error> {
        Vec::deserialize(d)
    }
}

/// Numbers, `Vec<f64>` (or `Option<Vec<f64>>`), as `[x, …]`: the serde shape is the plain
/// array; the module marks the field for the bindings' type generators (a binding may read a
/// typed array, `Float64Array` in JavaScript, as well). Its `serialize` alone
/// (`serialize_with`) marks it too, and leaves the field's reader as it is (a `with` reader
/// is a copy of the array reader in each binding's module).
pub mod numbers {
    use super::*;

    /// Writes the value as it is.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<T: Serialize, S: Serializer>(v: &T, s: S) -> Result<S::Ok, S::Error> {
        v.serialize(s)
    }

    /// Reads the value as it is.
    ///
    /// # Errors
    /// The deserializer's.
    pub fn deserialize<'de, T: Deserialize<'de>, D: Deserializer<'de>>(
        d: D,
    ) -> Result<T, D::Error> {
        T::deserialize(d)
    }
}

/// A `GaussianMixture` as results write it, `[{weight, mean, cov}, …]` with `cov` as rows:
/// the serde shape is the mixture's own; the module marks the field for the bindings' type
/// generators (a result's mixture, not one read).
pub mod components {
    pub use super::numbers::{deserialize, serialize};
}

/// An `Option<T>` that is always written: the value, or null for `None` (a required field
/// that may be null, where a plain `Option` field is optional); the module marks the field
/// for the bindings' type generators (`T | null`).
pub mod nullable {
    use super::*;

    /// Writes the value, or null for `None`.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<T: Serialize, S: Serializer>(v: &Option<T>, s: S) -> Result<S::Ok, S::Error> {
        v.serialize(s)
    }

    /// Reads the value, or `None` from null.
    ///
    /// # Errors
    /// The deserializer's.
    pub fn deserialize<'de, T: Deserialize<'de>, D: Deserializer<'de>>(
        d: D,
    ) -> Result<Option<T>, D::Error> {
        Option::deserialize(d)
    }
}

/// `Vec<u8>` as bytes: a typed array (`Uint8Array`) where the format has one, else an array
/// of numbers.
pub mod bytes {
    use super::*;

    /// Writes the bytes with `serialize_bytes`.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<S: Serializer>(v: &[u8], s: S) -> Result<S::Ok, S::Error> {
        s.serialize_bytes(v)
    }

    /// Reads an array of bytes.
    ///
    /// # Errors
    /// The deserializer's, for anything but an array of integers in [0, 255].
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<u8>, D::Error> {
        Vec::deserialize(d)
    }
}

/// The elements of a [`ScalarOr`] array, and how its error message names them.
pub trait ArrayElement {
    /// What the array holds, for "expected a number or an array of …".
    const ARRAY: &'static str;
    /// What the whole value is, when "a number or {ARRAY}" does not say it well.
    const EXPECTING: Option<&'static str> = None;
}

impl ArrayElement for f64 {
    const ARRAY: &'static str = "an array of numbers";
}

impl ArrayElement for Vec<f64> {
    const ARRAY: &'static str = "an array of rows (arrays of numbers)";
}

impl ArrayElement for ScalarOr<f64> {
    const ARRAY: &'static str = "an array of numbers or of rows";
    const EXPECTING: Option<&'static str> =
        Some("a covariance (nested rows, flat row-major numbers, or a 1D variance)");
}

/// A value a user gives as one number or as an array: `0.3` or `[0.1, 0.2]` (one per report,
/// cell, …), `1` or `[[1, 0], [0, 1]]` (a scalar gain or a matrix). Core types whose shape is
/// "a number or an array" read through it (`#[serde(from = "ScalarOr<f64>")]` or a
/// `TryFrom`), so every binding accepts the same two forms with the same message.
#[derive(Clone, Debug, PartialEq)]
pub enum ScalarOr<T> {
    /// One number.
    Scalar(f64),
    /// An array.
    Array(Vec<T>),
}

impl<T: Serialize> Serialize for ScalarOr<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            ScalarOr::Scalar(x) => s.serialize_f64(*x),
            ScalarOr::Array(v) => v.serialize(s),
        }
    }
}

impl<'de, T: Deserialize<'de> + ArrayElement> Deserialize<'de> for ScalarOr<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::{SeqAccess, Visitor};
        struct V<T>(core::marker::PhantomData<T>);
        impl<'de, T: Deserialize<'de> + ArrayElement> Visitor<'de> for V<T> {
            type Value = ScalarOr<T>;
            fn expecting(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                match T::EXPECTING {
                    Some(what) => f.write_str(what),
                    None => write!(f, "a number or {}", T::ARRAY),
                }
            }
            fn visit_f64<E: serde::de::Error>(self, x: f64) -> Result<Self::Value, E> {
                Ok(ScalarOr::Scalar(x))
            }
            // self-describing formats other than JavaScript's (JSON, Python) give integers
            fn visit_i64<E: serde::de::Error>(self, x: i64) -> Result<Self::Value, E> {
                Ok(ScalarOr::Scalar(x as f64))
            }
            fn visit_u64<E: serde::de::Error>(self, x: u64) -> Result<Self::Value, E> {
                Ok(ScalarOr::Scalar(x as f64))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
                let mut v = Vec::with_capacity(seq.size_hint().unwrap_or(0).min(4096));
                while let Some(x) = seq.next_element::<T>()? {
                    v.push(x);
                }
                Ok(ScalarOr::Array(v))
            }
        }
        d.deserialize_any(V(core::marker::PhantomData))
    }
}

/// A covariance as a user writes it: n rows of n numbers, n·n numbers in row-major order,
/// or (1D only) the variance as a bare number. [`covariance_row_major`] checks it against
/// the mean's length n.
pub type Covariance = ScalarOr<ScalarOr<f64>>;

/// Why a [`Covariance`] does not fit its mean: the message names the covariance by the path
/// given to [`covariance_row_major`]. `wrong_type` marks a bare number where n > 1 (a type
/// error for bindings that tell those apart); the others are range errors.
#[derive(Clone, Debug, PartialEq)]
pub struct CovarianceError {
    /// A bare number given for n > 1.
    pub wrong_type: bool,
    /// The message, starting with the path.
    pub message: alloc::string::String,
}

impl core::fmt::Display for CovarianceError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(&self.message)
    }
}

/// The n·n row-major entries of `cov` for a mean of length `n`; errors name `path`
/// (`options.mixture[2].cov`, or `.cov` relative to the Gaussian being read).
///
/// # Errors
/// A [`CovarianceError`] for a bare number when n ≠ 1, a flat array of other than n·n
/// numbers, other than n rows, a row of other than n numbers, or numbers and rows mixed.
pub fn covariance_row_major(
    cov: Covariance,
    n: usize,
    path: &str,
) -> Result<Vec<f64>, CovarianceError> {
    use alloc::format;
    let range = |message| CovarianceError {
        wrong_type: false,
        message,
    };
    let entries = match cov {
        ScalarOr::Scalar(x) if n == 1 => return Ok(alloc::vec![x]),
        ScalarOr::Scalar(_) => {
            return Err(CovarianceError {
                wrong_type: true,
                message: format!(
                    "{path} must be a nested {n}×{n} array (a bare number is a 1D variance)"
                ),
            });
        }
        ScalarOr::Array(entries) => entries,
    };
    let nested = matches!(entries.first(), Some(ScalarOr::Array(_)));
    let mut flat = Vec::with_capacity(n * n);
    for (i, entry) in entries.iter().enumerate() {
        match (entry, nested) {
            (ScalarOr::Scalar(x), false) => flat.push(*x),
            (ScalarOr::Array(row), true) => flat.extend_from_slice(row),
            (ScalarOr::Scalar(_), true) => {
                return Err(range(format!(
                    "{path}[{i}] must be a row (array of numbers) like the entries before it"
                )));
            }
            (ScalarOr::Array(_), false) => {
                return Err(range(format!(
                    "{path}[{i}] must be a number like the entries before it"
                )));
            }
        }
    }
    if !nested {
        if flat.len() != n * n {
            return Err(range(format!(
                "{path} has length {}, expected {n} rows or {} row-major numbers",
                flat.len(),
                n * n
            )));
        }
        return Ok(flat);
    }
    if entries.len() != n {
        return Err(range(format!(
            "{path} has length {}, expected {n}",
            entries.len()
        )));
    }
    if let Some((i, row)) = entries.iter().enumerate().find_map(|(i, e)| match e {
        ScalarOr::Array(row) if row.len() != n => Some((i, row)),
        _ => None,
    }) {
        return Err(range(format!(
            "{path}[{i}] has length {}, expected {n}",
            row.len()
        )));
    }
    Ok(flat)
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::string::ToString;

    #[derive(Serialize, Deserialize, Debug, PartialEq)]
    struct Shapes {
        #[serde(with = "vector")]
        v: DVector<f64>,
        #[serde(with = "matrix")]
        m: DMatrix<f64>,
    }

    #[test]
    fn vectors_are_arrays_and_matrices_rows() {
        let s = Shapes {
            v: DVector::from_vec(alloc::vec![1.0, 2.0]),
            m: DMatrix::from_row_slice(2, 3, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]),
        };
        let json = serde_json::to_string(&s).unwrap();
        assert_eq!(json, r#"{"v":[1.0,2.0],"m":[[1.0,2.0,3.0],[4.0,5.0,6.0]]}"#);
        assert_eq!(serde_json::from_str::<Shapes>(&json).unwrap(), s);
        let ragged = serde_json::from_str::<Shapes>(r#"{"v":[],"m":[[1.0],[2.0,3.0]]}"#);
        assert!(
            ragged
                .unwrap_err()
                .to_string()
                .contains("row 1 has length 2, expected 1")
        );
    }

    #[test]
    fn scalar_or_reads_a_number_or_an_array() {
        let one: ScalarOr<f64> = serde_json::from_str("0.5").unwrap();
        assert_eq!(one, ScalarOr::Scalar(0.5));
        let int: ScalarOr<f64> = serde_json::from_str("2").unwrap();
        assert_eq!(int, ScalarOr::Scalar(2.0));
        let many: ScalarOr<f64> = serde_json::from_str("[0.1, 0.2]").unwrap();
        assert_eq!(many, ScalarOr::Array(alloc::vec![0.1, 0.2]));
        let rows: ScalarOr<Vec<f64>> = serde_json::from_str("[[1, 0], [0, 1]]").unwrap();
        assert_eq!(
            rows,
            ScalarOr::Array(alloc::vec![alloc::vec![1.0, 0.0], alloc::vec![0.0, 1.0]])
        );
        assert_eq!(serde_json::to_string(&many).unwrap(), "[0.1,0.2]");
        let bad = serde_json::from_str::<ScalarOr<f64>>(r#""x""#).unwrap_err();
        assert!(
            bad.to_string()
                .contains("expected a number or an array of numbers"),
            "{bad}"
        );
    }
}
