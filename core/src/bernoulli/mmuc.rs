//! The minimum mean uniform cost (MMUC) estimate, eq. (12) of `000_…`:
//! a* = argmin_a q(a), the centre of the ball of radius r0 holding the most probability.

use alloc::vec::Vec;
use core::cell::Cell;

use crate::bernoulli::ball::{DEFAULT_TOLERANCE, GaussianBall, dist2};
use crate::bernoulli::density::{
    ParticleSet, Repr, SpatialDensity, mixture_outside, mixture_outside_in,
};
use crate::bernoulli::loss::check_radius;
use crate::error::Result;
use crate::math::fns;
use crate::math::geometry::{self, circumcentre, smallest_enclosing_ball};
use crate::math::optimise::{BfgsOptions, Minimum, bfgs};
use crate::math::sum::NeumaierSum;

/// How the MMUC search ([`SpatialDensity::mmuc`]) found a*, in kebab case: `"gaussian-mean"`, ….
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "kebab-case"))]
pub enum MmucMethod {
    /// The mean of a Gaussian: exact by Sherman's theorem (a symmetric unimodal density and
    /// a symmetric convex set: the ball holds the most mass when centred at the mean).
    GaussianMean,
    /// The common mean of a mixture whose components all share it: exact, by Sherman's
    /// theorem applied to each component (each q_j is minimised there, hence their sum).
    SharedMean,
    /// A multi-start local search over a mixture (see [`SpatialDensity::mmuc`]): the best of
    /// the local optima found; a global optimum in every case tested, not a proof.
    MixtureSearch,
    /// An exhaustive search over particles: exact.
    ParticlesExact,
    /// A local search over particles, used when exhaustive search would take too long (d ≥ 3
    /// and many close particles): a heuristic.
    ParticlesHeuristic,
}

/// The MMUC estimate a* and q(a*).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Mmuc {
    /// The MMUC point a*: the centre of the radius-r0 ball most likely to hold the object.
    pub center: Vec<f64>,
    /// q(a*) = ∫ 1{‖x − a*‖ > r0} s(dx), computed exactly as
    /// [`SpatialDensity::prob_outside_ball`] computes it (same tolerance, same value).
    pub miss_probability: f64,
    /// The error estimate of `miss_probability` (0 for particles).
    pub error: f64,
    /// How a* was found (exact or heuristic).
    pub method: MmucMethod,
}

/// The most mixture components the MMUC search of [`SpatialDensity::mmuc`] is offered
/// through [`SpatialDensity::check_mmuc_size`]: the search runs a local optimisation from
/// every component mean, each step costing a quadrature per component (O(L²) quadratures;
/// 10,000 components took minutes).
pub const MAX_MMUC_COMPONENTS: usize = 100;

/// The most particles in 2 or more dimensions [`SpatialDensity::check_mmuc_size`] accepts:
/// the 2D sweep visits every pair of particles within 2 r0 (O(n² log n) when all are close),
/// and the 3D search every close subset (1500 particles all within 2 r0: about 1 s in Node).
/// 1D particles (a sort and a sweep) have no cap.
pub const MAX_MMUC_PARTICLES: usize = 1_500;

/// The options of the MMUC estimate ([`MmucOptions::estimate`]): a spatial density and the
/// radius r0 of the ball of eq. (12) of `000_…`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MmucOptions {
    /// The spatial density of the object's state: at most 100 components and at most 1,500
    /// particles in 2 or more dimensions ([`SpatialDensity::check_mmuc_size`]).
    pub density: SpatialDensity,
    /// The radius r0 > 0 of the ball whose miss probability q(a) is minimised, in state units.
    pub radius: f64,
}

impl MmucOptions {
    /// The MMUC estimate a* = argmin_a q(a) (eq. (12) of `000_…`) of `density`
    /// ([`SpatialDensity::mmuc`]), within the search's size caps.
    ///
    /// # Errors
    /// [`Error::Count`](crate::Error::Count) naming `density.mixture` or `density.particles`
    /// beyond the caps of [`SpatialDensity::check_mmuc_size`]; as [`SpatialDensity::mmuc`]
    /// (`radius`).
    pub fn estimate(&self) -> Result<MmucEstimate> {
        self.density.check_mmuc_size()?;
        self.density
            .mmuc(self.radius)
            .map(|m| MmucEstimate::from(&m))
    }
}

/// The options of the miss probability q(a) of the loss (7) of `000_…`
/// ([`ProbabilityOutsideBallOptions::probability`]): a spatial density and a ball.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ProbabilityOutsideBallOptions {
    /// The spatial density of the object's state.
    pub density: SpatialDensity,
    /// The ball's centre (the density's dimension).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::numbers"))]
    pub center: Vec<f64>,
    /// The ball's radius, > 0, in state units.
    pub radius: f64,
}

impl ProbabilityOutsideBallOptions {
    /// q(`center`) = P(‖x − `center`‖ > `radius`) for x drawn from `density`
    /// ([`SpatialDensity::prob_outside_ball`]).
    ///
    /// # Errors
    /// As [`SpatialDensity::prob_outside_ball`] (`center`, `center[i]`, `radius`).
    pub fn probability(&self) -> Result<f64> {
        self.density.prob_outside_ball(&self.center, self.radius)
    }
}

/// The MMUC point a* (12) of `000_…`, its miss probability and how it was found: a [`Mmuc`]
/// without the quadrature's error estimate.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MmucEstimate {
    /// The MMUC point a*: the centre of the radius-r0 ball most likely to hold the object.
    pub center: Vec<f64>,
    /// The miss probability q(a*) ∈ [0, 1]: the probability that the object lies outside the
    /// radius-r0 ball about a*.
    pub miss_probability: f64,
    /// How a* was found (exact or heuristic).
    pub method: MmucMethod,
}

impl From<&Mmuc> for MmucEstimate {
    fn from(m: &Mmuc) -> Self {
        MmucEstimate {
            center: m.center.clone(),
            miss_probability: m.miss_probability,
            method: m.method,
        }
    }
}

impl SpatialDensity {
    /// `Ok` if [`SpatialDensity::mmuc`] on this density stays within its size caps: at most
    /// [`MAX_MMUC_COMPONENTS`] mixture components, and at most [`MAX_MMUC_PARTICLES`]
    /// particles in 2 or more dimensions (a Gaussian and 1D particles always pass).
    ///
    /// # Errors
    /// [`Error::Count`](crate::Error::Count) naming `density.mixture` or `density.particles`.
    pub fn check_mmuc_size(&self) -> Result<()> {
        match self.repr() {
            Repr::Gaussian(_) => Ok(()),
            Repr::Mixture { components, .. } => crate::Error::check_count(
                "density.mixture",
                "components",
                components.len(),
                1,
                MAX_MMUC_COMPONENTS,
            ),
            Repr::Particles(p) if p.dim() >= 2 => crate::Error::check_count(
                "density.particles",
                "particles in 2 or more dimensions",
                p.len(),
                1,
                MAX_MMUC_PARTICLES,
            ),
            Repr::Particles(_) => Ok(()),
        }
    }

    /// The MMUC estimate of eq. (12) of `000_…`, the a that minimises q(a) for this
    /// density and tolerance radius r0 (`radius`):
    ///
    /// ```text
    /// a* = argmin_a ∫ 1{‖x − a‖ > r0} s(dx)
    /// ```
    ///
    /// - **Gaussian**: the mean (Sherman's theorem: S. Sherman, "A theorem on convex sets
    ///   with applications," Ann. Math. Statist. 26(4):763–767, 1955; also T. W. Anderson,
    ///   Proc. AMS 6(2):170–176, 1955).
    /// - **Mixture**: the common mean if every component has it (exact, as above). Otherwise
    ///   a global search: BFGS with an Armijo line search on q, with the analytic gradient
    ///   `∂q/∂a = Σ_j w_j U_j M_j/λ_j` of each component (first moments over the ball, computed
    ///   on the quadrature's nodes; see `ball`), from every component mean, the mixture mean,
    ///   and the weighted midpoint of every pair of components close enough to share a ball
    ///   (≤ 2 r0 + 6(σ_i + σ_j) apart) when that midpoint beats both means — this finds optima
    ///   that lie between modes — each run to steps below 1e-7 of the smallest length scale
    ///   min(r0, σ_min); the best is kept. A local search cannot prove a global optimum; the
    ///   tests compare it with dense grid searches.
    ///   The whole search spends at most [`MMUC_SEARCH_BUDGET`] evaluations; when they are
    ///   spent it returns the best centre found so far, with q at it computed in full.
    /// - **Particles**: exact in any dimension with the weight covered by a closed ball
    ///   (particles at exactly r0 are inside, as in (9)). 1D: a sweep over the sorted
    ///   particles (an optimal interval can start at a particle), O(n log n). 2D: an optimal
    ///   disc can be moved until a particle lies on its boundary, so an angular sweep of the
    ///   disc centres on the circle of radius r0 about each particle finds it, O(n² log n).
    ///   d ≥ 3: the lowest point (in a fixed generic direction) of the set of centres covering
    ///   an optimal subset lies on the spheres of at most d particles, so enumerating the
    ///   centres defined by every set of ≤ d mutually close particles finds it; when that
    ///   would exceed ~2·10⁷ candidate checks a mean-shift local search from a subsample of
    ///   particles is used instead ([`MmucMethod::ParticlesHeuristic`]). In every case the
    ///   returned centre is then moved to the centre of the smallest ball enclosing the
    ///   covered particles (Welzl), which keeps them inside with the largest margin.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) naming `radius` unless
    /// finite and > 0.
    pub fn mmuc(&self, radius: f64) -> Result<Mmuc> {
        check_radius(radius)?;
        Ok(match self.repr() {
            Repr::Gaussian(g) => {
                let center: Vec<f64> = g.gaussian().mean().iter().copied().collect();
                let b = g.outside(&center, radius, DEFAULT_TOLERANCE);
                Mmuc {
                    center,
                    miss_probability: b.outside,
                    error: b.error,
                    method: MmucMethod::GaussianMean,
                }
            }
            Repr::Mixture { components, mean } => mixture_mmuc(components, mean, radius),
            Repr::Particles(p) => particle_mmuc(p, radius),
        })
    }
}

// ---------------------------------------------------------------------------------------
// Mixtures
// ---------------------------------------------------------------------------------------

/// Tolerance on q during the search.
const SEARCH_TOLERANCE: f64 = 1e-10;

/// Work allowed to one MMUC search over a mixture, in innermost evaluations of q (one per
/// component per evaluation at least; a nested-quadrature evaluation spends one per node of
/// its innermost level, an inversion d per term): about 0.5 s natively. Each evaluation of q
/// has its own budget as well, but a search evaluates q hundreds of times (a starting point
/// per component mean and per promising midpoint, up to 200 BFGS steps from each, and up to
/// 60 halvings per step), so a mixture whose components are each slow to integrate (one
/// nearly degenerate covariance made a 3-D search take 2.6 s in Node) needs a bound on the
/// whole. When it is spent the search stops with the best centre found so far, and q at that
/// centre is still computed in full (its own budget).
pub const MMUC_SEARCH_BUDGET: usize = 10_000_000;

fn mixture_mmuc(components: &[(f64, GaussianBall)], mean: &[f64], radius: f64) -> Mmuc {
    mixture_mmuc_within(components, mean, radius, MMUC_SEARCH_BUDGET).0
}

/// [`mixture_mmuc`] with a search budget of `search_budget` units; also returns the units
/// spent.
pub(crate) fn mixture_mmuc_within(
    components: &[(f64, GaussianBall)],
    mean: &[f64],
    radius: f64,
    search_budget: usize,
) -> (Mmuc, usize) {
    let finish = |center: Vec<f64>, method: MmucMethod| {
        let b = mixture_outside(components, &center, radius, DEFAULT_TOLERANCE);
        Mmuc {
            center,
            miss_probability: b.outside,
            error: b.error,
            method,
        }
    };
    let live: Vec<&(f64, GaussianBall)> = components.iter().filter(|(w, _)| *w > 0.0).collect();
    let means: Vec<Vec<f64>> = live
        .iter()
        .map(|(_, g)| g.gaussian().mean().iter().copied().collect())
        .collect();
    if let Some(first) = means.first()
        && means.iter().all(|m| m == first)
    {
        return (finish(first.clone(), MmucMethod::SharedMean), 0);
    }
    // The smallest length scale on which q(a) can change, floored at 1e-6 r0: a component
    // far narrower than the ball is a point mass for q (a step at the ball's edge that no
    // local search resolves), and resolving the centre below 1e-13 r0 only multiplies the
    // line-search halvings (a 1e-75-wide component once made one estimate take 15 s).
    let min_sd = live
        .iter()
        .map(|(_, g)| g.min_sd())
        .fold(f64::INFINITY, f64::min);
    let length = radius.min(min_sd).max(1e-6 * radius).max(f64::MIN_POSITIVE);
    let typical_sd = live.iter().map(|(w, g)| w * g.max_sd()).sum::<f64>();
    let step = 0.25 * (radius + typical_sd);
    let budget = Cell::new(search_budget);
    let q_start =
        |a: &[f64]| mixture_outside_in(components, a, radius, 1e-8, Some(&budget)).outside;

    // Starts: every component mean, the mixture mean, promising midpoints.
    let mut starts: Vec<Vec<f64>> = Vec::new();
    let push_unique = |starts: &mut Vec<Vec<f64>>, x: Vec<f64>| {
        if !starts.iter().any(|s| s == &x) {
            starts.push(x);
        }
    };
    for m in &means {
        push_unique(&mut starts, m.clone());
    }
    push_unique(&mut starts, mean.to_vec());
    let at_means: Vec<f64> = means.iter().map(|m| q_start(m)).collect();
    if live.len() <= 40 {
        for i in 0..live.len() {
            for j in i + 1..live.len() {
                if budget.get() == 0 {
                    break;
                }
                let (wi, gi) = live[i];
                let (wj, gj) = live[j];
                let reach = 2.0 * radius + 6.0 * (gi.max_sd() + gj.max_sd());
                if dist2(&means[i], &means[j]) > reach * reach {
                    continue;
                }
                let mid: Vec<f64> = means[i]
                    .iter()
                    .zip(&means[j])
                    .map(|(a, b)| (wi * a + wj * b) / (wi + wj))
                    .collect();
                if q_start(&mid) < at_means[i].min(at_means[j]) {
                    push_unique(&mut starts, mid);
                }
            }
        }
    }

    let opts = BfgsOptions {
        step,
        xtol: 1e-7 * length,
        max_iter: 200,
    };
    // Once the budget is spent every evaluation is +∞ (no step is accepted, so the BFGS run
    // in progress ends, and a later start ends at once).
    let mut q_grad = |a: &[f64]| {
        if budget.get() == 0 {
            return (f64::INFINITY, alloc::vec![0.0; a.len()]);
        }
        mixture_outside_with_gradient(components, a, radius, SEARCH_TOLERANCE, &budget)
    };
    let mut best: Option<(f64, Vec<f64>)> = None;
    for x0 in &starts {
        let Minimum { x, value: fx, .. } = bfgs(&mut q_grad, x0, &opts);
        if best.as_ref().is_none_or(|b| fx < b.0) {
            best = Some((fx, x));
        }
    }
    let center = best.map_or_else(|| mean.to_vec(), |b| b.1);
    let spent = search_budget - budget.get();
    (finish(center, MmucMethod::MixtureSearch), spent)
}

/// Σ_j w_j q_j(a) and its gradient, drawing on the search's `budget` (at least one unit per
/// component).
fn mixture_outside_with_gradient(
    components: &[(f64, GaussianBall)],
    center: &[f64],
    radius: f64,
    tol: f64,
    budget: &Cell<usize>,
) -> (f64, Vec<f64>) {
    let mut value = NeumaierSum::new();
    let mut grad = alloc::vec![0.0; center.len()];
    for (w, g) in components {
        if *w == 0.0 {
            continue;
        }
        budget.set(budget.get().saturating_sub(1));
        let (b, gj) = g.outside_with_gradient(center, radius, tol, budget);
        value.add(w * b.outside);
        for (a, x) in grad.iter_mut().zip(&gj) {
            *a += w * x;
        }
    }
    (value.total(), grad)
}

// ---------------------------------------------------------------------------------------
// Particles
// ---------------------------------------------------------------------------------------

/// Relative slack with which a particle counts as covered while searching (the final count
/// uses the exact test at the returned centre).
const COVER_SLACK: f64 = 1e-9;

/// Candidate checks (candidates × particles) allowed to the exhaustive search in d ≥ 3.
const EXHAUSTIVE_BUDGET: usize = 20_000_000;

/// Radii up to this (2^400 ≈ 2.6e120) are searched as given; beyond it the squared lengths of
/// the search (4 r0², ‖x_i − x_j‖² of covered particles) overflow (∞ − ∞ = NaN in the centres),
/// so the particles and r0 are first scaled by a power of two (exact) that brings r0 into
/// [1/2, 1), and the centre is scaled back: the MMUC problem is equivariant under scaling.
const HUGE_RADIUS: f64 = 2.582_249_878_086_908_6e120;

fn particle_mmuc(p: &ParticleSet, radius: f64) -> Mmuc {
    if radius > HUGE_RADIUS {
        let (_, e) = libm::frexp(radius);
        let scaled = p.scaled(-e);
        let mut m = particle_mmuc_as_given(&scaled, libm::scalbn(radius, -e));
        for c in &mut m.center {
            *c = libm::scalbn(*c, e);
        }
        return m;
    }
    particle_mmuc_as_given(p, radius)
}

fn particle_mmuc_as_given(p: &ParticleSet, radius: f64) -> Mmuc {
    let (candidate, method) = match p.dim() {
        1 => (sweep_1d(p, radius), MmucMethod::ParticlesExact),
        2 => (sweep_2d(p, radius), MmucMethod::ParticlesExact),
        _ => match enumerate_centres(p, radius) {
            Some(c) => (c, MmucMethod::ParticlesExact),
            None => (mean_shift_search(p, radius), MmucMethod::ParticlesHeuristic),
        },
    };
    // Re-centre on the smallest ball enclosing what the candidate covers.
    let slack = radius * (1.0 + COVER_SLACK);
    let covered: Vec<&[f64]> = (0..p.len())
        .filter(|&i| p.weights()[i] > 0.0 && dist2(p.point(i), &candidate) <= slack * slack)
        .map(|i| p.point(i))
        .collect();
    let mut center = candidate;
    let mut q = p.outside(&center, radius);
    if let Some((c, _)) = smallest_enclosing_ball(&covered) {
        let qc = p.outside(&c, radius);
        if qc <= q {
            center = c;
            q = qc;
        }
    }
    Mmuc {
        center,
        miss_probability: q,
        error: 0.0,
        method,
    }
}

/// Weight within the closed ball (with the search slack).
fn covered_weight(p: &ParticleSet, center: &[f64], radius: f64) -> f64 {
    let r = radius * (1.0 + COVER_SLACK);
    let r2 = r * r;
    (0..p.len())
        .filter(|&i| dist2(p.point(i), center) <= r2)
        .map(|i| p.weights()[i])
        .sum()
}

/// 1D: the best interval [x_i, x_j] with x_j − x_i ≤ 2 r0, centred at its midpoint.
fn sweep_1d(p: &ParticleSet, radius: f64) -> Vec<f64> {
    let mut xs: Vec<(f64, f64)> = (0..p.len())
        .map(|i| (p.point(i)[0], p.weights()[i]))
        .collect();
    crate::math::sort::sort_by(&mut xs, |a, b| a.0.total_cmp(&b.0));
    let width = 2.0 * radius;
    let (mut best, mut best_c) = (-1.0, xs[0].0);
    let mut j = 0;
    let mut window = 0.0;
    for i in 0..xs.len() {
        if j < i {
            j = i;
            window = 0.0;
        }
        if j == i {
            window = xs[i].1;
            j = i + 1;
        }
        while j < xs.len() && xs[j].0 - xs[i].0 <= width {
            window += xs[j].1;
            j += 1;
        }
        if window > best {
            best = window;
            best_c = 0.5 * (xs[i].0 + xs[j - 1].0);
        }
        window -= xs[i].1;
    }
    alloc::vec![best_c]
}

/// 2D: for each particle i, the centres c = x_i + r0 (cos θ, sin θ) of discs with x_i on
/// their boundary; particle j is covered for θ in an arc of half-width acos(d_ij / 2r0)
/// about the direction of x_j. A sweep over the arcs' ends finds the best θ.
fn sweep_2d(p: &ParticleSet, radius: f64) -> Vec<f64> {
    let n = p.len();
    let two_pi = 2.0 * core::f64::consts::PI;
    let reach2 = 4.0 * radius * radius * (1.0 + COVER_SLACK);
    // Sort by x so that only particles within 2 r0 in x are visited.
    let mut order: Vec<usize> = (0..n).collect();
    crate::math::sort::sort_by(&mut order, |&a, &b| p.point(a)[0].total_cmp(&p.point(b)[0]));
    let xs: Vec<f64> = order.iter().map(|&i| p.point(i)[0]).collect();
    let mut best = -1.0;
    let mut best_center = p.point(order[0]).to_vec();
    let mut events: Vec<(f64, f64)> = Vec::new();
    for (oi, &i) in order.iter().enumerate() {
        let xi = p.point(i);
        let mut base = p.weights()[i];
        let mut wrapped = 0.0;
        events.clear();
        let lo = xs.partition_point(|&x| x < xi[0] - 2.0 * radius);
        for (oj, &j) in order.iter().enumerate().skip(lo) {
            if xs[oj] > xi[0] + 2.0 * radius {
                break;
            }
            if oj == oi {
                continue;
            }
            let xj = p.point(j);
            let w = p.weights()[j];
            let d2 = dist2(xi, xj);
            if d2 > reach2 || w == 0.0 {
                continue;
            }
            if d2 == 0.0 {
                base += w;
                continue;
            }
            let d = fns::sqrt(d2);
            let alpha = fns::atan2(xj[1] - xi[1], xj[0] - xi[0]);
            let beta = fns::acos((d / (2.0 * radius)).min(1.0));
            let mut s = alpha - beta;
            while s < 0.0 {
                s += two_pi;
            }
            while s >= two_pi {
                s -= two_pi;
            }
            let e = s + 2.0 * beta;
            if e > two_pi {
                wrapped += w;
                events.push((e - two_pi, -w));
                events.push((s, w));
            } else {
                events.push((s, w));
                events.push((e, -w));
            }
        }
        // Arc starts before ends at equal angles: arcs are closed.
        crate::math::sort::sort_copy_by(&mut events, |a, b| {
            a.0.total_cmp(&b.0).then(b.1.total_cmp(&a.1))
        });
        let mut cur = base + wrapped;
        let candidate = |cur: f64, theta: f64, best: &mut f64, best_center: &mut Vec<f64>| {
            if cur > *best {
                *best = cur;
                *best_center = alloc::vec![
                    xi[0] + radius * fns::cos(theta),
                    xi[1] + radius * fns::sin(theta)
                ];
            }
        };
        let first_angle = events.first().map_or(0.0, |e| e.0);
        // Before the first event (angle 0 up to it) the wrapped arcs are active.
        candidate(cur, 0.5 * first_angle, &mut best, &mut best_center);
        for k in 0..events.len() {
            cur += events[k].1;
            if events[k].1 > 0.0 {
                let next = events.get(k + 1).map_or(two_pi, |e| e.0);
                candidate(cur, 0.5 * (events[k].0 + next), &mut best, &mut best_center);
            }
        }
    }
    best_center
}

/// d ≥ 3: the centres determined by every set of ≤ d mutually close particles (see
/// [`SpatialDensity::mmuc`]); `None` when the search would exceed its budget.
fn enumerate_centres(p: &ParticleSet, radius: f64) -> Option<Vec<f64>> {
    let n = p.len();
    let d = p.dim();
    let reach2 = 4.0 * radius * radius * (1.0 + COVER_SLACK);
    let live: Vec<usize> = (0..n).filter(|&i| p.weights()[i] > 0.0).collect();
    let neighbours: Vec<Vec<usize>> = live
        .iter()
        .map(|&i| {
            live.iter()
                .copied()
                .filter(|&j| j > i && dist2(p.point(i), p.point(j)) <= reach2)
                .collect()
        })
        .collect();
    // Count the subsets first (cliques of size ≤ d in the "within 2 r0" graph).
    let mut count = 0usize;
    let limit = EXHAUSTIVE_BUDGET / n.max(1);
    let index_of = |i: usize| live.binary_search(&i).unwrap_or(0);
    let mut stack: Vec<Vec<usize>> = live.iter().map(|&i| alloc::vec![i]).collect();
    let mut subsets: Vec<Vec<usize>> = Vec::new();
    while let Some(set) = stack.pop() {
        count += 1;
        if count > limit {
            return None;
        }
        if set.len() < d {
            let last = set[set.len() - 1];
            for &j in &neighbours[index_of(last)] {
                if set[..set.len() - 1]
                    .iter()
                    .all(|&k| dist2(p.point(k), p.point(j)) <= reach2)
                {
                    let mut s = set.clone();
                    s.push(j);
                    stack.push(s);
                }
            }
        }
        subsets.push(set);
    }
    let direction: Vec<f64> = {
        let v: Vec<f64> = (0..d)
            .map(|k| fns::sqrt(2.0 + k as f64) - 1.0 + 0.1 * k as f64)
            .collect();
        let norm = fns::sqrt(v.iter().map(|x| x * x).sum());
        v.iter().map(|x| x / norm).collect()
    };
    let mut best = -1.0;
    let mut best_center = p.point(live[0]).to_vec();
    for set in &subsets {
        let pts: Vec<&[f64]> = set.iter().map(|&i| p.point(i)).collect();
        for c in lowest_centres(&pts, radius, &direction) {
            let w = covered_weight(p, &c, radius);
            if w > best {
                best = w;
                best_center = c;
            }
        }
    }
    Some(best_center)
}

/// The points minimising ⟨e, c⟩ over the intersection of the spheres of radius r0 about
/// `pts` (one point, or two if e is orthogonal to that intersection's flat); empty when the
/// spheres do not meet or the points are affinely dependent.
fn lowest_centres(pts: &[&[f64]], radius: f64, e: &[f64]) -> Vec<Vec<f64>> {
    let d = e.len();
    let Some((o, r2)) = circumcentre(pts) else {
        return Vec::new();
    };
    let h2 = radius * radius - r2;
    if h2 < -COVER_SLACK * radius * radius {
        return Vec::new();
    }
    let h = fns::sqrt(h2.max(0.0));
    // Orthonormal basis of the hull's directions, then e's component orthogonal to it.
    let basis = orthonormal(pts.iter().skip(1).map(|x| {
        x.iter()
            .zip(pts[0])
            .map(|(a, b)| a - b)
            .collect::<Vec<f64>>()
    }));
    let project_out = |v: &[f64]| -> Vec<f64> {
        let mut v = v.to_vec();
        for b in &basis {
            let dot: f64 = v.iter().zip(b).map(|(x, y)| x * y).sum();
            for (vi, bi) in v.iter_mut().zip(b) {
                *vi -= dot * bi;
            }
        }
        v
    };
    let ep = project_out(e);
    let norm = fns::sqrt(ep.iter().map(|x| x * x).sum());
    if norm > 1e-9 {
        return alloc::vec![
            o.iter()
                .zip(&ep)
                .map(|(oi, ei)| oi - h * ei / norm)
                .collect()
        ];
    }
    // e lies in the hull's span: every point of the intersection is as low; take two.
    for k in 0..d {
        let mut u = alloc::vec![0.0; d];
        u[k] = 1.0;
        let up = project_out(&u);
        let un = fns::sqrt(up.iter().map(|x| x * x).sum());
        if un > 1e-6 {
            return [1.0, -1.0]
                .iter()
                .map(|s| {
                    o.iter()
                        .zip(&up)
                        .map(|(oi, ui)| oi + s * h * ui / un)
                        .collect()
                })
                .collect();
        }
    }
    alloc::vec![o]
}

/// Gram–Schmidt (twice, for stability); vectors that are dependent are dropped.
fn orthonormal(vs: impl Iterator<Item = Vec<f64>>) -> Vec<Vec<f64>> {
    let mut basis: Vec<Vec<f64>> = Vec::new();
    for mut v in vs {
        let scale = fns::sqrt(v.iter().map(|x| x * x).sum());
        for _ in 0..2 {
            for b in &basis {
                let dot: f64 = v.iter().zip(b).map(|(x, y)| x * y).sum();
                for (vi, bi) in v.iter_mut().zip(b) {
                    *vi -= dot * bi;
                }
            }
        }
        let norm = fns::sqrt(v.iter().map(|x| x * x).sum());
        if norm > 1e-12 * scale && norm > 0.0 {
            basis.push(v.iter().map(|x| x / norm).collect());
        }
    }
    basis
}

/// A heuristic for many particles in d ≥ 3: flat-kernel mean shift (move the centre to the
/// weighted mean of the particles it covers, [`geometry::mean_shift`]) from a subsample of at
/// most 256 particles, at most 30 steps each; the start ending with the most covered weight wins.
fn mean_shift_search(p: &ParticleSet, radius: f64) -> Vec<f64> {
    let n = p.len();
    let stride = n.div_ceil(256).max(1);
    let points: Vec<&[f64]> = (0..n).map(|i| p.point(i)).collect();
    let mut best = -1.0;
    let mut best_center = p.point(0).to_vec();
    for s in (0..n).step_by(stride) {
        let c = geometry::mean_shift(&points, p.weights(), p.point(s), radius, 30);
        let w = covered_weight(p, &c, radius);
        if w > best {
            best = w;
            best_center = c;
        }
    }
    best_center
}
