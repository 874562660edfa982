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
//!
//! | item | paper | tested by (`tests::` unless named) |
//! |---|---|---|
//! | [`poisson`] | (78) | `eq78_poisson_closed_form_is_the_series_and_the_simulation` |
//! | [`iid_cluster`] | (84) | `eq84_iid_cluster_matches_the_series_and_the_simulation` |
//! | [`multi_bernoulli`], [`multi_bernoulli_dft`], [`multi_bernoulli_enumerated`] | (88), (90) | `eq88_eq90_multi_bernoulli_forms_agree`, `eq88_multi_bernoulli_matches_the_simulation`, `cardinality::multi_bernoulli::tests::eq88_matches_enumeration` |
//! | [`glmb`] | (92) | `eq92_glmb_matches_the_simulation_and_reduces_to_multi_bernoulli` |
//! | [`fov_cardinality`] | (72)–(73) with the masses ⟨1_S, p⟩ | `front_door_names_fields`, `placement::tests::every_mass_matches_the_direct_bivariate_rectangle` |
//! | [`variance_map`] | Section VII, Fig. 10 | `placement::tests::fig10_variance_map_matches_the_pmf_and_finds_the_maximum`, `paper_001_fov::fig10_the_maximum_is_the_variance_of_the_pmf_there`, `paper_001_fov::fig10_no_grid_cell_exceeds_the_maximum`, `paper_001_fov::fig10_a_finer_search_gains_no_more_than_the_grid_step_allows`, `paper_001_fov::fig10_most_uncertain_is_not_most_populated`, `paper_001_fov::fig10_monte_carlo_of_the_rfs_matches_the_pmf_at_the_optimum` |
//! | [`fov_mass_work_us`], [`grid_work`] and their budgets | the cost of the masses of (72)–(73) and of the Section VII grids | `budget::tests::eq72_work_counts_every_mass_at_the_region_cost` |
//! | [`FovCardinalityOptions`], [`FovVarianceMapOptions`], [`MixtureDensityGridOptions`], [`Grid`] | the calls above with their caps and budgets | `options::tests::eq72_run_is_fov_cardinality_flattened`, `options::tests::eq72_caps_name_the_rust_fields`, `options::tests::eq72_the_mass_budget_names_rfs`, `options::tests::fig10_grid_axes_and_work_caps` |
//! | [`placement_scene`], [`PlacementScene`], [`mixture_density_grid`] | Figs 9–10, the PHD (99) | `scene::tests::scenes_follow_the_recipe`, `scene::tests::default_scene_is_pinned`, `density_grid::tests::sums_the_components_and_marginalises`, `paper_001_fov::fig9_the_phd_integrates_to_the_expected_counts`, `paper_001_fov::fig9_the_optimal_boundary_splits_components` |

mod budget;
mod density;
mod density_grid;
mod options;
mod placement;
pub mod pmf;
pub mod scene;

pub use budget::{
    FOV_MASS_BUDGET_US, MAX_CARDINALITY_LEN, MAX_DENSITY_GRID_WORK, MAX_VARIANCE_MAP_WORK,
    fov_mass_work_us, grid_work,
};
pub use density::{FovCount, IidCluster, MultiObjectDensity, fov_cardinality};
pub use density_grid::mixture_density_grid;
pub use options::{
    Axis, DEFAULT_DETECTION_PROBABILITY, FovCardinalityOptions, FovCardinalityResult,
    FovVarianceMapOptions, FovVarianceMapResult, Grid, MAX_VERTICES, MixtureDensityGridOptions,
};
pub use placement::{GridAxis, MAX_GRID_AXIS, MAX_GRID_CELLS, VarianceMap, variance_map};
pub use pmf::{
    FovCardinality, GlmbHypothesis, glmb, iid_cluster, multi_bernoulli, multi_bernoulli_dft,
    multi_bernoulli_enumerated, poisson,
};
pub use scene::{MAX_SCENE_COUNT, PlacementScene, SceneComponent, SceneOptions, placement_scene};

#[cfg(test)]
mod tests;
