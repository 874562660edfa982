//! The n = 2 terms of Theorem 2 (25) of paper 002 and the 2-point clutter rejection of η2 by
//! deterministic cubature over Z² (opt-in: [`TheoremOptions::quadrature_cardinality`] = 2), with
//! its own globally adaptive G10/K21 rule [`adaptive`] for the nested integrals.
//!
//! [`TheoremOptions::quadrature_cardinality`]: crate::bounds::TheoremOptions::quadrature_cardinality

use alloc::vec::Vec;

use super::{ModelII, Term, information_density};
use crate::bounds::model::{Density, Observation};
use crate::bounds::theorem::inverse_information;
use crate::math::fns;
use crate::math::optimise::bisect;
use crate::math::quadrature::{
    Control, Rule, Tolerance, integrate_equal_pieces as adaptive, integrate_vec,
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
/// adaptive G10/K21 on the sum w + null + A/A_1 (all ≥ 0), whose error estimate is given to
/// each; the inner ones add their relative tolerance.
pub(super) fn quadrature2(
    m: &ModelII<'_>,
    p: f64,
    scale_a: f64,
    z_range: (f64, f64),
    tol: f64,
) -> Term {
    let cub = Cubature::new(m, p, scale_a, z_range, tol);
    let mut terms = Vec::with_capacity(2);
    let (cl, ch) = m.clutter_density.support();
    let pts: Vec<f64> = (0..=8).map(|i| cl + (ch - cl) * i as f64 / 8.0).collect();
    let control = Control::new(
        Rule::G10K21,
        Tolerance::AbsoluteAboveNoise(2.0 * cub.inner),
        200,
    );
    let outer = integrate_vec(|z2| cub.outer(z2, &mut terms), &pts, &control);
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
    /// A_1, the unit of A_2 in the outer integrand.
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
}

impl<'a> Cubature<'a> {
    fn new(m: &ModelII<'a>, p: f64, scale_a: f64, z: (f64, f64), tol: f64) -> Self {
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
        };
        cub.grid = (0..=CELLS)
            .map(|i| {
                let z = cub.node(i);
                (cub.marginal(z), cub.lambda * cub.clutter.pdf(z))
            })
            .collect();
        cub
    }

    /// Node i of the scan.
    fn node(&self, i: usize) -> f64 {
        let (zl, zh) = self.z;
        zl + (zh - zl) * i as f64 / CELLS as f64
    }

    /// m(z) = ∫ f_d(x) g(z|x) dx by [`adaptive`].
    fn marginal(&self, z: f64) -> f64 {
        let p = self.p;
        if p <= 0.0 {
            return 0.0;
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

    /// The section {z_1 : r P̄o m(z_1) − K v(z_1) ≥ 0} as intervals.
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
                let edge = self.edge(k, i, prev_in);
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
        out
    }

    /// The section's edge in scan cell [i − 1, i] by bisection (m by quadrature), where the
    /// left node's side is `left_in`.
    fn edge(&self, k: f64, i: usize, left_in: bool) -> f64 {
        let (zl, zh) = self.z;
        bisect(
            |mid| {
                self.inside(k, self.marginal(mid), self.lambda * self.clutter.pdf(mid)) == left_in
            },
            self.node(i - 1),
            self.node(i),
            1e-11 * (zh - zl),
            usize::MAX,
        )
    }

    /// The outer integrand at z_2: [w + null + A/A_1, w, A, null] parts (each times c(z_2)).
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

    /// ∫ f_d(x) ∫_{R(z_2)} g(z_1|x) dz_1 dx.
    fn detected_mass(&self, zone: &[(f64, f64)]) -> f64 {
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

    /// P̄o times ∫_{R(z_2)} ∫ f_d(x) g(z_1|x) (−∂²_x ln p_2(x, z_1, z_2)) dx dz_1.
    fn information(&self, zone: &[(f64, f64)], z2: f64, terms: &mut Vec<(f64, f64, f64)>) -> f64 {
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
