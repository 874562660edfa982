//! Cardinality distributions of random finite sets.
//!
//! | item | paper | tested by |
//! |---|---|---|
//! | [`multi_bernoulli_cardinality`] | (88) of `001_…`; ρ in Lemma 4 of `003_…` | `multi_bernoulli::tests::eq88_matches_enumeration`, `multi_bernoulli::tests::thousands_of_components_stay_a_pmf`, `fov::tests::eq88_eq90_multi_bernoulli_forms_agree` |
//! | [`leave_one_out_cardinalities`], [`for_each_leave_one_out`] | ρ_{−i}, Lemma 4 (7) of `003_…` | `multi_bernoulli::tests::lemma4_leave_one_out_matches_recomputation`, `estimators::multi_bernoulli::tests::lemma4_matches_enumeration_with_real_metrics` |
//! | [`MAX_COMPONENTS`], [`MAX_LEAVE_ONE_OUT_COMPONENTS`] | the caps on M (time, memory) | `multi_bernoulli::tests::eq88_and_lemma4_pmfs_are_capped_by_the_component_count` |

pub mod multi_bernoulli;

pub use multi_bernoulli::{
    MAX_COMPONENTS, MAX_LEAVE_ONE_OUT_COMPONENTS, for_each_leave_one_out,
    leave_one_out_cardinalities, multi_bernoulli_cardinality,
};
