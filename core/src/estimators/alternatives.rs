//! The classical multi-object estimators that Fig. 2 of `003_…` compares with the
//! metric-optimal ones: the marginal multi-target (MaM) estimator, the joint multi-target (JoM)
//! estimator and "maximise the cardinality pmf, then report the most probable components".
//!
//! # The setting
//! A multi-Bernoulli whose component i exists with probability r_i and, if it exists, has a
//! Gaussian density N(·; m_i, P_i) of small covariance (Fig. 2 uses P_i = εI instead of the
//! Dirac deltas of Section III, for which MaM and JoM are undefined), with the components far
//! apart relative to their spreads. Its multi-object density at a set X = {x_i : i ∈ I} of
//! points placed at the means is, up to terms exponentially small in the separation,
//!
//! ```text
//! f({m_i : i ∈ I}) = Π_{j∉I} (1 − r_j) Π_{i∈I} r_i N(m_i; m_i, P_i),
//! N(m_i; m_i, P_i) = det(2π P_i)^(−1/2) =: exp(ln_peak_i)
//! ```
//!
//! and these are its local maxima, so every estimator below reports a set of means.
//!
//! # Decision rules (derived here; the tests check them against a direct grid maximisation)
//! - **MaM** (Mahler 2007, Sec. 14.5.2): n̂ = argmax_n ρ(n), then the maximiser of the n̂-object
//!   density. Among sets of size n̂, `f` is largest for the n̂ components of largest score
//!   `s_i = ln r_i − ln(1 − r_i) + ln_peak_i` (divide `f` by the constant Π_j (1 − r_j)).
//! - **JoM** (Mahler 2007, Sec. 14.5.3): maximise `f(X) c^|X| / |X|!` over all finite X, c a
//!   constant with units of volume. For each size k the best set is again the top-k by s_i;
//!   the size is the k maximising `Σ_{top k} (s_i + ln c) − ln k!`. With P_i = εI in d
//!   dimensions and `c = (2πε)^(d/2)` the objective becomes
//!   `Π_{j∉I} (1 − r_j) Π_{i∈I} r_i / |I|!`, free of ε (NOTES.md).
//! - **MAP cardinality, then most probable** (as in Vo & Vo 2013, ref. 30 of `003_…`): n̂ =
//!   argmax_n ρ(n), then the n̂ components of largest r_i.
//!
//! With equal covariances MaM and the third estimator coincide (the scores are ordered like
//! r_i); they differ when the spreads differ. Ties in ρ go to the smaller cardinality, ties in
//! score to the smaller index.
//!
//! # References
//! R. P. S. Mahler, *Statistical Multisource-Multitarget Information Fusion*, Artech House,
//! 2007, Sec. 14.5. Á. F. García-Fernández, L. Svensson, Fusion 2019 (`003_…`), Sec. III-C,
//! Fig. 2.

use alloc::vec;
use alloc::vec::Vec;

use nalgebra::DMatrix;

use crate::cardinality::MAX_COMPONENTS;
use crate::cardinality::multi_bernoulli::{check_components, pmf_unchecked};
use crate::error::{Error, Result, check_probabilities};
use crate::gaussian::covariance;
use crate::math::fns;
use crate::math::special::LN_2PI;

/// `ln N(m; m, P) = −½ ln det(2πP)`, the log peak height of a Gaussian.
///
/// # Errors
/// [`Error::DimensionMismatch`] naming `cov` if P is not square; [`Error::InvalidParameter`]
/// naming `cov[i][j]` for a non-finite entry; [`Error::NotSymmetric`] or
/// [`Error::NotDefinite`] naming `cov` (the checks of [`covariance`]).
pub fn gaussian_ln_peak(cov: &DMatrix<f64>) -> Result<f64> {
    let n = cov.nrows();
    if cov.ncols() != n {
        return Err(Error::dimension("cov", n, cov.ncols()));
    }
    if let Some(k) = cov.iter().position(|v| !v.is_finite()) {
        // nalgebra is column-major: k = col·n + row.
        return Err(Error::parameter(
            alloc::format!("cov[{}][{}]", k % n, k / n),
            cov[k],
            "finite",
        ));
    }
    covariance::check_symmetric(cov, &|| "cov".into())?;
    let chol = cov
        .clone()
        .cholesky()
        .ok_or_else(|| covariance::not_positive_definite(cov, "cov".into()))?;
    let ln_det: f64 = chol.l().diagonal().iter().map(|d| 2.0 * fns::ln(*d)).sum();
    Ok(-0.5 * (n as f64 * LN_2PI + ln_det))
}

/// `ln_peak` for the isotropic covariance εI in `dim` dimensions: `−(dim/2) ln(2πε)`.
pub fn isotropic_ln_peak(epsilon: f64, dim: usize) -> f64 {
    -0.5 * dim as f64 * fns::ln(2.0 * core::f64::consts::PI * epsilon)
}

fn check(existence: &[f64], ln_peak: &[f64]) -> Result<()> {
    check_probabilities("existence", existence)?;
    if ln_peak.len() != existence.len() {
        return Err(Error::dimension("lnPeak", existence.len(), ln_peak.len()));
    }
    if let Some(i) = ln_peak.iter().position(|v| !v.is_finite()) {
        return Err(Error::parameter(
            alloc::format!("lnPeak[{i}]"),
            ln_peak[i],
            "finite",
        ));
    }
    Ok(())
}

/// Indices sorted by decreasing `key`, ties by index.
fn ranked(key: &[f64]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..key.len()).collect();
    crate::math::sort::sort_by(&mut order, |&i, &j| {
        key[j].total_cmp(&key[i]).then(i.cmp(&j))
    });
    order
}

fn report_top(n: usize, order: &[usize], k: usize) -> Vec<bool> {
    let mut report = vec![false; n];
    for &i in &order[..k] {
        report[i] = true;
    }
    report
}

/// argmax_n ρ(n), the smallest on ties.
fn map_cardinality(existence: &[f64]) -> usize {
    let rho = pmf_unchecked(existence);
    let mut best = 0;
    for (n, &p) in rho.iter().enumerate() {
        if p > rho[best] {
            best = n;
        }
    }
    best
}

/// `s_i = ln r_i − ln(1 − r_i) + ln_peak_i` (±∞ for r_i ∈ {0, 1}).
fn scores(existence: &[f64], ln_peak: &[f64]) -> Vec<f64> {
    existence
        .iter()
        .zip(ln_peak)
        .map(|(&r, &lp)| fns::ln(r) - fns::ln_1p(-r) + lp)
        .collect()
}

/// "Maximise the cardinality pmf, then report the most probable components".
///
/// # Errors
/// [`Error::InvalidProbability`] naming `existence[i]`; [`Error::Count`] naming `existence`
/// beyond [`MAX_COMPONENTS`] (20,000) components (the pmf costs O(n²)).
pub fn map_cardinality_estimate(existence: &[f64]) -> Result<Vec<bool>> {
    check_probabilities("existence", existence)?;
    check_components(existence, MAX_COMPONENTS)?;
    let n_hat = map_cardinality(existence);
    Ok(report_top(existence.len(), &ranked(existence), n_hat))
}

/// The marginal multi-target (MaM) estimate: n̂ = argmax ρ, then the n̂ components of largest
/// `ln r_i − ln(1 − r_i) + ln_peak_i` (module docs).
///
/// # Errors
/// [`Error::InvalidProbability`] naming `existence[i]`; [`Error::DimensionMismatch`] or
/// [`Error::InvalidParameter`] naming `lnPeak`; [`Error::Count`] naming `existence` beyond
/// [`MAX_COMPONENTS`] (20,000) components (the pmf costs O(n²)).
pub fn mam_estimate(existence: &[f64], ln_peak: &[f64]) -> Result<Vec<bool>> {
    check(existence, ln_peak)?;
    check_components(existence, MAX_COMPONENTS)?;
    let n_hat = map_cardinality(existence);
    Ok(report_top(
        existence.len(),
        &ranked(&scores(existence, ln_peak)),
        n_hat,
    ))
}

/// The joint multi-target (JoM) estimate with constant `c` given as `ln_c` (module docs).
///
/// # Errors
/// As [`mam_estimate`], and [`Error::InvalidParameter`] naming `lnC` if it is not finite.
pub fn jom_estimate(existence: &[f64], ln_peak: &[f64], ln_c: f64) -> Result<Vec<bool>> {
    check(existence, ln_peak)?;
    if !ln_c.is_finite() {
        return Err(Error::parameter("lnC", ln_c, "finite"));
    }
    let n = existence.len();
    let order = ranked(&scores(existence, ln_peak));
    // objective_k = Σ_{i in top k} (ln r_i + ln_peak_i + ln c) + Σ_{j not in top k} ln(1 − r_j)
    //               − ln k!, from a prefix and a suffix sum so that −∞ terms never meet +∞.
    let mut suffix = vec![0.0; n + 1];
    for k in (0..n).rev() {
        suffix[k] = suffix[k + 1] + fns::ln_1p(-existence[order[k]]);
    }
    let (mut best_k, mut best) = (0, suffix[0]);
    let mut prefix = 0.0;
    let mut ln_fact = 0.0;
    for k in 1..=n {
        let i = order[k - 1];
        prefix += fns::ln(existence[i]) + ln_peak[i] + ln_c;
        ln_fact += fns::ln(k as f64);
        let objective = prefix + suffix[k] - ln_fact;
        if objective > best {
            (best_k, best) = (k, objective);
        }
    }
    Ok(report_top(n, &order, best_k))
}

/// One of the classical estimators of Fig. 2 of García-Fernández & Svensson, "Spooky effect in
/// optimal OSPA estimation and how GOSPA solves it" (paper 003).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "kebab-case"))]
pub enum AlternativeMethod {
    /// Marginal multi-target ([`mam_estimate`]).
    Mam,
    /// Joint multi-target ([`jom_estimate`]).
    Jom,
    /// MAP cardinality, then the most probable components ([`map_cardinality_estimate`]).
    MapCardinality,
}

/// The estimate of `method`: [`mam_estimate`], [`jom_estimate`] or
/// [`map_cardinality_estimate`] (which ignores `ln_peak` and `ln_c`; MaM ignores `ln_c`).
///
/// # Errors
/// As the estimator called.
pub fn alternative_estimate(
    existence: &[f64],
    method: AlternativeMethod,
    ln_peak: &[f64],
    ln_c: f64,
) -> Result<Vec<bool>> {
    match method {
        AlternativeMethod::Mam => mam_estimate(existence, ln_peak),
        AlternativeMethod::Jom => jom_estimate(existence, ln_peak, ln_c),
        AlternativeMethod::MapCardinality => map_cardinality_estimate(existence),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::string::ToString;

    #[test]
    fn fig2_alternative_estimate_dispatches_to_each_rule() {
        let (r, lp) = ([0.3, 0.6, 0.45], [0.0, 1.0, -0.5]);
        let call = |m| alternative_estimate(&r, m, &lp, 0.2).unwrap();
        assert_eq!(call(AlternativeMethod::Mam), mam_estimate(&r, &lp).unwrap());
        assert_eq!(
            call(AlternativeMethod::Jom),
            jom_estimate(&r, &lp, 0.2).unwrap()
        );
        assert_eq!(
            call(AlternativeMethod::MapCardinality),
            map_cardinality_estimate(&r).unwrap()
        );
    }

    #[test]
    fn two_component_rules() {
        // MAP cardinality for two components: ρ = ((1−a)(1−b), a(1−b)+(1−a)b, ab).
        assert_eq!(
            map_cardinality_estimate(&[0.4, 0.45]).unwrap(),
            vec![false, true]
        );
        assert_eq!(
            map_cardinality_estimate(&[0.9, 0.8]).unwrap(),
            vec![true, true]
        );
        assert_eq!(
            map_cardinality_estimate(&[0.2, 0.1]).unwrap(),
            vec![false, false]
        );
        // JoM with the ε-free constant: ∅ ↦ (1−a)(1−b), {1} ↦ a(1−b), {1,2} ↦ ab/2.
        let lp = [0.0, 0.0];
        assert_eq!(
            jom_estimate(&[0.6, 0.6], &lp, 0.0).unwrap(),
            vec![true, false]
        );
        assert_eq!(
            jom_estimate(&[0.95, 0.9], &lp, 0.0).unwrap(),
            vec![true, true]
        );
        assert_eq!(
            jom_estimate(&[0.3, 0.2], &lp, 0.0).unwrap(),
            vec![false, false]
        );
        // certain components are always reported, impossible ones never
        assert_eq!(
            jom_estimate(&[1.0, 0.0, 1.0], &[0.0; 3], 0.0).unwrap(),
            vec![true, false, true]
        );
        assert_eq!(
            mam_estimate(&[1.0, 0.0, 1.0], &[0.0; 3]).unwrap(),
            vec![true, false, true]
        );
    }

    #[test]
    fn mam_prefers_the_sharper_component_when_spreads_differ() {
        // Equal existence, one much tighter covariance: MaM picks the tighter one, the
        // MAP-then-most-probable rule the first by index.
        let r = [0.5, 0.5, 0.01];
        let lp = [isotropic_ln_peak(1.0, 2), isotropic_ln_peak(0.01, 2), 0.0];
        assert_eq!(mam_estimate(&r, &lp).unwrap(), vec![false, true, false]);
        assert_eq!(
            map_cardinality_estimate(&r).unwrap(),
            vec![true, false, false]
        );
    }

    #[test]
    fn ln_peak_of_a_gaussian() {
        let cov = DMatrix::from_row_slice(2, 2, &[2.0, 0.5, 0.5, 1.0]);
        let det: f64 = 2.0 * 1.0 - 0.25;
        let expected = -0.5 * ((2.0 * core::f64::consts::PI).powi(2) * det).ln();
        assert!((gaussian_ln_peak(&cov).unwrap() - expected).abs() < 1e-14);
        let say = |m: &DMatrix<f64>| gaussian_ln_peak(m).unwrap_err().to_string();
        let bad = DMatrix::from_row_slice(2, 2, &[1.25, 0.0, 0.0, -0.25]);
        assert_eq!(
            say(&bad),
            "cov is not positive definite (smallest eigenvalue -0.25)"
        );
        let not_square = DMatrix::from_row_slice(1, 2, &[1.0, 0.0]);
        assert_eq!(say(&not_square), "cov has length 2, expected 1");
        let asymmetric = DMatrix::from_row_slice(2, 2, &[1.0, 0.1, 0.0, 1.0]);
        assert_eq!(
            say(&asymmetric),
            "cov is not symmetric: [0][1] = 0.1 but [1][0] = 0"
        );
        let nan = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, f64::NAN, 1.0]);
        assert_eq!(say(&nan), "cov[1][0] must be finite, got NaN");
        assert!(
            (isotropic_ln_peak(0.5, 2)
                - gaussian_ln_peak(&DMatrix::identity(2, 2).scale(0.5)).unwrap())
            .abs()
                < 1e-14
        );
    }
}
