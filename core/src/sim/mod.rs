//! Seeded scenarios shared by tests, benchmarks and demos.

pub mod airport;
