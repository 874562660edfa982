//! A dense shortest-augmenting-path solver tuned for contiguous rows (crate-internal).
//!
//! It solves the inner problem of OSPA and GOSPA where most pairs of points are closer than c:
//! for GOSPA (α = 2) the minimum over assignments γ of `Σ_{(i,j)∈γ} d(x_i, y_j)^p + (c^p/2)
//! (|X| + |Y| − 2|γ|)` (paper 003, García-Fernández & Svensson 2019, Prop. 3, eq. 1), computed
//! as one assignment on the matrix `min(d, c)^p` (see `metrics::cutoff_assignment`), and every
//! [`crate::math::linear_assignment`].
//!
//! The same method as [`super::assignment::sap`] — Jonker–Volgenant's augmentation step in
//! the rectangular form of Crouse (Algorithm 1), one Dijkstra search over reduced costs per
//! row with duals `u`, `v` kept feasible and tight on the assignment — organised so that the
//! work of a search, `O(columns)` per row it scans, runs over contiguous memory:
//!
//! - the relaxation of a scanned row is a branch-free pass over all columns,
//!   `d[j] = min(d[j], h + C[i, j] − v[j])` with `h = min_val − u[i]`, which the compiler
//!   turns into SIMD minimum operations; it also returns the minimum of `d`. Columns already
//!   scanned are kept out of it by setting `d[j] = +∞` and (for the time of the search)
//!   `v[j] = −∞`, so that `h + C[i, j] − v[j] = +∞` never lowers them: no index list, no
//!   mask, no bounds checks in the loop;
//! - the predecessor of each column (the row whose relaxation set `d[j]`) is not stored in
//!   the loop: the path back from the free column is recovered after the search by
//!   recomputing `h + C[i, j] − v[j]` for the rows scanned before `j` and taking the first
//!   whose value equals `d[j]` exactly (the same operations on the same operands give the same
//!   double, and the minimum is one of them);
//! - as in LAPJV, all columns at the current minimum distance are taken together (Jonker &
//!   Volgenant's SCAN set): a free one among them ends the search at once — with GOSPA's
//!   cut-off, where many costs tie at `c^p`, this keeps paths short — otherwise all their rows
//!   are scanned before the next minimum is looked for.
//!
//! Square problems first take JV's column reduction (`v_j = min_i C[i, j]`, each column's
//! cheapest row assigned to it while free), so that only the rows left free search; JV's
//! augmenting row reduction is not used (on GOSPA's dense scenes it costs more than it saves:
//! `lap.lapjv` is 4–6× slower than SciPy's plain shortest augmenting paths there).
//!
//! It is exact in the same sense as `sap`: an optimal assignment up to the rounding of the
//! dual updates; the assignment may differ from `sap`'s among ties.
//!
//! # References
//! - R. Jonker, A. Volgenant, "A shortest augmenting path algorithm for dense and sparse linear
//!   assignment problems," Computing 38:325–340, 1987. doi:10.1007/BF02278710 — the
//!   augmentation procedure (Dijkstra with the SCAN/TODO/READY sets).
//! - D. F. Crouse, "On implementing 2D rectangular assignment algorithms," IEEE Trans. Aerosp.
//!   Electron. Syst. 52(4):1679–1696, 2016. doi:10.1109/TAES.2016.140952 — Algorithm 1 (the
//!   rectangular form and its dual update).

use alloc::vec;
use alloc::vec::Vec;

const NONE: usize = usize::MAX;
const LANES: usize = 4;

/// `d[j] = min(d[j], h + row[j] − v[j])` for every column; returns the new `min_j d[j]`.
#[inline]
fn relax(row: &[f64], h: f64, v: &[f64], d: &mut [f64]) -> f64 {
    let n = d.len();
    let (row, v) = (&row[..n], &v[..n]);
    let mut acc = [f64::INFINITY; LANES];
    let (dc, dt) = d.as_chunks_mut::<LANES>();
    let (rc, rt) = row.as_chunks::<LANES>();
    let (vc, vt) = v.as_chunks::<LANES>();
    for ((dk, rk), vk) in dc.iter_mut().zip(rc).zip(vc) {
        for l in 0..LANES {
            let x = h + rk[l] - vk[l];
            let y = if x < dk[l] { x } else { dk[l] };
            dk[l] = y;
            acc[l] = if y < acc[l] { y } else { acc[l] };
        }
    }
    let mut lowest = f64::INFINITY;
    for ((dk, &rk), &vk) in dt.iter_mut().zip(rt).zip(vt) {
        let x = h + rk - vk;
        if x < *dk {
            *dk = x;
        }
        if *dk < lowest {
            lowest = *dk;
        }
    }
    for a in acc {
        if a < lowest {
            lowest = a;
        }
    }
    lowest
}

/// Pushes every `j` with `d[j] == value` onto `out`.
#[inline]
fn positions_of(d: &[f64], value: f64, out: &mut Vec<usize>) {
    let (dc, dt) = d.as_chunks::<LANES>();
    for (c, dk) in dc.iter().enumerate() {
        if dk.iter().fold(false, |any, &x| any | (x == value)) {
            for (l, &x) in dk.iter().enumerate() {
                if x == value {
                    out.push(c * LANES + l);
                }
            }
        }
    }
    let base = dc.len() * LANES;
    for (l, &x) in dt.iter().enumerate() {
        if x == value {
            out.push(base + l);
        }
    }
}

/// Shortest augmenting paths for `nr ≤ nc` on the row-major `nr × nc` matrix `cost` (finite
/// entries, magnitudes such that sums of `nr` of them do not overflow); returns the column of
/// each row. See the module documentation.
pub(crate) fn solve(cost: &[f64], nr: usize, nc: usize) -> Vec<usize> {
    debug_assert!(nr <= nc && cost.len() == nr * nc);
    let mut u = vec![0.0f64; nr];
    let mut v = vec![0.0f64; nc];
    let mut col4row = vec![NONE; nr];
    let mut row4col = vec![NONE; nc];
    // Tentative distances of the columns not yet scanned (+∞ for scanned ones).
    let mut d = vec![f64::INFINITY; nc];
    // For scanned columns: their distance, their dual before the search, and how many rows
    // had been scanned when they were (their predecessor is among those).
    let mut fin = vec![0.0f64; nc];
    let mut saved_v = vec![0.0f64; nc];
    let mut rows_before = vec![0usize; nc];
    // The rows scanned by the current search, in order, with their `h = min_val − u[i]`.
    let mut scanned_rows: Vec<(usize, f64)> = Vec::with_capacity(nr);
    let mut scanned_cols: Vec<usize> = Vec::with_capacity(nc);
    let mut ties: Vec<usize> = Vec::new();
    let mut path: Vec<(usize, usize)> = Vec::new();

    if nr == nc && nr > 1 {
        // Column reduction (Jonker & Volgenant, square problems only: a column's dual may then
        // be positive): v_j = min_i C[i, j], u = 0, each column's first cheapest row takes it
        // if still free (columns in reverse order, as in JV).
        v.copy_from_slice(&cost[..nc]);
        let mut arg = vec![0usize; nc];
        for (i, row) in cost.chunks_exact(nc).enumerate().skip(1) {
            for ((vj, aj), &c) in v.iter_mut().zip(arg.iter_mut()).zip(row) {
                if c < *vj {
                    *vj = c;
                    *aj = i;
                }
            }
        }
        for j in (0..nc).rev() {
            let i = arg[j];
            if col4row[i] == NONE {
                col4row[i] = j;
                row4col[j] = i;
            }
        }
    }
    for cur in 0..nr {
        if col4row[cur] != NONE {
            continue;
        }
        d.fill(f64::INFINITY);
        let h = -u[cur];
        scanned_rows.push((cur, h));
        let mut lowest = relax(&cost[cur * nc..(cur + 1) * nc], h, &v, &mut d);
        let sink = loop {
            ties.clear();
            positions_of(&d, lowest, &mut ties);
            if let Some(&j) = ties.iter().find(|&&j| row4col[j] == NONE) {
                break j;
            }
            // No free column at this distance: scan all of them.
            let min_val = lowest;
            for &j in &ties {
                fin[j] = min_val;
                saved_v[j] = v[j];
                rows_before[j] = scanned_rows.len();
                d[j] = f64::INFINITY;
                v[j] = f64::NEG_INFINITY;
                scanned_cols.push(j);
            }
            for &j in &ties {
                let i = row4col[j];
                let h = min_val - u[i];
                scanned_rows.push((i, h));
                lowest = relax(&cost[i * nc..(i + 1) * nc], h, &v, &mut d);
            }
        };
        let min_val = lowest;

        // The alternating path back from the sink: each column's predecessor is the first
        // row, among those scanned before it, whose relaxation gave its distance.
        path.clear();
        let (mut j, mut target, mut vj, mut limit) = (sink, min_val, v[sink], scanned_rows.len());
        loop {
            // (Falls back to `cur`, which keeps the assignment one-to-one, should no value match.)
            let mut best = (f64::INFINITY, cur);
            for &(i, h) in &scanned_rows[..limit] {
                let gap = crate::math::fns::abs(h + cost[i * nc + j] - vj - target);
                if gap < best.0 {
                    best = (gap, i);
                    if gap == 0.0 {
                        break;
                    }
                }
            }
            let i = best.1;
            path.push((i, j));
            if i == cur {
                break;
            }
            j = col4row[i];
            (target, vj, limit) = (fin[j], saved_v[j], rows_before[j]);
        }

        // Dual update (Crouse, Algorithm 1): feasible everywhere, tight on the assignment.
        u[cur] += min_val;
        for &(i, _) in &scanned_rows[1..] {
            u[i] += min_val - fin[col4row[i]];
        }
        for &j in &scanned_cols {
            v[j] = saved_v[j] - (min_val - fin[j]);
        }
        scanned_rows.clear();
        scanned_cols.clear();

        for &(i, j) in &path {
            row4col[j] = i;
            col4row[i] = j;
        }
    }
    col4row
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::assignment::{sap, tests::brute_force};
    use rand::{RngExt, SeedableRng, rngs::SmallRng};

    /// Solves any `rows × cols` matrix (transposing when `rows > cols`); returns the pairs and
    /// their total, checking that the assignment is one-to-one and complete.
    fn solve_any(
        cost: &[f64],
        rows: usize,
        cols: usize,
        solver: fn(&[f64], usize, usize) -> Vec<usize>,
    ) -> f64 {
        let pairs: Vec<(usize, usize)> = if rows <= cols {
            solver(cost, rows, cols).into_iter().enumerate().collect()
        } else {
            let mut t = vec![0.0; rows * cols];
            for i in 0..rows {
                for j in 0..cols {
                    t[j * rows + i] = cost[i * cols + j];
                }
            }
            solver(&t, cols, rows)
                .into_iter()
                .enumerate()
                .map(|(j, i)| (i, j))
                .collect()
        };
        assert_eq!(pairs.len(), rows.min(cols));
        let (mut seen_r, mut seen_c) = (vec![false; rows], vec![false; cols]);
        for &(i, j) in &pairs {
            assert!(
                i < rows && j < cols && !seen_r[i] && !seen_c[j],
                "not one-to-one: {pairs:?}"
            );
            seen_r[i] = true;
            seen_c[j] = true;
        }
        pairs.iter().map(|&(i, j)| cost[i * cols + j]).sum()
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-9 * (1.0 + b.abs())
    }

    /// A random matrix of one of several kinds: continuous, heavy ties, zeros, wide dynamic
    /// range, tiny and large scales, and GOSPA's min(d, c)^2 of random points.
    fn matrix(rng: &mut SmallRng, rows: usize, cols: usize, kind: usize) -> Vec<f64> {
        let pts = |rng: &mut SmallRng, k: usize| -> Vec<[f64; 2]> {
            (0..k)
                .map(|_| [rng.random_range(0.0..4.0), rng.random_range(0.0..4.0)])
                .collect()
        };
        if kind == 6 {
            let (x, y) = (pts(rng, rows), pts(rng, cols));
            let c = 1.5f64;
            return x
                .iter()
                .flat_map(|a| {
                    y.iter().map(move |b| {
                        let d2 = (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2);
                        d2.min(c * c)
                    })
                })
                .collect();
        }
        (0..rows * cols)
            .map(|_| match kind {
                0 => rng.random_range(-5.0..10.0),
                1 => f64::from(rng.random_range(0..3u8)),
                2 => {
                    if rng.random_range(0..4u8) == 0 {
                        rng.random_range(0.0..1.0)
                    } else {
                        0.0
                    }
                }
                3 => rng.random_range(0.0..1.0f64).powi(8) * 1e6,
                4 => rng.random_range(0.0..1.0) * 1e-300,
                _ => rng.random_range(-1.0..1.0) * 1e200,
            })
            .collect()
    }

    #[test]
    fn matches_brute_force_up_to_size_8() {
        let mut rng = SmallRng::seed_from_u64(3);
        for rows in 0..=8 {
            for cols in 0..=8 {
                let trials = if rows.max(cols) >= 7 { 7 } else { 35 };
                for t in 0..trials {
                    let cost = matrix(&mut rng, rows, cols, t % 7);
                    let got = solve_any(&cost, rows, cols, solve);
                    let best = brute_force(&cost, rows, cols);
                    assert!(
                        close(got, best),
                        "{rows}x{cols} kind {}: {got} vs {best}; {cost:?}",
                        t % 7
                    );
                }
            }
        }
    }

    #[test]
    fn matches_the_reference_solver_on_dense_50_to_300() {
        let mut rng = SmallRng::seed_from_u64(11);
        for (t, &(rows, cols)) in [
            (50, 50),
            (80, 120),
            (120, 80),
            (200, 200),
            (300, 300),
            (150, 290),
            (300, 64),
        ]
        .iter()
        .enumerate()
        {
            for kind in 0..7 {
                let cost = matrix(&mut rng, rows, cols, (kind + t) % 7);
                let got = solve_any(&cost, rows, cols, solve);
                let reference = solve_any(&cost, rows, cols, sap);
                let scale = cost.iter().fold(0.0f64, |a, c| a.max(c.abs())) * rows.min(cols) as f64;
                assert!(
                    (got - reference).abs()
                        <= 1e-9 * (reference.abs() + scale * 1e-6).max(f64::MIN_POSITIVE),
                    "{rows}x{cols} kind {kind}: {got} vs {reference}"
                );
            }
        }
    }

    #[test]
    fn degenerate_matrices() {
        assert!(solve(&[], 0, 0).is_empty());
        assert!(solve(&[], 0, 5).is_empty());
        assert_eq!(solve(&[7.0], 1, 1), vec![0]);
        assert_eq!(solve(&[3.0, 1.0, 2.0], 1, 3), vec![1]);
        // All equal: any complete assignment, every column distinct.
        for (r, c) in [(1, 1), (3, 4), (10, 10), (40, 70)] {
            assert!(close(
                solve_any(&vec![2.5; r * c], r, c, solve),
                2.5 * r.min(c) as f64
            ));
            assert!(close(solve_any(&vec![0.0; r * c], r, c, solve), 0.0));
        }
        // A permutation matrix of zeros among ones, and its negation.
        let n = 9;
        let perm = |i: usize| (i * 4 + 3) % n;
        let mut cost = vec![1.0; n * n];
        for i in 0..n {
            cost[i * n + perm(i)] = 0.0;
        }
        let a = solve(&cost, n, n);
        assert!((0..n).all(|i| a[i] == perm(i)));
        // Every off-permutation entry is -1, and a derangement of the permutation avoids it.
        let neg: Vec<f64> = cost.iter().map(|c| -c).collect();
        assert!(close(solve_any(&neg, n, n, solve), -(n as f64)));
    }
}
