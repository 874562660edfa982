//! eˣ in plain arithmetic for the Rényi kernel of paper `004`
//! ([`crate::control`]): the same bits natively and in wasm, and a loop of it vectorises.
//!
//! [`exp_kernel_lanes`] is Tang's table-driven method (Tang 1989, in the shape of ARM's
//! optimized-routines `exp`) with a table of 2^{i/32}, without branches, division or fused
//! operations:
//!
//! 1. k = round(x·32/ln 2) by the magic addition t = x·32/ln 2 + 1.5·2⁵² (round to nearest in
//!    the addition; no float-to-integer conversion, which SSE2 has no vector form of), whose
//!    low bits are k (two's complement);
//! 2. r = x − k·ln2_hi/32 − k·ln2_lo/32 with fdlibm's two-part ln 2 (ln2_hi has 32 significant
//!    bits, so k·ln2_hi/32 and x − k·ln2_hi/32 are exact for |k| < 2²¹), |r| ≤ ln2/64 plus
//!    about 10⁻¹³ (the rounding of x·32/ln 2);
//! 3. with i = k mod 32 and m = ⌊k/32⌋, 2^{i/32} = H_i·(1 + T_i) from the table (H_i rounded
//!    to nearest, |T_i| < 2⁻⁵³), and eʳ − 1 ≈ r + r²(1/2! + r/3! + … + r⁴/6!) (truncation below
//!    r⁷/7! < 4·10⁻¹⁸ relatively), so eˣ ≈ 2ᵐ·H_i·(1 + (T_i + (eʳ − 1))) (the dropped
//!    T_i·(eʳ − 1) is below 2⁻⁵⁹), evaluated as s + s·(T_i + r + r²p) with s = 2ᵐH_i: the
//!    roundings of the small sum (a few ulps of a number below 0.012) and of s·(…), then one
//!    of the last addition;
//! 4. s = 2ᵐH_i built in the exponent bits: the table holds the bits of H_i less i·2⁴⁷, and
//!    adding k·2⁴⁷ (t's bits shifted left by 47) adds m to the exponent; with 64 more in the
//!    exponent, s·(…)·2⁻⁶⁴ is exact for a normal result and rounds once for a subnormal one.
//!
//! The table is 32 pairs of constant words read by index (no arithmetic is chosen by the
//! compiler, and the loads cannot round): every IEEE 754 implementation gives the same bits,
//! natively and in wasm (the checksums of `benches/control_table` and
//! `benches/control_node.mjs` agree). Only +, −, × and comparisons, no fused multiply-add
//! (whether `mul_add` fuses differs between a native build without FMA and wasm).
//! [`exp_kernel_lanes`] does `L` arguments in three passes (reduction, table loads,
//! polynomial and scaling), so that the first and the last vectorise (two SSE2 or wasm SIMD
//! lanes) though the loads cannot.
//!
//! Error: below 1 ulp of the exact value (faithful rounding, so at most 1 ulp from the
//! correctly rounded value) on [−746, 0], measured against a double-double evaluation (the
//! tests below): over 10⁸ stratified points at most 0.560 ulp for normal results, of which
//! 0.33 % not correctly rounded, and 0.759 ulp for subnormal ones (one rounding of the result
//! to the subnormal grid on top of its error); over the 10⁶ of `make test` 0.551 and 0.747.
//! The polynomial method this replaced (Cody & Waite's reduction and a degree-14 Taylor
//! polynomial, 56 operations against 31 here) had 0.644 ulp, 0.73 % and 0.787 ulp over the
//! same 10⁸ points (0.605 ulp and 0.72 % over the 10⁶).

/// Below this eˣ is 0 after rounding (e^{−745.14} is half the smallest subnormal); arguments
/// are clamped up to it, which also keeps 2^{m+64} a normal number.
const MIN_ARG: f64 = -746.0;
/// 1.5·2⁵²: adding it rounds a number of magnitude below 2⁵¹ to an integer, kept in the low
/// bits of the sum.
const MAGIC: f64 = 6_755_399_441_055_744.0;
/// 32/ln 2.
const INV_LN2_32: f64 = 46.166_241_308_446_83;
/// ln 2 rounded to 32 significant bits (fdlibm's `ln2HI`), over 32: k·LN2_HI_32 is exact for
/// |k| < 2²¹.
const LN2_HI_32: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000) / 32.0;
/// (ln 2 − fdlibm's `ln2HI`)/32 (fdlibm's `ln2LO` over 32).
const LN2_LO_32: f64 = f64::from_bits(0x3dea_39ef_3579_3c76) / 32.0;
/// 2⁻⁶⁴, undoing the offset of the exponent built in step 4.
const TWO_M64: f64 = f64::from_bits((1023 - 64) << 52);
/// The coefficients 1/n! of the polynomial, n = 2 … 6, each rounded to nearest.
const INV_FACT: [f64; 5] = [1.0 / 2.0, 1.0 / 6.0, 1.0 / 24.0, 1.0 / 120.0, 1.0 / 720.0];

/// 2^{i/32} = H_i·(1 + T_i) for i = 0 … 31: entry i the bits of T_i and those of H_i less
/// i·2⁴⁷ (step 4 of the [module](self) docs; one 16-byte load per lane). Computed with
/// 60-digit decimal arithmetic (H_i the double nearest 2^{i/32}, T_i = (2^{i/32} − H_i)/H_i
/// rounded to nearest); every entry i is that of ARM's 128-entry table at 4i.
static TABLE: [[u64; 2]; 32] = [
    [0x0000000000000000, 0x3ff0000000000000],
    [0x3c8cd2523567f613, 0x3fefd9b0d3158574],
    [0x3c979aa65d837b6d, 0x3fefb5586cf9890f],
    [0xbc9556522a2fbd0e, 0x3fef9301d0125b51],
    [0xbc801b15eaa59348, 0x3fef72b83c7d517b],
    [0x3c9aecf73e3a2f60, 0x3fef54873168b9aa],
    [0x3c968efde3a8a894, 0x3fef387a6e756238],
    [0x3c82f7e16d09ab31, 0x3fef1e9df51fdee1],
    [0x3c834d754db0abb6, 0x3fef06fe0a31b715],
    [0xbc924aedcc4b5068, 0x3feef1a7373aa9cb],
    [0x3c859f48a72a4c6d, 0x3feedea64c123422],
    [0x3c4363ed60c2ac11, 0x3feece086061892d],
    [0x3c7690cebb7aafb0, 0x3feebfdad5362a27],
    [0xbc78dec6bd0f385f, 0x3feeb42b569d4f82],
    [0x3c9063e1e21c5409, 0x3feeab07dd485429],
    [0xbc8c33c53bef4da8, 0x3feea47eb03a5585],
    [0xbc93b3efbf5e2228, 0x3feea09e667f3bcd],
    [0xbc781f647e5a3ecf, 0x3fee9f75e8ec5f74],
    [0xbc7b32dcb94da51d, 0x3feea11473eb0187],
    [0xbc9369b6f13b3734, 0x3feea589994cce13],
    [0x3c8db72fc1f0eab4, 0x3feeace5422aa0db],
    [0xbc5da9b88b6c1e29, 0x3feeb737b0cdc5e5],
    [0x3c71affc2b91ce27, 0x3feec49182a3f090],
    [0xbc91bbd1d3bcbb15, 0x3feed503b23e255d],
    [0x3c8c1a7792cb3387, 0x3feee89f995ad3ad],
    [0xbc68d6f438ad9334, 0x3feeff76f2fb5e47],
    [0x3c736eae30af0cb3, 0x3fef199bdd85529c],
    [0x3c676b2c6c921968, 0x3fef3720dcef9069],
    [0x3c74a385a63d07a7, 0x3fef5818dcfba487],
    [0xbc82d52107b43e1f, 0x3fef7c97337b9b5f],
    [0xbc8ff7128fd391f0, 0x3fefa4afa2a490da],
    [0x3c8a64a931d185ee, 0x3fefd0765b6e4540],
];

/// eˣ for each of the `L` arguments x ≤ 0 (the range of the Rényi kernel's pair factors) into
/// `out`, each within 1 ulp of the exact value, without branches or fused operations: see the
/// [module](self) for the method. Arguments below −746 give 0, as does the exact value
/// rounded; x > 0 is outside the contract (the formula holds up to about 665, where
/// 2^{m+64} overflows, but only x ≤ 0 is tested). Each lane's bits are those of the same
/// argument in one lane.
#[inline(always)]
pub(crate) fn exp_kernel_lanes<const L: usize>(x: &[f64; L], out: &mut [f64; L]) {
    // 1.–2. k and r.
    let mut r = [0.0f64; L];
    let mut t = [0u64; L];
    for l in 0..L {
        let x = if x[l] < MIN_ARG { MIN_ARG } else { x[l] };
        let tl = x * INV_LN2_32 + MAGIC;
        let kd = tl - MAGIC;
        t[l] = tl.to_bits();
        r[l] = (x - kd * LN2_HI_32) - kd * LN2_LO_32;
    }
    // 3. The table, by k mod 32.
    let mut tail = [0.0f64; L];
    let mut h = [0u64; L];
    for l in 0..L {
        let [ti, hi] = TABLE[(t[l] & 31) as usize];
        tail[l] = f64::from_bits(ti);
        h[l] = hi;
    }
    // 3.–4. The polynomial and s = 2^{m+64}·H_i.
    let c = &INV_FACT;
    for l in 0..L {
        let r = r[l];
        let r2 = r * r;
        let p = (c[0] + c[1] * r) + r2 * ((c[2] + c[3] * r) + r2 * c[4]);
        let small = tail[l] + (r + r2 * p);
        let s = f64::from_bits(h[l].wrapping_add(t[l] << 47).wrapping_add(64 << 52));
        out[l] = (s + s * small) * TWO_M64;
    }
}

/// eˣ for one x ≤ 0: [`exp_kernel_lanes`] of one lane (the tests' entry).
#[cfg(test)]
pub(crate) fn exp_kernel(x: f64) -> f64 {
    let mut out = [0.0];
    exp_kernel_lanes(&[x], &mut out);
    out[0]
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
    /// results, and all but about 1 % of those correctly rounded (measured: 0.551 ulp,
    /// 3410 points above ½ ulp; subnormal results 0.747 ulp). `--nocapture` prints the
    /// figures.
    #[test]
    fn exp_kernel_within_one_ulp() {
        let (worst, above_half) = check(1_000_000);
        assert!(worst < 0.65, "{worst}");
        assert!(above_half < 10_000, "{above_half}");
    }

    /// The same over 10⁸ points (`cargo test --release -p fisst exp_kernel -- --ignored`;
    /// measured: see the module docs; 2.3 min on one core).
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
