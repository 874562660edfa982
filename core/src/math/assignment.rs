//! Exact rectangular linear assignment for `f64` costs.
//!
//! Given an `rows × cols` cost matrix `C`, find a one-to-one assignment that covers every row
//! (when `rows ≤ cols`) or every column (when `rows > cols`) and minimises the total cost
//! `Σ C[i, σ(i)]`. This is the inner problem of every OSPA/GOSPA evaluation.
//!
//! The solver is the shortest-augmenting-path method (Jonker–Volgenant's augmentation step,
//! in the form of Crouse's rectangular algorithm, the one SciPy's `linear_sum_assignment`
//! uses): one Dijkstra search over reduced costs per row, with dual variables `u`, `v` kept
//! feasible (`C[i, j] − u[i] − v[j] ≥ 0`) and tight on assigned pairs. It is exact — it returns
//! an optimal assignment, not an approximation — up to the rounding of the dual updates, and
//! runs in `O(min(r, c)² · max(r, c))` time and `O(r + c)` extra memory. The searches run in
//! `math::jv`, which scans each row as one contiguous, branch-free pass and takes tied
//! columns together as Jonker and Volgenant's SCAN set.
//!
//! # References
//! - R. Jonker, A. Volgenant, "A shortest augmenting path algorithm for dense and sparse linear
//!   assignment problems," Computing 38:325–340, 1987. doi:10.1007/BF02278710
//! - D. F. Crouse, "On implementing 2D rectangular assignment algorithms," IEEE Trans. Aerosp.
//!   Electron. Syst. 52(4):1679–1696, 2016. doi:10.1109/TAES.2016.140952 — Algorithm 1.

use alloc::vec;
use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::math::sum::NeumaierSum;

/// An optimal assignment: the row–column pairs of least total cost.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Assignment {
    /// The assigned `(row, column)` pairs, sorted by row. Its length is `min(rows, cols)`.
    pub pairs: Vec<(usize, usize)>,
    /// The total cost of the assigned pairs (compensated sum).
    pub cost: f64,
}

/// A cost matrix given as rows of equal length (a serialised form's array of rows), stored
/// row-major for [`linear_assignment`].
#[derive(Clone, Debug, PartialEq)]
pub struct CostRows {
    flat: Vec<f64>,
    rows: usize,
    cols: usize,
}

impl CostRows {
    /// The matrix of `rows`, each as long as the first (no rows: an empty matrix).
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] naming `{what}[i]` for the first row `i` of another length.
    pub fn new(rows: &[Vec<f64>], what: &str) -> Result<Self> {
        let cols = rows.first().map_or(0, Vec::len);
        let mut flat = Vec::with_capacity(rows.len() * cols);
        for (i, row) in rows.iter().enumerate() {
            if row.len() != cols {
                return Err(Error::dimension(
                    alloc::format!("{what}[{i}]"),
                    cols,
                    row.len(),
                ));
            }
            flat.extend_from_slice(row);
        }
        Ok(Self {
            flat,
            rows: rows.len(),
            cols,
        })
    }

    /// [`linear_assignment`] on this matrix.
    ///
    /// # Errors
    /// As [`linear_assignment`] (a non-finite entry).
    pub fn assign(&self) -> Result<Assignment> {
        linear_assignment(&self.flat, self.rows, self.cols)
    }
}

/// Read as an array of rows of equal length; a row of another length fails as
/// `[i] has length …, expected …` (relative to the value read, see `serde_valid`).
#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for CostRows {
    fn deserialize<D: serde::Deserializer<'de>>(
        deserializer: D,
    ) -> core::result::Result<Self, D::Error> {
        let rows = Vec::<Vec<f64>>::deserialize(deserializer)?;
        Self::new(&rows, "").map_err(serde::de::Error::custom)
    }
}

/// Solves the rectangular linear assignment problem exactly.
///
/// `cost` is row-major with `rows · cols` entries, all finite. Every row is assigned when
/// `rows ≤ cols`, every column otherwise. An empty matrix (either size 0) gives an empty
/// assignment of cost 0.
///
/// # Errors
/// [`Error::DimensionMismatch`] if `cost.len() != rows · cols`; [`Error::InvalidParameter`]
/// naming `cost[i][j]` if an entry is NaN or infinite.
///
/// # Examples
/// ```
/// use fisst::math::linear_assignment;
/// // Row 0 prefers column 1, row 1 prefers column 0.
/// let a = linear_assignment(&[4.0, 1.0, 3.0, 2.0, 0.0, 5.0], 2, 3).unwrap();
/// assert_eq!(a.pairs, vec![(0, 1), (1, 0)]);
/// assert_eq!(a.cost, 3.0);
/// ```
pub fn linear_assignment(cost: &[f64], rows: usize, cols: usize) -> Result<Assignment> {
    let len = rows
        .checked_mul(cols)
        .ok_or_else(|| Error::dimension("cost", usize::MAX, cost.len()))?;
    if cost.len() != len {
        return Err(Error::dimension("cost", len, cost.len()));
    }
    if let Some(k) = cost.iter().position(|c| !c.is_finite()) {
        return Err(Error::parameter(
            alloc::format!("cost[{}][{}]", k / cols, k % cols),
            cost[k],
            "finite",
        ));
    }
    Ok(solve_unchecked(cost, rows, cols))
}

/// Costs above this magnitude (2^900 ≈ 8.5e270) are solved in units of [`HUGE_UNIT`]: the
/// dual variables and path lengths, sums of many costs, then stay far from overflow.
const HUGE_COST: f64 = 8.452712498170644e270;
/// 2^124: costs up to the largest double become at most 2^900 in these units.
const HUGE_UNIT: f64 = 2.1267647932558654e37;

/// [`linear_assignment`] without validation: the caller guarantees
/// `cost.len() == rows · cols` and finite entries.
///
/// Costs beyond ±2^900 (near the largest double, whose sums overflow) are solved on the
/// matrix divided by 2^124 — exactly the same problem, a power of two only shifting the
/// exponents — and the total is the compensated sum in those units times 2^124: finite
/// whenever the optimal total is representable, ±∞ where it is not, never NaN (∞ − ∞).
/// Ordinary costs take the direct path, unchanged.
pub(crate) fn solve_unchecked(cost: &[f64], rows: usize, cols: usize) -> Assignment {
    debug_assert_eq!(cost.len(), rows * cols);
    if rows == 0 || cols == 0 {
        return Assignment {
            pairs: Vec::new(),
            cost: 0.0,
        };
    }
    if cost.iter().any(|c| crate::math::fns::abs(*c) > HUGE_COST) {
        let scaled: Vec<f64> = cost.iter().map(|c| c / HUGE_UNIT).collect();
        let a = solve_unchecked(&scaled, rows, cols);
        return Assignment {
            pairs: a.pairs,
            cost: a.cost * HUGE_UNIT,
        };
    }
    let pairs = if rows <= cols {
        let col4row = crate::math::jv::solve(cost, rows, cols);
        col4row.into_iter().enumerate().collect::<Vec<_>>()
    } else {
        let mut transposed = vec![0.0; rows * cols];
        for i in 0..rows {
            for j in 0..cols {
                transposed[j * rows + i] = cost[i * cols + j];
            }
        }
        let row4col = crate::math::jv::solve(&transposed, cols, rows);
        let mut pairs: Vec<(usize, usize)> = row4col
            .into_iter()
            .enumerate()
            .map(|(j, i)| (i, j))
            .collect();
        crate::math::sort::sort_by(&mut pairs, |a, b| a.cmp(b));
        pairs
    };
    let total = pairs
        .iter()
        .map(|&(i, j)| cost[i * cols + j])
        .collect::<NeumaierSum>()
        .total();
    Assignment { pairs, cost: total }
}

#[cfg(test)]
const NONE: usize = usize::MAX;

/// Shortest augmenting paths for `nr ≤ nc`; returns the column of each row.
///
/// The straightforward form of the method (a list of the columns not yet scanned, the
/// predecessor of each column stored as it is relaxed): the solver before issue 29, kept as
/// the reference that [`crate::math::jv`]'s tests compare against.
#[cfg(test)]
pub(crate) fn sap(cost: &[f64], nr: usize, nc: usize) -> Vec<usize> {
    debug_assert!(nr <= nc);
    let mut u = vec![0.0f64; nr];
    let mut v = vec![0.0f64; nc];
    let mut shortest = vec![f64::INFINITY; nc];
    let mut path = vec![NONE; nc];
    let mut col4row = vec![NONE; nr];
    let mut row4col = vec![NONE; nc];
    let mut scanned_rows = vec![false; nr];
    let mut scanned_cols = vec![false; nc];
    let mut remaining: Vec<usize> = Vec::with_capacity(nc);
    // Rows visited by the current search, so the dual update touches only them.
    let mut visited_rows: Vec<usize> = Vec::with_capacity(nr);
    let mut visited_cols: Vec<usize> = Vec::with_capacity(nc);

    for cur_row in 0..nr {
        // Dijkstra from `cur_row` over reduced costs; stops at the first free column.
        remaining.clear();
        remaining.extend((0..nc).rev());
        shortest.fill(f64::INFINITY);
        let mut i = cur_row;
        let mut min_val = 0.0f64;
        let sink;
        loop {
            scanned_rows[i] = true;
            visited_rows.push(i);
            let row = &cost[i * nc..(i + 1) * nc];
            let ui = u[i];
            let mut lowest = f64::INFINITY;
            let mut index = NONE;
            for (it, &j) in remaining.iter().enumerate() {
                let r = min_val + row[j] - ui - v[j];
                if r < shortest[j] {
                    path[j] = i;
                    shortest[j] = r;
                }
                let s = shortest[j];
                if s < lowest || (s == lowest && row4col[j] == NONE) {
                    lowest = s;
                    index = it;
                }
            }
            // Costs are finite, so some column is always reachable.
            min_val = lowest;
            let j = remaining.swap_remove(index);
            scanned_cols[j] = true;
            visited_cols.push(j);
            if row4col[j] == NONE {
                sink = j;
                break;
            }
            i = row4col[j];
        }

        // Dual update keeps reduced costs nonnegative and assigned pairs tight.
        u[cur_row] += min_val;
        for &r in &visited_rows {
            if r != cur_row {
                u[r] += min_val - shortest[col4row[r]];
            }
            scanned_rows[r] = false;
        }
        for &c in &visited_cols {
            v[c] -= min_val - shortest[c];
            scanned_cols[c] = false;
        }
        visited_rows.clear();
        visited_cols.clear();

        // Augment along the alternating path back to `cur_row`.
        let mut j = sink;
        loop {
            let r = path[j];
            row4col[j] = r;
            core::mem::swap(&mut col4row[r], &mut j);
            if r == cur_row {
                break;
            }
        }
    }
    col4row
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng, rngs::SmallRng};

    #[test]
    fn cost_rows_flatten_equal_rows_and_name_the_first_ragged_row() {
        use alloc::string::ToString;
        let m = CostRows::new(&[vec![4.0, 1.0, 3.0], vec![2.0, 0.0, 5.0]], "cost").unwrap();
        assert_eq!(
            m.assign().unwrap(),
            linear_assignment(&[4.0, 1.0, 3.0, 2.0, 0.0, 5.0], 2, 3).unwrap()
        );
        assert_eq!(
            CostRows::new(&[], "cost").unwrap().assign().unwrap().pairs,
            vec![]
        );
        let e = CostRows::new(&[vec![1.0, 2.0], vec![3.0, 4.0], vec![5.0]], "cost").unwrap_err();
        assert_eq!(e.to_string(), "cost[2] has length 1, expected 2");
    }

    #[cfg(feature = "serde")]
    #[test]
    fn cost_rows_read_an_array_of_rows_and_fail_relative_to_it() {
        use alloc::string::ToString;
        let m: CostRows = serde_json::from_str("[[1, 2], [3, 4]]").unwrap();
        assert_eq!(
            m,
            CostRows::new(&[vec![1.0, 2.0], vec![3.0, 4.0]], "").unwrap()
        );
        let e = serde_json::from_str::<CostRows>("[[1, 2], [3]]").unwrap_err();
        assert!(
            e.to_string().starts_with("[1] has length 1, expected 2"),
            "{e}"
        );
    }

    /// Minimum over all injective maps from the smaller side into the larger.
    pub(crate) fn brute_force(cost: &[f64], rows: usize, cols: usize) -> f64 {
        fn rec(
            cost: &[f64],
            rows: usize,
            cols: usize,
            i: usize,
            used: &mut [bool],
            transposed: bool,
        ) -> f64 {
            let (n, m) = if transposed {
                (cols, rows)
            } else {
                (rows, cols)
            };
            if i == n {
                return 0.0;
            }
            let mut best = f64::INFINITY;
            for j in 0..m {
                if !used[j] {
                    used[j] = true;
                    let c = if transposed {
                        cost[j * cols + i]
                    } else {
                        cost[i * cols + j]
                    };
                    best = best.min(c + rec(cost, rows, cols, i + 1, used, transposed));
                    used[j] = false;
                }
            }
            best
        }
        let transposed = rows > cols;
        let mut used = vec![false; rows.max(cols)];
        rec(cost, rows, cols, 0, &mut used, transposed)
    }

    fn check(cost: &[f64], rows: usize, cols: usize) {
        let a = linear_assignment(cost, rows, cols).unwrap();
        assert_eq!(a.pairs.len(), rows.min(cols));
        let mut seen_r = vec![false; rows];
        let mut seen_c = vec![false; cols];
        for &(i, j) in &a.pairs {
            assert!(!seen_r[i] && !seen_c[j], "not one-to-one: {:?}", a.pairs);
            seen_r[i] = true;
            seen_c[j] = true;
        }
        let best = brute_force(cost, rows, cols);
        assert!(
            (a.cost - best).abs() <= 1e-9 * (1.0 + best.abs()),
            "{rows}x{cols}: got {} expected {best}; cost={cost:?}",
            a.cost
        );
    }

    #[test]
    fn matches_brute_force_up_to_size_8() {
        let mut rng = SmallRng::seed_from_u64(1);
        for rows in 0..=8 {
            for cols in 0..=8 {
                let trials = if rows.max(cols) >= 7 { 3 } else { 20 };
                for t in 0..trials {
                    let cost: Vec<f64> = (0..rows * cols)
                        .map(|_| match t % 3 {
                            // continuous costs
                            0 => rng.random_range(-5.0..10.0),
                            // heavy ties, as with GOSPA's cut-off
                            1 => f64::from(rng.random_range(0..3u8)),
                            // wide dynamic range
                            _ => rng.random_range(0.0..1.0f64).powi(8) * 1e6,
                        })
                        .collect();
                    check(&cost, rows, cols);
                }
            }
        }
    }

    #[test]
    fn empty_and_degenerate() {
        assert_eq!(linear_assignment(&[], 0, 5).unwrap().pairs, vec![]);
        assert_eq!(linear_assignment(&[], 3, 0).unwrap().cost, 0.0);
        let a = linear_assignment(&[7.0], 1, 1).unwrap();
        assert_eq!(a.pairs, vec![(0, 0)]);
        assert_eq!(a.cost, 7.0);
        // all equal
        let a = linear_assignment(&[1.0; 12], 3, 4).unwrap();
        assert_eq!(a.cost, 3.0);
    }

    #[test]
    fn costs_near_the_largest_double_give_the_optimum_or_infinity_never_nan() {
        // Found by the boundary fuzzer: the compensated total of 1e308 + 1e308 was NaN.
        let a = linear_assignment(&[1e308; 4], 2, 2).unwrap();
        assert_eq!((a.pairs.len(), a.cost), (2, f64::INFINITY));
        let a = linear_assignment(&[-1e308; 4], 2, 2).unwrap();
        assert_eq!(a.cost, f64::NEG_INFINITY);
        let a = linear_assignment(&[-1e308, 1e308, 1e308, -1e308], 2, 2).unwrap();
        assert_eq!(
            (a.pairs.clone(), a.cost),
            (vec![(0, 0), (1, 1)], f64::NEG_INFINITY)
        );
        // A representable optimum is found and summed in units where nothing overflows.
        let a = linear_assignment(&[1e308, 0.0, 0.0, f64::MAX], 2, 2).unwrap();
        assert_eq!((a.pairs.clone(), a.cost), (vec![(0, 1), (1, 0)], 0.0));
        let cost = [1e308, 5e307, 5e307, 1e308, 1e307, 3e307];
        let a = linear_assignment(&cost, 3, 2).unwrap();
        assert_eq!(a.pairs, vec![(0, 1), (2, 0)]);
        assert_eq!(a.cost, 5e307 + 1e307);
        // The same matrix at ordinary scale: the direct path, the same pairs.
        let small: Vec<f64> = cost.iter().map(|c| c / 1e300).collect();
        assert_eq!(linear_assignment(&small, 3, 2).unwrap().pairs, a.pairs);
    }

    #[test]
    fn rejects_bad_input() {
        let e = linear_assignment(&[1.0, f64::NAN, 0.0, 2.0], 2, 2).unwrap_err();
        assert_eq!(e.field(), "cost[0][1]");
        let e = linear_assignment(&[1.0, 2.0, 3.0], 2, 2).unwrap_err();
        assert_eq!(e.field(), "cost");
        assert!(linear_assignment(&[f64::INFINITY], 1, 1).is_err());
    }

    #[test]
    fn large_random_is_consistent_with_duals() {
        // Optimality certificate for a size brute force cannot reach: a feasible dual
        // (u, v) with Σu + Σv equal to the primal cost proves optimality. We rebuild it by
        // checking that no 2-swap or single column move improves the solution.
        let mut rng = SmallRng::seed_from_u64(9);
        let (rows, cols) = (60, 80);
        let cost: Vec<f64> = (0..rows * cols)
            .map(|_| rng.random_range(0.0..1.0))
            .collect();
        let a = linear_assignment(&cost, rows, cols).unwrap();
        let mut col_used = vec![false; cols];
        for &(_, j) in &a.pairs {
            col_used[j] = true;
        }
        for &(i1, j1) in &a.pairs {
            for &(i2, j2) in &a.pairs {
                let now = cost[i1 * cols + j1] + cost[i2 * cols + j2];
                let swapped = cost[i1 * cols + j2] + cost[i2 * cols + j1];
                assert!(swapped >= now - 1e-12);
            }
            for j in (0..cols).filter(|&j| !col_used[j]) {
                assert!(cost[i1 * cols + j] >= cost[i1 * cols + j1] - 1e-12);
            }
        }
    }
}
