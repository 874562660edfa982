//! Globally adaptive Gauss–Kronrod quadrature (the G10/K21 pair of QUADPACK's `qk21`).

use alloc::vec::Vec;

use crate::math::fns;

/// Positive Kronrod nodes of the 21-point rule, largest first; the odd positions (1, 3, …, 9)
/// are the 10-point Gauss–Legendre nodes. QUADPACK `qk21` (Piessens, de Doncker-Kapenga,
/// Überhuber, Kahaner, 1983).
#[allow(clippy::excessive_precision)] // QUADPACK's digits, as published
const XGK: [f64; 10] = [
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

/// Kronrod weights of [`XGK`], then the centre's.
#[allow(clippy::excessive_precision)] // QUADPACK's digits, as published
const WGK: [f64; 11] = [
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

/// Gauss weights of the nodes `XGK[1], XGK[3], …, XGK[9]` (the 10-point rule has no centre).
#[allow(clippy::excessive_precision)] // QUADPACK's digits, as published
const WG: [f64; 5] = [
    0.066_671_344_308_688_137_593_568_809_893_332,
    0.149_451_349_150_580_593_145_776_339_657_697,
    0.219_086_362_515_982_043_995_534_934_228_163,
    0.269_266_719_309_996_355_091_226_921_569_469,
    0.295_524_224_714_752_870_173_892_994_651_338,
];

/// One application of the 21-point Kronrod rule on [a, b]: the Kronrod value, QUADPACK's
/// error estimate `resasc · min(1, (200 |K − G| / resasc)^1.5)` (floored at 50 ε ∫|f|), and
/// the Kronrod estimate of ∫|f|.
pub(crate) fn gk21<F: FnMut(f64) -> f64>(f: &mut F, a: f64, b: f64) -> (f64, f64, f64) {
    let centre = 0.5 * (a + b);
    let half = 0.5 * (b - a);
    let fc = f(centre);
    let mut kronrod = WGK[10] * fc;
    let mut gauss = 0.0;
    let mut abs_sum = WGK[10] * fns::abs(fc);
    let mut values = [(0.0, 0.0); 10];
    for (j, &x) in XGK.iter().enumerate() {
        let dx = half * x;
        let f1 = f(centre - dx);
        let f2 = f(centre + dx);
        values[j] = (f1, f2);
        kronrod += WGK[j] * (f1 + f2);
        abs_sum += WGK[j] * (fns::abs(f1) + fns::abs(f2));
        if j % 2 == 1 {
            gauss += WG[j / 2] * (f1 + f2);
        }
    }
    let mean = 0.5 * kronrod;
    let mut asc = WGK[10] * fns::abs(fc - mean);
    for (j, &(f1, f2)) in values.iter().enumerate() {
        asc += WGK[j] * (fns::abs(f1 - mean) + fns::abs(f2 - mean));
    }
    let h = fns::abs(half);
    let result = kronrod * half;
    let resabs = abs_sum * h;
    let resasc = asc * h;
    let mut err = fns::abs((kronrod - gauss) * half);
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
    (result, err, resabs)
}

/// An integral with its error estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Estimate {
    pub value: f64,
    pub error: f64,
    pub pieces: usize,
}

struct Piece {
    a: f64,
    b: f64,
    value: f64,
    error: f64,
    abs: f64,
}

/// ∫ f over [points[0], points[last]], starting from the pieces between consecutive
/// `points` and bisecting the piece with the largest error estimate until the summed
/// estimate is at most `tol`, `max_pieces` pieces exist or `keep_going` says stop (then the
/// estimate is returned as it stands; the caller sees it in `error`).
pub(crate) fn integrate<F: FnMut(f64) -> f64>(
    f: &mut F,
    points: &[f64],
    tol: f64,
    max_pieces: usize,
    keep_going: &dyn Fn() -> bool,
) -> Estimate {
    let mut pieces: Vec<Piece> = Vec::with_capacity(16);
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        if b > a {
            let (value, error, abs) = gk21(f, a, b);
            pieces.push(Piece {
                a,
                b,
                value,
                error,
                abs,
            });
        }
    }
    loop {
        let error: f64 = pieces.iter().map(|p| p.error).sum();
        let worst = pieces
            .iter()
            .enumerate()
            .max_by(|x, y| x.1.error.total_cmp(&y.1.error))
            .map(|(i, _)| i);
        let Some(worst) = worst else {
            return Estimate {
                value: 0.0,
                error: 0.0,
                pieces: 0,
            };
        };
        let split = {
            let p = &pieces[worst];
            let mid = 0.5 * (p.a + p.b);
            // Stop when the tolerance is met, the budget is spent, or the worst piece can no
            // longer be split in floating point.
            // Below ~64 ε of the integral of |f| the estimate is rounding noise.
            let floor = 64.0 * f64::EPSILON * pieces.iter().map(|p| p.abs).sum::<f64>();
            if error <= tol.max(floor)
                || pieces.len() >= max_pieces
                || !(p.a < mid && mid < p.b)
                || !keep_going()
            {
                None
            } else {
                Some((p.a, mid, p.b))
            }
        };
        let Some((a, mid, b)) = split else {
            let value = crate::math::sum::sum(pieces.iter().map(|p| p.value));
            return Estimate {
                value,
                error,
                pieces: pieces.len(),
            };
        };
        let (v1, e1, a1) = gk21(f, a, mid);
        let (v2, e2, a2) = gk21(f, mid, b);
        pieces[worst] = Piece {
            a,
            b: mid,
            value: v1,
            error: e1,
            abs: a1,
        };
        pieces.push(Piece {
            a: mid,
            b,
            value: v2,
            error: e2,
            abs: a2,
        });
    }
}

/// [`gk21`] for a vector integrand: the Kronrod values of every component, the error
/// estimate and ∫|f| of component 0 (the only one under error control).
pub(crate) fn gk21_vec<const N: usize, F: FnMut(f64) -> [f64; N]>(
    f: &mut F,
    a: f64,
    b: f64,
) -> ([f64; N], f64, f64) {
    let centre = 0.5 * (a + b);
    let half = 0.5 * (b - a);
    let fc = f(centre);
    let mut kronrod = [0.0; N];
    for (k, v) in kronrod.iter_mut().zip(fc) {
        *k = WGK[10] * v;
    }
    let mut gauss = 0.0;
    let mut abs_sum = WGK[10] * fns::abs(fc[0]);
    let mut values = [(0.0, 0.0); 10];
    for (j, &x) in XGK.iter().enumerate() {
        let dx = half * x;
        let f1 = f(centre - dx);
        let f2 = f(centre + dx);
        for ((k, u), v) in kronrod.iter_mut().zip(f1).zip(f2) {
            *k += WGK[j] * (u + v);
        }
        values[j] = (f1[0], f2[0]);
        abs_sum += WGK[j] * (fns::abs(f1[0]) + fns::abs(f2[0]));
        if j % 2 == 1 {
            gauss += WG[j / 2] * (f1[0] + f2[0]);
        }
    }
    let mean = 0.5 * kronrod[0];
    let mut asc = WGK[10] * fns::abs(fc[0] - mean);
    for (j, &(f1, f2)) in values.iter().enumerate() {
        asc += WGK[j] * (fns::abs(f1 - mean) + fns::abs(f2 - mean));
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
    (kronrod, err, resabs)
}

struct VecPiece<const N: usize> {
    a: f64,
    b: f64,
    value: [f64; N],
    error: f64,
    abs: f64,
}

/// [`integrate`] for a vector integrand, with error control on component 0 only: returns
/// the integrals and the error estimate of component 0.
pub(crate) fn integrate_vec<const N: usize, F: FnMut(f64) -> [f64; N]>(
    f: &mut F,
    points: &[f64],
    tol: f64,
    max_pieces: usize,
    keep_going: &dyn Fn() -> bool,
) -> ([f64; N], f64) {
    let mut pieces: Vec<VecPiece<N>> = Vec::with_capacity(16);
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        if b > a {
            let (value, error, abs) = gk21_vec(f, a, b);
            pieces.push(VecPiece {
                a,
                b,
                value,
                error,
                abs,
            });
        }
    }
    loop {
        let error: f64 = pieces.iter().map(|p| p.error).sum();
        let worst = pieces
            .iter()
            .enumerate()
            .max_by(|x, y| x.1.error.total_cmp(&y.1.error))
            .map(|(i, _)| i);
        let Some(worst) = worst else {
            return ([0.0; N], 0.0);
        };
        let split = {
            let p = &pieces[worst];
            let mid = 0.5 * (p.a + p.b);
            let floor = 64.0 * f64::EPSILON * pieces.iter().map(|p| p.abs).sum::<f64>();
            if error <= tol.max(floor)
                || pieces.len() >= max_pieces
                || !(p.a < mid && mid < p.b)
                || !keep_going()
            {
                None
            } else {
                Some((p.a, mid, p.b))
            }
        };
        let Some((a, mid, b)) = split else {
            let mut value = [0.0; N];
            for (k, v) in value.iter_mut().enumerate() {
                *v = crate::math::sum::sum(pieces.iter().map(|p| p.value[k]));
            }
            return (value, error);
        };
        let (v1, e1, a1) = gk21_vec(f, a, mid);
        let (v2, e2, a2) = gk21_vec(f, mid, b);
        pieces[worst] = VecPiece {
            a,
            b: mid,
            value: v1,
            error: e1,
            abs: a1,
        };
        pieces.push(VecPiece {
            a: mid,
            b,
            value: v2,
            error: e2,
            abs: a2,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kronrod_and_gauss_rules_have_their_degrees() {
        // K21 integrates x^k exactly for k ≤ 31, G10 for k ≤ 19; on [0, 1] the integral is
        // 1/(k + 1). A wrong digit in a node or weight breaks this at ~1e-10 or worse.
        for k in 0..=31 {
            let mut f = |x: f64| x.powi(k);
            let (v, _, _) = gk21(&mut f, 0.0, 1.0);
            let exact = 1.0 / f64::from(k + 1);
            assert!((v - exact).abs() < 4e-16, "K21 x^{k}: {v} vs {exact}");
        }
        for k in 0..=19 {
            let centre = 0.5;
            let half = 0.5;
            let mut g = 0.0;
            for (j, w) in WG.iter().enumerate() {
                let x = XGK[2 * j + 1];
                g += w * ((centre - half * x).powi(k) + (centre + half * x).powi(k));
            }
            g *= half;
            assert!((g - 1.0 / f64::from(k + 1)).abs() < 4e-16, "G10 x^{k}");
        }
        let wsum: f64 = 2.0 * WGK[..10].iter().sum::<f64>() + WGK[10];
        assert!((wsum - 2.0).abs() < 1e-15);
    }

    #[test]
    fn adaptive_integration_meets_the_tolerance() {
        // ∫_0^1 √x dx = 2/3 (endpoint singularity) and ∫_{-5}^{5} e^{-x²/2e-4} (narrow peak,
        // which must sit at a breakpoint: 21 nodes spread over [−5, 5] would step over it).
        let mut f = |x: f64| x.sqrt();
        let e = integrate(&mut f, &[0.0, 1.0], 1e-12, 200, &|| true);
        assert!((e.value - 2.0 / 3.0).abs() < 1e-12, "{e:?}");
        assert!(e.error <= 1e-12);
        let s = 1e-2;
        let mut g = |x: f64| (-0.5 * x * x / (s * s)).exp();
        let e = integrate(&mut g, &[-5.0, 0.0, 5.0], 1e-13, 500, &|| true);
        let exact = s * (2.0 * core::f64::consts::PI).sqrt();
        assert!((e.value - exact).abs() < 1e-13, "{e:?} vs {exact}");
    }
}
