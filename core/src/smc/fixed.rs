//! The fixed-size kernels of eq. (20) of paper `004` (Ristic & Vo) for the small sets of the
//! sensor control's future scans: the sum of [`super::matchings`] in plain arithmetic on
//! stack tables, unrolled for sizes known at compile time, with the operations of the general
//! programme in the same order (hence its bits) when there are more objects than
//! measurements or no measurement; otherwise the last row is folded into the final sum,
//! which agrees with the general programme within 10⁻¹⁵ relatively.

use super::matchings::{dp_row, fold_columns};

/// The largest smaller side [`sum_matchings_small`] handles (a fixed 16-entry table).
pub(super) const SMALL_SIDE: usize = 4;

/// The largest larger side of [`super::batch::BatchLikelihood`].
pub(super) const MAX_LARGER: usize = 16;

/// Scratch tables of [`super::batch::BatchLikelihood`] for the sizes without a fixed kernel:
/// the pair factors and the objects' miss factors 1 − p_D.
#[derive(Clone, Debug)]
pub(super) struct SmallTables {
    pub(super) pair: [f64; MAX_LARGER * SMALL_SIDE],
    pub(super) miss: [f64; MAX_LARGER],
}

/// The sum of [`super::matchings::ln_sum_matchings`] in plain arithmetic, for the small sizes of the sensor
/// control's future scans: `pair`, `row_miss`, `col_miss` are the factors themselves (not
/// their logs), all in [0, 1], and `cols ≤ SMALL_SIDE`. No scaling is needed: with factors
/// ≤ 1 no partial product overflows, and the only loss beyond rounding is gradual
/// underflow, bounded as in [`super::matchings::ln_sum_matchings`] by e^{−700} (rows·(k+1)·2^k ≤ e^44 roundings
/// of ≤ 2^{−1074} each, none amplified). `None` when the sum is not e^{30} above that bound
/// (the caller then takes the exact log-space path), else `Some(Σ)` with Σ > 0.
#[inline]
pub(super) fn sum_matchings_small(
    rows: usize,
    cols: usize,
    pair: &[f64],
    row_miss: &[f64],
    col_miss: &[f64],
) -> Option<f64> {
    debug_assert!(cols <= SMALL_SIDE && rows < 1 << 20);
    debug_assert_eq!(pair.len(), rows * cols);
    debug_assert!(row_miss.len() >= rows && col_miss.len() >= cols);
    // One fixed-size table per column count, so that the compiler unrolls the subset loops;
    // the operations and their order are those of `dp_row` on a 2^cols table (same bits).
    let total = match cols {
        0 => sum_small::<1>(rows, pair, row_miss, col_miss),
        1 => sum_small::<2>(rows, pair, row_miss, col_miss),
        2 => sum_small::<4>(rows, pair, row_miss, col_miss),
        3 => sum_small::<8>(rows, pair, row_miss, col_miss),
        _ => sum_small::<16>(rows, pair, row_miss, col_miss),
    };
    if total > SMALL_FLOOR {
        Some(total)
    } else {
        None
    }
}

/// e^{−670} = e^{30} · e^{−700}, the acceptance margin of `ln_sum_matchings`: plain sums
/// below it are redone in log space.
pub(super) const SMALL_FLOOR: f64 = 1.1e-291;

/// `$body` once for each of the literals, in the order given, with `$i` bound to it: a loop
/// that the compiler sees unrolled, every index a constant.
macro_rules! unrolled {
    ($i:ident in [$($k:literal)*] $body:block) => {
        $({
            let $i: usize = $k;
            $body
        })*
    };
}

/// |S| for the subsets S of [`SMALL_SIDE`] columns. After r rows of the subset programme of
/// eq. (20) of paper `004` only the subsets of at most r columns can hold a non-zero sum (a
/// partial matching of r rows uses at most r columns), so [`sum_fixed`] and
/// [`sum_fixed_lanes`] skip the others in row r (0-based: |S| > r + 1) and start the sum of
/// a subset of exactly r + 1 columns at its first pair term (its previous value is 0). With
/// every factor finite and ≥ 0 the skipped terms are exact zeros and x + 0 = x, so this
/// changes no bit of the result.
const SUBSET_SIZE: [u8; 1 << SMALL_SIDE] = {
    let mut t = [0u8; 1 << SMALL_SIDE];
    let mut s = 0;
    while s < t.len() {
        t[s] = (s as u32).count_ones() as u8;
        s += 1;
    }
    t
};

/// [`sum_matchings_small`] for N objects and M measurements known at compile time (so that
/// every loop unrolls), the pair factors from `factor(i, j)`, the objects' miss factor `miss`
/// and the measurements' `clutter[j]`: [`sum_fixed_lanes`] of one lane.
#[inline(always)]
pub(super) fn sum_fixed<const N: usize, const M: usize>(
    miss: f64,
    clutter: &[f64],
    factor: &impl Fn(usize, usize) -> f64,
) -> f64 {
    sum_fixed_lanes::<N, M, 1>(miss, clutter, &|o, j| [factor(o, j)])[0]
}

/// [`sum_fixed`] for `L` sets of N objects at once (the lanes, e.g. consecutive particles of
/// one cardinality against the same scan): `factor(i, j)` gives the pair factors
/// p_D g(z_j | x_i) of eq. (20) of paper `004` of the `L` sets, `miss` and `clutter` are
/// shared. Each lane goes through exactly the operations of [`sum_fixed`] in the same order
/// (an array of lanes in place of each number), so each lane's result has [`sum_fixed`]'s
/// bits; the lanes are independent chains, which the processor overlaps and the compiler may
/// turn into vector instructions.
#[inline(always)]
#[allow(clippy::needless_range_loop)] // `clutter` is indexed by rows or by columns.
pub(super) fn sum_fixed_lanes<const N: usize, const M: usize, const L: usize>(
    miss: f64,
    clutter: &[f64],
    factor: &impl Fn(usize, usize) -> [f64; L],
) -> [f64; L] {
    const { assert!(N <= SMALL_SIDE && M <= SMALL_SIDE) };
    let objects_are_rows = N > M;
    let (rows, cols) = if objects_are_rows { (N, M) } else { (M, N) };
    let states = 1usize << cols;
    let clutter = &clutter[..M];
    let mut dp = [[0.0f64; L]; 1 << SMALL_SIDE];
    dp[0] = [1.0; L];
    // With the objects as the columns (one miss factor for all), the last row is folded into
    // the final sum (see below).
    let fold_last = !objects_are_rows && rows > 0;
    // Rows and subsets written out (`unrolled!`), so that every test on them below is
    // decided at compile time and the table is straight-line vector code.
    unrolled!(r in [0 1 2 3] {
        if r < rows && !(fold_last && r + 1 == rows) {
            let rm = if objects_are_rows { miss } else { clutter[r] };
            let mut row = [[0.0f64; L]; SMALL_SIDE];
            for (c, f) in row.iter_mut().enumerate().take(cols) {
                *f = if objects_are_rows {
                    factor(r, c)
                } else {
                    factor(c, r)
                };
            }
            unrolled!(s in [15 14 13 12 11 10 9 8 7 6 5 4 3 2 1] {
                let size = SUBSET_SIZE[s] as usize;
                if s < states && size <= r + 1 {
                    let mut v = [0.0; L];
                    if size <= r {
                        v = dp[s];
                        for x in &mut v {
                            *x *= rm;
                        }
                    }
                    for (c, f) in row.iter().enumerate().take(cols) {
                        if s & (1 << c) != 0 {
                            let d = dp[s & !(1 << c)];
                            for l in 0..L {
                                v[l] += d[l] * f[l];
                            }
                        }
                    }
                    dp[s] = v;
                }
            });
            for x in &mut dp[0] {
                *x *= rm;
            }
        }
    });
    if fold_last {
        // The last row r = rows − 1 (clutter factor κ, pair factors f_c) and the final sum
        // Σ_S dp'[S]·miss^{cols − |S|} in one: substituting dp'[S] = dp[S]·κ + Σ_{c∈S}
        // dp[S∖c]·f_c, the sum is dp[full]·κ + Σ_{|S| < cols} miss^{cols − |S| − 1}·dp[S]·
        // (κ·miss + Σ_{c∉S} f_c), accumulated by |S| (after r rows only |S| ≤ r is non-zero).
        let r = rows - 1;
        let rm = clutter[r];
        let mut row = [[0.0f64; L]; SMALL_SIDE];
        for (c, f) in row.iter_mut().enumerate().take(cols) {
            *f = factor(c, r);
        }
        let base = rm * miss;
        let mut full = [0.0f64; L];
        let mut by_size = [[0.0f64; L]; SMALL_SIDE];
        unrolled!(s in [0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15] {
            let size = SUBSET_SIZE[s] as usize;
            if s < states && size <= r {
                if size == cols {
                    for l in 0..L {
                        full[l] = dp[s][l] * rm;
                    }
                } else {
                    let mut w = [base; L];
                    for (c, f) in row.iter().enumerate().take(cols) {
                        if s & (1 << c) == 0 {
                            for l in 0..L {
                                w[l] += f[l];
                            }
                        }
                    }
                    for l in 0..L {
                        by_size[size][l] += dp[s][l] * w[l];
                    }
                }
            }
        });
        let mut total = full;
        let mut weight = 1.0;
        for k in (0..cols).rev() {
            for l in 0..L {
                total[l] += by_size[k][l] * weight;
            }
            weight *= miss;
        }
        return total;
    }
    let mut total = [0.0; L];
    unrolled!(s in [0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15] {
        if s < states {
            let mut f = dp[s];
            for c in 0..cols {
                if s & (1 << c) == 0 {
                    let k = if objects_are_rows { clutter[c] } else { miss };
                    for x in &mut f {
                        *x *= k;
                    }
                }
            }
            for l in 0..L {
                total[l] += f[l];
            }
        }
    });
    total
}

/// The plain sum of [`sum_matchings_small`] on a table of `STATES` = 2^cols subsets.
#[inline(always)]
fn sum_small<const STATES: usize>(
    rows: usize,
    pair: &[f64],
    row_miss: &[f64],
    col_miss: &[f64],
) -> f64 {
    let cols = STATES.trailing_zeros() as usize;
    let full = STATES - 1;
    let mut dp = [0.0f64; STATES];
    dp[0] = 1.0;
    for (row, &m) in pair.chunks_exact(cols.max(1)).zip(row_miss).take(rows) {
        dp_row(&mut dp, m, &row[..cols]);
    }
    if cols == 0 {
        // No columns: the rows are all missed (the chunks above saw no pair).
        for &m in row_miss.iter().take(rows) {
            dp[0] *= m;
        }
    }
    let col_miss = &col_miss[..cols];
    let mut total = 0.0;
    for (s, &d) in dp.iter().enumerate() {
        let f = fold_columns(d, full & !s, |f, c| f * col_miss[c]);
        total += f;
    }
    total
}
