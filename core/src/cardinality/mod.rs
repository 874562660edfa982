//! Cardinality distributions of random finite sets.

pub mod multi_bernoulli;

pub use multi_bernoulli::{
    for_each_leave_one_out, leave_one_out_cardinalities, multi_bernoulli_cardinality,
};
