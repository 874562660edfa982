//! The SMC multi-object filter of paper `004` (Ristic & Vo, Sec. 4 and 5.2): multi-object
//! particles (11), the multi-object likelihood (20) computed exactly without enumerating the
//! associations, and the update / resample / regularise cycle with the MAP cardinality (22).
//!
//! | file | what | paper | tested by |
//! | --- | --- | --- | --- |
//! | `likelihood.rs` | the model, (20) from logs, validated, and its brute-force oracle | (20) | `eq20_matches_enumeration_for_small_sets`, `eq20_edge_cases`, `eq20_extreme_logs_take_the_log_path`, `eq20_bad_input_names_the_field` |
//! | `matchings.rs` | the subset dynamic programme over the partial matchings | (20) | (through `likelihood.rs`) |
//! | `fixed.rs` | the fixed-size plain kernels (one set, or four sets as lanes) | (20) | `eq20_fixed_kernels_match_the_tables_bit_for_bit` |
//! | `batch.rs` | the batch interface the control calls, its one dispatch table | (20) | `eq20_small_plain_path_matches_the_log_path`, `eq20_fixed_kernels_match_the_tables_bit_for_bit`, `eq20_negligible_pairs_change_the_sum_by_at_most_the_bound` |
//! | `filter.rs` | reweight, systematic resampling, regularisation | (20), Alg. 1 lines 9–10 | `eq20_reweight_normalises_and_handles_zero_likelihoods`, `alg1_systematic_resampling_keeps_expected_counts`, `alg1_regularisation_changes_cardinality_at_the_stated_rates` |
//! | `particles.rs` | multi-object particles, initialisation, MAP estimate | (11), (22), Alg. 1 line 7 | `alg1_initialisation_puts_objects_on_the_arcs`, `eq22_estimate_aligns_permuted_particles` |

pub(crate) mod batch;
pub mod filter;
mod fixed;
pub mod likelihood;
mod matchings;
pub mod particles;

pub use filter::{Regularisation, regularise, resample, reweight, systematic};
pub use likelihood::{
    LikelihoodWorkspace, MultiObjectLikelihood, brute_force_ln_likelihood, ln_likelihood,
};
pub use particles::{Area, MultiObjectParticles, SetEstimate, State};
