//! The sum over the partial matchings of a bipartite graph that eq. (20) of paper `004`
//! (Ristic & Vo) reduces to (see [`super::likelihood`]): a dynamic programme over the subsets of
//! the smaller side, in linear arithmetic with each row scaled, and redone in log-sum-exp
//! arithmetic when gradual underflow could matter.

use alloc::vec::Vec;

use super::likelihood::MAX_SMALLER_SIDE;
use crate::math::fns::{exp, ln};
use crate::math::log_sum::{ln_add, ln_sum_exp};

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
            let f = fold_columns(d, full & !s, |f, c| f * group[c]);
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
            let f = fold_columns(d, full & !s, |f, c| f * exp(ln_col_miss[c] - v));
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
    let graph = LnGraph {
        rows,
        cols,
        pair: ln_pair,
        row_miss: ln_row_miss,
        col_miss: ln_col_miss,
    };
    ln_sum_matchings_log(&graph, dp)
}

/// The logs of [`ln_sum_matchings`]'s factors: a rows × cols graph, pairs row-major.
#[derive(Clone, Copy)]
struct LnGraph<'a> {
    rows: usize,
    cols: usize,
    pair: &'a [f64],
    row_miss: &'a [f64],
    col_miss: &'a [f64],
}

/// The same sum with log-sum-exp arithmetic throughout (no underflow at any scale).
fn ln_sum_matchings_log(graph: &LnGraph<'_>, dp: &mut Vec<f64>) -> f64 {
    let LnGraph {
        rows,
        cols,
        pair: ln_pair,
        row_miss: ln_row_miss,
        col_miss: ln_col_miss,
    } = *graph;
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
        let f = fold_columns(d, full & !s, |f, c| f + ln_col_miss[c]);
        total = ln_add(total, f);
    }
    total
}

/// One row of the subset DP of (20): dp[S] ← dp[S]·m + Σ_{c∈S} dp[S∖{c}]·row[c] for every
/// subset S of the columns (`dp.len()` = 2^columns), in place and descending so that dp[S∖{c}]
/// is still the previous row's value.
#[inline(always)]
pub(super) fn dp_row(dp: &mut [f64], m: f64, row: &[f64]) {
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

/// `f` combined with `factor(c)` for every column c of the set `out`, lowest first: the
/// unmatched columns' miss factors of one subset of (20)'s sum over matchings (`op` is × in
/// the plain sums, + in the log one).
#[inline(always)]
pub(super) fn fold_columns(mut f: f64, mut out: usize, op: impl Fn(f64, usize) -> f64) -> f64 {
    while out != 0 {
        let c = out.trailing_zeros() as usize;
        out &= out - 1;
        f = op(f, c);
    }
    f
}
