//! n_s ≥ 3: the nested quadrature. Condition on the first whitened component z₁ and
//! integrate the (n_s − 1)-dimensional mass of the slice of the region tree against φ(z₁)
//! by adaptive Gauss–Kronrod over |z₁| ≤ 9, with breakpoints where the slice changes shape
//! (see [`Region::gaussian_mass`](crate::regions::Region::gaussian_mass)).

use alloc::boxed::Box;
use alloc::vec;
use alloc::vec::Vec;

use super::{Quad, integrate_smooth_ends};
use crate::gaussian::normal;
use crate::math::fns;

use super::{MAX_INTERVALS, Shape, mass_of};

/// Standardised half-width beyond which the nested quadrature truncates each conditioning
/// variable: 2Φ(−9) ≈ 2.3e-19 of mass is dropped per level.
const Z_MAX: f64 = 9.0;

impl Shape {
    /// The slice {s' : (t, s') ∈ S}, one dimension lower. Polygons are 2D and are never
    /// sliced (2D regions go to the ray method).
    fn slice(&self, t: f64) -> Shape {
        match self {
            Shape::Empty => Shape::Empty,
            Shape::Full => Shape::Full,
            Shape::Box { min, max } => {
                if min[0] <= t && t <= max[0] {
                    Shape::Box {
                        min: min[1..].to_vec(),
                        max: max[1..].to_vec(),
                    }
                } else {
                    Shape::Empty
                }
            }
            Shape::Ball { center, radius } => {
                let d = t - center[0];
                let r2 = radius * radius - d * d;
                if r2 > 0.0 {
                    Shape::Ball {
                        center: center[1..].to_vec(),
                        radius: fns::sqrt(r2),
                    }
                } else {
                    Shape::Empty
                }
            }
            Shape::Polygon(_) => Shape::Empty,
            Shape::Union(m) => {
                let parts: Vec<Shape> = m
                    .iter()
                    .map(|s| s.slice(t))
                    .filter(|s| !matches!(s, Shape::Empty))
                    .collect();
                if parts.iter().any(|s| matches!(s, Shape::Full)) {
                    Shape::Full
                } else if parts.is_empty() {
                    Shape::Empty
                } else {
                    Shape::Union(parts)
                }
            }
            Shape::Inter(m) => {
                let parts: Vec<Shape> = m
                    .iter()
                    .map(|s| s.slice(t))
                    .filter(|s| !matches!(s, Shape::Full))
                    .collect();
                if parts.iter().any(|s| matches!(s, Shape::Empty)) {
                    Shape::Empty
                } else if parts.is_empty() {
                    Shape::Full
                } else {
                    Shape::Inter(parts)
                }
            }
            Shape::Compl(r) => match r.slice(t) {
                Shape::Empty => Shape::Full,
                Shape::Full => Shape::Empty,
                s => Shape::Compl(Box::new(s)),
            },
        }
    }

    /// First-coordinate values where the slice changes shape.
    fn first_axis_breaks(&self, out: &mut Vec<f64>) {
        match self {
            Shape::Empty | Shape::Full | Shape::Polygon(_) => {}
            Shape::Box { min, max } => {
                out.push(min[0]);
                out.push(max[0]);
            }
            Shape::Ball { center, radius } => {
                out.push(center[0] - radius);
                out.push(center[0] + radius);
            }
            Shape::Union(m) | Shape::Inter(m) => m.iter().for_each(|s| s.first_axis_breaks(out)),
            Shape::Compl(r) => r.first_axis_breaks(out),
        }
    }
}

/// The mass of `shape` under N(m, L Lᵀ) for n ≥ 3: the outer quadrature over z₁ of
/// φ(z₁) times the mass of the slice; the error adds the outer estimate and the largest
/// inner one.
pub(super) fn mass_nested(shape: &Shape, m: &[f64], l: &[f64], tol: f64) -> Quad {
    let n = m.len();
    let l00 = l[0];
    let mut breaks = Vec::new();
    shape.first_axis_breaks(&mut breaks);
    let mut pts: Vec<f64> = breaks
        .into_iter()
        .map(|t| (t - m[0]) / l00)
        .filter(|z| z.is_finite() && fns::abs(*z) < Z_MAX)
        .collect();
    pts.push(-Z_MAX);
    pts.push(Z_MAX);
    crate::math::sort::sort_f64(&mut pts);
    pts.dedup();
    // Sub-block of L and the column that shifts the conditional mean.
    let k = n - 1;
    let mut sub = vec![0.0; k * k];
    for i in 0..k {
        for j in 0..=i {
            sub[i * k + j] = l[(i + 1) * n + (j + 1)];
        }
    }
    let col: Vec<f64> = (1..n).map(|i| l[i * n]).collect();
    let inner_tol = tol * 0.1;
    let mut worst_inner = 0.0f64;
    let mut cm = vec![0.0; k];
    let q = integrate_smooth_ends(
        |z: f64| {
            let t = m[0] + l00 * z;
            let slice = shape.slice(t);
            for i in 0..k {
                cm[i] = m[i + 1] + col[i] * z;
            }
            let inner = mass_of(&slice, &cm, &sub, inner_tol);
            worst_inner = worst_inner.max(inner.error);
            normal::pdf(z) * inner.value
        },
        &pts,
        tol,
        MAX_INTERVALS,
    );
    Quad {
        value: q.value,
        error: q.error + worst_inner + 3e-19,
    }
}
