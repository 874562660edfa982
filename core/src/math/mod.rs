//! Numerical building blocks: float functions (and the Rényi kernel's own exp), compensated sums, linear assignment,
//! quadrature, special functions, optimisation and root finding, the portable seeded generator
//! and its samplers.

pub mod assignment;
pub mod decimal;
pub(crate) mod exp;
pub mod fns;
pub mod geometry;
pub(crate) mod jv;
pub mod log_sum;
pub(crate) mod matching;
pub mod optimise;
pub mod quadrature;
pub mod rng;
pub mod sort;
pub mod special;
pub mod sum;

pub use assignment::{Assignment, CostRows, linear_assignment};
pub use sum::NeumaierSum;
