//! Exact geometric predicates for the inclusion tests: a floating-point filter with a
//! rigorous error bound, and an exact fallback by error-free transformations (two-sum,
//! two-product) and Shewchuk's expansion arithmetic.
//!
//! The answers are the exact signs for the given `f64` inputs as long as no intermediate
//! product underflows or overflows (coordinates of magnitude between about 1e-140 and 1e140).
//!
//! # References
//! J. R. Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
//! predicates," Discrete Comput. Geom. 18:305–363, 1997. doi:10.1007/PL00009321.

use core::cmp::Ordering;

use alloc::vec::Vec;

use crate::math::fns;

/// Unit roundoff 2⁻⁵³.
pub(crate) const EPS: f64 = 1.110_223_024_625_156_5e-16;

#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let err = (a - (s - bb)) + (b - bb);
    (s, err)
}

#[inline]
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    // libm's fma is correctly rounded on every target, so a·b − p is exact.
    (p, libm::fma(a, b, -p))
}

/// An exact sum of `f64` terms, kept as a nonoverlapping expansion (increasing magnitude).
struct Expansion(Vec<f64>);

impl Expansion {
    fn new() -> Self {
        Self(Vec::with_capacity(16))
    }

    /// Adds `b` exactly (Shewchuk's Grow-Expansion with zero elimination).
    fn add(&mut self, b: f64) {
        let mut q = b;
        let mut out = Vec::with_capacity(self.0.len() + 1);
        for &e in &self.0 {
            let (s, h) = two_sum(q, e);
            if h != 0.0 {
                out.push(h);
            }
            q = s;
        }
        if q != 0.0 {
            out.push(q);
        }
        self.0 = out;
    }

    /// The sign of the exact sum: that of its largest component.
    fn sign(&self) -> Ordering {
        match self.0.last() {
            Some(&x) if x > 0.0 => Ordering::Greater,
            Some(&x) if x < 0.0 => Ordering::Less,
            _ => Ordering::Equal,
        }
    }
}

fn sign_of(x: f64) -> Ordering {
    if x > 0.0 {
        Ordering::Greater
    } else if x < 0.0 {
        Ordering::Less
    } else {
        Ordering::Equal
    }
}

/// The exact sign of (a − c) × (b − c): `Greater` when a, b, c turn counter-clockwise,
/// `Less` when clockwise, `Equal` when collinear.
pub(crate) fn orient2d(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Ordering {
    let left = (a[0] - c[0]) * (b[1] - c[1]);
    let right = (a[1] - c[1]) * (b[0] - c[0]);
    let det = left - right;
    // Shewchuk's ccwerrboundA = (3 + 16ε)ε.
    let bound = (3.0 + 16.0 * EPS) * EPS * (fns::abs(left) + fns::abs(right));
    if fns::abs(det) > bound {
        return sign_of(det);
    }
    // det = ax·by − ax·cy − cx·by − ay·bx + ay·cx + cy·bx, each product split exactly.
    let mut e = Expansion::new();
    for (x, y, s) in [
        (a[0], b[1], 1.0),
        (a[0], c[1], -1.0),
        (c[0], b[1], -1.0),
        (a[1], b[0], -1.0),
        (a[1], c[0], 1.0),
        (c[1], b[0], 1.0),
    ] {
        let (p, err) = two_product(s * x, y);
        e.add(err);
        e.add(p);
    }
    e.sign()
}

/// The exact sign of r² − |p − c|² (`Greater`: strictly inside the ball, `Equal`: on its
/// sphere, `Less`: outside). `p` and `c` have the same length.
///
/// The floating-point filter is inlined; the exact expansion arithmetic (for the points
/// within a few ulps of the sphere) is a separate, cold function.
#[inline]
pub(crate) fn ball_side(p: &[f64], c: &[f64], r: f64) -> Ordering {
    let mut d2 = 0.0;
    for (&x, &y) in p.iter().zip(c) {
        let d = x - y;
        d2 += d * d;
    }
    let r2 = r * r;
    let n = p.len() as f64;
    let bound = 4.0 * (n + 3.0) * EPS * (d2 + r2);
    let diff = r2 - d2;
    if fns::abs(diff) > bound {
        return sign_of(diff);
    }
    ball_side_exact(p, c, r)
}

/// Above this magnitude of an input, [`ball_side_exact`] rescales before it squares (2^500).
const BALL_SCALE_ABOVE: f64 = 3.273_390_607_896_142e150;

/// The exact sign of r² − |p − c|² by expansion arithmetic (the slow path of
/// [`ball_side`]).
#[cold]
#[inline(never)]
pub(crate) fn ball_side_exact(p: &[f64], c: &[f64], r: f64) -> Ordering {
    // Squares of differences above 2^1023 overflow, and the error terms of `two_product`
    // become NaN: scale every input by the same power of two first (exact, so the sign is
    // kept, but for parts below 2^−1022 of the scaled values, which flush to subnormals).
    let big = p.iter().chain(c).fold(
        fns::abs(r),
        |m, &x| if fns::abs(x) > m { fns::abs(x) } else { m },
    );
    if big > BALL_SCALE_ABOVE && big.is_finite() {
        let s = libm::scalbn(1.0, 400 - libm::ilogb(big));
        let ps: Vec<f64> = p.iter().map(|&x| x * s).collect();
        let cs: Vec<f64> = c.iter().map(|&x| x * s).collect();
        return ball_side_exact(&ps, &cs, r * s);
    }
    let mut e = Expansion::new();
    let (rr, rr_err) = two_product(r, r);
    e.add(rr_err);
    e.add(rr);
    for (&x, &y) in p.iter().zip(c) {
        // x − y = dh + dl exactly; (dh + dl)² = dh² + 2·dh·dl + dl².
        let (dh, dl) = two_sum(x, -y);
        for (u, v) in [(dh, dh), (2.0 * dh, dl), (dl, dl)] {
            let (q, q_err) = two_product(u, v);
            e.add(-q_err);
            e.add(-q);
        }
    }
    e.sign()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng, rngs::SmallRng};

    #[test]
    fn orientation_is_exact_where_the_naive_formula_fails() {
        // Points on the line y = x with coordinates near 0.5 (Kettner et al.'s classic
        // failure case): the naive determinant returns wrong and inconsistent signs, the exact
        // one says collinear for points that are exactly on the line.
        let a = [24.0, 24.0];
        let b = [12.0, 12.0];
        let mut rng = SmallRng::seed_from_u64(5);
        for _ in 0..2000 {
            let x = 0.5 + rng.random_range(0.0..1e-12);
            assert_eq!(orient2d(a, b, [x, x]), Ordering::Equal);
            let y = f64::from_bits(x.to_bits() + 1);
            // (x, next-up(x)) is strictly above y = x: a → b runs toward the origin, so the
            // point is on the right of it: clockwise.
            assert_eq!(orient2d(a, b, [x, y]), Ordering::Less);
            assert_eq!(orient2d(b, a, [x, y]), Ordering::Greater);
        }
        assert_eq!(
            orient2d([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]),
            Ordering::Greater
        );
    }

    #[test]
    fn orientation_agrees_with_exact_integer_arithmetic() {
        let mut rng = SmallRng::seed_from_u64(6);
        for _ in 0..20_000 {
            // Integer coordinates up to 2^40 scaled by a power of two: the determinant is an
            // exact i128 computation.
            let scale = 2f64.powi(rng.random_range(-30..30));
            let pts: Vec<[i64; 2]> = (0..3)
                .map(|_| {
                    let base = rng.random_range(-(1i64 << 40)..(1i64 << 40));
                    [
                        base + rng.random_range(-3..=3),
                        base + rng.random_range(-3..=3),
                    ]
                })
                .collect();
            let exact = {
                let [a, b, c] = [pts[0], pts[1], pts[2]].map(|p| [p[0] as i128, p[1] as i128]);
                let det = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]);
                det.cmp(&0)
            };
            let f = |p: [i64; 2]| [p[0] as f64 * scale, p[1] as f64 * scale];
            assert_eq!(orient2d(f(pts[0]), f(pts[1]), f(pts[2])), exact);
        }
    }

    #[test]
    fn ball_side_is_exact() {
        // 3-4-5 triangles at many scales: exactly on the circle.
        for e in -20..20 {
            let s = 2f64.powi(e);
            assert_eq!(
                ball_side(&[1.0 + 3.0 * s, 2.0 + 4.0 * s], &[1.0, 2.0], 5.0 * s),
                Ordering::Equal
            );
        }
        let r = 5.0;
        let p = [3.0, f64::from_bits(4f64.to_bits() + 1)];
        assert_eq!(ball_side(&p, &[0.0, 0.0], r), Ordering::Less);
        let p = [3.0, f64::from_bits(4f64.to_bits() - 1)];
        assert_eq!(ball_side(&p, &[0.0, 0.0], r), Ordering::Greater);
        // Far beyond √f64::MAX: |p − c|² overflows in the filter, the exact path rescales.
        assert_eq!(
            ball_side(&[1e300, -1e300], &[0.0, 0.0], 1.0),
            Ordering::Less
        );
        assert_eq!(
            ball_side(&[1e300, 0.0], &[0.0, 0.0], 2e300),
            Ordering::Greater
        );
        let s = 2f64.powi(1000);
        assert_eq!(
            ball_side(&[3.0 * s, 4.0 * s], &[0.0, 0.0], 5.0 * s),
            Ordering::Equal
        );
        assert_eq!(
            ball_side(
                &[3.0 * s, f64::from_bits((4.0 * s).to_bits() + 1)],
                &[0.0, 0.0],
                5.0 * s
            ),
            Ordering::Less
        );
        let mut rng = SmallRng::seed_from_u64(7);
        for _ in 0..10_000 {
            let p: Vec<f64> = (0..3).map(|_| rng.random_range(-1.0..1.0)).collect();
            let d = p.iter().map(|x| x * x).sum::<f64>().sqrt();
            let side = ball_side(&p, &[0.0; 3], 0.5);
            if (d - 0.5).abs() > 1e-12 {
                assert_eq!(side, (0.5f64).partial_cmp(&d).unwrap());
            }
        }
    }
}
