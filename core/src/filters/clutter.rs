//! Poisson false reports: rate λ_c and spatial density c̃(ζ) (Section V-B of `001_…`).

use alloc::sync::Arc;
use alloc::vec::Vec;
use core::fmt;

use crate::error::{Error, Result};

/// A clutter density given as a function of a vector measurement z (its intensity is
/// λ_c · c(z)). Cloning shares the function.
#[derive(Clone)]
pub struct ClutterFunction(pub Arc<ClutterFn>);

/// The function type behind [`ClutterFunction`]: c(z) of a vector measurement.
pub type ClutterFn = dyn Fn(&[f64]) -> f64 + Send + Sync;

impl fmt::Debug for ClutterFunction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("ClutterFunction(..)")
    }
}

/// c̃(ζ), the spatial density of false reports. With the `serde` feature it reads and writes
/// as a number or an array of numbers (`serde_shapes::ScalarOr`).
#[derive(Clone, Debug)]
pub enum ClutterDensity {
    /// One value for every report (`clutter.density: number`): e.g. 1/|𝔸| for reports
    /// uniform over the anchors, or 1/V for vector clutter uniform over a region of volume V.
    Constant(f64),
    /// One value per report of the scan, in report order (`clutter.density: number[]`).
    PerReport(Vec<f64>),
    /// A function of the vector measurement (Rust only; vector measurements only). Not
    /// (de)serialisable: serialising it is an error.
    Function(ClutterFunction),
}

#[cfg(feature = "serde")]
impl From<crate::serde_shapes::ScalarOr<f64>> for ClutterDensity {
    fn from(v: crate::serde_shapes::ScalarOr<f64>) -> Self {
        match v {
            crate::serde_shapes::ScalarOr::Scalar(c) => Self::Constant(c),
            crate::serde_shapes::ScalarOr::Array(v) => Self::PerReport(v),
        }
    }
}

// [`ClutterDensity`] as written (and read, as a `ScalarOr<f64>`); the JavaScript binding's
// TypeScript generator declares `ClutterDensity` by this form (its `rename`; a function,
// Rust only, has none).
/// c̃(ζ): one number for every report, or one per report.
#[cfg(feature = "serde")]
#[derive(serde::Serialize)]
#[serde(rename = "ClutterDensity", untagged)]
enum ClutterDensityRepr<'a> {
    /// One value for every report: e.g. 1/|𝔸| for reports uniform over the anchors, or 1/V
    /// for vector clutter uniform over a region of volume V.
    Constant(f64),
    /// One value per report of the scan, in report order.
    PerReport(&'a Vec<f64>),
}

#[cfg(feature = "serde")]
impl serde::Serialize for ClutterDensity {
    fn serialize<S: serde::Serializer>(&self, s: S) -> core::result::Result<S::Ok, S::Error> {
        let repr = match self {
            Self::Constant(c) => ClutterDensityRepr::Constant(*c),
            Self::PerReport(v) => ClutterDensityRepr::PerReport(v),
            Self::Function(_) => {
                return Err(serde::ser::Error::custom(
                    "a clutter density function cannot be serialised",
                ));
            }
        };
        serde::Serialize::serialize(&repr, s)
    }
}

#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for ClutterDensity {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> core::result::Result<Self, D::Error> {
        crate::serde_shapes::ScalarOr::<f64>::deserialize(d).map(Self::from)
    }
}

impl PartialEq for ClutterDensity {
    /// Functions compare by identity.
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (Self::Constant(a), Self::Constant(b)) => a == b,
            (Self::PerReport(a), Self::PerReport(b)) => a == b,
            (Self::Function(a), Self::Function(b)) => Arc::ptr_eq(&a.0, &b.0),
            _ => false,
        }
    }
}

/// Poisson false reports with mean count λ_c (`clutter.rate`) and density c̃(ζ)
/// (`clutter.density`): the clutter intensity is κ(ζ) = λ_c c̃(ζ), the denominator of
/// eqs. (53), (55), (57)–(58) of `001_0f0df91eee9b30d5.txt`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Clutter {
    /// The clutter rate λ_c ≥ 0: the expected number of false reports per scan.
    pub rate: f64,
    /// The clutter density c̃(ζ) ≥ 0 of a false report ζ: a constant (e.g. 1 / number of
    /// anchors, or 1 / area for vector measurements) or one value per report (in Rust, also a
    /// function).
    pub density: ClutterDensity,
}

impl Clutter {
    /// A validated clutter model.
    ///
    /// # Errors
    /// As [`Clutter::validate`].
    pub fn new(rate: f64, density: ClutterDensity) -> Result<Self> {
        let c = Self { rate, density };
        c.validate()?;
        Ok(c)
    }

    /// No clutter (λ_c = 0).
    pub fn none() -> Self {
        Self {
            rate: 0.0,
            density: ClutterDensity::Constant(1.0),
        }
    }

    /// Checks λ_c (finite, ≥ 0) and the density values (finite, ≥ 0).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `clutter.rate`, `clutter.density` or
    /// `clutter.density[i]`.
    pub fn validate(&self) -> Result<()> {
        if !(self.rate.is_finite() && self.rate >= 0.0) {
            return Err(Error::parameter(
                "clutter.rate",
                self.rate,
                "finite and >= 0",
            ));
        }
        match &self.density {
            ClutterDensity::Constant(c) => {
                if !(c.is_finite() && *c >= 0.0) {
                    return Err(Error::parameter("clutter.density", *c, "finite and >= 0"));
                }
            }
            ClutterDensity::PerReport(v) => {
                if let Some(i) = v.iter().position(|c| !(c.is_finite() && *c >= 0.0)) {
                    return Err(Error::parameter(
                        alloc::format!("clutter.density[{i}]"),
                        v[i],
                        "finite and >= 0",
                    ));
                }
            }
            ClutterDensity::Function(_) => {}
        }
        Ok(())
    }

    /// κ_i = λ_c c̃(ζ_i) for the reports of a scan of `count` reports; `measurement(i)` gives
    /// the vector measurement i when there is one (needed by [`ClutterDensity::Function`]).
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] naming `clutter.density` if a per-report list does not
    /// have `count` entries; [`Error::Unsupported`] for a function with region reports;
    /// [`Error::InvalidParameter`] naming `clutter.density[i]` if a function returns a
    /// negative or non-finite value.
    pub(crate) fn intensities<'a>(
        &self,
        count: usize,
        measurement: impl Fn(usize) -> Option<&'a [f64]>,
    ) -> Result<Vec<f64>> {
        match &self.density {
            ClutterDensity::Constant(c) => Ok(alloc::vec![self.rate * c; count]),
            ClutterDensity::PerReport(v) => {
                if v.len() != count {
                    return Err(Error::dimension("clutter.density", count, v.len()));
                }
                Ok(v.iter().map(|c| self.rate * c).collect())
            }
            ClutterDensity::Function(f) => (0..count)
                .map(|i| {
                    let z = measurement(i).ok_or_else(|| Error::Unsupported {
                        what: "clutter.density".into(),
                        reason: "a clutter density function needs vector measurements; give one number per report",
                    })?;
                    let c = (f.0)(z);
                    if c.is_finite() && c >= 0.0 {
                        Ok(self.rate * c)
                    } else {
                        Err(Error::parameter(
                            alloc::format!("clutter.density[{i}]"),
                            c,
                            "finite and >= 0",
                        ))
                    }
                })
                .collect(),
        }
    }
}
