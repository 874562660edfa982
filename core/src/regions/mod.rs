//! Regions of the position subspace and the probability mass of a Gaussian inside them.
//!
//! Section III of `001_0f0df91eee9b30d5.txt` (LeGrand, Ferrari, "Split happens!") splits the
//! state as x = (s, v) with s ∈ 𝕏_s ⊆ ℝ^{n_s} the position-like components that decide
//! whether an object is in a sensor's field of view S ⊂ 𝕏_s, and defines
//!
//! ```text
//! 1_S(x) = 1 if s ∈ S, 0 otherwise                       (6)
//! ```
//!
//! A [`Region`] is such an S: an [`AxisBox`] (any dimension), a [`Polygon`] (2D, convex or
//! not), a [`Ball`] (a disc in 2D), or unions, intersections and complements of these. Its
//! dimension n_s is the number of leading state components it looks at: a state or a
//! Gaussian may have more components (velocities, …), which are ignored.
//!
//! ## Inclusion tests
//! [`Region::contains`] is exact for the given `f64` inputs: boxes use comparisons only,
//! polygons and balls a floating-point filter backed by exact expansion arithmetic.
//! Primitives are **closed** (boundary points are inside), so a complement is open.
//!
//! ## Gaussian masses
//! [`Region::gaussian_mass`] returns ⟨1_S, N(m, P)⟩ and an error estimate; see
//! [`Region::gaussian_mass`] for the methods and accuracies, and [`bivariate_normal`] for the
//! bivariate normal distribution function behind the 2D boxes.

mod axis_box;
mod ball;
pub mod bivariate_normal;
mod mass;
mod polygon;
mod predicates;
mod quadrature;

pub use axis_box::AxisBox;
pub use ball::Ball;
pub use mass::{MAX_MASS_DIM, Mass};
pub use polygon::Polygon;

use alloc::boxed::Box;
use alloc::vec::Vec;

use crate::error::{Error, Result};

/// A region S of the position subspace: a primitive or a union, intersection or complement of
/// regions of the same dimension.
#[derive(Clone, Debug, PartialEq)]
pub struct Region {
    node: Node,
}

#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Node {
    Box(AxisBox),
    Polygon(Polygon),
    Ball(Ball),
    Union(Vec<Region>),
    Intersection(Vec<Region>),
    Complement(Box<Region>),
}

impl From<AxisBox> for Region {
    fn from(b: AxisBox) -> Self {
        Region { node: Node::Box(b) }
    }
}

impl From<Polygon> for Region {
    fn from(p: Polygon) -> Self {
        Region {
            node: Node::Polygon(p),
        }
    }
}

impl From<Ball> for Region {
    fn from(b: Ball) -> Self {
        Region {
            node: Node::Ball(b),
        }
    }
}

fn same_dims(members: &[Region], what: &str) -> Result<()> {
    let Some(first) = members.first() else {
        return Err(Error::parameter(what, 0.0, "a non-empty list of regions"));
    };
    let dim = first.dim();
    for (i, m) in members.iter().enumerate() {
        if m.dim() != dim {
            return Err(Error::dimension(
                alloc::format!("{what}[{i}]"),
                dim,
                m.dim(),
            ));
        }
    }
    Ok(())
}

impl Region {
    /// The closed box `[min, max]` (see [`AxisBox::new`]).
    ///
    /// # Errors
    /// As [`AxisBox::new`].
    pub fn axis_box(min: &[f64], max: &[f64], what: &str) -> Result<Self> {
        AxisBox::new(min, max, what).map(Self::from)
    }

    /// The polygon with these vertices (see [`Polygon::new`]).
    ///
    /// # Errors
    /// As [`Polygon::new`].
    pub fn polygon(vertices: &[[f64; 2]], what: &str) -> Result<Self> {
        Polygon::new(vertices, what).map(Self::from)
    }

    /// The closed ball (a disc in 2D) (see [`Ball::new`]).
    ///
    /// # Errors
    /// As [`Ball::new`].
    pub fn ball(center: &[f64], radius: f64, what: &str) -> Result<Self> {
        Ball::new(center, radius, what).map(Self::from)
    }

    /// S₁ ∪ S₂ ∪ … (a point is inside when it is inside any member).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for an empty list, [`Error::DimensionMismatch`] naming
    /// `{what}[i]` for a member of another dimension than the first.
    pub fn union(members: Vec<Region>, what: &str) -> Result<Self> {
        same_dims(&members, what)?;
        Ok(Region {
            node: Node::Union(members),
        })
    }

    /// S₁ ∩ S₂ ∩ … (a point is inside when it is inside every member).
    ///
    /// # Errors
    /// As [`Region::union`].
    pub fn intersection(members: Vec<Region>, what: &str) -> Result<Self> {
        same_dims(&members, what)?;
        Ok(Region {
            node: Node::Intersection(members),
        })
    }

    /// C(S) = 𝕏_s ∖ S, the complement (eq. (9) of `001_…` writes C(S)). The complement of a
    /// closed region is open: boundary points of S are not in C(S).
    pub fn complement(region: Region) -> Self {
        Region {
            node: Node::Complement(Box::new(region)),
        }
    }

    /// The dimension n_s of the position subspace the region lives in.
    pub fn dim(&self) -> usize {
        match &self.node {
            Node::Box(b) => b.dim(),
            Node::Polygon(_) => 2,
            Node::Ball(b) => b.dim(),
            Node::Union(m) | Node::Intersection(m) => m.first().map_or(0, Region::dim),
            Node::Complement(r) => r.dim(),
        }
    }

    pub(crate) fn node(&self) -> &Node {
        &self.node
    }

    /// 1_S(x), eq. (6) of `001_…`: true when the first `dim()` components of `s` lie in the
    /// region. Exact for the given floating-point inputs; primitives are closed.
    ///
    /// # Panics
    /// If `s.len() < self.dim()`.
    ///
    /// # Examples
    /// ```
    /// use fisst::regions::Region;
    /// let fov = Region::polygon(&[[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]], "fov")?;
    /// assert!(fov.contains(&[1.0, 1.0, 7.0])); // on the hypotenuse; the velocity is ignored
    /// assert!(!Region::complement(fov).contains(&[1.0, 1.0]));
    /// # Ok::<(), fisst::Error>(())
    /// ```
    pub fn contains(&self, s: &[f64]) -> bool {
        match &self.node {
            Node::Box(b) => b.contains(s),
            Node::Polygon(p) => p.contains(s),
            Node::Ball(b) => b.contains(s),
            Node::Union(m) => m.iter().any(|r| r.contains(s)),
            Node::Intersection(m) => m.iter().all(|r| r.contains(s)),
            Node::Complement(r) => !r.contains(s),
        }
    }
}
