//! Optimal Bernoulli point estimation (paper `000_…`: A. Narykov, M. Üney, J. F. Ralph,
//! "Optimal Bernoulli point estimation with applications").
//!
//! A Bernoulli filter hands over an existence probability p and a spatial density s. Under
//! the application-oriented loss (7) — a cost matrix for reporting or not, plus a cost c
//! when the reported point is farther than r0 from the target — the Bayes-optimal report
//! (Theorem III.3) is the MMUC point a* (12) when p exceeds a threshold Γ (11) that depends
//! on the costs and on how much of s a ball of radius r0 can hold:
//!
//! ```text
//! q(a) = ∫ 1{‖x − a‖ > r0} s(dx),   a* = argmin_a q(a)
//! Γ    = (c00 − c10) / (c00 − c01 − c10 + c11 + c q(a*))
//! ```
//!
//! | item | paper | tested by (`tests::` unless named) |
//! |---|---|---|
//! | [`Costs`], [`ApplicationLoss`] | loss (7)–(9), Table I presets ([`Costs::mpe`], [`Costs::mmol`]) | `loss::tests::eq7_loss_cases`, `loss::tests::table1_presets_follow_the_printed_costs`, `eq13_eq14_expected_losses_match_a_monte_carlo_of_the_loss` |
//! | [`SpatialDensity`] | s: Gaussian, Gaussian mixture, weighted particles | `density_validation_names_the_field`, `eq12_q_of_mixtures_and_particles` |
//! | [`SpatialDensity::prob_outside_ball`] | q(a), the integral in (11)–(13); method and error bound in [`ball`] | `eq12_q_is_exact_in_one_dimension`, `eq12_q_matches_closed_forms_for_centred_isotropic_gaussians`, `eq12_q_matches_brute_force_quadrature_in_2d`, `eq12_q_matches_brute_force_quadrature_in_3d`, `eq12_q_matches_monte_carlo_in_1d_2d_3d`, `eq12_q_matches_monte_carlo_in_6d`, `nested_quadrature_and_inversion_agree`, `nearly_singular_covariances_reduce_to_lower_dimensions`, `gradient_of_q_matches_finite_differences` |
//! | [`SpatialDensity::mmuc`] | a*, eq. (12) | `eq12_gaussian_mmuc_is_the_mean_and_beats_its_neighbours`, `eq12_mixture_mmuc_finds_the_optimum_between_modes`, `eq12_mixture_mmuc_matches_grid_search_on_an_asymmetric_mixture`, `eq12_mixture_mmuc_in_one_and_three_dimensions`, `eq12_mixture_with_a_shared_mean_uses_sherman_per_component`, `eq12_particle_mmuc_is_exact_in_1d_and_2d`, `eq12_particle_mmuc_in_3d_beats_every_sampled_centre`, `eq12_mmuc_of_a_mixture_with_a_point_like_component` |
//! | [`threshold`], [`expected_loss_empty`], [`expected_loss_singleton`] | (11), (14), (13) | `fig2_published_thresholds_of_section_four`, `eq13_eq14_expected_losses_match_a_monte_carlo_of_the_loss`, `paper_000_bernoulli::fig2_thresholds_to_the_printed_digits` |
//! | [`loss_curve`] | Fig. 2: (13), (14) and the rule's loss against p | `fig2_loss_curve_follows_the_rule_and_names_the_entry` |
//! | [`estimate`] | Theorem III.3, eq. (10); Corollaries IV.1 (MPE) and IV.2 (MMOL) | `eq24_decision_is_the_smaller_expected_loss_for_any_costs`, `eq10_ties_report_nothing`, `cor1_cor2_follow_from_the_general_form`, `cor2_free_countermeasure_threshold_is_positive_zero`, `paper_000_bernoulli::fig2_optimal_threshold_wins_exactly_between_it_and_one_half` |
//! | [`multi_bernoulli_estimate`] | the theorem per component of a multi-Bernoulli | `thm3_per_component_of_a_multi_bernoulli` |
//! | [`isotropic_threshold_curve`], [`chi_square_sf`] | Fig. 3: Γ against σ, in closed form | `fig3_properties`, `fig3_curve_matches_the_general_estimator`, `chi_square::tests::chi_square_matches_known_values`, `paper_000_bernoulli::fig3a_mpe_threshold_rises_from_one_half_with_sigma`, `paper_000_bernoulli::fig3b_mmol_threshold_is_bounded_below_by_the_cost_ratio` |
//!
//! ```
//! use fisst::bernoulli::{estimate, ApplicationLoss, Costs, SpatialDensity};
//! // A 2D Gaussian with correlated covariance, MMOL costs, r0 = 1.
//! let s = SpatialDensity::gaussian_from_slices(&[3.0, -1.0], &[1.0, 0.3, 0.3, 0.5])?;
//! let loss = ApplicationLoss::new(Costs::mmol(0.9, 0.1)?, 1.0)?;
//! let e = estimate(0.3, &s, &loss)?;
//! assert_eq!(e.mmuc.center, vec![3.0, -1.0]); // the mean (Sherman's theorem)
//! assert!(e.declare && e.expected_loss_singleton < e.expected_loss_empty);
//! # Ok::<(), fisst::Error>(())
//! ```

// Layers, each file using only those above it:
//   quadrature, loss, chi_square      numerics, the costs (7)–(9), P(χ²_d > t)
//   inversion                         Gil-Pelaez inversion (quadrature)
//   ball                              q(a) for one Gaussian (inversion, quadrature, chi_square)
//   density                           s and q(a) for every kind of density (ball, loss)
//   mmuc                              a*, eq. (12) (density, ball, loss)
//   threshold                         Γ (11), ρ (13)–(14) and their curves (loss)
//   estimate                          Theorem III.3 (density, mmuc, threshold, loss)
//   isotropic                         Fig. 3 in closed form (chi_square, threshold, loss)
pub mod ball;
mod chi_square;
mod density;
mod estimate;
pub mod inversion;
mod isotropic;
mod loss;
mod mmuc;
mod threshold;

pub use ball::{BallProbability, DEFAULT_TOLERANCE};
pub use chi_square::chi_square_sf;
pub use density::{DensityKind, MIN_TOLERANCE, ParticleSet, SpatialDensity};
pub use estimate::{
    BernoulliComponent, BernoulliEstimate, BernoulliEstimateOptions, BernoulliReport,
    MAX_MULTI_BERNOULLI_COMPONENTS, MultiBernoulliEstimate, MultiBernoulliPointOptions,
    MultiBernoulliReport, check_multi_bernoulli_count, estimate, multi_bernoulli_estimate,
};
pub use isotropic::{
    MAX_ISOTROPIC_DIM, ThresholdCurveOptions, isotropic_miss_probability, isotropic_threshold_curve,
};
pub use loss::{ApplicationLoss, Costs};
pub use mmuc::{
    MAX_MMUC_COMPONENTS, MAX_MMUC_PARTICLES, MMUC_SEARCH_BUDGET, Mmuc, MmucEstimate, MmucMethod,
    MmucOptions, ProbabilityOutsideBallOptions,
};
pub use threshold::{
    Direction, LossCurve, LossCurveOptions, Threshold, expected_loss_empty,
    expected_loss_singleton, loss_curve, threshold,
};

#[cfg(test)]
mod tests;
