//! Information-driven sensor control of paper `004` (Ristic & Vo): the rewards (Rényi
//! divergence (15)–(17), Fisher information (27)–(29), PENT (30)–(34), random), the
//! admissible actions (23), the range-only case study of Sec. 5 and the four-scheme Monte Carlo
//! comparison of Fig. 3. The filter itself is in [`crate::smc`].

pub mod actions;
pub mod case_study;
pub mod comparison;
pub mod rewards;

pub use actions::{Action, ActionGrid};
pub use case_study::{ControlConfig, ControlRun, RangeSensor, Scheme, StepOutcome};
pub use comparison::{MeanSeries, SchemeSummary, compare_schemes, run_seeds, run_series};
pub use rewards::{expected_renyi, fisher_reward, pent_reward, renyi_divergence};
