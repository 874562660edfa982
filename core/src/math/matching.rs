//! Exact minimum-cost partial matching on a sparse bipartite graph (crate-internal).
//!
//! Rows `i` and columns `j` are joined by the edges of a sparse graph, edge `(i, j)` costing
//! `C[i, j]`; every row either takes one of its edges, each column at most once, or stays
//! unmatched at the cost `exit` (the same for every row). The solver minimises the total.
//! This is the inner problem of OSPA and GOSPA restricted to the pairs closer than the
//! cut-off c (`C = d^p`, `exit = c^p`, see `metrics::cutoff_assignment`).
//!
//! # Method
//! The problem is the rectangular assignment problem in which row `i` has, besides its edges,
//! a private column `e_i` of cost `exit`: rows × (columns ∪ {e_i}). It is solved by shortest
//! augmenting paths (Jonker–Volgenant's augmentation, in Crouse's rectangular form, the method
//! of [`crate::math::linear_assignment`]) with the Dijkstra search run on the edge list with a
//! binary heap instead of a scan of all columns — the sparse form of JV that LAPMOD
//! implements. Duals `u` (rows) and `v` (columns) stay feasible
//! (`C[i, j] − u_i − v_j ≥ 0`, `exit − u_i − w_i ≥ 0`) and tight on assigned pairs, so each
//! augmentation keeps the partial assignment optimal for the rows processed so far, and the
//! final one is optimal (exact up to the rounding of the dual updates).
//!
//! Three facts keep it cheap:
//! - the private column `e_k` is reachable only from row `k`, and a row reached by the search
//!   is matched to a real column, so its `e_k` is free: the search keeps the cheapest such exit
//!   as a candidate sink instead of pushing it on the heap, and the exit duals `w` stay 0 (an
//!   exit column is only ever scanned as a sink, where Crouse's update is zero). A row that
//!   has exited is unreachable afterwards;
//! - a row is initialised at its cheapest option (`u_i = min(exit, min_j C[i, j])`, `v = 0`)
//!   and takes it when that column is free, so only the rows that collide need a search;
//! - a search never leaves the connected component of its row, so the method is the same as
//!   solving each connected component of the graph on its own; its cost is bounded by the
//!   part of the component closer (in reduced cost) than the nearest free column or exit.
//!
//! Memory is `O(rows + columns)` besides the graph.
//!
//! # References
//! - R. Jonker, A. Volgenant, "A shortest augmenting path algorithm for dense and sparse linear
//!   assignment problems," Computing 38:325–340, 1987. doi:10.1007/BF02278710 (LAPMOD is the
//!   sparse variant.)
//! - D. F. Crouse, "On implementing 2D rectangular assignment algorithms," IEEE Trans. Aerosp.
//!   Electron. Syst. 52(4):1679–1696, 2016. doi:10.1109/TAES.2016.140952 — Algorithm 1 (the
//!   dual update used here).

use alloc::collections::BinaryHeap;
use alloc::vec;
use alloc::vec::Vec;
use core::cmp::Ordering;

/// `col4row` of a row left unmatched (assigned to its exit).
pub(crate) const UNMATCHED: u32 = u32::MAX;

/// A sparse bipartite graph stored by rows: row `i`'s edges are `cols[start[i]..start[i + 1]]`
/// with costs `costs[start[i]..start[i + 1]]`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SparseRows<'a> {
    pub start: &'a [usize],
    pub cols: &'a [u32],
    pub costs: &'a [f64],
}

impl<'a> SparseRows<'a> {
    #[inline]
    fn row(&self, i: usize) -> (&'a [u32], &'a [f64]) {
        let (a, b) = (self.start[i], self.start[i + 1]);
        (&self.cols[a..b], &self.costs[a..b])
    }
}

/// A heap entry: tentative distance and column, ordered so that `BinaryHeap` pops the
/// smallest distance first (ties by column index, for determinism).
#[derive(Clone, Copy, Debug)]
struct Entry(f64, u32);

impl PartialEq for Entry {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Entry {}
impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Entry {
    fn cmp(&self, other: &Self) -> Ordering {
        other.0.total_cmp(&self.0).then(other.1.cmp(&self.1))
    }
}

/// Where an augmenting path ends.
enum Sink {
    Column(u32),
    Exit(u32),
}

/// Solves the partial matching for `rows` (global row indices, each with at least one edge,
/// in any order) of `graph` over `m` columns, with every finite cost. Writes the matched
/// column of each of `rows` into `col4row` (indexed by global row; [`UNMATCHED`] for rows
/// left out); other entries of `col4row` are not touched.
pub(crate) fn min_cost_partial_matching(
    graph: SparseRows<'_>,
    rows: &[u32],
    m: usize,
    exit: f64,
    col4row: &mut [u32],
) {
    if rows.is_empty() {
        return;
    }
    let n = col4row.len();
    let mut u = vec![0.0f64; n];
    let mut v = vec![0.0f64; m];
    let mut row4col = vec![UNMATCHED; m];
    // Initialisation: each row at its cheapest option, taken when free.
    let mut pending: Vec<u32> = Vec::new();
    for &i in rows {
        let (cols, costs) = graph.row(i as usize);
        let (mut best, mut best_col) = (exit, UNMATCHED);
        for (&j, &cost) in cols.iter().zip(costs) {
            if cost < best {
                best = cost;
                best_col = j;
            }
        }
        u[i as usize] = best;
        if best_col == UNMATCHED {
            col4row[i as usize] = UNMATCHED;
        } else if row4col[best_col as usize] == UNMATCHED {
            col4row[i as usize] = best_col;
            row4col[best_col as usize] = i;
        } else {
            col4row[i as usize] = UNMATCHED;
            pending.push(i);
        }
    }
    if pending.is_empty() {
        return;
    }

    let mut shortest = vec![f64::INFINITY; m];
    let mut path = vec![UNMATCHED; m];
    let mut done = vec![false; m];
    let mut touched: Vec<u32> = Vec::new();
    let mut finished: Vec<u32> = Vec::new();
    let mut visited_rows: Vec<u32> = Vec::new();
    let mut heap: BinaryHeap<Entry> = BinaryHeap::new();

    for &s in &pending {
        // Dijkstra from row s over reduced costs; ends at the first free column or exit.
        let mut i = s;
        let mut min_val = 0.0f64;
        let (mut best_exit, mut best_exit_row) = (f64::INFINITY, UNMATCHED);
        let sink = loop {
            visited_rows.push(i);
            let ui = u[i as usize];
            let r_exit = min_val + exit - ui;
            if r_exit < best_exit {
                best_exit = r_exit;
                best_exit_row = i;
            }
            let (cols, costs) = graph.row(i as usize);
            for (&j, &cost) in cols.iter().zip(costs) {
                let ju = j as usize;
                if done[ju] {
                    continue;
                }
                let r = min_val + cost - ui - v[ju];
                if r < shortest[ju] {
                    if shortest[ju] == f64::INFINITY {
                        touched.push(j);
                    }
                    shortest[ju] = r;
                    path[ju] = i;
                    heap.push(Entry(r, j));
                }
            }
            // The nearest column not yet finished (stale heap entries are skipped).
            let top = loop {
                match heap.peek() {
                    Some(&Entry(key, j)) if done[j as usize] || key > shortest[j as usize] => {
                        heap.pop();
                    }
                    other => break other.copied(),
                }
            };
            let take_exit = match top {
                None => true,
                Some(Entry(key, j)) => {
                    best_exit < key || (best_exit == key && row4col[j as usize] != UNMATCHED)
                }
            };
            if take_exit {
                min_val = best_exit;
                break Sink::Exit(best_exit_row);
            }
            let Some(Entry(key, j)) = heap.pop() else {
                unreachable!("top is Some");
            };
            done[j as usize] = true;
            finished.push(j);
            min_val = key;
            if row4col[j as usize] == UNMATCHED {
                break Sink::Column(j);
            }
            i = row4col[j as usize];
        };

        // Dual update (Crouse, Algorithm 1): feasible everywhere, tight on the matching.
        u[s as usize] += min_val;
        for &r in &visited_rows {
            if r != s {
                u[r as usize] += min_val - shortest[col4row[r as usize] as usize];
            }
        }
        for &j in &finished {
            v[j as usize] -= min_val - shortest[j as usize];
        }

        // Augment along the alternating path back to s.
        let mut j = match sink {
            Sink::Exit(k) if k == s => UNMATCHED, // s itself stays out: nothing moves
            Sink::Exit(k) => core::mem::replace(&mut col4row[k as usize], UNMATCHED),
            Sink::Column(j) => j,
        };
        while j != UNMATCHED {
            let r = path[j as usize];
            row4col[j as usize] = r;
            j = core::mem::replace(&mut col4row[r as usize], j);
            if r == s {
                break;
            }
        }

        for &j in &touched {
            shortest[j as usize] = f64::INFINITY;
            done[j as usize] = false;
        }
        touched.clear();
        finished.clear();
        visited_rows.clear();
        heap.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::assignment::tests::brute_force;
    use rand::{RngExt, SeedableRng, rngs::SmallRng};

    /// Random sparse instance: edges with probability `density`, costs in [0, exit] with ties.
    fn instance(
        rng: &mut SmallRng,
        n: usize,
        m: usize,
        density: f64,
        exit: f64,
        ties: bool,
    ) -> (Vec<usize>, Vec<u32>, Vec<f64>) {
        let mut start = vec![0];
        let (mut cols, mut costs) = (vec![], vec![]);
        for _ in 0..n {
            for j in 0..m {
                if rng.random_range(0.0..1.0) < density {
                    cols.push(j as u32);
                    costs.push(if ties {
                        f64::from(rng.random_range(0..4u8)) * exit / 4.0
                    } else {
                        rng.random_range(0.0..exit)
                    });
                }
            }
            start.push(cols.len());
        }
        (start, cols, costs)
    }

    fn solve(start: &[usize], cols: &[u32], costs: &[f64], m: usize, exit: f64) -> Vec<u32> {
        let n = start.len() - 1;
        let graph = SparseRows { start, cols, costs };
        let rows: Vec<u32> = (0..n as u32)
            .filter(|&i| start[i as usize + 1] > start[i as usize])
            .collect();
        let mut col4row = vec![UNMATCHED; n];
        min_cost_partial_matching(graph, &rows, m, exit, &mut col4row);
        col4row
    }

    /// The matching's cost, checking it is one (each column at most once, only edges).
    fn cost_of(
        col4row: &[u32],
        start: &[usize],
        cols: &[u32],
        costs: &[f64],
        m: usize,
        exit: f64,
    ) -> f64 {
        let mut used = vec![false; m];
        let mut total = 0.0;
        for (i, &j) in col4row.iter().enumerate() {
            if j == UNMATCHED {
                total += exit;
                continue;
            }
            assert!(!used[j as usize], "column {j} used twice");
            used[j as usize] = true;
            let e = (start[i]..start[i + 1])
                .find(|&e| cols[e] == j)
                .expect("an edge of the graph");
            total += costs[e];
        }
        total
    }

    /// The total cost of [`solve`]'s matching.
    fn solved_total(start: &[usize], cols: &[u32], costs: &[f64], m: usize, exit: f64) -> f64 {
        cost_of(
            &solve(start, cols, costs, m, exit),
            start,
            cols,
            costs,
            m,
            exit,
        )
    }

    /// The dense n × (m + n) matrix of the graph: the edges, row i's exit on private column
    /// m + i, and a prohibitive 1e6 elsewhere.
    fn with_private_exits(
        start: &[usize],
        cols: &[u32],
        costs: &[f64],
        m: usize,
        exit: f64,
    ) -> Vec<f64> {
        let n = start.len() - 1;
        let w = m + n;
        let mut dense = vec![1e6; n * w];
        for i in 0..n {
            for e in start[i]..start[i + 1] {
                dense[i * w + cols[e] as usize] = costs[e];
            }
            dense[i * w + m + i] = exit;
        }
        dense
    }

    #[test]
    fn matches_the_dense_oracle_with_private_exits() {
        // Dense oracle: the n × (m + n) matrix with the edges, exits on the private columns,
        // and a prohibitive cost elsewhere; brute force for small sizes.
        let mut rng = SmallRng::seed_from_u64(41);
        for t in 0..3000 {
            let (n, m) = (rng.random_range(0..=6usize), rng.random_range(0..=6usize));
            let density = [0.15, 0.4, 0.7, 1.0][t % 4];
            let exit = 3.0;
            let (start, cols, costs) = instance(&mut rng, n, m, density, exit, t % 3 == 0);
            let got = solved_total(&start, &cols, &costs, m, exit);
            let w = m + n;
            let best = brute_force(&with_private_exits(&start, &cols, &costs, m, exit), n, w);
            assert!(
                (got - best).abs() <= 1e-12 * (1.0 + best),
                "t={t} n={n} m={m}: {got} vs {best}"
            );
        }
    }

    #[test]
    fn larger_instances_agree_with_the_dense_solver() {
        let mut rng = SmallRng::seed_from_u64(43);
        for t in 0..60 {
            let (n, m) = (
                rng.random_range(20..120usize),
                rng.random_range(20..120usize),
            );
            let density = [0.01, 0.03, 0.1, 0.5, 1.0][t % 5];
            let exit = 1.0;
            let (start, cols, costs) = instance(&mut rng, n, m, density, exit, t % 2 == 0);
            let got = solved_total(&start, &cols, &costs, m, exit);
            let dense = with_private_exits(&start, &cols, &costs, m, exit);
            let best = crate::math::linear_assignment(&dense, n, m + n)
                .unwrap()
                .cost;
            assert!(
                (got - best).abs() <= 1e-11 * (1.0 + best),
                "t={t}: {got} vs {best}"
            );
        }
    }
}
