//! An axis-aligned box in any dimension.

use alloc::vec::Vec;

use crate::error::{Error, Result};

/// The closed axis-aligned box `{s : min[k] ≤ s[k] ≤ max[k] for every k}` in the position
/// subspace (the first `dim()` state components; Section III of `001_…`).
///
/// Bounds may be infinite (a half-space or a slab is a box with some infinite bounds); a
/// bound equal to its partner gives a box of zero volume, which contains its points but has
/// zero Gaussian mass.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisBox {
    min: Vec<f64>,
    max: Vec<f64>,
}

impl AxisBox {
    /// The box `[min[0], max[0]] × … × [min[n−1], max[n−1]]`. `what` names it in errors:
    /// `{what}.min[k]`, `{what}.max[k]`.
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] if `min` is empty or `max` has another length;
    /// [`Error::InvalidParameter`] for a NaN bound or `max[k] < min[k]`.
    pub fn new(min: &[f64], max: &[f64], what: &str) -> Result<Self> {
        if min.is_empty() {
            return Err(Error::dimension(alloc::format!("{what}.min"), 1, 0));
        }
        if max.len() != min.len() {
            return Err(Error::dimension(
                alloc::format!("{what}.max"),
                min.len(),
                max.len(),
            ));
        }
        for (k, (&lo, &hi)) in min.iter().zip(max).enumerate() {
            if lo.is_nan() {
                return Err(Error::parameter(
                    alloc::format!("{what}.min[{k}]"),
                    lo,
                    "a number (finite or infinite)",
                ));
            }
            if hi.is_nan() || hi < lo {
                return Err(Error::parameter(
                    alloc::format!("{what}.max[{k}]"),
                    hi,
                    "a number not below the matching min",
                ));
            }
        }
        Ok(Self {
            min: min.to_vec(),
            max: max.to_vec(),
        })
    }

    /// The dimension n.
    pub fn dim(&self) -> usize {
        self.min.len()
    }

    /// The lower corner.
    pub fn min(&self) -> &[f64] {
        &self.min
    }

    /// The upper corner.
    pub fn max(&self) -> &[f64] {
        &self.max
    }

    /// True when `min[k] ≤ s[k] ≤ max[k]` for every k < n (the box is closed). Exact: only
    /// comparisons. Components of `s` beyond n are ignored.
    ///
    /// # Panics
    /// If `s.len() < self.dim()`.
    #[inline]
    pub fn contains(&self, s: &[f64]) -> bool {
        let s = &s[..self.min.len()];
        s.iter()
            .zip(self.min.iter().zip(&self.max))
            .all(|(&x, (&lo, &hi))| lo <= x && x <= hi)
    }
}
