//! Field-of-view cardinality: the pmf of the number of objects inside a region S, and
//! sensor placement by its variance (Sections VI–VII of `001_0f0df91eee9b30d5.txt`,
//! LeGrand, Ferrari, "Split happens!").
//!
//! Every pmf of Section VI is a function of the masses ⟨1_S, p⟩ of the single-object
//! densities inside S:
//!
//! ```text
//! ρ_S(n) = ∫ ρ_S(n | X) f(X) δX,   ρ_S(n | X) = Σ_{Xⁿ ⊆ X} [1_S]^{Xⁿ} [1 − 1_S]^{X∖Xⁿ}   (72)–(73)
//! ```
//!
//! - [`pmf`]: the pmfs from those masses — [`poisson`] (78), [`iid_cluster`] (84),
//!   [`multi_bernoulli`] (88) (stable), [`multi_bernoulli_dft`] (90),
//!   [`multi_bernoulli_enumerated`] (88) by enumeration, [`glmb`] (92) — each with its mean
//!   and variance. The detection-count variant (75) with a constant p_D scales every mass by
//!   p_D.
//! - [`fov_cardinality`]: the same from Gaussian(-mixture) densities and a
//!   [`Region`](crate::regions::Region), with the masses by
//!   [`Region::gaussian_mass`](crate::regions::Region::gaussian_mass).
//! - [`variance_map`]: the FoV-count variance over a grid of FoV centres and its maximiser
//!   (Section VII).
//! - [`placement_scene`]: seeded random scenes like Section VII's (Figs 9–10), and
//!   [`mixture_density_grid`]: a Gaussian mixture (the PHD (99)) over a grid, for Fig. 9.

mod density;
mod density_grid;
mod placement;
pub mod pmf;
pub mod scene;

pub use density::{FovCount, MultiObjectDensity, fov_cardinality};
pub use density_grid::mixture_density_grid;
pub use placement::{GridAxis, MAX_GRID_AXIS, MAX_GRID_CELLS, VarianceMap, variance_map};
pub use pmf::{
    FovCardinality, GlmbHypothesis, glmb, iid_cluster, multi_bernoulli, multi_bernoulli_dft,
    multi_bernoulli_enumerated, poisson,
};
pub use scene::{MAX_SCENE_COUNT, SceneOptions, placement_scene};

#[cfg(test)]
mod tests;
