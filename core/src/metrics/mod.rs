//! Multi-object metrics: OSPA with its localisation and cardinality parts, UOSPA, and GOSPA
//! with its decomposition into localisation, missed and false targets.
//!
//! All of them are built on one computation ([`cutoff_assignment`]): the assignment that
//! minimises `Σ d^(c)(x_i, y_π(i))^p` with `d^(c) = min(d, c)` — the cut-off distance raised to
//! the order *before* the minimisation. (Minimising `Σ d` and raising afterwards, as Stone Soup
//! does, picks the wrong assignment whenever p ≠ 1.)

mod base;
mod gospa;
mod ospa;

pub use base::{Euclidean, FnMetric, Metric};
pub use gospa::{Gospa, GospaDecomposition};
pub use ospa::{Ospa, OspaDecomposition};

use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::math::{assignment, fns};

/// Validates a cut-off `c` (finite, > 0) and an order `p` (finite, ≥ 1).
pub(crate) fn check_cutoff_order(c: f64, p: f64) -> Result<()> {
    if !(c.is_finite() && c > 0.0) {
        return Err(Error::parameter("c", c, "finite and > 0"));
    }
    if !(p.is_finite() && p >= 1.0) {
        return Err(Error::parameter("p", p, "finite and >= 1"));
    }
    Ok(())
}

/// The optimal assignment of the cut-off costs `min(d(x, y), c)^p` between `x` and `y`.
///
/// Returns `(pairs, costs)`: the `min(|x|, |y|)` assigned `(i, j)` pairs (i indexes `x`, j
/// indexes `y`, sorted by i) and each pair's cut-off cost `min(d, c)^p` and raw distance `d`.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `distance(truth[i], estimate[j])` if the metric returns a
/// NaN or negative value, or the metric's own error (e.g. ragged points).
pub(crate) fn cutoff_assignment<T, M: Metric<T> + ?Sized>(
    x: &[T],
    y: &[T],
    metric: &M,
    c: f64,
    p: f64,
) -> Result<CutoffAssignment> {
    let (n, m) = (x.len(), y.len());
    let mut cost = Vec::with_capacity(n * m);
    let mut dist = Vec::with_capacity(n * m);
    metric.validate(x, y)?;
    let cp = fns::powp(c, p);
    for (i, xi) in x.iter().enumerate() {
        for (j, yj) in y.iter().enumerate() {
            let d = metric.distance(xi, yj);
            if d.is_nan() || d < 0.0 {
                return Err(Error::parameter(
                    alloc::format!("distance(truth[{i}], estimate[{j}])"),
                    d,
                    ">= 0 (a metric)",
                ));
            }
            cost.push(if d >= c { cp } else { fns::powp(d, p) });
            dist.push(d);
        }
    }
    let a = assignment::solve_unchecked(&cost, n, m);
    let pairs = a
        .pairs
        .into_iter()
        .map(|(i, j)| AssignedPair {
            truth: i,
            estimate: j,
            distance: dist[i * m + j],
            cost: cost[i * m + j],
        })
        .collect();
    Ok(CutoffAssignment {
        pairs,
        total: a.cost,
    })
}

/// An assigned pair and its distances.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct AssignedPair {
    pub truth: usize,
    pub estimate: usize,
    /// d(x, y), uncut.
    pub distance: f64,
    /// min(d, c)^p.
    pub cost: f64,
}

/// See [`cutoff_assignment`].
#[derive(Clone, Debug)]
pub(crate) struct CutoffAssignment {
    pub pairs: Vec<AssignedPair>,
    /// Σ min(d, c)^p over `pairs`.
    pub total: f64,
}

#[cfg(test)]
pub(crate) mod test_util {
    use super::{Euclidean, Metric};
    use alloc::vec;
    use alloc::vec::Vec;
    use rand::{Rng, RngExt};

    pub fn powp(x: f64, p: f64) -> f64 {
        crate::math::fns::powp(x, p)
    }

    /// Two random point sets of sizes 0..=n and 0..=m in `dim` dimensions, clustered so that
    /// cut-offs of 0.5 … 5 bite.
    pub fn point_sets<R: Rng>(
        rng: &mut R,
        n: usize,
        m: usize,
        dim: usize,
    ) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
        let nx = rng.random_range(0..=n);
        let ny = rng.random_range(0..=m);
        let mut pt = |_| (0..dim).map(|_| rng.random_range(0.0..4.0)).collect();
        (
            (0..nx).map(&mut pt).collect(),
            (0..ny).map(&mut pt).collect(),
        )
    }

    /// min over injective maps of the smaller set into the larger of Σ min(d, c)^p.
    pub fn brute_force_cut_sum(x: &[Vec<f64>], y: &[Vec<f64>], c: f64, p: f64) -> f64 {
        let (small, large) = if x.len() <= y.len() { (x, y) } else { (y, x) };
        fn rec(s: &[Vec<f64>], l: &[Vec<f64>], i: usize, used: &mut [bool], c: f64, p: f64) -> f64 {
            if i == s.len() {
                return 0.0;
            }
            let mut best = f64::INFINITY;
            for j in 0..l.len() {
                if !used[j] {
                    used[j] = true;
                    let d = Euclidean.distance(&s[i], &l[j]).min(c);
                    best = best.min(powp(d, p) + rec(s, l, i + 1, used, c, p));
                    used[j] = false;
                }
            }
            best
        }
        let mut used = vec![false; large.len()];
        rec(small, large, 0, &mut used, c, p)
    }
}
