//! The n = 2 terms of Theorem 2 (25) of paper 002 and the 2-point clutter rejection of η2 by
//! deterministic cubature over Z² ([`TheoremOptions::quadrature_cardinality`] = 2), with its
//! own globally adaptive G10/K21 rule [`adaptive`] for the nested integrals.
//!
//! In the linear-Gaussian case of (22) (f = N(μ, P), constant P_o, g(z|x) = N(z; a x + b, R),
//! any clutter density c; [`LinearGaussianCase`]) the x-integrals are taken in closed form:
//! m(z) = N(z; a μ + b, a² P + R), ∫_R m by erfc, and the x-integral of the information density
//! of p_2 by (see [`LinearGaussianCase::information`])
//!
//! ```text
//! ∫ f_d(x) g(z_1|x) (−∂²_x ln p_2(x, z_1, z_2)) dx
//!     = m(z_1) [1/P + a²/R − (a (z_1 − z_2)/R)² E σ'(u)],   u ~ N(μ_u, s_u²)
//! ```
//!
//! σ' the logistic density: the one integral left, a smooth 1D one ([`logistic_normal`], a
//! sinh-mapped trapezoidal rule over u). The general path (nested quadratures over x) is kept
//! for every other model, and forced by the tests to check the closed forms.
//!
//! [`TheoremOptions::quadrature_cardinality`]: crate::bounds::TheoremOptions::quadrature_cardinality

use alloc::vec::Vec;

use super::{ModelII, Term, information_density};
use crate::bounds::model::{
    Density, Observation, linear_gaussian_marginal, normal_mass, normal_pdf,
};
use crate::bounds::theorem::inverse_information;
use crate::math::fns;
use crate::math::optimise::{bisect, golden_section};
use crate::math::quadrature::{
    Control, Rule, Tolerance, integrate, integrate_equal_pieces as adaptive, integrate_vec,
};

/// The cells of the scan of r P̄o m − K v for the MAP region's section.
const CELLS: usize = 512;

/// The n = 2 terms of (25) and the 2-point clutter rejection of η2 by deterministic
/// cubature over Z², with the target's point z_1 and the clutter point z_2 (p_2 and the MAP
/// region are symmetric in the two points, so the target may be put first):
///
/// ```text
/// w_2     = ∫ c(z_2) ∫_{R(z_2)} m(z_1) dz_1 dz_2
/// A_2     = ∫ c(z_2) ∫_{R(z_2)} ∫ f_d(x) g(z_1|x) (−∂²_x ln p_2(x, z_1, z_2)) dx dz_1 dz_2
/// null_2  = ∫ c(z_2) (1 − ∫_{R(z_2)} c) dz_2,      J'_2⁻¹ = w_2² / A_2
/// ```
///
/// R(z_2) = {z_1 : r(1 − P̄o) + r P̄o (β(z_1) + β(z_2)) ≥ 1 − r} (Lemma 1, β = m/v) is the MAP
/// region's section at z_2: for each outer node it is found by root-finding on
/// r P̄o m(z_1) − K v(z_1) (a 512-cell scan of tabulated m and v, then bisection with m by
/// quadrature), and the inner integrals are split at its ends. The outer integral is
/// adaptive G10/K21 to half the inner tolerance on the sum w + null + A/(A_1/w_1) (all ≥ 0;
/// A_1/w_1 the information per unit of detected mass of n = 1), whose error estimate is
/// given to each; the inner ones add their relative tolerance. Its pieces are split where
/// R(z_2) changes form (`Cubature::outer_breakpoints`: there the integrand has a kink or a
/// √ behaviour) and each is mapped by z_2 = a + (b − a)(3u² − 2u³), which makes a √ at
/// its ends smooth: the integrand is then smooth on each piece.
///
/// With `closed_form` and a linear-Gaussian model ([`LinearGaussianCase::of`]) m, the inner
/// w-integral and the x-integral of A_2 are closed forms (the module docs); otherwise (and
/// always with `closed_form` false, as the tests force) every integral is by quadrature.
pub(super) fn quadrature2(
    m: &ModelII<'_>,
    p: f64,
    scale_a: f64,
    z_range: (f64, f64),
    tol: f64,
    closed_form: bool,
) -> Term {
    let cub = Cubature::new(m, p, scale_a, z_range, tol, closed_form);
    let mut terms = Vec::with_capacity(2);
    let pts = cub.outer_breakpoints(m.clutter_density.support());
    let control = Control::new(
        Rule::G10K21,
        Tolerance::AbsoluteAboveNoise(0.5 * cub.inner),
        200,
    );
    // z_2 = a + (b − a)(3u² − 2u³) on each piece [a, b] = [pts[i], pts[i + 1]], u ∈ [i, i + 1]:
    // the Jacobian 6(b − a)u(1 − u) turns the √ behaviour of the section's width where it
    // appears into a smooth one
    let unit: Vec<f64> = (0..pts.len()).map(|i| i as f64).collect();
    let smoothed = |x: f64| {
        let i = (x.max(0.0) as usize).min(pts.len() - 2);
        let u = x - i as f64;
        let (a, b) = (pts[i], pts[i + 1]);
        let jac = 6.0 * (b - a) * u * (1.0 - u);
        if jac <= 0.0 {
            return [0.0; 4];
        }
        cub.outer(a + (b - a) * (u * u * (3.0 - 2.0 * u)), &mut terms)
            .map(|v| v * jac)
    };
    let outer = integrate_vec(smoothed, &unit, &control);
    let (v, err) = (outer.value, outer.error);
    let inner = cub.inner;
    let (w, a, null) = (v[1].clamp(0.0, 1.0), v[2], v[3].clamp(0.0, 1.0));
    let ew = err + 2.0 * inner * w;
    let ea = err * scale_a + 2.0 * inner * fns::abs(a);
    let enull = err;
    let (s, es) = inverse_information(w, a, ew, ea);
    Term {
        w,
        ew,
        s,
        es,
        null,
        enull,
    }
}

/// The breakpoints of [`quadrature2`]'s outer integral (`Cubature::outer_breakpoints`).
#[cfg(test)]
pub(super) fn outer_breakpoints(m: &ModelII<'_>, p: f64, z_range: (f64, f64)) -> Vec<f64> {
    Cubature::new(m, p, 1.0, z_range, 1e-10, true).outer_breakpoints(m.clutter_density.support())
}

/// The MAP region's section {z_1 : r P̄o m(z_1) − K v(z_1) ≥ 0} (`Cubature::section`).
#[cfg(test)]
pub(super) fn section(m: &ModelII<'_>, p: f64, z_range: (f64, f64), k: f64) -> Vec<(f64, f64)> {
    Cubature::new(m, p, 1.0, z_range, 1e-10, true).section(k)
}

/// What the nested integrals of [`quadrature2`] share: the model, the MAP test's constants,
/// the ranges, and m and v tabulated on the scan's grid.
struct Cubature<'a> {
    prior: &'a dyn Density,
    obs: &'a dyn Observation,
    clutter: &'a dyn Density,
    lambda: f64,
    p: f64,
    /// r P̄o.
    rp: f64,
    /// (1 − r) − r(1 − P̄o): the section at z_2 is r P̄o m(z_1) − (k0 − r P̄o β(z_2)) v(z_1) ≥ 0.
    k0: f64,
    /// A_1/w_1, the unit of A_2 in the outer integrand.
    scale_a: f64,
    /// The inner relative tolerance.
    inner: f64,
    /// The prior's support.
    x: (f64, f64),
    /// The measurement range scanned.
    z: (f64, f64),
    /// g's z range over the prior's support.
    o: (f64, f64),
    /// (m, v) at the scan's nodes.
    grid: Vec<(f64, f64)>,
    /// The local extrema of β_1 = r P̄o m/v between the scan's nodes where v > 0: (the node i
    /// where the scan sees one, the point z in [node i − 1, node i + 1] where it is (golden
    /// section), β_1(z), whether it is a maximum).
    extrema: Vec<(usize, f64, f64, bool)>,
    /// The closed forms of the linear-Gaussian case, when they are used.
    lg: Option<LinearGaussianCase>,
}

impl<'a> Cubature<'a> {
    fn new(
        m: &ModelII<'a>,
        p: f64,
        scale_a: f64,
        z: (f64, f64),
        tol: f64,
        closed_form: bool,
    ) -> Self {
        let r = m.existence;
        let x = m.prior.support();
        let mut cub = Cubature {
            prior: m.prior,
            obs: m.observation,
            clutter: m.clutter_density,
            lambda: m.clutter_rate,
            p,
            rp: r * p,
            k0: (1.0 - r) - r * (1.0 - p),
            scale_a,
            // Nested tolerances are floored at 1e-6 (relative) to keep the cost of a call
            // down; the error estimate reports what is reached.
            inner: tol.max(1e-6),
            x,
            z,
            o: m.observation.z_range(x.0, x.1),
            grid: Vec::new(),
            extrema: Vec::new(),
            lg: if closed_form {
                LinearGaussianCase::of(m.prior, m.observation)
            } else {
                None
            },
        };
        cub.grid = (0..=CELLS)
            .map(|i| {
                let z = cub.node(i);
                (cub.marginal(z), cub.lambda * cub.clutter.pdf(z))
            })
            .collect();
        cub.extrema = cub.extrema();
        cub
    }

    /// β_1(z) = r P̄o m(z)/v(z) (∞ where v = 0).
    fn beta(&self, z: f64) -> f64 {
        let v = self.lambda * self.clutter.pdf(z);
        if v > 0.0 {
            self.rp * self.marginal(z) / v
        } else {
            f64::INFINITY
        }
    }

    /// The local extrema of β_1 seen by the scan (a node above or below both neighbours, v > 0
    /// at all three), each found by golden section between the neighbours.
    fn extrema(&self) -> Vec<(usize, f64, f64, bool)> {
        let grid = &self.grid;
        let b_at = |i: usize| self.rp * grid[i].0 / grid[i].1;
        let mut out = Vec::new();
        for i in 1..CELLS {
            if !(grid[i - 1].1 > 0.0 && grid[i].1 > 0.0 && grid[i + 1].1 > 0.0) {
                continue;
            }
            let (bl, b, br) = (b_at(i - 1), b_at(i), b_at(i + 1));
            let sign = if b > bl && b >= br {
                -1.0
            } else if b < bl && b <= br {
                1.0
            } else {
                continue;
            };
            let (z, v) = golden_section(
                |z| sign * self.beta(z),
                self.node(i - 1),
                self.node(i + 1),
                80,
            );
            out.push((i, z, sign * v, sign < 0.0));
        }
        out
    }

    /// The breakpoints of the outer integral over the clutter's support [cl, ch]: 8 equal
    /// pieces, and the z_2 where the section R(z_2) changes form. R(z_2) is
    /// {z_1 : β_1(z_1) ≥ k0 − β_1(z_2)}, β_1 = r P̄o m/v, so it changes form where
    /// β_1(z_2) = k0 − b for b = 0 (K = 0: the whole range) and b a critical value of β_1
    /// (a local extremum, or its value at an end of the clutter's support): there the
    /// section appears, splits or reaches an end, and the outer integrand has a kink or a
    /// √ behaviour.
    fn outer_breakpoints(&self, (cl, ch): (f64, f64)) -> Vec<f64> {
        let mut pts: Vec<f64> = (0..=8).map(|i| cl + (ch - cl) * i as f64 / 8.0).collect();
        let grid = &self.grid;
        let beta = |z: f64| self.beta(z);
        let on = |i: usize| grid[i].1 > 0.0;
        let b_at = |i: usize| self.rp * grid[i].0 / grid[i].1;
        let mut critical = alloc::vec![0.0];
        critical.extend(self.extrema.iter().map(|e| e.2));
        let cell = (self.z.1 - self.z.0) / CELLS as f64;
        for i in 0..=CELLS {
            let left = i > 0 && on(i - 1);
            let right = i < CELLS && on(i + 1);
            if on(i) && !(left && right) {
                // an end of a run where v > 0: the clutter's support's end when it is within
                // a cell (β_1 there exactly), else the node
                let near = [cl, ch]
                    .into_iter()
                    .find(|&e| fns::abs(e - self.node(i)) <= cell && beta(e).is_finite());
                critical.push(near.map_or(b_at(i), beta));
            }
        }
        let (zl, zh) = self.z;
        for c in critical {
            let t = self.k0 - c;
            if !(t > 0.0 && t.is_finite()) {
                continue;
            }
            let above = |mz: f64, vz: f64| self.rp * mz - t * vz >= 0.0;
            for i in 1..=CELLS {
                if !(on(i - 1) && on(i)) {
                    continue;
                }
                let left_above = above(grid[i - 1].0, grid[i - 1].1);
                if left_above == above(grid[i].0, grid[i].1) {
                    continue;
                }
                let z = bisect(
                    |mid| {
                        let v = self.lambda * self.clutter.pdf(mid);
                        above(self.marginal(mid), v) == left_above
                    },
                    self.node(i - 1),
                    self.node(i),
                    1e-11 * (zh - zl),
                    usize::MAX,
                );
                if z > cl && z < ch {
                    pts.push(z);
                }
            }
        }
        crate::math::sort::sort_f64(&mut pts);
        let min_gap = 1e-9 * (ch - cl);
        pts.dedup_by(|b, a| *b - *a <= min_gap);
        pts
    }

    /// Node i of the scan.
    fn node(&self, i: usize) -> f64 {
        let (zl, zh) = self.z;
        zl + (zh - zl) * i as f64 / CELLS as f64
    }

    /// m(z) = ∫ f_d(x) g(z|x) dx by [`adaptive`] (closed form in the linear-Gaussian case).
    fn marginal(&self, z: f64) -> f64 {
        let p = self.p;
        if p <= 0.0 {
            return 0.0;
        }
        if let Some(lg) = &self.lg {
            return lg.marginal(z);
        }
        let (prior, obs) = (self.prior, self.obs);
        let (a, b) = obs.x_range(z, self.x.0, self.x.1);
        adaptive(
            &mut |x| prior.pdf(x) * obs.detection(x) * obs.likelihood(z, x),
            a,
            b,
            2,
            self.inner,
        )
        .0 / p
    }

    /// Whether z (with m(z), v(z)) is in the section {z_1 : r P̄o m(z_1) − K v(z_1) ≥ 0}.
    fn inside(&self, k: f64, mz: f64, vz: f64) -> bool {
        self.rp * mz - k * vz >= 0.0
    }

    /// The section {z_1 : r P̄o m(z_1) − K v(z_1) ≥ 0} as intervals: the sign changes of the
    /// scan's nodes, each edge by bisection, and an interval around each maximum of β_1
    /// that lies inside while its node does not (narrower than a cell, which the scan
    /// alone would miss).
    fn section(&self, k: f64) -> Vec<(f64, f64)> {
        let (zl, zh) = self.z;
        if k <= 0.0 {
            return alloc::vec![(zl, zh)];
        }
        let grid = &self.grid;
        let mut out = Vec::new();
        let mut prev_in = self.inside(k, grid[0].0, grid[0].1);
        let mut start = if prev_in { Some(zl) } else { None };
        for (i, g) in grid.iter().enumerate().skip(1) {
            let inside = self.inside(k, g.0, g.1);
            if inside != prev_in {
                let edge = self.edge(k, self.node(i - 1), self.node(i), prev_in);
                if inside {
                    start = Some(edge);
                } else if let Some(s) = start.take() {
                    out.push((s, edge));
                }
            }
            prev_in = inside;
        }
        if let Some(s) = start {
            out.push((s, zh));
        }
        // a section narrower than a cell around a maximum of β_1 the scan's nodes miss
        let mut added = false;
        for &(i, z, _, is_max) in &self.extrema {
            let at = |z: f64| self.inside(k, self.marginal(z), self.lambda * self.clutter.pdf(z));
            if is_max && !self.inside(k, grid[i].0, grid[i].1) && at(z) {
                let lo = self.edge(k, self.node(i - 1), z, false);
                let hi = self.edge(k, z, self.node(i + 1), true);
                out.push((lo, hi));
                added = true;
            }
        }
        if added {
            crate::math::sort::sort_by(&mut out, |a, b| a.0.total_cmp(&b.0));
        }
        out
    }

    /// The section's edge in [lo, hi] (within a scan cell or two) by bisection (m by
    /// quadrature), where lo's side is `left_in`.
    fn edge(&self, k: f64, lo: f64, hi: f64, left_in: bool) -> f64 {
        let (zl, zh) = self.z;
        bisect(
            |mid| {
                self.inside(k, self.marginal(mid), self.lambda * self.clutter.pdf(mid)) == left_in
            },
            lo,
            hi,
            1e-11 * (zh - zl),
            usize::MAX,
        )
    }

    /// The outer integrand at z_2: [w + null + A/(A_1/w_1), w, A, null] parts (each times c(z_2)).
    fn outer(&self, z2: f64, terms: &mut Vec<(f64, f64, f64)>) -> [f64; 4] {
        let c2 = self.clutter.pdf(z2);
        if c2 <= 0.0 {
            return [0.0; 4];
        }
        let v2 = self.lambda * c2;
        let k = self.k0 - self.rp * self.marginal(z2) / v2;
        let zone = self.section(k);
        let kept: f64 = zone.iter().map(|&(a, b)| self.clutter.mass(a, b)).sum();
        let null = c2 * (1.0 - kept).clamp(0.0, 1.0);
        if self.p <= 0.0 || zone.is_empty() {
            return [null, 0.0, 0.0, null];
        }
        let w = self.detected_mass(&zone);
        let a_sum = self.information(&zone, z2, terms);
        let a_part = c2 * a_sum / self.p;
        let w_part = c2 * w.clamp(0.0, 1.0);
        [w_part + null + a_part / self.scale_a, w_part, a_part, null]
    }

    /// ∫ f_d(x) ∫_{R(z_2)} g(z_1|x) dz_1 dx (= ∫_{R(z_2)} m, closed form in the
    /// linear-Gaussian case).
    fn detected_mass(&self, zone: &[(f64, f64)]) -> f64 {
        if let Some(lg) = &self.lg {
            return zone.iter().map(|&(a, b)| lg.marginal_mass(a, b)).sum();
        }
        let (prior, obs) = (self.prior, self.obs);
        adaptive(
            &mut |x| {
                let f = prior.pdf(x) * obs.detection(x);
                if f > 0.0 {
                    f * zone
                        .iter()
                        .map(|&(a, b)| obs.likelihood_mass(a, b, x))
                        .sum::<f64>()
                } else {
                    0.0
                }
            },
            self.x.0,
            self.x.1,
            8,
            self.inner,
        )
        .0 / self.p
    }

    /// P̄o times ∫_{R(z_2)} ∫ f_d(x) g(z_1|x) (−∂²_x ln p_2(x, z_1, z_2)) dx dz_1 (the
    /// x-integral in closed form in the linear-Gaussian case).
    fn information(&self, zone: &[(f64, f64)], z2: f64, terms: &mut Vec<(f64, f64, f64)>) -> f64 {
        if let Some(lg) = &self.lg {
            return self.p * lg.information(zone, z2, self.clutter, self.o, self.inner);
        }
        let (prior, obs, clutter) = (self.prior, self.obs, self.clutter);
        let (xl, xh) = self.x;
        let (ol, oh) = self.o;
        let mut a_sum = 0.0;
        // g(z_1|x) is negligible outside the observation's z range for x in the prior's
        // support, so the z_1 integral is cut to it.
        for &(a, b) in zone {
            let (a, b) = (a.max(ol), b.min(oh));
            a_sum += adaptive(
                &mut |z1| {
                    let (u, v) = obs.x_range(z1, xl, xh);
                    adaptive(
                        &mut |x| {
                            let f = prior.pdf(x) * obs.detection(x);
                            if f > 0.0 {
                                let g = obs.likelihood(z1, x);
                                if g > 0.0 {
                                    let z = [z1, z2];
                                    f * g * information_density(prior, obs, clutter, x, &z, terms)
                                } else {
                                    0.0
                                }
                            } else {
                                0.0
                            }
                        },
                        u,
                        v,
                        4,
                        self.inner,
                    )
                    .0
                },
                a,
                b,
                4,
                self.inner,
            )
            .0;
        }
        a_sum
    }
}

/// The linear-Gaussian case of measurement model II (22) of paper 002: the prior
/// f = N(μ, P), a constant P_o (so f_d = f), g(z|x) = N(z; a x + b, R); the clutter density c
/// is any. Its x-integrals in closed form: the marginal m(z) = ∫ f_d g (the m of Lemma 1's
/// β = m/v) is N(z; a μ + b, a² P + R), and f(x) g(z|x) = m(z) N(x; μ(z), s²) with
/// s² = (1/P + a²/R)⁻¹ and μ(z) = s² (μ/P + a (z − b)/R) (Bayes).
#[derive(Clone, Copy, Debug)]
pub(super) struct LinearGaussianCase {
    /// a, b and R of g.
    gain: f64,
    offset: f64,
    noise: f64,
    /// μ/P.
    mu_over_p: f64,
    /// 1/P + a²/R: the information density of p_1, and of p_2 where one point dominates S.
    j0: f64,
    /// The mean and variance of m.
    m_mean: f64,
    m_var: f64,
}

impl LinearGaussianCase {
    /// The case when the prior is Gaussian ([`Density::gaussian_form`]) and the observation
    /// linear-Gaussian with a constant P_o ([`Observation::linear_gaussian_form`]).
    pub(super) fn of(prior: &dyn Density, obs: &dyn Observation) -> Option<Self> {
        let (mu, var) = prior.gaussian_form()?;
        let (_, gain, offset, noise) = obs.linear_gaussian_form()?;
        let (m_mean, m_var) = linear_gaussian_marginal(prior, obs)?;
        Some(LinearGaussianCase {
            gain,
            offset,
            noise,
            mu_over_p: mu / var,
            j0: 1.0 / var + gain * gain / noise,
            m_mean,
            m_var,
        })
    }

    /// m(z) = N(z; a μ + b, a² P + R).
    fn marginal(&self, z: f64) -> f64 {
        normal_pdf(z, self.m_mean, self.m_var)
    }

    /// ∫_a^b m.
    fn marginal_mass(&self, a: f64, b: f64) -> f64 {
        normal_mass(a, b, self.m_mean, self.m_var)
    }

    /// ∫_{zone} ∫ f_d(x) g(z_1|x) (−∂²_x ln p_2(x, z_1, z_2)) dx dz_1 (25), with the
    /// x-integral in closed form. With S = t_1 + t_2, t_i = g(z_i|x)/c(z_i) (the x-dependence
    /// of p_2, NOTES.md's reading of (22)), l_i = ∂_x ln g(z_i|x) = a (z_i − a x − b)/R and
    /// π_i = t_i/S, −∂²_x ln p_2 = 1/P + a²/R − π_1 π_2 (l_1 − l_2)², where
    /// (l_1 − l_2)² = (a (z_1 − z_2)/R)² and π_1 π_2 = σ'(u) (σ' the logistic density) with
    /// u = ln(t_1/t_2) = ln(c(z_2)/c(z_1)) + (z_2 − z_1)((z_1 + z_2)/2 − a x − b)/R linear in
    /// x. Under f(x) g(z_1|x) = m(z_1) N(x; μ(z_1), s²), u ~ N(μ_u, s_u²) with
    /// μ_u = ln(c(z_2)/c(z_1)) + (z_2 − z_1)((z_1 + z_2)/2 − a μ(z_1) − b)/R and
    /// s_u = |a (z_2 − z_1)| s/R, so
    ///
    /// ```text
    /// ∫ f g (−∂²_x ln p_2) dx = m(z_1) [1/P + a²/R − (a (z_1 − z_2)/R)² E σ'(u)]
    /// ```
    ///
    /// The first part integrates over the zone by erfc; the second by adaptive G10/K21 over
    /// z_1 (cut to g's range `o`) to `inner` of the first, each E σ'(u) by [`logistic_normal`].
    /// Where c(z_1) = 0 the point z_1 alone makes S (as in `information_density`): no second
    /// part.
    fn information(
        &self,
        zone: &[(f64, f64)],
        z2: f64,
        clutter: &dyn Density,
        (ol, oh): (f64, f64),
        inner: f64,
    ) -> f64 {
        let base: f64 = self.j0
            * zone
                .iter()
                .map(|&(a, b)| self.marginal_mass(a, b))
                .sum::<f64>();
        if self.gain == 0.0 {
            return base;
        }
        let c2 = clutter.pdf(z2);
        let (a, r) = (self.gain, self.noise);
        let s2 = 1.0 / self.j0;
        let s = fns::sqrt(s2);
        let spread = |z1: f64| {
            let c1 = clutter.pdf(z1);
            let mz = self.marginal(z1);
            if c1 <= 0.0 || c2 <= 0.0 || mz <= 0.0 {
                return 0.0;
            }
            let d = z2 - z1;
            let mean_x = s2 * (self.mu_over_p + a * (z1 - self.offset) / r);
            let mu_u = fns::ln(c2 / c1) + d * (0.5 * (z1 + z2) - a * mean_x - self.offset) / r;
            let s_u = fns::abs(a * d) * s / r;
            let k2 = (a * d / r) * (a * d / r);
            // E σ'(u) to 0.1 inner J0/k²: the part's error is then below 0.1 inner of m J0
            mz * k2 * logistic_normal(mu_u, s_u, 0.1 * inner * self.j0 / k2)
        };
        let control = Control::new(
            Rule::G7K15,
            Tolerance::AbsoluteAboveNoise(inner * base),
            200,
        );
        let (cl, ch) = clutter.support();
        // beyond 10 standard deviations of m the part is below e^{−50} of it
        let reach = 10.0 * fns::sqrt(self.m_var);
        let (ml, mh) = (self.m_mean - reach, self.m_mean + reach);
        let mut correction = 0.0;
        for &(lo, hi) in zone {
            let (lo, hi) = (lo.max(ol).max(ml), hi.min(oh).min(mh));
            if hi <= lo {
                continue;
            }
            let pts = breakpoints(lo, hi, [cl, ch]);
            correction += integrate(spread, &pts, &control).value;
        }
        base - correction
    }
}

/// E σ'(u) for u ~ N(μ, s²), σ'(u) = σ(u)(1 − σ(u)) the logistic density, to about the
/// absolute tolerance `tol`: the product N(u; μ, s²) σ'(u) is log-concave, so it is
/// integrated by the trapezoidal rule (step [`SINH_STEP`]) after the substitution
/// u = u* + w sinh t, u* its mode and w = (1/s² + 2σ'(u*))^{−1/2} its curvature's scale (its
/// tails then fall double-exponentially in t); σ'(μ) when s is below 1e-9.
pub(super) fn logistic_normal(mu: f64, s: f64, tol: f64) -> f64 {
    let sp = logistic_density;
    if s < 1e-9 {
        return sp(mu);
    }
    // all of N but Φ(−9) < 2e-19 lies where σ' ≤ σ'(|μ| − 9 s)
    let gap = fns::abs(mu) - 9.0 * s;
    if gap > 0.0 && sp(gap) <= 0.5 * tol {
        return 0.0;
    }
    let s2 = s * s;
    // the mode: (u − μ)/s² = 1 − 2σ(u), increasing in u, root in [μ − s², μ + s²]
    let slope = |u: f64| {
        let e = fns::exp(-fns::abs(u));
        let sig = if u >= 0.0 {
            1.0 / (1.0 + e)
        } else {
            e / (1.0 + e)
        };
        (
            (u - mu) / s2 - (1.0 - 2.0 * sig),
            1.0 / s2 + 2.0 * e / ((1.0 + e) * (1.0 + e)),
        )
    };
    let (mut lo, mut hi) = (mu - s2, mu + s2);
    let mut u = crate::math::fns::clamp(mu / (1.0 + 0.5 * s2), lo, hi);
    for _ in 0..60 {
        let (f, d) = slope(u);
        if f > 0.0 {
            hi = u;
        } else {
            lo = u;
        }
        let next = u - f / d;
        let next = if next > lo && next < hi {
            next
        } else {
            0.5 * (lo + hi)
        };
        if fns::abs(next - u) <= 1e-6 * (1.0 + fns::abs(u)) {
            u = next;
            break;
        }
        u = next;
    }
    let w = 1.0 / fns::sqrt(slope(u).1);
    let norm = 1.0 / (s * fns::sqrt(2.0 * core::f64::consts::PI));
    // the term at t = k h from e^{t} (kept as powers of e^{±h})
    let term = |et: f64| {
        let ei = 1.0 / et;
        let x = u + 0.5 * w * (et - ei);
        let d = x - mu;
        norm * fns::exp(-0.5 * d * d / s2) * sp(x) * 0.5 * w * (et + ei)
    };
    let h = SINH_STEP;
    let mut sum = term(1.0);
    for step in [fns::exp(h), fns::exp(-h)] {
        let mut et = 1.0;
        for k in 1..=SINH_TERMS {
            et *= step;
            let v = term(et);
            sum += v;
            if h * v <= 1e-2 * tol && k >= 4 {
                break;
            }
        }
    }
    h * sum
}

/// The step of [`logistic_normal`]'s trapezoidal rule in t.
const SINH_STEP: f64 = 0.25;
/// At most this many steps each side.
const SINH_TERMS: usize = 40;

/// E σ'(u) for u ~ N(μ, s²), σ'(u) = σ(u)(1 − σ(u)) the logistic density, to the absolute
/// tolerance `tol`: adaptive G10/K21 over u where both factors are above e^{−40}
/// (|u − μ| ≤ 9 s and |u| ≤ 40), 0 when σ' is below `tol` there, σ'(μ) when s is below 1e-9.
/// The reference [`logistic_normal`] is tested against: adaptive G10/K21 to the absolute `tol`.
#[cfg(test)]
pub(super) fn logistic_normal_adaptive(mu: f64, s: f64, tol: f64) -> f64 {
    let sp = logistic_density;
    if s < 1e-9 {
        return sp(mu);
    }
    // adaptive G10/K21 where both factors are above e^{−40}, split along σ' and at μ
    let (lo, hi) = ((mu - 9.0 * s).max(-40.0), (mu + 9.0 * s).min(40.0));
    if hi <= lo {
        return 0.0;
    }
    let pts = breakpoints(lo, hi, [-8.0, -2.0, 0.0, 2.0, 8.0, mu]);
    let control = Control::new(Rule::G10K21, Tolerance::AbsoluteAboveNoise(tol), 400);
    integrate(|u| normal_pdf(u, mu, s * s) * sp(u), &pts, &control).value
}

/// The pieces of [lo, hi] split at the `cuts` strictly inside it, in increasing order (a cut
/// repeated or outside is skipped): the breakpoints of a piecewise quadrature.
fn breakpoints<const K: usize>(lo: f64, hi: f64, mut cuts: [f64; K]) -> Vec<f64> {
    crate::math::sort::sort_f64(&mut cuts);
    let mut pts = alloc::vec![lo];
    for t in cuts {
        if t > lo && t < hi && t > pts[pts.len() - 1] {
            pts.push(t);
        }
    }
    pts.push(hi);
    pts
}

/// σ'(u) = σ(u)(1 − σ(u)) = e^{−|u|}/(1 + e^{−|u|})², the logistic density (written with
/// e^{−|u|} so that it cannot overflow).
fn logistic_density(u: f64) -> f64 {
    let e = fns::exp(-fns::abs(u));
    e / ((1.0 + e) * (1.0 + e))
}
