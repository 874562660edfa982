//! Recursive Gaussian splitting along region boundaries: Section IV of
//! `001_0f0df91eee9b30d5.txt` (K. A. LeGrand, S. Ferrari, "Split happens! Imprecise and
//! negative information in Gaussian mixture random finite set filtering," JAIF 2022).
//!
//! The posterior of "not detected in the field of view S" (or "inside region S") is the
//! prior times an indicator, eqs. (8)–(9): no longer a Gaussian mixture. The mean-based
//! partition (11)–(12) ([`partition`]) keeps or drops whole components by where their mean
//! lies, which is accurate only when the components near ∂S are small. Algorithms 1 and 2
//! ([`split_for_region`], [`split_for_regions`]) make them small: every component that
//! straddles a boundary (tested on a collocation grid in its whitened position space) is
//! split along its best direction with a precomputed univariate split ([`SplitLibrary`],
//! eqs. (13)–(14), applied by [`split_component`], eqs. (27)–(31)), recursively.
//!
//! - [`SplitLibrary`]: Table I verbatim, an optimiser for any R and λ with equally
//!   spaced or free symmetric means, and the variance-preserving library of the authors'
//!   `pyest` ([`SplitLibrary::variance_preserving`]).
//! - [`split_component`]: one split along an eigenvector; mean exact, covariance short by
//!   (1 − [`SplitLibrary::variance`]) λ_k along that eigenvector.
//! - [`split_for_regions`]: Algorithms 1–2 with w_min, the grid (ζ, N_g), the split
//!   direction (26) and its tie rule, k* (32), and caps on depth and size
//!   ([`SplitOptions`], [`SplitOutcome`]).
//! - [`partition`], [`partition_accuracy`]: (11)–(12) and their error against the exact
//!   region mass ([`crate::regions::Region::gaussian_mass`]).
//! - [`non_detection_update`], [`NegativeInformationScenario`]: the non-detection update
//!   (57)–(58) and the Fig. 5 example.
//!
//! | item | paper | tested by (`tests::` unless named) |
//! |---|---|---|
//! | [`SplitLibrary::table_i`] | Table I | `table1_is_shipped_verbatim`, `table1_optimiser_reproduces_it_to_the_notes_tolerance` |
//! | [`SplitLibrary`] optimiser, [`SplitLibrary::variance_preserving`] | (13)–(14) | `eq13_free_means_split_has_lower_objective`, `eq13_r3_entry_matches_the_reference_optimum`, `eq13_optimised_entries_are_valid_local_minima`, `filters::tests::eq13_variance_preserving_constants_are_the_optimiser_output` |
//! | [`split_component`] | (27)–(31) | `eq27_split_preserves_the_mean_and_removes_the_library_variance_defect`, `split_component_rejects_bad_arguments` |
//! | [`split_for_region`], [`split_for_regions`] | Algorithms 1 and 2, (26), (32) | `alg1_is_alg2_with_one_region`, `alg2_does_not_depend_on_the_order_of_the_regions`, `alg2_components_away_from_boundaries_or_too_light_are_not_split`, `eq26_split_direction_follows_the_boundary_and_ties_go_to_the_largest_eigenvalue`, `eq32_full_state_direction_is_the_best_aligned_eigenvector`, `caps_stop_the_recursion_and_say_so`, `extreme_inputs_give_sane_results_or_typed_errors` |
//! | [`partition`], [`partition_accuracy`] | (11)–(12) | `eq11_partition_splits_the_weight_by_the_means`, `eq11_partition_error_falls_as_the_recursion_deepens` |
//! | [`split_work`], [`grid_size`], [`exact_mass_affordable`], [`check_bounded_split`] and the caps | the worst-case work of Algorithm 2 and of the exact mass of (8) | `budget::tests::alg2_work_and_grid_caps`, `budget::tests::alg2_bounded_request_names_the_first_field_out_of_range` |
//! | [`non_detection_update`] | (57)–(58) | `eq57_non_detection_update_reweights_by_the_mean_based_partition` |
//! | [`NegativeInformationScenario`] | Fig. 5 | `fig5_negative_information_scenario`, `fig5_accuracy_improves_with_a_smaller_min_weight`, `filters::tests::fig5_no_report_reduces_to_the_negative_information_scenario` |
//!
//! Mixture reduction after an update is in [`crate::mixture`].
//!
//! ```
//! use fisst::gaussian::{Gaussian, GaussianMixture};
//! use fisst::regions::Region;
//! use fisst::splitting::{SplitLibrary, SplitOptions, non_detection_update, split_for_region};
//! // A density straddling the FoV's left edge; the sensor saw nothing (p_D = 1).
//! let g = Gaussian::from_slices(&[-1.0, 0.0], &[1.0, 0.0, 0.0, 1.0], "prior[0]")?;
//! let prior = GaussianMixture::new(vec![(1.0, g)], "prior")?;
//! let fov = Region::axis_box(&[-1.0, -2.0], &[3.0, 2.0], "fov")?;
//! let library = SplitLibrary::table_i();
//! let split = split_for_region(&prior, &fov, &library, &SplitOptions::default())?;
//! let (posterior, p_miss) = non_detection_update(&split.mixture, &fov, 1.0)?;
//! // The exact non-detection probability is 1 − P(x ∈ FoV) ≈ 0.52.
//! assert!((p_miss - 0.52).abs() < 0.03);
//! assert!(posterior.len() > 10);
//! # Ok::<(), fisst::Error>(())
//! ```
//!
//! # References
//! - `001_0f0df91eee9b30d5.txt`, Section IV (eqs. (10)–(35), Algorithms 1 and 2, Fig. 5,
//!   Appendix A) and Section V-B (eqs. (57)–(58)).
//! - K. J. DeMars, R. H. Bishop, M. K. Jah, "Entropy-based approach for uncertainty
//!   propagation of nonlinear dynamical systems," J. Guid. Control Dyn. 36(4):1047–1057,
//!   2013, doi:10.2514/1.58987 — the split library and the multivariate split (reference 34 of `001`).
mod budget;
mod component;
mod library;
mod negative_information;
mod objective;
mod optimise;
mod partition;
mod recursive;
mod request;
mod variance_preserving;

pub use budget::{
    EXACT_MASS_BUDGET_US, MAX_GRID_SIZE, MAX_POSITION_DIMS, MAX_REDUCE_INPUT,
    MAX_REDUCED_COMPONENTS, MAX_REGIONS, MAX_RUNNALLS_INPUT, MAX_SPLIT_RESULT_COMPONENTS,
    ReduceMixtureOptions, SPLIT_WORK_BUDGET, check_bounded_split, check_reduce_input,
    exact_mass_affordable, grid_size, split_work,
};
pub use component::{Eigen, split_component};
pub use library::{
    MAX_LAMBDA, MAX_SPLIT_COMPONENTS, MIN_LAMBDA, MIN_SPLIT_COMPONENTS, Spacing, SplitLibrary,
};
pub use negative_information::{
    NegativeInformationScenario, NegativeInformationStep, constant_velocity, non_detection_update,
    predict,
};
pub use partition::{Partition, PartitionAccuracy, partition, partition_accuracy};
pub use recursive::{
    MAX_DEPTH_LIMIT, MAX_GRID_POINTS, SplitOptions, SplitOutcome, SplitStop, defaults,
    split_for_region, split_for_regions,
};
pub use request::{
    NegativeInformationOptions, NegativeInformationReport, NegativeInformationResult,
    NegativeInformationStepReport, SplitForRegionsOptions, SplitForRegionsReport,
    SplitLibraryOptions, SplitLibraryReport, split_for_regions_report,
};
#[cfg(test)]
pub(crate) use variance_preserving::optimise as variance_preserving_optimise;
#[cfg(test)]
mod tests;
