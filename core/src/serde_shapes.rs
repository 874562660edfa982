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

/// `Vec<f64>` as `[x, …]`, serde's own shape: the marker of "a list of numbers" that a
/// binding may also take as a typed array (TypeScript `number[] | Float64Array`).
pub mod numbers {
    use super::*;

    /// Writes the entries in order.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<S: Serializer>(v: &[f64], s: S) -> Result<S::Ok, S::Error> {
        v.serialize(s)
    }

    /// Reads `[x, …]`.
    ///
    /// # Errors
    /// The deserializer's.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<f64>, D::Error> {
        Vec::<f64>::deserialize(d)
    }
}

/// `Vec<Vec<f64>>` as `[[x, …], …]`, each row a [`numbers`] (rows may differ in length).
pub mod rows_of_numbers {
    use super::*;

    /// Writes the rows in order.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<S: Serializer>(v: &[Vec<f64>], s: S) -> Result<S::Ok, S::Error> {
        v.serialize(s)
    }

    /// Reads `[[x, …], …]`.
    ///
    /// # Errors
    /// The deserializer's.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<Vec<f64>>, D::Error> {
        Vec::<Vec<f64>>::deserialize(d)
    }
}

/// The elements of a [`ScalarOr`] array, and how its error message names them.
pub trait ArrayElement {
    /// What the array holds, for "expected a number or an array of …".
    const ARRAY: &'static str;
}

impl ArrayElement for f64 {
    const ARRAY: &'static str = "an array of numbers";
}

impl ArrayElement for Vec<f64> {
    const ARRAY: &'static str = "an array of rows (arrays of numbers)";
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
                write!(f, "a number or {}", T::ARRAY)
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
