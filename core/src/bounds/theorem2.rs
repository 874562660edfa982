//! Theorem 2 (22)–(26) of paper 002: measurement model II, Z = Θ_b0(X) ∪ W with W Poisson of
//! intensity v = λ c. The n = 1 terms by quadrature, n ≥ 2 by Monte Carlo over Z^n.
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

use alloc::vec::Vec;

use crate::bounds::closed::{Ingredients, assemble, check_nonnegative, poisson_pmf};
use crate::bounds::model::{Density, Observation};
use crate::bounds::theorem::{
    Cardinality, JdeBound, Method, Settings, check_common, detected_parts, inverse_information,
    marginal, prior_stats, region,
};
use crate::error::{Error, Result};
use crate::math::fns;
use crate::math::rng::{SeededRng, seeded};

/// Measurement model II: Z = Θ_b0(X) ∪ W, W a Poisson RFS of intensity v = λ c.
pub struct ModelII<'a> {
    /// r.
    pub existence: f64,
    /// f.
    pub prior: &'a dyn Density,
    /// P_o and g.
    pub observation: &'a dyn Observation,
    /// λ, the mean number of clutter points.
    pub clutter_rate: f64,
    /// c = v/λ, the clutter points' density.
    pub clutter_density: &'a dyn Density,
    /// e_0².
    pub false_alarm_error: f64,
    /// e_1².
    pub miss_error: f64,
}

/// Largest λ accepted (the series would need more than `max_clutter` terms).
pub const MAX_CLUTTER_RATE: f64 = 1000.0;

struct Table {
    lo: f64,
    step: f64,
    values: Vec<f64>,
}

impl Table {
    fn at(&self, z: f64) -> f64 {
        let t = (z - self.lo) / self.step;
        if t.is_nan() || t < 0.0 {
            return 0.0;
        }
        let last = self.values.len() - 1;
        let i = libm::floor(t);
        if i >= last as f64 {
            return if t <= last as f64 {
                self.values[last]
            } else {
                0.0
            };
        }
        let k = i as usize; // 0 ≤ i < last, checked above
        let u = t - i;
        self.values[k] * (1.0 - u) + self.values[k + 1] * u
    }
}

/// Theorem 2 (23)–(26) with the series and η2 computed as the module docs say.
pub fn theorem2(m: &ModelII<'_>, s: &Settings) -> Result<JdeBound> {
    let r = m.existence;
    check_common(r, m.false_alarm_error, m.miss_error, s)?;
    let lambda = check_nonnegative("clutter.rate", m.clutter_rate)?;
    if lambda > MAX_CLUTTER_RATE {
        return Err(Error::parameter("clutter.rate", lambda, "≤ 1000"));
    }
    let tol = s.tolerance;
    let (prior, obs, clutter) = (m.prior, m.observation, m.clutter_density);
    let st = prior_stats(prior, obs, tol);
    let p = st.p_bar;
    let (xl, xh) = prior.support();
    let (ol, oh) = obs.z_range(xl, xh);
    let (cl, ch) = clutter.support();
    let (zl, zh) = if lambda > 0.0 {
        (ol.min(cl), oh.max(ch))
    } else {
        (ol, oh)
    };
    // MAP (Lemma 1), multiplied through by v(z) ≥ 0: r(1 − P̄o) v + r P̄o m ≥ (1 − r) v.
    let declare_sum = |beta_num: f64, v_prod_is_zero: bool| -> bool {
        // for n points: r(1 − P̄o) + r P̄o β ≥ 1 − r, β = Σ m/v (∞ when a v is 0)
        if v_prod_is_zero {
            r * p > 0.0 || r >= 1.0 - r
        } else {
            r * (1.0 - p) + r * p * beta_num >= 1.0 - r
        }
    };
    let zone = region(
        &mut |z| {
            let v = lambda * clutter.pdf(z);
            r * (1.0 - p) * v + r * p * marginal(prior, obs, p, z, tol) - (1.0 - r) * v
        },
        zl,
        zh,
    );
    let (w1, a1, ew1, ea1) = detected_parts(prior, obs, p, &zone, tol);
    let (s1, es1) = inverse_information(w1, a1, ew1, ea1);
    let null1 = (1.0 - zone.iter().map(|&(a, b)| clutter.mass(a, b)).sum::<f64>()).clamp(0.0, 1.0);
    let mut cards = alloc::vec![Cardinality {
        n: 1,
        probability: poisson_pmf(lambda, 0),
        w: w1,
        inverse_information: s1,
        clutter_null: null1,
        method: Method::Quadrature,
        error: es1,
    }];
    let mut w_errors = alloc::vec![ew1];
    let mut null_errors = alloc::vec![0.0];
    // N: the last k (clutter count) kept.
    let mut last = 0usize;
    let mut kept = poisson_pmf(lambda, 0);
    while 1.0 - kept > s.series_tolerance && last < s.max_clutter {
        last += 1;
        kept += poisson_pmf(lambda, last);
    }
    if last > 0 {
        let samples = s.samples.max(2);
        // m(z) tabulated for the Monte Carlo (linear interpolation, 0 outside g's range).
        let cells = 2048;
        let step = (oh - ol) / cells as f64;
        let table = Table {
            lo: ol,
            step,
            values: (0..=cells)
                .map(|i| marginal(prior, obs, p, ol + step * i as f64, tol))
                .collect(),
        };
        let mut rng = seeded(s.seed);
        for k in 1..=last {
            let n = k + 1;
            let c = monte_carlo(m, &table, p, n, samples, &mut rng, &declare_sum)?;
            cards.push(Cardinality {
                n,
                probability: poisson_pmf(lambda, k),
                w: c.w,
                inverse_information: c.s,
                clutter_null: c.null,
                method: Method::MonteCarlo,
                error: c.es,
            });
            w_errors.push(c.ew);
            null_errors.push(c.enull);
        }
    }
    let tail = (1.0 - kept).max(0.0);
    let mut big_s = 0.0;
    let mut big_w = tail;
    let mut err_s = 0.0;
    let mut err_w = 0.0;
    for (c, ew) in cards.iter().zip(&w_errors) {
        big_s += c.probability * c.inverse_information;
        big_w += c.probability * c.w;
        err_s += c.probability * c.error;
        err_w += c.probability * ew;
    }
    // η2 = Σ_{n ≥ 1} C_n null_n: cardinality n of clutter alone has probability C_n.
    let mut eta = 0.0;
    let mut err_eta = 0.0;
    let mut covered = poisson_pmf(lambda, 0);
    for (c, e) in cards.iter().zip(&null_errors) {
        let cn = poisson_pmf(lambda, c.n);
        eta += cn * c.clutter_null;
        err_eta += cn * e;
        covered += cn;
    }
    let eta_tail = (1.0 - covered).max(0.0);
    let ingredients = |eta: f64| Ingredients {
        existence: r,
        mean_detection: p,
        undetected_variance: st.sigma_e2,
        inverse_information: big_s,
        detected_mass: big_w.min(1.0),
        absent_empty: fns::exp(-lambda),
        absent_null: eta,
        undetected_empty: fns::exp(-lambda),
        undetected_null: eta,
        false_alarm_error: m.false_alarm_error,
        miss_error: m.miss_error,
    };
    let lo = assemble(&ingredients(eta));
    let hi = assemble(&ingredients((eta + eta_tail).min(1.0)));
    let (assembled, eta) = if hi.bound < lo.bound {
        (hi, (eta + eta_tail).min(1.0))
    } else {
        (lo, eta)
    };
    let coef_eta = m.false_alarm_error + st.sigma_e2 + m.miss_error;
    let error = r * p * (err_s + m.miss_error * err_w)
        + coef_eta * err_eta
        + r * st.error * (m.miss_error + st.sigma_e2 + 1.0);
    Ok(JdeBound {
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

struct McTerm {
    w: f64,
    ew: f64,
    s: f64,
    es: f64,
    null: f64,
    enull: f64,
}

/// w_n, J'_n⁻¹ and the clutter-only null probability for n points by Monte Carlo: x from the
/// prior weighted by P_o(x)/P̄o (so x ~ f_d), the target's point z_1 ~ g(·|x) (p_n is symmetric
/// in the points and so is the MAP region, so the target may be put first), z_2 … z_n ~ c.
fn monte_carlo(
    m: &ModelII<'_>,
    table: &Table,
    p: f64,
    n: usize,
    samples: usize,
    rng: &mut SeededRng,
    declare: &dyn Fn(f64, bool) -> bool,
) -> Result<McTerm> {
    let (prior, obs, clutter, lambda) = (m.prior, m.observation, m.clutter_density, m.clutter_rate);
    let unsampled = |what: &'static str| Error::Unsupported {
        what: what.into(),
        reason: "Theorem 2 with clutter needs draws from it (Monte Carlo for n ≥ 2)",
    };
    let (mut sx, mut sy, mut sxx, mut syy, mut sxy, mut snull) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    let mut z = alloc::vec![0.0; n];
    let mut terms = alloc::vec![(0.0, 0.0, 0.0); n];
    for _ in 0..samples {
        // clutter alone: does the detector reject n clutter points?
        let mut beta = 0.0;
        let mut zero = false;
        for _ in 0..n {
            let c = clutter.sample(rng).ok_or_else(|| unsampled("clutter"))?;
            let v = lambda * clutter.pdf(c);
            if v > 0.0 {
                beta += table.at(c) / v;
            } else {
                zero = true;
            }
        }
        if !declare(beta, zero) {
            snull += 1.0;
        }
        if p <= 0.0 {
            continue;
        }
        let x = prior.sample(rng).ok_or_else(|| unsampled("prior"))?;
        let omega = obs.detection(x) / p;
        if omega <= 0.0 {
            continue;
        }
        z[0] = obs.sample(x, rng).ok_or_else(|| unsampled("observation"))?;
        for zi in z.iter_mut().skip(1) {
            *zi = clutter.sample(rng).ok_or_else(|| unsampled("clutter"))?;
        }
        let mut beta = 0.0;
        let mut zero = false;
        for &zi in &z {
            let v = lambda * clutter.pdf(zi);
            if v > 0.0 {
                beta += table.at(zi) / v;
            } else {
                zero = true;
            }
        }
        if !declare(beta, zero) {
            continue;
        }
        // −∂²_x ln p_n = −(ln f)'' − (ln P_o)'' − (ln S)'', S = Σ_i g(z_i|x)/c(z_i).
        let mut any_zero_c = false;
        for (t, &zi) in terms.iter_mut().zip(&z) {
            let c = clutter.pdf(zi);
            let g = obs.likelihood(zi, x);
            any_zero_c |= c <= 0.0 && g > 0.0;
            *t = (if c > 0.0 { g / c } else { g }, c, g);
        }
        let (mut sum, mut d1, mut d2) = (0.0, 0.0, 0.0);
        for (&(t, c, g), &zi) in terms.iter().zip(&z) {
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
        let q = if sum > 0.0 {
            let (d1, d2) = (d1 / sum, d2 / sum);
            -(prior.d2_ln_pdf(x) + obs.d2_ln_detection(x) + d2 - d1 * d1)
        } else {
            0.0
        };
        let (xv, yv) = (omega, omega * q);
        sx += xv;
        sy += yv;
        sxx += xv * xv;
        syy += yv * yv;
        sxy += xv * yv;
    }
    let nf = samples as f64;
    let (w, a) = (sx / nf, sy / nf);
    let var = |s2: f64, mean: f64| (s2 / nf - mean * mean).max(0.0) / nf;
    let (vx, vy) = (var(sxx, w), var(syy, a));
    let cxy = (sxy / nf - w * a) / nf;
    let null = snull / nf;
    let enull = fns::sqrt(null * (1.0 - null) / nf);
    let ew = fns::sqrt(vx);
    let (s, es) = if w > 0.0 && a > 0.0 {
        let (gw, ga) = (2.0 * w / a, -(w * w) / (a * a));
        let v = gw * gw * vx + ga * ga * vy + 2.0 * gw * ga * cxy;
        (w * w / a, fns::sqrt(v.max(0.0)))
    } else {
        (0.0, 0.0)
    };
    Ok(McTerm {
        w: w.min(1.0),
        ew,
        s,
        es,
        null,
        enull,
    })
}
