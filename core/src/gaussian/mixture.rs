//! Weighted sums of Gaussians.

use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::gaussian::Gaussian;
use crate::math::sum::sum;

/// Σ_j w_j N(m_j, P_j): nonnegative weights (not necessarily normalised; a PHD's weights sum
/// to the expected count) and components of one dimension.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct GaussianMixture {
    components: Vec<(f64, Gaussian)>,
}

impl GaussianMixture {
    /// A mixture from `(weight, Gaussian)` pairs. `what` names it in errors
    /// (`{what}[j].weight`, `{what}[j].mean`).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a negative or non-finite weight,
    /// [`Error::DimensionMismatch`] for components of different dimensions.
    pub fn new(components: Vec<(f64, Gaussian)>, what: &str) -> Result<Self> {
        let dim = components.first().map(|(_, g)| g.dim());
        for (j, (w, g)) in components.iter().enumerate() {
            if !(w.is_finite() && *w >= 0.0) {
                return Err(Error::parameter(
                    alloc::format!("{what}[{j}].weight"),
                    *w,
                    "finite and >= 0",
                ));
            }
            if Some(g.dim()) != dim {
                return Err(Error::dimension(
                    alloc::format!("{what}[{j}].mean"),
                    dim.unwrap_or(0),
                    g.dim(),
                ));
            }
        }
        Ok(Self { components })
    }

    /// The components.
    pub fn components(&self) -> &[(f64, Gaussian)] {
        &self.components
    }

    /// The components, by value (no copy).
    pub fn into_components(self) -> Vec<(f64, Gaussian)> {
        self.components
    }

    /// The number of components.
    pub fn len(&self) -> usize {
        self.components.len()
    }

    /// True when there are no components.
    pub fn is_empty(&self) -> bool {
        self.components.is_empty()
    }

    /// The dimension (`None` for an empty mixture).
    pub fn dim(&self) -> Option<usize> {
        self.components.first().map(|(_, g)| g.dim())
    }

    /// Σ w_j (compensated).
    pub fn total_weight(&self) -> f64 {
        sum(self.components.iter().map(|(w, _)| *w))
    }

    /// Σ_j w_j N(x; m_j, P_j).
    pub fn pdf(&self, x: &[f64]) -> f64 {
        sum(self.components.iter().map(|(w, g)| w * g.pdf(x)))
    }
}
