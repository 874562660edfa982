//! OSPA with its localisation and cardinality parts.

use alloc::vec::Vec;

use super::base::{InUnitsOf, extreme_scale};
use super::{Euclidean, Metric, check_cutoff_order, cutoff_assignment};
use crate::error::Result;
use crate::math::fns;

/// The OSPA metric `d̄_{c,p}` with cut-off `c > 0` and order `1 ≤ p < ∞`.
///
/// For `X = {x_1 … x_m}`, `Y = {y_1 … y_n}` with `m ≤ n` (swap otherwise), `n > 0`:
///
/// ```text
/// d̄_{c,p}(X, Y)    = ( (1/n) ( min_π Σ_{i=1}^m d_c(x_i, y_π(i))^p + c^p (n − m) ) )^(1/p)   (24)
/// e^card_{c,p}(X, Y) = ( c^p (n − m) / n )^(1/p)                                             (25)
/// e^loc_{c,p}(X, Y)  = ( (1/n) min_π Σ_{i=1}^m d_c(x_i, y_π(i))^p )^(1/p)                    (26)
/// ```
///
/// with `d_c(x, y) = min(c, d(x, y))`, and `d̄ = 0` when both sets are empty. The parts satisfy
/// `d̄^p = (e^loc)^p + (e^card)^p`, and `0 ≤ d̄ ≤ c`.
///
/// The minimum over π is computed exactly from the pairs closer than c only (pairs at
/// `d ≥ c` all cost `c^p`; see [`crate::metrics::Gospa`]), found for Euclidean points with a
/// uniform grid. Whole scenarios: [`Ospa::series`].
///
/// # References
/// - D. Schuhmacher, B.-T. Vo, B.-N. Vo, "A consistent metric for performance evaluation of
///   multi-object filters," IEEE Trans. Signal Process. 56(8):3447–3457, 2008.
///   doi:10.1109/TSP.2008.920469
/// - B. Ristic, B.-N. Vo, "Sensor control for multi-object state-space estimation using random
///   finite sets," Automatica 46(11):1812–1818, 2010 — eqs. (24)–(26) (`004_…`).
///
/// # Examples
/// ```
/// use fisst::metrics::Ospa;
/// let o = Ospa::new(10.0, 1.0).unwrap();
/// let d = o.decompose(&[[0.0], [5.0]], &[[1.0]]).unwrap();
/// // (1 + 10)/2 = 5.5, split into 1/2 and 10/2
/// assert_eq!((d.distance, d.localisation, d.cardinality), (5.5, 0.5, 5.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ospa {
    c: f64,
    p: f64,
}

/// OSPA split into its localisation and cardinality parts, eqs. (24)–(26) of Ristic & Vo, "Sensor
/// control for multi-object state-space estimation using random finite sets" (paper 004).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OspaDecomposition {
    /// The OSPA distance d̄_{c,p}(X, Y), eq. (24), in [0, c].
    pub distance: f64,
    /// The localisation part e^loc_{c,p}, eq. (26): rooted and normalised,
    /// `((1/n) Σ min(d, c)^p)^(1/p)` over the optimal pairs (n the larger set's size), so
    /// `distance^p = localisation^p + cardinality^p`; not GOSPA's `localisation`, which is
    /// the sum Σ d^p itself.
    pub localisation: f64,
    /// The cardinality part e^card_{c,p}, eq. (25) (rooted), in [0, c].
    pub cardinality: f64,
    /// The optimal permutation's `(truth index, estimate index)` pairs: all of the smaller
    /// set, sorted by truth index (cut-off pairs included).
    pub assignment: Vec<(usize, usize)>,
}

impl Ospa {
    /// OSPA with cut-off `c` and order `p`.
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] naming `c` (finite, > 0) or `p` (finite, ≥ 1).
    pub fn new(c: f64, p: f64) -> Result<Self> {
        check_cutoff_order(c, p)?;
        Ok(Self { c, p })
    }

    /// The cut-off c of eqs. (24)–(26).
    pub fn cutoff(&self) -> f64 {
        self.c
    }

    /// The order p of eqs. (24)–(26).
    pub fn order(&self) -> f64 {
        self.p
    }

    /// The OSPA distance under the Euclidean distance.
    ///
    /// # Errors
    /// As [`crate::metrics::Gospa::distance`].
    pub fn distance<P: AsRef<[f64]>>(&self, truth: &[P], estimate: &[P]) -> Result<f64> {
        Ok(self.decompose(truth, estimate)?.distance)
    }

    /// The OSPA distance under a user-supplied single-object distance.
    ///
    /// # Errors
    /// As [`crate::metrics::Gospa::distance_with`].
    pub fn distance_with<T, M>(&self, truth: &[T], estimate: &[T], metric: &M) -> Result<f64>
    where
        M: Metric<T> + ?Sized,
    {
        Ok(self.decompose_with(truth, estimate, metric)?.distance)
    }

    /// OSPA and its parts under the Euclidean distance.
    ///
    /// # Errors
    /// As [`Ospa::distance`].
    pub fn decompose<P: AsRef<[f64]>>(
        &self,
        truth: &[P],
        estimate: &[P],
    ) -> Result<OspaDecomposition> {
        self.decompose_with(truth, estimate, &Euclidean)
    }

    /// OSPA and its parts under a user-supplied single-object distance.
    ///
    /// # Errors
    /// As [`Ospa::distance_with`].
    pub fn decompose_with<T, M>(
        &self,
        truth: &[T],
        estimate: &[T],
        metric: &M,
    ) -> Result<OspaDecomposition>
    where
        M: Metric<T> + ?Sized,
    {
        if extreme_scale(self.c, self.p) {
            let unit = Ospa { c: 1.0, ..*self };
            let d = unit.decompose_in_units(truth, estimate, &InUnitsOf { metric, c: self.c })?;
            return Ok(d.times(self.c));
        }
        self.decompose_in_units(truth, estimate, metric)
    }

    /// [`Ospa::decompose_with`] in the units of the points (c^p representable): eqs.
    /// (24)–(26) with X = `x` the truth and Y = `y` the estimate.
    fn decompose_in_units<T, M: Metric<T> + ?Sized>(
        &self,
        x: &[T],
        y: &[T],
        metric: &M,
    ) -> Result<OspaDecomposition> {
        let a = cutoff_assignment(x, y, metric, self.c, self.p)?;
        let n = x.len().max(y.len());
        if n == 0 {
            return Ok(OspaDecomposition {
                distance: 0.0,
                localisation: 0.0,
                cardinality: 0.0,
                assignment: Vec::new(),
            });
        }
        let nf = n as f64;
        let loc = a.total / nf;
        let card = fns::powp(self.c, self.p) * x.len().abs_diff(y.len()) as f64 / nf;
        Ok(OspaDecomposition {
            distance: fns::rootp(loc + card, self.p),
            localisation: fns::rootp(loc, self.p),
            cardinality: fns::rootp(card, self.p),
            assignment: a.pairs.iter().map(|q| (q.truth, q.estimate)).collect(),
        })
    }
}

impl OspaDecomposition {
    /// The decomposition of distances given in units of `c`, in the units of the points
    /// (every part is rooted, so each scales by `c`).
    fn times(self, c: f64) -> Self {
        OspaDecomposition {
            distance: c * self.distance,
            localisation: c * self.localisation,
            cardinality: c * self.cardinality,
            ..self
        }
    }
}

#[cfg(test)]
mod tests {
    //! OSPA against brute-force enumeration of the permutations.
    use super::*;
    use crate::metrics::test_util::{brute_force_cut_sum, point_sets, powp};
    use rand::{SeedableRng, rngs::SmallRng};

    #[test]
    fn matches_brute_force_and_parts_add_up() {
        let mut rng = SmallRng::seed_from_u64(17);
        for t in 0..400 {
            let (x, y) = point_sets(&mut rng, 6, 6, 2);
            let (c, p) = ([0.5, 2.0, 5.0][t % 3], [1.0, 2.0, 3.0][(t / 3) % 3]);
            let o = Ospa::new(c, p).unwrap();
            let d = o.decompose(&x, &y).unwrap();
            let n = x.len().max(y.len());
            let expected = if n == 0 {
                0.0
            } else {
                let s = brute_force_cut_sum(&x, &y, c, p);
                fns::rootp(
                    (s + powp(c, p) * x.len().abs_diff(y.len()) as f64) / n as f64,
                    p,
                )
            };
            assert!((d.distance - expected).abs() <= 1e-12 * (1.0 + expected));
            let parts = powp(d.localisation, p) + powp(d.cardinality, p);
            assert!((parts - powp(d.distance, p)).abs() <= 1e-12 * (1.0 + parts));
            assert!(d.distance <= c * (1.0 + 1e-15), "OSPA ≤ c");
            assert_eq!(d.assignment.len(), x.len().min(y.len()));
        }
    }

    #[test]
    fn is_a_metric_bounded_by_c() {
        let mut rng = SmallRng::seed_from_u64(23);
        for t in 0..300 {
            let (x, y) = point_sets(&mut rng, 5, 5, 3);
            let (z, _) = point_sets(&mut rng, 5, 0, 3);
            let o = Ospa::new([1.0, 3.0][t % 2], [1.0, 2.0, 4.0][t % 3]).unwrap();
            let dxy = o.distance(&x, &y).unwrap();
            assert!((0.0..=o.cutoff()).contains(&dxy));
            assert_eq!(o.distance(&y, &y).unwrap(), 0.0);
            assert!((dxy - o.distance(&y, &x).unwrap()).abs() <= 1e-12);
            let (dxz, dyz) = (o.distance(&x, &z).unwrap(), o.distance(&y, &z).unwrap());
            assert!(dxz <= dxy + dyz + 1e-9);
        }
    }

    #[test]
    fn one_empty_set_is_at_distance_c() {
        let o = Ospa::new(7.0, 2.0).unwrap();
        let empty: [[f64; 1]; 0] = [];
        let d = o.decompose(&[[1.0], [2.0]], &empty).unwrap();
        assert_eq!((d.distance, d.localisation, d.cardinality), (7.0, 0.0, 7.0));
        assert_eq!(o.distance(&empty, &empty).unwrap(), 0.0);
    }
}
