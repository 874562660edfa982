//! Numerical building blocks: float functions, compensated sums, linear assignment.

pub mod assignment;
pub mod fns;
pub mod sum;

pub use assignment::{Assignment, linear_assignment};
pub use sum::NeumaierSum;
