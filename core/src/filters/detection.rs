//! The detection model p_D(x; S) = 1_S(x) p_D, eq. (51) of `001_…`.

#[cfg(doc)]
use crate::error::Error;
use crate::error::{Result, check_probability};
use crate::regions::Region;

/// p_D(x; S) = 1_S(x) p_D (eq. (51) of `001_0f0df91eee9b30d5.txt`): a constant detection
/// probability inside an optional field of view S (a [`Region`] of the position subspace,
/// e.g. the union of the anchor discs (68)); without a field of view the object is
/// detectable everywhere.
#[derive(Clone, Debug, PartialEq)]
pub struct Detection {
    /// The detection probability p_D ∈ [0, 1] inside the field of view (`detection.probability`).
    pub probability: f64,
    /// The field of view S (`detection.fov`); `None`: detection everywhere.
    pub fov: Option<Region>,
}

impl Detection {
    /// A validated detection model.
    ///
    /// # Errors
    /// [`Error::InvalidProbability`] naming `detection.probability`.
    pub fn new(probability: f64, fov: Option<Region>) -> Result<Self> {
        let d = Self { probability, fov };
        d.validate(None)?;
        Ok(d)
    }

    /// Checks p_D and, when `position_dims` is given, that the field of view has that
    /// dimension.
    ///
    /// # Errors
    /// [`Error::InvalidProbability`] naming `detection.probability`;
    /// [`Error::ShapeMismatch`] naming the field of `detection.fov` that carries its
    /// dimension (`detection.fov.box.min`) and `position_dims`.
    pub fn validate(&self, position_dims: Option<usize>) -> Result<()> {
        check_probability(|| "detection.probability".into(), self.probability)?;
        match (&self.fov, position_dims) {
            (Some(fov), Some(ns)) => super::validate::check_region(fov, "detection.fov", ns),
            _ => Ok(()),
        }
    }

    /// p_D(x; S) of eq. (51) at state `x` (its first n_s components are the position).
    #[inline]
    pub fn probability_at(&self, x: &[f64]) -> f64 {
        match &self.fov {
            Some(fov) if !fov.contains(x) => 0.0,
            _ => self.probability,
        }
    }
}
