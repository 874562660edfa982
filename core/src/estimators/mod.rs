//! Estimators: optimal multi-Bernoulli estimation under OSPA/UOSPA/GOSPA and the classical
//! alternatives.

pub mod alternatives;
pub mod multi_bernoulli;
