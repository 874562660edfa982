//! Numerical building blocks: float functions, compensated sums, linear assignment, the
//! portable seeded generator.

pub mod assignment;
pub mod fns;
pub mod log_sum;
pub(crate) mod matching;
pub mod quadrature;
pub mod rng;
pub mod sort;
pub mod special;
pub mod sum;

pub use assignment::{Assignment, linear_assignment};
pub use sum::NeumaierSum;
