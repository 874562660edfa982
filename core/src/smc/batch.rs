//! The batch interface to eq. (20) of paper `004` (Ristic & Vo) that the sensor control's
//! Rényi reward (17) calls: e^{λ} g(Z | X_q) in plain arithmetic for many sets X_q of the same
//! cardinality against one scan Z, with one dispatch table over the fixed sizes of
//! [`super::fixed`], and the bound below which a pair factor may be dropped.

use super::fixed::{
    MAX_LARGER, SMALL_FLOOR, SMALL_SIDE, SmallTables, sum_fixed, sum_fixed_lanes,
    sum_matchings_small,
};
use super::likelihood::MultiObjectLikelihood;

/// The sets of one cardinality that [`BatchLikelihood::scaled_likelihoods`] evaluates at once
/// by [`sum_fixed_lanes`] (eq. (20) of paper `004`): independent chains of the same
/// operations, one per particle.
const LANES: usize = 4;

/// ln of the largest pair factor that [`BatchLikelihood::negligible_pair_bound`] lets one replace by 0, as a
/// multiple of ln 2: 2^{−64}.
const NEGLIGIBLE_LN: f64 = -64.0 * core::f64::consts::LN_2;

/// The batch evaluation of (20) for one model: its scratch tables, made once and reused
/// across batches.
#[derive(Clone, Debug)]
pub(crate) struct BatchLikelihood {
    tables: SmallTables,
}

impl BatchLikelihood {
    /// The scratch of `model` (its miss factor 1 − p_D).
    pub(crate) fn new(model: &MultiObjectLikelihood) -> Self {
        Self {
            tables: SmallTables {
                pair: [0.0; MAX_LARGER * SMALL_SIDE],
                miss: [1.0 - model.detection(); MAX_LARGER],
            },
        }
    }

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

    /// e^{λ} g(Z | X_q) of (20) (above e^{−670}) in plain arithmetic for `out.len()` sets of
    /// `n` objects at once: the pair factors p_D g(z_j | x_o) of set q at
    /// `factors[(j·n + o)·count + q]` (measurement j, object o, count = `out.len()`) and
    /// `clutter[j]` = λ c(z_j) (m = `clutter.len()`), all in [0, 1] (the caller's invariant).
    /// `out[q]` is the value, NaN where it declined: min(n, m) > 4, max(n, m) > 16, or
    /// gradual underflow could matter (see [`sum_matchings_small`]); the caller then evaluates
    /// [`MultiObjectLikelihood::ln_likelihood_from_logs`], which is exact at every scale.
    ///
    /// The common sizes (n, m ≤ 4) go to a kernel unrolled for them, [`LANES`] sets at a time
    /// ([`sum_fixed_lanes`], then [`sum_fixed`] for the last few), the others to the fixed
    /// tables ([`sum_matchings_small`], the smaller side as the columns); all with the
    /// operations of the general programme in the same order (the same bits), except that
    /// the unrolled kernels fold the last row into the final sum when n ≤ m, n, m ≥ 1 (within
    /// 10⁻¹⁵ relatively; see `smc/fixed.rs`). The loop over
    /// the sets is the inner one, so the size dispatch is paid once per batch and not once per
    /// set.
    pub(crate) fn scaled_likelihoods(
        &mut self,
        n: usize,
        clutter: &[f64],
        factors: &[f64],
        out: &mut [f64],
    ) {
        let m = clutter.len();
        let count = out.len();
        assert_eq!(factors.len(), n * m * count);
        if n.min(m) > SMALL_SIDE || n.max(m) > MAX_LARGER {
            out.fill(f64::NAN);
            return;
        }
        let SmallTables { pair, miss } = &mut self.tables;
        // The one dispatch table of the unrolled sizes.
        macro_rules! fixed {
            ($(($a:literal, $b:literal)),*) => {
                match (n, m) {
                    $(($a, $b) => {
                        let whole = count - count % LANES;
                        for (q, t) in out[..whole].chunks_exact_mut(LANES).enumerate() {
                            let q = q * LANES;
                            let v = sum_fixed_lanes::<$a, $b, LANES>(miss[0], clutter, &|o, j| {
                                let at = (j * $a + o) * count + q;
                                core::array::from_fn(|l| factors[at + l])
                            });
                            for (t, v) in t.iter_mut().zip(v) {
                                *t = if v > SMALL_FLOOR { v } else { f64::NAN };
                            }
                        }
                        for (q, t) in out.iter_mut().enumerate().skip(whole) {
                            let v = sum_fixed::<$a, $b>(miss[0], clutter, &|o, j| {
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
            (3, 3),
            (0, 4),
            (1, 4),
            (2, 4),
            (3, 4),
            (4, 0),
            (4, 1),
            (4, 2),
            (4, 3),
            (4, 4)
        );
        for (q, t) in out.iter_mut().enumerate() {
            let factor = |o: usize, j: usize| factors[(j * n + o) * count + q];
            let v = if n > m {
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
            };
            *t = v.unwrap_or(f64::NAN);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::fns::{exp, ln};
    use crate::math::rng::{seeded, uniform};
    use crate::smc::LikelihoodWorkspace;
    use alloc::vec;
    use alloc::vec::Vec;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a == b) || (a - b).abs() <= tol * (1.0 + a.abs().max(b.abs()))
    }

    /// ln g(Z | X) of (20) for one set by the batch interface: `pair[i·m + j]` = p_D g(z_j | x_i)
    /// and `clutter[j]` = λ c(z_j), `None` where a factor is outside [0, 1] or it declined.
    fn ln_likelihood_small(
        model: &MultiObjectLikelihood,
        n: usize,
        pair: &[f64],
        clutter: &[f64],
    ) -> Option<f64> {
        let m = clutter.len();
        let unit = |v: &f64| (0.0..=1.0).contains(v);
        if pair.len() != n * m || !(pair.iter().all(unit) && clutter.iter().all(unit)) {
            return None;
        }
        let factors: Vec<f64> = (0..m)
            .flat_map(|j| (0..n).map(move |o| (o, j)))
            .map(|(o, j)| pair[o * m + j])
            .collect();
        let mut out = [0.0];
        BatchLikelihood::new(model).scaled_likelihoods(n, clutter, &factors, &mut out);
        (!out[0].is_nan()).then(|| -model.clutter_rate() + ln(out[0]))
    }

    #[test]
    fn eq20_small_plain_path_matches_the_log_path() {
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
                    match ln_likelihood_small(&model, n, &pair, &clutter) {
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
        // Of the 7·7·6 = 294 cases, these many take the plain path (seed 41).
        assert_eq!(taken, 218);
        // Underflow: the plain sum of 1e-200 · 1e-220 is 0; declined, the log path is exact.
        let model = MultiObjectLikelihood::new(1.0, 0.0).unwrap();
        assert_eq!(
            ln_likelihood_small(&model, 2, &[1e-200, 0.0, 0.0, 1e-220], &[0.0, 0.0]),
            None
        );
        // Factors above 1 are declined.
        let model = MultiObjectLikelihood::new(0.9, 0.8).unwrap();
        assert_eq!(ln_likelihood_small(&model, 1, &[2.0], &[0.5]), None);
        assert_eq!(ln_likelihood_small(&model, 1, &[0.5], &[f64::NAN]), None);
        assert!(ln_likelihood_small(&model, 1, &[0.5], &[0.5]).is_some());
    }

    /// The unrolled kernels of the batch give the sums of the table-driven programme, in both
    /// orientations, for every set of a batch: those of the lanes ([`sum_fixed_lanes`]) and
    /// those after the last whole group of lanes, with exact zeros among the factors (as the
    /// kernel's dropped pairs). Bit for bit with more objects than measurements (the same
    /// operations in the same order); otherwise within 10⁻¹⁵ relatively, since the kernels
    /// fold the last row into the final sum there (measured: at most 3.0·10⁻¹⁶).
    #[test]
    fn eq20_fixed_kernels_match_the_tables() {
        let mut rng = seeded(77);
        let model = MultiObjectLikelihood::new(0.9, 0.8).unwrap();
        let mut batch = BatchLikelihood::new(&model);
        let count = 4 * LANES + 3;
        let mut worst = 0.0f64;
        for n in 0..=SMALL_SIDE {
            for m in 0..=SMALL_SIDE {
                let pairs: Vec<Vec<f64>> = (0..count)
                    .map(|_| {
                        (0..n * m)
                            .map(|_| {
                                let u = uniform(&mut rng);
                                if u < 0.4 { 0.0 } else { u }
                            })
                            .collect()
                    })
                    .collect();
                let clutter: Vec<f64> = (0..m).map(|_| uniform(&mut rng)).collect();
                let mut factors = vec![0.0; n * m * count];
                for (q, pair) in pairs.iter().enumerate() {
                    for j in 0..m {
                        for o in 0..n {
                            factors[(j * n + o) * count + q] = pair[o * m + j];
                        }
                    }
                }
                let mut out = vec![0.0; count];
                batch.scaled_likelihoods(n, &clutter, &factors, &mut out);
                for (pair, fixed) in pairs.iter().zip(&out) {
                    let miss = [1.0 - 0.9; SMALL_SIDE];
                    let table = if n > m {
                        sum_matchings_small(n, m, pair, &miss[..n], &clutter)
                    } else {
                        let t: Vec<f64> = (0..m)
                            .flat_map(|j| (0..n).map(move |i| (i, j)))
                            .map(|(i, j)| pair[i * m + j])
                            .collect();
                        sum_matchings_small(m, n, &t, &clutter, &miss[..n])
                    };
                    let table = table.unwrap();
                    if n > m || m == 0 {
                        assert_eq!(fixed.to_bits(), table.to_bits(), "n={n} m={m}");
                    } else {
                        let rel = (fixed - table).abs() / table;
                        worst = worst.max(rel);
                        assert!(rel <= 1e-15, "n={n} m={m}: {fixed} against {table}");
                    }
                }
            }
        }
        std::eprintln!("folded kernels: at most {worst:e} relatively from the tables");
        assert!(worst > 0.0, "the folded kernels were not exercised");
    }

    /// The inequality behind `negligible_pair_bound`: pair factors f_ij ≤ 2^{−b} r_i c_j set
    /// to 0 lower the sum by a relative amount in [0, k·2^{−b}] (k of them), checked at
    /// b = 20 where it is far above rounding, and tight for one pair.
    #[test]
    fn eq20_negligible_pairs_change_the_sum_by_at_most_the_bound() {
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
                    let t_full = ln_likelihood_small(&model, n, &full, &clutter).unwrap();
                    let t_drop = ln_likelihood_small(&model, n, &dropped, &clutter).unwrap();
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
        let ln_b = BatchLikelihood::negligible_pair_bound(ln(0.05), ln(1e-3));
        assert!((ln_b - (ln(0.05) + ln(1e-3) - 64.0 * core::f64::consts::LN_2)).abs() < 1e-12);
    }
}
