//! The optimiser behind [`SplitLibrary::optimise`](super::SplitLibrary::optimise): damped
//! Newton with a backtracking line search on an unconstrained parametrisation of the
//! symmetric splits, from several deterministic starts.
//!
//! # Parametrisation
//! The R components are sorted by mean and grouped into `h = ⌈R/2⌉` weight classes from the
//! inside out: class 0 is the centre component (odd R) or the innermost pair (even R), class
//! c the c-th pair outward. With θ the unconstrained parameters,
//!
//! ```text
//! σ̃ = e^s
//! w̃ of class c = e^{u_c} / Σ_d mult_d e^{u_d}   (u_0 = 0; mult_d = 1 for a centre, 2 for a pair)
//! equal spacing: m̃_j = e^t (j − (R − 1)/2)
//! free means:    the q-th pair sits at ±μ_q, μ_q = Σ_{r ≤ q} e^{t_r}
//! ```
//!
//! so the weights are positive and sum to one, the means are symmetric (the split preserves
//! the mean exactly) and ordered, and σ̃ > 0, for every θ.

use alloc::vec;
use alloc::vec::Vec;

use nalgebra::{DMatrix, DVector};

use super::Spacing;
use super::objective::objective_with_gradient;
use crate::math::fns;

/// The parametrisation of symmetric R-component splits.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Layout {
    pub r: usize,
    pub spacing: Spacing,
}

impl Layout {
    /// ⌈R/2⌉ weight classes.
    fn classes(&self) -> usize {
        self.r.div_ceil(2)
    }

    fn odd(&self) -> bool {
        self.r % 2 == 1
    }

    /// Number of pairs ⌊R/2⌋.
    fn pairs(&self) -> usize {
        self.r / 2
    }

    fn mean_params(&self) -> usize {
        match self.spacing {
            Spacing::Equal => 1,
            Spacing::Free => self.pairs(),
        }
    }

    /// The number of unconstrained parameters.
    pub fn len(&self) -> usize {
        1 + self.mean_params() + self.classes() - 1
    }

    /// The class of component j (components sorted by mean).
    fn class_of(&self, j: usize) -> usize {
        let r = self.r;
        if self.odd() {
            let c = (r - 1) / 2;
            j.abs_diff(c)
        } else {
            let upper = r / 2;
            if j >= upper { j - upper } else { upper - 1 - j }
        }
    }

    /// Multiplicity of class c (1 for the centre of an odd split, 2 for a pair).
    fn mult(&self, c: usize) -> f64 {
        if self.odd() && c == 0 { 1.0 } else { 2.0 }
    }

    /// The pair index of class c, `None` for the centre.
    fn pair_of_class(&self, c: usize) -> Option<usize> {
        if self.odd() {
            c.checked_sub(1)
        } else {
            Some(c)
        }
    }

    /// (w̃, m̃, σ̃) of θ.
    pub fn unpack(&self, theta: &[f64]) -> (Vec<f64>, Vec<f64>, f64) {
        let sigma = fns::exp(theta[0]);
        let class_w = self.class_weights(theta);
        let r = self.r;
        let weights: Vec<f64> = (0..r).map(|j| class_w[self.class_of(j)]).collect();
        let pair_pos = self.pair_positions(theta);
        let means = (0..r).map(|j| self.mean_of(j, &pair_pos)).collect();
        (weights, means, sigma)
    }

    /// Positions μ_q > 0 of the pairs (the positive member), innermost first.
    fn pair_positions(&self, theta: &[f64]) -> Vec<f64> {
        let t = &theta[1..1 + self.mean_params()];
        match self.spacing {
            Spacing::Equal => {
                let delta = fns::exp(t[0]);
                (0..self.pairs())
                    .map(|q| {
                        if self.odd() {
                            delta * (q + 1) as f64
                        } else {
                            delta * (q as f64 + 0.5)
                        }
                    })
                    .collect()
            }
            Spacing::Free => {
                let mut acc = 0.0;
                t.iter()
                    .map(|&tq| {
                        acc += fns::exp(tq);
                        acc
                    })
                    .collect()
            }
        }
    }

    fn mean_of(&self, j: usize, pair_pos: &[f64]) -> f64 {
        let c = self.class_of(j);
        match self.pair_of_class(c) {
            None => 0.0,
            Some(q) => {
                let upper = self.r / 2 + usize::from(self.odd());
                if j >= upper {
                    pair_pos[q]
                } else {
                    -pair_pos[q]
                }
            }
        }
    }

    fn class_weights(&self, theta: &[f64]) -> Vec<f64> {
        let h = self.classes();
        let u0 = 1 + self.mean_params();
        let logit = |c: usize| if c == 0 { 0.0 } else { theta[u0 + c - 1] };
        let top = (0..h).map(logit).fold(f64::NEG_INFINITY, f64::max);
        let e: Vec<f64> = (0..h).map(|c| fns::exp(logit(c) - top)).collect();
        let z: f64 = (0..h).map(|c| self.mult(c) * e[c]).sum();
        e.iter().map(|x| x / z).collect()
    }

    /// J(θ) and ∇_θ J.
    pub fn value_grad(&self, theta: &[f64], lambda: f64) -> (f64, Vec<f64>) {
        let (w, m, sigma) = self.unpack(theta);
        let (value, g) = objective_with_gradient(&w, &m, sigma, lambda, true);
        let Some(g) = g else {
            return (value, vec![0.0; self.len()]);
        };
        let mut grad = vec![0.0; self.len()];
        grad[0] = g.sigma * sigma;
        // Means.
        let pair_pos = self.pair_positions(theta);
        let upper = self.r / 2 + usize::from(self.odd());
        // ∂J/∂μ_q: the positive member moves with μ_q, the negative against it.
        let mut g_pair = vec![0.0; self.pairs()];
        for j in 0..self.r {
            if let Some(q) = self.pair_of_class(self.class_of(j)) {
                g_pair[q] += if j >= upper { g.means[j] } else { -g.means[j] };
            }
        }
        let t = &theta[1..1 + self.mean_params()];
        match self.spacing {
            Spacing::Equal => {
                // μ_q = δ·c_q, ∂μ_q/∂t = μ_q.
                grad[1] = g_pair.iter().zip(&pair_pos).map(|(gq, mq)| gq * mq).sum();
            }
            Spacing::Free => {
                // μ_q = Σ_{r ≤ q} e^{t_r}: ∂J/∂t_r = e^{t_r} Σ_{q ≥ r} ∂J/∂μ_q.
                let mut tail = 0.0;
                for r in (0..self.pairs()).rev() {
                    tail += g_pair[r];
                    grad[1 + r] = fns::exp(t[r]) * tail;
                }
            }
        }
        // Weights: ∂J/∂u_d = ω_d G_d − mult_d ω_d Σ_c ω_c G_c with G_c = Σ_{j ∈ c} ∂J/∂w̃_j.
        let h = self.classes();
        let omega = self.class_weights(theta);
        let mut big_g = vec![0.0; h];
        for j in 0..self.r {
            big_g[self.class_of(j)] += g.weights[j];
        }
        let avg: f64 = (0..h).map(|c| omega[c] * big_g[c]).sum();
        let u0 = 1 + self.mean_params();
        for d in 1..h {
            grad[u0 + d - 1] = omega[d] * big_g[d] - self.mult(d) * omega[d] * avg;
        }
        (value, grad)
    }

    /// θ from a split (the inverse of [`Layout::unpack`] on symmetric splits of this
    /// layout; for [`Spacing::Equal`] the spacing is taken from the innermost pair).
    pub fn pack(&self, class_weights: &[f64], pair_positions: &[f64], sigma: f64) -> Vec<f64> {
        let mut theta = vec![fns::ln(sigma)];
        match self.spacing {
            Spacing::Equal => {
                let delta = if self.odd() {
                    pair_positions[0]
                } else {
                    2.0 * pair_positions[0]
                };
                theta.push(fns::ln(delta));
            }
            Spacing::Free => {
                let mut prev = 0.0;
                for &p in pair_positions {
                    theta.push(fns::ln((p - prev).max(1e-12)));
                    prev = p;
                }
            }
        }
        let w0 = class_weights[0].max(1e-300);
        for &wc in &class_weights[1..] {
            theta.push(fns::ln(wc.max(1e-300) / w0));
        }
        theta
    }
}

/// Result of one optimisation.
pub(crate) struct Optimum {
    pub theta: Vec<f64>,
    pub value: f64,
}

/// Largest step (in θ) of one Newton iteration.
const MAX_STEP: f64 = 2.0;
/// Iteration cap per start.
const MAX_ITER: usize = 300;

/// Damped Newton from `theta0` with a finite-difference Hessian of the analytic gradient.
pub(crate) fn newton(layout: &Layout, lambda: f64, theta0: Vec<f64>) -> Optimum {
    let n = layout.len();
    let mut theta = theta0;
    let (mut value, mut grad) = layout.value_grad(&theta, lambda);
    for _ in 0..MAX_ITER {
        let gnorm = grad.iter().fold(0.0f64, |a, g| a.max(fns::abs(*g)));
        if !value.is_finite() || gnorm < 1e-15 {
            break;
        }
        // Hessian by central differences of the gradient.
        let mut hess = DMatrix::<f64>::zeros(n, n);
        for k in 0..n {
            let h = 1e-5 * (1.0 + fns::abs(theta[k]));
            let mut tp = theta.clone();
            tp[k] += h;
            let mut tm = theta.clone();
            tm[k] -= h;
            let (_, gp) = layout.value_grad(&tp, lambda);
            let (_, gm) = layout.value_grad(&tm, lambda);
            for i in 0..n {
                hess[(i, k)] = (gp[i] - gm[i]) / (2.0 * h);
            }
        }
        let hess = (&hess + hess.transpose()) * 0.5;
        let g = DVector::from_column_slice(&grad);
        // Levenberg damping until the system is positive definite.
        let scale = (0..n).fold(0.0f64, |a, i| a.max(fns::abs(hess[(i, i)])));
        let mut mu = 0.0;
        let step = loop {
            let mut damped = hess.clone();
            for i in 0..n {
                damped[(i, i)] += mu;
            }
            if let Some(ch) = damped.cholesky() {
                break Some(-ch.solve(&g));
            }
            mu = if mu == 0.0 {
                1e-10 * scale.max(1e-12)
            } else {
                mu * 10.0
            };
            if mu > 1e20 * scale.max(1e-12) {
                break None;
            }
        };
        let Some(mut step) = step else { break };
        let len = step.amax();
        if len > MAX_STEP {
            step *= MAX_STEP / len;
        }
        let slope = g.dot(&step);
        if slope >= 0.0 {
            break;
        }
        let gnorm2: f64 = grad.iter().map(|x| x * x).sum();
        let mut alpha = 1.0;
        let mut accepted = false;
        for _ in 0..60 {
            let trial: Vec<f64> = theta
                .iter()
                .zip(step.iter())
                .map(|(t, s)| t + alpha * s)
                .collect();
            let (v, gr) = layout.value_grad(&trial, lambda);
            let armijo = v <= value + 1e-4 * alpha * slope;
            // At the rounding floor of J (|predicted decrease| ~ 1e-17), accept a step that
            // reduces the gradient instead: J can no longer see the progress.
            let floor = -alpha * slope < 1e-14 && gr.iter().map(|x| x * x).sum::<f64>() < gnorm2;
            if v.is_finite() && (armijo || floor) {
                theta = trial;
                value = v;
                grad = gr;
                accepted = true;
                break;
            }
            alpha *= 0.5;
        }
        if !accepted {
            break;
        }
    }
    Optimum { theta, value }
}
