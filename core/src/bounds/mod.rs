//! Error bounds for joint detection and estimation of a single object (paper `002`: M.
//! Rezaeian, B.-N. Vo, "Error bounds for joint detection and estimation of a single object
//! with random finite set observation").
//!
//! The state is a Bernoulli RFS X ~ B(r, f); the estimate X̂(Z) is ∅ or {x̂}; the error is the
//! metric e with e(∅, {x'}) = e0, e({x}, ∅) = e1 and e({x}, {x'}) = x − x'. The bounds are
//! on E e²(X, X̂(Z)) for MAP detection on Z ≠ ∅ and any rule on Z = ∅.
//!
//! | item | paper | tested by |
//! |---|---|---|
//! | [`assemble`], [`Ingredients`], [`Terms`] | the HPE/LPE bounds (47)–(48), (57)–(58); (17)/(21), (23)–(24) | `theorem2::tests::thm2_eta_bracket_takes_the_smaller_bound`, `vector::tests::eq72_one_component_is_the_scalar_bound` |
//! | [`corollary1`], [`corollary2`], [`corollary3`] | (27), (28), (29) | `closed::tests::cor2_with_no_clutter_is_cor1`; P: `cor3_is_what_the_theorems_reduce_to_without_clutter`, `cor2_is_an_asserted_target_with_clutter` |
//! | [`gaussian_no_clutter`], [`gaussian_fisher_information`] | (30)–(31), Example 1 (with NOTES.md's erratum) | `closed::tests::eq31_gaussian_form_is_cor3`, this module's doctest |
//! | [`map_threshold`], [`NoClutterBound::map_bound`] | Section IV-A: MAP detection on Z = ∅ moves r* to r_M* | `closed::tests::sec4a_map_threshold_equals_r_star_when_sigma_is_e1_minus_e0` |
//! | [`sequential_bound`] | IRF (35), Enumeration (37) | `closed::tests::eq35_eq37_enumeration_dominates_irf`; P: `fig3_enumeration_dominates_irf_and_they_meet` |
//! | [`Density`], [`Observation`] (closures with derivatives), [`Density1`], [`Detection`], [`LinearGaussian`] | f, P_o, g, ψ, v of models I (13) and II (22) | `model::tests::eq13_tables_name_the_knot_at_fault`, `model::tests::thm2_subnormal_variances_are_rejected_by_name`, `closed::tests::errors_name_the_field` |
//! | [`theorem1`], [`ModelI`] | Theorem 1 (14)–(21) by quadrature: P̄o, f_d, f_d', σ_e², Z'_0 by root-finding, w_1, η_1, J'_1 (20) | P: `thm1_is_attained_by_map_detection_and_the_posterior_mean`, `thm1_a_non_gaussian_prior_and_variable_detection_stay_below_the_mse` |
//! | [`theorem2`], [`ModelII`] | Theorem 2 (22)–(26): n = 1 by quadrature, n = 2 by 2D cubature over Z² with closed-form x-integrals in the linear-Gaussian case (the default there) or by Monte Carlo (the default otherwise; [`TheoremOptions::quadrature_cardinality`] chooses), n ≥ 3 by Monte Carlo; η2 exact (see [`theorem2`]'s module) | `theorem2::tests::thm2_n2_cubature_agrees_with_monte_carlo`, `thm2_n2_closed_form_equals_the_general_cubature`, `thm2_logistic_normal_agrees_with_adaptive_quadrature`, `thm2_n2_cubature_agrees_with_a_fine_grid_sum`, `thm2_each_cardinality_reports_its_method`, `thm2_series_is_cut_where_its_tail_is_below_the_tolerance`, `thm2_eta_bracket_takes_the_smaller_bound`; P: `thm2_lies_below_the_optimal_mse` |
//! | [`component_bound`], [`component_bounds_no_clutter`], [`component_corollary1`], [`gaussian_information_matrix`] | the vector extensions (63)–(72) | `vector::tests::eq72_one_component_is_the_scalar_bound`, `eq72_independent_components_split_the_scalar_error`; P: `eq72_vector_bounds_reduce_to_the_scalar_ones` |
//! | [`vector_bound`], [`VectorModel`], [`GaussianPrior`], [`LinearGaussianSensor`] | (63)–(65) for a Gaussian state in R^l and a linear-Gaussian sensor: per-component and whole-state bounds of Theorems 1 and 2 | `vector::tests::eq63_one_dimension_is_the_scalar_theorem`, `eq63_an_observed_component_with_false_alarms_is_the_scalar_theorem`, `eq65_the_rank_one_reduction_is_the_matrix_information_without_clutter`, `eq72_independent_components_are_corollary3_per_component`, `eq72_a_negligible_gain_is_no_gain`, `eq63_vector_errors_name_the_field`; P: `eq64_vector_bounds_against_the_optimal_detector_estimator` |
//! | [`jde_monte_carlo`], [`MonteCarloModel`], [`JdeMonteCarloOptions`], [`EmptyRule`] | the risk E e² (11) of the optimal joint detector-estimator (MAP detection (39)/(40), the posterior mean, HPE/LPE (46) or MAP on ∅ (Section IV-A)) by a seeded Monte Carlo; k scans (Section III-E) | `simulate::tests::cor3_the_optimal_detector_estimator_attains_the_no_clutter_bound`, `eq37_the_posterior_mean_over_scans_attains_the_enumeration_bound`, `ex2_the_posterior_mean_mse_is_below_the_regularity_failing_curve`, `eq11_same_seed_same_bits_and_another_seed_other_draws`, `eq11_bad_options_are_errors_naming_the_field`; P: `thm1_is_attained_by_map_detection_and_the_posterior_mean`, `thm2_lies_below_the_optimal_mse`, `eq64_vector_bounds_against_the_optimal_detector_estimator` |
//! | [`jde_bound`], [`JdeOptions`], [`JdeBoundOutcome`] | Theorems 1 and 2 and (63)–(72) behind one call: model I/II, scalar/vector prior, Theorem 2's Monte Carlo work cap | `jde::tests::thm1_model_i_dispatches_to_theorem1`, `thm2_model_ii_dispatches_to_theorem2_with_the_seed_and_samples`, `thm2_work_cap_is_samples_times_the_sampled_cardinalities`, `eq63_a_vector_of_one_is_the_scalar_bound` |
//! | `JdeBoundOptions`, `JdeMonteCarloRequest`, `PriorOptions`, `MonteCarloPrior`, `ObservationOptions`, `JdeDetectionOptions`, `GaussianOptions` (feature `serde`; not linked, so that the docs build without it) | the options of [`jde_bound`] and [`jde_monte_carlo`] as the bindings take them: f, P_o and g of (13)/(22) and (63), checked together, errors naming the Rust path | `options_tests::eq63_a_vector_prior_takes_rows_and_noise_cov`, `eq13_a_scalar_prior_takes_numbers`, `eq13_eq22_false_observations_belong_to_their_model`, `eq11_the_request_runs_the_monte_carlo_with_its_defaults`, `defaults_are_the_core_options` |
//! | [`example2`], [`example2_regularity`] | Example 2 (32), Fig. 2 right: (32) against (20), and the regularity failure | P: `ex2_is_reproduced_and_its_regularity_fails` |
//!
//! "P:" names a test in `tests/tests/paper_002_bounds.rs`; the others are unit tests under
//! `core/src/bounds/`.
//!
//! ## What is a bound, and what is returned
//! - Every term is computed as the paper defines it except where NOTES.md or these docs say
//!   otherwise: J'_n carries the 1/w_n² of (20)/(25) (Example 2's (32) drops it: both are in
//!   [`Example2`]); (23) is read as NOTES.md says; η2 is the exact clutter-rejection
//!   probability, not the product-region formula e^{−λ0} − e^{−λ}.
//! - Truncation: Σ C_n J'⁻¹ is cut where the Poisson tail is below
//!   [`TheoremOptions::series_tolerance`] (a valid lower bound: the terms are ≥ 0); Σ C_n w_{n+1} gets
//!   the tail added (w ≤ 1), and the η2 tail is bracketed, so the returned number stays a lower
//!   bound. Monte Carlo and quadrature errors are in [`JdeBound::error`]; the bound is the point
//!   estimate (subtract `error` for a conservative one).
//! - The information inequality needs p_1(·, z) to vanish at the ends of the prior's support;
//!   [`JdeBound::regular`] is false when it does not (uniform priors, tables, Example 2, where
//!   1/J_1 = 0.1897 exceeds the posterior mean's MSE 0.0340): there the estimation term, and so
//!   the "bound", can exceed what an estimator attains.
//!
//! ```
//! use fisst::bounds::{gaussian_no_clutter, gaussian_fisher_information};
//! // Fig. 2 left: σf² = 100, σh² = 25, e0² = 150, e1² = 200.
//! let b = gaussian_no_clutter(1.0, 0.5, 100.0, 25.0, 150.0, 200.0)?;
//! assert!((b.bound - 62.5).abs() < 1e-12); // 100 − 0.5 (100 − 25)
//! let j = gaussian_fisher_information(100.0, 1.0, 100.0 / 3.0)?;
//! assert!((j.posterior_variance - 25.0).abs() < 1e-12);
//! # Ok::<(), fisst::Error>(())
//! ```

mod closed;

pub use closed::{
    Assembled, GaussianInformation, GaussianInformationOptions, Ingredients, MAX_STEPS,
    NoClutterBound, NoClutterOptions, Phase, Sequential, SequentialBound, SequentialOptions, Terms,
    assemble, corollary1, corollary2, corollary3, gaussian_fisher_information, gaussian_no_clutter,
    map_threshold, poisson_pmf, sequential_bound,
};
mod model;
mod theorem;
mod theorem2;

pub use model::{
    Density, Density1, Detection, GAUSSIAN_SPAN, LinearGaussian, MAX_COMPONENTS, MAX_KNOTS,
    Observation, is_linear_gaussian,
};
pub use theorem::{Cardinality, JdeBound, Method, ModelI, TheoremOptions, theorem1};
pub use theorem2::{MAX_CLUTTER_RATE, ModelII, theorem2};
mod example2;
#[cfg(feature = "serde")]
pub use crate::serde_valid::{DENSITY1_KINDS, DensityOr, deserialize_density_or};
pub use example2::{
    Example2, Example2Observation, Example2Options, Example2Prior, Example2Regularity, UnitUniform,
    example2, example2_regularity,
};
mod jde;
pub use jde::{
    BoundTerm, CardinalityTerm, JdeBoundOutcome, JdeBoundReport, JdeClutter, JdeComponentBound,
    JdeFalseAlarm, JdeModel, JdeObservation, JdeOptions, JdePrior, MAX_DIMS, MAX_SAMPLE_POINTS,
    MAX_SAMPLES, MIN_SAMPLES, TermName, jde_bound, wrong_model,
};
mod vector;
pub use vector::{
    ComponentBound, GaussianPrior, LinearGaussianSensor, VectorBound, VectorMeasurement,
    VectorModel, check_measurement_dims, check_state_dims, component_bound,
    component_bounds_no_clutter, component_corollary1, gaussian_information_matrix, vector_bound,
};
#[cfg(feature = "serde")]
mod options;
#[cfg(feature = "serde")]
pub use options::{
    GaussianOptions, JdeBoundOptions, JdeDetectionOptions, JdeMonteCarloRequest, MonteCarloPrior,
    ObservationOptions, PriorOptions,
};
#[cfg(all(test, feature = "serde"))]
mod options_tests;
mod simulate;
pub use simulate::{
    EmptyRule, JdeMonteCarlo, JdeMonteCarloOptions, MAX_MONTE_CARLO_WORK, MonteCarloModel,
    MonteCarloRisk, SimulatedSystem, jde_monte_carlo,
};
