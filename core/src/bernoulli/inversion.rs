//! P(Q ≤ t) for Q = Σ_j y_j², y_j ~ N(μ_j, λ_j) independent (a generalised noncentral
//! chi-square), by Davies' midpoint rule for the Gil-Pelaez inversion formula, with rigorous
//! bounds on both its errors. Used for d ≥ 5, where the characteristic function decays fast
//! enough (like u^{−d/2}) for plain truncation.
//!
//! # Method
//! With φ(u) = E e^{iuQ} = Π_j (1 − 2iλ_j u)^{−1/2} exp(i u μ_j² / (1 − 2iλ_j u)) and the
//! spacing Δ = 2π/L (R. B. Davies, "Numerical inversion of a characteristic function,"
//! Biometrika 60(2):415–417, 1973, and Algorithm AS 155, Appl. Statist. 29:323–333, 1980):
//!
//! ```text
//! P(Q ≤ t) ≈ ½ − Σ_{k=0}^{K−1} Im[φ(u_k) e^{−i u_k t}] / (π (k + ½)),   u_k = (k + ½) Δ
//! ```
//!
//! - **Aliasing.** Summed to infinity the series equals ½ − ½ E[sgn sin(Δ(Q − t)/2)]
//!   (the Fourier series of a square wave), which is P(Q ≤ t) except on |Q − t| ≥ L; so its
//!   error lies between −P(Q ≤ t − L) and P(Q ≥ t + L). L ≥ t makes the first 0 (Q > 0), and
//!   L ≥ s − t with the Chernoff bound P(Q ≥ s) ≤ min_θ M(θ) e^{−θs},
//!   M(θ) = E e^{θQ} = Π_j (1 − 2θλ_j)^{−1/2} exp(θ μ_j² / (1 − 2θλ_j)), bounds the second.
//! - **Truncation.** |φ(u)| ≤ E(u) Π_j min(1, (2λ_j u)^{−1/2}) with the decreasing factor
//!   E(u) = exp(−Σ_j 2λ_j u² μ_j² / (1 + 4λ_j² u²)); for the set S of j with 2λ_j u_K ≥ 1 the
//!   terms k ≥ K sum to at most
//!   `E(u_K) Π_{j∈S} (2λ_j Δ)^{−1/2} (2 / (π |S|)) K^{−|S|/2}` (a convex decreasing summand is
//!   below its integral over [k, k + 1]). K is the smallest power-of-two multiple (then
//!   bisected) that brings this below its share of the tolerance.
//!
//! Both bounds are rigorous; the only other error is rounding in the sum (about K ε).

use crate::math::fns;
use crate::math::quadrature::Estimate;
use crate::math::sum::NeumaierSum;

/// P(Σ y_j² ≤ t) for y_j ~ N(μ_j, λ_j), λ_j > 0, to absolute error `tol` (0.4 `tol` each for
/// aliasing and truncation, the rest for rounding). At most `max_terms` terms are summed;
/// if that is not enough the returned error bound says so. `None` if the aliasing bound
/// cannot be formed (non-finite inputs).
pub(crate) fn cdf(
    lambda: &[f64],
    mu: &[f64],
    t: f64,
    tol: f64,
    max_terms: usize,
) -> Option<Estimate> {
    debug_assert!(lambda.iter().all(|&l| l > 0.0));
    if t <= 0.0 {
        return Some(Estimate {
            value: 0.0,
            error: 0.0,
            pieces: 0,
        });
    }
    let eps_alias = 0.4 * tol;
    let eps_trunc = 0.4 * tol;
    let s = chernoff_quantile(lambda, mu, eps_alias);
    let l = (s - t).max(t);
    if !(l.is_finite() && l > 0.0) {
        return None;
    }
    let delta = 2.0 * core::f64::consts::PI / l;
    let bound = |k: usize| truncation_bound(lambda, mu, delta, k);
    // Smallest K (doubling, then bisection) with bound(K) ≤ eps_trunc.
    let mut hi = 64usize.min(max_terms);
    while bound(hi) > eps_trunc {
        if hi >= max_terms {
            break;
        }
        hi = (2 * hi).min(max_terms);
    }
    let mut lo = hi / 2;
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if bound(mid) <= eps_trunc {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let k_max = hi;
    let mut total = NeumaierSum::new();
    // Rounding: each term carries a few ulps of its size, plus the absolute error of its
    // phase (a few ulps of |u t| + |arg φ|) times its modulus.
    let mut rounding = 0.0;
    for k in 0..k_max {
        let kh = k as f64 + 0.5;
        let u = kh * delta;
        let (ln_abs, arg) = ln_cf(lambda, mu, u);
        let modulus = fns::exp(ln_abs) / kh;
        let phase = arg - u * t;
        total.add(modulus * fns::sin(phase));
        rounding += modulus * (8.0 + 2.0 * (fns::abs(u * t) + fns::abs(arg)));
    }
    let value = 0.5 - total.total() / core::f64::consts::PI;
    Some(Estimate {
        value: value.clamp(0.0, 1.0),
        error: eps_alias + bound(k_max) + rounding * f64::EPSILON / core::f64::consts::PI,
        pieces: k_max,
    })
}

/// (ln |φ(u)|, arg φ(u)).
fn ln_cf(lambda: &[f64], mu: &[f64], u: f64) -> (f64, f64) {
    let mut ln_abs = 0.0;
    let mut arg = 0.0;
    for (&l, &m) in lambda.iter().zip(mu) {
        let x = 2.0 * l * u;
        let den = 1.0 + x * x;
        ln_abs += -0.25 * fns::ln_1p(x * x) - x * u * m * m / den;
        arg += 0.5 * fns::atan(x) + u * m * m / den;
    }
    (ln_abs, arg)
}

/// The truncation bound of the module docs for the terms k ≥ K.
fn truncation_bound(lambda: &[f64], mu: &[f64], delta: f64, k: usize) -> f64 {
    let u = k as f64 * delta;
    let mut ln_b = 0.0;
    let mut count = 0usize;
    for (&l, &m) in lambda.iter().zip(mu) {
        let x = 2.0 * l * u;
        ln_b -= x * u * m * m / (1.0 + x * x);
        if x >= 1.0 {
            ln_b -= 0.5 * fns::ln(2.0 * l * delta);
            count += 1;
        }
    }
    if count == 0 {
        return f64::INFINITY;
    }
    let c = count as f64;
    fns::exp(ln_b - 0.5 * c * fns::ln(k as f64)) * 2.0 / (core::f64::consts::PI * c)
}

/// An s with P(Q ≥ s) ≤ eps: min over θ ∈ (0, 1/(2λ_max)) of (ln M(θ) − ln eps)/θ, by
/// golden-section search (the objective is unimodal: its derivative is
/// (θ M'/M − ln M + ln(1/eps))/θ² with an increasing numerator).
fn chernoff_quantile(lambda: &[f64], mu: &[f64], eps: f64) -> f64 {
    let lmax = lambda.iter().copied().fold(0.0, f64::max);
    let c = -fns::ln(eps);
    let s_of = |x: f64| -> f64 {
        // θ = x / (2 λ_max), x ∈ (0, 1)
        let theta = x / (2.0 * lmax);
        let mut ln_m = 0.0;
        for (&l, &m) in lambda.iter().zip(mu) {
            let a = 1.0 - 2.0 * theta * l;
            ln_m += -0.5 * fns::ln(a) + theta * m * m / a;
        }
        (ln_m + c) / theta
    };
    // Any θ gives a valid bound; take the smaller of the two last evaluations.
    crate::math::optimise::golden_section(s_of, 1e-9, 1.0 - 1e-9, 90).1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bernoulli::chi_square::chi_square_sf;

    #[test]
    fn matches_central_chi_square() {
        for d in [5usize, 6, 8, 11] {
            for &(l, t) in &[
                (1.0, 1.0),
                (0.04, 1.0),
                (0.49, 4.0),
                (4.0, 0.25),
                (1.0, 30.0),
            ] {
                let lambda = alloc::vec![l; d];
                let mu = alloc::vec![0.0; d];
                let e = cdf(&lambda, &mu, t, 1e-10, 1 << 24).unwrap();
                let exact = 1.0 - chi_square_sf(d, t / l);
                assert!(
                    (e.value - exact).abs() < 1e-10,
                    "d={d} λ={l} t={t}: {} vs {exact}",
                    e.value
                );
                assert!(e.error <= 1e-10, "{e:?}");
            }
        }
    }

    #[test]
    fn chernoff_quantile_bounds_the_tail() {
        // For χ²_6 (λ = 1, μ = 0), P(Q ≥ s) = e^{−s/2}(1 + s/2 + s²/8) must be ≤ eps.
        let s = chernoff_quantile(&[1.0; 6], &[0.0; 6], 1e-11);
        let tail = (-s / 2.0).exp() * (1.0 + s / 2.0 + s * s / 8.0);
        assert!(tail <= 1e-11 && tail > 1e-14, "s={s} tail={tail}");
    }
}
