//! eˣ in plain arithmetic for the Rényi kernel of paper `004`
//! ([`crate::control`]): the same bits natively and in wasm, and a loop of it vectorises.
//!
//! [`exp_kernel`] is Cody & Waite's range reduction (Cody & Waite 1980) with a Taylor
//! polynomial, in the shape of fdlibm's and musl's `exp` but without their branches, table or
//! division, the lower parts of the reduced argument and of the sums carried as in Tang 1989:
//!
//! 1. k = round(x·log₂e) by the magic addition t = x·log₂e + 1.5·2⁵² (round to nearest
//!    in the addition; no float-to-integer conversion, which SSE2 has no vector form of);
//! 2. r = x − k·ln2_hi − k·ln2_lo with fdlibm's two-part ln 2 (ln2_hi has 32 significant
//!    bits, so k·ln2_hi and x − k·ln2_hi are exact for |k| < 2²¹), |r| ≤ ln2/2 (+ an ulp),
//!    and the rounding error r_lo of the second subtraction recovered exactly (Fast2Sum);
//! 3. eʳ = 1 + r + r²·q(r), q the Taylor polynomial 1/2! + r/3! + … + r¹²/14! by Estrin's
//!    scheme (a dependency chain of depth 4 instead of Horner's 12: the loop is bound by
//!    latency), truncation below r¹⁵/15! < 10⁻¹⁹ relatively; the sums r + r²q and
//!    1 + (r + r²q) carried with their rounding errors (Fast2Sum), so that the roundings
//!    left are the final one and those of r²q (a few ulps of a number below 0.07);
//! 4. 2ᵏ built in the exponent bits: the low bits of t are k (two's complement), so
//!    `(t.to_bits() << 52) + ((1023 + 64) << 52)` is 2^{k+64} for every k of the range, and
//!    p·2^{k+64}·2⁻⁶⁴ is exact for a normal result and rounds once for a subnormal one.
//!
//! Only +, −, × and comparisons, no fused multiply-add (whether `mul_add` fuses differs
//! between a native build without FMA and wasm), so every IEEE 754 implementation gives the
//! same bits. Error: below 1 ulp of the exact value (faithful rounding, so at most 1 ulp from
//! the correctly rounded value) on [−746, 0], measured against a double-double evaluation
//! (the tests below): over 10⁸ stratified points at most 0.644 ulp for normal results, of
//! which 0.73 % not correctly rounded, and 0.787 ulp for subnormal ones (one rounding of p·2ᵏ
//! to the subnormal grid on top of p's error).

/// Below this eˣ is 0 after rounding (e^{−745.14} is half the smallest subnormal); arguments
/// are clamped up to it, which also keeps 2^{k+64} a normal number.
const MIN_ARG: f64 = -746.0;
/// log₂ e.
const LOG2_E: f64 = core::f64::consts::LOG2_E;
/// 1.5·2⁵²: adding it rounds a number of magnitude below 2⁵¹ to an integer, kept in the low
/// bits of the sum.
const MAGIC: f64 = 6_755_399_441_055_744.0;
/// ln 2 rounded to 32 significant bits (fdlibm's `ln2HI`): k·LN2_HI is exact for |k| < 2²¹.
const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
/// ln 2 − LN2_HI (fdlibm's `ln2LO`).
const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);
/// 2⁻⁶⁴, undoing the offset of the exponent built in step 4.
const TWO_M64: f64 = f64::from_bits((1023 - 64) << 52);
/// The coefficients 1/n! of the Taylor polynomial, n = 2 … 14, each rounded to nearest.
const INV_FACT: [f64; 13] = [
    1.0 / 2.0,
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 120.0,
    1.0 / 720.0,
    1.0 / 5_040.0,
    1.0 / 40_320.0,
    1.0 / 362_880.0,
    1.0 / 3_628_800.0,
    1.0 / 39_916_800.0,
    1.0 / 479_001_600.0,
    1.0 / 6_227_020_800.0,
    1.0 / 87_178_291_200.0,
];

/// eˣ for x ≤ 0 (the range of the Rényi kernel's pair factors), within 1 ulp of the exact
/// value, without branches, tables or fused operations: see the [module](self) for the
/// method. Arguments below −746 give 0, as does the exact value rounded; x > 0 is outside the
/// contract (the formula holds up to about 664, but only x ≤ 0 is tested).
#[inline(always)]
pub(crate) fn exp_kernel(x: f64) -> f64 {
    let x = if x < MIN_ARG { MIN_ARG } else { x };
    // 1. k = round(x·log₂e).
    let t = x * LOG2_E + MAGIC;
    let kd = t - MAGIC;
    // 2. r + r_lo = x − k·ln 2.
    let hi = x - kd * LN2_HI;
    let lo = kd * LN2_LO;
    let r = hi - lo;
    let r_lo = (hi - r) - lo;
    // 3. eʳ = 1 + r + r²·q(r), q by Estrin's scheme (depth 4 instead of Horner's 12), the
    //    two sums with their rounding errors (Fast2Sum: |r| ≥ r²q and 1 > |y|).
    let c = &INV_FACT;
    let r2 = r * r;
    let r4 = r2 * r2;
    let r8 = r4 * r4;
    let q01 = (c[0] + c[1] * r) + (c[2] + c[3] * r) * r2;
    let q23 = (c[4] + c[5] * r) + (c[6] + c[7] * r) * r2;
    let q45 = (c[8] + c[9] * r) + (c[10] + c[11] * r) * r2;
    let q = (q01 + q23 * r4) + (q45 + c[12] * r4) * r8;
    let tail = r2 * q;
    let y = r + tail;
    let y_err = tail - (y - r);
    let s = 1.0 + y;
    let s_err = (1.0 - s) + y;
    // d/dr eʳ = eʳ ≈ 1 + r for the correction r_lo (|r_lo| ≤ 2⁻⁵⁵).
    let p = s + (s_err + (y_err + r_lo * (1.0 + r)));
    // 4. p·2ᵏ through 2^{k+64}.
    let scale = f64::from_bits((t.to_bits() << 52).wrapping_add((1023 + 64) << 52));
    (p * scale) * TWO_M64
}

#[cfg(test)]
mod tests {
    //! Accuracy of [`exp_kernel`] against eˣ in double-double arithmetic (about 100 bits,
    //! checked against libm), over a stratified sample of the kernel's range [−746, 0].

    use super::{MIN_ARG, exp_kernel};
    use crate::math::rng::SplitMix64;

    /// a + b = s + e exactly (Knuth's TwoSum).
    fn two_sum(a: f64, b: f64) -> (f64, f64) {
        let s = a + b;
        let bb = s - a;
        (s, (a - (s - bb)) + (b - bb))
    }

    /// a + b = s + e exactly for |a| ≥ |b| (Dekker's Fast2Sum).
    fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
        let s = a + b;
        (s, b - (s - a))
    }

    /// a = hi + lo with 26-bit halves (Dekker's split).
    fn split(a: f64) -> (f64, f64) {
        let c = 134_217_729.0 * a;
        let hi = c - (c - a);
        (hi, a - hi)
    }

    /// a·b = p + e exactly (Dekker's TwoProduct, no FMA).
    fn two_prod(a: f64, b: f64) -> (f64, f64) {
        let p = a * b;
        let ((ah, al), (bh, bl)) = (split(a), split(b));
        (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
    }

    type Dd = (f64, f64);

    fn dd_add(a: Dd, b: Dd) -> Dd {
        let (s, e) = two_sum(a.0, b.0);
        fast_two_sum(s, e + a.1 + b.1)
    }

    fn dd_mul(a: Dd, b: Dd) -> Dd {
        let (p, e) = two_prod(a.0, b.0);
        fast_two_sum(p, e + (a.0 * b.1 + a.1 * b.0))
    }

    /// a/n for a small integer n.
    fn dd_div_int(a: Dd, n: f64) -> Dd {
        let q1 = a.0 / n;
        let (p, e) = two_prod(q1, n);
        let q2 = (((a.0 - p) - e) + a.1) / n;
        fast_two_sum(q1, q2)
    }

    /// ln 2 to 106 bits.
    const LN2_DD: Dd = (
        f64::from_bits(0x3fe6_2e42_fefa_39ef),
        f64::from_bits(0x3c7a_bc9e_3b39_803f),
    );

    /// eˣ = 2ᵏ·(H + L) with H + L = e^r to about 2⁻¹⁰⁰ relatively: r = x − k ln 2 in
    /// double-double, then 1 + r(1 + r/2(1 + r/3(…(1 + r/24)))) by Horner (|r| ≤ 0.35:
    /// truncation below r²⁵/25! < 10⁻³⁶).
    fn exp_dd(x: f64) -> (i32, Dd) {
        let k = libm::round(x / LN2_DD.0);
        let (p, e) = two_prod(k, LN2_DD.0);
        let kl = fast_two_sum(p, e + k * LN2_DD.1);
        let r = dd_add((x, 0.0), (-kl.0, -kl.1));
        let mut acc: Dd = (1.0, 0.0);
        for n in (1..=24).rev() {
            acc = dd_add((1.0, 0.0), dd_div_int(dd_mul(acc, r), n as f64));
        }
        (k as i32, acc)
    }

    /// 2ⁿ for |n| ≤ 1023 and n ≥ −1022.
    fn pow2(n: i32) -> f64 {
        f64::from_bits(((n + 1023) as u64) << 52)
    }

    /// |y − eˣ| in ulps of eˣ (the spacing of the doubles at eˣ, 2⁻¹⁰⁷⁴ for subnormals).
    fn ulp_error(x: f64, y: f64) -> f64 {
        let (k, (h, l)) = exp_dd(x);
        // y·2⁻ᵏ exactly, in two steps to stay in range.
        let (k1, k2) = (-k / 2, -k - (-k / 2));
        let ys = y * pow2(k1) * pow2(k2);
        let diff = (ys - h) - l;
        // The binade of the exact value H + L (H may have rounded up to a power of 2).
        let bits = h.to_bits();
        let mut e = ((bits >> 52) as i32) - 1023;
        if bits & ((1 << 52) - 1) == 0 && l < 0.0 {
            e -= 1;
        }
        let ulp_exp = (e + k - 52).max(-1074);
        // ulp in the scaled frame: 2^{ulp_exp − k}, split likewise.
        let u = ulp_exp - k;
        let ulp = pow2(u / 2) * pow2(u - u / 2);
        libm::fabs(diff) / ulp
    }

    /// The stratified sample of `n` points: half in 1000 equal strata of [−746, 0], half
    /// with |x| in 500 log-uniform strata of [2⁻⁴⁰, 746], one uniform draw each per stratum
    /// per round; then the edges (0, the subnormal and underflow thresholds, −746).
    fn sample(n: usize, seed: u64) -> impl Iterator<Item = f64> {
        let mut rng = SplitMix64::new(seed);
        let (lo2, hi2) = (-40.0, libm::log2(-MIN_ARG));
        let edges = [
            0.0,
            -0.0,
            -1e-300,
            -708.396_418_532_264_1,
            -708.396_418_532_264_2,
            -745.133_219_101_941_1,
            -745.133_219_101_941_2,
            -745.9,
            MIN_ARG,
        ];
        (0..n)
            .map(move |i| {
                let u = rng.uniform();
                if i % 2 == 0 {
                    let s = (i / 2) % 1000;
                    MIN_ARG * (s as f64 + u) / 1000.0
                } else {
                    let s = (i / 2) % 500;
                    let e = lo2 + (hi2 - lo2) * (s as f64 + u) / 500.0;
                    (-libm::exp2(e)).max(MIN_ARG)
                }
            })
            .chain(edges)
    }

    /// Runs the sample: asserts that every point is within 1 ulp of eˣ, and the reference
    /// within 1 ulp of libm's; returns the largest error and the count above ½ ulp (not
    /// correctly rounded).
    fn check(n: usize) -> (f64, usize) {
        let (mut worst, mut worst_x, mut above_half, mut worst_sub) = (0.0f64, 0.0, 0, 0.0f64);
        for x in sample(n, 29) {
            let err = ulp_error(x, exp_kernel(x));
            assert!(
                err < 1.0,
                "exp_kernel({x:e}) = {:e}: {err} ulp",
                exp_kernel(x)
            );
            let libm_err = ulp_error(x, libm::exp(x));
            assert!(libm_err < 1.0, "reference at {x:e}: libm {libm_err} ulp");
            if exp_kernel(x) < f64::MIN_POSITIVE {
                worst_sub = worst_sub.max(err);
                continue;
            }
            if err > worst {
                (worst, worst_x) = (err, x);
            }
            above_half += usize::from(err > 0.5);
        }
        std::eprintln!(
            "n = {n}: worst {worst} ulp at {worst_x:e}, {above_half} above half; subnormal worst {worst_sub}"
        );
        (worst, above_half)
    }

    /// 10⁶ stratified points of [−746, 0]: below 1 ulp everywhere, below 0.65 ulp for normal
    /// results, and all but about 1 % of those correctly rounded (measured: 0.605 ulp,
    /// 7229 points above ½ ulp; subnormal results 0.778 ulp). `--nocapture` prints the
    /// figures.
    #[test]
    fn exp_kernel_within_one_ulp() {
        let (worst, above_half) = check(1_000_000);
        assert!(worst < 0.65, "{worst}");
        assert!(above_half < 10_000, "{above_half}");
    }

    /// The same over 10⁸ points (`cargo test --release -p fisst exp_kernel -- --ignored`;
    /// measured: see the module docs; 5 min).
    #[test]
    #[ignore]
    fn exp_kernel_within_one_ulp_1e8() {
        let (worst, above_half) = check(100_000_000);
        assert!(worst < 0.65, "{worst}");
        assert!(above_half < 1_000_000, "{above_half}");
    }

    /// The edges: 1 at 0, 0 where the exact value rounds to 0, the smallest subnormal near
    /// its threshold.
    #[test]
    fn exp_kernel_edges() {
        assert_eq!(exp_kernel(0.0), 1.0);
        assert_eq!(exp_kernel(-0.0), 1.0);
        assert_eq!(exp_kernel(-746.0), 0.0);
        assert_eq!(exp_kernel(-1e9), 0.0);
        assert_eq!(exp_kernel(f64::NEG_INFINITY), 0.0);
        assert_eq!(exp_kernel(-745.1), f64::from_bits(1));
        assert_eq!(exp_kernel(-1.0), libm::exp(-1.0));
    }
}
