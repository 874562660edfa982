//! The n-point terms of Theorem 2 (25) of paper 002 by Monte Carlo over Z^n: w_n, J'_n⁻¹ and
//! the clutter-only rejection probability of η2, each with one standard error. Used for every
//! n ≥ 2 (n ≥ 3 when the n = 2 cubature is chosen); m(z) is tabulated for the MAP test.

use alloc::vec::Vec;

use super::{MapTest, ModelII, Term, information_density};
use crate::bounds::closed::poisson_pmf;
use crate::bounds::theorem::{Cardinality, Method, TheoremOptions, marginal};
use crate::error::{Error, Result};
use crate::math::fns;
use crate::math::rng::{SeededRng, seeded};

/// The cardinalities n = k + 1 for k in `first..=last` by Monte Carlo, pushed onto `cards`;
/// one generator seeded with [`TheoremOptions::seed`] runs through them in order.
pub(super) fn terms(
    m: &ModelII<'_>,
    p: f64,
    first: usize,
    last: usize,
    s: &TheoremOptions,
    cards: &mut Vec<Cardinality>,
) -> Result<()> {
    let samples = s.samples.max(2);
    let table = Table::marginal(m, p, s.tolerance);
    let map = MapTest { r: m.existence, p };
    let mut rng = seeded(s.seed);
    for k in first..=last {
        let n = k + 1;
        let c = monte_carlo(m, &table, p, n, samples, &mut rng, map)?;
        cards.push(c.cardinality(n, poisson_pmf(m.clutter_rate, k), Method::MonteCarlo));
    }
    Ok(())
}

/// m(z) on a grid (linear interpolation, 0 outside g's range).
pub(super) struct Table {
    lo: f64,
    step: f64,
    values: Vec<f64>,
}

impl Table {
    /// m(z) at 2049 nodes over g's z range for x in the prior's support, by quadrature.
    pub fn marginal(m: &ModelII<'_>, p: f64, tol: f64) -> Table {
        let (xl, xh) = m.prior.support();
        let (ol, oh) = m.observation.z_range(xl, xh);
        let cells = 2048;
        let step = (oh - ol) / cells as f64;
        Table {
            lo: ol,
            step,
            values: (0..=cells)
                .map(|i| marginal(m.prior, m.observation, p, ol + step * i as f64, tol))
                .collect(),
        }
    }

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

/// w_n, J'_n⁻¹ and the clutter-only null probability for n points by Monte Carlo: x from the
/// prior weighted by P_o(x)/P̄o (so x ~ f_d), the target's point z_1 ~ g(·|x) (p_n is symmetric
/// in the points and so is the MAP region, so the target may be put first), z_2 … z_n ~ c.
pub(super) fn monte_carlo(
    m: &ModelII<'_>,
    table: &Table,
    p: f64,
    n: usize,
    samples: usize,
    rng: &mut SeededRng,
    map: MapTest,
) -> Result<Term> {
    let (prior, obs, clutter) = (m.prior, m.observation, m.clutter_density);
    let beta = |points: &[f64]| beta(m, table, points);
    let mut moments = Moments::default();
    let mut clutter_only = alloc::vec![0.0; n];
    let mut z = alloc::vec![0.0; n];
    let mut terms = Vec::with_capacity(n);
    for _ in 0..samples {
        // clutter alone: does the detector reject n clutter points?
        for c in clutter_only.iter_mut() {
            *c = clutter.sample(rng).ok_or_else(|| unsampled("clutter"))?;
        }
        let (b, zero) = beta(&clutter_only);
        if !map.declares(b, zero) {
            moments.rejected += 1.0;
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
        let (b, zero) = beta(&z);
        if !map.declares(b, zero) {
            continue;
        }
        let q = information_density(prior, obs, clutter, x, &z, &mut terms);
        moments.add(omega, omega * q);
    }
    Ok(moments.term(samples))
}

/// The error of a density that cannot be drawn from.
fn unsampled(what: &'static str) -> Error {
    Error::Unsupported {
        what: what.into(),
        reason: "Theorem 2 with clutter needs draws from it (Monte Carlo for n ≥ 3, or n ≥ 2 without quadrature)",
    }
}

/// β(Z) = Σ_i m(z_i)/v(z_i) over the points where v > 0, and whether v is 0 at any.
fn beta(m: &ModelII<'_>, table: &Table, points: &[f64]) -> (f64, bool) {
    let mut beta = 0.0;
    let mut zero = false;
    for &zi in points {
        let v = m.clutter_rate * m.clutter_density.pdf(zi);
        if v > 0.0 {
            beta += table.at(zi) / v;
        } else {
            zero = true;
        }
    }
    (beta, zero)
}

/// The running sums of ω (the f_d weight on the MAP region) and ω q (q the information
/// density), their squares and product, and the count of rejected clutter-only draws.
#[derive(Default)]
struct Moments {
    sx: f64,
    sy: f64,
    sxx: f64,
    syy: f64,
    sxy: f64,
    rejected: f64,
}

impl Moments {
    fn add(&mut self, xv: f64, yv: f64) {
        self.sx += xv;
        self.sy += yv;
        self.sxx += xv * xv;
        self.syy += yv * yv;
        self.sxy += xv * yv;
    }

    /// The means over `samples` draws: w = E ω, A = E ω q, null; J'⁻¹ = w²/A with its standard
    /// error by the delta method.
    fn term(&self, samples: usize) -> Term {
        let nf = samples as f64;
        let (w, a) = (self.sx / nf, self.sy / nf);
        let var = |s2: f64, mean: f64| (s2 / nf - mean * mean).max(0.0) / nf;
        let (vx, vy) = (var(self.sxx, w), var(self.syy, a));
        let cxy = (self.sxy / nf - w * a) / nf;
        let null = self.rejected / nf;
        let enull = fns::sqrt(null * (1.0 - null) / nf);
        let ew = fns::sqrt(vx);
        let (s, es) = if w > 0.0 && a > 0.0 {
            let (gw, ga) = (2.0 * w / a, -(w * w) / (a * a));
            let v = gw * gw * vx + ga * ga * vy + 2.0 * gw * ga * cxy;
            (w * w / a, fns::sqrt(v.max(0.0)))
        } else {
            (0.0, 0.0)
        };
        Term {
            w: w.min(1.0),
            ew,
            s,
            es,
            null,
            enull,
        }
    }
}
