//! Work budgets of the field-of-view computations of Sections VI–VII of `001_…`: estimates
//! of what a call costs, and the caps that let a caller (the bindings, an interactive page)
//! refuse a call that would take more than a few seconds before starting it.

use super::{GridAxis, MultiObjectDensity};
use crate::regions::Region;

/// Budget of one [`fov_cardinality`](super::fov_cardinality) call, in estimated native
/// microseconds ([`fov_mass_work_us`]): about 2 s.
pub const FOV_MASS_BUDGET_US: f64 = 2e6;

/// At most this many entries of an i.i.d.-cluster cardinality pmf (the thinning (84) is
/// O(n²)).
pub const MAX_CARDINALITY_LEN: usize = 20_001;

/// At most this many (component, FoV centre) pairs in one
/// [`variance_map`](super::variance_map) ([`grid_work`]).
pub const MAX_VARIANCE_MAP_WORK: f64 = 2e8;

/// At most this many (component, grid point) density evaluations in one
/// [`mixture_density_grid`](super::mixture_density_grid) ([`grid_work`]): about 80 ns each
/// natively, so about 2 s.
pub const MAX_DENSITY_GRID_WORK: f64 = 2.5e7;

impl MultiObjectDensity {
    /// The number of Gaussians whose masses ⟨1_S, p⟩ [`fov_cardinality`](super::fov_cardinality)
    /// computes: the mixture components (Poisson, i.i.d. cluster), the Bernoulli components, or
    /// every label of every GLMB hypothesis.
    pub fn gaussian_count(&self) -> usize {
        match self {
            MultiObjectDensity::Poisson(m) => m.len(),
            MultiObjectDensity::IidCluster(c) => c.density.len(),
            MultiObjectDensity::MultiBernoulli(c) => c.len(),
            MultiObjectDensity::Glmb(h) => h.iter().map(|(_, c)| c.len()).sum(),
        }
    }
}

/// The estimated native cost of [`fov_cardinality`](super::fov_cardinality) in microseconds:
/// [`MultiObjectDensity::gaussian_count`] masses at [`Region::mass_cost_us`] each (the pmfs
/// themselves are cheap next to the masses). Compare with [`FOV_MASS_BUDGET_US`].
pub fn fov_mass_work_us(density: &MultiObjectDensity, fov: &Region) -> f64 {
    density.gaussian_count() as f64 * fov.mass_cost_us()
}

/// `components` × the cells of the grid `x` × `y`: the work of a
/// [`variance_map`](super::variance_map) (compare with [`MAX_VARIANCE_MAP_WORK`]) or a
/// [`mixture_density_grid`](super::mixture_density_grid) (with [`MAX_DENSITY_GRID_WORK`]).
pub fn grid_work(components: usize, x: GridAxis, y: GridAxis) -> f64 {
    components as f64 * (x.count * y.count) as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gaussian::{Gaussian, GaussianMixture};
    use alloc::vec;

    #[test]
    fn eq72_work_counts_every_mass_at_the_region_cost() {
        let g = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0], "g").unwrap();
        let mb = MultiObjectDensity::MultiBernoulli(vec![(0.5, g.clone()); 3]);
        let glmb =
            MultiObjectDensity::Glmb(vec![(0.4, vec![g.clone()]), (0.6, vec![g.clone(); 2])]);
        let poisson =
            MultiObjectDensity::Poisson(GaussianMixture::new(vec![(2.0, g)], "p").unwrap());
        assert_eq!(mb.gaussian_count(), 3);
        assert_eq!(glmb.gaussian_count(), 3);
        assert_eq!(poisson.gaussian_count(), 1);
        let disc = Region::ball(&[0.0, 0.0], 1.0, "fov").unwrap();
        assert_eq!(fov_mass_work_us(&mb, &disc), 450.0);
        let axis = |count| GridAxis {
            min: 0.0,
            max: 1.0,
            count,
        };
        assert_eq!(grid_work(7, axis(10), axis(20)), 1400.0);
        assert!(grid_work(100, axis(4096), axis(4096)) > MAX_VARIANCE_MAP_WORK);
    }
}
