//! The pairs closer than the cut-off: the candidate search (a uniform grid, or all pairs) and
//! the sparse graph they form, split into its connected components.

use alloc::format;
use alloc::vec;
use alloc::vec::Vec;

use super::Metric;
use crate::error::{Error, Result};
use crate::math::fns;

/// The most pairs closer than the cut-off c that one OSPA/GOSPA evaluation accepts:
/// `2^28 = 268,435,456` on 64-bit targets, `2^26 = 67,108,864` on 32-bit targets (wasm32,
/// whose whole address space is 4 GiB).
///
/// Each such pair takes 12 bytes (its estimate index and cost) in a sparse component, or up to
/// 16 bytes in a dense one (a component stored as a matrix is at least half full), so the cap
/// bounds the graph at 4 GiB natively and 1 GiB in wasm32. Beyond it the call returns
/// [`Error::InvalidParameter`] naming `truth × estimate pairs closer than c` with their count,
/// after a counting pass that allocates nothing. Only scenes where a large share of all pairs
/// lie within c reach it (e.g. two sets of 8,193 points within c of each other in wasm32);
/// scenes where each point has a bounded number of neighbours within c stay far below it at
/// any size.
#[cfg(target_pointer_width = "64")]
pub const MAX_CLOSE_PAIRS: usize = 1 << 28;
/// See the 64-bit documentation: `2^26` on 32-bit targets.
#[cfg(not(target_pointer_width = "64"))]
pub const MAX_CLOSE_PAIRS: usize = 1 << 26;

/// The most points in one set: `2^31 − 1` (indices are stored in 32 bits).
pub const MAX_POINTS: usize = (1 << 31) - 1;

pub(crate) const PAIRS_FIELD: &str = "truth × estimate pairs closer than c";
const PAIRS_EXPECTED: &str = "at most MAX_CLOSE_PAIRS (2^28 on 64-bit targets, 2^26 on 32-bit \
                              targets such as wasm32; up to 16 bytes of memory each): lower c \
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

/// The candidate pairs: a superset of the pairs closer than c.
enum Candidates {
    /// Every pair (no grid coordinates, an empty set, or points that a grid cannot separate).
    All { n: usize, m: usize },
    Grid(Grid),
}

/// A uniform grid on up to three coordinates (those spanning the most cells), with cells of
/// width `h = c (1 + 2^-20)`: only pairs in neighbouring cells (`|Δq_k| ≤ 1` on every gridded
/// axis) are candidates.
///
/// Exactness: with `q_k = ⌊fl(fl(x_k − o_k) · fl(1/h))⌋` (`o_k` the smallest coordinate), two
/// points whose computed distance is below c differ on axis k by less than
/// `c (1 + 10⁻⁹)` (the [`Metric::grid_coordinates`] contract), and the rounding of the cell
/// coordinates adds at most `4.02 ε R` cells for an axis of `R` cells (ε = 2⁻⁵³). Their
/// unrounded cell coordinates then differ by less than
/// `(1 + 10⁻⁹ + 3ε) / (1 + 2⁻²⁰) + 4.02 ε R < 1` whenever `R ≤ 2³⁰` (the bound is reached at
/// `R ≈ 2.1·10⁹`), so their cells are neighbours: the grid never misses a pair closer than c,
/// and the result is bit for bit the one from all pairs (up to the order of equally good
/// assignments). Axes spanning more than 2³⁰ cells are not gridded.
struct Grid {
    /// `(cell key, index)`, sorted.
    truths: Vec<(u64, u32)>,
    /// `(cell key, index)`, sorted.
    estimates: Vec<(u64, u32)>,
    /// Key offsets of the neighbouring lines of cells (all gridded axes but the last, whose
    /// neighbours `key − 1 ..= key + 1` are contiguous).
    deltas: Vec<i64>,
}

impl Candidates {
    fn new<T, M: Metric<T> + ?Sized>(x: &[T], y: &[T], metric: &M, c: f64) -> Result<Self> {
        let (n, m) = (x.len(), y.len());
        let all = Candidates::All { n, m };
        if n == 0 || m == 0 {
            return Ok(all);
        }
        let Some(first) = metric.grid_coordinates(&x[0]) else {
            return Ok(all);
        };
        let dim = first.len();
        let mut lo = vec![f64::INFINITY; dim];
        let mut hi = vec![f64::NEG_INFINITY; dim];
        for (name, pts) in [("truth", x), ("estimate", y)] {
            for (i, pt) in pts.iter().enumerate() {
                let Some(q) = metric.grid_coordinates(pt) else {
                    return Ok(Candidates::All { n, m });
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
        let s = 1.0 / (c * GRID_MARGIN);
        // (cells, axis) for the axes worth gridding, most cells first.
        let mut axes: Vec<(u64, usize)> = (0..dim)
            .filter_map(|k| {
                let span = (hi[k] - lo[k]) * s;
                // floor(span) + 1 cells; fewer than 4 prune nothing with ±1 neighbours.
                (span.is_finite() && span < MAX_CELLS_PER_AXIS && span >= 3.0)
                    .then(|| (span as u64 + 1, k))
            })
            .collect();
        axes.sort_unstable_by(|a, b| b.0.cmp(&a.0).then(a.1.cmp(&b.1)));
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
            return Ok(all);
        }
        // Strides: the last chosen axis varies fastest.
        let mut strides = vec![1u64; chosen.len()];
        for a in (0..chosen.len() - 1).rev() {
            strides[a] = strides[a + 1] * (chosen[a + 1].0 + 2);
        }
        let key = |q: &[f64]| -> u64 {
            chosen
                .iter()
                .zip(&strides)
                .map(|(&(_, k), &stride)| (((q[k] - lo[k]) * s) as u64 + 1) * stride)
                .sum()
        };
        let keyed = |pts: &[T]| -> Vec<(u64, u32)> {
            let mut v: Vec<(u64, u32)> = pts
                .iter()
                .enumerate()
                .map(|(i, pt)| {
                    // `grid_coordinates` returned Some for every point above.
                    let q = metric.grid_coordinates(pt).unwrap_or(&[]);
                    (key(q), i as u32)
                })
                .collect();
            v.sort_unstable();
            v
        };
        let (truths, estimates) = (keyed(x), keyed(y));
        // Offsets in {-1, 0, 1} on every chosen axis but the last.
        let mut deltas = vec![0i64];
        for &stride in &strides[..strides.len() - 1] {
            deltas = deltas
                .iter()
                .flat_map(|&d| [d - stride as i64, d, d + stride as i64])
                .collect();
        }
        Ok(Candidates::Grid(Grid {
            truths,
            estimates,
            deltas,
        }))
    }

    /// Calls `f(i, j)` once for every candidate pair, grouped by truth `i` (each truth's
    /// candidates in one run).
    fn for_each(&self, mut f: impl FnMut(usize, usize) -> Result<()>) -> Result<()> {
        match self {
            Candidates::All { n, m } => {
                for i in 0..*n {
                    for j in 0..*m {
                        f(i, j)?;
                    }
                }
            }
            Candidates::Grid(g) => {
                let mut ranges: Vec<(usize, usize)> = Vec::with_capacity(g.deltas.len());
                let mut a = 0;
                while a < g.truths.len() {
                    let key = g.truths[a].0;
                    let b = a + g.truths[a..].partition_point(|t| t.0 == key);
                    ranges.clear();
                    for &d in &g.deltas {
                        // Every cell coordinate is ≥ 1, so the neighbours' keys are ≥ 0.
                        let centre = (key as i64 + d) as u64;
                        let from = g.estimates.partition_point(|e| e.0 < centre - 1);
                        let to = from + g.estimates[from..].partition_point(|e| e.0 <= centre + 1);
                        if from < to {
                            ranges.push((from, to));
                        }
                    }
                    for &(_, i) in &g.truths[a..b] {
                        for &(from, to) in &ranges {
                            for &(_, j) in &g.estimates[from..to] {
                                f(i as usize, j as usize)?;
                            }
                        }
                    }
                    a = b;
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
    /// Truth indices, increasing.
    pub rows: Vec<u32>,
    /// Estimate indices, increasing.
    pub cols: Vec<u32>,
    /// Start of the matrix in [`CloseGraph::block_costs`].
    pub offset: usize,
}

/// The bipartite graph of the pairs closer than c, split into the sparse part (stored by rows)
/// and the dense components (stored as matrices).
pub(crate) struct CloseGraph {
    /// Row offsets into `cols`/`costs` (length n + 1; empty for rows not in the sparse part).
    pub start: Vec<usize>,
    /// Estimate index of each sparse edge.
    pub cols: Vec<u32>,
    /// `d^p` of each sparse edge.
    pub costs: Vec<f64>,
    /// The truths with edges in the sparse part, increasing.
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

fn nondeterministic(i: usize, j: usize, d: f64) -> Error {
    Error::parameter(
        format!("distance(truth[{i}], estimate[{j}])"),
        d,
        "the same value at every call (a deterministic metric)",
    )
}

fn out_of_memory(pairs: usize) -> Error {
    Error::parameter(
        PAIRS_FIELD,
        pairs as f64,
        "few enough to allocate (the allocation failed): lower c or split the sets",
    )
}

/// Builds the graph of the pairs with `metric.distance(x_i, y_j) < c`, edge costs `d^p`.
///
/// Two passes over the candidate pairs: the first counts the edges and joins the components
/// (union-find), allocating `O(n + m)`; then, unless there are more than `cap` edges, the
/// second stores them (exactly sized, `O(n + m + E)`).
///
/// # Errors
/// `distance(truth[i], estimate[j])` for a NaN or negative distance (or a metric that changes
/// its mind between the passes), [`PAIRS_FIELD`] beyond `cap` or when the allocation fails,
/// and the grid's coordinate errors.
pub(crate) fn close_graph<T, M: Metric<T> + ?Sized>(
    x: &[T],
    y: &[T],
    metric: &M,
    c: f64,
    p: f64,
    cap: usize,
) -> Result<CloseGraph> {
    let (n, m) = (x.len(), y.len());
    let candidates = Candidates::new(x, y, metric, c)?;

    // Pass 1: count and join.
    let mut forest = UnionFind::new(n + m);
    let mut degree = vec![0u32; n];
    let mut col_has_edge = vec![false; m];
    let mut total = 0usize;
    candidates.for_each(|i, j| {
        let d = metric.distance(&x[i], &y[j]);
        if d.is_nan() || d < 0.0 {
            return Err(Error::parameter(
                format!("distance(truth[{i}], estimate[{j}])"),
                d,
                ">= 0 (a metric)",
            ));
        }
        if d < c {
            total += 1;
            forest.union(i as u32, (n + j) as u32);
            degree[i] += 1;
            col_has_edge[j] = true;
        }
        Ok(())
    })?;
    if total > cap {
        return Err(Error::parameter(PAIRS_FIELD, total as f64, PAIRS_EXPECTED));
    }

    // Components, numbered by first appearance (rows in index order, then columns), with
    // the local index of each vertex inside its component.
    let mut comp_of_root = vec![u32::MAX; n + m];
    let mut comp_row = vec![u32::MAX; n];
    let mut comp_col = vec![u32::MAX; m];
    let mut local = vec![0u32; n + m];
    let mut stats: Vec<Stat> = Vec::new();
    for i in (0..n).filter(|&i| degree[i] > 0) {
        let root = forest.find(i as u32) as usize;
        if comp_of_root[root] == u32::MAX {
            comp_of_root[root] = stats.len() as u32;
            stats.push(Stat::default());
        }
        let id = comp_of_root[root];
        let st = &mut stats[id as usize];
        comp_row[i] = id;
        local[i] = st.rows;
        st.rows += 1;
        st.edges += degree[i] as usize;
    }
    for j in (0..m).filter(|&j| col_has_edge[j]) {
        let id = comp_of_root[forest.find((n + j) as u32) as usize];
        let st = &mut stats[id as usize];
        comp_col[j] = id;
        local[n + j] = st.cols;
        st.cols += 1;
    }
    drop(forest);
    drop(comp_of_root);

    // Storage: dense blocks for components at least half full and not tiny, rows otherwise.
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
    let mut start = vec![0usize; n + 1];
    let mut sparse_rows: Vec<u32> = Vec::new();
    for i in 0..n {
        let mut len = 0;
        if comp_row[i] != u32::MAX {
            let b = stats[comp_row[i] as usize].block;
            if b == u32::MAX {
                sparse_rows.push(i as u32);
                len = degree[i] as usize;
            } else {
                blocks[b as usize].rows.push(i as u32);
            }
        }
        start[i + 1] = start[i] + len;
    }
    for j in 0..m {
        if comp_col[j] != u32::MAX {
            let b = stats[comp_col[j] as usize].block;
            if b != u32::MAX {
                blocks[b as usize].cols.push(j as u32);
            }
        }
    }
    let sparse_len = start[n];
    let cp = fns::powp(c, p);
    let mut cols: Vec<u32> = Vec::new();
    let mut costs: Vec<f64> = Vec::new();
    let mut block_costs: Vec<f64> = Vec::new();
    cols.try_reserve_exact(sparse_len)
        .and_then(|()| costs.try_reserve_exact(sparse_len))
        .and_then(|()| block_costs.try_reserve_exact(dense_len))
        .map_err(|_| out_of_memory(total))?;
    cols.resize(sparse_len, 0);
    costs.resize(sparse_len, 0.0);
    block_costs.resize(dense_len, cp);

    // Pass 2: store. `degree` becomes the fill count of each sparse row.
    degree.iter_mut().for_each(|d| *d = 0);
    let mut stored = 0usize;
    candidates.for_each(|i, j| {
        let d = metric.distance(&x[i], &y[j]);
        if !(d < c) {
            return Ok(());
        }
        let id = comp_row[i];
        if id == u32::MAX || id != comp_col[j] {
            return Err(nondeterministic(i, j, d));
        }
        let cost = fns::powp(d, p);
        let st = stats[id as usize];
        if st.block == u32::MAX {
            let pos = start[i] + degree[i] as usize;
            if pos >= start[i + 1] {
                return Err(nondeterministic(i, j, d));
            }
            cols[pos] = j as u32;
            costs[pos] = cost;
            degree[i] += 1;
        } else {
            let block = &blocks[st.block as usize];
            let (a, b) = (local[i] as usize, local[n + j] as usize);
            let index = if st.rows <= st.cols {
                a * st.cols as usize + b
            } else {
                b * st.rows as usize + a
            };
            block_costs[block.offset + index] = cost;
        }
        stored += 1;
        Ok(())
    })?;
    if stored != total
        || sparse_rows
            .iter()
            .any(|&i| start[i as usize] + degree[i as usize] as usize != start[i as usize + 1])
    {
        return Err(Error::parameter(
            "distance(truth, estimate)",
            stored as f64,
            "the same value at every call (a deterministic metric)",
        ));
    }
    Ok(CloseGraph {
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

    fn union(&mut self, a: u32, b: u32) {
        let (mut a, mut b) = (self.find(a), self.find(b));
        if a == b {
            return;
        }
        if self.size[a as usize] < self.size[b as usize] {
            core::mem::swap(&mut a, &mut b);
        }
        self.parent[b as usize] = a;
        self.size[a as usize] += self.size[b as usize];
    }
}
