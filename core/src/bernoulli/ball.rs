//! q(a) = P(‖x − a‖ > r0) for a Gaussian x ~ N(m, P): the mass of the rejection region (9)
//! of `000_…`, the integral in its eqs. (11)–(13).
//!
//! # Reduction
//! With P = U Λ Uᵀ (eigenvalues λ_1 ≤ … ≤ λ_d, s_j = √λ_j) and y = Uᵀ(x − a), the
//! coordinates y_j ~ N(μ_j, λ_j), μ = Uᵀ(m − a), are independent and ‖x − a‖ = ‖y‖: the
//! squared distance Σ_j y_j² = Σ_j λ_j (z_j + μ_j/s_j)² is a generalised noncentral
//! chi-square. q is computed as 1 − P(Σ_j y_j² ≤ r0²) by one of three methods:
//!
//! | d | method | error |
//! |---|---|---|
//! | 1 | `Φ((a − r0 − m)/s) + Φ((m − a − r0)/s)` through `erfc` | a few ulps, also relative |
//! | 2–4 | nested adaptive Gauss–Kronrod quadrature | QUADPACK estimate + rigorous truncation |
//! | ≥ 5 | Gil-Pelaez inversion, Davies' midpoint rule (see the [inversion module](super::inversion)) | rigorous bounds |
//!
//! # Nested quadrature (d = 2 … 4)
//!
//! ```text
//! 1 − q(a) = I_1(r0²),
//! I_d(ρ²)  = Φ((ρ − μ_d)/s_d) − Φ((−ρ − μ_d)/s_d)
//! I_k(ρ²)  = ∫_{−ρ}^{ρ} φ((y − μ_k)/s_k)/s_k · I_{k+1}(ρ² − y²) dy,        k < d
//! ```
//!
//! The innermost, widest coordinate is exact; each outer level is a globally adaptive
//! Gauss–Kronrod (G10/K21, QUADPACK's `qk21`) integral over
//! `[−ρ, ρ] ∩ [μ_k − 9 s_k, μ_k + 9 s_k]`, cut at the peak μ_k and at μ_k ± 3 s_k, with the
//! substitution `y = ±(ρ − v²)` on a piece that ends at the ball's edge ±ρ (it removes the
//! square-root singularity of `I_{k+1}(ρ² − y²)` there), and every `ρ² − y²` formed as the
//! product `(ρ − y)(ρ + y)` so that nothing cancels. Sorting the coordinates by increasing
//! s_k puts the narrowest Gaussian outermost, where the cuts resolve it.
//!
//! **Error.** A level spends `tol/2` on its own quadrature and `tol/4` on its inner calls:
//! an inner error ε(u) changes the outer integral by ∫ weight(u) ε(u) du, so the inner call
//! at node u gets `ε(u) = (tol/4)/(weight(u) · pieces)` — loose in the tails, tight at the
//! peak. The total is at most `tol` (default [`DEFAULT_TOLERANCE`] = 1e-10) plus the
//! truncation to ±9 s_k, which drops at most `erfc(9/√2) = 2.3e-19` per level (rigorous).
//! The quadrature part is QUADPACK's estimate `resasc · min(1, (200 |K21 − G10| / resasc)^1.5)`,
//! an estimate rather than a proof: it is reliable here because the integrands are
//! analytic on each piece once the edge singularity is removed, and every feature narrower
//! than a piece (the Gaussian's peak, the edges) sits at a breakpoint. In the tests the
//! actual errors are below 1e-15 against closed forms and below 1e-9 against brute-force
//! quadrature and against the inversion. A budget of 5·10⁶ innermost evaluations bounds
//! the time of a pathological case; when it is spent the returned
//! [`BallProbability::error`] grows to say so.
//!
//! **Shortcuts** (rigorous): with δ = ‖m − a‖, `1 − q ≤ P(χ²_d > (δ − r0)²/λ_max)` if
//! δ > r0 and `q ≤ P(χ²_d > (r0 − δ)²/λ_max)` if δ < r0; when the bound is below 1e-3 `tol`
//! the answer is 1 (or 0) without quadrature.
//!
//! **Cost.** About 21 · (pieces, 2–4) evaluations per level: d = 2 takes a few µs, d = 3
//! 0.1–1 ms, d = 4 a few to a few tens of ms; from d = 5 on the inversion (ms, falling with
//! d) is used instead.
//!
//! # Gradient
//! ∇_a q, for the MMUC search over mixtures, comes from the first moments
//! `M_j = E[(y_j − μ_j) 1{‖y‖ ≤ r0}]` (the score of N(μ_j, λ_j)): `∂q/∂a_i = Σ_j U_ij M_j/λ_j`,
//! integrated on the same nodes as q (d ≤ 4), in closed form in 1D, by central differences
//! for d ≥ 5.
//!
//! # Accuracy of the reduction
//! The eigen-decomposition is backward stable: with a covariance of condition number κ the
//! smallest eigenvalue carries a relative error of order κ·ε, which matters only for
//! near-singular covariances whose thin direction is comparable to r0.

use alloc::vec::Vec;
use core::cell::Cell;

use nalgebra::SymmetricEigen;

use crate::bernoulli::chi_square::chi_square_sf;
use crate::bernoulli::inversion;
use crate::error::{Error, Result};
use crate::gaussian::{Gaussian, normal};
use crate::math::fns;
use crate::math::quadrature::{Control, Estimate, Rule, Tolerance, integrate, integrate_vec};

/// The default absolute tolerance of [`BallProbability`] computations: 1e-10 (the contract
/// is 1e-9).
pub const DEFAULT_TOLERANCE: f64 = 1e-10;

/// Truncation of each level to μ ± 9 s: the dropped mass is erfc(9/√2) ≈ 2.26e-19.
const TRUNCATION_SIGMAS: f64 = 9.0;
const TRUNCATION_MASS: f64 = 2.26e-19;

/// From this dimension on, q is computed by characteristic-function inversion
/// (see the [inversion module](super::inversion)) instead of nested quadrature.
const INVERSION_MIN_DIM: usize = 5;

/// Term budget of the inversion (about 1 s natively in 5D); if it is not enough, the
/// error bound reports the shortfall.
const INVERSION_MAX_TERMS: usize = 1 << 22;

/// Subdivision budget of one adaptive level.
const MAX_PIECES: usize = 100;

/// q(a) with its error estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BallProbability {
    /// q(a) = P(‖x − a‖ > r0), in [0, 1].
    pub outside: f64,
    /// The estimated absolute error of `outside` (see the [module docs](self)).
    pub error: f64,
}

/// Which algorithm computes q in 2D and up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Method {
    /// Nested quadrature below [`INVERSION_MIN_DIM`], inversion from it on.
    Auto,
    /// Nested quadrature.
    #[cfg_attr(not(test), allow(dead_code))]
    Nested,
    /// Characteristic-function inversion (directions with λ_j = 0 to working precision are
    /// taken as deterministic; nested quadrature only if the inversion's bounds cannot be
    /// formed).
    #[cfg_attr(not(test), allow(dead_code))]
    Inversion,
}

/// A Gaussian prepared for ball probabilities: its covariance's eigen-decomposition, sorted
/// by increasing eigenvalue.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct GaussianBall {
    gaussian: Gaussian,
    /// √λ_j, increasing.
    sd: Vec<f64>,
    /// Row j is the unit eigenvector of λ_j.
    basis: Vec<Vec<f64>>,
}

impl GaussianBall {
    pub(crate) fn new(gaussian: Gaussian, what: &str) -> Result<Self> {
        let d = gaussian.dim();
        let (sd, basis) = if d == 1 {
            (
                alloc::vec![fns::sqrt(gaussian.cov()[(0, 0)])],
                alloc::vec![alloc::vec![1.0]],
            )
        } else {
            let eig = SymmetricEigen::try_new(gaussian.cov().clone(), f64::EPSILON, 100_000)
                // The Gaussian's P passed the checks of `covariance`: only a solver that
                // does not converge gets here (no eigenvalue to say).
                .ok_or_else(|| Error::NotDefinite {
                    what: alloc::format!("{what}.cov"),
                    smallest_eigenvalue: f64::NAN,
                    semidefinite: false,
                })?;
            let mut order: Vec<usize> = (0..d).collect();
            crate::math::sort::sort_by(&mut order, |&i, &j| {
                eig.eigenvalues[i].total_cmp(&eig.eigenvalues[j])
            });
            let sd = order
                .iter()
                .map(|&i| fns::sqrt(eig.eigenvalues[i].max(0.0)))
                .collect();
            let basis = order
                .iter()
                .map(|&i| eig.eigenvectors.column(i).iter().copied().collect())
                .collect();
            (sd, basis)
        };
        Ok(Self {
            gaussian,
            sd,
            basis,
        })
    }

    pub(crate) fn gaussian(&self) -> &Gaussian {
        &self.gaussian
    }

    pub(crate) fn dim(&self) -> usize {
        self.sd.len()
    }

    /// √λ_min.
    pub(crate) fn min_sd(&self) -> f64 {
        self.sd.first().copied().unwrap_or(0.0)
    }

    /// √λ_max.
    pub(crate) fn max_sd(&self) -> f64 {
        self.sd.last().copied().unwrap_or(0.0)
    }

    /// q(center) for the ball of radius `radius`. The caller has checked the dimension, the
    /// finiteness of `center` and `radius > 0`.
    pub(crate) fn outside(&self, center: &[f64], radius: f64, tol: f64) -> BallProbability {
        self.outside_by(center, radius, tol, Method::Auto)
    }

    /// [`outside`](Self::outside) that also draws on a work budget shared by a whole search
    /// (see [`Nested`]): its innermost evaluations, and d per inversion term, come out of
    /// `shared` as well as out of the call's own budget.
    pub(crate) fn outside_within(
        &self,
        center: &[f64],
        radius: f64,
        tol: f64,
        shared: &Cell<usize>,
    ) -> BallProbability {
        self.outside_in(center, radius, tol, Method::Auto, Some(shared))
    }

    /// q(center) in one dimension, in closed form: Φ(lo) + Q(hi) with lo, hi the standardised
    /// ends of the interval [center − radius, center + radius]; also returns lo and hi.
    fn outside_1d(&self, center: &[f64], radius: f64) -> (BallProbability, f64, f64) {
        let (mean, s) = (self.gaussian.mean()[0], self.sd[0]);
        let lo = (center[0] - radius - mean) / s;
        let hi = (center[0] + radius - mean) / s;
        let b = BallProbability {
            outside: normal::cdf(lo) + normal::sf(hi),
            error: 4.0 * f64::EPSILON,
        };
        (b, lo, hi)
    }

    /// q(center) and its gradient ∇_a q. With y = Uᵀ(x − a) and the first moments
    /// M_j = E[(y_j − μ_j) 1{‖y‖ ≤ r0}] (the score of N(μ_j, λ_j) gives ∂(1 − q)/∂μ_j =
    /// M_j/λ_j, and ∂μ/∂a = −Uᵀ):
    ///
    /// ```text
    /// ∂q/∂a_i = Σ_j U_ij M_j / λ_j
    /// ```
    ///
    /// computed on the nodes of the nested quadrature (d ≤ 4), in closed form in 1D, and by
    /// central differences otherwise.
    ///
    /// Its work comes out of the search's budget `shared` as well (see
    /// [`outside_within`](Self::outside_within)).
    pub(crate) fn outside_with_gradient(
        &self,
        center: &[f64],
        radius: f64,
        tol: f64,
        shared: &Cell<usize>,
    ) -> (BallProbability, Vec<f64>) {
        let d = self.dim();
        if d == 1 {
            let (b, lo, hi) = self.outside_1d(center, radius);
            let s = self.sd[0];
            return (b, alloc::vec![(normal::pdf(lo) - normal::pdf(hi)) / s]);
        }
        if d > GRAD_MAX_DIM || self.sd.iter().any(|&s| s <= 0.0) {
            let b = self.outside_within(center, radius, tol, shared);
            let h = 1e-6 * (radius + self.max_sd());
            let mut a = center.to_vec();
            let grad = (0..d)
                .map(|i| {
                    a[i] = center[i] + h;
                    let up = self.outside_within(&a, radius, 0.1 * tol, shared).outside;
                    a[i] = center[i] - h;
                    let down = self.outside_within(&a, radius, 0.1 * tol, shared).outside;
                    a[i] = center[i];
                    (up - down) / (2.0 * h)
                })
                .collect();
            return (b, grad);
        }
        if let Some(b) = self.shortcut(center, radius, tol) {
            return (b, alloc::vec![0.0; d]);
        }
        let mu = self.rotate(center);
        let (v, error) =
            Nested::new(&self.sd, &mu, Some(shared)).inside_grad(0, radius * radius, tol);
        let mut grad = alloc::vec![0.0; d];
        for (j, u) in self.basis.iter().enumerate() {
            let g = v[1 + j] / (self.sd[j] * self.sd[j]);
            for (gi, ui) in grad.iter_mut().zip(u) {
                *gi += ui * g;
            }
        }
        let b = BallProbability {
            outside: (1.0 - v[0]).clamp(0.0, 1.0),
            error: error + (d as f64) * TRUNCATION_MASS,
        };
        (b, grad)
    }

    /// The rigorous shortcuts of the module docs: q = 1 or q = 0 within 1e-3 `tol`.
    fn shortcut(&self, center: &[f64], radius: f64, tol: f64) -> Option<BallProbability> {
        let d = self.dim();
        let dist = fns::sqrt(dist2(self.gaussian.mean().as_slice(), center));
        let smax = self.max_sd();
        let limit = 1e-3 * tol;
        if dist > radius {
            let bound = chi_square_sf(d, sq((dist - radius) / smax));
            (bound <= limit).then_some(BallProbability {
                outside: 1.0,
                error: bound,
            })
        } else {
            let bound = chi_square_sf(d, sq((radius - dist) / smax));
            (bound <= limit).then_some(BallProbability {
                outside: 0.0,
                error: bound,
            })
        }
    }

    /// μ = Uᵀ(m − a), in the sorted eigenbasis.
    fn rotate(&self, center: &[f64]) -> Vec<f64> {
        let offset: Vec<f64> = self
            .gaussian
            .mean()
            .iter()
            .zip(center)
            .map(|(m, a)| m - a)
            .collect();
        self.basis
            .iter()
            .map(|u| u.iter().zip(&offset).map(|(ui, oi)| ui * oi).sum())
            .collect()
    }

    /// [`outside`](Self::outside) with the method forced (for cross-checks).
    pub(crate) fn outside_by(
        &self,
        center: &[f64],
        radius: f64,
        tol: f64,
        method: Method,
    ) -> BallProbability {
        self.outside_in(center, radius, tol, method, None)
    }

    /// [`outside_by`](Self::outside_by), drawing on a search's budget `shared` too if given.
    fn outside_in(
        &self,
        center: &[f64],
        radius: f64,
        tol: f64,
        method: Method,
        shared: Option<&Cell<usize>>,
    ) -> BallProbability {
        let d = self.dim();
        if d == 1 {
            return self.outside_1d(center, radius).0;
        }
        if let Some(b) = self.shortcut(center, radius, tol) {
            return b;
        }
        let mu = self.rotate(center);
        let use_inversion = match method {
            Method::Auto => d >= INVERSION_MIN_DIM,
            Method::Nested => false,
            Method::Inversion => true,
        };
        let inside = if use_inversion {
            // A direction with λ_j = 0 (to working precision) is deterministic, y_j = μ_j:
            // it moves μ_j² out of the budget r0².
            let mut t = radius * radius;
            let (mut lambda, mut mu_live) = (Vec::with_capacity(d), Vec::with_capacity(d));
            for (&s, &m) in self.sd.iter().zip(&mu) {
                if s > 0.0 {
                    lambda.push(s * s);
                    mu_live.push(m);
                } else {
                    t -= m * m;
                }
            }
            let mut max_terms = if method == Method::Inversion {
                1 << 26
            } else {
                INVERSION_MAX_TERMS
            };
            // A term costs about d innermost evaluations; at least 64 terms (the first
            // doubling step) so that a spent budget still returns an estimate, with its
            // error bound saying how good it is.
            if let Some(shared) = shared {
                max_terms = max_terms.min((shared.get() / d).max(64));
            }
            if lambda.is_empty() {
                Some(Estimate {
                    value: if t >= 0.0 { 1.0 } else { 0.0 },
                    error: 0.0,
                    pieces: 0,
                })
            } else {
                let estimate = inversion::cdf(&lambda, &mu_live, t, tol, max_terms);
                if let (Some(shared), Some(e)) = (shared, &estimate) {
                    shared.set(shared.get().saturating_sub(e.pieces.saturating_mul(d)));
                }
                estimate
            }
        } else {
            None
        };
        let inside = inside
            .unwrap_or_else(|| Nested::new(&self.sd, &mu, shared).inside(0, radius * radius, tol));
        BallProbability {
            outside: (1.0 - inside.value).clamp(0.0, 1.0),
            error: inside.error + (d as f64) * TRUNCATION_MASS,
        }
    }
}

/// ‖x − y‖², the squared distance of a point to a ball's centre.
pub(crate) fn dist2(x: &[f64], y: &[f64]) -> f64 {
    x.iter().zip(y).map(|(a, b)| (a - b) * (a - b)).sum()
}

fn sq(x: f64) -> f64 {
    x * x
}

/// The nested integral I_k of the module docs, coordinates sorted by increasing s_k.
struct Nested<'a> {
    sd: &'a [f64],
    mu: &'a [f64],
    /// Innermost evaluations left; when spent, no level subdivides further (the error
    /// estimate then reports the shortfall). Bounds the time of a pathological case.
    budget: Cell<usize>,
    /// The budget of a whole search (the MMUC search over a mixture evaluates q hundreds of
    /// times), spent alongside `budget`: a search of many costly evaluations stays bounded
    /// even when each one is within its own budget.
    shared: Option<&'a Cell<usize>>,
}

/// Innermost evaluations allowed to one nested computation (about 0.2 s natively).
const NESTED_BUDGET: usize = 5_000_000;

impl<'a> Nested<'a> {
    fn new(sd: &'a [f64], mu: &'a [f64], shared: Option<&'a Cell<usize>>) -> Self {
        Self {
            sd,
            mu,
            budget: Cell::new(NESTED_BUDGET),
            shared,
        }
    }

    fn spend(&self) {
        self.budget.set(self.budget.get().saturating_sub(1));
        if let Some(shared) = self.shared {
            shared.set(shared.get().saturating_sub(1));
        }
    }

    fn keep_going(&self) -> bool {
        self.budget.get() > 0 && self.shared.is_none_or(|s| s.get() > 0)
    }

    /// A level's quadrature: G10/K21 to `tol` (or 64 ε ∫|f|), at most [`MAX_PIECES`] pieces,
    /// while the evaluation budget lasts.
    fn control<'k>(&self, tol: f64, keep_going: &'k dyn Fn() -> bool) -> Control<'k> {
        Control {
            rule: Rule::G10K21,
            tolerance: Tolerance::AbsoluteAboveNoise(tol),
            max_pieces: MAX_PIECES,
            keep_going: Some(keep_going),
        }
    }
}

/// One piece of an outer level, parameterised by w ∈ [0, 1].
#[derive(Clone, Copy)]
enum Piece {
    /// t = t0 + (t1 − t0) w, t = y − μ.
    Interior { t0: f64, t1: f64 },
    /// y = −ρ + v², v = v_max w.
    LeftEdge { v_max: f64 },
    /// y = ρ − v², v = v_max w.
    RightEdge { v_max: f64 },
}

/// The outer levels' pieces over t = y − μ, for one ρ.
struct Level {
    pieces: [Option<Piece>; 5],
    count: usize,
    s: f64,
    rho: f64,
    /// t at y = −ρ and y = ρ.
    left_t: f64,
    right_t: f64,
    rho_plus_mu: f64,
}

impl Level {
    /// [−ρ − μ, ρ − μ] ∩ [−9s, 9s], cut at the peak and at ±3s (so that each piece sees a
    /// slowly varying part of the Gaussian); a piece that ends at the ball's edge gets the v²
    /// substitution. `None` when the intersection is empty.
    fn new(s: f64, mu: f64, rho: f64) -> Option<Self> {
        let left_t = -rho - mu;
        let right_t = rho - mu;
        let reach = TRUNCATION_SIGMAS * s;
        let left_edge = left_t >= -reach;
        let right_edge = right_t <= reach;
        let t_lo = if left_edge { left_t } else { -reach };
        let t_hi = if right_edge { right_t } else { reach };
        if t_lo >= t_hi {
            return None;
        }
        let mut cuts = [0.0; 6];
        let mut n_cuts = 0;
        cuts[n_cuts] = t_lo;
        n_cuts += 1;
        for c in [-3.0 * s, 0.0, 3.0 * s] {
            if t_lo < c && c < t_hi {
                cuts[n_cuts] = c;
                n_cuts += 1;
            }
        }
        if n_cuts == 1 && left_edge && right_edge {
            cuts[n_cuts] = 0.5 * (t_lo + t_hi);
            n_cuts += 1;
        }
        cuts[n_cuts] = t_hi;
        n_cuts += 1;
        let mut pieces: [Option<Piece>; 5] = [None; 5];
        for j in 0..n_cuts - 1 {
            let (a, b) = (cuts[j], cuts[j + 1]);
            pieces[j] = Some(if j == 0 && left_edge {
                Piece::LeftEdge {
                    v_max: fns::sqrt(b - left_t),
                }
            } else if j == n_cuts - 2 && right_edge {
                Piece::RightEdge {
                    v_max: fns::sqrt(right_t - a),
                }
            } else {
                Piece::Interior { t0: a, t1: b }
            });
        }
        Some(Self {
            pieces,
            count: n_cuts - 1,
            s,
            rho,
            left_t,
            right_t,
            rho_plus_mu: rho + mu,
        })
    }

    /// The parameter's breakpoints: piece j is u ∈ [j, j + 1].
    fn points(&self) -> &'static [f64] {
        const POINTS: [f64; 6] = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        &POINTS[..=self.count]
    }

    /// At parameter u: (t, weight = jacobian · φ(t/s)/s, ρ² − y²); `None` where the weight
    /// vanishes.
    fn at(&self, u: f64) -> Option<(f64, f64, f64)> {
        let j = (u as usize).min(self.count - 1);
        let w = u - j as f64;
        let piece = self.pieces[j]?;
        let (t, jac, rem) = match piece {
            Piece::Interior { t0, t1 } => {
                let t = t0 + (t1 - t0) * w;
                (t, t1 - t0, (self.right_t - t) * (self.rho_plus_mu + t))
            }
            Piece::LeftEdge { v_max } => {
                let v = v_max * w;
                let v2 = v * v;
                (
                    self.left_t + v2,
                    2.0 * v * v_max,
                    v2 * (2.0 * self.rho - v2),
                )
            }
            Piece::RightEdge { v_max } => {
                let v = v_max * w;
                let v2 = v * v;
                (
                    self.right_t - v2,
                    2.0 * v * v_max,
                    v2 * (2.0 * self.rho - v2),
                )
            }
        };
        let weight = jac * normal::pdf(t / self.s) / self.s;
        (weight != 0.0).then_some((t, weight, rem))
    }
}

/// Largest dimension for which [`Nested::inside_grad`] is used (its vectors have 1 + d
/// entries).
pub(crate) const GRAD_MAX_DIM: usize = 4;
const GRAD_LEN: usize = GRAD_MAX_DIM + 1;

impl Nested<'_> {
    fn inside(&self, k: usize, rho2: f64, tol: f64) -> Estimate {
        let zero = Estimate {
            value: 0.0,
            error: 0.0,
            pieces: 0,
        };
        if rho2.is_nan() || rho2 <= 0.0 {
            return zero;
        }
        let rho = fns::sqrt(rho2);
        let (s, mu) = (self.sd[k], self.mu[k]);
        let last = k + 1 == self.sd.len();
        if s == 0.0 {
            // A degenerate direction: y_k = μ_k.
            if fns::abs(mu) > rho {
                return zero;
            }
            if last {
                return Estimate {
                    value: 1.0,
                    error: 0.0,
                    pieces: 0,
                };
            }
            return self.inside(k + 1, (rho - mu) * (rho + mu), tol);
        }
        if last {
            self.spend();
            return Estimate {
                value: normal::interval((-rho - mu) / s, (rho - mu) / s),
                error: 4.0 * f64::EPSILON,
                pieces: 0,
            };
        }
        let Some(level) = Level::new(s, mu, rho) else {
            return zero;
        };
        // Inner tolerances: an inner error ε(u) changes this level's integral by
        // ∫ weight(u) ε(u) du, so ε(u) = (tol/4) / (weight(u) · count) keeps the total within
        // tol/4 while letting the tails, where the weight is small, be computed loosely.
        let inner_budget = 0.25 * tol / level.count as f64;
        let mut f = |u: f64| -> f64 {
            let Some((_, weight, rem)) = level.at(u) else {
                return 0.0;
            };
            let inner_tol = (inner_budget / weight).min(1.0);
            weight * self.inside(k + 1, rem, inner_tol).value
        };
        let own = integrate(
            &mut f,
            level.points(),
            &self.control(0.5 * tol, &|| self.keep_going()),
        );
        Estimate {
            value: own.value,
            error: own.error + 0.25 * tol + TRUNCATION_MASS,
            pieces: own.pieces,
        }
    }

    /// I_k(ρ²) and the first moments M_j = E[(y_j − μ_j) 1{Σ_{i≥k} y_i² ≤ ρ²} Π_{i<k}…] for
    /// j ≥ k: entry 0 is I_k, entry 1 + j is M_j (0 for j < k). Error control on I_k as in
    /// [`inside`](Self::inside); the moments ride along on the same nodes. Requires
    /// d ≤ [`GRAD_MAX_DIM`] and every s_j > 0.
    fn inside_grad(&self, k: usize, rho2: f64, tol: f64) -> ([f64; GRAD_LEN], f64) {
        let mut out = [0.0; GRAD_LEN];
        if rho2.is_nan() || rho2 <= 0.0 {
            return (out, 0.0);
        }
        let rho = fns::sqrt(rho2);
        let (s, mu) = (self.sd[k], self.mu[k]);
        if k + 1 == self.sd.len() {
            self.spend();
            let (a, b) = ((-rho - mu) / s, (rho - mu) / s);
            out[0] = normal::interval(a, b);
            // ∫_a^b s z φ(z) dz = s (φ(a) − φ(b))
            out[1 + k] = s * (normal::pdf(a) - normal::pdf(b));
            return (out, 4.0 * f64::EPSILON);
        }
        let Some(level) = Level::new(s, mu, rho) else {
            return (out, 0.0);
        };
        let inner_budget = 0.25 * tol / level.count as f64;
        let mut f = |u: f64| -> [f64; GRAD_LEN] {
            let mut v = [0.0; GRAD_LEN];
            let Some((t, weight, rem)) = level.at(u) else {
                return v;
            };
            let inner_tol = (inner_budget / weight).min(1.0);
            let (inner, _) = self.inside_grad(k + 1, rem, inner_tol);
            v[0] = weight * inner[0];
            v[1 + k] = weight * t * inner[0];
            for j in k + 1..self.sd.len() {
                v[1 + j] = weight * inner[1 + j];
            }
            v
        };
        let own = integrate_vec(
            &mut f,
            level.points(),
            &self.control(0.5 * tol, &|| self.keep_going()),
        );
        (own.value, own.error + 0.25 * tol + TRUNCATION_MASS)
    }
}
