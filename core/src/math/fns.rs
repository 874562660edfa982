//! The only place that knows where float functions come from.
//!
//! Every transcendental function goes through the pure-Rust [`libm`] crate, with std or
//! without, so that a native build, a `wasm32` build and a `no_std` microcontroller build give
//! bit-identical results for the same inputs (std's `powf`/`exp` call the platform's C library
//! natively but compiler-builtins on wasm32, and those differ in the last bits).

/// √x, correctly rounded (IEEE 754 requires it of every implementation, so any correct
/// square root gives the same bits). With `std` this is the hardware instruction (`sqrtsd`,
/// wasm's `f64.sqrt`): libm's own wasm path needs nightly intrinsics and otherwise falls back
/// to a software square root about ten times slower. Without `std`, libm's.
#[inline]
pub fn sqrt(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        f64::sqrt(x)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::sqrt(x)
    }
}

/// xʸ.
#[inline]
pub fn pow(x: f64, y: f64) -> f64 {
    libm::pow(x, y)
}

/// eˣ.
#[inline]
pub fn exp(x: f64) -> f64 {
    libm::exp(x)
}

/// Natural logarithm.
#[inline]
pub fn ln(x: f64) -> f64 {
    libm::log(x)
}

/// ln(1 + x), accurate for small x.
#[inline]
pub fn ln_1p(x: f64) -> f64 {
    libm::log1p(x)
}

/// |x|.
#[inline]
pub fn abs(x: f64) -> f64 {
    libm::fabs(x)
}

/// x clamped to [lo, hi]: `f64::clamp`'s result, bit for bit (lo if x < lo, hi if x > hi, x
/// otherwise, so NaN stays NaN), without its panic for lo > hi or a NaN bound, whose message
/// prints both bounds with the standard library's float formatting, about 19 KB of every wasm
/// module that calls it with bounds not known at compile time (issue 25, wasm size). Callers
/// pass lo ≤ hi.
#[inline]
pub fn clamp(x: f64, lo: f64, hi: f64) -> f64 {
    if x < lo {
        lo
    } else if x > hi {
        hi
    } else {
        x
    }
}

/// xᵖ for the metric orders: exact shortcuts for p = 1 and p = 2, `pow` otherwise.
#[inline]
pub fn powp(x: f64, p: f64) -> f64 {
    if p == 1.0 {
        x
    } else if p == 2.0 {
        x * x
    } else {
        pow(x, p)
    }
}

/// x^(1/p), the inverse of [`powp`]: exact shortcuts for p = 1 and p = 2.
#[inline]
pub fn rootp(x: f64, p: f64) -> f64 {
    if p == 1.0 {
        x
    } else if p == 2.0 {
        sqrt(x)
    } else {
        pow(x, 1.0 / p)
    }
}

/// The four-quadrant arctangent of y/x, in (−π, π].
#[inline]
pub fn atan2(y: f64, x: f64) -> f64 {
    libm::atan2(y, x)
}

/// arccos x, in [0, π] (NaN outside [−1, 1]).
#[inline]
pub fn acos(x: f64) -> f64 {
    libm::acos(x)
}

/// The complementary error function erfc x = 1 − erf x, accurate in the upper tail.
#[inline]
pub fn erfc(x: f64) -> f64 {
    libm::erfc(x)
}

/// sin x.
#[inline]
pub fn sin(x: f64) -> f64 {
    libm::sin(x)
}

/// cos x.
#[inline]
pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}

/// arctan x, in (−π/2, π/2).
#[inline]
pub fn atan(x: f64) -> f64 {
    libm::atan(x)
}
