//! Estimators: optimal multi-Bernoulli estimation under OSPA/UOSPA/GOSPA and the classical
//! alternatives.
//!
//! | item | paper (`003_…`) | tested by |
//! |---|---|---|
//! | [`multi_bernoulli::mean_error`] | Lemma 4, (5)–(8) | `multi_bernoulli::tests::lemma4_matches_enumeration_with_real_metrics`, `multi_bernoulli::tests::huge_orders_give_zero_or_infinity_never_nan` |
//! | [`multi_bernoulli::optimal_estimate`] | the optimal estimates (9), (11); Figs 1 and 3 | `multi_bernoulli::tests::eq9_gospa_closed_form_is_per_component`, `multi_bernoulli::tests::eq11_identical_components_all_or_nothing`, `multi_bernoulli::tests::top_k_sets_contain_the_optimum_exhaustively_up_to_12`, `paper_003_spooky::fig1_single_component_threshold_is_one_half_for_every_metric`, `paper_003_spooky::fig1_gospa_decides_each_component_alone`, `paper_003_spooky::fig1_ospa_and_uospa_are_spooky`, `paper_003_spooky::eq11_all_or_nothing_for_many_identical_components`, `paper_003_spooky::fig3_uospa_reports_the_r_quantile_and_moves_one_by_one`, `paper_003_spooky::example5_madrid_and_liverpool` |
//! | [`alternatives`] (MaM, JoM, MAP cardinality) | Fig. 2 | `alternatives::tests::two_component_rules`, `alternatives::tests::fig2_alternative_estimate_dispatches_to_each_rule`, `alternatives::tests::mam_prefers_the_sharper_component_when_spreads_differ`, `paper_003_spooky::fig2_decision_rules_match_a_direct_maximisation`, `paper_003_spooky::fig2_estimators_are_spooky_too` |
//! | [`figures::decision_map`] | Figs 1 and 2: decisions over a grid of (r1, r2) | `figures::tests::fig1_decision_map_cells_are_the_optimal_estimates`, `figures::tests::fig2_decision_map_uses_the_alternatives_with_equal_covariances`, `figures::tests::fig1_decision_map_checks_its_options` |
//! | [`figures::identical_component_counts`] | Fig. 3, eqs. (9) and (11) | `figures::tests::fig3_counts_follow_eq9_and_eq11`, `figures::tests::fig3_counts_check_their_options` |
//! | caps: [`multi_bernoulli::MAX_OSPA_ESTIMATE_COMPONENTS`], [`crate::cardinality::MAX_COMPONENTS`], [`figures::MAX_IDENTICAL_COMPONENTS`]; tiny α | Lemma 4, (9)/(11), Fig. 3 | `multi_bernoulli::overflow_tests::lemma4_and_eq11_component_counts_are_capped_per_metric`, `multi_bernoulli::overflow_tests::lemma4_subnormal_alpha_and_cutoff_give_numbers_never_nan`, `figures::tests::fig3_counts_check_their_options` |
//! | [`options`]: [`MbOptimalEstimateOptions`], [`MbMeanSquareErrorOptions`], [`MbAlternativeEstimateOptions`] | the inputs of (9)/(11), Lemma 4 and Fig. 2 as data | `options::tests::lemma4_and_eq9_options_call_the_estimators`, `options::tests::fig2_alternative_options_default_ln_peak_to_zero` |

pub mod alternatives;
pub mod figures;
pub mod multi_bernoulli;
pub mod options;

pub use options::{
    AlternativeEstimate, MbAlternativeEstimateOptions, MbMeanSquareErrorOptions,
    MbOptimalEstimateOptions, SetMetricName,
};
