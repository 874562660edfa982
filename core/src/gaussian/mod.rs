//! Gaussian densities with validated covariances, Gaussian mixtures, and the scalar normal
//! distribution functions.

pub mod covariance;
mod density;
mod mixture;
pub mod normal;

pub use density::Gaussian;
pub use mixture::GaussianMixture;
