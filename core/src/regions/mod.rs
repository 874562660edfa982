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
//!
//! | item | paper `001` | tested by |
//! |---|---|---|
//! | [`Region::contains`] | 1_S of (6) | `mass::tests::eq8_inclusion_tests_and_boundaries`, `mass::tests::eq8_unions_intersections_and_complements`, `predicates::tests::ball_side_is_exact`, `predicates::tests::orientation_is_exact_where_the_naive_formula_fails`, `predicates::tests::orientation_agrees_with_exact_integer_arithmetic` |
//! | [`Region::gaussian_mass`] | ⟨1_S, N(m, P)⟩, the integral of (8) | `mass::tests::eq8_box_2d_is_the_bivariate_rectangle_and_the_ray_method_agrees`, `mass::tests::eq8_discs_match_closed_forms`, `mass::tests::eq8_discs_and_polygons_match_the_slab_oracle_and_monte_carlo`, `mass::tests::eq8_self_intersecting_polygons_follow_the_even_odd_rule`, `mass::tests::eq8_one_dimensional_regions_are_exact`, `mass::tests::eq8_higher_dimensions_against_closed_forms`, `mass::tests::eq8_extra_state_components_are_ignored_and_dimensions_checked` |
//! | [`Region::mass_cost_us`] | the cost of one mass of (8), a model of the methods' native time | `mass::cost::tests::eq8_mass_cost_follows_the_method_of_each_region` |
//! | [`bivariate_normal`] | the 2D box masses of (8) (Genz 2004) | `bivariate_normal::tests::matches_high_precision_references`, `bivariate_normal::tests::closed_forms_symmetries_and_limits`, `bivariate_normal::tests::rectangles_sum_to_one_and_are_continuous_in_rho` |

mod axis_box;
mod ball;
pub mod bivariate_normal;
mod compiled;
mod mass;
mod polygon;
mod predicates;

pub use axis_box::AxisBox;
pub use ball::Ball;
pub use mass::{MAX_MASS_DIM, Mass};
pub use polygon::{MAX_VERTICES, Polygon};

pub(crate) use compiled::{Hull, RegionSet};

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

/// The most members of one union or intersection (a user's list of regions is bounded here;
/// nesting is bounded by the readers' depth caps).
pub const MAX_MEMBERS: usize = 1_000;

fn same_dims(members: &[Region], what: &str) -> Result<()> {
    Error::check_count(what, "members", members.len(), 0, MAX_MEMBERS)?;
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
    /// [`Error::Count`] naming `what` for more than [`MAX_MEMBERS`] members;
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

    /// A conservative classification of the closed ball of `radius` about the first
    /// `dim()` components of `center`: `Some(true)` when the whole ball is inside the
    /// region, `Some(false)` when it is wholly outside, `None` when undecided (the ball may
    /// straddle the boundary). Never wrong when it decides; used to skip regions far from a
    /// component in the splitting test.
    pub(crate) fn ball_relation(&self, center: &[f64], radius: f64) -> Option<bool> {
        match &self.node {
            Node::Box(b) => {
                let (lo, hi) = (b.min(), b.max());
                let mut d2 = 0.0;
                let mut inside = true;
                for i in 0..lo.len() {
                    let c = center[i];
                    let gap = if c < lo[i] {
                        lo[i] - c
                    } else if c > hi[i] {
                        c - hi[i]
                    } else {
                        0.0
                    };
                    d2 += gap * gap;
                    if !(c - radius >= lo[i] && c + radius <= hi[i]) {
                        inside = false;
                    }
                }
                if d2 > radius * radius {
                    Some(false)
                } else if inside {
                    Some(true)
                } else {
                    None
                }
            }
            Node::Ball(b) => {
                let c = b.center();
                let d2: f64 = c.iter().zip(center).map(|(a, x)| (a - x) * (a - x)).sum();
                let d = crate::math::fns::sqrt(d2);
                if d > b.radius() + radius {
                    Some(false)
                } else if d + radius < b.radius() {
                    Some(true)
                } else {
                    None
                }
            }
            Node::Polygon(p) => {
                let v = p.vertices();
                let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
                for q in v {
                    for k in 0..2 {
                        lo[k] = lo[k].min(q[k]);
                        hi[k] = hi[k].max(q[k]);
                    }
                }
                let mut d2 = 0.0;
                for k in 0..2 {
                    let c = center[k];
                    let gap = if c < lo[k] {
                        lo[k] - c
                    } else if c > hi[k] {
                        c - hi[k]
                    } else {
                        0.0
                    };
                    d2 += gap * gap;
                }
                if d2 > radius * radius {
                    Some(false)
                } else {
                    None
                }
            }
            Node::Union(m) => {
                let mut all_out = true;
                for r in m {
                    match r.ball_relation(center, radius) {
                        Some(true) => return Some(true),
                        Some(false) => {}
                        None => all_out = false,
                    }
                }
                if all_out { Some(false) } else { None }
            }
            Node::Intersection(m) => {
                let mut all_in = true;
                for r in m {
                    match r.ball_relation(center, radius) {
                        Some(false) => return Some(false),
                        Some(true) => {}
                        None => all_in = false,
                    }
                }
                if all_in { Some(true) } else { None }
            }
            Node::Complement(r) => r.ball_relation(center, radius).map(|b| !b),
        }
    }
}
