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

    /// Coordinates on which the set metrics may search for the pairs closer than the cut-off
    /// with a uniform grid, instead of evaluating `d` on all `|X|·|Y|` pairs. The default,
    /// `None`, means "no such coordinates": every pair is evaluated (time `O(|X||Y|)`, memory
    /// still `O(|X| + |Y| + E)` for the `E` pairs closer than c).
    ///
    /// Contract when this returns `Some` for a point: every point gets coordinates of one
    /// common length, all finite, and for all points `a`, `b` and every coordinate `k`,
    /// `distance(a, b) ≥ (1 − 10⁻⁹)·|a_k − b_k|` as computed in `f64`. The Euclidean distance
    /// and every ℓ_q distance (q ≥ 1) on the same coordinates satisfy it. The grid then never
    /// misses a pair whose `distance` is below the cut-off, so the result is the same as with
    /// all pairs. [`Euclidean`] returns the point itself.
    fn grid_coordinates<'a>(&self, point: &'a T) -> Option<&'a [f64]> {
        let _ = point;
        None
    }
}

/// The Euclidean distance between points given as slices (`Vec<f64>`, `[f64; N]`, `&[f64]`).
///
/// Points of different lengths are an error ([`Error::DimensionMismatch`] naming
/// `estimate[j]`), never a silent truncation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Euclidean;

impl Euclidean {
    /// Σ (a_k − b_k)², summed left to right (unrolled for 1 to 3 dimensions: the same
    /// operations in the same order, so the same bits).
    #[inline]
    fn sq(a: &[f64], b: &[f64]) -> f64 {
        let d = |k: usize| (a[k] - b[k]) * (a[k] - b[k]);
        match (a.len(), b.len()) {
            (1, 1) => d(0),
            (2, 2) => d(0) + d(1),
            (3, 3) => d(0) + d(1) + d(2),
            _ => a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum::<f64>(),
        }
    }
}

impl<P: AsRef<[f64]> + ?Sized> Metric<P> for Euclidean {
    /// The Euclidean distance; NaN when the lengths differ ([`Metric::validate`] reports
    /// that case as an error before the set metrics take any distance).
    fn distance(&self, a: &P, b: &P) -> f64 {
        if a.as_ref().len() != b.as_ref().len() {
            return f64::NAN;
        }
        fns::sqrt(Self::sq(a.as_ref(), b.as_ref()))
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

    /// The point's coordinates: the set metrics find the pairs closer than c with a grid.
    fn grid_coordinates<'a>(&self, point: &'a P) -> Option<&'a [f64]> {
        Some(point.as_ref())
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

/// A metric in units of `c`: d(a, b) / c. The set metrics evaluate in these units when c^p
/// would overflow or underflow an `f64` (c = 1e300, p = 2), so that a huge or tiny cut-off
/// gives the right distance instead of `∞ · 0 = NaN` or a spurious 0. No grid: this path is
/// for extreme scales only. As on every path, the result is exact to rounding relative to c: a
/// distance whose p-th power underflows next to c^p counts as 0.
pub(crate) struct InUnitsOf<'m, M: ?Sized> {
    pub(crate) metric: &'m M,
    pub(crate) c: f64,
}

impl<T: ?Sized, M: Metric<T> + ?Sized> Metric<T> for InUnitsOf<'_, M> {
    fn distance(&self, a: &T, b: &T) -> f64 {
        self.metric.distance(a, b) / self.c
    }

    fn validate(&self, truth: &[T], estimate: &[T]) -> Result<()>
    where
        T: Sized,
    {
        self.metric.validate(truth, estimate)
    }
}

/// Whether c^p is too large or too small for the set metrics to work in the units of the
/// points (then they work in units of c, see [`InUnitsOf`]).
pub(crate) fn extreme_scale(c: f64, p: f64) -> bool {
    let cp = fns::powp(c, p);
    !(1e-280..=1e280).contains(&cp)
}
