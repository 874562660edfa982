//! The multi-object likelihood (20) of paper `004` (Ristic & Vo), exactly and in log space.
//!
//! With n objects x_1 … x_n, m measurements z_1 … z_m, detection probability p_D, Poisson
//! clutter of rate λ and density c(z), and f_c(Z) = e^{−λ} Π_j λ c(z_j), eq. (20) reads
//!
//! ```text
//! g(Z | X) = f_c(Z) (1 − p_D)^n Σ_θ Π_{i: θ(i) > 0} p_D g(z_θ(i) | x_i) / ((1 − p_D) λ c(z_θ(i)))
//! ```
//!
//! with θ over the associations {1 … n} → {0 … m} that are one-to-one on the detected
//! objects. Multiplying the factors out gives the form evaluated here, which has no division
//! (so it is also defined for p_D = 1, λ = 0 or c(z) = 0):
//!
//! ```text
//! g(Z | X) = e^{−λ} Σ_θ Π_{i undetected} (1 − p_D) · Π_{(i, j) ∈ θ} p_D g(z_j | x_i) · Π_{j unassigned} λ c(z_j),
//! ```
//!
//! a sum over the partial matchings of the bipartite graph objects × measurements. It is
//! computed by dynamic programming over the subsets of the smaller side (k = min(n, m)),
//! sweeping the larger side once: O(max(n, m) · k · 2^k) operations instead of the
//! Σ_d C(n, d) m!/(m − d)! associations. A zero likelihood is −∞, never NaN.
//!
//! The sweep runs in linear arithmetic, each row scaled by its largest factor, with a
//! rigorous bound on what gradual underflow can have lost; when that bound is not 10^{-13}
//! of the result it is redone with log-sum-exp arithmetic throughout, so the returned value
//! is exact to rounding in every case.

use alloc::vec;
use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::math::fns::{exp, ln, ln_1p};
use crate::math::log_sum::{ln_add, ln_sum_exp};

/// The largest min(n, m) the dynamic programme accepts (2^k states).
pub const MAX_SMALLER_SIDE: usize = 20;

/// Reusable scratch memory of the dynamic programme (no allocation per call once warm).
#[derive(Clone, Debug, Default)]
pub struct LikelihoodWorkspace {
    dp: Vec<f64>,
    miss: Vec<f64>,
    pair: Vec<f64>,
    row_miss: Vec<f64>,
    col_miss: Vec<f64>,
    group: Vec<f64>,
}

impl LikelihoodWorkspace {
    /// An empty workspace.
    pub fn new() -> Self {
        Self::default()
    }
}

/// ln Σ over the partial matchings of a rows × cols bipartite graph of
/// Π_{unmatched rows} e^{row_miss[r]} Π_{pairs} e^{pair[r·cols + c]} Π_{unmatched cols} e^{col_miss[c]}.
///
/// The caller makes `cols` the smaller side (`cols ≤ MAX_SMALLER_SIDE`). Inputs are logs, may
/// be −∞ (a zero factor), never NaN or +∞.
pub(crate) fn ln_sum_matchings(
    rows: usize,
    cols: usize,
    ln_pair: &[f64],
    ln_row_miss: &[f64],
    ln_col_miss: &[f64],
    dp: &mut Vec<f64>,
    group: &mut Vec<f64>,
) -> f64 {
    debug_assert!(cols <= MAX_SMALLER_SIDE);
    debug_assert_eq!(ln_pair.len(), rows * cols);
    let states = 1usize << cols;
    let full = states - 1;
    dp.clear();
    dp.resize(states, 0.0);
    dp[0] = 1.0;
    group.clear();
    group.resize(cols, 0.0);
    // Linear sweep, row r scaled by e^{T_r}, T_r = its largest log factor.
    let mut ln_scale = 0.0;
    for r in 0..rows {
        let row = &ln_pair[r * cols..(r + 1) * cols];
        let t = row.iter().copied().fold(ln_row_miss[r], f64::max);
        if t == f64::NEG_INFINITY {
            // Row r can be neither missed nor matched: no matching has a non-zero weight.
            return f64::NEG_INFINITY;
        }
        ln_scale += t;
        let m = exp(ln_row_miss[r] - t);
        for (f, &l) in group.iter_mut().zip(row) {
            *f = exp(l - t);
        }
        dp_row(&mut dp[..states], m, group);
    }
    // Final factor of the unmatched columns, Σ_S dp[S] Π_{c∉S} e^{L_c}: linearly when the
    // e^{L_c} are moderate, else grouped by |S| with e^{(k−|S|) V} (V the largest L_c)
    // applied in log space.
    let v = ln_col_miss
        .iter()
        .copied()
        .fold(f64::NEG_INFINITY, f64::max);
    let moderate = ln_col_miss
        .iter()
        .all(|&l| l == f64::NEG_INFINITY || l.abs() * (cols as f64) < 600.0);
    let ln_val = if v == f64::NEG_INFINITY {
        // Every column must be matched.
        if dp[full] > 0.0 {
            ln(dp[full])
        } else {
            f64::NEG_INFINITY
        }
    } else if moderate {
        for (f, &l) in group.iter_mut().zip(ln_col_miss) {
            *f = exp(l);
        }
        let mut total = 0.0;
        for (s, &d) in dp.iter().enumerate() {
            if d == 0.0 {
                continue;
            }
            let mut f = d;
            let mut out = full & !s;
            while out != 0 {
                let c = out.trailing_zeros() as usize;
                out &= out - 1;
                f *= group[c];
            }
            total += f;
        }
        if total > 0.0 {
            ln(total)
        } else {
            f64::NEG_INFINITY
        }
    } else {
        group.clear();
        group.resize(cols + 1, 0.0);
        for (s, &d) in dp.iter().enumerate() {
            if d == 0.0 {
                continue;
            }
            let mut f = d;
            let mut out = full & !s;
            while out != 0 {
                let c = out.trailing_zeros() as usize;
                out &= out - 1;
                f *= exp(ln_col_miss[c] - v);
            }
            group[s.count_ones() as usize] += f;
        }
        ln_sum_exp(
            group
                .iter()
                .enumerate()
                .filter(|(_, g)| **g > 0.0)
                .map(|(p, g)| ln(*g) + (cols - p) as f64 * v),
        )
    };
    // Rigorous underflow bound: each dp entry is built by at most rows·(k+1) roundings, each
    // losing at most 2^-1074 ≈ e^-744.4 absolutely to gradual underflow, the scaled factors
    // are ≤ 1 and there are 2^k entries: for any rows·(k+1)·2^k ≤ e^44 the total loss is
    // below e^-700 · e^{k·max(V, 0)}.
    let ln_err = -700.0 + if v > 0.0 { cols as f64 * v } else { 0.0 };
    if rows == 0 || (ln_val != f64::NEG_INFINITY && ln_val - ln_err > 30.0) {
        return ln_scale + ln_val;
    }
    ln_sum_matchings_log(rows, cols, ln_pair, ln_row_miss, ln_col_miss, dp)
}

/// The largest smaller side [`sum_matchings_small`] handles (a fixed 16-entry table).
pub(crate) const SMALL_SIDE: usize = 4;

/// The largest larger side of [`MultiObjectLikelihood::scaled_likelihood_small`].
pub(crate) const MAX_LARGER: usize = 16;

/// ln of the largest pair factor that [`negligible_pair_bound`] lets one replace by 0, as a
/// multiple of ln 2: 2^{−64}.
const NEGLIGIBLE_LN: f64 = -64.0 * core::f64::consts::LN_2;

/// ln of a bound below which the pair factor f_{ij} = p_D g(z_j | x_i) of (20) may be replaced
/// by 0, given the logs of the two miss factors it competes with: row i's (object: 1 − p_D)
/// and column j's (measurement: λ c(z_j)). `ln_row_miss + ln_col_miss − 64 ln 2`.
///
/// Why this changes the sum T = Σ_matchings Π factors of (20) only below rounding: T is
/// affine in f_{ij}, T = T|_{f_{ij}=0} + f_{ij} T_{−i,−j} with T_{−i,−j} the sum over the
/// matchings of the graph without row i and column j; each of those, extended by "i missed,
/// j unassigned", is a matching of the full graph not using (i, j), so
/// T|_{f_{ij}=0} ≥ r_i c_j T_{−i,−j}, and with f_{ij} ≤ 2^{−64} r_i c_j,
/// T ≤ T|_{f_{ij}=0} (1 + 2^{−64}). Dropping the pairs one after the other (the argument holds
/// whatever the other factors are), k dropped pairs change T by a relative amount below
/// k·2^{−64} (< 2^{−58} for the ≤ 64 pairs of the small tables), far under the 2^{−53} of a
/// single rounding, and only downwards. −∞ when a miss factor is 0 (nothing may be dropped).
#[inline]
pub(crate) fn negligible_pair_bound(ln_row_miss: f64, ln_col_miss: f64) -> f64 {
    ln_row_miss + ln_col_miss + NEGLIGIBLE_LN
}

/// Scratch tables of [`MultiObjectLikelihood::scaled_likelihood_factors`]: the pair factors
/// and the objects' miss factors 1 − p_D.
#[derive(Clone, Debug)]
pub(crate) struct SmallTables {
    pair: [f64; MAX_LARGER * SMALL_SIDE],
    miss: [f64; MAX_LARGER],
}

/// The sum of [`ln_sum_matchings`] in plain arithmetic, for the small sizes of the sensor
/// control's future scans: `pair`, `row_miss`, `col_miss` are the factors themselves (not
/// their logs), all in [0, 1], and `cols ≤ SMALL_SIDE`. No scaling is needed: with factors
/// ≤ 1 no partial product overflows, and the only loss beyond rounding is gradual
/// underflow, bounded as in [`ln_sum_matchings`] by e^{−700} (rows·(k+1)·2^k ≤ e^44 roundings
/// of ≤ 2^{−1074} each, none amplified). `None` when the sum is not e^{30} above that bound
/// (the caller then takes the exact log-space path), else `Some(Σ)` with Σ > 0.
#[inline]
pub(crate) fn sum_matchings_small(
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
const SMALL_FLOOR: f64 = 1.1e-291;

/// [`sum_matchings_small`] for N objects and M measurements known at compile time (so that
/// every loop unrolls), the pair factors from `factor(i, j)`, the objects' miss factor `miss`
/// and the measurements' `clutter[j]`: the smaller side as the columns, and the operations of
/// `dp_row` and of the final sum in the same order, hence the same bits.
#[inline(always)]
#[allow(clippy::needless_range_loop)] // `clutter` is indexed by rows or by columns.
fn sum_fixed<const N: usize, const M: usize>(
    miss: f64,
    clutter: &[f64],
    factor: &impl Fn(usize, usize) -> f64,
) -> f64 {
    let objects_are_rows = N > M;
    let (rows, cols) = if objects_are_rows { (N, M) } else { (M, N) };
    let states = 1usize << cols;
    let clutter = &clutter[..M];
    let mut dp = [0.0f64; 1 << SMALL_SIDE];
    dp[0] = 1.0;
    for r in 0..rows {
        let rm = if objects_are_rows { miss } else { clutter[r] };
        let mut row = [0.0f64; SMALL_SIDE];
        for (c, f) in row.iter_mut().enumerate().take(cols) {
            *f = if objects_are_rows {
                factor(r, c)
            } else {
                factor(c, r)
            };
        }
        for s in (1..states).rev() {
            let mut v = dp[s] * rm;
            for (c, &f) in row.iter().enumerate().take(cols) {
                if s & (1 << c) != 0 {
                    v += dp[s & !(1 << c)] * f;
                }
            }
            dp[s] = v;
        }
        dp[0] *= rm;
    }
    let mut total = 0.0;
    for (s, &d) in dp.iter().enumerate().take(states) {
        let mut f = d;
        for c in 0..cols {
            if s & (1 << c) == 0 {
                f *= if objects_are_rows { clutter[c] } else { miss };
            }
        }
        total += f;
    }
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
        let mut f = d;
        let mut out = full & !s;
        while out != 0 {
            let c = out.trailing_zeros() as usize;
            out &= out - 1;
            f *= col_miss[c];
        }
        total += f;
    }
    total
}

/// The same sum with log-sum-exp arithmetic throughout (no underflow at any scale).
fn ln_sum_matchings_log(
    rows: usize,
    cols: usize,
    ln_pair: &[f64],
    ln_row_miss: &[f64],
    ln_col_miss: &[f64],
    dp: &mut Vec<f64>,
) -> f64 {
    let states = 1usize << cols;
    let full = states - 1;
    dp.clear();
    dp.resize(states, f64::NEG_INFINITY);
    dp[0] = 0.0;
    for r in 0..rows {
        let row = &ln_pair[r * cols..(r + 1) * cols];
        for s in (0..states).rev() {
            let mut v = dp[s] + ln_row_miss[r];
            let mut bits = s;
            while bits != 0 {
                let c = bits.trailing_zeros() as usize;
                bits &= bits - 1;
                v = ln_add(v, dp[s & !(1 << c)] + row[c]);
            }
            dp[s] = v;
        }
    }
    let mut total = f64::NEG_INFINITY;
    for (s, &d) in dp.iter().enumerate() {
        let mut f = d;
        let mut out = full & !s;
        while out != 0 {
            let c = out.trailing_zeros() as usize;
            out &= out - 1;
            f += ln_col_miss[c];
        }
        total = ln_add(total, f);
    }
    total
}

/// The multi-object likelihood model of (20): p_D and the clutter rate λ (the clutter density
/// c(z_j) comes with each scan).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MultiObjectLikelihood {
    detection: f64,
    clutter_rate: f64,
    ln_detection: f64,
    ln_miss: f64,
    ln_rate: f64,
}

impl MultiObjectLikelihood {
    /// Validates p_D ∈ [0, 1] (`detectionProbability`) and λ ≥ 0 finite (`clutterRate`).
    pub fn new(detection: f64, clutter_rate: f64) -> Result<Self> {
        crate::error::check_probability(|| "detectionProbability".into(), detection)?;
        if !(clutter_rate.is_finite() && clutter_rate >= 0.0) {
            return Err(Error::parameter(
                "clutterRate",
                clutter_rate,
                "finite and ≥ 0",
            ));
        }
        Ok(Self {
            detection,
            clutter_rate,
            ln_detection: ln(detection),
            ln_miss: ln_1p(-detection),
            ln_rate: ln(clutter_rate),
        })
    }

    /// p_D.
    pub fn detection(&self) -> f64 {
        self.detection
    }

    /// λ.
    pub fn clutter_rate(&self) -> f64 {
        self.clutter_rate
    }

    /// ln g(Z | X) of (20) from [`Self::scaled_likelihood_small`] (the tests' handle on it).
    #[cfg(test)]
    pub(crate) fn ln_likelihood_small(
        &self,
        n: usize,
        pair: &[f64],
        clutter: &[f64],
    ) -> Option<f64> {
        self.scaled_likelihood_small(n, pair, clutter)
            .map(|t| -self.clutter_rate + ln(t))
    }

    /// e^{λ} g(Z | X) of (20) (above e^{−670}) for small sets in plain arithmetic:
    /// `pair[i·m + j]` = p_D g(z_j | x_i) and `clutter[j]` = λ c(z_j) (m = `clutter.len()`), all
    /// in [0, 1]. `None` when a factor is outside [0, 1] (or NaN), min(n, m) > 4,
    /// max(n, m) > 16, or gradual underflow could matter (see [`sum_matchings_small`]): the
    /// caller then evaluates
    /// [`Self::ln_likelihood_from_logs`], which is exact at every scale. Agrees with its
    /// e^{λ + value} to rounding otherwise.
    #[cfg(test)]
    pub(crate) fn scaled_likelihood_small(
        &self,
        n: usize,
        pair: &[f64],
        clutter: &[f64],
    ) -> Option<f64> {
        let m = clutter.len();
        if pair.len() != n * m {
            return None;
        }
        let unit = |v: &f64| (0.0..=1.0).contains(v);
        if !(pair.iter().all(unit) && clutter.iter().all(unit)) {
            return None;
        }
        let mut tables = self.small_tables();
        self.scaled_likelihood_factors(n, clutter, &mut tables, |i, j| pair[i * m + j])
    }

    /// The scratch tables of [`Self::scaled_likelihood_factors`] (made once, reused).
    pub(crate) fn small_tables(&self) -> SmallTables {
        SmallTables {
            pair: [0.0; MAX_LARGER * SMALL_SIDE],
            miss: [1.0 - self.detection; MAX_LARGER],
        }
    }

    /// [`Self::scaled_likelihood_small`] with the pair factors p_D g(z_j | x_i) given by
    /// `factor(i, j)` (in [0, 1], the caller's invariant, as are the `clutter` values),
    /// written straight into the orientation of the dynamic programme (the smaller side as
    /// the columns). `tables` from [`Self::small_tables`] of this model.
    #[inline(always)]
    pub(crate) fn scaled_likelihood_factors(
        &self,
        n: usize,
        clutter: &[f64],
        tables: &mut SmallTables,
        factor: impl Fn(usize, usize) -> f64,
    ) -> Option<f64> {
        let m = clutter.len();
        if n.min(m) > SMALL_SIDE || n.max(m) > MAX_LARGER {
            return None;
        }
        let SmallTables { pair, miss } = tables;
        // The common sizes (n, m ≤ 3) by a kernel unrolled for them, same operations.
        macro_rules! fixed {
            ($(($a:literal, $b:literal)),*) => {
                match (n, m) {
                    $(($a, $b) => {
                        let t = sum_fixed::<$a, $b>(miss[0], clutter, &factor);
                        return if t > SMALL_FLOOR { Some(t) } else { None };
                    })*
                    _ => {}
                }
            };
        }
        fixed!(
            (0, 0),
            (0, 1),
            (0, 2),
            (0, 3),
            (1, 0),
            (1, 1),
            (1, 2),
            (1, 3),
            (2, 0),
            (2, 1),
            (2, 2),
            (2, 3),
            (3, 0),
            (3, 1),
            (3, 2),
            (3, 3)
        );
        if n > m {
            // Rows: objects (miss 1 − p_D); columns: measurements (miss λ c(z_j)).
            for i in 0..n {
                for j in 0..m {
                    pair[i * m + j] = factor(i, j);
                }
            }
            sum_matchings_small(n, m, &pair[..n * m], &miss[..n], clutter)
        } else {
            // Rows: measurements; columns: objects.
            for j in 0..m {
                for i in 0..n {
                    pair[j * n + i] = factor(i, j);
                }
            }
            sum_matchings_small(m, n, &pair[..n * m], clutter, &miss[..n])
        }
    }

    /// [`Self::scaled_likelihood_factors`] for `out.len()` sets of `n` objects at once, the
    /// pair factors of set q at `factors[(j·n + o)·count + q]` (measurement j, object o,
    /// count = `out.len()`): `out[q]` is the value, NaN where it declined. The same kernels,
    /// with the same operations per set, hence the same bits; the loop over the sets is the
    /// inner one, so the size dispatch is paid once per batch and not once per set.
    pub(crate) fn scaled_likelihood_batch(
        &self,
        n: usize,
        clutter: &[f64],
        factors: &[f64],
        tables: &mut SmallTables,
        out: &mut [f64],
    ) {
        let m = clutter.len();
        let count = out.len();
        assert_eq!(factors.len(), n * m * count);
        if n.min(m) > SMALL_SIDE || n.max(m) > MAX_LARGER {
            out.fill(f64::NAN);
            return;
        }
        let miss = tables.miss[0];
        macro_rules! fixed {
            ($(($a:literal, $b:literal)),*) => {
                match (n, m) {
                    $(($a, $b) => {
                        for (q, t) in out.iter_mut().enumerate() {
                            let v = sum_fixed::<$a, $b>(miss, clutter, &|o, j| {
                                factors[(j * $a + o) * count + q]
                            });
                            *t = if v > SMALL_FLOOR { v } else { f64::NAN };
                        }
                        return;
                    })*
                    _ => {}
                }
            };
        }
        fixed!(
            (0, 0),
            (0, 1),
            (0, 2),
            (0, 3),
            (1, 0),
            (1, 1),
            (1, 2),
            (1, 3),
            (2, 0),
            (2, 1),
            (2, 2),
            (2, 3),
            (3, 0),
            (3, 1),
            (3, 2),
            (3, 3)
        );
        for (q, t) in out.iter_mut().enumerate() {
            *t = self
                .scaled_likelihood_factors(n, clutter, tables, |o, j| {
                    factors[(j * n + o) * count + q]
                })
                .unwrap_or(f64::NAN);
        }
    }

    /// ln g(Z | X) of (20) from logs: `ln_g[i·m + j]` = ln g(z_j | x_i) for the n objects and
    /// m measurements, `ln_clutter[j]` = ln c(z_j). Entries may be −∞ (zero), never NaN or
    /// +∞ (the caller's invariant; [`ln_likelihood`] checks it). min(n, m) ≤
    /// [`MAX_SMALLER_SIDE`].
    pub fn ln_likelihood_from_logs(
        &self,
        n: usize,
        ln_g: &[f64],
        ln_clutter: &[f64],
        ws: &mut LikelihoodWorkspace,
    ) -> f64 {
        let m = ln_clutter.len();
        debug_assert_eq!(ln_g.len(), n * m);
        let ln_rate = self.ln_rate;
        let LikelihoodWorkspace {
            dp,
            miss,
            pair,
            row_miss,
            col_miss,
            group,
        } = ws;
        miss.clear();
        miss.extend(ln_clutter.iter().map(|c| ln_rate + c));
        pair.clear();
        row_miss.clear();
        col_miss.clear();
        let body = if n > m {
            // Rows: objects (miss 1 − p_D); columns: measurements (miss λ c(z_j)).
            pair.extend(ln_g.iter().map(|g| self.ln_detection + g));
            row_miss.resize(n, self.ln_miss);
            ln_sum_matchings(n, m, pair, row_miss, miss, dp, group)
        } else {
            // Rows: measurements; columns: objects.
            for j in 0..m {
                pair.extend((0..n).map(|i| self.ln_detection + ln_g[i * m + j]));
            }
            col_miss.resize(n, self.ln_miss);
            ln_sum_matchings(m, n, pair, miss, col_miss, dp, group)
        };
        -self.clutter_rate + body
    }
}

/// ln g(Z | X) of (20) for one particle, validated: `likelihoods[i][j]` = g(z_j | x_i) ≥ 0
/// (n rows of m numbers, `[]` for n = 0), `clutter_density[j]` = c(z_j) ≥ 0 (length m),
/// p_D ∈ [0, 1], λ ≥ 0. A zero likelihood is −∞.
///
/// # Errors
/// Field-named errors (`likelihoods[i][j]`, `clutterDensity[j]`, `detectionProbability`,
/// `clutterRate`), and [`Error::Unsupported`] when min(n, m) > [`MAX_SMALLER_SIDE`].
pub fn ln_likelihood<R: AsRef<[f64]>>(
    likelihoods: &[R],
    detection: f64,
    clutter_rate: f64,
    clutter_density: &[f64],
) -> Result<f64> {
    let model = MultiObjectLikelihood::new(detection, clutter_rate)?;
    let m = clutter_density.len();
    let n = likelihoods.len();
    let mut ln_g = Vec::with_capacity(n * m);
    for (i, row) in likelihoods.iter().enumerate() {
        let row = row.as_ref();
        if row.len() != m {
            return Err(Error::dimension(
                alloc::format!("likelihoods[{i}]"),
                m,
                row.len(),
            ));
        }
        for (j, &g) in row.iter().enumerate() {
            if !(g.is_finite() && g >= 0.0) {
                return Err(Error::parameter(
                    alloc::format!("likelihoods[{i}][{j}]"),
                    g,
                    "finite and ≥ 0",
                ));
            }
            ln_g.push(ln(g));
        }
    }
    let mut ln_c = Vec::with_capacity(m);
    for (j, &c) in clutter_density.iter().enumerate() {
        if !(c.is_finite() && c >= 0.0) {
            return Err(Error::parameter(
                alloc::format!("clutterDensity[{j}]"),
                c,
                "finite and ≥ 0",
            ));
        }
        ln_c.push(ln(c));
    }
    if n.min(m) > MAX_SMALLER_SIDE {
        return Err(Error::Unsupported {
            what: "likelihoods".into(),
            reason: "min(objects, measurements) must be at most 20",
        });
    }
    Ok(model.ln_likelihood_from_logs(n, &ln_g, &ln_c, &mut LikelihoodWorkspace::new()))
}

/// The oracle: (20) as printed, by enumerating every association θ (one-to-one on the detected
/// objects) in log space. Exponential in n and m; for tests and the benchmark's comparison.
/// Inputs as in [`ln_likelihood`], unchecked; p_D < 1 and λ c(z) > 0 are needed by the printed
/// ratio form, so this evaluates the equivalent product form term by term instead.
pub fn brute_force_ln_likelihood<R: AsRef<[f64]>>(
    likelihoods: &[R],
    detection: f64,
    clutter_rate: f64,
    clutter_density: &[f64],
) -> f64 {
    let n = likelihoods.len();
    let m = clutter_density.len();
    let mut theta = vec![0usize; n];
    let mut used = vec![false; m];
    let mut total = f64::NEG_INFINITY;
    #[allow(clippy::too_many_arguments)]
    fn recurse<R: AsRef<[f64]>>(
        i: usize,
        g: &[R],
        pd: f64,
        rate: f64,
        c: &[f64],
        theta: &mut [usize],
        used: &mut [bool],
        total: &mut f64,
    ) {
        if i == g.len() {
            let mut t = -rate;
            for (k, &a) in theta.iter().enumerate() {
                t += if a == 0 {
                    ln(1.0 - pd)
                } else {
                    ln(pd) + ln(g[k].as_ref()[a - 1])
                };
            }
            for (j, &u) in used.iter().enumerate() {
                if !u {
                    t += ln(rate * c[j]);
                }
            }
            *total = ln_add(*total, t);
            return;
        }
        theta[i] = 0;
        recurse(i + 1, g, pd, rate, c, theta, used, total);
        for j in 0..c.len() {
            if !used[j] {
                used[j] = true;
                theta[i] = j + 1;
                recurse(i + 1, g, pd, rate, c, theta, used, total);
                used[j] = false;
            }
        }
    }
    recurse(
        0,
        likelihoods,
        detection,
        clutter_rate,
        clutter_density,
        &mut theta,
        &mut used,
        &mut total,
    );
    total
}

/// One row of the subset DP of (20): dp[S] ← dp[S]·m + Σ_{c∈S} dp[S∖{c}]·row[c] for every
/// subset S of the columns (`dp.len()` = 2^columns), in place and descending so that dp[S∖{c}]
/// is still the previous row's value.
#[inline(always)]
fn dp_row(dp: &mut [f64], m: f64, row: &[f64]) {
    for s in (1..dp.len()).rev() {
        let mut v = dp[s] * m;
        let mut bits = s;
        while bits != 0 {
            let c = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            v += dp[s & !(1 << c)] * row[c];
        }
        dp[s] = v;
    }
    dp[0] *= m;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng::{seeded, uniform};

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a == b) || (a - b).abs() <= tol * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn matches_enumeration_for_small_sets() {
        let mut rng = seeded(14);
        for n in 0..=5 {
            for m in 0..=7 {
                for trial in 0..4 {
                    let pd = [0.95, 1.0, 0.0, 0.5][trial];
                    let rate = [0.8, 0.0, 2.5, 1e-3][trial];
                    let g: Vec<Vec<f64>> = (0..n)
                        .map(|_| {
                            (0..m)
                                .map(|_| {
                                    let u = uniform(&mut rng);
                                    if u < 0.15 { 0.0 } else { exp(-40.0 * u) * 3.0 }
                                })
                                .collect()
                        })
                        .collect();
                    let c: Vec<f64> = (0..m).map(|_| 1e-3 + uniform(&mut rng)).collect();
                    let fast = ln_likelihood(&g, pd, rate, &c).unwrap();
                    let slow = brute_force_ln_likelihood(&g, pd, rate, &c);
                    assert!(!fast.is_nan());
                    assert!(
                        close(fast, slow, 1e-12),
                        "n={n} m={m} pd={pd}: {fast} vs {slow}"
                    );
                }
            }
        }
    }

    #[test]
    fn edge_cases() {
        let empty: [[f64; 0]; 0] = [];
        // n = 0, |Z| = 0: e^{−λ}.
        assert_eq!(ln_likelihood(&empty, 0.9, 0.8, &[]).unwrap(), -0.8);
        // n = 0: pure clutter.
        let v = ln_likelihood(&empty, 0.9, 0.8, &[0.5, 0.25]).unwrap();
        assert!(close(v, -0.8 + ln(0.8 * 0.5) + ln(0.8 * 0.25), 1e-15));
        // |Z| = 0: all missed.
        let v = ln_likelihood(&[[0.0; 0]; 3], 0.9, 0.8, &[]).unwrap();
        assert!(close(v, -0.8 + 3.0 * ln(0.1), 1e-14));
        // p_D = 1 with no measurement for an object: zero, i.e. −∞, not NaN.
        assert_eq!(
            ln_likelihood(&[[0.0; 0]; 2], 1.0, 0.8, &[]).unwrap(),
            f64::NEG_INFINITY
        );
        // p_D = 1, λ = 0, one object per measurement: the permanent.
        let v = ln_likelihood(&[[1.0, 2.0], [3.0, 4.0]], 1.0, 0.0, &[1.0, 1.0]).unwrap();
        assert!(close(v, ln(1.0 * 4.0 + 2.0 * 3.0), 1e-15));
        // λ = 0 and more measurements than objects: impossible.
        assert_eq!(
            ln_likelihood(&[[1.0, 2.0]], 0.9, 0.0, &[1.0, 1.0]).unwrap(),
            f64::NEG_INFINITY
        );
        // Tiny likelihoods (below the double range after products) stay finite.
        let g = [[1e-200, 1e-250], [1e-300, 1e-220]];
        let v = ln_likelihood(&g, 1.0, 0.0, &[1.0, 1.0]).unwrap();
        let exact = ln_add(ln(1e-200) + ln(1e-220), ln(1e-250) + ln(1e-300));
        assert!(close(v, exact, 1e-13), "{v} vs {exact}");
    }

    #[test]
    fn extreme_logs_take_the_log_path() {
        let model = MultiObjectLikelihood::new(0.95, 0.8).unwrap();
        let mut ws = LikelihoodWorkspace::new();
        // ln g far below the double range: the linear sweep underflows, the log one does not.
        let ln_g = [-2000.0, -5000.0, -4000.0, -2500.0];
        let ln_c = [-7.0, -7.0];
        let v = model.ln_likelihood_from_logs(2, &ln_g, &ln_c, &mut ws);
        let g: Vec<f64> = ln_g.to_vec();
        // Oracle in logs: enumerate the 7 associations by hand.
        let (lp, lq, lr) = (ln(0.95), ln(0.05), ln(0.8) - 7.0);
        let terms = [
            2.0 * lq + 2.0 * lr,
            lp + g[0] + lq + lr,
            lp + g[1] + lq + lr,
            lp + g[2] + lq + lr,
            lp + g[3] + lq + lr,
            2.0 * lp + g[0] + g[3],
            2.0 * lp + g[1] + g[2],
        ];
        let exact = -0.8 + ln_sum_exp(terms);
        assert!(close(v, exact, 1e-13));
        let ln_g = [-2000.0, -5000.0];
        let v = MultiObjectLikelihood::new(1.0, 0.0)
            .unwrap()
            .ln_likelihood_from_logs(1, &ln_g, &[0.0, 0.0], &mut ws);
        assert_eq!(v, f64::NEG_INFINITY);
        let v = MultiObjectLikelihood::new(1.0, 0.0)
            .unwrap()
            .ln_likelihood_from_logs(2, &[-3000.0, -1e4, -1e4, -3000.0], &[0.0, 0.0], &mut ws);
        assert!(close(v, -6000.0, 1e-13), "{v}");
    }

    #[test]
    fn small_plain_path_matches_the_log_path() {
        let mut rng = seeded(41);
        let mut ws = LikelihoodWorkspace::new();
        let mut taken = 0;
        for n in 0..=6 {
            for m in 0..=6 {
                for trial in 0..6 {
                    let pd = [0.95, 1.0, 0.0, 0.5, 0.95, 0.3][trial];
                    let rate = [0.8, 0.0, 2.5, 1e-3, 0.8, 0.8][trial];
                    let spread = [40.0, 40.0, 40.0, 40.0, 900.0, 5.0][trial];
                    let ln_g: Vec<f64> = (0..n * m)
                        .map(|_| {
                            let u = uniform(&mut rng);
                            if u < 0.1 {
                                f64::NEG_INFINITY
                            } else {
                                -spread * u - 1.0
                            }
                        })
                        .collect();
                    let ln_c: Vec<f64> = (0..m).map(|_| -7.0 * uniform(&mut rng)).collect();
                    let model = MultiObjectLikelihood::new(pd, rate).unwrap();
                    let pair: Vec<f64> = ln_g.iter().map(|g| pd * exp(*g)).collect();
                    let clutter: Vec<f64> = ln_c.iter().map(|c| rate * exp(*c)).collect();
                    let exact = model.ln_likelihood_from_logs(n, &ln_g, &ln_c, &mut ws);
                    match model.ln_likelihood_small(n, &pair, &clutter) {
                        Some(v) => {
                            assert!(n.min(m) <= SMALL_SIDE);
                            assert!(
                                close(v, exact, 1e-13),
                                "n={n} m={m} t={trial}: {v} vs {exact}"
                            );
                            taken += 1;
                        }
                        // Declined: too large, a factor above 1, or too small for the
                        // plain sum (or zero).
                        None => assert!(
                            n.min(m) > SMALL_SIDE
                                || clutter.iter().any(|&v| v > 1.0)
                                || exact < -rate - 600.0,
                            "n={n} m={m} t={trial}: {exact}"
                        ),
                    }
                }
            }
        }
        assert!(taken > 100, "{taken}");
        // Underflow: the plain sum of 1e-200 · 1e-220 is 0; declined, the log path is exact.
        let model = MultiObjectLikelihood::new(1.0, 0.0).unwrap();
        assert_eq!(
            model.ln_likelihood_small(2, &[1e-200, 0.0, 0.0, 1e-220], &[0.0, 0.0]),
            None
        );
        // Factors above 1 are declined.
        let model = MultiObjectLikelihood::new(0.9, 0.8).unwrap();
        assert_eq!(model.ln_likelihood_small(1, &[2.0], &[0.5]), None);
        assert_eq!(model.ln_likelihood_small(1, &[0.5], &[f64::NAN]), None);
        assert!(model.ln_likelihood_small(1, &[0.5], &[0.5]).is_some());
    }

    /// The unrolled kernels give the bits of the table-driven programme, in both orientations.
    #[test]
    fn fixed_kernels_match_the_tables_bit_for_bit() {
        let mut rng = seeded(77);
        let model = MultiObjectLikelihood::new(0.9, 0.8).unwrap();
        let mut tables = model.small_tables();
        for n in 0..=3 {
            for m in 0..=3 {
                for _ in 0..20 {
                    let pair: Vec<f64> = (0..n * m).map(|_| uniform(&mut rng)).collect();
                    let clutter: Vec<f64> = (0..m).map(|_| uniform(&mut rng)).collect();
                    let fixed = model
                        .scaled_likelihood_factors(n, &clutter, &mut tables, |i, j| pair[i * m + j])
                        .unwrap();
                    let miss = [1.0 - 0.9; 3];
                    let table = if n > m {
                        sum_matchings_small(n, m, &pair, &miss[..n], &clutter)
                    } else {
                        let t: Vec<f64> = (0..m)
                            .flat_map(|j| (0..n).map(move |i| (i, j)))
                            .map(|(i, j)| pair[i * m + j])
                            .collect();
                        sum_matchings_small(m, n, &t, &clutter, &miss[..n])
                    };
                    assert_eq!(fixed.to_bits(), table.unwrap().to_bits(), "n={n} m={m}");
                }
            }
        }
    }

    /// The inequality behind `negligible_pair_bound`: pair factors f_ij ≤ 2^{−b} r_i c_j set
    /// to 0 lower the sum by a relative amount in [0, k·2^{−b}] (k of them), checked at
    /// b = 20 where it is far above rounding, and tight for one pair.
    #[test]
    fn negligible_pairs_change_the_sum_by_at_most_the_bound() {
        let mut rng = seeded(5);
        let b = 20.0f64;
        let eps = libm::exp2(-b);
        let mut worst = 0.0f64;
        for n in 1..=4 {
            for m in 1..=4 {
                for trial in 0..30 {
                    let (pd, rate) = ([0.95, 0.5, 0.1][trial % 3], 0.8);
                    let model = MultiObjectLikelihood::new(pd, rate).unwrap();
                    let clutter: Vec<f64> =
                        (0..m).map(|_| 1e-4 + 0.5 * uniform(&mut rng)).collect();
                    let (mut full, mut dropped, mut k) = (vec![0.0; n * m], vec![0.0; n * m], 0);
                    for i in 0..n {
                        for j in 0..m {
                            let f = if uniform(&mut rng) < 0.5 {
                                // At most the bound (with the code's own formula).
                                k += 1;
                                let ln_b =
                                    ln(1.0 - pd) + ln(clutter[j]) - b * core::f64::consts::LN_2;
                                exp(ln_b) * (1.0 - 0.5 * uniform(&mut rng)) * (1.0 - 1e-12)
                            } else {
                                let f = 0.9 * uniform(&mut rng);
                                dropped[i * m + j] = f;
                                f
                            };
                            full[i * m + j] = f;
                        }
                    }
                    let t_full = model.ln_likelihood_small(n, &full, &clutter).unwrap();
                    let t_drop = model.ln_likelihood_small(n, &dropped, &clutter).unwrap();
                    // ln T_full − ln T_dropped ∈ [0, ln(1 + ε)^k] up to rounding.
                    let d = t_full - t_drop;
                    assert!(d >= -1e-14, "n={n} m={m}: {d}");
                    assert!(
                        d <= k as f64 * eps + 1e-14,
                        "n={n} m={m} k={k}: {d} vs {}",
                        k as f64 * eps
                    );
                    if k > 0 {
                        worst = worst.max(d / (k as f64 * eps));
                    }
                }
            }
        }
        // Not vacuous: some case comes close to the bound.
        assert!(worst > 0.1, "{worst}");
        // The code's bound is this one at b = 64.
        let ln_b = negligible_pair_bound(ln(0.05), ln(1e-3));
        assert!((ln_b - (ln(0.05) + ln(1e-3) - 64.0 * core::f64::consts::LN_2)).abs() < 1e-12);
    }

    #[test]
    fn bad_input_names_the_field() {
        let e = ln_likelihood(&[[0.5, -1.0]], 0.9, 0.8, &[1.0, 1.0]).unwrap_err();
        assert_eq!(e.field(), "likelihoods[0][1]");
        let e = ln_likelihood(&[[0.5]], 0.9, 0.8, &[1.0, 1.0]).unwrap_err();
        assert_eq!(e.field(), "likelihoods[0]");
        let e = ln_likelihood(&[[0.5]], 1.5, 0.8, &[1.0]).unwrap_err();
        assert_eq!(e.field(), "detectionProbability");
        let e = ln_likelihood(&[[0.5]], 0.5, f64::NAN, &[1.0]).unwrap_err();
        assert_eq!(e.field(), "clutterRate");
        let e = ln_likelihood(&[[0.5]], 0.5, 1.0, &[f64::INFINITY]).unwrap_err();
        assert_eq!(e.field(), "clutterDensity[0]");
    }
}
