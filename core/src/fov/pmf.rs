//! The FoV cardinality pmfs of Section VI of `001_…`, from the inclusion probabilities.

use alloc::vec;
use alloc::vec::Vec;

use crate::cardinality::multi_bernoulli::pmf_unchecked;
use crate::error::{Error, Result, check_probabilities, check_probability};
use crate::math::fns;
use crate::math::special::poisson_pmf;
use crate::math::sum::{NeumaierSum, sum};

/// The largest pmf any function here builds (2²⁰ entries).
pub const MAX_PMF_LEN: usize = 1 << 20;
/// Poisson and i.i.d.-cluster pmfs stop where the mass left beyond them is below this.
pub const TAIL_TOLERANCE: f64 = 1e-15;
/// The largest number of components [`multi_bernoulli_enumerated`] accepts (3^12 terms).
pub const MAX_ENUMERATED: usize = 12;

/// The pmf ρ_S(n), n = 0 … `pmf.len() − 1`, of the number of objects in a region, with its
/// mean and variance.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FovCardinality {
    /// The pmf ρ_S(0), ρ_S(1), … of the number of objects in the field of view S.
    pub pmf: Vec<f64>,
    /// E[|X ∩ S|], by the closed form of each function (not from the truncated pmf).
    pub mean: f64,
    /// Var[|X ∩ S|], by the closed form of each function.
    pub variance: f64,
    /// An upper bound on the probability beyond the last entry of `pmf` (below
    /// [`TAIL_TOLERANCE`] for Poisson and i.i.d. cluster, 0 where the support is finite and
    /// complete).
    pub truncated: f64,
}

fn check_nonnegative(what: impl FnOnce() -> alloc::string::String, x: f64) -> Result<f64> {
    if x.is_finite() && x >= 0.0 {
        Ok(x)
    } else {
        Err(Error::parameter(what(), x, "finite and >= 0"))
    }
}

// ---------------------------------------------------------------------------------------
// Poisson (78)

/// The FoV cardinality pmf of a Poisson RFS, Proposition 1, eq. (78) of `001_…`:
///
/// ```text
/// ρ_S(n) = Σ_{m=n}^{∞} e^{−N_X} / (n! (m − n)!) · ⟨1_S, D⟩ⁿ ⟨1 − 1_S, D⟩^{m−n}
///        = e^{−λ_S} λ_Sⁿ / n!,    λ_S = ⟨1_S, D⟩
/// ```
///
/// The series over m sums in closed form (Σ_j λ_Cʲ/j! = e^{λ_C} and λ_C = N_X − λ_S by
/// (82)): the count in S is Poisson with mean λ_S, the PHD mass inside S, whatever N_X is.
/// Each entry is computed directly (Loader's saddle-point form, relative error a few ulps) —
/// no truncation of the series over m is needed. **Truncation of the pmf**: entries
/// n = 0 … n_max, with n_max the first n ≥ λ_S whose tail bound
/// `ρ_S(n + 1) / (1 − λ_S/(n + 2)) ≥ Σ_{k>n} ρ_S(k)` is below 1e-15; the bound is returned as
/// `truncated`. Mean and variance: λ_S (closed form). For the detection count (75) with a
/// constant p_D pass λ_S = p_D ⟨1_S, D⟩.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `inside` if λ_S is negative or not finite;
/// [`Error::Unsupported`] if the pmf would exceed [`MAX_PMF_LEN`] entries (λ_S ≳ 1.04e6).
///
/// # Examples
/// ```
/// let c = fisst::fov::poisson(2.0)?;
/// assert!((c.pmf[0] - (-2.0f64).exp()).abs() < 1e-16);
/// assert!(c.truncated < 1e-15 && c.mean == 2.0 && c.variance == 2.0);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn poisson(inside: f64) -> Result<FovCardinality> {
    let lambda = check_nonnegative(|| "inside".into(), inside)?;
    let mut pmf = Vec::new();
    let mut n = 0usize;
    loop {
        if pmf.len() >= MAX_PMF_LEN {
            return Err(Error::Unsupported {
                what: "inside".into(),
                reason: "the Poisson pmf would have more than 2^20 entries",
            });
        }
        pmf.push(poisson_pmf(lambda, n));
        if (n + 2) as f64 > lambda {
            let next = poisson_pmf(lambda, n + 1);
            let tail = next / (1.0 - lambda / (n + 2) as f64);
            if n as f64 >= lambda && tail < TAIL_TOLERANCE {
                return Ok(FovCardinality {
                    pmf,
                    mean: lambda,
                    variance: lambda,
                    truncated: tail,
                });
            }
        }
        n += 1;
    }
}

// ---------------------------------------------------------------------------------------
// i.i.d. cluster (84)

/// The FoV cardinality pmf of an i.i.d. cluster RFS, Proposition 2, eq. (84) of `001_…`:
///
/// ```text
/// ρ_S(n) = Σ_{m=n}^{∞} ρ(m) C(m, n) ⟨1_S, p⟩ⁿ ⟨1 − 1_S, p⟩^{m−n}
/// ```
///
/// (binomial thinning of ρ with q = ⟨1_S, p⟩ = `inside`). Computed through the probability
/// generating function, G_S(z) = G(1 − q + qz), by Horner's scheme: each step multiplies a
/// polynomial with nonnegative coefficients by (1 − q + qz) and adds ρ(m) — only sums of
/// nonnegative products, so every entry is accurate relative to itself. `O(M²)` for
/// `cardinality.len() = M + 1`. **Truncation**: trailing entries are dropped while the
/// dropped total stays below 1e-15 (returned as `truncated`). Mean qE\[N\] and variance
/// q² Var\[N\] + q(1 − q) E\[N\] (closed forms, law of total variance). For the detection count
/// (75) pass q = p_D ⟨1_S, p⟩.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `cardinality[n]` for a negative or non-finite entry,
/// `cardinality` if the entries do not sum to 1 within 1e-9 (they are then normalised),
/// [`Error::InvalidProbability`] naming `inside`; [`Error::Unsupported`] for more than
/// [`MAX_PMF_LEN`] entries.
pub fn iid_cluster(cardinality: &[f64], inside: f64) -> Result<FovCardinality> {
    check_probability(|| "inside".into(), inside)?;
    for (n, &p) in cardinality.iter().enumerate() {
        check_nonnegative(|| alloc::format!("cardinality[{n}]"), p)?;
    }
    if cardinality.len() > MAX_PMF_LEN {
        return Err(Error::Unsupported {
            what: "cardinality".into(),
            reason: "the cardinality pmf has more than 2^20 entries",
        });
    }
    let total = sum(cardinality.iter().copied());
    if total.is_nan() || fns::abs(total - 1.0) > 1e-9 {
        return Err(Error::parameter(
            "cardinality",
            total,
            "a pmf summing to 1 within 1e-9 (the value is its sum)",
        ));
    }
    let rho: Vec<f64> = cardinality.iter().map(|p| p / total).collect();
    let q = inside;
    let mut acc: Vec<f64> = Vec::with_capacity(rho.len());
    for &r in rho.iter().rev() {
        // acc ← acc · (1 − q + q z) + r
        acc.push(0.0);
        for i in (1..acc.len()).rev() {
            acc[i] = (1.0 - q) * acc[i] + q * acc[i - 1];
        }
        acc[0] = (1.0 - q) * acc[0] + r;
    }
    if acc.is_empty() {
        acc.push(1.0);
    }
    let mut truncated = 0.0;
    while acc.len() > 1 {
        let last = acc[acc.len() - 1];
        if truncated + last < TAIL_TOLERANCE {
            truncated += last;
            acc.pop();
        } else {
            break;
        }
    }
    let mean_n = sum(rho.iter().enumerate().map(|(n, p)| n as f64 * p));
    let var_n = sum(rho
        .iter()
        .enumerate()
        .map(|(n, p)| (n as f64 - mean_n) * (n as f64 - mean_n) * p));
    Ok(FovCardinality {
        pmf: acc,
        mean: q * mean_n,
        variance: q * q * var_n + q * (1.0 - q) * mean_n,
        truncated,
    })
}

// ---------------------------------------------------------------------------------------
// Multi-Bernoulli (88)–(90)

/// The FoV cardinality pmf of a multi-Bernoulli RFS, Proposition 3, eq. (88) of `001_…`,
/// by the stable method. With r_S⁽ⁱ⁾ = r⁽ⁱ⁾ ⟨1_S, p⁽ⁱ⁾⟩ (eq. (89); `inside[i]`), (88) is the
/// Poisson-binomial pmf of the r_S⁽ⁱ⁾:
///
/// ```text
/// ρ_S(n) = Π_i (1 − r⁽ⁱ⁾) Σ_{I₁ ⊎ I₂ ⊆ ℕ_M} δ_n(|I₁|) Π_{I₁} ⟨1_S, r p⟩/(1 − r) Π_{I₂} ⟨1 − 1_S, r p⟩/(1 − r)
///        = Σ_{|I| = n} Π_{i∈I} r_S⁽ⁱ⁾ Π_{j∉I} (1 − r_S⁽ʲ⁾)
/// ```
///
/// (summing over I₂ for a fixed I₁ collapses each non-I₁ factor to 1 − r + r⟨1 − 1_S, p⟩ =
/// 1 − r_S). Computed by the convolution recursion of
/// [`multi_bernoulli_cardinality`](crate::cardinality::multi_bernoulli_cardinality): only
/// sums of nonnegative products, so every entry is nonnegative and the pmf sums to 1 within
/// a few ulps for any M (tested to 1e-12 at M = 10 000). Mean Σ r_S⁽ⁱ⁾ and variance
/// Σ r_S⁽ⁱ⁾(1 − r_S⁽ⁱ⁾) (closed forms). For the detection count (75) pass p_D r_S⁽ⁱ⁾.
///
/// # Errors
/// [`Error::InvalidProbability`] naming `inside[i]`.
pub fn multi_bernoulli(inside: &[f64]) -> Result<FovCardinality> {
    check_probabilities("inside", inside)?;
    Ok(multi_bernoulli_unchecked(inside))
}

pub(crate) fn multi_bernoulli_unchecked(inside: &[f64]) -> FovCardinality {
    FovCardinality {
        pmf: pmf_unchecked(inside),
        mean: sum(inside.iter().copied()),
        variance: sum(inside.iter().map(|r| r * (1.0 - r))),
        truncated: 0.0,
    }
}

/// The multi-Bernoulli FoV pmf by the discrete Fourier transform form, eq. (90) of `001_…`:
///
/// ```text
/// ρ_S(n) = 1/(M + 1) Σ_{m=0}^{M} e^{−j2πmn/(M+1)} Π_{k=1}^{M} [ r_S⁽ᵏ⁾ e^{j2πm/(M+1)} + (1 − r_S⁽ᵏ⁾) ]
/// ```
///
/// The products are accumulated as sums of logarithms of the moduli and of the arguments
/// (no underflow), and the transform is evaluated directly with exactly reduced angles
/// (`O(M²)`). As a Fourier inversion it cancels terms: entries carry absolute errors of a
/// few ulps times √M and tail entries can come out slightly negative. Prefer
/// [`multi_bernoulli`]; this form is kept as the paper's method and a cross-check.
///
/// # Errors
/// [`Error::InvalidProbability`] naming `inside[i]`; [`Error::Unsupported`] for more than
/// 100 000 components.
pub fn multi_bernoulli_dft(inside: &[f64]) -> Result<Vec<f64>> {
    check_probabilities("inside", inside)?;
    if inside.len() > 100_000 {
        return Err(Error::Unsupported {
            what: "inside".into(),
            reason: "the O(M^2) DFT form is limited to 100000 components",
        });
    }
    let n1 = inside.len() + 1;
    let tau = 2.0 * core::f64::consts::PI / n1 as f64;
    let (cos_t, sin_t): (Vec<f64>, Vec<f64>) = (0..n1)
        .map(|k| (libm::cos(tau * k as f64), libm::sin(tau * k as f64)))
        .unzip();
    // Π(m) for m = 0 … M, as (modulus, argument).
    let prods: Vec<(f64, f64)> = (0..n1)
        .map(|m| {
            let (c, s) = (cos_t[m], sin_t[m]);
            let half = libm::sin(0.5 * tau * m as f64);
            let mut ln_mod = NeumaierSum::new();
            let mut arg = NeumaierSum::new();
            for &r in inside {
                // |1 − r + r e^{jω}|² = 1 − 4r(1 − r) sin²(ω/2)
                ln_mod.add(0.5 * fns::ln_1p(-4.0 * r * (1.0 - r) * half * half));
                arg.add(libm::atan2(r * s, 1.0 - r + r * c));
            }
            let modulus = fns::exp(ln_mod.total());
            (modulus, arg.total())
        })
        .collect();
    let (re, im): (Vec<f64>, Vec<f64>) = prods
        .iter()
        .map(|&(md, a)| (md * libm::cos(a), md * libm::sin(a)))
        .unzip();
    Ok((0..n1)
        .map(|n| {
            let mut acc = NeumaierSum::new();
            for m in 0..n1 {
                // e^{−jθ} Π = (cos θ − j sin θ)(re + j im): real part re cos θ + im sin θ.
                let k = (m * n) % n1;
                acc.add(re[m] * cos_t[k] + im[m] * sin_t[k]);
            }
            acc.total() / n1 as f64
        })
        .collect())
}

/// The multi-Bernoulli FoV pmf by direct enumeration of eq. (88) of `001_…` over all
/// partitions I₁ ⊎ I₂ ⊆ ℕ_M (3^M terms; an oracle for small M). Component i is in I₁
/// (exists, inside), I₂ (exists, outside) or neither (does not exist), with factors
/// r⁽ⁱ⁾⟨1_S, p⁽ⁱ⁾⟩, r⁽ⁱ⁾⟨1 − 1_S, p⁽ⁱ⁾⟩ = r⁽ⁱ⁾(1 − ⟨1_S, p⁽ⁱ⁾⟩) and 1 − r⁽ⁱ⁾: (88) with
/// the prefactor Π(1 − r) multiplied into the terms, which keeps it defined at r = 1.
///
/// # Errors
/// [`Error::InvalidProbability`] naming `existence[i]` or `mass[i]`;
/// [`Error::DimensionMismatch`] naming `mass` if the lengths differ; [`Error::Unsupported`]
/// for more than [`MAX_ENUMERATED`] components.
pub fn multi_bernoulli_enumerated(existence: &[f64], mass: &[f64]) -> Result<Vec<f64>> {
    check_probabilities("existence", existence)?;
    check_probabilities("mass", mass)?;
    if mass.len() != existence.len() {
        return Err(Error::dimension("mass", existence.len(), mass.len()));
    }
    let m = existence.len();
    if m > MAX_ENUMERATED {
        return Err(Error::Unsupported {
            what: "existence".into(),
            reason: "direct enumeration is limited to 12 components",
        });
    }
    let mut pmf = vec![0.0; m + 1];
    let mut labels = vec![0u8; m]; // 0: absent, 1: in I₁, 2: in I₂
    loop {
        let mut p = 1.0;
        let mut n = 0;
        for (i, &l) in labels.iter().enumerate() {
            p *= match l {
                0 => 1.0 - existence[i],
                1 => {
                    n += 1;
                    existence[i] * mass[i]
                }
                _ => existence[i] * (1.0 - mass[i]),
            };
        }
        pmf[n] += p;
        // next base-3 number
        let mut i = 0;
        loop {
            if i == m {
                return Ok(pmf);
            }
            labels[i] += 1;
            if labels[i] == 3 {
                labels[i] = 0;
                i += 1;
            } else {
                break;
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// GLMB (92)

/// One GLMB hypothesis (ξ, I) reduced to what (92) needs: its weight w⁽ξ⁾(I) and, for each
/// label ℓ ∈ I, the inclusion probability ⟨1_S, p⁽ξ,ℓ⁾⟩.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GlmbHypothesis {
    /// w⁽ξ⁾(I) ≥ 0; the weights of all hypotheses sum to 1.
    pub weight: f64,
    /// ⟨1_S, p⁽ξ,ℓ⁾⟩ for every label ℓ ∈ I (times p_D for the detection count (75)).
    pub inside: Vec<f64>,
}

/// The FoV cardinality pmf of a GLMB RFS, Proposition 4, eq. (92) of `001_…`:
///
/// ```text
/// ρ_S(n) = Σ_{(ξ, I₁ ⊎ I₂) ∈ Ξ × F(𝕃)} w⁽ξ⁾(I) δ_n(|I₁|) ⟨1_S, p⁽ξ,·⁾⟩^{I₁} ⟨1 − 1_S, p⁽ξ,·⁾⟩^{I₂}
/// ```
///
/// with I = I₁ ⊎ I₂: for each hypothesis, the sum over the splits of its label set is the
/// Poisson-binomial pmf of its inclusion probabilities, computed by the stable convolution
/// recursion, and the result is the w-weighted mixture of these (length: the largest label
/// set + 1). Mean Σ_h w_h μ_h and variance Σ_h w_h (σ_h² + (μ_h − μ)²), where
/// μ_h = Σ_ℓ q_ℓ, σ_h² = Σ_ℓ q_ℓ(1 − q_ℓ) (closed forms). ρ_S(0) is the GLMB void
/// probability.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `hypotheses[h].weight` for a negative or non-finite
/// weight, `hypotheses` if the weights do not sum to 1 within 1e-9 (they are then
/// normalised); [`Error::InvalidProbability`] naming `hypotheses[h].inside[l]`.
pub fn glmb(hypotheses: &[GlmbHypothesis]) -> Result<FovCardinality> {
    for (h, hyp) in hypotheses.iter().enumerate() {
        check_nonnegative(|| alloc::format!("hypotheses[{h}].weight"), hyp.weight)?;
        for (l, &q) in hyp.inside.iter().enumerate() {
            check_probability(|| alloc::format!("hypotheses[{h}].inside[{l}]"), q)?;
        }
    }
    let total = sum(hypotheses.iter().map(|h| h.weight));
    if total.is_nan() || fns::abs(total - 1.0) > 1e-9 {
        return Err(Error::parameter(
            "hypotheses",
            total,
            "weights summing to 1 within 1e-9 (the value is their sum)",
        ));
    }
    let len = hypotheses.iter().map(|h| h.inside.len()).max().unwrap_or(0) + 1;
    let mut acc: Vec<NeumaierSum> = vec![NeumaierSum::new(); len];
    let mut moments = Vec::with_capacity(hypotheses.len());
    for hyp in hypotheses {
        let w = hyp.weight / total;
        let c = multi_bernoulli_unchecked(&hyp.inside);
        for (a, p) in acc.iter_mut().zip(&c.pmf) {
            a.add(w * p);
        }
        moments.push((w, c.mean, c.variance));
    }
    let mean = sum(moments.iter().map(|&(w, mu, _)| w * mu));
    let variance = sum(moments
        .iter()
        .map(|&(w, mu, var)| w * (var + (mu - mean) * (mu - mean))));
    Ok(FovCardinality {
        pmf: acc.iter().map(NeumaierSum::total).collect(),
        mean,
        variance,
        truncated: 0.0,
    })
}
