//! ⟨1_S, N(m, P)⟩: the probability mass of a Gaussian inside a region, the integral of
//! eq. (8) of `001_…` (LeGrand, Ferrari, *Split Happens!*) and the ⟨1_S, p⟩ its Section VI
//! builds every field-of-view pmf from.
//!
//! This file holds the public entry points ([`Region::gaussian_mass`], [`Mass`]), the region
//! tree `Shape` the methods share, the dispatch by dimension and the 2D box (Genz's bivariate
//! rectangle); the other methods live in
//! - `intervals`: interval-set algebra and the exact n_s = 1 mass,
//! - `ray_tree`: the ray method for other 2D regions, in whitened coordinates,
//! - `nested`: the nested quadrature for n_s = 3, 4 (slicing the region tree).

use alloc::boxed::Box;
use alloc::vec;
use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::gaussian::Gaussian;
use crate::math::fns;

use super::{Node, Region, bivariate_normal};
use crate::math::quadrature::{self as q, Control, Rule, Tolerance};

mod intervals;
mod nested;
mod ray_tree;

use intervals::mass_1d;
use nested::mass_nested;
use ray_tree::mass_ray_2d;

/// A mass (or integral) with its error estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Quad {
    /// The value.
    pub value: f64,
    /// Its error estimate.
    pub error: f64,
}

/// ∫ f over the sub-intervals of `points` with [`q::smooth_ends`] applied, by the masses'
/// rule: [`Rule::G7K15`] of [`math::quadrature`](crate::math::quadrature), bisecting until the
/// summed |K₁₅ − G₇| estimates are at most `abs_tol` or `max_intervals` pieces are in use.
pub(crate) fn integrate_smooth_ends(
    f: impl FnMut(f64) -> f64,
    points: &[f64],
    abs_tol: f64,
    max_intervals: usize,
) -> Quad {
    let control = Control::new(Rule::G7K15, Tolerance::Absolute(abs_tol), max_intervals);
    let e = q::integrate_smooth_ends(f, points, &control);
    Quad {
        value: e.value,
        error: e.error,
    }
}

/// The largest region dimension [`Region::gaussian_mass`] serves (n_s ≥ 3 uses nested
/// quadrature whose cost grows exponentially with n_s).
pub const MAX_MASS_DIM: usize = 4;

/// Default absolute tolerance of the quadratures (2D rays and the nested n_s ≥ 3 levels).
const DEFAULT_TOL: f64 = 1e-13;
/// Interval cap of an adaptive quadrature.
const MAX_INTERVALS: usize = 4000;

/// A probability mass and an estimate of its absolute error.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Mass {
    /// ⟨1_S, N(m, P)⟩ ∈ [0, 1].
    pub value: f64,
    /// An estimate of |value − exact| (see [`Region::gaussian_mass`] for what backs it).
    pub error: f64,
}

impl Region {
    /// ⟨1_S, N(m, P)⟩ = P(s ∈ S) for x ~ N(m, P), s the first n_s = `self.dim()` components
    /// of x: the integral of eq. (8) of `001_…` (`p_S`), and the quantity ⟨1_S, p⟩ its
    /// Section VI builds every field-of-view pmf from. Only the marginal N(m_s, P_s) of the
    /// first n_s components matters; its Cholesky factor is the leading block of the full one.
    ///
    /// ```text
    /// ⟨1_S, N(m, P)⟩ = ∫_S N(s; m_s, P_s) ds
    /// ```
    ///
    /// # Methods and accuracy
    /// - **n_s = 1**: the region is a finite union of intervals, found exactly; the mass is
    ///   a sum of Φ differences taken in the accurate tail. Error ≈ 1e-16 per interval.
    /// - **a 2D box**: the bivariate normal rectangle probability
    ///   ([`bivariate_normal::rectangle`], Genz's method). Error below 1e-14 (reported as
    ///   1e-14).
    /// - **any other 2D region** (polygon, disc, unions, intersections, complements):
    ///   whiten with the Cholesky factor L (s = m + L z), so z is standard normal and the
    ///   region maps to polygons, parallelograms and ellipses; along the ray z = ρ(cos θ,
    ///   sin θ) the region is a set of segments [ρ₁, ρ₂], whose mass is exact, and
    ///
    ///   ```text
    ///   ⟨1_S, N(m, P)⟩ = (1/2π) ∫₀^{2π} Σ_{segments} ( e^{−ρ₁²/2} − e^{−ρ₂²/2} ) dθ
    ///   ```
    ///
    ///   by adaptive Gauss–Kronrod (7–15) with breakpoints at every vertex direction,
    ///   every direction parallel to a box face, every tangent direction of a disc, and every
    ///   crossing of two boundaries (except two discs'), and a substitution that removes
    ///   the √ behaviour at tangents. The returned error is the sum of the |K₁₅ − G₇|
    ///   estimates (target: `abs_tol`, default 1e-13) — an estimate, not a proof.
    /// - **n_s = 3, 4**: condition on the first whitened component z₁ and integrate the
    ///   (n_s − 1)-dimensional mass of the slice against φ(z₁) by adaptive Gauss–Kronrod over
    ///   |z₁| ≤ 9 (dropping < 2.3e-19), with breakpoints where the slice changes shape; the
    ///   error adds the outer estimate and the largest inner one.
    /// - a **complement** at the top is 1 − the mass of what it complements.
    ///
    /// # Errors
    /// [`Error::DimensionMismatch`] naming `{what}.mean` if the Gaussian has fewer than n_s
    /// components (`what` is how the caller names the Gaussian, e.g. `rfs.poisson[1]`);
    /// [`Error::Unsupported`] for n_s > [`MAX_MASS_DIM`].
    ///
    /// # Examples
    /// ```
    /// use fisst::gaussian::Gaussian;
    /// use fisst::regions::Region;
    /// // A disc of radius 1 centred on the mean of N(0, I): mass 1 − e^{−1/2}.
    /// let g = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0], "p")?;
    /// let disc = Region::ball(&[0.0, 0.0], 1.0, "fov")?;
    /// let m = disc.gaussian_mass(&g, "p")?;
    /// assert!((m.value - (1.0 - (-0.5f64).exp())).abs() < 1e-13);
    /// # Ok::<(), fisst::Error>(())
    /// ```
    pub fn gaussian_mass(&self, gaussian: &Gaussian, what: &str) -> Result<Mass> {
        self.gaussian_mass_with_tolerance(gaussian, what, DEFAULT_TOL)
    }

    /// [`Region::gaussian_mass`] with the absolute tolerance of the adaptive quadratures
    /// (values below 1e-15 are raised to it; a 2D box or a 1D region is exact regardless).
    ///
    /// # Errors
    /// As [`Region::gaussian_mass`].
    pub fn gaussian_mass_with_tolerance(
        &self,
        gaussian: &Gaussian,
        what: &str,
        abs_tol: f64,
    ) -> Result<Mass> {
        let ns = self.dim();
        if gaussian.dim() < ns {
            return Err(Error::dimension(
                alloc::format!("{what}.mean"),
                ns,
                gaussian.dim(),
            ));
        }
        if ns > MAX_MASS_DIM {
            return Err(Error::Unsupported {
                what: alloc::format!("{what}.mean"),
                reason: "Gaussian masses of regions of more than 4 dimensions are not supported",
            });
        }
        let tol = if abs_tol.is_nan() {
            DEFAULT_TOL
        } else {
            abs_tol.max(1e-15)
        };
        let m: Vec<f64> = gaussian.mean().iter().take(ns).copied().collect();
        let chol = gaussian.chol();
        let mut l = vec![0.0; ns * ns];
        for i in 0..ns {
            for j in 0..=i {
                l[i * ns + j] = chol[(i, j)];
            }
        }
        let shape = Shape::from_region(self);
        let q = mass_of(&shape, &m, &l, tol);
        Ok(Mass {
            value: q.value.clamp(0.0, 1.0),
            error: q.error,
        })
    }
}

/// The region as a tree that can be sliced (a slice of a box is a box, of a ball a ball).
#[derive(Clone, Debug)]
enum Shape {
    Empty,
    Full,
    Box { min: Vec<f64>, max: Vec<f64> },
    Ball { center: Vec<f64>, radius: f64 },
    Polygon(Vec<[f64; 2]>),
    Union(Vec<Shape>),
    Inter(Vec<Shape>),
    Compl(Box<Shape>),
}

impl Shape {
    fn from_region(r: &Region) -> Shape {
        match r.node() {
            Node::Box(b) => Shape::Box {
                min: b.min().to_vec(),
                max: b.max().to_vec(),
            },
            Node::Polygon(p) => Shape::Polygon(p.vertices().to_vec()),
            Node::Ball(b) => Shape::Ball {
                center: b.center().to_vec(),
                radius: b.radius(),
            },
            Node::Union(m) => Shape::Union(m.iter().map(Shape::from_region).collect()),
            Node::Intersection(m) => Shape::Inter(m.iter().map(Shape::from_region).collect()),
            Node::Complement(r) => Shape::Compl(Box::new(Shape::from_region(r))),
        }
    }
}

/// The mass of `shape` under N(m, L Lᵀ), L lower-triangular row-major n × n.
fn mass_of(shape: &Shape, m: &[f64], l: &[f64], tol: f64) -> Quad {
    let n = m.len();
    match shape {
        Shape::Empty => {
            return Quad {
                value: 0.0,
                error: 0.0,
            };
        }
        Shape::Full => {
            return Quad {
                value: 1.0,
                error: 0.0,
            };
        }
        Shape::Compl(inner) => {
            let q = mass_of(inner, m, l, tol);
            return Quad {
                value: 1.0 - q.value,
                error: q.error,
            };
        }
        _ => {}
    }
    match n {
        1 => mass_1d(shape, m[0], l[0]),
        2 => {
            if let Shape::Box { min, max } = shape {
                mass_box_2d(min, max, m, l)
            } else {
                mass_ray_2d(shape, m, l, tol)
            }
        }
        _ => mass_nested(shape, m, l, tol),
    }
}

/// A 2D box: the bivariate normal rectangle probability.
fn mass_box_2d(min: &[f64], max: &[f64], m: &[f64], l: &[f64]) -> Quad {
    let s0 = l[0];
    let s1 = fns::sqrt(l[2] * l[2] + l[3] * l[3]);
    let rho = (l[2] / s1).clamp(-1.0, 1.0);
    let value = bivariate_normal::rectangle(
        (min[0] - m[0]) / s0,
        (max[0] - m[0]) / s0,
        (min[1] - m[1]) / s1,
        (max[1] - m[1]) / s1,
        rho,
    );
    Quad {
        value,
        error: 1e-14,
    }
}

#[cfg(test)]
mod tests;
