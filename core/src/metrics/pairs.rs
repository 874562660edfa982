//! The pairs closer than the cut-off: the candidate search (a uniform grid, or all pairs) and
//! the sparse graph they form, split into its connected components.

use alloc::format;
use alloc::vec;
use alloc::vec::Vec;

use super::Metric;
use super::caps::{CANDIDATES_FIELD, MAX_CANDIDATE_PAIRS, check_dense_work, dense_work};
use crate::error::{Error, Result};
use crate::math::fns;

/// The most pairs closer than the cut-off c that one OSPA/GOSPA evaluation accepts:
/// `2^27 = 134,217,728` on 64-bit targets, `2^25 = 33,554,432` on 32-bit targets (wasm32,
/// whose whole address space is 4 GiB).
///
/// Each such pair takes 12 bytes (its estimate index and cost), plus up to 16 more in a
/// component solved as a dense matrix (one at least half full), so the cap bounds the graph
/// at 3.5 GiB natively and 0.9 GiB in wasm32, whatever the input. Beyond it the call returns
/// [`Error::InvalidParameter`] naming `truth × estimate pairs closer than c` with their
/// count (after a pass that only counts). Only scenes where a large share of all pairs lie
/// within c of each other reach it — e.g. two sets of 5,793 points all within c of each other
/// in wasm32, whose dense assignment would take tens of seconds — while scenes in which every
/// point has a bounded number of neighbours within c stay far below it at any size.
#[cfg(target_pointer_width = "64")]
pub const MAX_CLOSE_PAIRS: usize = 1 << 27;
/// See the 64-bit documentation: `2^25` on 32-bit targets.
#[cfg(not(target_pointer_width = "64"))]
pub const MAX_CLOSE_PAIRS: usize = 1 << 25;

/// The most points in one set: `2^31 − 1` (indices are stored in 32 bits).
pub const MAX_POINTS: usize = (1 << 31) - 1;

pub(crate) const PAIRS_FIELD: &str = "truth × estimate pairs closer than c";
const PAIRS_EXPECTED: &str = "at most MAX_CLOSE_PAIRS (2^27 on 64-bit targets, 2^25 on 32-bit \
                              targets such as wasm32; up to 28 bytes of memory each): lower c \
                              or split the sets";

/// Grid cells are `c · (1 + 2^-20)` wide: the margin absorbs the rounding of the cell
/// coordinates (see [`Grid`]).
const GRID_MARGIN: f64 = 1.0 + 1.0 / 1_048_576.0;
/// An axis spanning more cells than this is not used by the grid (rounding bound, see [`Grid`]).
const MAX_CELLS_PER_AXIS: f64 = 1_073_741_824.0;
/// The grid indexes at most this many axes (3^(k−1) neighbour lines per cell).
const MAX_GRID_AXES: usize = 3;

/// A component is solved as a dense matrix when it is at least half full and this large:
/// there the dense shortest-augmenting-path scan beats the heap-based sparse search.
const DENSE_MIN_ENTRIES: u64 = 256;

/// The candidate pairs, a superset of the pairs closer than c, over an internal numbering of
/// the points: truths and estimates sorted by grid cell, so that neighbours in space are
/// neighbours in memory for everything downstream (union-find, graph, solver).
struct Candidates {
    /// Internal row → truth index.
    truth_order: Vec<u32>,
    /// Internal column → estimate index.
    estimate_order: Vec<u32>,
    /// `None`: every pair is a candidate (no grid coordinates, an empty set, or points that a
    /// grid cannot separate); the orders are then the identity.
    grid: Option<Grid>,
}

/// A uniform grid on up to three coordinates (those spanning the most cells), with cells of
/// width `h = c (1 + 2^-20)`: only pairs in neighbouring cells (`|Δq_k| ≤ 1` on every gridded
/// axis) whose gridded coordinates also differ by less than `h` are candidates.
///
/// Exactness: with `q_k = ⌊fl(fl(x_k − o_k) · fl(1/h))⌋` (`o_k` the smallest coordinate), two
/// points whose computed distance is below c differ on axis k by less than
/// `c / (1 − 10⁻⁹) < h` (the [`Metric::grid_coordinates`] contract, on the same computed
/// difference the box test uses), and the rounding of the cell coordinates adds at most
/// `4.02 ε R` cells for an axis of `R` cells (ε = 2⁻⁵³). Their unrounded cell coordinates
/// then differ by less than `(1 + 10⁻⁹ + 3ε) / (1 + 2⁻²⁰) + 4.02 ε R < 1` whenever
/// `R ≤ 2³⁰` (the bound is reached at `R ≈ 2.1·10⁹`), so their cells are neighbours: the grid
/// never misses a pair closer than c and gives exactly the graph that all pairs give. Axes
/// spanning more than 2³⁰ cells are not gridded.
struct Grid {
    /// Cell key of each internal row, sorted.
    truth_keys: Vec<u64>,
    /// Cell key of each internal column, sorted.
    estimate_keys: Vec<u64>,
    /// The gridded coordinates of each internal row (`axes` per row).
    truth_coords: Vec<f64>,
    /// The gridded coordinates of each internal column.
    estimate_coords: Vec<f64>,
    /// Number of gridded axes (1 to 3).
    axes: usize,
    /// The box half-width `h`.
    reach: f64,
    /// Key offsets of the neighbouring lines of cells (all gridded axes but the last, whose
    /// neighbours `key − 1 ..= key + 1` are contiguous).
    deltas: Vec<i64>,
}

/// The bounding box of the grid coordinates of both sets, `None` if the metric has none
/// (for any point).
///
/// # Errors
/// [`Error::DimensionMismatch`] naming `truth[i]`/`estimate[j]` for coordinates of another
/// length than the first point's, [`Error::InvalidParameter`] naming `truth[i][k]` for a
/// non-finite one.
fn coordinate_bounds<T, M: Metric<T> + ?Sized>(
    x: &[T],
    y: &[T],
    metric: &M,
) -> Result<Option<(Vec<f64>, Vec<f64>)>> {
    let Some(first) = x
        .first()
        .or(y.first())
        .and_then(|pt| metric.grid_coordinates(pt))
    else {
        return Ok(None);
    };
    let dim = first.len();
    let mut lo = vec![f64::INFINITY; dim];
    let mut hi = vec![f64::NEG_INFINITY; dim];
    for (name, pts) in [("truth", x), ("estimate", y)] {
        for (i, pt) in pts.iter().enumerate() {
            let Some(q) = metric.grid_coordinates(pt) else {
                return Ok(None);
            };
            if q.len() != dim {
                return Err(Error::dimension(format!("{name}[{i}]"), dim, q.len()));
            }
            for (k, &v) in q.iter().enumerate() {
                if !v.is_finite() {
                    return Err(Error::parameter(format!("{name}[{i}][{k}]"), v, "finite"));
                }
                lo[k] = lo[k].min(v);
                hi[k] = hi[k].max(v);
            }
        }
    }
    Ok(Some((lo, hi)))
}

impl Candidates {
    fn new<T, M: Metric<T> + ?Sized>(x: &[T], y: &[T], metric: &M, c: f64) -> Result<Self> {
        let (n, m) = (x.len(), y.len());
        let all = || Candidates {
            truth_order: (0..n as u32).collect(),
            estimate_order: (0..m as u32).collect(),
            grid: None,
        };
        if n == 0 || m == 0 {
            return Ok(all());
        }
        let Some((lo, hi)) = coordinate_bounds(x, y, metric)? else {
            return Ok(all());
        };
        let dim = lo.len();
        let reach = c * GRID_MARGIN;
        let s = 1.0 / reach;
        // (cells, axis) for the axes worth gridding, most cells first.
        let mut axes: Vec<(u64, usize)> = (0..dim)
            .filter_map(|k| {
                let span = (hi[k] - lo[k]) * s;
                // floor(span) + 1 cells; fewer than 4 prune nothing with ±1 neighbours.
                (3.0..MAX_CELLS_PER_AXIS)
                    .contains(&span)
                    .then(|| (span as u64 + 1, k))
            })
            .collect();
        crate::math::sort::sort_by(&mut axes, |a, b| b.0.cmp(&a.0).then(a.1.cmp(&b.1)));
        // Keep axes while the key space (cells + 2 per axis, for the ±1 guard cells) fits.
        let mut chosen: Vec<(u64, usize)> = Vec::new();
        let mut space: u64 = 1;
        for &(cells, k) in &axes {
            if chosen.len() == MAX_GRID_AXES {
                break;
            }
            match space.checked_mul(cells + 2) {
                Some(sp) if sp < 1 << 62 => {
                    space = sp;
                    chosen.push((cells, k));
                }
                _ => break,
            }
        }
        if chosen.is_empty() {
            return Ok(all());
        }
        // Strides: the last chosen axis varies fastest.
        let mut strides = vec![1u64; chosen.len()];
        for a in (0..chosen.len() - 1).rev() {
            strides[a] = strides[a + 1] * (chosen[a + 1].0 + 2);
        }
        let axes = chosen.len();
        // Sorted (key, index) and the gridded coordinates in that order.
        let keyed = |pts: &[T]| -> (Vec<u64>, Vec<u32>, Vec<f64>) {
            let mut order: Vec<(u64, u32)> = pts
                .iter()
                .enumerate()
                .map(|(i, pt)| {
                    // `grid_coordinates` returned Some for every point above.
                    let q = metric.grid_coordinates(pt).unwrap_or(&[]);
                    let key = chosen
                        .iter()
                        .zip(&strides)
                        .map(|(&(_, k), &stride)| (((q[k] - lo[k]) * s) as u64 + 1) * stride)
                        .sum();
                    (key, i as u32)
                })
                .collect();
            crate::math::sort::sort(&mut order);
            let mut coords = Vec::with_capacity(order.len() * axes);
            for &(_, i) in &order {
                let q = metric.grid_coordinates(&pts[i as usize]).unwrap_or(&[]);
                coords.extend(chosen.iter().map(|&(_, k)| q[k]));
            }
            let (keys, idx) = order.into_iter().unzip();
            (keys, idx, coords)
        };
        let (truth_keys, truth_order, truth_coords) = keyed(x);
        let (estimate_keys, estimate_order, estimate_coords) = keyed(y);
        // Offsets in {-1, 0, 1} on every chosen axis but the last.
        let mut deltas = vec![0i64];
        for &stride in &strides[..axes - 1] {
            deltas = deltas
                .iter()
                .flat_map(|&d| [d - stride as i64, d, d + stride as i64])
                .collect();
        }
        Ok(Candidates {
            truth_order,
            estimate_order,
            grid: Some(Grid {
                truth_keys,
                estimate_keys,
                truth_coords,
                estimate_coords,
                axes,
                reach,
                deltas,
            }),
        })
    }

    /// Calls `f(r, k)` once for every candidate pair of internal row `r` and internal column
    /// `k`, in increasing `r` (each row's candidates in one run).
    fn for_each(&self, mut f: impl FnMut(usize, usize) -> Result<()>) -> Result<()> {
        let Some(g) = &self.grid else {
            for r in 0..self.truth_order.len() {
                for k in 0..self.estimate_order.len() {
                    f(r, k)?;
                }
            }
            return Ok(());
        };
        g.for_each_cell(|rows, ranges| match g.axes {
            1 => g.scan::<1>(rows, ranges, &mut f),
            2 => g.scan::<2>(rows, ranges, &mut f),
            _ => g.scan::<3>(rows, ranges, &mut f),
        })
    }

    /// An upper bound on the number of candidate pairs (before the box test), without
    /// looking at any point: `n·m` without a grid.
    fn upper_bound(&self) -> u64 {
        let Some(g) = &self.grid else {
            return (self.truth_order.len() as u64)
                .saturating_mul(self.estimate_order.len() as u64);
        };
        let mut bound = 0u64;
        let _ = g.for_each_cell(|rows, ranges| {
            let cols: usize = ranges.iter().map(|(from, to)| to - from).sum();
            bound = bound.saturating_add(rows.len() as u64 * cols as u64);
            Ok(())
        });
        bound
    }
}

impl Grid {
    /// Calls `f(rows, ranges)` for every cell holding truths: its internal rows and the
    /// ranges of internal columns in the neighbouring cells.
    fn for_each_cell(
        &self,
        mut f: impl FnMut(core::ops::Range<usize>, &[(usize, usize)]) -> Result<()>,
    ) -> Result<()> {
        let keys = &self.estimate_keys;
        let mut ranges: Vec<(usize, usize)> = Vec::with_capacity(self.deltas.len());
        // One pair of cursors per neighbouring line: the rows come in increasing key order, so
        // every range only moves forward (a merge, O(n + m) per line).
        let mut cursors: Vec<(usize, usize)> = vec![(0, 0); self.deltas.len()];
        let mut a = 0;
        while a < self.truth_keys.len() {
            let key = self.truth_keys[a];
            let mut b = a + 1;
            while b < self.truth_keys.len() && self.truth_keys[b] == key {
                b += 1;
            }
            ranges.clear();
            for (&d, (from, to)) in self.deltas.iter().zip(&mut cursors) {
                // Every cell coordinate is ≥ 1, so the neighbours' keys are ≥ 0.
                let centre = (key as i64 + d) as u64;
                while *from < keys.len() && keys[*from] < centre - 1 {
                    *from += 1;
                }
                *to = (*to).max(*from);
                while *to < keys.len() && keys[*to] <= centre + 1 {
                    *to += 1;
                }
                if from < to {
                    ranges.push((*from, *to));
                }
            }
            f(a..b, &ranges)?;
            a = b;
        }
        Ok(())
    }

    /// The candidates of the rows `rows` (one cell) among the columns of `ranges`: those whose
    /// `A` gridded coordinates all differ by less than the reach.
    #[inline]
    fn scan<const A: usize>(
        &self,
        rows: core::ops::Range<usize>,
        ranges: &[(usize, usize)],
        f: &mut impl FnMut(usize, usize) -> Result<()>,
    ) -> Result<()> {
        let (truths, _) = self.truth_coords.as_chunks::<A>();
        let (estimates, _) = self.estimate_coords.as_chunks::<A>();
        for r in rows {
            let t = truths[r];
            for &(from, to) in ranges {
                for (k, e) in estimates[from..to].iter().enumerate() {
                    if (0..A).all(|a| fns::abs(t[a] - e[a]) < self.reach) {
                        f(r, from + k)?;
                    }
                }
            }
        }
        Ok(())
    }
}

/// A connected component stored as a dense matrix: `rows × cols` row-major when there are no
/// more rows than columns, `cols × rows` otherwise (the solver wants the shorter side first).
/// Non-edges cost `c^p`.
pub(crate) struct DenseBlock {
    /// Internal rows, increasing.
    pub rows: Vec<u32>,
    /// Internal columns, increasing.
    pub cols: Vec<u32>,
    /// Start of the matrix in [`CloseGraph::block_costs`].
    pub offset: usize,
}

/// The bipartite graph of the pairs closer than c on the internal numbering (rows and
/// columns in grid order), split into the sparse part (stored by rows) and the dense
/// components (stored as matrices).
pub(crate) struct CloseGraph {
    /// Internal row → truth index.
    pub truth_order: Vec<u32>,
    /// Internal column → estimate index.
    pub estimate_order: Vec<u32>,
    /// Row offsets into `cols`/`costs` (length n + 1; empty for rows not in the sparse part).
    pub start: Vec<usize>,
    /// Internal column of each sparse edge.
    pub cols: Vec<u32>,
    /// `d^p` of each sparse edge.
    pub costs: Vec<f64>,
    /// The internal rows with edges in the sparse part, increasing.
    pub sparse_rows: Vec<u32>,
    /// The dense components.
    pub blocks: Vec<DenseBlock>,
    /// Their matrices, concatenated.
    pub block_costs: Vec<f64>,
}

/// Per-component counts and storage decision.
#[derive(Clone, Copy, Default)]
struct Stat {
    rows: u32,
    cols: u32,
    edges: usize,
    /// Index into the dense blocks, or `u32::MAX` for the sparse part.
    block: u32,
}

fn out_of_memory(pairs: usize) -> Error {
    Error::parameter(
        PAIRS_FIELD,
        pairs as f64,
        "few enough to allocate (the allocation failed): lower c or split the sets",
    )
}

/// The number of axes the grid indexes for these sets (0: all pairs), for tests.
#[cfg(test)]
pub(crate) fn grid_axes<T, M: Metric<T> + ?Sized>(x: &[T], y: &[T], metric: &M, c: f64) -> usize {
    Candidates::new(x, y, metric, c)
        .ok()
        .and_then(|cands| cands.grid.map(|g| g.axes))
        .unwrap_or(0)
}

/// The graph, whatever the size (for tests).
#[cfg(test)]
pub(crate) fn graph_for_tests<T, M: Metric<T> + ?Sized>(
    x: &[T],
    y: &[T],
    metric: &M,
    c: f64,
    p: f64,
) -> Result<CloseGraph> {
    close_graph(
        x,
        y,
        metric,
        (c, p),
        MAX_CLOSE_PAIRS,
        Candidates::new(x, y, metric, c)?,
    )
}

/// Grows the edge buffers (doubling, at most to `cap`) without aborting on failure.
fn grow(cols: &mut Vec<u32>, costs: &mut Vec<f64>, cap: usize, total: usize) -> Result<()> {
    let want = (2 * cols.len()).max(1024).min(cap) - cols.len();
    cols.try_reserve_exact(want)
        .and_then(|()| costs.try_reserve_exact(want))
        .map_err(|_| out_of_memory(total))
}

/// When the candidates number more than this many per point, the graph is built in two
/// passes (count, then store exactly where each component goes) instead of one: dense
/// components then go straight into their matrices, never through the edge list.
const CANDIDATES_PER_POINT_ONE_PASS: u64 = 16;

fn nondeterministic(i: u32, j: u32, d: f64) -> Error {
    Error::parameter(
        format!("distance(truth[{i}], estimate[{j}])"),
        d,
        "the same value at every call (a deterministic metric)",
    )
}

/// Up to this many pairs (`|X|·|Y|`), the whole problem is solved as one dense assignment:
/// below it the fixed cost of the grid and the graph outweighs anything they save.
const SMALL_PROBLEM: usize = 1 << 10;
/// Up to this many pairs (32 MiB of costs), a problem the grid cannot split (every point
/// within about 3c of the others on every axis, so that a large share of all pairs is close,
/// or coordinates too spread for a grid) is solved as one dense assignment: one pass over the
/// pairs instead of two. Above it, the two-pass graph keeps the memory at the pairs closer
/// than c.
const DIRECT_DENSE_MAX: usize = 1 << 22;

/// How a problem is solved.
pub(crate) enum Problem {
    /// The full `min(d, c)^p` matrix, row-major with the smaller set as rows (`transposed`:
    /// the estimates are the rows).
    Dense { costs: Vec<f64>, transposed: bool },
    /// The graph of the pairs closer than c.
    Graph(CloseGraph),
}

#[inline(always)]
fn checked<T, M: Metric<T> + ?Sized>(metric: &M, a: &T, b: &T, i: u32, j: u32) -> Result<f64> {
    let d = metric.distance(a, b);
    if d.is_nan() || d < 0.0 {
        return Err(Error::parameter(
            format!("distance(truth[{i}], estimate[{j}])"),
            d,
            ">= 0 (a metric)",
        ));
    }
    Ok(d)
}

/// The problem of `x` against `y`: a dense matrix for small problems and for problems a grid
/// cannot split (up to [`DIRECT_DENSE_MAX`] pairs), the graph of the pairs closer than c
/// otherwise (see [`close_graph`]).
///
/// # Errors
/// As [`close_graph`].
pub(crate) fn build<T, M: Metric<T> + ?Sized>(
    x: &[T],
    y: &[T],
    metric: &M,
    (c, p): (f64, f64),
    cap: usize,
    force_graph: bool,
) -> Result<Problem> {
    let (n, m) = (x.len(), y.len());
    let pairs = n.saturating_mul(m);
    let candidates = if pairs <= SMALL_PROBLEM && !force_graph {
        // The same coordinate errors as with a grid, whatever the size.
        coordinate_bounds(x, y, metric)?;
        None
    } else {
        let candidates = Candidates::new(x, y, metric, c)?;
        if force_graph || candidates.grid.is_some() || pairs > DIRECT_DENSE_MAX {
            return close_graph(x, y, metric, (c, p), cap, candidates).map(Problem::Graph);
        }
        Some(candidates)
    };
    drop(candidates);
    check_dense_work(dense_work(n, m))?;
    let cp = fns::powp(c, p);
    let transposed = n > m;
    let mut costs: Vec<f64> = Vec::new();
    costs
        .try_reserve_exact(pairs)
        .map_err(|_| out_of_memory(pairs))?;
    costs.resize(pairs, cp);
    for (i, a) in x.iter().enumerate() {
        for (j, b) in y.iter().enumerate() {
            let d = checked(metric, a, b, i as u32, j as u32)?;
            if d < c {
                costs[if transposed { j * n + i } else { i * m + j }] = fns::powp(d, p);
            }
        }
    }
    Ok(Problem::Dense { costs, transposed })
}

/// Builds the graph of the pairs with `metric.distance(x_i, y_j) < c`, edge costs `d^p`.
///
/// The candidate pairs come in row order. Where they are few (at most 16 per point, as in
/// scenes where every point has a bounded number of neighbours within c), one pass stores the
/// edges by rows and joins the components (union-find), and components at least half full
/// (and not tiny) are then copied into dense matrices: memory `O(n + m)` plus 12 bytes per
/// edge, plus at most 16 per edge of a dense component. Otherwise (a large share of all
/// pairs may be close) a first pass counts the edges and joins the components without
/// storing anything — an input over `cap` fails there — and a second stores each edge where
/// its component goes: 12 bytes per sparse edge, at most 16 per dense one.
///
/// # Errors
/// `distance(truth[i], estimate[j])` for a NaN or negative distance (or a metric that
/// changes its mind between the passes), [`PAIRS_FIELD`] beyond `cap` or when an allocation
/// fails, and the grid's coordinate errors.
fn close_graph<T, M: Metric<T> + ?Sized>(
    x: &[T],
    y: &[T],
    metric: &M,
    (c, p): (f64, f64),
    cap: usize,
    candidates: Candidates,
) -> Result<CloseGraph> {
    let (n, m) = (x.len(), y.len());
    let (to, eo) = (&candidates.truth_order, &candidates.estimate_order);
    let distance = |r: usize, k: usize| -> Result<f64> {
        let (i, j) = (to[r], eo[k]);
        checked(metric, &x[i as usize], &y[j as usize], i, j)
    };
    let bound = candidates.upper_bound();
    if bound > MAX_CANDIDATE_PAIRS as u64 {
        return Err(Error::parameter(
            CANDIDATES_FIELD,
            bound as f64,
            "at most MAX_CANDIDATE_PAIRS (2^28 on 64-bit targets, 2^26 on 32-bit targets such \
             as wasm32; the pairs in neighbouring grid cells of width c, or all pairs without a \
             grid): lower c or split the sets",
        ));
    }
    let two_pass =
        bound > cap as u64 || bound > CANDIDATES_PER_POINT_ONE_PASS.saturating_mul((n + m) as u64);

    // First pass: join components and count edges per row; in one-pass mode also store them.
    let mut forest = UnionFind::new(n + m);
    let mut col_has_edge = vec![false; m];
    // start[r + 1]: in one-pass mode the end of row r's edges (fixed up below for rows
    // without edges); in two-pass mode the degree of row r.
    let mut start = vec![0usize; n + 1];
    let mut cols: Vec<u32> = Vec::new();
    let mut costs: Vec<f64> = Vec::new();
    let mut total = 0usize;
    // The root of the current row's component (rows come in order): one find per edge.
    let mut row_root = (usize::MAX, 0u32);
    candidates.for_each(|r, k| {
        let d = distance(r, k)?;
        if d < c {
            total += 1;
            if total > cap {
                if total == cap + 1 {
                    // Only count from here on (the error needs the count).
                    cols = Vec::new();
                    costs = Vec::new();
                }
                return Ok(());
            }
            if two_pass {
                start[r + 1] += 1;
            } else {
                if cols.len() == cols.capacity() {
                    grow(&mut cols, &mut costs, cap, total)?;
                }
                cols.push(k as u32);
                costs.push(fns::powp(d, p));
                start[r + 1] = cols.len();
            }
            if row_root.0 != r {
                row_root = (r, forest.find(r as u32));
            }
            let col_root = forest.find((n + k) as u32);
            if col_root != row_root.1 {
                row_root.1 = forest.link(row_root.1, col_root);
            }
            col_has_edge[k] = true;
        }
        Ok(())
    })?;
    if total > cap {
        return Err(Error::parameter(PAIRS_FIELD, total as f64, PAIRS_EXPECTED));
    }
    let mut degree = vec![0u32; n];
    for r in 0..n {
        if two_pass {
            degree[r] = start[r + 1] as u32;
        } else {
            start[r + 1] = start[r + 1].max(start[r]);
            degree[r] = (start[r + 1] - start[r]) as u32;
        }
    }

    // Components, numbered by first appearance (rows, then columns), with the local index of
    // each vertex inside its component.
    let mut comp_of_root = vec![u32::MAX; n + m];
    let mut comp_row = vec![u32::MAX; n];
    let mut comp_col = vec![u32::MAX; m];
    let mut local = vec![0u32; n + m];
    let mut stats: Vec<Stat> = Vec::new();
    for r in (0..n).filter(|&r| degree[r] > 0) {
        let root = forest.find(r as u32) as usize;
        if comp_of_root[root] == u32::MAX {
            comp_of_root[root] = stats.len() as u32;
            stats.push(Stat::default());
        }
        let id = comp_of_root[root];
        let st = &mut stats[id as usize];
        comp_row[r] = id;
        local[r] = st.rows;
        st.rows += 1;
        st.edges += degree[r] as usize;
    }
    for k in (0..m).filter(|&k| col_has_edge[k]) {
        let id = comp_of_root[forest.find((n + k) as u32) as usize];
        let st = &mut stats[id as usize];
        comp_col[k] = id;
        local[n + k] = st.cols;
        st.cols += 1;
    }
    drop(forest);
    drop(comp_of_root);
    drop(col_has_edge);

    // Dense blocks for components at least half full and not tiny; rows otherwise.
    let mut blocks: Vec<DenseBlock> = Vec::new();
    let mut dense_len = 0usize;
    for st in &mut stats {
        let entries = u64::from(st.rows) * u64::from(st.cols);
        st.block = u32::MAX;
        if entries >= DENSE_MIN_ENTRIES && entries <= 2 * st.edges as u64 {
            st.block = blocks.len() as u32;
            blocks.push(DenseBlock {
                rows: Vec::with_capacity(st.rows as usize),
                cols: Vec::with_capacity(st.cols as usize),
                offset: dense_len,
            });
            dense_len += entries as usize;
        }
    }
    check_dense_work(
        stats
            .iter()
            .filter(|st| st.block != u32::MAX)
            .map(|st| dense_work(st.rows as usize, st.cols as usize))
            .fold(0u64, u64::saturating_add),
    )?;
    let mut sparse_rows: Vec<u32> = Vec::new();
    for r in (0..n).filter(|&r| comp_row[r] != u32::MAX) {
        match stats[comp_row[r] as usize].block {
            u32::MAX => sparse_rows.push(r as u32),
            b => blocks[b as usize].rows.push(r as u32),
        }
    }
    for k in (0..m).filter(|&k| comp_col[k] != u32::MAX) {
        let b = stats[comp_col[k] as usize].block;
        if b != u32::MAX {
            blocks[b as usize].cols.push(k as u32);
        }
    }
    let mut block_costs: Vec<f64> = Vec::new();
    block_costs
        .try_reserve_exact(dense_len)
        .map_err(|_| out_of_memory(total))?;
    block_costs.resize(dense_len, fns::powp(c, p));
    let index = |st: &Stat, r: usize, k: usize| {
        let (a, b) = (local[r] as usize, local[n + k] as usize);
        let offset = blocks[st.block as usize].offset;
        if st.rows <= st.cols {
            offset + a * st.cols as usize + b
        } else {
            offset + b * st.rows as usize + a
        }
    };

    if two_pass {
        // The edge list of the sparse part only, exactly sized, then the second pass.
        for r in 0..n {
            let sparse = comp_row[r] != u32::MAX && stats[comp_row[r] as usize].block == u32::MAX;
            start[r + 1] = start[r] + if sparse { degree[r] as usize } else { 0 };
        }
        let sparse_len = start[n];
        cols.try_reserve_exact(sparse_len)
            .and_then(|()| costs.try_reserve_exact(sparse_len))
            .map_err(|_| out_of_memory(total))?;
        let mut stored = 0usize;
        candidates.for_each(|r, k| {
            let d = distance(r, k)?;
            if d >= c {
                return Ok(());
            }
            let (i, j) = (to[r], eo[k]);
            let id = comp_row[r];
            if id == u32::MAX || id != comp_col[k] {
                return Err(nondeterministic(i, j, d));
            }
            let st = &stats[id as usize];
            if st.block == u32::MAX {
                if cols.len() < start[r] || cols.len() >= start[r + 1] {
                    return Err(nondeterministic(i, j, d));
                }
                cols.push(k as u32);
                costs.push(fns::powp(d, p));
            } else {
                block_costs[index(st, r, k)] = fns::powp(d, p);
            }
            stored += 1;
            Ok(())
        })?;
        if stored != total || cols.len() != sparse_len {
            return Err(Error::parameter(
                "distance(truth, estimate)",
                stored as f64,
                "the same value at every call (a deterministic metric)",
            ));
        }
    } else {
        for st in stats.iter().filter(|st| st.block != u32::MAX) {
            for &r in &blocks[st.block as usize].rows {
                for e in start[r as usize]..start[r as usize + 1] {
                    block_costs[index(st, r as usize, cols[e] as usize)] = costs[e];
                }
            }
        }
    }
    Ok(CloseGraph {
        truth_order: candidates.truth_order,
        estimate_order: candidates.estimate_order,
        start,
        cols,
        costs,
        sparse_rows,
        blocks,
        block_costs,
    })
}

/// Disjoint sets with path halving and union by size (32-bit indices).
struct UnionFind {
    parent: Vec<u32>,
    size: Vec<u32>,
}

impl UnionFind {
    fn new(n: usize) -> Self {
        Self {
            parent: (0..n as u32).collect(),
            size: vec![1; n],
        }
    }

    fn find(&mut self, mut v: u32) -> u32 {
        while self.parent[v as usize] != v {
            let grand = self.parent[self.parent[v as usize] as usize];
            self.parent[v as usize] = grand;
            v = grand;
        }
        v
    }

    /// Joins the sets of the distinct roots `a` and `b`; returns the new root.
    fn link(&mut self, mut a: u32, mut b: u32) -> u32 {
        if self.size[a as usize] < self.size[b as usize] {
            core::mem::swap(&mut a, &mut b);
        }
        self.parent[b as usize] = a;
        self.size[a as usize] += self.size[b as usize];
        a
    }
}
