//! Information-driven sensor control of paper `004` (Ristic & Vo): the rewards (Rényi
//! divergence (15)–(17), Fisher information (27)–(29), PENT (30)–(34), random), the
//! admissible actions (23), the range-only case study of Sec. 5 and the four-scheme Monte Carlo
//! comparison of Fig. 3. The filter itself is in [`crate::smc`].
//!
//! | file | what | paper | tested by |
//! | --- | --- | --- | --- |
//! | `sensor.rs` | the range sensor, its scans and (20) of one particle | (19)–(21) | `alg1_reduced_run_localises_both_sources` |
//! | `case_study.rs` | the run driver, choice of the action | Alg. 1, Sec. 5 | `alg1_reduced_run_localises_both_sources` |
//! | `renyi_kernel.rs` | the batched expected Rényi reward | (15)–(17), (20) | `eq17_renyi_reward_matches_the_reference`, `eq17_renyi_rewards_are_pinned`, `eq17_chunked_rewards_are_the_whole_ones` |
//! | `reference.rs` | the plain reference of the reward (tests only) | (15)–(17) | (the oracle of the three above) |
//! | `rewards.rs` | Rényi divergence, its mean, α → 1 | (9), (15)–(17) | `eq9_expected_renyi_is_the_direct_evaluation`, `eq15_alpha_to_one_is_the_kl_divergence` |
//! | `rewards.rs` | Fisher information gain | (27)–(29) | `eq29_fisher_reward_by_hand` |
//! | `rewards.rs` | PENT | (30)–(34) | `eq30_pent_reward_by_hand` |
//! | `actions.rs` | the admissible actions | (23) | `eq23_seventeen_actions_with_corner_exclusions`, `eq23_diagonal_move_back_to_the_corner_is_inside` |
//! | `comparison.rs` | the Monte Carlo comparison of the schemes, its options and caps | Fig. 3 | `fig3_summaries_have_the_stated_shape_and_progress_counts`, `fig3_options_check_runs_schemes_and_the_run_caps` |
//! | `particle_likelihood.rs` | (20) of one particle as the bindings take it, with its caps | (20) | `eq20_options_caps_come_before_the_values` |

pub mod actions;
pub mod case_study;
pub mod comparison;
pub mod particle_likelihood;
#[cfg(test)]
mod reference;
mod renyi_kernel;
pub mod rewards;
pub mod sensor;
#[cfg(test)]
mod tests;

pub use actions::{Action, ActionGrid};
pub use case_study::{
    ControlOptions, ControlParticles, ControlRun, OspaParts, Scheme, StepOutcome,
};
pub use comparison::{
    CompareOptions, Comparison, MeanSeries, SchemeSummary, compare_schemes, run_seeds, run_series,
};
pub use particle_likelihood::{MultiObjectLikelihoodOptions, ParticleLikelihood};
pub use rewards::{expected_renyi, fisher_reward, pent_reward, renyi_divergence};
pub use sensor::RangeSensor;
