//! Work budgets of Algorithms 1–2 of `001_…` (Section IV): caps on the inputs of
//! [`split_for_regions`](super::split_for_regions) and an estimate of its worst-case work, so
//! that a caller (the bindings, an interactive page) can refuse a call that would take more
//! than a few seconds before starting it; and the budget of the exact inside mass reported
//! next to the mean-based partition.

use super::{MAX_DEPTH_LIMIT, MAX_SPLIT_COMPONENTS, MIN_SPLIT_COMPONENTS, SplitOptions};
use crate::error::{Error, Phrase, Result};
use crate::gaussian::GaussianMixture;
use crate::mixture::{merge_close, prune, runnalls};
use crate::regions::{MAX_MASS_DIM, Region};

/// At most this many position dimensions n_s in a bounded split request.
pub const MAX_POSITION_DIMS: usize = 8;

/// At most this many components asked of Runnalls' reduction
/// ([`runnalls`](crate::mixture::runnalls)'s `max_components`) by a bounded caller.
pub const MAX_REDUCED_COMPONENTS: usize = 1_000_000;

/// At most this many regions in one [`split_for_regions`](super::split_for_regions) call.
pub const MAX_REGIONS: usize = 32;

/// At most this many collocation points N_g^{n_s} (before the ball cut) per component.
pub const MAX_GRID_SIZE: usize = 20_000;

/// Largest [`SplitOptions::max_components`](super::SplitOptions::max_components) a bounded
/// caller accepts.
pub const MAX_SPLIT_RESULT_COMPONENTS: usize = 50_000;

/// Budget of one [`split_for_regions`](super::split_for_regions) call in inclusion tests
/// ([`split_work`]), ≈ 5 ns each natively: a few seconds in wasm.
pub const SPLIT_WORK_BUDGET: f64 = 5e8;

/// Budget of the exact inside mass ⟨1_S, p⟩ of a mixture, in estimated native µs
/// ([`exact_mass_affordable`]).
pub const EXACT_MASS_BUDGET_US: f64 = 5e5;

/// At most this many components enter Runnalls' reduction
/// ([`runnalls`](crate::mixture::runnalls): O(L²) bound evaluations; 5000 components to 1
/// took 2.4 s in Node, 3000 about 0.9 s).
pub const MAX_RUNNALLS_INPUT: usize = 3_000;

/// At most this many components in a bounded reduction request's mixture (Vo & Ma's merge
/// ([`merge_close`](crate::mixture::merge_close)) computes O(L²) Mahalanobis distances when
/// nothing merges: 10,000 components took 1.9 s in Node, 5000 about 0.7 s).
pub const MAX_REDUCE_INPUT: usize = 5_000;

/// `Ok` if a bounded reduction request's mixture has at most [`MAX_REDUCE_INPUT`]
/// components.
///
/// # Errors
/// [`Error::Count`] naming `mixture`.
pub fn check_reduce_input(len: usize) -> Result<()> {
    Error::check_count("mixture", "components", len, 0, MAX_REDUCE_INPUT)
}

/// Checks the integer knobs of a bounded split request (an interactive caller's caps, tighter
/// than [`split_for_regions`](super::split_for_regions)'s own checks), in this order:
/// `position_dims` in [1, [`MAX_POSITION_DIMS`]], the library's `components` R in
/// [[`MIN_SPLIT_COMPONENTS`], [`MAX_SPLIT_COMPONENTS`]], `grid_points` in
/// [2, [`MAX_GRID_SIZE`]], `max_depth` in [0, [`MAX_DEPTH_LIMIT`]], `max_components` in
/// [1, [`MAX_SPLIT_RESULT_COMPONENTS`]].
///
/// # Errors
/// [`Error::OutOfRange`] naming the first field outside its interval (Rust names:
/// `position_dims`, `components`, `grid_points`, `max_depth`, `max_components`).
pub fn check_bounded_split(components: usize, options: &SplitOptions) -> Result<()> {
    Error::check_range("position_dims", options.position_dims, 1, MAX_POSITION_DIMS)?;
    Error::check_range(
        "components",
        components,
        MIN_SPLIT_COMPONENTS,
        MAX_SPLIT_COMPONENTS,
    )?;
    Error::check_range("grid_points", options.grid_points, 2, MAX_GRID_SIZE)?;
    Error::check_range("max_depth", options.max_depth, 0, MAX_DEPTH_LIMIT)?;
    Error::check_range(
        "max_components",
        options.max_components,
        1,
        MAX_SPLIT_RESULT_COMPONENTS,
    )?;
    Ok(())
}

/// The collocation grid's size N_g^{n_s} (`grid_points^position_dims`), or `None` when it
/// exceeds [`MAX_GRID_SIZE`] (or overflows).
pub fn grid_size(position_dims: usize, grid_points: usize) -> Option<usize> {
    (0..position_dims)
        .try_fold(1usize, |acc, _| acc.checked_mul(grid_points))
        .filter(|&g| g <= MAX_GRID_SIZE)
}

/// The worst-case inclusion tests of [`split_for_regions`](super::split_for_regions):
/// `max_components × grid_size × Σ region weights`. An inclusion test costs about 1 (box),
/// 2 (disc), 2 + vertices/15 (polygon) units; [`Region::mass_cost_us`] (1, 150,
/// 150 + 10·vertices µs) maps onto that scale as 1 + cost/150. Compare with
/// [`SPLIT_WORK_BUDGET`].
pub fn split_work(max_components: usize, grid_size: usize, regions: &[Region]) -> f64 {
    let region_work: f64 = regions.iter().map(|r| 1.0 + r.mass_cost_us() / 150.0).sum();
    max_components as f64 * grid_size as f64 * region_work
}

/// Whether the exact mass of `region` under a mixture of `components` Gaussians fits
/// [`EXACT_MASS_BUDGET_US`] ([`Region::mass_cost_us`] each) and the region's dimension is
/// served by [`Region::gaussian_mass`] (at most [`MAX_MASS_DIM`]).
pub fn exact_mass_affordable(components: usize, region: &Region) -> bool {
    components as f64 * region.mass_cost_us() <= EXACT_MASS_BUDGET_US
        && region.dim() <= MAX_MASS_DIM
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alg2_work_and_grid_caps() {
        assert_eq!(grid_size(2, 15), Some(225));
        assert_eq!(grid_size(0, 15), Some(1));
        assert_eq!(grid_size(4, 15), None); // 50 625 > 20 000
        assert_eq!(grid_size(8, usize::MAX), None);
        let b = Region::axis_box(&[0.0, 0.0], &[1.0, 1.0], "b").unwrap();
        let d = Region::ball(&[0.0, 0.0], 1.0, "d").unwrap();
        // 10 000 × 225 × ((1 + 1/150) + (1 + 1))
        let w = split_work(10_000, 225, &[b.clone(), d.clone()]);
        assert_eq!(w, 10_000.0 * 225.0 * ((1.0 + 1.0 / 150.0) + 2.0));
        assert!(w <= SPLIT_WORK_BUDGET);
        assert!(
            split_work(
                MAX_SPLIT_RESULT_COMPONENTS,
                MAX_GRID_SIZE,
                core::slice::from_ref(&b)
            ) > SPLIT_WORK_BUDGET
        );
        assert!(exact_mass_affordable(3333, &d));
        assert!(!exact_mass_affordable(3334, &d));
        let b5 = Region::axis_box(&[0.0; 5], &[1.0; 5], "b").unwrap();
        assert!(!exact_mass_affordable(1, &b5));
    }

    #[test]
    fn alg2_bounded_request_names_the_first_field_out_of_range() {
        use alloc::string::ToString;
        let ok = SplitOptions::default();
        assert_eq!(check_bounded_split(3, &ok), Ok(()));
        let cases = [
            (
                3,
                SplitOptions {
                    position_dims: 9,
                    ..ok.clone()
                },
                Error::range("position_dims", 9, 1, 8),
            ),
            (17, ok.clone(), Error::range("components", 17, 2, 16)),
            (1, ok.clone(), Error::range("components", 1, 2, 16)),
            (
                3,
                SplitOptions {
                    grid_points: 1,
                    ..ok.clone()
                },
                Error::range("grid_points", 1, 2, MAX_GRID_SIZE),
            ),
            (
                3,
                SplitOptions {
                    max_depth: 65,
                    ..ok.clone()
                },
                Error::range("max_depth", 65, 0, 64),
            ),
            (
                3,
                SplitOptions {
                    max_components: 0,
                    ..ok.clone()
                },
                Error::range("max_components", 0, 1, MAX_SPLIT_RESULT_COMPONENTS),
            ),
            // two fields out of range: the first in the documented order is named
            (
                0,
                SplitOptions {
                    position_dims: 0,
                    ..ok.clone()
                },
                Error::range("position_dims", 0, 1, 8),
            ),
        ];
        for (components, options, expected) in cases {
            assert_eq!(check_bounded_split(components, &options), Err(expected));
        }
        assert_eq!(
            Error::range("max_depth", 65, 0, 64).to_string(),
            "max_depth must be an integer in [0, 64], got 65"
        );
    }
}

/// A bounded mixture reduction as a caller writes it (an interactive page's): prune
/// (renormalising), Vo & Ma's Mahalanobis merge, then Runnalls' KL-based reduction, each pass
/// only when asked; at most 5,000 components ([`MAX_REDUCE_INPUT`]) and 3,000 into Runnalls'
/// reduction ([`MAX_RUNNALLS_INPUT`]) (in Rust, [`ReduceMixtureOptions::reduce`] runs it).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ReduceMixtureOptions {
    /// The mixture to reduce: at most 5000 components.
    pub mixture: GaussianMixture,
    /// Drop components lighter than this, renormalising the rest (default 0: keep all).
    #[cfg_attr(feature = "serde", serde(default))]
    pub prune_below: f64,
    /// Vo & Ma merge within this Mahalanobis distance (U = distance²); omitted: no merging.
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub merge_distance: Option<f64>,
    /// Runnalls' reduction to at most this many components, an integer in [1, 1e6]; omitted:
    /// no cap. Runnalls' reduction takes at most 3000 components (those left after pruning
    /// and merging; an error naming `max_components` beyond).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub max_components: Option<usize>,
}

impl ReduceMixtureOptions {
    /// The reduced mixture: [`prune`](crate::mixture::prune), then
    /// [`merge_close`](crate::mixture::merge_close) and [`runnalls`](crate::mixture::runnalls)
    /// when asked. The total weight is preserved; merges preserve the mixture's mean and
    /// covariance.
    ///
    /// # Errors
    /// [`check_reduce_input`]'s; an [`Error::OutOfRange`] naming `max_components` outside
    /// [1, [`MAX_REDUCED_COMPONENTS`]]; the passes' own; an [`Error::Form`] naming
    /// `max_components` when more than [`MAX_RUNNALLS_INPUT`] components reach Runnalls'
    /// reduction.
    pub fn reduce(&self) -> Result<GaussianMixture> {
        check_reduce_input(self.mixture.len())?;
        let max_components = self
            .max_components
            .map(|m| Error::check_range("max_components", m, 1, MAX_REDUCED_COMPONENTS))
            .transpose()?;
        let mut out = prune(&self.mixture, self.prune_below)?;
        if let Some(d) = self.merge_distance {
            out = merge_close(&out, d)?;
        }
        if let Some(max) = max_components {
            if out.len() > max && out.len() > MAX_RUNNALLS_INPUT {
                return Err(Error::form(
                    "max_components",
                    false,
                    alloc::vec![
                        Phrase::text(alloc::format!(
                            ": Runnalls' reduction takes at most {MAX_RUNNALLS_INPUT} \
                             components, {} remain after pruning and merging; raise ",
                            out.len()
                        )),
                        Phrase::name("prune_below"),
                        Phrase::text(" or "),
                        Phrase::name("merge_distance"),
                    ],
                ));
            }
            out = runnalls(&out, max)?;
        }
        Ok(out)
    }
}
