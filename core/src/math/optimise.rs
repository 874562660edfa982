//! Local minimisation and bracketing root finding: BFGS with an Armijo backtracking line
//! search, the Nelder–Mead simplex, golden-section search on an interval, and bisection on a
//! sign (or side) change.
//!
//! References: J. Nocedal & S. J. Wright, *Numerical Optimization*, 2nd ed., Springer 2006
//! (Algorithm 6.1, BFGS; eq. (6.20), the initial scaling; Algorithm 3.1, backtracking);
//! J. A. Nelder & R. Mead, "A simplex method for function minimization", *Comput. J.* 7 (1965)
//! 308–313, with the coefficients and the inside/outside contraction of J. C. Lagarias,
//! J. A. Reeds, M. H. Wright & P. E. Wright, "Convergence properties of the Nelder–Mead simplex
//! method in low dimensions", *SIAM J. Optim.* 9 (1998) 112–147; J. Kiefer, "Sequential
//! minimax search for a maximum", *Proc. AMS* 4 (1953) 502–506 (golden section).
//!
//! The arithmetic of each routine is that of the code it came from (the MMUC search of
//! `000_…`, the variance-preserving split library of `001_…`, the section edges of `002_…`), so
//! their seeded results are unchanged.

use alloc::vec;
use alloc::vec::Vec;

use super::fns;

/// A local minimum found by [`bfgs`] or [`nelder_mead`].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Minimum {
    /// The best point found.
    pub x: Vec<f64>,
    /// The objective at [`x`](Self::x).
    pub value: f64,
    /// Iterations taken (BFGS steps, or simplex updates).
    pub iterations: usize,
}

/// The settings of [`bfgs`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BfgsOptions {
    /// Length of the first step (the initial inverse Hessian is `step`/‖∇f(x₀)‖ · I), and a
    /// quarter of the longest step.
    pub step: f64,
    /// Stop when every coordinate of a step is shorter than this, or when the line search
    /// would take a step shorter than this (max norm of the step).
    pub xtol: f64,
    /// Largest number of BFGS steps.
    pub max_iter: usize,
}

/// BFGS on the inverse Hessian H (Nocedal & Wright 2006, Algorithm 6.1) for `f` returning
/// (value, gradient), from `x0`:
///
/// - direction p = −H ∇f, reset to the scaled identity when it is not a descent direction,
///   and capped at length 4·`step`;
/// - Armijo backtracking (c₁ = 10⁻⁴, halving, at most 60 halvings; Algorithm 3.1); no
///   acceptable step ends the search;
/// - H₀ rescaled by sᵀy / yᵀy before the first update (eq. 6.20), then the update (6.17)
///   H ← (I − ρ s yᵀ) H (I − ρ y sᵀ) + ρ s sᵀ, skipped when sᵀy ≤ 10⁻¹² ‖s‖ ‖y‖.
///
/// ```
/// use fisst::math::optimise::{bfgs, BfgsOptions};
/// let f = |x: &[f64]| ((x[0] - 3.0).powi(2), vec![2.0 * (x[0] - 3.0)]);
/// let m = bfgs(f, &[0.0], &BfgsOptions { step: 1.0, xtol: 1e-12, max_iter: 100 });
/// assert!((m.x[0] - 3.0).abs() < 1e-9);
/// ```
pub fn bfgs<F: FnMut(&[f64]) -> (f64, Vec<f64>)>(mut f: F, x0: &[f64], o: &BfgsOptions) -> Minimum {
    let n = x0.len();
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let norm = |a: &[f64]| fns::sqrt(dot(a, a));
    let mut x = x0.to_vec();
    let (mut fx, mut g) = f(&x);
    let scaled_identity = |g: &[f64]| -> Vec<f64> {
        let c = o.step / norm(g).max(f64::MIN_POSITIVE);
        let mut h = vec![0.0; n * n];
        for i in 0..n {
            h[i * n + i] = c;
        }
        h
    };
    let mut h = scaled_identity(&g);
    let mut first = true;
    let mut iterations = 0;
    for _ in 0..o.max_iter {
        if norm(&g) == 0.0 {
            break;
        }
        iterations += 1;
        let mut p: Vec<f64> = (0..n).map(|i| -dot(&h[i * n..(i + 1) * n], &g)).collect();
        let mut slope = dot(&g, &p);
        if slope >= 0.0 {
            h = scaled_identity(&g);
            p = (0..n).map(|i| -h[i * n + i] * g[i]).collect();
            slope = dot(&g, &p);
        }
        let cap = 4.0 * o.step;
        let len = norm(&p);
        if len > cap {
            for v in &mut p {
                *v *= cap / len;
            }
            slope *= cap / len;
        }
        let plen = norm(&p);
        let mut alpha = 1.0;
        let mut halvings = 0;
        let accepted = loop {
            let xn: Vec<f64> = x.iter().zip(&p).map(|(xi, pi)| xi + alpha * pi).collect();
            let (fnew, gnew) = f(&xn);
            if fnew <= fx + 1e-4 * alpha * slope {
                break Some((xn, fnew, gnew));
            }
            alpha *= 0.5;
            halvings += 1;
            // At most 60 halvings (a step 1e-18 of the first): a bound on the work of one
            // line search whatever the tolerance.
            if alpha * plen < o.xtol || halvings > 60 {
                break None;
            }
        };
        let Some((xn, fnew, gnew)) = accepted else {
            break;
        };
        let s: Vec<f64> = xn.iter().zip(&x).map(|(a, b)| a - b).collect();
        let y: Vec<f64> = gnew.iter().zip(&g).map(|(a, b)| a - b).collect();
        x = xn;
        fx = fnew;
        g = gnew;
        if s.iter().all(|v| fns::abs(*v) < o.xtol) {
            break;
        }
        let sy = dot(&s, &y);
        if sy > 1e-12 * norm(&s) * norm(&y) {
            if first {
                // Nocedal & Wright (6.20): scale H₀ before the first update.
                let c = sy / dot(&y, &y);
                h = vec![0.0; n * n];
                for i in 0..n {
                    h[i * n + i] = c;
                }
                first = false;
            }
            // H ← (I − ρ s yᵀ) H (I − ρ y sᵀ) + ρ s sᵀ
            let rho = 1.0 / sy;
            let hy: Vec<f64> = (0..n).map(|i| dot(&h[i * n..(i + 1) * n], &y)).collect();
            let yhy = dot(&y, &hy);
            for i in 0..n {
                for j in 0..n {
                    h[i * n + j] += -rho * (hy[i] * s[j] + s[i] * hy[j])
                        + (rho * rho * yhy + rho) * s[i] * s[j];
                }
            }
        }
    }
    Minimum {
        x,
        value: fx,
        iterations,
    }
}

/// The Nelder–Mead simplex (Nelder & Mead 1965) with the standard coefficients of Lagarias
/// et al. (1998): reflection 1, expansion 2 (kept when it beats the reflected point),
/// contraction ½ (outside when the reflected point beats the worst, inside otherwise; kept when
/// it beats both the worst and the reflected value), else shrink ½ towards the best vertex. The first simplex is
/// `x0` and `x0 + step·e_i`; the vertices are sorted best first each iteration (a stable sort,
/// so ties keep their order and the run is deterministic). Stops when the worst and best
/// values differ by at most 10⁻¹⁷ or after `max_iter` iterations.
///
/// ```
/// use fisst::math::optimise::nelder_mead;
/// let m = nelder_mead(|x: &[f64]| (x[0] - 1.0).powi(2) + (x[1] + 2.0).powi(2), &[0.0, 0.0], 0.5, 500);
/// assert!((m.x[0] - 1.0).abs() < 1e-6 && (m.x[1] + 2.0).abs() < 1e-6);
/// ```
pub fn nelder_mead<F: FnMut(&[f64]) -> f64>(
    mut f: F,
    x0: &[f64],
    step: f64,
    max_iter: usize,
) -> Minimum {
    let d = x0.len();
    let mut pts: Vec<Vec<f64>> = vec![x0.to_vec()];
    for i in 0..d {
        let mut p = x0.to_vec();
        p[i] += step;
        pts.push(p);
    }
    let mut vals: Vec<f64> = pts.iter().map(|p| f(p)).collect();
    let mut iterations = 0;
    for _ in 0..max_iter {
        // Order: best first (stable on ties, so the run is deterministic).
        let mut order: Vec<usize> = (0..=d).collect();
        super::sort::sort_by(&mut order, |&a, &b| vals[a].total_cmp(&vals[b]));
        pts = order.iter().map(|&i| pts[i].clone()).collect();
        vals = order.iter().map(|&i| vals[i]).collect();
        if vals[d] - vals[0] <= 1e-17 {
            break;
        }
        iterations += 1;
        let centroid: Vec<f64> = (0..d)
            .map(|k| pts[..d].iter().map(|p| p[k]).sum::<f64>() / d as f64)
            .collect();
        let along = |t: f64| -> Vec<f64> {
            (0..d)
                .map(|k| centroid[k] + t * (pts[d][k] - centroid[k]))
                .collect()
        };
        let xr = along(-1.0);
        let fr = f(&xr);
        if fr < vals[0] {
            let xe = along(-2.0);
            let fe = f(&xe);
            if fe < fr {
                pts[d] = xe;
                vals[d] = fe;
            } else {
                pts[d] = xr;
                vals[d] = fr;
            }
        } else if fr < vals[d - 1] {
            pts[d] = xr;
            vals[d] = fr;
        } else {
            let (xc, fc) = if fr < vals[d] {
                let x = along(-0.5);
                let v = f(&x);
                (x, v)
            } else {
                let x = along(0.5);
                let v = f(&x);
                (x, v)
            };
            if fc < vals[d].min(fr) {
                pts[d] = xc;
                vals[d] = fc;
            } else {
                // Shrink towards the best point.
                for i in 1..=d {
                    let p: Vec<f64> = (0..d)
                        .map(|k| pts[0][k] + 0.5 * (pts[i][k] - pts[0][k]))
                        .collect();
                    vals[i] = f(&p);
                    pts[i] = p;
                }
            }
        }
    }
    let best = (0..=d)
        .min_by(|&a, &b| vals[a].total_cmp(&vals[b]))
        .unwrap_or(0);
    Minimum {
        x: pts[best].clone(),
        value: vals[best],
        iterations,
    }
}

/// Bisection of [a, b] for the point where `same_side_as_a` switches from true (at a) to
/// false (at b): halve at m = ½(a + b) while b − a > `resolution` and m lies strictly inside
/// (a, b) (so it also stops at the floating-point resolution of the bracket), at most
/// `max_iter` halvings; returns the midpoint ½(a + b) of the last bracket. For a root of a
/// continuous g with g(a) < 0 < g(b) pass `|x| g(x) < 0`.
///
/// ```
/// use fisst::math::optimise::bisect;
/// // The real root of x³ − 2x − 5 (Wallis's cubic) in [2, 3].
/// let g = |x: f64| x * x * x - 2.0 * x - 5.0;
/// let r = bisect(|x| g(x) < 0.0, 2.0, 3.0, 1e-14, usize::MAX);
/// assert!((r - 2.0945514815423265).abs() < 1e-13);
/// ```
pub fn bisect<P: FnMut(f64) -> bool>(
    mut same_side_as_a: P,
    a: f64,
    b: f64,
    resolution: f64,
    max_iter: usize,
) -> f64 {
    let (mut a, mut b) = (a, b);
    let mut halvings = 0;
    while b - a > resolution && halvings < max_iter {
        let mid = 0.5 * (a + b);
        if !(a < mid && mid < b) {
            break;
        }
        if same_side_as_a(mid) {
            a = mid;
        } else {
            b = mid;
        }
        halvings += 1;
    }
    0.5 * (a + b)
}

/// Golden-section search for the minimum of a unimodal `f` on [a, b]: `iterations` steps, each
/// shrinking the bracket by the golden ratio g = (√5 − 1)/2 with one evaluation (Kiefer 1953).
/// Returns the smaller of the two last interior values (`f64::min`, so a NaN at one point is
/// passed over) and the point where it was found.
pub fn golden_section<F: FnMut(f64) -> f64>(
    mut f: F,
    a: f64,
    b: f64,
    iterations: usize,
) -> (f64, f64) {
    let g = 0.5 * (fns::sqrt(5.0) - 1.0);
    let (mut a, mut b) = (a, b);
    let mut x1 = b - g * (b - a);
    let mut x2 = a + g * (b - a);
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..iterations {
        if f1 <= f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = f(x2);
        }
    }
    (if f1 <= f2 { x1 } else { x2 }, f1.min(f2))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rosenbrock's function, minimum 0 at (1, 1), and its gradient.
    fn rosenbrock(x: &[f64]) -> (f64, Vec<f64>) {
        let (a, b) = (1.0 - x[0], x[1] - x[0] * x[0]);
        (
            a * a + 100.0 * b * b,
            vec![-2.0 * a - 400.0 * x[0] * b, 200.0 * b],
        )
    }

    #[test]
    fn bfgs_finds_the_rosenbrock_minimum() {
        let o = BfgsOptions {
            step: 0.5,
            xtol: 1e-12,
            max_iter: 500,
        };
        let m = bfgs(rosenbrock, &[-1.2, 1.0], &o);
        assert!(
            (m.x[0] - 1.0).abs() < 1e-6 && (m.x[1] - 1.0).abs() < 1e-6,
            "{m:?}"
        );
        assert!(
            m.value < 1e-12 && m.iterations > 0 && m.iterations < 500,
            "{m:?}"
        );
    }

    #[test]
    fn bfgs_solves_a_quadratic() {
        // f = ½ xᵀ A x − bᵀ x with A = [[4, 1], [1, 3]], b = (1, 2): x* = A⁻¹ b = (1/11, 7/11).
        let f = |x: &[f64]| {
            let ax = [4.0 * x[0] + x[1], x[0] + 3.0 * x[1]];
            (
                0.5 * (x[0] * ax[0] + x[1] * ax[1]) - x[0] - 2.0 * x[1],
                vec![ax[0] - 1.0, ax[1] - 2.0],
            )
        };
        let o = BfgsOptions {
            step: 1.0,
            xtol: 1e-14,
            max_iter: 100,
        };
        let m = bfgs(f, &[5.0, -3.0], &o);
        assert!((m.x[0] - 1.0 / 11.0).abs() < 1e-10, "{m:?}");
        assert!((m.x[1] - 7.0 / 11.0).abs() < 1e-10, "{m:?}");
        // On a quadratic BFGS with an exact-enough line search converges in a few steps.
        assert!(m.iterations <= 20, "{m:?}");
    }

    #[test]
    fn nelder_mead_finds_the_rosenbrock_minimum() {
        let m = nelder_mead(|x: &[f64]| rosenbrock(x).0, &[-1.2, 1.0], 0.5, 5000);
        assert!(
            (m.x[0] - 1.0).abs() < 1e-4 && (m.x[1] - 1.0).abs() < 1e-4,
            "{m:?}"
        );
        assert!(m.value < 1e-8 && m.iterations < 5000, "{m:?}");
    }

    #[test]
    fn nelder_mead_solves_a_quadratic() {
        let f = |x: &[f64]| {
            (x[0] - 0.5) * (x[0] - 0.5) + 3.0 * (x[1] + 1.0) * (x[1] + 1.0) + x[2] * x[2]
        };
        let m = nelder_mead(f, &[0.0, 0.0, 0.0], 1.0, 4000);
        for (got, want) in m.x.iter().zip([0.5, -1.0, 0.0]) {
            assert!((got - want).abs() < 1e-7, "{m:?}");
        }
        // Zero iterations when the simplex starts flat.
        let flat = nelder_mead(|_: &[f64]| 1.0, &[0.0, 0.0], 1.0, 10);
        assert_eq!((flat.iterations, flat.value), (0, 1.0));
    }

    #[test]
    fn bisect_finds_the_root_of_a_cubic() {
        // (x − 1)(x + 2)(x − 4) = x³ − 3x² − 6x + 8: the root 1 in [0, 2.5].
        let g = |x: f64| ((x - 3.0) * x - 6.0) * x + 8.0;
        let r = bisect(|x| g(x) > 0.0, 0.0, 2.5, 0.0, usize::MAX);
        // Resolution 0: it stops at the floating-point resolution of the bracket.
        assert!((r - 1.0).abs() <= 4.0 * f64::EPSILON, "{r}");
        // A coarse resolution stops early, still bracketing the root.
        let coarse = bisect(|x| g(x) > 0.0, 0.0, 2.5, 1e-3, usize::MAX);
        assert!((coarse - 1.0).abs() <= 1e-3, "{coarse}");
        // And the iteration cap: one halving of [0, 2.5] leaves [0, 1.25], midpoint 0.625.
        assert_eq!(bisect(|x| g(x) > 0.0, 0.0, 2.5, 0.0, 1), 0.625);
    }

    #[test]
    fn golden_section_finds_the_minimum_of_a_unimodal_function() {
        // (x − 0.3)² + 1 on [0, 1]: 90 steps shrink the bracket by g^90 ≈ 1.6e-19, so the
        // point is found to the square root of ε (the function is flat to ε there).
        let (x, v) = golden_section(|x| (x - 0.3) * (x - 0.3) + 1.0, 0.0, 1.0, 90);
        assert!((x - 0.3).abs() < 1e-7, "{x}");
        assert_eq!(v, 1.0);
        // A minimum at an end of the bracket is approached from inside.
        let (x, v) = golden_section(|x| x, 0.0, 1.0, 60);
        assert!(x > 0.0 && x < 1e-11 && v == x, "{x} {v}");
        // No steps: the two first interior points.
        let g = 0.5 * (5f64.sqrt() - 1.0);
        assert_eq!(golden_section(|x| -x, 0.0, 1.0, 0), (g, -g));
    }
}
