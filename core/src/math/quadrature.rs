//! Globally adaptive Gauss–Kronrod quadrature (QUADPACK's QAG), one engine for every caller.
//!
//! The rule is a parameter ([`Rule`]):
//! - [`Rule::G7K15`]: the 15-point Kronrod rule with its embedded 7-point Gauss rule; the error
//!   estimate of a piece is the raw |K₁₅ − G₇|. For an integrand that is smooth on the piece,
//!   G₇ is far less accurate than K₁₅, so the estimate bounds the error of K₁₅ with a wide
//!   margin.
//! - [`Rule::G10K21`]: QUADPACK's `qk21` (21-point Kronrod, 10-point Gauss) with QUADPACK's
//!   scaled estimate `resasc · min(1, (200 |K₂₁ − G₁₀| / resasc)^1.5)`, floored at 50 ε ∫|f|.
//!
//! Either is an estimate, not a proof: an integrand with features narrower than the node
//! spacing can fool any rule that samples it. Kinks must be placed at piece ends (the callers
//! pass them as breakpoints) and square-root end-point singularities are best removed by
//! [`smooth_ends`].
//!
//! The engine starts from the pieces between consecutive breakpoints and bisects the piece
//! with the largest error estimate (the last of equal ones) until the [`Control`] says stop.
//! Values are summed with [`sum`](crate::math::sum::sum) (compensated), error estimates and
//! ∫|f| plainly. Integrands may be scalar ([`integrate`]) or fixed-size vectors
//! ([`integrate_vec`], error control on component 0, the other components riding along on the
//! same nodes); a scalar integrand is the N = 1 case, bit for bit.
//!
//! # References
//! R. Piessens, E. de Doncker-Kapenga, C. W. Überhuber, D. K. Kahaner, *QUADPACK: A
//! Subroutine Package for Automatic Integration*, Springer, 1983. doi:10.1007/978-3-642-61786-7.

use alloc::vec::Vec;

use crate::math::fns;

/// Kronrod abscissae of the 15-point rule on [−1, 1] (the positive half, from the end point
/// inwards; the odd positions and the centre are the 7-point Gauss nodes). QUADPACK `qk15`.
const XGK15: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
/// Kronrod weights of the 15-point rule, then the centre's.
const WGK15: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
/// Gauss weights of the nodes `XGK15[1], XGK15[3], XGK15[5]` and the centre.
const WG7: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// Positive Kronrod nodes of the 21-point rule, largest first; the odd positions (1, 3, …, 9)
/// are the 10-point Gauss–Legendre nodes. QUADPACK `qk21`.
#[allow(clippy::excessive_precision)] // QUADPACK's digits, as published
const XGK21: [f64; 10] = [
    0.995_657_163_025_808_080_735_527_280_689_003,
    0.973_906_528_517_171_720_077_964_012_084_452,
    0.930_157_491_355_708_226_001_207_180_059_508,
    0.865_063_366_688_984_510_732_096_688_423_493,
    0.780_817_726_586_416_897_063_717_578_345_042,
    0.679_409_568_299_024_406_234_327_365_114_874,
    0.562_757_134_668_604_683_339_000_099_272_694,
    0.433_395_394_129_247_190_799_265_943_165_784,
    0.294_392_862_701_460_198_131_126_603_103_866,
    0.148_874_338_981_631_210_884_826_001_129_720,
];

/// Kronrod weights of [`XGK21`], then the centre's.
#[allow(clippy::excessive_precision)] // QUADPACK's digits, as published
const WGK21: [f64; 11] = [
    0.011_694_638_867_371_874_278_064_396_062_192,
    0.032_558_162_307_964_727_478_818_972_459_390,
    0.054_755_896_574_351_996_031_381_300_244_580,
    0.075_039_674_810_919_952_767_043_140_916_190,
    0.093_125_454_583_697_605_535_065_465_083_366,
    0.109_387_158_802_297_641_899_210_590_325_805,
    0.123_491_976_262_065_851_077_958_109_831_074,
    0.134_709_217_311_473_325_928_054_001_771_707,
    0.142_775_938_577_060_080_797_094_273_138_717,
    0.147_739_104_901_338_491_374_841_515_972_068,
    0.149_445_554_002_916_905_664_936_468_389_821,
];

/// Gauss weights of the nodes `XGK21[1], XGK21[3], …, XGK21[9]` (the 10-point rule has no
/// centre).
#[allow(clippy::excessive_precision)] // QUADPACK's digits, as published
const WG10: [f64; 5] = [
    0.066_671_344_308_688_137_593_568_809_893_332,
    0.149_451_349_150_580_593_145_776_339_657_697,
    0.219_086_362_515_982_043_995_534_934_228_163,
    0.269_266_719_309_996_355_091_226_921_569_469,
    0.295_524_224_714_752_870_173_892_994_651_338,
];

/// A Gauss–Kronrod pair: the rule applied to each piece.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Rule {
    /// 15-point Kronrod, 7-point Gauss; error estimate |K₁₅ − G₇| (QUADPACK `qk15`'s nodes,
    /// without its scaling).
    G7K15,
    /// 21-point Kronrod, 10-point Gauss; QUADPACK `qk21`'s scaled error estimate.
    G10K21,
}

/// One application of a [`Rule`] on one piece.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Panel<V = f64> {
    /// The Kronrod estimate of the integral (every component).
    pub value: V,
    /// The rule's error estimate (of component 0).
    pub error: f64,
    /// The Kronrod estimate of ∫|f| (QUADPACK's `resabs`, of component 0).
    pub abs: f64,
}

impl Rule {
    /// The rule on [a, b] for a scalar integrand.
    pub fn apply<F: FnMut(f64) -> f64>(self, f: &mut F, a: f64, b: f64) -> Panel {
        let p = self.apply_vec(&mut |x| [f(x)], a, b);
        Panel {
            value: p.value[0],
            error: p.error,
            abs: p.abs,
        }
    }

    /// The rule on [a, b] for a vector integrand (N ≥ 1): every component's Kronrod value,
    /// the error estimate and ∫|f| of component 0.
    pub fn apply_vec<const N: usize, F: FnMut(f64) -> [f64; N]>(
        self,
        f: &mut F,
        a: f64,
        b: f64,
    ) -> Panel<[f64; N]> {
        const { assert!(N > 0, "a vector integrand needs a component 0") };
        match self {
            Rule::G7K15 => gk15(f, a, b),
            Rule::G10K21 => gk21(f, a, b),
        }
    }
}

fn gk15<const N: usize, F: FnMut(f64) -> [f64; N]>(f: &mut F, a: f64, b: f64) -> Panel<[f64; N]> {
    let c = 0.5 * (a + b);
    let h = 0.5 * (b - a);
    let fc = f(c);
    let mut k = [0.0; N];
    for (k, v) in k.iter_mut().zip(fc) {
        *k = WGK15[7] * v;
    }
    let mut g = WG7[3] * fc[0];
    let mut abs = WGK15[7] * fns::abs(fc[0]);
    for j in 0..7 {
        let dx = h * XGK15[j];
        let f1 = f(c - dx);
        let f2 = f(c + dx);
        for ((k, u), v) in k.iter_mut().zip(f1).zip(f2) {
            *k += WGK15[j] * (u + v);
        }
        abs += WGK15[j] * (fns::abs(f1[0]) + fns::abs(f2[0]));
        if j % 2 == 1 {
            g += WG7[j / 2] * (f1[0] + f2[0]);
        }
    }
    let error = fns::abs((k[0] - g) * h);
    for k in &mut k {
        *k *= h;
    }
    Panel {
        value: k,
        error,
        abs: abs * fns::abs(h),
    }
}

fn gk21<const N: usize, F: FnMut(f64) -> [f64; N]>(f: &mut F, a: f64, b: f64) -> Panel<[f64; N]> {
    let centre = 0.5 * (a + b);
    let half = 0.5 * (b - a);
    let fc = f(centre);
    let mut kronrod = [0.0; N];
    for (k, v) in kronrod.iter_mut().zip(fc) {
        *k = WGK21[10] * v;
    }
    let mut gauss = 0.0;
    let mut abs_sum = WGK21[10] * fns::abs(fc[0]);
    let mut values = [(0.0, 0.0); 10];
    for (j, &x) in XGK21.iter().enumerate() {
        let dx = half * x;
        let f1 = f(centre - dx);
        let f2 = f(centre + dx);
        for ((k, u), v) in kronrod.iter_mut().zip(f1).zip(f2) {
            *k += WGK21[j] * (u + v);
        }
        values[j] = (f1[0], f2[0]);
        abs_sum += WGK21[j] * (fns::abs(f1[0]) + fns::abs(f2[0]));
        if j % 2 == 1 {
            gauss += WG10[j / 2] * (f1[0] + f2[0]);
        }
    }
    let mean = 0.5 * kronrod[0];
    let mut asc = WGK21[10] * fns::abs(fc[0] - mean);
    for (j, &(f1, f2)) in values.iter().enumerate() {
        asc += WGK21[j] * (fns::abs(f1 - mean) + fns::abs(f2 - mean));
    }
    let h = fns::abs(half);
    let resabs = abs_sum * h;
    let resasc = asc * h;
    let mut err = fns::abs((kronrod[0] - gauss) * half);
    if resasc != 0.0 && err != 0.0 {
        let scaled = 200.0 * err / resasc;
        err = resasc
            * if scaled < 1.0 {
                fns::pow(scaled, 1.5)
            } else {
                1.0
            };
    }
    let floor = 50.0 * f64::EPSILON * resabs;
    if resabs > f64::MIN_POSITIVE / (50.0 * f64::EPSILON) && err < floor {
        err = floor;
    }
    for k in &mut kronrod {
        *k *= half;
    }
    Panel {
        value: kronrod,
        error: err,
        abs: resabs,
    }
}

/// When the summed error estimate E = Σ error of the pieces is small enough (A = Σ ∫|f| of
/// the pieces, both plain sums).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Tolerance {
    /// E ≤ tol.
    Absolute(f64),
    /// E ≤ max(tol, 64 ε A): below 64 ε of ∫|f| the estimate is rounding noise.
    AbsoluteAboveNoise(f64),
    /// E ≤ rel · A.
    RelativeToAbs(f64),
}

impl Tolerance {
    fn met(self, error: f64, abs: impl FnOnce() -> f64) -> bool {
        match self {
            Tolerance::Absolute(tol) => error <= tol,
            Tolerance::AbsoluteAboveNoise(tol) => error <= tol.max(64.0 * f64::EPSILON * abs()),
            Tolerance::RelativeToAbs(rel) => error <= rel * abs(),
        }
    }
}

/// The rule and the stop criterion of an adaptive integration. The engine stops when, in
/// this order, the [`Tolerance`] is met, `max_pieces` pieces are in use, the worst piece can
/// no longer be bisected in floating point, or `keep_going` returns false (it is asked only
/// when everything else says go on); the estimate is then returned as it stands.
#[derive(Clone, Copy)]
pub struct Control<'a> {
    /// The Gauss–Kronrod pair.
    pub rule: Rule,
    /// When the summed error estimate is small enough.
    pub tolerance: Tolerance,
    /// The largest number of pieces.
    pub max_pieces: usize,
    /// An external budget (a deadline, an evaluation count); `None` never stops.
    pub keep_going: Option<&'a dyn Fn() -> bool>,
}

impl core::fmt::Debug for Control<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Control")
            .field("rule", &self.rule)
            .field("tolerance", &self.tolerance)
            .field("max_pieces", &self.max_pieces)
            .field("keep_going", &self.keep_going.is_some())
            .finish()
    }
}

impl Control<'static> {
    /// `rule` to `tolerance` with at most `max_pieces` pieces and no external budget.
    pub const fn new(rule: Rule, tolerance: Tolerance, max_pieces: usize) -> Self {
        Self {
            rule,
            tolerance,
            max_pieces,
            keep_going: None,
        }
    }
}

/// An integral with its error estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Estimate<V = f64> {
    /// The integral (every component).
    pub value: V,
    /// The summed error estimate (of component 0).
    pub error: f64,
    /// The number of pieces (0 when there was nothing to integrate).
    pub pieces: usize,
}

struct Piece<const N: usize> {
    a: f64,
    b: f64,
    panel: Panel<[f64; N]>,
}

/// The engine: the pieces `intervals` (taken as given), bisected under `control`. Returns the
/// estimate and Σ ∫|f| of the final pieces.
fn adapt<const N: usize, F: FnMut(f64) -> [f64; N]>(
    f: &mut F,
    intervals: impl Iterator<Item = (f64, f64)>,
    control: &Control<'_>,
) -> (Estimate<[f64; N]>, f64) {
    let rule = control.rule;
    let mut pieces: Vec<Piece<N>> = Vec::with_capacity(16);
    for (a, b) in intervals {
        let panel = rule.apply_vec(f, a, b);
        pieces.push(Piece { a, b, panel });
    }
    loop {
        let error: f64 = pieces.iter().map(|p| p.panel.error).sum();
        let worst = pieces
            .iter()
            .enumerate()
            .max_by(|x, y| x.1.panel.error.total_cmp(&y.1.panel.error))
            .map(|(i, _)| i);
        let Some(worst) = worst else {
            let zero = Estimate {
                value: [0.0; N],
                error: 0.0,
                pieces: 0,
            };
            return (zero, 0.0);
        };
        let (a, b) = (pieces[worst].a, pieces[worst].b);
        let mid = 0.5 * (a + b);
        let abs = || pieces.iter().map(|p| p.panel.abs).sum::<f64>();
        if control.tolerance.met(error, abs)
            || pieces.len() >= control.max_pieces
            || !(a < mid && mid < b)
            || !control.keep_going.is_none_or(|k| k())
        {
            let mut value = [0.0; N];
            for (k, v) in value.iter_mut().enumerate() {
                *v = crate::math::sum::sum(pieces.iter().map(|p| p.panel.value[k]));
            }
            let estimate = Estimate {
                value,
                error,
                pieces: pieces.len(),
            };
            return (estimate, abs());
        }
        let left = rule.apply_vec(f, a, mid);
        let right = rule.apply_vec(f, mid, b);
        pieces[worst] = Piece {
            a,
            b: mid,
            panel: left,
        };
        pieces.push(Piece {
            a: mid,
            b,
            panel: right,
        });
    }
}

/// The non-empty pieces between consecutive breakpoints.
fn between(points: &[f64]) -> impl Iterator<Item = (f64, f64)> + '_ {
    points
        .windows(2)
        .map(|w| (w[0], w[1]))
        .filter(|(a, b)| b > a)
}

/// ∫ f over `[points[0], points[last]]`, with the interior points as initial breakpoints
/// (empty or reversed pieces are skipped).
///
/// ```
/// use fisst::math::quadrature::{Control, Rule, Tolerance, integrate};
/// let c = Control::new(Rule::G10K21, Tolerance::Absolute(1e-13), 100);
/// let e = integrate(|x: f64| x.exp(), &[0.0, 1.0], &c);
/// assert!((e.value - (1f64.exp() - 1.0)).abs() < 1e-14);
/// ```
pub fn integrate<F: FnMut(f64) -> f64>(
    mut f: F,
    points: &[f64],
    control: &Control<'_>,
) -> Estimate {
    let (e, _) = adapt(&mut |x| [f(x)], between(points), control);
    Estimate {
        value: e.value[0],
        error: e.error,
        pieces: e.pieces,
    }
}

/// [`integrate`] for a vector integrand (N ≥ 1), with error control on component 0 only.
pub fn integrate_vec<const N: usize, F: FnMut(f64) -> [f64; N]>(
    mut f: F,
    points: &[f64],
    control: &Control<'_>,
) -> Estimate<[f64; N]> {
    adapt(&mut f, between(points), control).0
}

/// ∫_a^b f by globally adaptive G10/K21 from `init` equal pieces (a + (b − a) i / init)
/// until the summed error estimate is at most `rel` of ∫|f| or 64 pieces are in use:
/// (value, error, ∫|f|), all 0 unless b > a. The quadrature of Theorem 2's n = 1 and n = 2
/// terms (paper 002, `bounds::theorem2`).
pub fn integrate_equal_pieces<F: FnMut(f64) -> f64>(
    mut f: F,
    a: f64,
    b: f64,
    init: usize,
    rel: f64,
) -> (f64, f64, f64) {
    if b.partial_cmp(&a) != Some(core::cmp::Ordering::Greater) {
        return (0.0, 0.0, 0.0);
    }
    let at = |i: usize| a + (b - a) * i as f64 / init as f64;
    let control = Control::new(Rule::G10K21, Tolerance::RelativeToAbs(rel), 64);
    let (e, abs) = adapt(
        &mut |x| [f(x)],
        (0..init).map(|i| (at(i), at(i + 1))),
        &control,
    );
    (e.value[0], e.error, abs)
}

/// `f` composed with the substitution t = a + (b − a)(3u² − 2u³) on every sub-interval of
/// `points`, times its Jacobian: integrating the returned function over u ∈ [i, i + 1] (for
/// the i-th sub-interval) gives ∫ f over that sub-interval. The Jacobian 6(b − a)u(1 − u)
/// vanishes at both ends, which turns a √(t − a) behaviour at an end into a smooth one.
pub fn smooth_ends<'a>(
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
pub fn integrate_smooth_ends(
    f: impl FnMut(f64) -> f64,
    points: &[f64],
    control: &Control<'_>,
) -> Estimate {
    let n = points.len().saturating_sub(1);
    let unit: Vec<f64> = (0..=n).map(|i| i as f64).collect();
    integrate(smooth_ends(f, points), &unit, control)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn g15(f: &mut impl FnMut(f64) -> f64, a: f64, b: f64) -> Panel {
        Rule::G7K15.apply(f, a, b)
    }

    fn g21(f: &mut impl FnMut(f64) -> f64, a: f64, b: f64) -> Panel {
        Rule::G10K21.apply(f, a, b)
    }

    #[test]
    fn k15_is_exact_for_degree_22_and_g7_for_13() {
        for deg in 0..=22 {
            let mut f = |x: f64| x.powi(deg);
            let p = g15(&mut f, -1.0, 1.0);
            let exact = if deg % 2 == 1 {
                0.0
            } else {
                2.0 / (deg as f64 + 1.0)
            };
            assert!(
                (p.value - exact).abs() < 1e-15,
                "degree {deg}: {p:?} vs {exact}"
            );
            if deg <= 13 {
                assert!(p.error < 1e-15, "degree {deg}: G7 error estimate {p:?}");
            }
        }
    }

    #[test]
    fn k21_is_exact_for_degree_31_and_g10_for_19() {
        // K21 integrates x^k exactly for k ≤ 31, G10 for k ≤ 19; on [0, 1] the integral is
        // 1/(k + 1). A wrong digit in a node or weight breaks this at ~1e-10 or worse.
        for k in 0..=31 {
            let mut f = |x: f64| x.powi(k);
            let v = g21(&mut f, 0.0, 1.0).value;
            let exact = 1.0 / f64::from(k + 1);
            assert!((v - exact).abs() < 4e-16, "K21 x^{k}: {v} vs {exact}");
        }
        for k in 0..=19 {
            let centre = 0.5;
            let half = 0.5;
            let mut g = 0.0;
            for (j, w) in WG10.iter().enumerate() {
                let x = XGK21[2 * j + 1];
                g += w * ((centre - half * x).powi(k) + (centre + half * x).powi(k));
            }
            g *= half;
            assert!((g - 1.0 / f64::from(k + 1)).abs() < 4e-16, "G10 x^{k}");
        }
        let wsum: f64 = 2.0 * WGK21[..10].iter().sum::<f64>() + WGK21[10];
        assert!((wsum - 2.0).abs() < 1e-15);
    }

    #[test]
    fn resabs_is_the_integral_of_the_absolute_value() {
        for rule in [Rule::G7K15, Rule::G10K21] {
            let p = rule.apply(&mut |x: f64| x, -1.0, 2.0);
            assert!((p.abs - 2.5).abs() < 1e-2, "{rule:?}: {p:?}");
            assert!((p.value - 1.5).abs() < 1e-15, "{rule:?}: {p:?}");
        }
    }

    #[test]
    fn scalar_integrand_is_the_one_component_vector_bit_for_bit() {
        for rule in [Rule::G7K15, Rule::G10K21] {
            let c = Control::new(rule, Tolerance::AbsoluteAboveNoise(1e-12), 50);
            let s = integrate(|x: f64| (x - 0.3).abs().sqrt(), &[0.0, 1.0], &c);
            let v = integrate_vec(|x: f64| [(x - 0.3).abs().sqrt(), x * x], &[0.0, 1.0], &c);
            assert_eq!(s.value.to_bits(), v.value[0].to_bits());
            assert_eq!(s.error.to_bits(), v.error.to_bits());
            assert_eq!(s.pieces, v.pieces);
            assert!((v.value[1] - 1.0 / 3.0).abs() < 1e-15);
        }
    }

    #[test]
    fn g7k15_adaptive_integration_of_known_integrals() {
        let c = |tol: f64, max: usize| Control::new(Rule::G7K15, Tolerance::Absolute(tol), max);
        let q = integrate(|x: f64| x.exp(), &[0.0, 1.0], &c(1e-14, 100));
        assert!((q.value - (1f64.exp() - 1.0)).abs() < 1e-14);
        // A kink at 1/3 given as a breakpoint, and one not given.
        let q = integrate(
            |x: f64| (x - 1.0 / 3.0).abs(),
            &[0.0, 1.0 / 3.0, 1.0],
            &c(1e-14, 100),
        );
        assert!((q.value - (1.0 / 18.0 + 2.0 / 9.0)).abs() < 1e-15);
        let q = integrate(|x: f64| (x - 0.3).abs(), &[0.0, 1.0], &c(1e-13, 500));
        assert!((q.value - (0.045 + 0.245)).abs() < 1e-13, "{q:?}");
        assert!(q.error <= 1e-13);
        // √ end-point singularities at both ends, removed by the substitution.
        let q = integrate_smooth_ends(|x: f64| (x * (1.0 - x)).sqrt(), &[0.0, 1.0], &c(1e-15, 100));
        assert!(
            (q.value - std::f64::consts::PI / 8.0).abs() < 1e-15,
            "{q:?}"
        );
    }

    #[test]
    fn g10k21_adaptive_integration_meets_the_tolerance() {
        // ∫_0^1 √x dx = 2/3 (endpoint singularity) and ∫_{-5}^{5} e^{-x²/2e-4} (narrow peak,
        // which must sit at a breakpoint: 21 nodes spread over [−5, 5] would step over it).
        let c = |tol: f64, max: usize| {
            Control::new(Rule::G10K21, Tolerance::AbsoluteAboveNoise(tol), max)
        };
        let e = integrate(|x: f64| x.sqrt(), &[0.0, 1.0], &c(1e-12, 200));
        assert!((e.value - 2.0 / 3.0).abs() < 1e-12, "{e:?}");
        assert!(e.error <= 1e-12);
        let s = 1e-2;
        let g = |x: f64| (-0.5 * x * x / (s * s)).exp();
        let e = integrate(g, &[-5.0, 0.0, 5.0], &c(1e-13, 500));
        let exact = s * (2.0 * core::f64::consts::PI).sqrt();
        assert!((e.value - exact).abs() < 1e-13, "{e:?} vs {exact}");
    }

    #[test]
    fn the_budget_and_the_piece_cap_stop_early() {
        let calls = core::cell::Cell::new(0);
        let keep_going = || {
            calls.set(calls.get() + 1);
            calls.get() < 3
        };
        let c = Control {
            keep_going: Some(&keep_going),
            ..Control::new(Rule::G10K21, Tolerance::Absolute(0.0), 100)
        };
        let e = integrate(|x: f64| x.sqrt(), &[0.0, 1.0], &c);
        // Asked before each of the bisections: two went ahead, the third was refused.
        assert_eq!((e.pieces, calls.get()), (3, 3));
        let c = Control::new(Rule::G7K15, Tolerance::Absolute(0.0), 5);
        assert_eq!(integrate(|x: f64| x.sqrt(), &[0.0, 1.0], &c).pieces, 5);
        let none = integrate(|x: f64| x, &[1.0, 1.0], &c);
        assert_eq!((none.value, none.error, none.pieces), (0.0, 0.0, 0));
    }

    #[test]
    fn equal_pieces_meet_a_relative_tolerance_of_the_absolute_integral() {
        // ∫_{-1}^{2} x dx = 3/2 with ∫|x| = 5/2; ∫_0^π sin = 2 from 4 pieces.
        let (v, e, abs) = integrate_equal_pieces(|x: f64| x, -1.0, 2.0, 3, 1e-12);
        assert!((v - 1.5).abs() < 1e-15 && (abs - 2.5).abs() < 1e-15 && e <= 1e-12 * abs);
        let (v, e, abs) =
            integrate_equal_pieces(|x: f64| x.sin(), 0.0, core::f64::consts::PI, 4, 1e-10);
        assert!((v - 2.0).abs() < 1e-12 && (abs - 2.0).abs() < 1e-12 && e <= 1e-10 * abs);
        assert_eq!(
            integrate_equal_pieces(|x: f64| x, 1.0, 0.0, 4, 1e-10),
            (0.0, 0.0, 0.0)
        );
        // The piece cap: √ at 0 needs more than 64 pieces to 1e-15.
        let (v, e, _) = integrate_equal_pieces(|x: f64| x.sqrt(), 0.0, 1.0, 8, 0.0);
        assert!((v - 2.0 / 3.0).abs() < 1e-9 && e > 0.0);
    }
}
