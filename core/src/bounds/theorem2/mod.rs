//! Theorem 2 (22)–(26) of paper 002: measurement model II, Z = Θ_b0(X) ∪ W with W Poisson of
//! intensity v = λ c. The n = 1 terms by 1D quadrature; the n = 2 terms by deterministic 2D
//! cubature over Z² (nested adaptive G10/K21 split at the MAP region's boundary found by
//! root-finding) or by Monte Carlo, as [`TheoremOptions::quadrature_cardinality`] says: by
//! default the cubature in the linear-Gaussian case (Gaussian prior, linear-Gaussian g with
//! constant P_o, any clutter density), where its x-integrals are closed forms and a call takes
//! 3–35 ms natively, and Monte Carlo otherwise (the general cubature takes seconds); n ≥ 3
//! by Monte Carlo over Z^n (error: one standard error).
//! Each [`Cardinality::method`] says which.
//! Truncation: the series stops at N clutter points as [`TheoremOptions::series_tolerance`] and
//! [`TheoremOptions::max_clutter`] say; the bound returned is the truncated one below.
//!
//! What is computed, exactly (NOTES.md's reading of (23), checked against (57)–(58)):
//!
//! ```text
//! S = Σ_{k=0}^{N} C_k J'_{k+1}⁻¹        dropped tail ≥ 0: still a lower bound
//! W = Σ_{k=0}^{N} C_k w_{k+1} + tail    the tail's w taken as 1: still a lower bound
//! η2 = Σ_{n≥1} C_n Pr(Σ_i β(c_i) below the MAP threshold | c_1 … c_n ~ c)
//! ```
//!
//! The paper writes η2 = e^{−λ0} − e^{−λ} with λ0 = ∫_{Z_0^1} v; that equals the η2 the proof
//! needs ((51), (54)) only when the MAP null region of Z^n is the product of the 1-point null
//! region, which it is not (the detector sums β over the points). We compute η2 as its
//! definition in the proof; the truncated tail of the η2 series is bracketed by [0, tail] and
//! the smaller bound returned. The MAP test is r(1 − P̄o + P̄o β(Z)) ≥ 1 − r (Lemma 1),
//! written without division so that λ = 0, P̄o = 0 and r ∈ {0, 1} need no special cases.
//!
//! | file | holds |
//! |---|---|
//! | `mod.rs` | [`ModelII`], [`theorem2`] and its steps (checks, the n = 1 terms, the assembly (23)–(24)), the MAP test of n points, the integrand of (25) shared by the two below |
//! | `series.rs` | the Poisson series over n: its truncation, the sums S and W, the η2 bracket |
//! | `monte_carlo.rs` | the n ≥ 2 terms by Monte Carlo over Z^n |
//! | `cubature.rs` | the n = 2 terms by deterministic cubature over Z² (closed-form x-integrals in the linear-Gaussian case) |

use alloc::vec::Vec;

use crate::bounds::closed::{Ingredients, check_nonnegative, poisson_pmf};
use crate::bounds::model::{Density, Observation, is_linear_gaussian};
use crate::bounds::theorem::{
    Cardinality, JdeBound, Method, TheoremOptions, check_common, check_interval, check_result,
    detected_parts, inverse_information, marginal, prior_stats, region,
};
use crate::error::{Error, Result};
use crate::math::fns;

mod cubature;
mod monte_carlo;
mod series;

pub(crate) use series::EtaBracket;

/// Measurement model II: Z = Θ_b0(X) ∪ W, W a Poisson RFS of intensity v = λ c.
pub struct ModelII<'a> {
    /// The prior existence probability r ∈ [0, 1]: the probability that the target exists.
    pub existence: f64,
    /// The prior density f of the target's state.
    pub prior: &'a dyn Density,
    /// The observation: the detection probability P_o and the likelihood g.
    pub observation: &'a dyn Observation,
    /// The clutter rate λ ≥ 0: the mean number of clutter points.
    pub clutter_rate: f64,
    /// The density c = v/λ of one clutter point.
    pub clutter_density: &'a dyn Density,
    /// The squared error e_0² ≥ 0 of a false target.
    pub false_alarm_error: f64,
    /// The squared error e_1² ≥ 0 of a missed target.
    pub miss_error: f64,
}

/// Largest λ accepted (the series would need more than `max_clutter` terms).
pub const MAX_CLUTTER_RATE: f64 = 1000.0;

/// Theorem 2 (23)–(26) with the series and η2 computed as the module docs say.
pub fn theorem2(m: &ModelII<'_>, s: &TheoremOptions) -> Result<JdeBound> {
    let lambda = check(m, s)?;
    let tol = s.tolerance;
    let st = prior_stats(m.prior, m.observation, tol);
    let p = st.p_bar;
    let z_range = measurement_range(m);
    let zone = map_region(m, p, z_range, tol);
    let (first, a1) = single_point(m, p, &zone, tol);
    let scale_a = information_scale(first.w, a1);
    let mut cards = alloc::vec![first.cardinality(1, poisson_pmf(lambda, 0), Method::Quadrature)];
    let (last, kept) = series::truncation(lambda, s);
    let linear_gaussian = is_linear_gaussian(m.prior, m.observation);
    let quad2 = s.quadrature_cardinality_for(linear_gaussian) >= 2;
    if last > 0 && quad2 {
        let c = cubature::quadrature2(m, p, scale_a, z_range, tol, true);
        cards.push(c.cardinality(2, poisson_pmf(lambda, 1), Method::Quadrature));
    }
    let first_mc = if quad2 { 2 } else { 1 };
    if last >= first_mc {
        monte_carlo::terms(m, p, first_mc, last, s, &mut cards)?;
    }
    let sums = series::Sums::new(&cards, kept);
    let bracket = EtaBracket::new(lambda, &cards);
    let (assembled, eta) = bracket.assemble(|eta| Ingredients {
        existence: m.existence,
        mean_detection: p,
        undetected_variance: st.sigma_e2,
        inverse_information: sums.s,
        detected_mass: sums.w.min(1.0),
        absent_empty: fns::exp(-lambda),
        absent_null: eta,
        undetected_empty: fns::exp(-lambda),
        undetected_null: eta,
        false_alarm_error: m.false_alarm_error,
        miss_error: m.miss_error,
    });
    let r = m.existence;
    let coef_eta = m.false_alarm_error + st.sigma_e2 + m.miss_error;
    let error = r * p * (sums.err_s + m.miss_error * sums.err_w)
        + coef_eta * bracket.error
        + r * st.error * (m.miss_error + st.sigma_e2 + 1.0);
    check_result(JdeBound {
        assembled,
        mean_detection: p,
        undetected_mean: st.x_star,
        undetected_variance: st.sigma_e2,
        eta,
        region: zone,
        cardinalities: cards,
        error,
        regular: st.regular,
    })
}

/// The checks of Theorem 2's inputs; returns λ.
fn check(m: &ModelII<'_>, s: &TheoremOptions) -> Result<f64> {
    check_common(m.existence, m.false_alarm_error, m.miss_error, s)?;
    let lambda = check_nonnegative("clutter.rate", m.clutter_rate)?;
    if lambda > MAX_CLUTTER_RATE {
        return Err(Error::parameter("clutter.rate", lambda, "≤ 1000"));
    }
    let (prior, obs) = (m.prior, m.observation);
    check_interval("prior", prior.support())?;
    check_interval(
        "observation",
        obs.z_range(prior.support().0, prior.support().1),
    )?;
    if lambda > 0.0 {
        check_interval("clutter.density", m.clutter_density.support())?;
    }
    Ok(lambda)
}

/// The z interval the measurements live in: g's range over the prior's support, and the
/// clutter's support when there is clutter.
fn measurement_range(m: &ModelII<'_>) -> (f64, f64) {
    let (xl, xh) = m.prior.support();
    let (ol, oh) = m.observation.z_range(xl, xh);
    let (cl, ch) = m.clutter_density.support();
    if m.clutter_rate > 0.0 {
        (ol.min(cl), oh.max(ch))
    } else {
        (ol, oh)
    }
}

/// Z_0^1, the one-point MAP region (Lemma 1) multiplied through by v(z) ≥ 0:
/// r(1 − P̄o) v + r P̄o m ≥ (1 − r) v.
fn map_region(m: &ModelII<'_>, p: f64, (zl, zh): (f64, f64), tol: f64) -> Vec<(f64, f64)> {
    let (r, lambda) = (m.existence, m.clutter_rate);
    region(
        &mut |z| {
            let v = lambda * m.clutter_density.pdf(z);
            r * (1.0 - p) * v + r * p * marginal(m.prior, m.observation, p, z, tol) - (1.0 - r) * v
        },
        zl,
        zh,
    )
}

/// The n = 1 terms by quadrature over the region `zone` (w_1, J'_1⁻¹ (25) and the one-point
/// clutter rejection), and A_1 (with w_1, the scale the n = 2 cubature measures its A_2 in).
fn single_point(m: &ModelII<'_>, p: f64, zone: &[(f64, f64)], tol: f64) -> (Term, f64) {
    let (w1, a1, ew1, ea1) = detected_parts(m.prior, m.observation, p, zone, tol);
    let (s1, es1) = inverse_information(w1, a1, ew1, ea1);
    let kept: f64 = zone
        .iter()
        .map(|&(a, b)| m.clutter_density.mass(a, b))
        .sum();
    let null1 = (1.0 - kept).clamp(0.0, 1.0);
    let term = Term {
        w: w1,
        ew: ew1,
        s: s1,
        es: es1,
        null: null1,
        enull: 0.0,
    };
    (term, a1)
}

/// The unit the n = 2 cubature measures A_2 in: A_1/w_1, the n = 1 information per unit of
/// detected mass (A_1 alone is tiny when the one-point region is, and the tolerance on A_2
/// would follow it), or 1 when the one-point region is empty.
fn information_scale(w1: f64, a1: f64) -> f64 {
    if a1 > 0.0 && w1 > 0.0 { a1 / w1 } else { 1.0 }
}

/// The terms of one cardinality n, with their error estimates (quadrature estimate or one
/// standard error).
struct Term {
    /// w_n (25).
    w: f64,
    ew: f64,
    /// J'_n⁻¹ (25).
    s: f64,
    es: f64,
    /// Pr(n clutter points alone are rejected by the MAP detector).
    null: f64,
    enull: f64,
}

impl Term {
    fn cardinality(self, n: usize, probability: f64, method: Method) -> Cardinality {
        Cardinality {
            n,
            probability,
            w: self.w,
            inverse_information: self.s,
            clutter_null: self.null,
            method,
            error: self.es,
            w_error: self.ew,
            clutter_null_error: self.enull,
        }
    }
}

/// The MAP detector of n points (Lemma 1): declare a target when
/// r(1 − P̄o) + r P̄o β ≥ 1 − r, β = Σ_i m(z_i)/v(z_i) (∞ when a v is 0).
#[derive(Clone, Copy)]
struct MapTest {
    r: f64,
    p: f64,
}

impl MapTest {
    fn declares(&self, beta: f64, v_is_zero: bool) -> bool {
        let (r, p) = (self.r, self.p);
        if v_is_zero {
            r * p > 0.0 || r >= 1.0 - r
        } else {
            r * (1.0 - p) + r * p * beta >= 1.0 - r
        }
    }
}

/// −∂²_x ln p_n(x, z) = −(ln f)'' − (ln P_o)'' − (ln S)'', S = Σ_i g(z_i|x)/c(z_i) (25): the
/// x-dependence of p_n (NOTES.md's reading of (22)); the points outside the clutter's support
/// dominate S when there are any.
fn information_density(
    prior: &dyn Density,
    obs: &dyn Observation,
    clutter: &dyn Density,
    x: f64,
    z: &[f64],
    terms: &mut Vec<(f64, f64, f64)>,
) -> f64 {
    terms.clear();
    let mut any_zero_c = false;
    for &zi in z {
        let c = clutter.pdf(zi);
        let g = obs.likelihood(zi, x);
        any_zero_c |= c <= 0.0 && g > 0.0;
        terms.push((if c > 0.0 { g / c } else { g }, c, g));
    }
    let (mut sum, mut d1, mut d2) = (0.0, 0.0, 0.0);
    for (&(t, c, g), &zi) in terms.iter().zip(z) {
        if any_zero_c && (c > 0.0 || g <= 0.0) {
            continue; // the points outside the clutter's support dominate S
        }
        if t <= 0.0 {
            continue;
        }
        let l1 = obs.d_ln_likelihood(zi, x);
        let l2 = obs.d2_ln_likelihood(zi, x);
        sum += t;
        d1 += t * l1;
        d2 += t * (l2 + l1 * l1);
    }
    if sum > 0.0 {
        let (d1, d2) = (d1 / sum, d2 / sum);
        -(prior.d2_ln_pdf(x) + obs.d2_ln_detection(x) + d2 - d1 * d1)
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests;
