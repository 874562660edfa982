//! The metrics' parameters as data: the options a caller gives to build a [`Gospa`] or an
//! [`Ospa`] (cut-off, order, α, with their defaults) and to evaluate a whole scenario
//! ([`Gospa::series`], [`Ospa::series`]) in one call.
//!
//! References: GOSPA and UOSPA, `003_…` (Def. 2, Prop. 3); OSPA, eqs. (24)–(26) of `004_…`.

use alloc::vec::Vec;

use super::{Gospa, GospaReport, GospaSeries, Ospa, OspaSeries};
use crate::error::Result;

/// The default order p of GOSPA and OSPA: 2.
pub const fn default_order() -> f64 {
    2.0
}

/// The default α of GOSPA: 2, the one α with a decomposition into localisation, missed and
/// false targets (Prop. 3 of `003_…`).
pub const fn default_alpha() -> f64 {
    2.0
}

/// The parameters of a [`Gospa`] metric: cut-off c, order p and cardinality-mismatch weight α.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GospaOptions {
    /// The cut-off c > 0, in the units of the points.
    pub c: f64,
    /// The order p ≥ 1 (finite; default 2).
    #[cfg_attr(feature = "serde", serde(default = "default_order"))]
    pub p: f64,
    /// α in (0, 2], the weight of cardinality mismatch (default 2; the decomposition into
    /// localisation, missed and false targets exists for α = 2 only).
    #[cfg_attr(feature = "serde", serde(default = "default_alpha"))]
    pub alpha: f64,
}

impl GospaOptions {
    /// The metric, [`Gospa::new`].
    ///
    /// # Errors
    /// As [`Gospa::new`] (fields `c`, `p`, `alpha`).
    pub fn metric(&self) -> Result<Gospa> {
        Gospa::new(self.c, self.p, self.alpha)
    }
}

/// The parameters of an [`Ospa`] metric, or of UOSPA ([`Gospa::uospa`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OspaOptions {
    /// The cut-off c > 0, in the units of the points.
    pub c: f64,
    /// The order p ≥ 1 (finite; default 2).
    #[cfg_attr(feature = "serde", serde(default = "default_order"))]
    pub p: f64,
}

impl OspaOptions {
    /// The metric, [`Ospa::new`].
    ///
    /// # Errors
    /// As [`Ospa::new`] (fields `c`, `p`).
    pub fn metric(&self) -> Result<Ospa> {
        Ospa::new(self.c, self.p)
    }

    /// UOSPA with these parameters, [`Gospa::uospa`].
    ///
    /// # Errors
    /// As [`Gospa::uospa`] (fields `c`, `p`).
    pub fn uospa(&self) -> Result<Gospa> {
        Gospa::uospa(self.c, self.p)
    }
}

/// A whole scenario for GOSPA: one truth set and one estimate set per time step, and the
/// metric's parameters.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GospaSeriesOptions {
    /// The truth at each step (arrays of points of one common dimension; empty sets allowed).
    /// At most 2^18 = 262,144 steps ([`crate::metrics::MAX_SERIES_STEPS`]) and 2^18 points
    /// over all steps of `truths` and `estimates` together
    /// ([`crate::metrics::MAX_SERIES_POINTS`]), and within each step the caps of one
    /// evaluation.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::point_sets"))]
    pub truths: Vec<Vec<Vec<f64>>>,
    /// The estimate at each step (as many steps as `truths`).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::point_sets"))]
    pub estimates: Vec<Vec<Vec<f64>>>,
    /// The cut-off c > 0, in the units of the points.
    pub c: f64,
    /// The order p ≥ 1 (finite; default 2).
    #[cfg_attr(feature = "serde", serde(default = "default_order"))]
    pub p: f64,
    /// α in (0, 2] (default 2; the decomposition exists for α = 2 only).
    #[cfg_attr(feature = "serde", serde(default = "default_alpha"))]
    pub alpha: f64,
}

impl GospaSeriesOptions {
    /// [`Gospa::series`] of `truths` against `estimates`.
    ///
    /// # Errors
    /// As [`Gospa::new`] and [`Gospa::series`].
    pub fn series(&self) -> Result<GospaSeries> {
        Gospa::new(self.c, self.p, self.alpha)?.series(&self.truths, &self.estimates)
    }
}

/// A whole scenario for OSPA: one truth set and one estimate set per time step, and the
/// metric's parameters.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OspaSeriesOptions {
    /// The cut-off c > 0, in the units of the points.
    pub c: f64,
    /// The order p ≥ 1 (finite; default 2).
    #[cfg_attr(feature = "serde", serde(default = "default_order"))]
    pub p: f64,
    /// The truth at each step. At most 2^18 = 262,144 steps
    /// ([`crate::metrics::MAX_SERIES_STEPS`]) and 2^18 points over all steps of `truths` and
    /// `estimates` together ([`crate::metrics::MAX_SERIES_POINTS`]).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::point_sets"))]
    pub truths: Vec<Vec<Vec<f64>>>,
    /// The estimate at each step (as many steps as `truths`).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::point_sets"))]
    pub estimates: Vec<Vec<Vec<f64>>>,
}

impl OspaSeriesOptions {
    /// [`Ospa::series`] of `truths` against `estimates`.
    ///
    /// # Errors
    /// As [`Ospa::new`] and [`Ospa::series`].
    pub fn series(&self) -> Result<OspaSeries> {
        Ospa::new(self.c, self.p)?.series(&self.truths, &self.estimates)
    }
}

impl Gospa {
    /// The distance between two point sets with, for α = 2, its decomposition
    /// ([`Gospa::decompose`]); other α give the distance alone ([`Gospa::distance`]).
    ///
    /// # Errors
    /// As [`Gospa::distance`] and [`Gospa::decompose`].
    pub fn report<P: AsRef<[f64]>>(&self, truth: &[P], estimate: &[P]) -> Result<GospaReport> {
        if self.alpha() != 2.0 {
            let distance = self.distance(truth, estimate)?;
            return Ok(GospaReport {
                distance,
                ..GospaReport::default()
            });
        }
        self.decompose(truth, estimate).map(GospaReport::from)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;

    #[test]
    fn prop3_report_decomposes_for_alpha_2_only() {
        let truth = [[0.0, 0.0], [10.0, 0.0]];
        let estimate = [[0.0, 1.0]];
        let two = GospaOptions {
            c: 2.0,
            p: default_order(),
            alpha: default_alpha(),
        };
        let r = two.metric().unwrap().report(&truth, &estimate).unwrap();
        let d = two.metric().unwrap().decompose(&truth, &estimate).unwrap();
        assert_eq!(r, GospaReport::from(d));
        assert_eq!((r.missed, r.false_targets), (Some(1), Some(0)));
        let one = GospaOptions { alpha: 1.0, ..two };
        let r = one.metric().unwrap().report(&truth, &estimate).unwrap();
        let distance = one.metric().unwrap().distance(&truth, &estimate).unwrap();
        assert_eq!(
            r,
            GospaReport {
                distance,
                ..GospaReport::default()
            }
        );
        let bad = GospaOptions { c: 0.0, ..two }.metric().unwrap_err();
        assert_eq!(bad.field(), "c");
    }

    #[test]
    fn def2_and_eq24_series_options_are_the_series_of_their_metric() {
        let truths = vec![vec![vec![0.0]], vec![]];
        let estimates = vec![vec![vec![0.5]], vec![vec![3.0]]];
        let o = GospaSeriesOptions {
            truths: truths.clone(),
            estimates: estimates.clone(),
            c: 1.0,
            p: 2.0,
            alpha: 2.0,
        };
        let g = Gospa::new(1.0, 2.0, 2.0).unwrap();
        assert_eq!(o.series().unwrap(), g.series(&truths, &estimates).unwrap());
        let o = OspaSeriesOptions {
            truths: truths.clone(),
            estimates: estimates.clone(),
            c: 1.0,
            p: 2.0,
        };
        let m = OspaOptions { c: 1.0, p: 2.0 }.metric().unwrap();
        assert_eq!(o.series().unwrap(), m.series(&truths, &estimates).unwrap());
        let short = OspaSeriesOptions {
            estimates: vec![],
            ..o
        };
        assert_eq!(short.series().unwrap_err().field(), "estimates");
        let u = OspaOptions { c: 1.0, p: 2.0 }.uospa().unwrap();
        assert_eq!(u.alpha(), 1.0);
    }
}
