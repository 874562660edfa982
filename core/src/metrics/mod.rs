//! Multi-object metrics: OSPA with its localisation and cardinality parts, UOSPA, and GOSPA
//! with its decomposition into localisation, missed and false targets.
//!
//! All of them are built on one computation (a crate-internal `cutoff_assignment`): the assignment that
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
/// Returns the `min(|x|, |y|)` assigned pairs (sorted by truth index) with their raw distance
/// and cut-off cost, and the minimal total `Σ min(d, c)^p`.
///
/// # Method: decomposition into the components of the "closer than c" graph
/// Every pair with `d ≥ c` costs exactly `c^p`, so for `|x| ≤ |y|`
///
/// ```text
/// min_π Σ_i min(d(x_i, y_π(i)), c)^p = c^p |x| + min_γ Σ_{(i,j)∈γ} (d(x_i, y_j)^p − c^p)
/// ```
///
/// where γ ranges over the partial matchings that use only edges of the bipartite graph
/// `G = {(i, j) : d(x_i, y_j) < c}` (rows of π outside γ go to leftover columns at cost c^p;
/// there are enough of them because |x| ≤ |y|). The right-hand minimum splits over the
/// connected components of G, and each component's part is again a rectangular assignment
/// problem on its own (small) cost matrix by the same identity. So the solver runs one exact
/// assignment per component, keeps the pairs closer than c, and completes the permutation
/// with leftover rows and columns in index order (all at cost c^p, since a leftover pair
/// closer than c would improve an optimum). For the sparse scenes trackers are scored on this
/// is close to linear after the `O(|x||y|)` distance pass; in the dense worst case it is the
/// single full problem. The value is exactly the optimum; among equally good assignments the
/// one returned may differ from a dense solver's.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `distance(truth[i], estimate[j])` if the metric returns a
/// NaN or negative value, or the metric's own validation error (e.g. ragged points).
pub(crate) fn cutoff_assignment<T, M: Metric<T> + ?Sized>(
    x: &[T],
    y: &[T],
    metric: &M,
    c: f64,
    p: f64,
) -> Result<CutoffAssignment> {
    metric.validate(x, y)?;
    let (n, m) = (x.len(), y.len());
    let cp = fns::powp(c, p);
    // All distances (row-major), and a union-find over the n + m vertices (rows first) joined
    // by the edges of G.
    let mut dist = Vec::with_capacity(n * m);
    let mut forest = UnionFind::new(n + m);
    let mut has_edge = alloc::vec![false; n + m];
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
            if d < c {
                forest.union(i, n + j);
                has_edge[i] = true;
                has_edge[n + j] = true;
            }
            dist.push(d);
        }
    }
    // Components with at least one edge, numbered by first appearance (rows, then columns).
    let mut component_of_root = alloc::vec![usize::MAX; n + m];
    let mut members: Vec<Component> = Vec::new();
    for v in (0..n + m).filter(|&v| has_edge[v]) {
        let root = forest.find(v);
        if component_of_root[root] == usize::MAX {
            component_of_root[root] = members.len();
            members.push(Component::default());
        }
        let comp = &mut members[component_of_root[root]];
        if v < n {
            comp.rows.push(v);
        } else {
            comp.cols.push(v - n);
        }
    }
    let cost_of = |d: f64| if d < c { fns::powp(d, p) } else { cp };
    let mut pairs: Vec<AssignedPair> = Vec::with_capacity(n.min(m));
    let mut row_done = alloc::vec![false; n];
    let mut col_done = alloc::vec![false; m];
    let mut keep = |i: usize, j: usize, d: f64, pairs: &mut Vec<AssignedPair>| {
        if d < c {
            row_done[i] = true;
            col_done[j] = true;
            pairs.push(AssignedPair {
                truth: i,
                estimate: j,
                distance: d,
                cost: fns::powp(d, p),
            });
        }
    };
    if members.len() == 1 && members[0].rows.len() == n && members[0].cols.len() == m {
        // One component holds everything: solve the full problem in the distance buffer.
        let costs: Vec<f64> = dist.iter().map(|&d| cost_of(d)).collect();
        for (i, j) in assignment::solve_unchecked(&costs, n, m).pairs {
            keep(i, j, dist[i * m + j], &mut pairs);
        }
    } else {
        let mut costs = Vec::new();
        for Component { rows, cols } in &members {
            let k = cols.len();
            costs.clear();
            costs.extend(
                rows.iter()
                    .flat_map(|&i| cols.iter().map(move |&j| (i, j)))
                    .map(|(i, j)| cost_of(dist[i * m + j])),
            );
            for (a, b) in assignment::solve_unchecked(&costs, rows.len(), k).pairs {
                let (i, j) = (rows[a], cols[b]);
                keep(i, j, dist[i * m + j], &mut pairs);
            }
        }
    }
    // Complete the permutation with leftover rows and columns, in index order.
    let leftover_rows = (0..n).filter(|&i| !row_done[i]);
    let leftover_cols = (0..m).filter(|&j| !col_done[j]);
    let mut completion: Vec<AssignedPair> = leftover_rows
        .zip(leftover_cols)
        .map(|(i, j)| AssignedPair {
            truth: i,
            estimate: j,
            distance: dist[i * m + j],
            cost: cp,
        })
        .collect();
    pairs.append(&mut completion);
    pairs.sort_unstable_by_key(|q| q.truth);
    let total = crate::math::sum::sum(pairs.iter().map(|q| q.cost));
    Ok(CutoffAssignment { pairs, total })
}

/// A connected component of the "closer than c" graph: its rows and columns (global indices).
#[derive(Default)]
struct Component {
    rows: Vec<usize>,
    cols: Vec<usize>,
}

/// Disjoint sets with path halving and union by size.
struct UnionFind {
    parent: Vec<usize>,
    size: Vec<usize>,
}

impl UnionFind {
    fn new(n: usize) -> Self {
        Self {
            parent: (0..n).collect(),
            size: alloc::vec![1; n],
        }
    }

    fn find(&mut self, mut v: usize) -> usize {
        while self.parent[v] != v {
            self.parent[v] = self.parent[self.parent[v]];
            v = self.parent[v];
        }
        v
    }

    fn union(&mut self, a: usize, b: usize) {
        let (mut a, mut b) = (self.find(a), self.find(b));
        if a == b {
            return;
        }
        if self.size[a] < self.size[b] {
            core::mem::swap(&mut a, &mut b);
        }
        self.parent[b] = a;
        self.size[a] += self.size[b];
    }
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
