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
}
