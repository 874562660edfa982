//! The multi-Bernoulli estimators' inputs as data (`003_…`, Section III): the existence
//! probabilities, the metric and its parameters (with their defaults) of the optimal estimate
//! (9)/(11) and of its mean error (Lemma 4), and the classical estimators of Fig. 2.

use alloc::vec;
use alloc::vec::Vec;

use super::alternatives::{AlternativeMethod, alternative_estimate};
#[cfg(any(test, feature = "serde"))]
use super::figures::default_cutoff;
use super::multi_bernoulli::{MbEstimate, SetMetric, mean_error, optimal_estimate};
use crate::error::Result;
#[cfg(any(test, feature = "serde"))]
use crate::metrics::{default_alpha, default_order};

/// A set metric of Section III, by name (GOSPA's α is given beside it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum SetMetricName {
    /// `gospa`: GOSPA with the given `alpha`.
    Gospa,
    /// `ospa`: OSPA.
    Ospa,
    /// `uospa`: UOSPA (GOSPA with α = 1).
    Uospa,
}

impl SetMetricName {
    /// The metric, GOSPA with `alpha` (ignored by OSPA and UOSPA).
    pub fn with_alpha(self, alpha: f64) -> SetMetric {
        match self {
            SetMetricName::Gospa => SetMetric::Gospa { alpha },
            SetMetricName::Ospa => SetMetric::Ospa,
            SetMetricName::Uospa => SetMetric::Uospa,
        }
    }
}

/// The optimal estimate of far-apart components, [`optimal_estimate`]: which of n
/// multi-Bernoulli components with Dirac densities to report, given their existence
/// probabilities alone, minimising E[d^p] under a set metric (García-Fernández & Svensson,
/// "Spooky effect in optimal OSPA estimation and how GOSPA solves it", Section III). Not
/// `multiBernoulliPointEstimate` (Narykov, Üney & Ralph's Bernoulli estimate applied to each
/// component with its Gaussian density and the loss (7)).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MbOptimalEstimateOptions {
    /// Existence probability r_i in [0, 1] of each far-apart component. Any number for GOSPA
    /// with α = 2; at most 4,000 for OSPA and 20,000 for UOSPA and other α (the cost is
    /// O(n² log n) and O(n²)).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::numbers"))]
    pub existence: Vec<f64>,
    /// The metric whose mean error is minimised.
    pub metric: SetMetricName,
    /// The metric's cut-off c > 0, in the units of the states (default 1).
    #[cfg_attr(feature = "serde", serde(default = "default_cutoff"))]
    pub c: f64,
    /// GOSPA's α in (0, 2] (default 2; ignored by OSPA and UOSPA).
    #[cfg_attr(feature = "serde", serde(default = "default_alpha"))]
    pub alpha: f64,
    /// Order p ≥ 1 (default 2). The error minimised is E[d^p], the mean square error for
    /// p = 2.
    #[cfg_attr(feature = "serde", serde(default = "default_order"))]
    pub p: f64,
}

impl MbOptimalEstimateOptions {
    /// [`optimal_estimate`] of these options.
    ///
    /// # Errors
    /// As [`optimal_estimate`].
    pub fn estimate(&self) -> Result<MbEstimate> {
        let metric = self.metric.with_alpha(self.alpha);
        optimal_estimate(&self.existence, metric, self.c, self.p)
    }
}

/// The mean error E[d^p] of a given estimate, [`mean_error`] (Lemma 4): the mean of the
/// metric's p-th power, not rooted; the mean square error for p = 2, the default, and E[d^p]
/// for any other p (the JavaScript name `mbMeanSquareError` says the usual case).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MbMeanSquareErrorOptions {
    /// The estimate: `report[i]` says whether component i is reported (one per component).
    pub report: Vec<bool>,
    /// Existence probability r_i in [0, 1] of each far-apart component. Any number for GOSPA
    /// with α = 2; at most 20,000 for the other metrics (the cost is O(n²)).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::numbers"))]
    pub existence: Vec<f64>,
    /// The set metric whose mean error E[d^p] is computed.
    pub metric: SetMetricName,
    /// GOSPA's cardinality-mismatch weight α ∈ (0, 2] (default 2).
    #[cfg_attr(feature = "serde", serde(default = "default_alpha"))]
    pub alpha: f64,
    /// The metric's order p ≥ 1 (default 2).
    #[cfg_attr(feature = "serde", serde(default = "default_order"))]
    pub p: f64,
    /// The metric's cut-off c > 0, in the units of the states (default 1).
    #[cfg_attr(feature = "serde", serde(default = "default_cutoff"))]
    pub c: f64,
}

impl MbMeanSquareErrorOptions {
    /// [`mean_error`] of `report`: E[d^p], the mean square error for p = 2.
    ///
    /// # Errors
    /// As [`mean_error`].
    pub fn mean_error(&self) -> Result<f64> {
        let metric = self.metric.with_alpha(self.alpha);
        mean_error(&self.existence, &self.report, metric, self.c, self.p)
    }
}

/// A classical estimator of Fig. 2 of García-Fernández & Svensson, "Spooky effect in optimal OSPA
/// estimation and how GOSPA solves it" (paper 003), [`alternative_estimate`].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MbAlternativeEstimateOptions {
    /// Existence probability r_i in [0, 1] of each component. At most 20,000 for `mam` and
    /// `map-cardinality` (the cardinality pmf costs O(n²)); any number for `jom`.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::numbers"))]
    pub existence: Vec<f64>,
    /// The classical estimator: `mam`, `jom` or `map-cardinality`.
    pub method: AlternativeMethod,
    /// `ln_peak[i]` = −½ ln det(2π P_i) of component i's Gaussian (default 0 for all: equal
    /// covariances); one per component.
    #[cfg_attr(
        feature = "serde",
        serde(default, with = "crate::serde_shapes::numbers")
    )]
    pub ln_peak: Option<Vec<f64>>,
    /// ln of JoM's constant (default 0, i.e. c = (2πε)^(d/2) for P = εI).
    #[cfg_attr(feature = "serde", serde(default))]
    pub ln_c: f64,
}

/// The estimate of a classical estimator ([`MbAlternativeEstimateOptions::estimate`]).
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct AlternativeEstimate {
    /// `report[i]`: whether component i is reported.
    pub report: Vec<bool>,
}

impl MbAlternativeEstimateOptions {
    /// [`alternative_estimate`] of these options (`ln_peak` omitted: all 0).
    ///
    /// # Errors
    /// As [`alternative_estimate`].
    pub fn estimate(&self) -> Result<AlternativeEstimate> {
        let zeros;
        let ln_peak = match &self.ln_peak {
            Some(v) => v.as_slice(),
            None => {
                zeros = vec![0.0; self.existence.len()];
                zeros.as_slice()
            }
        };
        let report = alternative_estimate(&self.existence, self.method, ln_peak, self.ln_c)?;
        Ok(AlternativeEstimate { report })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lemma4_and_eq9_options_call_the_estimators() {
        let existence = vec![0.4, 0.9];
        let o = MbOptimalEstimateOptions {
            existence: existence.clone(),
            metric: SetMetricName::Ospa,
            c: default_cutoff(),
            p: default_order(),
            alpha: default_alpha(),
        };
        let e = o.estimate().unwrap();
        assert_eq!(
            e,
            optimal_estimate(&existence, SetMetric::Ospa, 1.0, 2.0).unwrap()
        );
        let m = MbMeanSquareErrorOptions {
            report: e.report.clone(),
            existence: existence.clone(),
            metric: SetMetricName::Gospa,
            alpha: 1.0,
            p: 2.0,
            c: 1.0,
        };
        let uospa = SetMetric::Gospa { alpha: 1.0 };
        let direct = mean_error(&existence, &e.report, uospa, 1.0, 2.0).unwrap();
        assert_eq!(m.mean_error().unwrap(), direct);
        let bad = MbOptimalEstimateOptions { c: -1.0, ..o };
        assert_eq!(bad.estimate().unwrap_err().field(), "c");
    }

    #[test]
    fn fig2_alternative_options_default_ln_peak_to_zero() {
        let mut o = MbAlternativeEstimateOptions {
            existence: vec![0.3, 0.6, 0.45],
            method: AlternativeMethod::Jom,
            ln_peak: None,
            ln_c: 0.2,
        };
        let zeros = alternative_estimate(&o.existence, o.method, &[0.0; 3], 0.2).unwrap();
        assert_eq!(o.estimate().unwrap().report, zeros);
        o.ln_peak = Some(vec![0.0, 1.0, -0.5]);
        let given = alternative_estimate(&o.existence, o.method, &[0.0, 1.0, -0.5], 0.2).unwrap();
        assert_eq!(o.estimate().unwrap().report, given);
    }
}
