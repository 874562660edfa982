//! The cardinality pmf of a multi-Bernoulli RFS (the Poisson-binomial distribution) and its
//! leave-one-out pmfs.
//!
//! A multi-Bernoulli RFS with existence probabilities `r_1 … r_M` has a cardinality `N` that
//! is a sum of independent Bernoulli variables, so its pmf is the convolution
//!
//! ```text
//! ρ(n) = Σ_{|I| = n} Π_{i∈I} r_i Π_{j∉I} (1 − r_j),   n = 0 … M
//! ```
//!
//! (Mahler, *Advances in Statistical Multisource-Multitarget Information Fusion*, 2014, p. 102,
//! cited as ref. 27 in `003_…`; eq. (88) of `001_…` with r_S = r). It is computed by the
//! recursion `ρ_k(n) = (1 − r_k) ρ_{k−1}(n) + r_k ρ_{k−1}(n − 1)`, which only adds and
//! multiplies nonnegative numbers: every entry is nonnegative and accurate to a few ulps
//! *relative to itself*, with no cancellation. (The DFT form (90) of `001_…` and the
//! characteristic-function methods used elsewhere cancel terms and can return negative
//! "probabilities" in the tails.) The result is finally normalised by its compensated sum, so
//! it sums to 1 within a few ulps for any M.
//!
//! `ρ_{−i}`, the pmf of all components but the i-th, appears in the mean-square OSPA error
//! (Lemma 4 (7) of `003_…`). [`for_each_leave_one_out`] produces all M of them in
//! `O(M² log M)` time and `O(M log M)` memory by a divide-and-conquer over a balanced tree —
//! again only nonnegative products and sums, never a deconvolution (dividing out a component
//! is unstable when r_i is near 1/2).

use alloc::vec;
use alloc::vec::Vec;

use crate::error::{Error, Result, check_probabilities};
use crate::math::sum::NeumaierSum;

/// The most components (existence probabilities) whose cardinality pmf is computed: 20,000.
/// The exact recursion costs M²/2 multiply-adds, about 0.3 s at the cap in Node; beyond it
/// [`multi_bernoulli_cardinality`] (and the estimators built on the pmf) return
/// [`Error::Count`] naming `existence`.
pub const MAX_COMPONENTS: usize = 20_000;

/// The most components [`leave_one_out_cardinalities`] accepts: 1,000 (its result holds M²
/// numbers; about 0.3 s at the cap in Node). [`for_each_leave_one_out`] streams them
/// without a cap.
pub const MAX_LEAVE_ONE_OUT_COMPONENTS: usize = 1_000;

/// `Ok` if `existence` has at most `max` components, else [`Error::Count`] naming it.
pub(crate) fn check_components(existence: &[f64], max: usize) -> Result<()> {
    Error::check_count("existence", "components", existence.len(), 0, max)
}

/// The cardinality pmf `ρ(0) … ρ(M)` of a multi-Bernoulli with existence probabilities `r`.
///
/// # Errors
/// [`crate::Error::InvalidProbability`] naming `existence[i]` for a NaN or a value outside
/// [0, 1]; [`Error::Count`] naming `existence` beyond [`MAX_COMPONENTS`] components.
///
/// # Examples
/// ```
/// let rho = fisst::cardinality::multi_bernoulli_cardinality(&[0.5, 0.5]).unwrap();
/// assert_eq!(rho, vec![0.25, 0.5, 0.25]);
/// ```
pub fn multi_bernoulli_cardinality(existence: &[f64]) -> Result<Vec<f64>> {
    check_components(existence, MAX_COMPONENTS)?;
    check_probabilities("existence", existence)?;
    Ok(pmf_unchecked(existence))
}

/// [`multi_bernoulli_cardinality`] for inputs the caller has validated.
pub(crate) fn pmf_unchecked(r: &[f64]) -> Vec<f64> {
    let mut pmf = raw_pmf(r);
    normalise(&mut pmf);
    pmf
}

/// The convolution recursion without the final normalisation.
fn raw_pmf(r: &[f64]) -> Vec<f64> {
    let m = r.len();
    let mut cur = vec![0.0; m + 1];
    let mut next = vec![0.0; m + 1];
    cur[0] = 1.0;
    for (k, &rk) in r.iter().enumerate() {
        let qk = 1.0 - rk;
        // next[n] = q cur[n] + r cur[n−1] for n = 1 … k; written with zipped slices so the
        // loop vectorises.
        next[0] = qk * cur[0];
        for ((out, &a), &b) in next[1..=k].iter_mut().zip(&cur[1..=k]).zip(&cur[0..k]) {
            *out = qk * a + rk * b;
        }
        next[k + 1] = rk * cur[k];
        core::mem::swap(&mut cur, &mut next);
    }
    cur
}

fn normalise(pmf: &mut [f64]) {
    let total = pmf.iter().copied().collect::<NeumaierSum>().total();
    if total > 0.0 && total != 1.0 {
        for v in pmf.iter_mut() {
            *v /= total;
        }
    }
}

/// The full convolution of two nonnegative sequences.
pub(crate) fn convolve(a: &[f64], b: &[f64]) -> Vec<f64> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![0.0; a.len() + b.len() - 1];
    for (i, &ai) in a.iter().enumerate() {
        if ai == 0.0 {
            continue;
        }
        for (o, &bj) in out[i..i + b.len()].iter_mut().zip(b) {
            *o += ai * bj;
        }
    }
    out
}

/// Calls `visit(i, ρ_{−i})` for every component i = 0 … M−1, in increasing i, where `ρ_{−i}`
/// (length M) is the cardinality pmf of the multi-Bernoulli without component i.
///
/// Divide and conquer: a node covering components `[lo, hi)` receives the pmf of everything
/// outside it, convolves it with the pmf of its right half to hand to its left half and vice
/// versa, so each tree level costs `O(M²)` and the whole visit `O(M² log M)`.
///
/// # Errors
/// As [`multi_bernoulli_cardinality`].
pub fn for_each_leave_one_out(
    existence: &[f64],
    mut visit: impl FnMut(usize, &[f64]),
) -> Result<()> {
    check_probabilities("existence", existence)?;
    if !existence.is_empty() {
        descend(existence, 0, &[1.0], &mut visit);
    }
    Ok(())
}

fn descend(r: &[f64], offset: usize, outside: &[f64], visit: &mut impl FnMut(usize, &[f64])) {
    if r.len() == 1 {
        let mut pmf = outside.to_vec();
        normalise(&mut pmf);
        visit(offset, &pmf);
        return;
    }
    let mid = r.len() / 2;
    let (left, right) = r.split_at(mid);
    let for_left = convolve(outside, &raw_pmf(right));
    descend(left, offset, &for_left, visit);
    drop(for_left);
    let for_right = convolve(outside, &raw_pmf(left));
    descend(right, offset + mid, &for_right, visit);
}

/// All leave-one-out pmfs `ρ_{−i}`, i = 0 … M−1, each of length M. Memory is `O(M²)`; use
/// [`for_each_leave_one_out`] to stream them instead.
///
/// # Errors
/// [`crate::Error::InvalidProbability`] naming `existence[i]`; [`Error::Count`] naming
/// `existence` beyond [`MAX_LEAVE_ONE_OUT_COMPONENTS`] components.
pub fn leave_one_out_cardinalities(existence: &[f64]) -> Result<Vec<Vec<f64>>> {
    check_components(existence, MAX_LEAVE_ONE_OUT_COMPONENTS)?;
    let mut out = Vec::with_capacity(existence.len());
    for_each_leave_one_out(existence, |_, pmf| out.push(pmf.to_vec()))?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Error;
    use rand::{RngExt, SeedableRng, rngs::SmallRng};

    /// ρ by enumerating all 2^M existence patterns.
    fn enumerate(r: &[f64]) -> Vec<f64> {
        let m = r.len();
        let mut pmf = vec![0.0; m + 1];
        for mask in 0u32..(1 << m) {
            let mut p = 1.0;
            for (i, &ri) in r.iter().enumerate() {
                p *= if mask >> i & 1 == 1 { ri } else { 1.0 - ri };
            }
            pmf[mask.count_ones() as usize] += p;
        }
        pmf
    }

    #[test]
    fn eq88_matches_enumeration() {
        let mut rng = SmallRng::seed_from_u64(2);
        for m in 0..=12 {
            for _ in 0..5 {
                let r: Vec<f64> = (0..m)
                    .map(|_| match rng.random_range(0..5) {
                        0 => 0.0,
                        1 => 1.0,
                        _ => rng.random_range(0.0..1.0),
                    })
                    .collect();
                let fast = multi_bernoulli_cardinality(&r).unwrap();
                let slow = enumerate(&r);
                for (a, b) in fast.iter().zip(&slow) {
                    assert!((a - b).abs() <= 1e-14, "{r:?}: {fast:?} vs {slow:?}");
                }
            }
        }
    }

    #[test]
    fn thousands_of_components_stay_a_pmf() {
        let mut rng = SmallRng::seed_from_u64(4);
        for m in [1000, 5000, 10_000] {
            let r: Vec<f64> = (0..m).map(|_| rng.random_range(0.0..1.0)).collect();
            let rho = multi_bernoulli_cardinality(&r).unwrap();
            assert_eq!(rho.len(), m + 1);
            assert!(rho.iter().all(|&v| v >= 0.0 && v.is_finite()));
            let total: f64 = rho.iter().copied().collect::<NeumaierSum>().total();
            assert!((total - 1.0).abs() <= 1e-12, "sum {total}");
            // mean and variance against Σr and Σr(1−r)
            let mean: f64 = rho.iter().enumerate().map(|(n, p)| n as f64 * p).sum();
            let var: f64 = rho
                .iter()
                .enumerate()
                .map(|(n, p)| (n as f64 - mean).powi(2) * p)
                .sum();
            let (em, ev) = r
                .iter()
                .fold((0.0, 0.0), |(a, b), &x| (a + x, b + x * (1.0 - x)));
            assert!((mean - em).abs() <= 1e-9 * em);
            assert!((var - ev).abs() <= 1e-8 * ev);
        }
    }

    #[test]
    fn lemma4_leave_one_out_matches_recomputation() {
        let mut rng = SmallRng::seed_from_u64(8);
        for m in 1..=40 {
            let r: Vec<f64> = (0..m)
                .map(|i| {
                    if i % 7 == 3 {
                        0.5
                    } else {
                        rng.random_range(0.0..1.0)
                    }
                })
                .collect();
            let loo = leave_one_out_cardinalities(&r).unwrap();
            assert_eq!(loo.len(), m);
            for (i, pmf) in loo.iter().enumerate() {
                let mut others = r.clone();
                others.remove(i);
                let direct = multi_bernoulli_cardinality(&others).unwrap();
                assert_eq!(pmf.len(), m);
                for (a, b) in pmf.iter().zip(&direct) {
                    assert!(*a >= 0.0);
                    assert!((a - b).abs() <= 1e-14, "m={m} i={i}");
                }
            }
        }
    }

    #[test]
    fn rejects_non_probabilities() {
        let e = multi_bernoulli_cardinality(&[0.2, f64::NAN]).unwrap_err();
        assert_eq!(e.field(), "existence[1]");
        let mut called = false;
        let e = for_each_leave_one_out(&[1.2], |_, _| called = true).unwrap_err();
        assert!(matches!(e, Error::InvalidProbability { .. }), "{e}");
        assert_eq!(e.field(), "existence[0]");
        assert!(!called, "the callback ran before the input was checked");
        assert_eq!(multi_bernoulli_cardinality(&[]).unwrap(), vec![1.0]);
    }

    #[test]
    fn eq88_and_lemma4_pmfs_are_capped_by_the_component_count() {
        // Found by the boundary fuzzer: 10^6 components ran for seconds (O(M²)).
        let over = vec![0.5; MAX_COMPONENTS + 1];
        let e = multi_bernoulli_cardinality(&over).unwrap_err();
        assert!(matches!(e, Error::Count { .. }), "{e}");
        assert_eq!(e.field(), "existence");
        assert_eq!(
            alloc::string::ToString::to_string(&e),
            "existence has 20001 components, at most 20000 are supported"
        );
        let rho = multi_bernoulli_cardinality(&over[..MAX_COMPONENTS]).unwrap();
        assert_eq!(rho.len(), MAX_COMPONENTS + 1);
        let over = vec![0.5; MAX_LEAVE_ONE_OUT_COMPONENTS + 1];
        let e = leave_one_out_cardinalities(&over).unwrap_err();
        assert_eq!(e.field(), "existence");
        let loo = leave_one_out_cardinalities(&over[..MAX_LEAVE_ONE_OUT_COMPONENTS]).unwrap();
        assert_eq!(loo.len(), MAX_LEAVE_ONE_OUT_COMPONENTS);
    }
}
