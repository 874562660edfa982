//! Shared helpers for fisst's paper reproductions and cross-crate tests.
