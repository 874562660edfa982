//! Multi-object metrics: OSPA with its localisation and cardinality parts, UOSPA, and GOSPA
//! with its decomposition into localisation, missed and false targets.
//!
//! All of them are built on one computation (a crate-internal `cutoff_assignment`): the
//! assignment that minimises `Σ d^(c)(x_i, y_π(i))^p` with `d^(c) = min(d, c)` — the cut-off
//! distance raised to the order *before* the minimisation. (Minimising `Σ d` and raising
//! afterwards, as Stone Soup 1.9.1's `OSPAMetric` does, picks the wrong assignment whenever
//! p ≠ 1; its `GOSPAMetric` raises first.) Only the pairs closer than c matter to it, and for
//! Euclidean points they are found with a uniform grid, so that scenes of 100,000 points
//! take memory proportional to the pairs closer than c, never to `|X|·|Y|`
//! ([`MAX_CLOSE_PAIRS`] caps them). [`Gospa::series`] and [`Ospa::series`] evaluate whole
//! scenarios, in parallel over the steps with the `parallel` feature.
//!
//! | item | paper | tested by (`tests::` unless named) |
//! |---|---|---|
//! | [`Ospa`] | OSPA and its localisation and cardinality parts, (24)–(26) of `004_…`; UOSPA of `003_…` | `ospa::tests::matches_brute_force_and_parts_add_up`, `ospa::tests::is_a_metric_bounded_by_c`, `ospa::tests::one_empty_set_is_at_distance_c` |
//! | [`Gospa`] | GOSPA and its decomposition, `003_…` | `gospa::tests::matches_brute_force_and_prop3`, `gospa::tests::is_a_metric`, `gospa::tests::empty_sets`, `gospa::tests::assignment_minimises_the_p_th_powers_not_the_distances`, `extreme_cut_offs_are_computed_in_units_of_c`, `a_tiny_alpha_with_every_point_matched_is_not_nan` |
//! | the caps on the time of one evaluation: [`MAX_TOTAL_POINTS`], [`MAX_SERIES_POINTS`], [`MAX_SERIES_STEPS`], [`MAX_CANDIDATE_PAIRS`], [`MAX_DENSE_WORK`] | — | `tests::the_caps_on_points_candidates_and_dense_work_are_errors_naming_the_field` |
//! | the cut-off assignment over close pairs, [`MAX_CLOSE_PAIRS`] | — | `small_instances_match_brute_force_in_1d_to_3d_with_ties`, `every_density_matches_the_dense_solver`, `coincident_points_exact_cutoff_and_cell_boundaries`, `gospa_and_ospa_agree_with_the_dense_oracle_on_a_percolating_scene`, `the_cap_on_pairs_closer_than_c_is_an_error_with_the_count`, `metrics_memory::twenty_thousand_percolating_points_take_megabytes_not_gigabytes`, `metrics_memory::over_the_cap_fails_before_storing_the_pairs` |
//! | [`Gospa::series`], [`Ospa::series`] | per-step values and their means | `series::tests::gospa_series_is_the_per_step_values_and_their_means`, `series::tests::ospa_series_is_the_per_step_values_and_their_means` |
//! | [`GospaOptions`], [`OspaOptions`], [`GospaSeriesOptions`], [`OspaSeriesOptions`], [`Gospa::report`], [`GospaReport`] | the parameters as data; GOSPA with its α = 2 decomposition | `options::tests::prop3_report_decomposes_for_alpha_2_only`, `options::tests::def2_and_eq24_series_options_are_the_series_of_their_metric` |

mod base;
mod caps;
mod gospa;
mod options;
mod ospa;
mod pairs;
mod series;
#[cfg(test)]
mod tests;

pub use base::{Euclidean, FnMetric, Metric};
pub use caps::{
    MAX_CANDIDATE_PAIRS, MAX_DENSE_WORK, MAX_SERIES_POINTS, MAX_SERIES_STEPS, MAX_TOTAL_POINTS,
    check_series_steps,
};
pub use gospa::{Gospa, GospaDecomposition, GospaReport};
pub use options::{
    GospaOptions, GospaSeriesOptions, OspaOptions, OspaSeriesOptions, default_alpha, default_order,
};
pub use ospa::{Ospa, OspaDecomposition};
pub use pairs::{MAX_CLOSE_PAIRS, MAX_POINTS};
pub use series::{GospaSeries, OspaSeries};

use alloc::vec;
use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::math::matching::{SparseRows, UNMATCHED, min_cost_partial_matching};
use crate::math::{fns, jv};
use pairs::{Problem, build};

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
/// Returns the `min(|x|, |y|)` pairs of an optimal permutation (sorted by truth index), each
/// with its cut-off cost and whether it is closer than c, and the minimal total
/// `Σ min(d, c)^p`.
///
/// # Method: only the pairs closer than c
/// Every pair with `d ≥ c` costs exactly `c^p`, so for `|x| ≤ |y|`
///
/// ```text
/// min_π Σ_i min(d(x_i, y_π(i)), c)^p = c^p |x| + min_γ Σ_{(i,j)∈γ} (d(x_i, y_j)^p − c^p)
/// ```
///
/// where γ ranges over the partial matchings that use only edges of the bipartite graph
/// `G = {(i, j) : d(x_i, y_j) < c}`: rows of π outside γ go to leftover columns at cost c^p
/// (there are enough of them because |x| ≤ |y|), and conversely dropping the pairs at
/// `d ≥ c` from π leaves such a γ. The identity is the α = 2 form of GOSPA (Prop. 3 of
/// `003_…`, `Σ_γ d^p + (c^p/2)(|x| + |y| − 2|γ|)`, the same minimiser) and holds for every
/// α, for UOSPA and for OSPA alike, because α and OSPA's normalisation only multiply the
/// constant `|y| − |x|` term: the assignment problem itself never depends on α. So all of
/// them are computed exactly from `G` alone; what is special to α = 2 is only reading γ as
/// localisation, missed and false targets.
///
/// `G` is built without all `|x||y|` distances when the metric provides grid coordinates
/// ([`Metric::grid_coordinates`], e.g. [`Euclidean`]): a uniform grid of cells about c wide
/// proposes the pairs in neighbouring cells only (exactly the same `G`, see `pairs.rs`).
/// Otherwise every pair is evaluated, but only the pairs closer than c are stored. The
/// minimum over γ splits over the connected components of `G`: components at least half full
/// (and not tiny) are solved as dense rectangular assignments on their own cost matrices
/// (non-edges at `c^p`, by the same identity); the rest by an exact sparse shortest-
/// augmenting-path matching on the edge list in which every row may also stay unmatched at
/// cost `c^p` (`math/matching.rs`). Memory is `O(|x| + |y| + E)` for the E pairs closer than
/// c, capped by [`MAX_CLOSE_PAIRS`]. Two cases skip the graph and solve the whole problem as
/// one dense assignment on `min(d, c)^p` (the same optimum by the identity above): at most
/// 1,024 pairs (where the graph's fixed cost dominates), and at most 2²² pairs (32 MiB) that
/// no grid can split (all points within about 3c of each other on every axis, where most
/// pairs are close anyway, or a metric without grid coordinates). The permutation is
/// completed with the leftover rows and columns in index order (all at cost c^p). The value
/// is exactly the optimum (up to the rounding of the dual updates); among equally good
/// assignments the one returned may differ from a dense solver's.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `distance(truth[i], estimate[j])` if the metric returns a
/// NaN or negative value, naming `truth × estimate pairs closer than c` (with their count)
/// beyond [`MAX_CLOSE_PAIRS`], naming `truth`/`estimate` beyond [`MAX_POINTS`] points; the
/// metric's own validation error (e.g. ragged points). [`Error::OverBudget`] naming the
/// larger of `truth` and `estimate` beyond [`MAX_TOTAL_POINTS`] points together;
/// [`Error::InvalidParameter`] naming `truth × estimate candidate pairs` beyond
/// [`MAX_CANDIDATE_PAIRS`] and `truth × estimate dense assignment work` beyond
/// [`MAX_DENSE_WORK`] (the caps that bound the time of one evaluation).
pub(crate) fn cutoff_assignment<T, M: Metric<T> + ?Sized>(
    x: &[T],
    y: &[T],
    metric: &M,
    c: f64,
    p: f64,
) -> Result<CutoffAssignment> {
    cutoff_assignment_capped(x, y, metric, c, p, MAX_CLOSE_PAIRS, false)
}

/// [`cutoff_assignment`] with the cap on the pairs closer than c as a parameter, and the
/// graph path forced whatever the size (for tests).
pub(crate) fn cutoff_assignment_capped<T, M: Metric<T> + ?Sized>(
    x: &[T],
    y: &[T],
    metric: &M,
    c: f64,
    p: f64,
    cap: usize,
    force_graph: bool,
) -> Result<CutoffAssignment> {
    let total = x.len().saturating_add(y.len());
    if total > MAX_TOTAL_POINTS {
        let (what, other) = if x.len() >= y.len() {
            ("truth", y.len())
        } else {
            ("estimate", x.len())
        };
        return Err(Error::OverBudget {
            what: what.into(),
            measure: "points in truth and estimate",
            work: total,
            limit: "MAX_TOTAL_POINTS = 2^19 per evaluation",
            at_most: MAX_TOTAL_POINTS.saturating_sub(other),
        });
    }
    metric.validate(x, y)?;
    for (name, len) in [("truth", x.len()), ("estimate", y.len())] {
        if len > MAX_POINTS {
            return Err(Error::parameter(
                name,
                len as f64,
                "at most MAX_POINTS = 2^31 - 1 points",
            ));
        }
    }
    let (n, m) = (x.len(), y.len());
    let cp = fns::powp(c, p);
    let (estimate_of, cost_of) = match build(x, y, metric, (c, p), cap, force_graph)? {
        Problem::Dense { costs, transposed } => {
            // One dense assignment on min(d, c)^p; pairs at c^p are not close.
            let (nr, nc) = if transposed { (m, n) } else { (n, m) };
            let mut estimate_of = vec![UNMATCHED; n];
            let mut cost_of = vec![0.0f64; n];
            if nr > 0 {
                for (a, b) in jv::solve(&costs, nr, nc).into_iter().enumerate() {
                    let cost = costs[a * nc + b];
                    let (i, j) = if transposed { (b, a) } else { (a, b) };
                    if cost < cp {
                        estimate_of[i] = j as u32;
                        cost_of[i] = cost;
                    }
                }
            }
            (estimate_of, cost_of)
        }
        Problem::Graph(graph) => solve_graph(graph, n, m, cp),
    };

    let mut col_done = vec![false; m];
    let mut pairs: Vec<AssignedPair> = Vec::with_capacity(n.min(m));
    for (i, &j) in estimate_of.iter().enumerate() {
        if j != UNMATCHED {
            col_done[j as usize] = true;
            pairs.push(AssignedPair {
                truth: i,
                estimate: j as usize,
                cost: cost_of[i],
                close: true,
            });
        }
    }
    // Complete the permutation with leftover rows and columns, in index order.
    let leftover_rows = (0..n).filter(|&i| estimate_of[i] == UNMATCHED);
    let leftover_cols = (0..m).filter(|&j| !col_done[j]);
    let completion: Vec<AssignedPair> = leftover_rows
        .zip(leftover_cols)
        .map(|(i, j)| AssignedPair {
            truth: i,
            estimate: j,
            cost: cp,
            close: false,
        })
        .collect();
    pairs.extend(completion);
    crate::math::sort::sort_by(&mut pairs, |a, b| a.truth.cmp(&b.truth));
    let total = crate::math::sum::sum(pairs.iter().map(|q| q.cost));
    Ok(CutoffAssignment { pairs, total })
}

/// Solves the graph of the pairs closer than c: dense blocks by the dense solver, the rest by
/// the sparse partial matching. Returns each truth's estimate ([`UNMATCHED`] if none) and the
/// pair's cost `d^p`.
fn solve_graph(graph: pairs::CloseGraph, n: usize, m: usize, cp: f64) -> (Vec<u32>, Vec<f64>) {
    // Solve on the internal numbering (rows and columns in grid order).
    let mut col4row = vec![UNMATCHED; n];
    let mut cost4row = vec![0.0f64; n];
    for block in &graph.blocks {
        let (r, k) = (block.rows.len(), block.cols.len());
        let matrix = &graph.block_costs[block.offset..block.offset + r * k];
        let mut take = |a: usize, b: usize, cost: f64| {
            if cost < cp {
                col4row[block.rows[a] as usize] = block.cols[b];
                cost4row[block.rows[a] as usize] = cost;
            }
        };
        if r <= k {
            for (a, b) in jv::solve(matrix, r, k).into_iter().enumerate() {
                take(a, b, matrix[a * k + b]);
            }
        } else {
            for (b, a) in jv::solve(matrix, k, r).into_iter().enumerate() {
                take(a, b, matrix[b * r + a]);
            }
        }
    }
    let rows = SparseRows {
        start: &graph.start,
        cols: &graph.cols,
        costs: &graph.costs,
    };
    min_cost_partial_matching(rows, &graph.sparse_rows, m, cp, &mut col4row);
    for &r in &graph.sparse_rows {
        let r = r as usize;
        let k = col4row[r];
        if k == UNMATCHED {
            continue;
        }
        let e = (graph.start[r]..graph.start[r + 1])
            .find(|&e| graph.cols[e] == k)
            .unwrap_or(graph.start[r]);
        cost4row[r] = graph.costs[e];
        if cost4row[r] >= cp {
            // d < c but d^p rounds to c^p: the same cost as leaving both out.
            col4row[r] = UNMATCHED;
        }
    }
    // Back to the caller's indices.
    let mut estimate_of = vec![UNMATCHED; n];
    let mut cost_of = vec![0.0f64; n];
    for r in 0..n {
        let i = graph.truth_order[r] as usize;
        if col4row[r] != UNMATCHED {
            estimate_of[i] = graph.estimate_order[col4row[r] as usize];
            cost_of[i] = cost4row[r];
        }
    }
    (estimate_of, cost_of)
}

/// A pair of the optimal permutation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct AssignedPair {
    pub truth: usize,
    pub estimate: usize,
    /// min(d, c)^p.
    pub cost: f64,
    /// Whether the pair is closer than c (assigned in GOSPA's sense; `cost = d^p < c^p`).
    /// Otherwise it only completes the permutation, at cost `c^p`.
    pub close: bool,
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
