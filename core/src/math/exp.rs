//! eˣ for hot loops: the same bits as [`libm::exp`], in straight-line arithmetic that the
//! compiler can inline and vectorise.
//!
//! [`libm::exp`] is FreeBSD's `e_exp.c` (Sun's fdlibm): x = k ln 2 + r with |r| ≤ ln 2 / 2,
//! eʳ by a degree-5 Remez rational form, then 2ᵏ by `scalbn`; error below 1 ulp. It branches on
//! the size of |x| and calls `scalbn`, so a loop of it is a loop of calls. [`exp`] here does the
//! same operations in the same order, with the branches turned into selects between values
//! computed on every path (no table, no call, no data-dependent control flow in the common
//! range), so it gives the bits of [`libm::exp`] for every input — natively, in wasm and
//! without `std` alike — and `fns::exp` callers may switch to it without changing a result.
//! The tests check the bits against [`libm::exp`] on a stratified million points and against a
//! double-double reference (within 1 ulp of the exact value).

/// ln 2 in two parts (fdlibm's `ln2HI`, `ln2LO`, by their bits): `k · LN2_HI` is exact for
/// |k| < 2¹¹.
const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);
const INV_LN2: f64 = f64::from_bits(0x3ff7_1547_652b_82fe);
/// The Remez coefficients of R(r²) (fdlibm's `P1`–`P5`, by their bits).
const P1: f64 = f64::from_bits(0x3fc5_5555_5555_553e);
const P2: f64 = f64::from_bits(0xbf66_c16c_16be_bd93);
const P3: f64 = f64::from_bits(0x3f11_566a_af25_de2c);
const P4: f64 = f64::from_bits(0xbebb_bd41_c5d2_6bf1);
const P5: f64 = f64::from_bits(0x3e66_3769_72be_a4d0);
/// Above this eˣ overflows (fdlibm's threshold 709.782712893383973096).
const OVERFLOW: f64 = 709.782_712_893_384;
/// Below this eˣ rounds to 0 (fdlibm's threshold −745.13321910194110842).
const UNDERFLOW: f64 = -745.133_219_101_941_1;

/// 2ⁿ for −1022 ≤ n ≤ 1023, from its bits.
#[inline(always)]
fn pow2(n: i32) -> f64 {
    f64::from_bits(((n + 1023) as u64) << 52)
}

/// eˣ, bit for bit [`libm::exp`]`(x)` for every x (NaN, ±∞ and the overflow and underflow
/// ranges included). Written for loops: inline, no call and no branch on x in
/// [−745.13, 709.78] (the special cases are selects), so a loop of it vectorises.
///
/// The steps of `e_exp.c`: k = ⌊x/ln 2 ± ½⌋ (0 where |x| ≤ ½ ln 2, as fdlibm's test on the
/// high word decides), hi = x − k·ln2_hi, lo = k·ln2_lo, r = hi − lo,
/// c = r − r²(P1 + r²(P2 + …)), eʳ = 1 + (r c/(2 − c) − lo + hi), and 1 + x where
/// |x| ≤ 2⁻²⁸. Then 2ᵏ as two exact powers of two, 2^⌊k/2⌋ · 2^(k − ⌊k/2⌋): the first product is
/// exact (normal), so the result is rounded once, as `scalbn`'s is, also where it is
/// subnormal (k < −1022) or k = 1024.
#[inline(always)]
pub fn exp(x: f64) -> f64 {
    let bits = x.to_bits();
    let hx = ((bits >> 32) as u32) & 0x7fff_ffff; // the high word of |x|
    // fdlibm: k from x/ln 2 rounded half away from zero where |x| > ½ ln 2 (by the high word),
    // else 0 (which makes hi = x and lo = 0 exactly, as its middle branch sets them).
    let half = if bits >> 63 == 0 { 0.5 } else { -0.5 };
    let t = INV_LN2 * x + half;
    // `as i32` truncates toward zero (saturating outside the range, where the result is
    // replaced below).
    let k = if hx > 0x3fd6_2e42 { t as i32 } else { 0 };
    let kf = k as f64;
    let hi = x - kf * LN2_HI;
    let lo = kf * LN2_LO;
    let r = hi - lo;
    let rr = r * r;
    let c = r - rr * (P1 + rr * (P2 + rr * (P3 + rr * (P4 + rr * P5))));
    let y = 1.0 + (r * c / (2.0 - c) - lo + hi);
    let k = k.clamp(-1075, 1024);
    let half_k = k >> 1;
    let scaled = y * pow2(half_k) * pow2(k - half_k);
    // |x| ≤ 2⁻²⁸: fdlibm returns 1 + x.
    let value = if hx <= 0x3e30_0000 { 1.0 + x } else { scaled };
    if x > OVERFLOW {
        x * f64::from_bits(0x7fe0_0000_0000_0000) // +∞ (and +∞ for +∞), as fdlibm
    } else if x < UNDERFLOW {
        0.0
    } else if x.is_nan() {
        x
    } else {
        value
    }
}

#[cfg(test)]
mod tests {
    use super::{OVERFLOW, UNDERFLOW, exp};
    use crate::math::rng::SplitMix64;
    use alloc::vec;
    use alloc::vec::Vec;

    /// The bits agree with libm's, on special values and the thresholds of fdlibm's branches.
    #[test]
    fn special_values_and_branch_thresholds() {
        let mut xs = vec![
            0.0,
            -0.0,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            -f64::NAN,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            1.0,
            -1.0,
            OVERFLOW,
            709.782_712_893_384,
            710.0,
            -708.396_418_532_264_1,
            UNDERFLOW,
            -745.133_219_101_941_2,
            -746.0,
            -1e300,
            1e300,
            f64::MAX,
            f64::MIN,
        ];
        // around the high-word tests of e_exp.c: 0x3e300000 (2⁻²⁸), 0x3fd62e42 (½ ln 2),
        // 0x3ff0a2b2 (1.5 ln 2), 0x4086232b (708.39)
        for hi in [0x3e30_0000u64, 0x3fd6_2e42, 0x3ff0_a2b2, 0x4086_232b] {
            for dh in [-1i64, 0, 1] {
                for lo in [0u64, 1, 0x8000_0000, 0xffff_ffff] {
                    let b = (((hi as i64 + dh) as u64) << 32) | lo;
                    xs.push(f64::from_bits(b));
                    xs.push(-f64::from_bits(b));
                }
            }
        }
        for k in -1080..=1030 {
            let x = k as f64 * core::f64::consts::LN_2;
            for d in [-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0] {
                xs.push(x + d * 1e-9);
                xs.push(x + d * core::f64::consts::LN_2 / 2.0);
            }
        }
        for &x in &xs {
            let (got, want) = (exp(x), libm::exp(x));
            assert!(
                got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                "exp({x:e}) = {got:e}, libm {want:e}"
            );
        }
    }

    /// `n` points stratified over [−746, 711] (equal-width strata, one uniform point each)
    /// plus as many log-uniform in magnitude (|x| from 2⁻⁶⁰ to 746, either sign): the bits
    /// agree with libm's on every one, and each is within 1 ulp of a double-double reference.
    fn stratified(n: usize, seed: u64) {
        let mut rng = SplitMix64::new(seed);
        let (a, b) = (-746.0, 711.0);
        let width = (b - a) / n as f64;
        let mut worst = 0.0f64;
        for i in 0..n {
            let x = a + (i as f64 + rng.uniform()) * width;
            let mag = libm::exp2(-60.0 + rng.uniform() * (60.0 + libm::log2(746.0)));
            let y = if rng.uniform() < 0.5 { -mag } else { mag };
            for x in [x, y] {
                let (got, want) = (exp(x), libm::exp(x));
                assert_eq!(
                    got.to_bits(),
                    want.to_bits(),
                    "exp({x:e}) = {got:e}, libm {want:e}"
                );
                if got.is_finite() && got > f64::MIN_POSITIVE {
                    let ulps = reference::ulps(got, x);
                    worst = worst.max(ulps);
                    assert!(
                        ulps <= 1.0,
                        "exp({x:e}) = {got:e} is {ulps} ulp from the exact value"
                    );
                }
            }
        }
        assert!(worst > 0.0 && worst <= 1.0, "worst error {worst} ulp");
    }

    /// The reference itself: the correctly rounded e (`consts::E`) is within ½ ulp of e¹ and its
    /// neighbours are not; around libm's eˣ exactly one of five neighbouring doubles is within
    /// ½ ulp (the correctly rounded one), and it is libm's value or next to it (libm's e¹ is
    /// not: it is 0.67 ulp off, the upper neighbour).
    #[test]
    fn reference_resolves_half_an_ulp() {
        let e = core::f64::consts::E;
        assert!(reference::ulps(e, 1.0) < 0.5);
        assert!(reference::ulps(libm::nextafter(e, 0.0), 1.0) > 0.5);
        assert!(reference::ulps(libm::nextafter(e, 3.0), 1.0) > 0.5);
        for x in [1.0, -0.3, 20.5, -700.25, 0.125, 3.7e-5, 600.0] {
            let y = libm::exp(x);
            let down = libm::nextafter(y, 0.0);
            let up = libm::nextafter(y, f64::INFINITY);
            let near = [
                libm::nextafter(down, 0.0),
                down,
                y,
                up,
                libm::nextafter(up, f64::INFINITY),
            ];
            let errors: Vec<f64> = near.iter().map(|&v| reference::ulps(v, x)).collect();
            let within: Vec<usize> = (0..5).filter(|&i| errors[i] <= 0.5).collect();
            assert!(
                within.len() == 1 && (1..=3).contains(&within[0]),
                "{x}: {errors:?}"
            );
            // consecutive doubles differ by one ulp in the reference's measure
            for w in errors.windows(2) {
                assert!(
                    libm::fabs(libm::fabs(w[0] - w[1]) - 1.0) < 1e-6 || w[0] + w[1] < 1.0 + 1e-6,
                    "{x}: {errors:?}"
                );
            }
        }
    }

    /// A stratified million points (in `make test`).
    #[test]
    fn stratified_million_points_bits_equal_libm_and_within_one_ulp() {
        stratified(500_000, 0x5eed_e4b0);
    }

    /// 10⁸ points: `cargo test --release -p fisst exp::tests::stratified_10e8 -- --ignored`.
    #[test]
    #[ignore]
    fn stratified_10e8() {
        stratified(50_000_000, 0x1e8_e4b0);
    }

    /// eˣ in double-double arithmetic (about 100 bits): the error of a double in ulps.
    mod reference {
        /// (s, e) with s + e = a + b exactly.
        fn two_sum(a: f64, b: f64) -> (f64, f64) {
            let s = a + b;
            let bb = s - a;
            (s, (a - (s - bb)) + (b - bb))
        }
        /// (p, e) with p + e = a·b exactly (by fma).
        fn two_prod(a: f64, b: f64) -> (f64, f64) {
            let p = a * b;
            (p, libm::fma(a, b, -p))
        }
        fn add(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
            let (s, e) = two_sum(a.0, b.0);
            let (s, e) = two_sum(s, e + a.1 + b.1);
            (s, e)
        }
        fn mul(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
            let (p, e) = two_prod(a.0, b.0);
            two_sum(p, e + a.0 * b.1 + a.1 * b.0)
        }
        /// ln 2 to about 160 bits, in three doubles.
        const LN2: [f64; 3] = [
            core::f64::consts::LN_2,
            2.319_046_813_846_299_6e-17,
            5.707_708_438_416_212e-34,
        ];

        /// e^x as a double-double, for |x| ≤ 746: x = k ln 2 + r (r in double-double from the
        /// three-part ln 2), e^r by its Taylor series to 30 terms (|r| ≤ 0.35: the terms fall
        /// below 2⁻¹¹⁰), scaled by 2^k.
        pub fn exp_dd(x: f64) -> (f64, f64, i32) {
            let k = libm::round(x / LN2[0]);
            let r = add(
                add((x, 0.0), mul((-k, 0.0), (LN2[0], 0.0))),
                add(mul((-k, 0.0), (LN2[1], 0.0)), mul((-k, 0.0), (LN2[2], 0.0))),
            );
            let mut term = (1.0, 0.0);
            let mut sum = (1.0, 0.0);
            for n in 1..30 {
                term = mul(term, r);
                let inv = 1.0 / n as f64;
                let (q, qe) = two_prod(term.0, inv);
                // term / n in double-double: refine q by one Newton step
                let rem = add(term, mul((-q, -qe), (n as f64, 0.0)));
                term = add((q, qe), (rem.0 * inv, 0.0));
                sum = add(sum, term);
            }
            (sum.0, sum.1, k as i32)
        }

        /// |y − eˣ| in ulps of y (y normal and finite).
        pub fn ulps(y: f64, x: f64) -> f64 {
            let (s, e, k) = exp_dd(x);
            // y / 2^k (exact: a power of two) against s + e
            let yk = libm::scalbn(y, -k);
            let diff = (yk - s) - e;
            let ulp_y = libm::nextafter(yk, f64::INFINITY) - yk;
            libm::fabs(diff) / ulp_y
        }
    }
}
