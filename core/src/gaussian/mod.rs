//! Gaussian densities with validated covariances, Gaussian mixtures, and the scalar normal
//! distribution functions.

pub mod covariance;
mod density;
mod mixture;
pub mod normal;

pub use density::Gaussian;
pub use mixture::GaussianMixture;

/// At most this many Gaussians in one mixture or density argument read by a binding (a
/// `GaussianMixture`, a multi-Bernoulli, all the labels of a GLMB): a longer one is an error
/// naming it ("has 10001 entries, at most 10000 are supported").
pub const MAX_GAUSSIANS: usize = 10_000;
