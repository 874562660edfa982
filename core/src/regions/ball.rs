//! A closed ball (a disc in 2D) in any dimension.

use alloc::vec::Vec;
use core::cmp::Ordering;

use crate::error::{Error, Result};

use super::predicates::ball_side;

/// The closed ball `{s : |s − center| ≤ radius}` (Euclidean norm) in the position subspace.
#[derive(Clone, Debug, PartialEq)]
pub struct Ball {
    center: Vec<f64>,
    radius: f64,
}

impl Ball {
    /// The ball of `radius` around `center`. `what` names it in errors: `{what}.center[k]`,
    /// `{what}.radius`.
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] for an empty centre; [`Error::InvalidParameter`] for a
    /// non-finite coordinate or a radius that is not finite and > 0.
    pub fn new(center: &[f64], radius: f64, what: &str) -> Result<Self> {
        if center.is_empty() {
            return Err(Error::dimension(alloc::format!("{what}.center"), 1, 0));
        }
        if let Some(k) = center.iter().position(|c| !c.is_finite()) {
            return Err(Error::parameter(
                alloc::format!("{what}.center[{k}]"),
                center[k],
                "finite",
            ));
        }
        if !(radius.is_finite() && radius > 0.0) {
            return Err(Error::parameter(
                alloc::format!("{what}.radius"),
                radius,
                "finite and > 0",
            ));
        }
        Ok(Self {
            center: center.to_vec(),
            radius,
        })
    }

    /// The dimension n.
    pub fn dim(&self) -> usize {
        self.center.len()
    }

    /// The centre.
    pub fn center(&self) -> &[f64] {
        &self.center
    }

    /// The radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// True when |s − center|² ≤ radius² (the ball is closed). Exact: a floating-point filter
    /// decides all but the points within a few ulps of the sphere, and those are decided by
    /// exact expansion arithmetic. Components of `s` beyond n are ignored.
    ///
    /// # Panics
    /// If `s.len() < self.dim()`.
    #[inline]
    pub fn contains(&self, s: &[f64]) -> bool {
        ball_side(&s[..self.center.len()], &self.center, self.radius) != Ordering::Less
    }
}
