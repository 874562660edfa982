//! GOSPA (and UOSPA, its α = 1 case).

use alloc::vec::Vec;

use super::base::{InUnitsOf, extreme_scale};
use super::{Euclidean, Metric, check_cutoff_order, cutoff_assignment};
use crate::error::{Error, Result};
use crate::math::fns;

/// The generalised OSPA metric `d_p^(c, α)` with cut-off `c > 0`, order `1 ≤ p < ∞` and
/// cardinality-mismatch weight `0 < α ≤ 2`.
///
/// For `|X| ≤ |Y|` (swap the arguments otherwise):
///
/// ```text
/// d_p^(c,α)(X, Y) = ( min_π Σ_{i=1}^{|X|} d^(c)(x_i, y_π(i))^p + (c^p / α) (|Y| − |X|) )^(1/p)
/// d^(c)(x, y) = min(d(x, y), c),   π over the permutations of {1 … |Y|}
/// ```
///
/// α = 1 gives UOSPA ([`Gospa::uospa`]). For α = 2 the metric is a minimum over partial
/// assignments γ (Prop. 3 of the spooky-effect paper),
///
/// ```text
/// d_p^(c,2)(X, Y) = ( min_γ Σ_{(i,j)∈γ} d(x_i, y_j)^p + (c^p / 2) (|X| + |Y| − 2|γ|) )^(1/p)
/// ```
///
/// which [`Gospa::decompose`] reports as the localisation cost, the missed targets (unassigned
/// truths) and the false targets (unassigned estimates). The optimal γ never assigns a pair
/// with `d ≥ c`. Two empty sets are at distance 0.
///
/// Every α is computed exactly from the pairs closer than c only: the minimisation over π is
/// the same for all α (α only weights the constant `|Y| − |X|`), and it equals
/// `c^p |X| + min_γ Σ_γ (d^p − c^p)` over partial assignments γ of pairs with `d < c` — the
/// α = 2 form above, up to constants. For Euclidean points those pairs come from a uniform
/// grid, without the `|X|·|Y|` distances. Only the *reading* of γ as missed and false targets
/// is particular to α = 2, so [`Gospa::decompose`] needs α = 2 and [`Gospa::distance`] takes
/// any α. Whole scenarios: [`Gospa::series`].
///
/// # References
/// - A. S. Rahmathullah, Á. F. García-Fernández, L. Svensson, "Generalized optimal sub-pattern
///   assignment metric," Proc. 20th Int. Conf. Information Fusion, 2017 — Def. 1, Prop. 1.
/// - Á. F. García-Fernández, L. Svensson, "Spooky effect in optimal OSPA estimation and how
///   GOSPA solves it," Proc. 22nd Int. Conf. Information Fusion, 2019 — Def. 2, Prop. 3 (eq. 1);
///   `003_…` in `shared/papers`, equations restated in its NOTES.md.
///
/// # Examples
/// ```
/// use fisst::metrics::Gospa;
/// let g = Gospa::new(2.0, 2.0, 2.0).unwrap();
/// let truth = [[0.0, 0.0], [10.0, 0.0]];
/// let estimate = [[0.0, 1.0]];
/// let d = g.decompose(&truth, &estimate).unwrap();
/// assert_eq!((d.localisation, d.missed, d.false_targets), (1.0, 1, 0));
/// // d² = 1 + (2²/2)·1
/// assert!((d.distance - 3f64.sqrt()).abs() < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gospa {
    c: f64,
    p: f64,
    alpha: f64,
}

/// GOSPA (α = 2) split into its parts (Prop. 3 of García-Fernández & Svensson, "Spooky effect in
/// optimal OSPA estimation and how GOSPA solves it", paper 003).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GospaDecomposition {
    /// The GOSPA distance, `(localisation + c^p/2 · (missed + false_targets))^(1/p)`.
    pub distance: f64,
    /// The localisation cost Σ d(x_i, y_j)^p over the assigned pairs: a sum of p-th powers,
    /// not rooted, not normalised (so `distance^p = localisation + c^p/2 · (missed +
    /// false_targets)`), unlike OSPA's rooted, normalised `OspaDecomposition::localisation`.
    pub localisation: f64,
    /// The number of missed targets: truth points left unassigned.
    pub missed: usize,
    /// The number of false targets: estimate points left unassigned.
    pub false_targets: usize,
    /// The assigned `(truth index, estimate index)` pairs, sorted by truth index; every pair
    /// has `d < c`.
    pub assignment: Vec<(usize, usize)>,
}

/// GOSPA between two point sets with, for α = 2, its decomposition (Prop. 3 of
/// García-Fernández & Svensson, "Spooky effect in optimal OSPA estimation and how GOSPA solves it",
/// paper 003) ([`Gospa::report`]). For α ≠ 2 only `distance` is set
/// (the decomposition into localisation, missed and false targets exists for α = 2 only).
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GospaReport {
    /// The GOSPA distance, ≥ 0, in the units of the points.
    pub distance: f64,
    /// The localisation cost Σ d^p over the assigned pairs: a sum of p-th powers, not rooted,
    /// not normalised, so `distance^p = localisation + c^p/2 · (missed + falseTargets)`
    /// (unlike `ospa`'s `localisation`, a rooted, normalised part). α = 2 only.
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub localisation: Option<f64>,
    /// The number of missed targets: unassigned truth points (α = 2 only).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub missed: Option<usize>,
    /// The number of false targets: unassigned estimate points (α = 2 only).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub false_targets: Option<usize>,
    /// `(truth index, estimate index)` pairs of the optimal assignment (α = 2 only).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub assignment: Option<Vec<(usize, usize)>>,
}

impl From<GospaDecomposition> for GospaReport {
    fn from(d: GospaDecomposition) -> Self {
        Self {
            distance: d.distance,
            localisation: Some(d.localisation),
            missed: Some(d.missed),
            false_targets: Some(d.false_targets),
            assignment: Some(d.assignment),
        }
    }
}

impl Gospa {
    /// GOSPA with cut-off `c`, order `p` and `alpha`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `c` (must be finite and > 0), `p` (finite, ≥ 1) or
    /// `alpha` (in (0, 2]).
    pub fn new(c: f64, p: f64, alpha: f64) -> Result<Self> {
        check_cutoff_order(c, p)?;
        if !(alpha > 0.0 && alpha <= 2.0) {
            return Err(Error::parameter("alpha", alpha, "in (0, 2]"));
        }
        Ok(Self { c, p, alpha })
    }

    /// UOSPA, the unnormalised OSPA: GOSPA with α = 1.
    ///
    /// # Errors
    /// As [`Gospa::new`].
    pub fn uospa(c: f64, p: f64) -> Result<Self> {
        Self::new(c, p, 1.0)
    }

    /// The cut-off c.
    pub fn cutoff(&self) -> f64 {
        self.c
    }

    /// The order p.
    pub fn order(&self) -> f64 {
        self.p
    }

    /// The cardinality-mismatch weight α.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// The GOSPA distance between point sets under the Euclidean distance.
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] naming `truth[i]` or `estimate[j]` for ragged points,
    /// [`Error::InvalidParameter`] for a non-finite coordinate.
    pub fn distance<P: AsRef<[f64]>>(&self, truth: &[P], estimate: &[P]) -> Result<f64> {
        self.distance_with(truth, estimate, &Euclidean)
    }

    /// The GOSPA distance under a user-supplied single-object distance.
    ///
    /// # Errors
    /// The metric's validation errors, or [`Error::InvalidParameter`] if it returns NaN or a
    /// negative value.
    pub fn distance_with<T, M: Metric<T> + ?Sized>(
        &self,
        truth: &[T],
        estimate: &[T],
        metric: &M,
    ) -> Result<f64> {
        if extreme_scale(self.c, self.p) {
            let unit = Gospa { c: 1.0, ..*self };
            let scaled = InUnitsOf { metric, c: self.c };
            return Ok(self.c * unit.distance_in_units(truth, estimate, &scaled)?);
        }
        self.distance_in_units(truth, estimate, metric)
    }

    /// [`Gospa::distance_with`] in the units of the points (c^p representable).
    fn distance_in_units<T, M: Metric<T> + ?Sized>(
        &self,
        truth: &[T],
        estimate: &[T],
        metric: &M,
    ) -> Result<f64> {
        let a = cutoff_assignment(truth, estimate, metric, self.c, self.p)?;
        let unmatched = truth.len().abs_diff(estimate.len());
        // No unmatched points, no term: c^p/α overflows for a tiny α and ∞·0 would be NaN.
        let total = if unmatched == 0 {
            a.total
        } else {
            a.total + fns::powp(self.c, self.p) / self.alpha * unmatched as f64
        };
        if total.is_finite() {
            return Ok(fns::rootp(total, self.p));
        }
        // c^p/α overflowed (α near the smallest double; c^p itself is representable here):
        // the same sum times α, `(α Σ d^p + c^p |unmatched|)^(1/p) / α^(1/p)`, which is finite
        // whenever the distance is (α Σ d^p is then far below c^p's rounding).
        let times_alpha = a.total * self.alpha + fns::powp(self.c, self.p) * unmatched as f64;
        Ok(fns::rootp(times_alpha, self.p) / fns::rootp(self.alpha, self.p))
    }

    /// The α = 2 decomposition under the Euclidean distance.
    ///
    /// # Errors
    /// [`Error::Unsupported`] naming `alpha` unless α = 2, and the errors of
    /// [`Gospa::distance`].
    pub fn decompose<P: AsRef<[f64]>>(
        &self,
        truth: &[P],
        estimate: &[P],
    ) -> Result<GospaDecomposition> {
        self.decompose_with(truth, estimate, &Euclidean)
    }

    /// The α = 2 decomposition under a user-supplied single-object distance.
    ///
    /// # Errors
    /// As [`Gospa::decompose`] and [`Gospa::distance_with`].
    pub fn decompose_with<T, M: Metric<T> + ?Sized>(
        &self,
        truth: &[T],
        estimate: &[T],
        metric: &M,
    ) -> Result<GospaDecomposition> {
        if self.alpha != 2.0 {
            return Err(Error::Unsupported {
                what: "alpha".into(),
                reason: "the GOSPA decomposition into localisation, missed and false targets \
                         exists only for alpha = 2",
            });
        }
        if extreme_scale(self.c, self.p) {
            let unit = Gospa { c: 1.0, ..*self };
            let scaled = InUnitsOf { metric, c: self.c };
            let d = unit.decompose_in_units(truth, estimate, &scaled)?;
            return Ok(GospaDecomposition {
                distance: self.c * d.distance,
                localisation: scale_power(d.localisation, self.c, self.p),
                ..d
            });
        }
        self.decompose_in_units(truth, estimate, metric)
    }

    /// [`Gospa::decompose_with`] in the units of the points (c^p representable).
    fn decompose_in_units<T, M: Metric<T> + ?Sized>(
        &self,
        truth: &[T],
        estimate: &[T],
        metric: &M,
    ) -> Result<GospaDecomposition> {
        let a = cutoff_assignment(truth, estimate, metric, self.c, self.p)?;
        // Pairs at d ≥ c cost c^p assigned or c^p/2 + c^p/2 unassigned: Prop. 3's optimal γ
        // leaves them unassigned.
        let kept: Vec<_> = a.pairs.iter().filter(|q| q.close).collect();
        let localisation = crate::math::sum::sum(kept.iter().map(|q| q.cost));
        let missed = truth.len() - kept.len();
        let false_targets = estimate.len() - kept.len();
        let penalty = fns::powp(self.c, self.p) / 2.0 * (missed + false_targets) as f64;
        Ok(GospaDecomposition {
            distance: fns::rootp(localisation + penalty, self.p),
            localisation,
            missed,
            false_targets,
            assignment: kept.iter().map(|q| (q.truth, q.estimate)).collect(),
        })
    }
}

/// x·c^p for x ≥ 0 given in units of c^p, as (c·x^(1/p))^p so that it is finite whenever the
/// result is (c^p alone may overflow).
fn scale_power(x: f64, c: f64, p: f64) -> f64 {
    fns::powp(c * fns::rootp(x, p), p)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::test_util::{brute_force_cut_sum, point_sets, powp};
    use alloc::vec;
    use rand::{SeedableRng, rngs::SmallRng};

    fn brute_gospa(x: &[Vec<f64>], y: &[Vec<f64>], c: f64, p: f64, alpha: f64) -> f64 {
        let s = brute_force_cut_sum(x, y, c, p);
        let extra = x.len().abs_diff(y.len()) as f64;
        fns::rootp(s + powp(c, p) / alpha * extra, p)
    }

    /// Minimum over all partial assignments γ, enumerated: the α = 2 form of Prop. 3.
    fn brute_partial(x: &[Vec<f64>], y: &[Vec<f64>], c: f64, p: f64) -> f64 {
        fn rec(x: &[Vec<f64>], y: &[Vec<f64>], i: usize, used: &mut [bool], c: f64, p: f64) -> f64 {
            if i == x.len() {
                let unassigned_y = used.iter().filter(|u| !**u).count();
                return powp(c, p) / 2.0 * unassigned_y as f64;
            }
            // leave x_i unassigned
            let mut best = powp(c, p) / 2.0 + rec(x, y, i + 1, used, c, p);
            for j in 0..y.len() {
                if !used[j] {
                    used[j] = true;
                    let d = Euclidean.distance(&x[i], &y[j]);
                    best = best.min(powp(d, p) + rec(x, y, i + 1, used, c, p));
                    used[j] = false;
                }
            }
            best
        }
        let mut used = vec![false; y.len()];
        fns::rootp(rec(x, y, 0, &mut used, c, p), p)
    }

    #[test]
    fn matches_brute_force_and_prop3() {
        let mut rng = SmallRng::seed_from_u64(11);
        for t in 0..400 {
            let (x, y) = point_sets(&mut rng, 6, 6, 2);
            let c = [0.5, 2.0, 5.0][t % 3];
            let p = [1.0, 2.0, 3.5][(t / 3) % 3];
            for alpha in [0.5, 1.0, 2.0] {
                let g = Gospa::new(c, p, alpha).unwrap();
                let fast = g.distance(&x, &y).unwrap();
                let slow = brute_gospa(&x, &y, c, p, alpha);
                assert!((fast - slow).abs() <= 1e-12 * (1.0 + slow), "{x:?} {y:?}");
            }
            let g = Gospa::new(c, p, 2.0).unwrap();
            let d = g.decompose(&x, &y).unwrap();
            let partial = brute_partial(&x, &y, c, p);
            assert!((d.distance - partial).abs() <= 1e-12 * (1.0 + partial));
            let recomposed =
                d.localisation + powp(c, p) / 2.0 * (d.missed + d.false_targets) as f64;
            assert!((fns::rootp(recomposed, p) - d.distance).abs() <= 1e-12);
            for &(i, j) in &d.assignment {
                assert!(Euclidean.distance(&x[i], &y[j]) < c);
            }
            assert_eq!(x.len() - d.assignment.len(), d.missed);
            assert_eq!(y.len() - d.assignment.len(), d.false_targets);
        }
    }

    #[test]
    fn is_a_metric() {
        let mut rng = SmallRng::seed_from_u64(5);
        for t in 0..300 {
            let (x, y) = point_sets(&mut rng, 5, 5, 2);
            let (z, _) = point_sets(&mut rng, 5, 0, 2);
            let (c, p, alpha) = (
                [1.0, 3.0][t % 2],
                [1.0, 2.0, 4.0][t % 3],
                [0.3, 1.0, 2.0][t % 3],
            );
            let g = Gospa::new(c, p, alpha).unwrap();
            let dxy = g.distance(&x, &y).unwrap();
            assert!(dxy >= 0.0);
            assert_eq!(g.distance(&x, &x).unwrap(), 0.0);
            assert!((dxy - g.distance(&y, &x).unwrap()).abs() <= 1e-12);
            let dxz = g.distance(&x, &z).unwrap();
            let dyz = g.distance(&y, &z).unwrap();
            assert!(dxz <= dxy + dyz + 1e-9, "triangle: {dxz} > {dxy} + {dyz}");
        }
    }

    #[test]
    fn empty_sets() {
        let g = Gospa::new(3.0, 2.0, 2.0).unwrap();
        let empty: [[f64; 2]; 0] = [];
        assert_eq!(g.distance(&empty, &empty).unwrap(), 0.0);
        let d = g.decompose(&empty, &empty).unwrap();
        assert_eq!((d.distance, d.missed, d.false_targets), (0.0, 0, 0));
        // three missed targets: (3 · 9/2)^(1/2)
        let x = [[0.0, 0.0], [1.0, 1.0], [5.0, 5.0]];
        let d = g.decompose(&x, &empty).unwrap();
        assert_eq!((d.missed, d.false_targets), (3, 0));
        assert!((d.distance - (13.5f64).sqrt()).abs() < 1e-15);
        let u = Gospa::uospa(3.0, 1.0).unwrap();
        assert_eq!(u.distance(&empty, &x).unwrap(), 9.0);
    }

    #[test]
    fn assignment_minimises_the_p_th_powers_not_the_distances() {
        // Stone Soup minimises Σ d^(c) and raises to p afterwards. Over random sets, the right
        // assignment is never worse, and some instances show it strictly better.
        let g = Gospa::new(100.0, 2.0, 2.0).unwrap();
        let mut rng = SmallRng::seed_from_u64(3);
        let mut strictly_better = 0;
        for _ in 0..2000 {
            let (x, y) = point_sets(&mut rng, 4, 4, 2);
            let wrong = stone_soup_style(&x, &y, 100.0, 2.0);
            let right = g.decompose(&x, &y).unwrap().localisation;
            assert!(right <= wrong + 1e-12);
            if right < wrong - 1e-9 {
                strictly_better += 1;
            }
        }
        assert!(
            strictly_better > 0,
            "no instance where argmin Σd ≠ argmin Σd²"
        );
    }

    /// Σ d^p at the assignment minimising Σ d (raise to p afterwards).
    fn stone_soup_style(x: &[Vec<f64>], y: &[Vec<f64>], c: f64, p: f64) -> f64 {
        let n = x.len();
        let cost: Vec<f64> = x
            .iter()
            .flat_map(|a| y.iter().map(|b| Euclidean.distance(a, b).min(c)))
            .collect();
        let a = crate::math::linear_assignment(&cost, n, y.len()).unwrap();
        a.pairs
            .iter()
            .map(|&(i, j)| powp(cost[i * y.len() + j], p))
            .sum()
    }

    #[test]
    fn rejects_bad_parameters_and_points() {
        for (c, p, alpha, field) in [
            (0.0, 2.0, 2.0, "c"),
            (-1.0, 2.0, 2.0, "c"),
            (f64::NAN, 2.0, 2.0, "c"),
            (f64::INFINITY, 2.0, 2.0, "c"),
            (1.0, 0.5, 2.0, "p"),
            (1.0, f64::INFINITY, 2.0, "p"),
            (1.0, 2.0, 0.0, "alpha"),
            (1.0, 2.0, 2.5, "alpha"),
            (1.0, 2.0, f64::NAN, "alpha"),
        ] {
            assert_eq!(Gospa::new(c, p, alpha).unwrap_err().field(), field);
        }
        let g = Gospa::new(1.0, 2.0, 2.0).unwrap();
        let x = vec![vec![0.0, 0.0], vec![1.0]];
        let y = vec![vec![0.0, 0.0]];
        assert_eq!(g.distance(&x, &y).unwrap_err().field(), "truth[1]");
        let y = vec![vec![0.0, f64::NAN]];
        assert_eq!(g.distance(&y, &y).unwrap_err().field(), "truth[0][1]");
        let ok = vec![vec![0.0, 0.0]];
        let e = Gospa::new(1.0, 2.0, 1.0)
            .unwrap()
            .decompose(&ok, &ok)
            .unwrap_err();
        assert!(matches!(e, Error::Unsupported { .. }), "{e}");
        assert_eq!(e.field(), "alpha");
        let neg = crate::metrics::FnMetric(|_: &f64, _: &f64| -1.0);
        let e = g.distance_with(&[1.0], &[2.0], &neg).unwrap_err();
        assert_eq!(e.field(), "distance(truth[0], estimate[0])");
    }
}
