//! The detection model p_D(x; S) = 1_S(x) p_D, eq. (51) of `001_…`.

use crate::error::{Error, Result, check_probability};
use crate::regions::Region;

/// p_D(x; S) = 1_S(x) p_D (eq. (51) of `001_0f0df91eee9b30d5.txt`): a constant detection
/// probability inside an optional field of view S (a [`Region`] of the position subspace,
/// e.g. the union of the anchor discs (68)); without a field of view the object is
/// detectable everywhere.
#[derive(Clone, Debug, PartialEq)]
pub struct Detection {
    /// p_D inside the field of view (`detection.probability`).
    pub probability: f64,
    /// S (`detection.fov`); `None`: detection everywhere.
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
    /// [`Error::DimensionMismatch`] naming `detection.fov`.
    pub fn validate(&self, position_dims: Option<usize>) -> Result<()> {
        check_probability(|| "detection.probability".into(), self.probability)?;
        if let (Some(fov), Some(ns)) = (&self.fov, position_dims)
            && fov.dim() != ns
        {
            return Err(Error::dimension("detection.fov", ns, fov.dim()));
        }
        Ok(())
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
