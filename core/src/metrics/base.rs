//! Single-object distances d(x, y) on which the set metrics are built.

use crate::error::{Error, Result};
use crate::math::fns;

/// A distance between two single-object states: the `d` of OSPA and GOSPA.
///
/// It should be a metric (nonnegative, zero exactly on equal states, symmetric, triangle
/// inequality) for OSPA and GOSPA to be metrics. `+∞` is allowed (it is cut to `c`); NaN and
/// negative values are rejected by the set metrics.
pub trait Metric<T: ?Sized> {
    /// d(a, b).
    fn distance(&self, a: &T, b: &T) -> f64;

    /// Checks the inputs of a set metric before any distance is taken (e.g. that all points
    /// have one dimension), naming the offending `truth[i]` or `estimate[j]`. The default
    /// accepts everything.
    fn validate(&self, truth: &[T], estimate: &[T]) -> Result<()>
    where
        T: Sized,
    {
        let _ = (truth, estimate);
        Ok(())
    }
}

/// The Euclidean distance between points given as slices (`Vec<f64>`, `[f64; N]`, `&[f64]`).
///
/// Points of different lengths are an error ([`Error::DimensionMismatch`] naming
/// `estimate[j]`), never a silent truncation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Euclidean;

impl Euclidean {
    fn sq<P: AsRef<[f64]> + ?Sized>(a: &P, b: &P) -> f64 {
        a.as_ref()
            .iter()
            .zip(b.as_ref())
            .map(|(x, y)| (x - y) * (x - y))
            .sum::<f64>()
    }
}

impl<P: AsRef<[f64]> + ?Sized> Metric<P> for Euclidean {
    /// The Euclidean distance; NaN when the lengths differ ([`Metric::validate`] reports
    /// that case as an error before the set metrics take any distance).
    fn distance(&self, a: &P, b: &P) -> f64 {
        if a.as_ref().len() != b.as_ref().len() {
            return f64::NAN;
        }
        fns::sqrt(Self::sq(a, b))
    }

    fn validate(&self, truth: &[P], estimate: &[P]) -> Result<()>
    where
        P: Sized,
    {
        let Some(dim) = truth.first().or(estimate.first()).map(|p| p.as_ref().len()) else {
            return Ok(());
        };
        let named = |name: &'static str, pts: &[P]| -> Result<()> {
            for (i, pt) in pts.iter().enumerate() {
                let (len, pt) = (pt.as_ref().len(), pt.as_ref());
                if len != dim {
                    return Err(Error::dimension(alloc::format!("{name}[{i}]"), dim, len));
                }
                if let Some(k) = pt.iter().position(|v| !v.is_finite()) {
                    return Err(Error::parameter(
                        alloc::format!("{name}[{i}][{k}]"),
                        pt[k],
                        "finite",
                    ));
                }
            }
            Ok(())
        };
        named("truth", truth)?;
        named("estimate", estimate)
    }
}

/// Wraps a closure `|a, b| -> f64` as a [`Metric`].
///
/// ```
/// use fisst::metrics::{FnMetric, Gospa};
/// // distance on the circle of circumference 10
/// let circle = FnMetric(|a: &f64, b: &f64| { let d = (a - b).abs() % 10.0; d.min(10.0 - d) });
/// let g = Gospa::new(3.0, 1.0, 2.0).unwrap();
/// assert_eq!(g.distance_with(&[0.5], &[9.5], &circle).unwrap(), 1.0);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct FnMetric<F>(pub F);

impl<T: ?Sized, F: Fn(&T, &T) -> f64> Metric<T> for FnMetric<F> {
    fn distance(&self, a: &T, b: &T) -> f64 {
        (self.0)(a, b)
    }
}
