//! A float in decimal, exactly as the standard library's `Display` writes it (`{}`), in about
//! 5 KB of wasm instead of the standard library's 19 KB.
//!
//! `<f64 as Display>::fmt` carries both of the standard library's float printers (Grisu with a
//! Dragon4 fallback, each in a shortest and an exact-precision mode, and a 40-word bignum):
//! about 19 KB of every wasm module, 114 KB of the npm package's six, for the few error
//! messages that quote a number (issue 25, wasm size). [`Decimal`] writes the same text with
//! one small algorithm: Dragon4's shortest mode (Steele & White 1990, with the free-format
//! termination of Burger & Dybvig 1996) on a fixed-size big integer of its own, with the
//! standard library's decoding of the rounding interval (inclusive when the mantissa is even;
//! half as wide below a power of two), its first-digit estimate and its rounding of the last
//! digit (up when the remainder is at least half), so that the digits are the shortest that
//! read back as the same float and, among those, the closest. The layout is `Display`'s:
//! positional, never an exponent (`1e21` is `1000000000000000000000`, `1e-7` is `0.0000001`),
//! no `.0` on integers, `-0` for negative zero, `inf`, `-inf` and `NaN`. Width, fill and
//! precision flags are not supported (the crate's messages use none). The tests compare it with
//! the standard library on the edges of the format and on 10⁶ random bit patterns.

use core::cmp::Ordering;
use core::fmt;

/// Writes an `f64` as `format!("{}", x)` does (see the [module](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Decimal(pub f64);

impl fmt::Display for Decimal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if x.is_nan() {
            return f.write_str("NaN");
        }
        if x.is_sign_negative() {
            f.write_str("-")?;
        }
        if x.is_infinite() {
            return f.write_str("inf");
        }
        if x == 0.0 {
            return f.write_str("0");
        }
        let mut buf = [0u8; 20];
        let (n, k) = shortest(x.abs(), &mut buf);
        let digits = &buf[..n];
        // The value is 0.d₁d₂…dₙ × 10ᵏ; `digits` holds ASCII digits only.
        fn text(d: &[u8]) -> &str {
            core::str::from_utf8(d).unwrap_or("")
        }
        if k <= 0 {
            f.write_str("0.")?;
            for _ in 0..-k {
                f.write_str("0")?;
            }
            f.write_str(text(digits))
        } else {
            let k = k as usize;
            if k < n {
                f.write_str(text(&digits[..k]))?;
                f.write_str(".")?;
                f.write_str(text(&digits[k..]))
            } else {
                f.write_str(text(digits))?;
                for _ in n..k {
                    f.write_str("0")?;
                }
                Ok(())
            }
        }
    }
}

/// The shortest digits of a finite x > 0, written into `buf` (at most 18), and their exponent
/// k (x ≈ 0.d₁d₂… × 10ᵏ): the standard library's Dragon4 shortest mode.
#[inline(never)]
fn shortest(x: f64, buf: &mut [u8; 20]) -> (usize, i32) {
    // The standard library's `integer_decode`: x = m·2^e.
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & ((1 << 52) - 1);
    let (m, e) = if biased == 0 {
        (frac << 1, -1075)
    } else {
        (frac | (1 << 52), biased - 1075)
    };
    let inclusive = m & 1 == 0;
    // The rounding interval (x − minus·2^exp, x + plus·2^exp), x = mant·2^exp: half as wide
    // below when x is a power of two (the standard library's `decode`, which says so for every
    // normal x with an empty fraction).
    let (mant, minus, plus, exp) = if biased == 0 {
        (m, 1u64, 1u64, e)
    } else if frac == 0 {
        (m << 2, 1, 2, e - 2)
    } else {
        (m << 1, 1, 1, e - 1)
    };
    let rounding = if inclusive {
        Ordering::Greater
    } else {
        Ordering::Equal
    };
    // k with 10^(k−1) < mant·2^exp ≤ 10^(k+1) (the standard library's estimate).
    let nbits = 64 - i64::from((mant + plus - 1).leading_zeros());
    let mut k = (((nbits + i64::from(exp)) * 1_292_913_986) >> 32) as i32;
    let mut mant = Big::from_u64(mant);
    let mut minus = Big::from_u64(minus);
    let mut plus = Big::from_u64(plus);
    let mut scale = Big::from_u64(1);
    // mant, minus and plus over scale, times 10^−k.
    let e2 = exp.unsigned_abs();
    if exp < 0 {
        scale.mul_pow(2, e2);
    } else {
        for b in [&mut mant, &mut minus, &mut plus] {
            b.mul_pow(2, e2);
        }
    }
    if k >= 0 {
        scale.mul_pow(10, k as u32);
    } else {
        for b in [&mut mant, &mut minus, &mut plus] {
            b.mul_pow(10, k.unsigned_abs());
        }
    }
    // Fix the estimate up: scale < mant + plus ≤ 10·scale.
    if scale.cmp(&mant.plus(&plus)) < rounding {
        k += 1;
    } else {
        for b in [&mut mant, &mut minus, &mut plus] {
            b.mul_pow(10, 1);
        }
    }
    let mut n = 0;
    let (down, up) = loop {
        let mut d = b'0';
        while mant.cmp(&scale) != Ordering::Less {
            mant.sub_assign(&scale);
            d += 1;
        }
        buf[n] = d;
        n += 1;
        let down = mant.cmp(&minus) < rounding;
        let up = scale.cmp(&mant.plus(&plus)) < rounding;
        if down || up || n == 18 {
            break (down, up);
        }
        for b in [&mut mant, &mut minus, &mut plus] {
            b.mul_pow(10, 1);
        }
    };
    // Round the last digit up when only rounding up stays in the interval, or when both do
    // and the rest is at least half a unit of it.
    mant.mul_pow(2, 1);
    if up && (!down || mant.cmp(&scale) != Ordering::Less) {
        match buf[..n].iter().rposition(|&c| c != b'9') {
            Some(i) => {
                buf[i] += 1;
                buf[i + 1..n].fill(b'0');
            }
            None => {
                // 9…9 becomes 10…0: one more digit, and k one higher.
                buf[0] = b'1';
                buf[1..=n].fill(b'0');
                n += 1;
                k += 1;
            }
        }
    }
    (n, k)
}

/// Words of [`Big`]: 1,280 bits, the standard library's `Big32x40` (the largest number is
/// below 2^1,200: a 55-bit mantissa times 2^971 or times 10^342).
const WORDS: usize = 40;

/// A non-negative integer in base 2³², least significant word first, in a fixed array of which
/// the first `len` words are in use (the rest are zero). Every operation runs over the words in
/// use, a loop whose length the compiler does not know: over all 40 it would unroll each loop
/// 40 times, 2.6 KB more wasm per module (issue 25, wasm size).
#[derive(Clone)]
struct Big {
    w: [u32; WORDS],
    len: usize,
}

impl Big {
    fn from_u64(v: u64) -> Self {
        let mut w = [0; WORDS];
        w[0] = v as u32;
        w[1] = (v >> 32) as u32;
        Big { w, len: 2 }
    }

    /// Puts a final carry in the next word (there is always room: the numbers stay below
    /// 2^1,200).
    fn push(&mut self, carry: u64) {
        if carry != 0
            && let Some(w) = self.w.get_mut(self.len)
        {
            *w = carry as u32;
            self.len += 1;
        }
    }

    /// self ·= baseⁿ (base 2 or 10), in factors that fit in a word.
    fn mul_pow(&mut self, base: u32, mut n: u32) {
        let (step, big) = if base == 2 {
            (31, 1 << 31)
        } else {
            (9, 1_000_000_000)
        };
        while n > 0 {
            let now = n.min(step);
            let m = if now == step { big } else { base.pow(now) };
            let mut carry = 0u64;
            for w in self.w.iter_mut().take(self.len) {
                let t = u64::from(*w) * u64::from(m) + carry;
                *w = t as u32;
                carry = t >> 32;
            }
            self.push(carry);
            n -= now;
        }
    }

    #[inline(never)]
    fn plus(&self, other: &Big) -> Big {
        let mut out = self.clone();
        out.len = self.len.max(other.len);
        let mut carry = 0u64;
        for (w, &o) in out.w.iter_mut().zip(&other.w).take(out.len) {
            let t = u64::from(*w) + u64::from(o) + carry;
            *w = t as u32;
            carry = t >> 32;
        }
        out.push(carry);
        out
    }

    /// self −= other, for self ≥ other.
    #[inline(never)]
    fn sub_assign(&mut self, other: &Big) {
        let mut borrow = 0u64;
        let n = self.len.max(other.len);
        for (w, &o) in self.w.iter_mut().zip(&other.w).take(n) {
            let t = u64::from(*w)
                .wrapping_sub(u64::from(o))
                .wrapping_sub(borrow);
            *w = t as u32;
            borrow = t >> 63;
        }
        self.len = n;
    }

    fn cmp(&self, other: &Big) -> Ordering {
        let n = self.len.max(other.len);
        let (a, b) = (self.w.iter().take(n), other.w.iter().take(n));
        a.rev().cmp(b.rev())
    }
}

#[cfg(test)]
mod tests {
    use super::Decimal;
    use crate::math::rng::SplitMix64;
    use alloc::format;

    fn check(x: f64) {
        assert_eq!(
            format!("{}", Decimal(x)),
            format!("{x}"),
            "bits {:#x}",
            x.to_bits()
        );
    }

    #[test]
    fn edges_of_the_format() {
        for x in [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.1,
            0.3,
            1.5,
            -0.1,
            1.0 + 1e-12,
            1e-7,
            1e-5,
            123.456,
            1e15,
            1e16,
            1e21,
            1e22,
            1e23,
            f64::from_bits(0x44b5_2d02_c7e1_4af5),
            5e-324,
            -5e-324,
            1e-323,
            2.225_073_858_507_201e-308,
            2.225_073_858_507_201_4e-308,
            f64::MIN_POSITIVE,
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            -f64::NAN,
            0.5,
            2.0,
            1024.0,
            9.5,
            0.95,
            99.999_999_999_999_99,
            core::f64::consts::PI,
            4.35e6,
        ] {
            check(x);
        }
        for e in -1074..=1023 {
            check(libm::ldexp(1.0, e));
            check(f64::from_bits(libm::ldexp(1.0, e).to_bits() - 1));
            check(f64::from_bits(libm::ldexp(1.0, e).to_bits() + 1));
        }
        for p in -325..=308 {
            let x: f64 = format!("1e{p}").parse().unwrap_or(0.0);
            check(x);
            check(f64::from_bits(x.to_bits().wrapping_add(1)));
        }
    }

    #[test]
    fn agrees_with_std_on_random_bits() {
        let mut rng = SplitMix64::new(0x0dec_13a1);
        for _ in 0..1_000_000 {
            check(f64::from_bits(rng.next_u64()));
        }
        // Short decimals, the common case in messages.
        for i in 0..100_000u32 {
            check(f64::from(i) / 1000.0);
            check(f64::from(i) * 1e-9);
        }
    }
}
