//! The densities of measurement models I (13) and II (22) of paper 002: the traits a caller
//! implements with closures ([`Density`] for f, ψ and v/λ; [`Observation`] for P_o and g),
//! and the ready-made forms the JavaScript bindings use ([`Density1`], [`Detection`],
//! [`LinearGaussian`]).

use alloc::vec::Vec;

use crate::bounds::closed::{check_finite, check_positive, check_variance};
use crate::error::{Error, Result, check_probability};
use crate::math::fns;
use crate::math::quadrature::{Control, Rule, Tolerance, integrate};
use crate::math::rng::{SeededRng, uniform};

/// The default integrals of [`Density`] and [`Observation`]: adaptive G10/K21 to an absolute
/// 1e-12 (or the rounding floor 64 ε ∫|f|), at most 200 pieces.
const MODEL_QUADRATURE: Control<'static> =
    Control::new(Rule::G10K21, Tolerance::AbsoluteAboveNoise(1e-12), 200);

/// A probability density on an interval, with what the bounds need of it.
pub trait Density {
    /// The interval [lo, hi] outside which the density is (numerically) 0.
    fn support(&self) -> (f64, f64);
    /// The density at x.
    fn pdf(&self, x: f64) -> f64;
    /// ∂²/∂x² ln f(x) where f(x) > 0 (the prior's share of the Fisher information; for a
    /// false-alarm or clutter density it is never called).
    fn d2_ln_pdf(&self, x: f64) -> f64;
    /// ∫_a^b f (default: adaptive quadrature).
    fn mass(&self, a: f64, b: f64) -> f64 {
        let (lo, hi) = self.support();
        let (a, b) = (a.max(lo), b.min(hi));
        if b <= a {
            return 0.0;
        }
        integrate(|x| self.pdf(x), &[a, b], &MODEL_QUADRATURE).value
    }
    /// A draw (needed by the Monte Carlo part of Theorem 2 only; default: none).
    fn sample(&self, _rng: &mut SeededRng) -> Option<f64> {
        None
    }
    /// `Some((mean, variance))` when the density is the Gaussian N(mean, variance) (truncated
    /// to its support only where it is below e^{−72}), so that Theorem 2's n = 2 terms can
    /// take their x-integrals in closed form (default: `None`).
    fn gaussian_form(&self) -> Option<(f64, f64)> {
        None
    }
}

/// P_o(x) and g(z|x) of the Bernoulli observation Θ_b (13).
pub trait Observation {
    /// P_o(x), the probability of observing the target at x.
    fn detection(&self, x: f64) -> f64;
    /// ∂²/∂x² ln P_o(x) where P_o(x) > 0.
    fn d2_ln_detection(&self, x: f64) -> f64;
    /// g(z|x).
    fn likelihood(&self, z: f64, x: f64) -> f64;
    /// ∂/∂x ln g(z|x).
    fn d_ln_likelihood(&self, z: f64, x: f64) -> f64;
    /// ∂²/∂x² ln g(z|x).
    fn d2_ln_likelihood(&self, z: f64, x: f64) -> f64;
    /// An interval of z holding g(·|x) for every x in [x_lo, x_hi].
    fn z_range(&self, x_lo: f64, x_hi: f64) -> (f64, f64);
    /// The part of [x_lo, x_hi] where g(z|x) is not negligible, so that ∫ f(x) g(z|x) dx can
    /// skip the rest (default: all of it).
    fn x_range(&self, _z: f64, x_lo: f64, x_hi: f64) -> (f64, f64) {
        (x_lo, x_hi)
    }
    /// ∫_a^b g(z|x) dz (default: quadrature).
    fn likelihood_mass(&self, a: f64, b: f64, x: f64) -> f64 {
        integrate(|z| self.likelihood(z, x), &[a, b], &MODEL_QUADRATURE).value
    }
    /// ∫_a^b g(z|x) ∂²_x ln g(z|x) dz (default: quadrature).
    fn fisher_mass(&self, a: f64, b: f64, x: f64) -> f64 {
        integrate(
            |z| {
                let g = self.likelihood(z, x);
                if g > 0.0 {
                    g * self.d2_ln_likelihood(z, x)
                } else {
                    0.0
                }
            },
            &[a, b],
            &MODEL_QUADRATURE,
        )
        .value
    }
    /// A draw of z from g(·|x) (Monte Carlo part of Theorem 2 only; default: none).
    fn sample(&self, _x: f64, _rng: &mut SeededRng) -> Option<f64> {
        None
    }
    /// `Some((P_o, a, b, σ_v²))` when P_o is the constant P_o and g(z|x) = N(z; a x + b, σ_v²),
    /// so that Theorem 2's n = 2 terms can take their x-integrals in closed form (default:
    /// `None`).
    fn linear_gaussian_form(&self) -> Option<(f64, f64, f64, f64)> {
        None
    }
}

/// Whether the prior is Gaussian ([`Density::gaussian_form`]) and the observation
/// linear-Gaussian with a constant P_o ([`Observation::linear_gaussian_form`]): the case where
/// Theorem 2's n = 2 cubature has closed-form x-integrals and is the default.
pub fn is_linear_gaussian(prior: &dyn Density, obs: &dyn Observation) -> bool {
    prior.gaussian_form().is_some() && obs.linear_gaussian_form().is_some()
}

/// In that case, the mean and variance of the marginal m(z) = ∫ f_d(x) g(z|x) dx (the m of
/// Lemma 1's β = m/v, paper 002; f_d = f when P_o is constant): with f = N(μ, P) and
/// g(z|x) = N(z; a x + b, R), m = N(a μ + b, a² P + R). `None` outside the case.
pub(crate) fn linear_gaussian_marginal(
    prior: &dyn Density,
    obs: &dyn Observation,
) -> Option<(f64, f64)> {
    let (mu, var) = prior.gaussian_form()?;
    let (_, a, b, r) = obs.linear_gaussian_form()?;
    Some((a * mu + b, a * a * var + r))
}

/// A standard normal draw (Box–Muller with libm, the same on every platform).
pub(crate) fn standard_normal(rng: &mut SeededRng) -> f64 {
    let u1 = 1.0 - uniform(rng); // (0, 1]
    let u2 = uniform(rng);
    fns::sqrt(-2.0 * fns::ln(u1)) * fns::cos(2.0 * core::f64::consts::PI * u2)
}

pub(crate) fn normal_pdf(x: f64, mean: f64, var: f64) -> f64 {
    let d = x - mean;
    fns::exp(-0.5 * d * d / var) / fns::sqrt(2.0 * core::f64::consts::PI * var)
}

/// Φ((b − μ)/σ) − Φ((a − μ)/σ) through erfc (accurate in both tails).
pub(crate) fn normal_mass(a: f64, b: f64, mean: f64, var: f64) -> f64 {
    let s = fns::sqrt(2.0 * var);
    let (ua, ub) = ((a - mean) / s, (b - mean) / s);
    if ua >= 0.0 {
        0.5 * (fns::erfc(ua) - fns::erfc(ub))
    } else if ub <= 0.0 {
        0.5 * (fns::erfc(-ub) - fns::erfc(-ua))
    } else {
        1.0 - 0.5 * (fns::erfc(-ua) + fns::erfc(ub))
    }
}

/// At most this many knots in a table ([`Density1::table`], [`Detection::table`]).
pub const MAX_KNOTS: usize = 10_000;
/// At most this many components in a [`Density1::mixture`].
pub const MAX_COMPONENTS: usize = 1_000;

/// The knots of a table: `x` strictly increasing and finite, 2 to [`MAX_KNOTS`] of them, and
/// `values` (the length of the column named `what`) as many. Errors name `x.length`, `x[i]`
/// or `what`.
fn check_knots(x: &[f64], values: usize, what: &str) -> Result<()> {
    Error::check_range("x.length", x.len(), 2, MAX_KNOTS)?;
    if values != x.len() {
        return Err(Error::dimension(what, x.len(), values));
    }
    for (i, &v) in x.iter().enumerate() {
        check_finite(&alloc::format!("x[{i}]"), v)?;
        if i > 0 && v <= x[i - 1] {
            return Err(Error::parameter(
                alloc::format!("x[{i}]"),
                v,
                "> the previous knot",
            ));
        }
    }
    Ok(())
}

/// How many standard deviations a Gaussian's support spans each side (e^{−72} beyond).
pub const GAUSSIAN_SPAN: f64 = 12.0;

/// The ready-made densities: Gaussian, uniform, Gaussian mixture, and tabulated (linear
/// interpolation between knots, 0 outside, normalised to integrate to 1).
#[derive(Clone, Debug, PartialEq)]
pub enum Density1 {
    /// A Gaussian N(mean, variance).
    Gaussian {
        /// The mean, finite.
        mean: f64,
        /// The variance (> 0).
        variance: f64,
    },
    /// A uniform density U[low, high].
    Uniform {
        /// The lower end of the support.
        low: f64,
        /// The upper end of the support (> low).
        high: f64,
    },
    /// Σ w_i N(mean_i, var_i) with normalised weights.
    Mixture(Vec<(f64, f64, f64)>),
    /// Linear interpolation of `density` at the increasing knots `x`, normalised; `cdf[i]` is
    /// the mass left of knot i.
    Table {
        /// Knots, strictly increasing.
        x: Vec<f64>,
        /// Density at the knots (normalised).
        density: Vec<f64>,
        /// Mass left of each knot.
        cdf: Vec<f64>,
    },
}

impl Density1 {
    /// N(mean, variance); errors name `mean` or `variance`.
    pub fn gaussian(mean: f64, variance: f64) -> Result<Self> {
        check_finite("mean", mean)?;
        check_variance("variance", variance)?;
        Ok(Density1::Gaussian { mean, variance })
    }

    /// U[low, high]; errors name `low` or `high`.
    pub fn uniform(low: f64, high: f64) -> Result<Self> {
        check_finite("low", low)?;
        check_finite("high", high)?;
        if high <= low {
            return Err(Error::parameter("high", high, "> low"));
        }
        Ok(Density1::Uniform { low, high })
    }

    /// A mixture of 1 to [`MAX_COMPONENTS`] `(weight, mean, variance)`; weights > 0,
    /// normalised here. Errors name `length`, `[i].weight` etc.
    pub fn mixture(components: &[(f64, f64, f64)]) -> Result<Self> {
        Error::check_range("length", components.len(), 1, MAX_COMPONENTS)?;
        let mut total = 0.0;
        for (i, &(w, m, v)) in components.iter().enumerate() {
            check_positive(&alloc::format!("[{i}].weight"), w)?;
            check_finite(&alloc::format!("[{i}].mean"), m)?;
            check_variance(&alloc::format!("[{i}].variance"), v)?;
            total += w;
        }
        if !total.is_finite() {
            return Err(Error::parameter("[0].weight", total, "with a finite sum"));
        }
        Ok(Density1::Mixture(
            components
                .iter()
                .map(|&(w, m, v)| (w / total, m, v))
                .collect(),
        ))
    }

    /// A table: `x` strictly increasing (2 to [`MAX_KNOTS`] knots), `density` ≥ 0 with a
    /// positive integral. Errors name `x.length`, `x[i]` or `density[i]`.
    pub fn table(x: &[f64], density: &[f64]) -> Result<Self> {
        check_knots(x, density.len(), "density")?;
        for (i, &d) in density.iter().enumerate() {
            if !(d.is_finite() && d >= 0.0) {
                return Err(Error::parameter(
                    alloc::format!("density[{i}]"),
                    d,
                    "finite and ≥ 0",
                ));
            }
        }
        let mut cdf = Vec::with_capacity(x.len());
        let mut acc = 0.0;
        cdf.push(0.0);
        for i in 1..x.len() {
            acc += 0.5 * (density[i] + density[i - 1]) * (x[i] - x[i - 1]);
            cdf.push(acc);
        }
        if !(acc.is_finite() && acc > 0.0) {
            return Err(Error::parameter(
                "density",
                acc,
                "with a finite, positive integral",
            ));
        }
        Ok(Density1::Table {
            x: x.to_vec(),
            density: density.iter().map(|d| d / acc).collect(),
            cdf: cdf.iter().map(|c| c / acc).collect(),
        })
    }

    /// The segment of a table holding t (None outside).
    fn segment(x: &[f64], t: f64) -> Option<usize> {
        let last = x.len().checked_sub(1)?;
        if !(t >= x[0] && t <= x[last]) {
            return None;
        }
        let i = x.partition_point(|&k| k <= t);
        Some(i.clamp(1, last) - 1)
    }

    /// (f, f', f'') at x.
    fn derivatives(&self, t: f64) -> (f64, f64, f64) {
        match self {
            Density1::Gaussian { mean, variance } => {
                let f = normal_pdf(t, *mean, *variance);
                let u = (t - mean) / variance;
                (f, -u * f, (u * u - 1.0 / variance) * f)
            }
            Density1::Uniform { low, high } => {
                if t >= *low && t <= *high {
                    (1.0 / (high - low), 0.0, 0.0)
                } else {
                    (0.0, 0.0, 0.0)
                }
            }
            Density1::Mixture(c) => {
                let mut s = (0.0, 0.0, 0.0);
                for &(w, m, v) in c {
                    let f = w * normal_pdf(t, m, v);
                    let u = (t - m) / v;
                    s.0 += f;
                    s.1 += -u * f;
                    s.2 += (u * u - 1.0 / v) * f;
                }
                s
            }
            Density1::Table { x, density, .. } => match Self::segment(x, t) {
                Some(i) => {
                    let slope = (density[i + 1] - density[i]) / (x[i + 1] - x[i]);
                    (density[i] + slope * (t - x[i]), slope, 0.0)
                }
                None => (0.0, 0.0, 0.0),
            },
        }
    }
}

impl Density for Density1 {
    fn support(&self) -> (f64, f64) {
        match self {
            Density1::Gaussian { mean, variance } => {
                let s = GAUSSIAN_SPAN * fns::sqrt(*variance);
                (mean - s, mean + s)
            }
            Density1::Uniform { low, high } => (*low, *high),
            Density1::Mixture(c) => {
                c.iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |a, &(_, m, v)| {
                        let s = GAUSSIAN_SPAN * fns::sqrt(v);
                        (a.0.min(m - s), a.1.max(m + s))
                    })
            }
            Density1::Table { x, .. } => (x[0], x[x.len() - 1]),
        }
    }

    fn pdf(&self, x: f64) -> f64 {
        self.derivatives(x).0
    }

    fn d2_ln_pdf(&self, x: f64) -> f64 {
        match self {
            Density1::Gaussian { variance, .. } => -1.0 / variance,
            _ => {
                let (f, d1, d2) = self.derivatives(x);
                if f > 0.0 {
                    d2 / f - (d1 / f) * (d1 / f)
                } else {
                    0.0
                }
            }
        }
    }

    fn gaussian_form(&self) -> Option<(f64, f64)> {
        match self {
            Density1::Gaussian { mean, variance } => Some((*mean, *variance)),
            _ => None,
        }
    }

    fn mass(&self, a: f64, b: f64) -> f64 {
        if b <= a {
            return 0.0;
        }
        match self {
            Density1::Gaussian { mean, variance } => normal_mass(a, b, *mean, *variance),
            Density1::Uniform { low, high } => (b.min(*high) - a.max(*low)).max(0.0) / (high - low),
            Density1::Mixture(c) => c.iter().map(|&(w, m, v)| w * normal_mass(a, b, m, v)).sum(),
            Density1::Table { .. } => self.cdf(b) - self.cdf(a),
        }
    }

    fn sample(&self, rng: &mut SeededRng) -> Option<f64> {
        Some(match self {
            Density1::Gaussian { mean, variance } => {
                mean + fns::sqrt(*variance) * standard_normal(rng)
            }
            Density1::Uniform { low, high } => low + (high - low) * uniform(rng),
            Density1::Mixture(c) => {
                let mut u = uniform(rng);
                let mut pick = c.last()?;
                for comp in c {
                    if u < comp.0 {
                        pick = comp;
                        break;
                    }
                    u -= comp.0;
                }
                pick.1 + fns::sqrt(pick.2) * standard_normal(rng)
            }
            Density1::Table { x, density, cdf } => {
                let u = uniform(rng);
                let i = cdf.partition_point(|&c| c <= u).clamp(1, x.len() - 1) - 1;
                // Invert the quadratic CDF of the trapezoid [x_i, x_{i+1}].
                let (h, d0) = (x[i + 1] - x[i], density[i]);
                let slope = (density[i + 1] - d0) / h;
                let m = u - cdf[i];
                let t = if fns::abs(slope) < 1e-300 {
                    if d0 > 0.0 { m / d0 } else { 0.0 }
                } else {
                    let disc = (d0 * d0 + 2.0 * slope * m).max(0.0);
                    (fns::sqrt(disc) - d0) / slope
                };
                x[i] + crate::math::fns::clamp(t, 0.0, h)
            }
        })
    }
}

impl Density1 {
    /// The mass left of t (tables; others through [`Density::mass`]).
    fn cdf(&self, t: f64) -> f64 {
        match self {
            Density1::Table { x, density, cdf } => {
                if t <= x[0] {
                    return 0.0;
                }
                let last = x.len() - 1;
                if t >= x[last] {
                    return 1.0;
                }
                let i = x.partition_point(|&k| k <= t).clamp(1, last) - 1;
                let d = t - x[i];
                let slope = (density[i + 1] - density[i]) / (x[i + 1] - x[i]);
                cdf[i] + density[i] * d + 0.5 * slope * d * d
            }
            _ => self.mass(f64::NEG_INFINITY, t),
        }
    }
}

/// P_o(x): a constant, or linear interpolation of a table (held constant beyond its ends).
#[derive(Clone, Debug, PartialEq)]
pub enum Detection {
    /// The same detection probability P_o everywhere.
    Constant(f64),
    /// Knots x (strictly increasing) and probabilities in [0, 1].
    Table {
        /// The knots, strictly increasing.
        x: Vec<f64>,
        /// The detection probability P_o ∈ [0, 1] at the knots.
        probability: Vec<f64>,
    },
}

impl Detection {
    /// Validated constant; the error names `detection_probability`.
    pub fn constant(p: f64) -> Result<Self> {
        check_probability(|| "detection_probability".into(), p)?;
        Ok(Detection::Constant(p))
    }

    /// Validated table (2 to [`MAX_KNOTS`] knots); errors name `x.length`, `x[i]` or
    /// `probability[i]`.
    pub fn table(x: &[f64], probability: &[f64]) -> Result<Self> {
        check_knots(x, probability.len(), "probability")?;
        for (i, &p) in probability.iter().enumerate() {
            check_probability(|| alloc::format!("probability[{i}]"), p)?;
        }
        Ok(Detection::Table {
            x: x.to_vec(),
            probability: probability.to_vec(),
        })
    }

    /// (P_o, P_o') at t.
    fn value(&self, t: f64) -> (f64, f64) {
        match self {
            Detection::Constant(p) => (*p, 0.0),
            Detection::Table { x, probability } => {
                let last = x.len() - 1;
                if t <= x[0] {
                    return (probability[0], 0.0);
                }
                if t >= x[last] {
                    return (probability[last], 0.0);
                }
                let i = x.partition_point(|&k| k <= t).clamp(1, last) - 1;
                let slope = (probability[i + 1] - probability[i]) / (x[i + 1] - x[i]);
                (probability[i] + slope * (t - x[i]), slope)
            }
        }
    }
}

/// g(z|x) = N(z; a x + b, σ_v²) with detection P_o(x): the linear-Gaussian observation.
#[derive(Clone, Debug, PartialEq)]
pub struct LinearGaussian {
    /// The detection probability P_o(x).
    pub detection: Detection,
    /// The gain a of z = a x + b + v.
    pub gain: f64,
    /// The offset b of z = a x + b + v.
    pub offset: f64,
    /// The measurement noise variance σ_v² > 0 of v.
    pub noise_variance: f64,
}

impl LinearGaussian {
    /// Validated; errors name `gain`, `offset` or `noise_variance`.
    pub fn new(detection: Detection, gain: f64, offset: f64, noise_variance: f64) -> Result<Self> {
        check_finite("gain", gain)?;
        check_finite("offset", offset)?;
        check_variance("noise_variance", noise_variance)?;
        Ok(LinearGaussian {
            detection,
            gain,
            offset,
            noise_variance,
        })
    }
}

impl Observation for LinearGaussian {
    fn detection(&self, x: f64) -> f64 {
        self.detection.value(x).0
    }
    fn d2_ln_detection(&self, x: f64) -> f64 {
        let (p, d) = self.detection.value(x);
        if p > 0.0 { -(d / p) * (d / p) } else { 0.0 }
    }
    fn likelihood(&self, z: f64, x: f64) -> f64 {
        normal_pdf(z, self.gain * x + self.offset, self.noise_variance)
    }
    fn d_ln_likelihood(&self, z: f64, x: f64) -> f64 {
        self.gain * (z - self.gain * x - self.offset) / self.noise_variance
    }
    fn d2_ln_likelihood(&self, _z: f64, _x: f64) -> f64 {
        -self.gain * self.gain / self.noise_variance
    }
    fn z_range(&self, x_lo: f64, x_hi: f64) -> (f64, f64) {
        let (a, b) = (
            self.gain * x_lo + self.offset,
            self.gain * x_hi + self.offset,
        );
        let s = GAUSSIAN_SPAN * fns::sqrt(self.noise_variance);
        (a.min(b) - s, a.max(b) + s)
    }
    fn x_range(&self, z: f64, x_lo: f64, x_hi: f64) -> (f64, f64) {
        if self.gain == 0.0 {
            return (x_lo, x_hi);
        }
        let s = GAUSSIAN_SPAN * fns::sqrt(self.noise_variance);
        let (u, v) = (
            (z - self.offset - s) / self.gain,
            (z - self.offset + s) / self.gain,
        );
        (u.min(v).max(x_lo), u.max(v).min(x_hi))
    }
    fn likelihood_mass(&self, a: f64, b: f64, x: f64) -> f64 {
        normal_mass(a, b, self.gain * x + self.offset, self.noise_variance)
    }
    fn fisher_mass(&self, a: f64, b: f64, x: f64) -> f64 {
        self.d2_ln_likelihood(a, x) * self.likelihood_mass(a, b, x)
    }
    fn sample(&self, x: f64, rng: &mut SeededRng) -> Option<f64> {
        Some(self.gain * x + self.offset + fns::sqrt(self.noise_variance) * standard_normal(rng))
    }
    fn linear_gaussian_form(&self) -> Option<(f64, f64, f64, f64)> {
        match self.detection {
            Detection::Constant(p) => Some((p, self.gain, self.offset, self.noise_variance)),
            Detection::Table { .. } => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A subnormal variance is an error naming the field (it made Theorem 2's quadrature run
    /// for 37 s in the fuzzer); the smallest normal one is accepted.
    #[test]
    fn thm2_subnormal_variances_are_rejected_by_name() {
        for v in [5e-324, 1e-310, 0.0, -1.0, f64::NAN, f64::INFINITY] {
            let e = Density1::gaussian(0.0, v).unwrap_err();
            assert!(alloc::format!("{e}").contains("variance"), "{e}");
            let e = Density1::mixture(&[(1.0, 0.0, v)]).unwrap_err();
            assert!(alloc::format!("{e}").contains("[0].variance"), "{e}");
        }
        assert!(Density1::gaussian(0.0, f64::MIN_POSITIVE).is_ok());
        let e = Density1::mixture(&[]).unwrap_err();
        assert_eq!(e, Error::range("length", 0, 1, MAX_COMPONENTS));
        let e = Density1::mixture(&alloc::vec![(1.0, 0.0, 1.0); MAX_COMPONENTS + 1]).unwrap_err();
        assert_eq!(e.field(), "length");
        assert!(Density1::mixture(&[(1.0, 0.0, 1e-300)]).is_ok());
    }

    /// The tables of f, ψ, c (13)/(22) and of P_o: the error names the column or knot at fault,
    /// the same way for both.
    #[test]
    fn eq13_tables_name_the_knot_at_fault() {
        let field = |e: Error| alloc::string::String::from(e.field());
        let d = |x: &[f64], v: &[f64]| field(Density1::table(x, v).unwrap_err());
        let p = |x: &[f64], v: &[f64]| field(Detection::table(x, v).unwrap_err());
        assert_eq!(d(&[0.0], &[1.0]), "x.length");
        assert_eq!(p(&[0.0], &[1.0]), "x.length");
        let many = alloc::vec![1.0; MAX_KNOTS + 1];
        assert_eq!(d(&many, &many), "x.length");
        assert_eq!(p(&many, &many), "x.length");
        assert_eq!(d(&[0.0, 1.0], &[1.0]), "density");
        assert_eq!(p(&[0.0, 1.0], &[1.0]), "probability");
        assert_eq!(d(&[0.0, f64::NAN], &[1.0, 1.0]), "x[1]");
        assert_eq!(p(&[0.0, 1.0, 1.0], &[1.0, 1.0, 1.0]), "x[2]");
        assert_eq!(d(&[0.0, 1.0], &[1.0, -1.0]), "density[1]");
        assert_eq!(p(&[0.0, 1.0], &[1.0, 1.5]), "probability[1]");
        assert!(Density1::table(&[0.0, 1.0], &[1.0, 1.0]).is_ok());
        assert!(Detection::table(&[0.0, 1.0], &[0.2, 0.9]).is_ok());
    }
}
