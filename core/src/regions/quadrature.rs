//! Globally adaptive Gauss–Kronrod (7–15) quadrature, as in QUADPACK's QAG.
//!
//! The error estimate of an interval is |K₁₅ − G₇|, the difference between the 15-point
//! Kronrod and the embedded 7-point Gauss result. For an integrand that is smooth on the
//! interval, G₇ is far less accurate than K₁₅, so the estimate bounds the error of K₁₅ with a
//! wide margin; it is an estimate, not a proof (an integrand with features narrower than the
//! node spacing can fool any rule that samples it). Kinks and square-root end-point
//! singularities must be placed at interval ends (the callers pass them as breakpoints and,
//! for square roots, use [`smooth_ends`]).
//!
//! # References
//! R. Piessens, E. de Doncker-Kapenga, C. W. Überhuber, D. K. Kahaner, *QUADPACK: A
//! Subroutine Package for Automatic Integration*, Springer, 1983. doi:10.1007/978-3-642-61786-7.

use alloc::vec::Vec;

use crate::math::fns;

/// Kronrod abscissae on [−1, 1] (the positive half, from the end point inwards).
const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
/// Kronrod weights.
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
/// Gauss weights of the nodes XGK[1], XGK[3], XGK[5], XGK[7].
const WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// One 15-point Kronrod estimate on [a, b] and its error estimate |K₁₅ − G₇|.
pub(crate) fn gk15(f: &mut impl FnMut(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let c = 0.5 * (a + b);
    let h = 0.5 * (b - a);
    let fc = f(c);
    let mut k = WGK[7] * fc;
    let mut g = WG[3] * fc;
    for j in 0..7 {
        let dx = h * XGK[j];
        let s = f(c - dx) + f(c + dx);
        k += WGK[j] * s;
        if j % 2 == 1 {
            g += WG[j / 2] * s;
        }
    }
    (k * h, fns::abs((k - g) * h))
}

/// The outcome of an adaptive integration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Quad {
    /// The integral.
    pub value: f64,
    /// The sum of the |K₁₅ − G₇| estimates of the final intervals.
    pub error: f64,
}

/// ∫ f over [points[0], points[last]], with the interior points as initial breakpoints.
/// Bisects the interval with the largest error estimate until the total estimate is at most
/// `abs_tol` or `max_intervals` intervals are in use.
pub(crate) fn integrate(
    mut f: impl FnMut(f64) -> f64,
    points: &[f64],
    abs_tol: f64,
    max_intervals: usize,
) -> Quad {
    let mut intervals: Vec<(f64, f64, f64, f64)> = Vec::new();
    for w in points.windows(2) {
        if w[1] > w[0] {
            let (v, e) = gk15(&mut f, w[0], w[1]);
            intervals.push((w[0], w[1], v, e));
        }
    }
    loop {
        let total_err: f64 = intervals.iter().map(|iv| iv.3).sum();
        if total_err <= abs_tol || intervals.len() >= max_intervals {
            break;
        }
        let Some((worst, _)) = intervals
            .iter()
            .enumerate()
            .max_by(|x, y| x.1.3.total_cmp(&y.1.3))
        else {
            break;
        };
        let (a, b, _, _) = intervals[worst];
        let m = 0.5 * (a + b);
        if !(m > a && m < b) {
            // Cannot bisect further in floating point.
            break;
        }
        let (v1, e1) = gk15(&mut f, a, m);
        let (v2, e2) = gk15(&mut f, m, b);
        intervals[worst] = (a, m, v1, e1);
        intervals.push((m, b, v2, e2));
    }
    let value = crate::math::sum::sum(intervals.iter().map(|iv| iv.2));
    let error = intervals.iter().map(|iv| iv.3).sum();
    Quad { value, error }
}

/// `f` composed with the substitution t = a + (b − a)(3u² − 2u³) on every sub-interval of
/// `points`, times its Jacobian: integrating the returned function over u ∈ [i, i + 1] (for
/// the i-th sub-interval) gives ∫ f over that sub-interval. The Jacobian 6(b − a)u(1 − u)
/// vanishes at both ends, which turns a √(t − a) behaviour at an end into a smooth one.
pub(crate) fn smooth_ends<'a>(
    mut f: impl FnMut(f64) -> f64 + 'a,
    points: &'a [f64],
) -> impl FnMut(f64) -> f64 + 'a {
    move |x: f64| {
        let n = points.len().saturating_sub(1);
        if n == 0 {
            return 0.0;
        }
        let i = (x.max(0.0) as usize).min(n - 1);
        let u = x - i as f64;
        let (a, b) = (points[i], points[i + 1]);
        let t = a + (b - a) * (u * u * (3.0 - 2.0 * u));
        let jac = 6.0 * (b - a) * u * (1.0 - u);
        if jac == 0.0 { 0.0 } else { f(t) * jac }
    }
}

/// [`integrate`] over the sub-intervals of `points` with [`smooth_ends`] applied.
pub(crate) fn integrate_smooth_ends(
    f: impl FnMut(f64) -> f64,
    points: &[f64],
    abs_tol: f64,
    max_intervals: usize,
) -> Quad {
    let n = points.len().saturating_sub(1);
    let unit: Vec<f64> = (0..=n).map(|i| i as f64).collect();
    integrate(smooth_ends(f, points), &unit, abs_tol, max_intervals)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kronrod_rule_is_exact_for_degree_22_and_gauss_for_13() {
        for deg in 0..=22 {
            let mut f = |x: f64| x.powi(deg);
            let (k, _) = gk15(&mut f, -1.0, 1.0);
            let exact = if deg % 2 == 1 {
                0.0
            } else {
                2.0 / (deg as f64 + 1.0)
            };
            assert!((k - exact).abs() < 1e-15, "degree {deg}: {k} vs {exact}");
            let (_, e) = gk15(&mut f, -1.0, 1.0);
            if deg <= 13 {
                assert!(e < 1e-15, "degree {deg}: G7 error estimate {e}");
            }
        }
    }

    #[test]
    fn adaptive_integration_of_known_integrals() {
        let q = integrate(|x: f64| x.exp(), &[0.0, 1.0], 1e-14, 100);
        assert!((q.value - (1f64.exp() - 1.0)).abs() < 1e-14);
        // A kink at 1/3 given as a breakpoint, and one not given.
        let q = integrate(
            |x: f64| (x - 1.0 / 3.0).abs(),
            &[0.0, 1.0 / 3.0, 1.0],
            1e-14,
            100,
        );
        assert!((q.value - (1.0 / 18.0 + 2.0 / 9.0)).abs() < 1e-15);
        let q = integrate(|x: f64| (x - 0.3).abs(), &[0.0, 1.0], 1e-13, 500);
        assert!((q.value - (0.045 + 0.245)).abs() < 1e-13, "{q:?}");
        assert!(q.error <= 1e-13);
        // √ end-point singularities at both ends, removed by the substitution.
        let q = integrate_smooth_ends(|x: f64| (x * (1.0 - x)).sqrt(), &[0.0, 1.0], 1e-15, 100);
        assert!(
            (q.value - std::f64::consts::PI / 8.0).abs() < 1e-15,
            "{q:?}"
        );
    }
}
