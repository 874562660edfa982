//! Theorem 1 (17)–(21) and the n = 1 part of Theorem 2 (22)–(26) of paper 002 by adaptive
//! quadrature: P̄_o (14), f_d, f_d' and p_1 (15) (with NOTES.md's prime), σ_e² (16), the MAP
//! regions by root-finding, w_1, η and J'_1 (20).

use alloc::vec::Vec;

use crate::bounds::closed::{Assembled, Ingredients, assemble, check_nonnegative};
use crate::bounds::model::{Density, Observation, linear_gaussian_marginal, normal_pdf};
use crate::error::{Error, Result, check_probability};
use crate::math::fns;
use crate::math::quadrature::{self, Control, Rule, Tolerance};

/// How the bounds integrate and sample.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct TheoremOptions {
    /// Relative tolerance of each quadrature (default 1e-10).
    pub tolerance: f64,
    /// Monte Carlo samples per cardinality n ≥ 2 (n ≥ 3 when `quadrature_cardinality` is 2,
    /// or 0 on a linear-Gaussian model) (Theorem 2; default 20,000).
    pub samples: usize,
    /// The seed of the Monte Carlo draws.
    pub seed: u64,
    /// The Poisson series (23) stops where its tail Σ_{n>N} C_n is below this (default 1e-6).
    pub series_tolerance: f64,
    /// … or at this many clutter points N (default 40).
    pub max_clutter: usize,
    /// Theorem 2: the largest |Z| = n whose terms are integrated by deterministic quadrature:
    /// 1 (n = 1 by 1D quadrature, n ≥ 2 by Monte Carlo) or 2 (n = 2 by 2D cubature over Z² as
    /// well; values above 2 act as 2); every larger n is Monte Carlo. 0, the default, is
    /// automatic ([`TheoremOptions::quadrature_cardinality_for`]): 2 in the linear-Gaussian
    /// case ([`is_linear_gaussian`](crate::bounds::is_linear_gaussian)), where the cubature's
    /// x-integrals are closed forms (3–35 ms a call natively, release), 1 otherwise (the
    /// general cubature costs 0.5–5.4 s a call, against ~50 ms for its Monte Carlo).
    pub quadrature_cardinality: usize,
}

impl Default for TheoremOptions {
    fn default() -> Self {
        TheoremOptions {
            tolerance: 1e-10,
            samples: 20_000,
            seed: 0,
            series_tolerance: 1e-6,
            max_clutter: 40,
            quadrature_cardinality: 0,
        }
    }
}

impl TheoremOptions {
    /// The largest n integrated by quadrature for a model: [`Self::quadrature_cardinality`]
    /// when it is set (≥ 1), else (0, the default) 2 when the model is linear-Gaussian
    /// (`linear_gaussian`, [`is_linear_gaussian`](crate::bounds::is_linear_gaussian)) and 1
    /// otherwise. The one place the default is decided.
    pub fn quadrature_cardinality_for(&self, linear_gaussian: bool) -> usize {
        match self.quadrature_cardinality {
            0 if linear_gaussian => 2,
            0 => 1,
            k => k,
        }
    }
}

/// How a term of the bound was integrated (written `"quadrature"`, `"monte-carlo"`,
/// `"closed-form"`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "kebab-case"))]
pub enum Method {
    /// Adaptive Gauss–Kronrod quadrature.
    Quadrature,
    /// Monte Carlo (error: one standard error).
    MonteCarlo,
    /// A closed form (no integration; error 0): the vector bounds without clutter.
    ClosedForm,
}

/// The n-point part of Theorem 2 (or the one term of Theorem 1).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Cardinality {
    /// n = |Z| (the target's point and n − 1 clutter points).
    pub n: usize,
    /// C_{n−1}, the Poisson probability of n − 1 clutter points.
    pub probability: f64,
    /// w_n (25): the mass of p_n on the MAP region.
    pub w: f64,
    /// J'_n⁻¹ = w_n² / (−∫∫ p_n ∂² ln p_n) (25) (0 when w_n = 0: J'_n = ∞).
    pub inverse_information: f64,
    /// Pr(Σ β < threshold | n clutter points only): n-point clutter the detector rejects.
    pub clutter_null: f64,
    /// How `w` and the information were computed (quadrature or Monte Carlo).
    pub method: Method,
    /// The error estimate of J'_n⁻¹ (quadrature estimate or one standard error).
    pub error: f64,
    /// The error estimate of `w`.
    pub w_error: f64,
    /// The error estimate of `clutter_null`.
    pub clutter_null_error: f64,
}

/// A bound of Theorem 1 or 2 with everything it was built from.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct JdeBound {
    /// The bound, its phase, threshold and terms.
    pub assembled: Assembled,
    /// The mean detection probability P̄_o (14) = ∫ P_o(x) f(x) dx, in [0, 1].
    pub mean_detection: f64,
    /// The mean x* of f_d', an undetected target's state (Lemma 2).
    pub undetected_mean: f64,
    /// The variance σ_e² (16) of f_d', an undetected target's state.
    pub undetected_variance: f64,
    /// η1 (model I) or η2 (model II, computed exactly: see [`super::theorem2`]).
    pub eta: f64,
    /// The MAP detection region Z'_0 (model I) or Z_0^1 (model II) as intervals.
    pub region: Vec<(f64, f64)>,
    /// Per cardinality n: model I has the single n = 1 entry.
    pub cardinalities: Vec<Cardinality>,
    /// Error estimate of the bound: quadrature errors, one Monte Carlo standard error and
    /// the truncated tail, propagated through (17)/(23).
    pub error: f64,
    /// false when f·P_o does not vanish at the ends of the prior's support (uniform priors,
    /// tables ending above 0, Example 2): the information inequality's regularity condition
    /// fails and the estimation term need not be a bound.
    pub regular: bool,
}

/// ∫ f over [a, b] by adaptive G10/K21 from 8 equal pieces, to relative tolerance `rel` of
/// the first pieces' ∫|f| (or 64 ε ∫|f|), at most 400 pieces: (value, error).
pub(crate) fn integrate(f: &mut dyn FnMut(f64) -> f64, a: f64, b: f64, rel: f64) -> (f64, f64) {
    if b.partial_cmp(&a) != Some(core::cmp::Ordering::Greater) {
        return (0.0, 0.0);
    }
    let n = 8;
    let pts: Vec<f64> = (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
    let mut g = |x: f64| f(x);
    let mut scale = 0.0;
    for w in pts.windows(2) {
        scale += Rule::G10K21.apply(&mut g, w[0], w[1]).abs;
    }
    let tolerance = Tolerance::AbsoluteAboveNoise(rel * scale);
    let e = quadrature::integrate(&mut g, &pts, &Control::new(Rule::G10K21, tolerance, 400));
    (e.value, e.error)
}

/// P̄_o, x*, σ_e² and their error.
pub(crate) struct PriorStats {
    pub p_bar: f64,
    pub x_star: f64,
    pub sigma_e2: f64,
    pub error: f64,
    pub regular: bool,
}

pub(crate) fn prior_stats(prior: &dyn Density, obs: &dyn Observation, tol: f64) -> PriorStats {
    let (lo, hi) = prior.support();
    let (p_bar, e1) = integrate(&mut |x| prior.pdf(x) * obs.detection(x), lo, hi, tol);
    let p_bar = p_bar.clamp(0.0, 1.0);
    // f_d' = f (1 − P_o) / (1 − P̄_o); at P̄_o = 1 (constant P_o = 1) its limit is f.
    let undetected = |x: f64| {
        if 1.0 - p_bar > 1e-12 {
            prior.pdf(x) * (1.0 - obs.detection(x))
        } else {
            prior.pdf(x)
        }
    };
    let (mass, _) = integrate(&mut |x| undetected(x), lo, hi, tol);
    let (m1, _) = integrate(&mut |x| x * undetected(x), lo, hi, tol);
    let x_star = if mass > 0.0 {
        m1 / mass
    } else {
        0.5 * (lo + hi)
    };
    let (m2, e2) = integrate(
        &mut |x| (x - x_star) * (x - x_star) * undetected(x),
        lo,
        hi,
        tol,
    );
    let sigma_e2 = if mass > 0.0 { m2 / mass } else { 0.0 };
    let peak = (0..=64)
        .map(|i| {
            let x = lo + (hi - lo) * i as f64 / 64.0;
            prior.pdf(x) * obs.detection(x)
        })
        .fold(0.0, f64::max)
        .max(prior.pdf(lo) * obs.detection(lo))
        .max(prior.pdf(hi) * obs.detection(hi));
    let edge = (prior.pdf(lo) * obs.detection(lo)).max(prior.pdf(hi) * obs.detection(hi));
    PriorStats {
        p_bar,
        x_star,
        sigma_e2,
        error: e1 + if mass > 0.0 { e2 / mass } else { 0.0 },
        regular: edge <= 1e-9 * peak,
    }
}

/// m(z) = ∫ f_d(x) g(z|x) dx = ∫ p_1(x, z) dx (the m of Lemma 1's β = m/v, paper 002), by
/// quadrature; in the linear-Gaussian case of (22) the closed form N(z; a μ + b, a² P + R)
/// ([`linear_gaussian_marginal`]).
pub(crate) fn marginal(
    prior: &dyn Density,
    obs: &dyn Observation,
    p_bar: f64,
    z: f64,
    tol: f64,
) -> f64 {
    if p_bar <= 0.0 {
        return 0.0;
    }
    if let Some((mean, var)) = linear_gaussian_marginal(prior, obs) {
        return normal_pdf(z, mean, var);
    }
    let (lo, hi) = prior.support();
    let (lo, hi) = obs.x_range(z, lo, hi);
    integrate(
        &mut |x| prior.pdf(x) * obs.detection(x) * obs.likelihood(z, x),
        lo,
        hi,
        tol,
    )
    .0 / p_bar
}

/// The intervals of [lo, hi] where h ≥ 0: a scan of 512 cells, then bisection of each sign
/// change to the floating-point resolution of the interval.
pub(crate) fn region(h: &mut dyn FnMut(f64) -> f64, lo: f64, hi: f64) -> Vec<(f64, f64)> {
    let cells = 512;
    let at = |i: usize| lo + (hi - lo) * i as f64 / cells as f64;
    let mut out: Vec<(f64, f64)> = Vec::new();
    let mut prev_x = lo;
    let mut prev_in = h(lo) >= 0.0;
    let mut start = if prev_in { Some(lo) } else { None };
    for i in 1..=cells {
        let x = at(i);
        let inside = h(x) >= 0.0;
        if inside != prev_in {
            // bisect [prev_x, x] for the switch
            let (mut a, mut b) = (prev_x, x);
            let resolution = 1e-13 * (hi - lo);
            for _ in 0..64 {
                let m = 0.5 * (a + b);
                if !(a < m && m < b) || b - a < resolution {
                    break;
                }
                if (h(m) >= 0.0) == prev_in {
                    a = m;
                } else {
                    b = m;
                }
            }
            let edge = 0.5 * (a + b);
            if inside {
                start = Some(edge);
            } else if let Some(s) = start.take() {
                out.push((s, edge));
            }
        }
        prev_x = x;
        prev_in = inside;
    }
    if let Some(s) = start {
        out.push((s, hi));
    }
    out
}

/// w = ∫_X f_d G and A = −∫_X ∫_R p_1 ∂²_x ln p_1 over the region R, with their errors.
pub(crate) fn detected_parts(
    prior: &dyn Density,
    obs: &dyn Observation,
    p_bar: f64,
    region: &[(f64, f64)],
    tol: f64,
) -> (f64, f64, f64, f64) {
    if p_bar <= 0.0 || region.is_empty() {
        return (0.0, 0.0, 0.0, 0.0);
    }
    let (lo, hi) = prior.support();
    let fd = |x: f64| prior.pdf(x) * obs.detection(x) / p_bar;
    let (w, ew) = integrate(
        &mut |x| {
            let f = fd(x);
            if f > 0.0 {
                f * region
                    .iter()
                    .map(|&(a, b)| obs.likelihood_mass(a, b, x))
                    .sum::<f64>()
            } else {
                0.0
            }
        },
        lo,
        hi,
        tol,
    );
    let (a, ea) = integrate(
        &mut |x| {
            let f = fd(x);
            if f > 0.0 {
                let mut g = 0.0;
                let mut fisher = 0.0;
                for &(a, b) in region {
                    g += obs.likelihood_mass(a, b, x);
                    fisher += obs.fisher_mass(a, b, x);
                }
                -f * ((prior.d2_ln_pdf(x) + obs.d2_ln_detection(x)) * g + fisher)
            } else {
                0.0
            }
        },
        lo,
        hi,
        tol,
    );
    (w.clamp(0.0, 1.0), a, ew, ea)
}

/// J'⁻¹ = w²/A and its error from those of w and A (0 when w = 0: J' = ∞).
pub(crate) fn inverse_information(w: f64, a: f64, ew: f64, ea: f64) -> (f64, f64) {
    if w <= 0.0 || a <= 0.0 {
        return (0.0, 0.0);
    }
    let s = w * w / a;
    (s, s * (2.0 * ew / w + ea / a))
}

/// Measurement model I (13): Z = Θ_b(X), a Bernoulli observation with false alarms.
pub struct ModelI<'a> {
    /// The prior existence probability r ∈ [0, 1]: the probability that the target exists.
    pub existence: f64,
    /// The prior density f of the target's state.
    pub prior: &'a dyn Density,
    /// The observation: the detection probability P_o and the likelihood g.
    pub observation: &'a dyn Observation,
    /// The false-observation probability q ∈ [0, 1].
    pub false_alarm_probability: f64,
    /// The false-observation density ψ.
    pub false_alarm_density: &'a dyn Density,
    /// The squared error e_0² ≥ 0 of a false target.
    pub false_alarm_error: f64,
    /// The squared error e_1² ≥ 0 of a missed target.
    pub miss_error: f64,
}

/// The interval must be finite with a finite, positive width (so quadrature can cover it).
pub(crate) fn check_interval(what: &'static str, (lo, hi): (f64, f64)) -> Result<()> {
    let w = hi - lo;
    if lo.is_finite() && hi.is_finite() && w.is_finite() && w > 0.0 && w < 1e150 {
        Ok(())
    } else {
        Err(Error::Unsupported {
            what: what.into(),
            reason: "its support must be a finite interval narrower than 1e150",
        })
    }
}

/// A NaN anywhere in the result is an error, never a silent number.
pub(crate) fn check_result(b: JdeBound) -> Result<JdeBound> {
    let a = &b.assembled;
    if [
        a.bound,
        a.hpe,
        a.lpe,
        b.error,
        b.eta,
        b.mean_detection,
        b.undetected_variance,
    ]
    .iter()
    .any(|v| v.is_nan())
        || b.cardinalities
            .iter()
            .any(|c| c.w.is_nan() || c.inverse_information.is_nan())
    {
        return Err(Error::Unsupported {
            what: "prior".into(),
            reason: "the integrals did not converge at this scale (NaN); rescale the problem",
        });
    }
    Ok(b)
}

pub(crate) fn check_common(r: f64, e0: f64, e1: f64, s: &TheoremOptions) -> Result<()> {
    check_probability(|| "existence".into(), r)?;
    check_nonnegative("false_alarm_error", e0)?;
    check_nonnegative("miss_error", e1)?;
    if !(s.tolerance.is_finite() && s.tolerance >= 1e-14 && s.tolerance <= 0.1) {
        return Err(Error::parameter(
            "tolerance",
            s.tolerance,
            "in [1e-14, 0.1]",
        ));
    }
    Ok(())
}

/// Theorem 1 (17)–(21): the bound on the MSE of MAP detection (on Z ≠ ∅) and unbiased
/// estimation under measurement model I. J'_1 is (20), with the 1/w_1² (Example 2's (32)
/// omits it, NOTES.md); the whole computation is quadrature, with `error` its estimate.
pub fn theorem1(m: &ModelI<'_>, s: &TheoremOptions) -> Result<JdeBound> {
    let (r, q) = (m.existence, m.false_alarm_probability);
    check_common(r, m.false_alarm_error, m.miss_error, s)?;
    check_probability(|| "false_alarm.probability".into(), q)?;
    let tol = s.tolerance;
    check_interval("prior", m.prior.support())?;
    let (xl, xh) = m.prior.support();
    check_interval("observation", m.observation.z_range(xl, xh))?;
    if q > 0.0 {
        check_interval("false_alarm.density", m.false_alarm_density.support())?;
    }
    let st = prior_stats(m.prior, m.observation, tol);
    let (zl, zh) = m.observation.z_range(xl, xh);
    // Z'_0 (19): r P̄o m(z) ≥ (1 − r) q ψ(z), i.e. β_b ≥ (1 − r)/(r P̄o).
    let zone = if q == 0.0 {
        alloc::vec![(zl, zh)]
    } else {
        region(
            &mut |z| {
                r * st.p_bar * marginal(m.prior, m.observation, st.p_bar, z, tol)
                    - (1.0 - r) * q * m.false_alarm_density.pdf(z)
            },
            zl,
            zh,
        )
    };
    let (w, a, ew, ea) = detected_parts(m.prior, m.observation, st.p_bar, &zone, tol);
    let (inv, einv) = inverse_information(w, a, ew, ea);
    let psi_in: f64 = zone
        .iter()
        .map(|&(a, b)| m.false_alarm_density.mass(a, b))
        .sum();
    let eta = (q - q * psi_in).max(0.0);
    let assembled = assemble(&Ingredients {
        existence: r,
        mean_detection: st.p_bar,
        undetected_variance: st.sigma_e2,
        inverse_information: inv,
        detected_mass: w,
        absent_empty: 1.0 - q,
        absent_null: eta,
        undetected_empty: 1.0,
        undetected_null: 0.0,
        false_alarm_error: m.false_alarm_error,
        miss_error: m.miss_error,
    });
    let error = r * st.p_bar * (einv + ew * m.miss_error)
        + r * st.error * (m.miss_error + st.sigma_e2 + 1.0);
    check_result(JdeBound {
        assembled,
        mean_detection: st.p_bar,
        undetected_mean: st.x_star,
        undetected_variance: st.sigma_e2,
        eta,
        region: zone,
        cardinalities: alloc::vec![Cardinality {
            n: 1,
            probability: 1.0,
            w,
            inverse_information: inv,
            clutter_null: 1.0 - psi_in,
            method: Method::Quadrature,
            error: einv,
            w_error: ew,
            clutter_null_error: 0.0,
        }],
        error: fns::abs(error),
        regular: st.regular,
    })
}
