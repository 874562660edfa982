//! The bounded requests of Section IV of `001_0f0df91eee9b30d5.txt` (LeGrand & Ferrari, "Split
//! Happens! Imprecise and negative information in Gaussian mixture random finite set
//! filtering", paper 001) as a caller (the npm package's `splitLibrary`, `splitForRegions`,
//! `negativeInformationScenario`, the Python package's `split_library`, …) asks for them: one
//! options type each, validated here with the caps of [`super::budget`], and a result type
//! whose serde form is the flat shape the bindings return.

use alloc::vec::Vec;

use super::{
    MAX_REGIONS, MAX_SPLIT_COMPONENTS, MIN_SPLIT_COMPONENTS, NegativeInformationScenario,
    NegativeInformationStep, SPLIT_WORK_BUDGET, Spacing, SplitLibrary, SplitOptions, SplitStop,
    check_bounded_split, defaults, exact_mass_affordable, grid_size, partition, split_for_regions,
    split_work,
};
use crate::error::{Error, Result};
use crate::gaussian::GaussianMixture;
use crate::regions::Region;

/// Options of a split-library request (eqs. (13)–(14) of `001_…`): R, λ and the means'
/// family.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SplitLibraryOptions {
    /// The number R of components of the split: an integer in [2, 16].
    pub components: usize,
    /// The weight λ ∈ [1e-6, 10] of the σ̃² penalty in the split objective J of eq. (13).
    /// Named `lambda_` because `lambda` is a Python keyword (PEP 8's trailing underscore);
    /// JavaScript's camelCase name is `lambda`.
    pub lambda_: f64,
    /// `equal` (default): symmetric, equally spaced means (Table I's family); `free`:
    /// symmetric free means (a lower objective J).
    #[cfg_attr(feature = "serde", serde(default))]
    pub spacing: Spacing,
}

impl SplitLibraryOptions {
    /// Checks R = `components` against [[`MIN_SPLIT_COMPONENTS`], [`MAX_SPLIT_COMPONENTS`]]
    /// (λ is checked by [`SplitLibrary::for_components`]).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `components`.
    pub fn validate(&self) -> Result<()> {
        Error::check_range(
            "components",
            self.components,
            MIN_SPLIT_COMPONENTS,
            MAX_SPLIT_COMPONENTS,
        )?;
        Ok(())
    }

    /// The library of eqs. (13)–(14): Table I verbatim for R = 4, λ = 0.001, equal spacing,
    /// else [`SplitLibrary::optimise`].
    ///
    /// # Errors
    /// As [`SplitLibraryOptions::validate`], then [`SplitLibrary::for_components`] (naming
    /// `lambda_`).
    pub fn library(&self) -> Result<SplitLibrary> {
        self.validate()?;
        SplitLibrary::for_components(self.components, self.lambda_, self.spacing).map_err(|e| {
            e.map_field(|f| match f {
                "lambda" => "lambda_".into(),
                other => other.into(),
            })
        })
    }

    /// [`SplitLibraryOptions::library`], memoised per thread on the last (R, λ, spacing): a
    /// caller that asks for the same split repeatedly (a demo page) pays for one optimisation
    /// (a few ms in wasm).
    ///
    /// # Errors
    /// As [`SplitLibraryOptions::library`] (errors are not memoised).
    #[cfg(feature = "std")]
    pub fn library_memo(&self) -> Result<SplitLibrary> {
        type Key = (usize, u64, Spacing);
        std::thread_local! {
            static LAST: core::cell::RefCell<Option<(Key, SplitLibrary)>> =
                const { core::cell::RefCell::new(None) };
        }
        let key = (self.components, self.lambda_.to_bits(), self.spacing);
        let hit = LAST.with(|c| {
            c.borrow()
                .as_ref()
                .filter(|(k, _)| *k == key)
                .map(|(_, l)| l.clone())
        });
        if let Some(lib) = hit {
            return Ok(lib);
        }
        let lib = self.library()?;
        LAST.with(|c| *c.borrow_mut() = Some((key, lib.clone())));
        Ok(lib)
    }
}

/// An R-component split of N(0, 1), eq. (14) of `001_…`, with its objective J of eq. (13)
/// and its variance: R = 4, λ = 0.001, equal spacing gives Table I verbatim.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SplitLibraryReport {
    /// The component weights w̃_j, one per component (they sum to 1).
    pub weights: Vec<f64>,
    /// The component means m̃_j, ascending and symmetric about 0.
    pub means: Vec<f64>,
    /// The components' common standard deviation σ̃ > 0.
    pub sigma: f64,
    /// The split objective J of eq. (13) at the optimum (L2 error plus λ σ̃²).
    pub objective: f64,
    /// The mixture variance σ̃² + Σ w m² (Table I: 0.9503).
    pub variance: f64,
}

impl From<&SplitLibrary> for SplitLibraryReport {
    fn from(l: &SplitLibrary) -> Self {
        Self {
            weights: l.weights().to_vec(),
            means: l.means().to_vec(),
            sigma: l.sigma(),
            objective: l.objective(),
            variance: l.variance(),
        }
    }
}

/// Options of a bounded split request: Algorithm 2 (Algorithm 1 for one region) of `001_…`
/// on `mixture` along the boundaries of `regions`, with the split library (R, λ, spacing)
/// and [`SplitOptions`]' knobs side by side. The defaults are those of [`defaults`].
#[derive(Clone, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SplitForRegionsOptions {
    /// The mixture to split: weights ≥ 0, means of length n, covariances n × n.
    pub mixture: GaussianMixture,
    /// One or more regions (at most 32) of dimension `position_dims`.
    pub regions: Vec<Region>,
    /// The number n_s of position components: the first n_s state components are the position
    /// that regions refer to (default 2; in [1, 8]).
    #[cfg_attr(feature = "serde", serde(default = "defaults::position_dims"))]
    pub position_dims: usize,
    /// The minimum weight w_min ≥ 0 to split: lighter components are not split (default 0.01;
    /// absolute weight).
    #[cfg_attr(feature = "serde", serde(default = "defaults::min_weight"))]
    pub min_weight: f64,
    /// The number R of components each split makes (default 3), an integer in [2, 16].
    #[cfg_attr(feature = "serde", serde(default = "defaults::components"))]
    pub components: usize,
    /// The split library's penalty weight λ of eq. (13) (default 0.001), in [1e-6, 10]
    /// (in Rust `lambda_`: see [`SplitLibraryOptions::lambda_`]).
    #[cfg_attr(feature = "serde", serde(default = "defaults::lambda"))]
    pub lambda_: f64,
    /// The split library's family: how its means are spaced (default `equal`).
    #[cfg_attr(feature = "serde", serde(default))]
    pub spacing: Spacing,
    /// The collocation grid's Mahalanobis radius ζ > 0 (default 2, as the authors' pyest).
    /// Components whose boundary lies beyond ζ are not split, which floors the partition
    /// error at a few 1e-3 to 1e-2 of mass; 3 lowers that part to about 1e-4, with more
    /// components.
    #[cfg_attr(feature = "serde", serde(default = "defaults::grid_bound"))]
    pub grid_bound: f64,
    /// The number N_g of collocation grid points per axis (default 15; N_g^position_dims ≤
    /// 20000).
    #[cfg_attr(feature = "serde", serde(default = "defaults::grid_points"))]
    pub grid_points: usize,
    /// The most recursion levels (default 16, at most 64); 0 splits nothing: the result is the
    /// mean-based partition of `mixture` itself.
    #[cfg_attr(feature = "serde", serde(default = "defaults::max_depth"))]
    pub max_depth: usize,
    /// The most components the split may make (default 10000, at most 50000).
    #[cfg_attr(feature = "serde", serde(default = "defaults::max_components"))]
    pub max_components: usize,
}

impl SplitForRegionsOptions {
    /// The options with the defaults of [`defaults`] for everything but the mixture and the
    /// regions.
    pub fn new(mixture: GaussianMixture, regions: Vec<Region>) -> Self {
        let s = SplitOptions::default();
        Self {
            mixture,
            regions,
            position_dims: s.position_dims,
            min_weight: s.min_weight,
            components: defaults::components(),
            lambda_: defaults::lambda(),
            spacing: Spacing::default(),
            grid_bound: s.grid_bound,
            grid_points: s.grid_points,
            max_depth: s.max_depth,
            max_components: s.max_components,
        }
    }

    /// Algorithm 1–2's knobs.
    pub fn split_options(&self) -> SplitOptions {
        SplitOptions {
            position_dims: self.position_dims,
            min_weight: self.min_weight,
            grid_bound: self.grid_bound,
            grid_points: self.grid_points,
            max_depth: self.max_depth,
            max_components: self.max_components,
        }
    }

    /// The split library's options (R, λ, spacing).
    pub fn library_options(&self) -> SplitLibraryOptions {
        SplitLibraryOptions {
            components: self.components,
            lambda_: self.lambda_,
            spacing: self.spacing,
        }
    }

    /// Checks the request against the caps of a bounded caller, in this order: 1 to
    /// [`MAX_REGIONS`] regions; [`check_bounded_split`]; the grid N_g^{n_s} at most
    /// [`MAX_GRID_SIZE`](super::MAX_GRID_SIZE); the worst-case work [`split_work`] at most [`SPLIT_WORK_BUDGET`].
    ///
    /// # Errors
    /// [`Error::Count`] naming `regions`; [`Error::OutOfRange`] naming the first integer knob
    /// out of range; [`Error::OverBudget`] naming `grid_points^position_dims` (the grid; its
    /// `at_most` is the largest `grid_points` at this `position_dims`) or `max_components`
    /// (the work).
    pub fn validate(&self) -> Result<()> {
        Error::check_count("regions", "entries", self.regions.len(), 1, MAX_REGIONS)?;
        check_bounded_split(self.components, &self.split_options())?;
        let grid = grid_size(self.position_dims, self.grid_points).ok_or_else(|| {
            let work = (0..self.position_dims)
                .try_fold(1usize, |acc, _| acc.checked_mul(self.grid_points))
                .unwrap_or(usize::MAX);
            // both fields in the path: either may be the one to lower
            Error::OverBudget {
                what: "grid_points^position_dims".into(),
                measure: "collocation points per component",
                work,
                limit: "20000",
                at_most: max_grid_points(self.position_dims),
            }
        })?;
        let work = split_work(self.max_components, grid, &self.regions);
        if work > SPLIT_WORK_BUDGET {
            let per_component = work / self.max_components as f64;
            return Err(Error::OverBudget {
                what: "max_components".into(),
                measure: "inclusion tests in the worst case (components × grid points × \
                          regions)",
                work: work as usize,
                limit: "5e8; lower the most components, the grid points or the number of regions",
                at_most: (SPLIT_WORK_BUDGET / per_component) as usize,
            });
        }
        Ok(())
    }
}

/// The largest N_g with N_g^{n_s} ≤ [`MAX_GRID_SIZE`](super::MAX_GRID_SIZE).
fn max_grid_points(position_dims: usize) -> usize {
    let mut g = 2;
    while grid_size(position_dims, g + 1).is_some() {
        g += 1;
    }
    g
}

/// The result of [`split_for_regions_report`]: the split mixture, its mean-based partition
/// (11)–(12) of `001_…` for the first region, and the exact mass of that region.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SplitForRegionsReport {
    /// The split mixture (each input component replaced in place by its descendants).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::components"))]
    pub mixture: GaussianMixture,
    /// The mean-based partition (11)–(12) for the first region: the inside weight.
    pub inside: f64,
    /// The mean-based partition for the first region: the outside weight (of the components
    /// whose mean lies outside it).
    pub outside: f64,
    /// `inside_mask[i]`: whether component i of `mixture` is in p_S, i.e. its mean (position
    /// part) lies in the first region (`inside` is the sum of the weights it selects).
    pub inside_mask: Vec<bool>,
    /// The exact mass ⟨1_S, p⟩ of the first region S under the input mixture p, eq. (8)
    /// (`None` when too costly: [`exact_mass_affordable`]).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::nullable"))]
    pub exact_inside: Option<f64>,
    /// The number of recursion levels used.
    pub depth: usize,
    /// The number of split operations (components replaced by R children).
    pub splits: usize,
    /// `None`, or the cap that stopped the recursion.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::nullable"))]
    pub stop: Option<SplitStop>,
}

/// Algorithm 2 (Algorithm 1 for one region) of `001_…` with `library` (R, λ and spacing
/// of `options` are not read: the caller builds or caches the library, e.g. by
/// [`SplitLibraryOptions::library`] of [`SplitForRegionsOptions::library_options`]), then
/// the mean-based partition (11)–(12) for the first region and its exact mass (8). The
/// result does not depend on the order of the regions.
///
/// # Errors
/// [`SplitForRegionsOptions::validate`], then those of [`split_for_regions`], [`partition`]
/// and [`Region::gaussian_mass`] (naming `mixture[i]`).
pub fn split_for_regions_report(
    options: &SplitForRegionsOptions,
    library: &SplitLibrary,
) -> Result<SplitForRegionsReport> {
    options.validate()?;
    let mixture = &options.mixture;
    let out = split_for_regions(mixture, &options.regions, library, &options.split_options())?;
    let first = &options.regions[0];
    let part = partition(&out.mixture, first)?;
    // The same inclusion test as the partition (11)–(12), per component.
    let inside_mask: Vec<bool> = out
        .mixture
        .components()
        .iter()
        .map(|(_, g)| first.contains(g.mean().as_slice()))
        .collect();
    let exact_inside = if exact_mass_affordable(mixture.len(), first) {
        let mut total = 0.0;
        for (i, (w, g)) in mixture.components().iter().enumerate() {
            total += w * first
                .gaussian_mass(g, &alloc::format!("mixture[{i}]"))?
                .value;
        }
        Some(total)
    } else {
        None
    };
    Ok(SplitForRegionsReport {
        mixture: out.mixture,
        inside: part.inside_weight,
        outside: part.outside_weight,
        inside_mask,
        exact_inside,
        depth: out.depth,
        splits: out.splits,
        stop: out.stop,
    })
}

/// Options of the Fig. 5 negative-information example of `001_…`: one step or all.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct NegativeInformationOptions {
    /// One step, 1–3; `None`: the whole scenario.
    pub step: Option<usize>,
}

/// One predict → split → non-detection update cycle of the Fig. 5 example of `001_…`, flat
/// ([`NegativeInformationStep`] with the split's depth and count next to its mixture).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NegativeInformationStepReport {
    /// The step number k: 1, 2 or 3.
    pub step: usize,
    /// The predicted density p_{k|k−1}, a Gaussian mixture.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::components"))]
    pub predicted: GaussianMixture,
    /// Algorithm 1 applied to it (R = 3, λ = 0.001, w_min = 0.01).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::components"))]
    pub split: GaussianMixture,
    /// The posterior density p_{k|k}: the mean-based partition's outside part, normalised
    /// (eqs. (57)–(58)).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::components"))]
    pub posterior: GaussianMixture,
    /// The predicted probability 1 − Δ_k of the non-detection.
    pub non_detection_prob: f64,
    /// The exact predicted mass in the field of view, ⟨1_S, p_{k|k−1}⟩ ∈ [0, 1].
    pub predicted_inside: f64,
    /// The exact posterior mass in the field of view, ⟨1_S, p_{k|k}⟩ ∈ [0, 1].
    pub posterior_inside: f64,
    /// The number of recursion levels used by the split.
    pub depth: usize,
    /// The number of split operations (components replaced by R children).
    pub splits: usize,
}

impl From<&NegativeInformationStep> for NegativeInformationStepReport {
    fn from(s: &NegativeInformationStep) -> Self {
        Self {
            step: s.step,
            predicted: s.predicted.clone(),
            split: s.split.mixture.clone(),
            posterior: s.posterior.clone(),
            non_detection_prob: s.non_detection_prob,
            predicted_inside: s.predicted_inside,
            posterior_inside: s.posterior_inside,
            depth: s.split.depth,
            splits: s.split.splits,
        }
    }
}

/// The Fig. 5 example of `001_…` as a result: the FoV, the initial mixture (state x, y, ẋ,
/// ẏ) and the three steps (in Rust, [`NegativeInformationScenario::fig5`] and its run).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NegativeInformationReport {
    /// The field of view S, a box in (x, y).
    pub fov: Region,
    /// The initial density p_{0|0}, a Gaussian mixture over (x, y, ẋ, ẏ).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::components"))]
    pub initial: GaussianMixture,
    /// The three predict → split → update steps, k = 1, 2, 3.
    pub steps: Vec<NegativeInformationStepReport>,
}

impl NegativeInformationReport {
    /// [`NegativeInformationScenario::fig5`], run.
    ///
    /// # Errors
    /// Those of [`NegativeInformationScenario::run`] (none in practice).
    pub fn fig5() -> Result<Self> {
        let sc = NegativeInformationScenario::fig5()?;
        let steps = sc.run()?;
        Ok(Self {
            fov: sc.fov,
            initial: sc.initial,
            steps: steps
                .iter()
                .map(NegativeInformationStepReport::from)
                .collect(),
        })
    }

    /// [`NegativeInformationReport::fig5`], computed once per thread (it is deterministic;
    /// about 8 ms in wasm) and cloned for every later call.
    ///
    /// # Errors
    /// As [`NegativeInformationReport::fig5`] (none in practice).
    #[cfg(feature = "std")]
    pub fn fig5_memo() -> Result<Self> {
        std::thread_local! {
            static FIG5: core::cell::OnceCell<NegativeInformationReport> =
                const { core::cell::OnceCell::new() };
        }
        if let Some(r) = FIG5.with(|c| c.get().cloned()) {
            return Ok(r);
        }
        let r = Self::fig5()?;
        Ok(FIG5.with(|c| c.get_or_init(|| r).clone()))
    }

    /// Step `k` (1 to the number of steps).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `step`.
    pub fn step(&self, k: usize) -> Result<&NegativeInformationStepReport> {
        Error::check_range("step", k, 1, self.steps.len())?;
        Ok(&self.steps[k - 1])
    }
}

/// The Fig. 5 example's result for `options`: the whole report (`step` omitted) or one step.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(untagged)
)]
pub enum NegativeInformationResult {
    /// `step` omitted: the FoV, the initial mixture and the steps.
    Whole(NegativeInformationReport),
    /// One step.
    Step(NegativeInformationStepReport),
}

impl NegativeInformationOptions {
    /// Checks `step` against [1, 3] (Fig. 5's three steps).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `step`.
    pub fn validate(&self) -> Result<()> {
        if let Some(k) = self.step {
            Error::check_range("step", k, 1, 3)?;
        }
        Ok(())
    }

    /// The part of `report` these options ask for.
    ///
    /// # Errors
    /// As [`NegativeInformationOptions::validate`] and [`NegativeInformationReport::step`].
    pub fn select(&self, report: &NegativeInformationReport) -> Result<NegativeInformationResult> {
        self.validate()?;
        Ok(match self.step {
            None => NegativeInformationResult::Whole(report.clone()),
            Some(k) => NegativeInformationResult::Step(report.step(k)?.clone()),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gaussian::Gaussian;
    use alloc::string::ToString;
    use alloc::vec;

    fn unit_mixture() -> GaussianMixture {
        let g = Gaussian::from_slices(&[0.0, 0.0], &[1.0, 0.0, 0.0, 1.0], "mixture[0]").unwrap();
        GaussianMixture::new(vec![(1.0, g)], "mixture").unwrap()
    }

    fn half_plane() -> Region {
        Region::axis_box(&[0.3, -10.0], &[10.0, 10.0], "regions[0]").unwrap()
    }

    #[test]
    fn eq13_library_request_gives_table1_and_names_its_fields() {
        let o = SplitLibraryOptions {
            components: 4,
            lambda_: 0.001,
            spacing: Spacing::Equal,
        };
        let r = SplitLibraryReport::from(&o.library().unwrap());
        assert_eq!(r, SplitLibraryReport::from(&SplitLibrary::table_i()));
        assert!((r.variance - 0.9503).abs() < 1e-4);
        let bad_r = SplitLibraryOptions {
            components: 17,
            ..o.clone()
        };
        assert_eq!(
            bad_r.library().unwrap_err().to_string(),
            "components must be an integer in [2, 16], got 17"
        );
        let bad_lambda = SplitLibraryOptions { lambda_: 0.0, ..o };
        assert!(
            bad_lambda
                .library()
                .unwrap_err()
                .to_string()
                .starts_with("lambda_ ")
        );
    }

    #[test]
    fn alg2_request_caps_name_the_field() {
        let mut o = SplitForRegionsOptions::new(unit_mixture(), Vec::new());
        assert_eq!(
            o.validate().unwrap_err().to_string(),
            "regions must have 1 to 32 entries, got 0"
        );
        o.regions = vec![half_plane()];
        o.validate().unwrap();
        o.components = 1;
        assert_eq!(o.validate().unwrap_err().field(), "components");
        o.components = 3;
        o.grid_points = 200; // 200² = 40000 > 20000
        let e = o.validate().unwrap_err();
        assert_eq!(e.field(), "grid_points^position_dims");
        assert!(e.to_string().contains("(at most 141)"), "{e}");
        o.grid_points = 141; // 141² = 19881; 50000 × 19881 × 1 ≈ 9.9e8 > 5e8
        o.max_components = 50_000;
        let e = o.validate().unwrap_err();
        assert_eq!(e.field(), "max_components");
        let Error::OverBudget { at_most, .. } = e else {
            panic!("{e:?}")
        };
        o.max_components = at_most;
        o.validate().unwrap();
        o.max_components = at_most + 1;
        assert!(o.validate().is_err());
    }

    #[test]
    fn eq11_request_reports_the_partition_its_mask_and_the_exact_mass() {
        let o = SplitForRegionsOptions::new(unit_mixture(), vec![half_plane()]);
        let lib = o.library_options().library().unwrap();
        let r = split_for_regions_report(&o, &lib).unwrap();
        assert_eq!(r.inside_mask.len(), r.mixture.len());
        let masked: f64 = r
            .mixture
            .components()
            .iter()
            .zip(&r.inside_mask)
            .filter(|(_, m)| **m)
            .map(|((w, _), _)| w)
            .sum();
        assert!((masked - r.inside).abs() < 1e-12);
        assert!((r.inside + r.outside - 1.0).abs() < 1e-9);
        // ⟨1_S, N(0, I)⟩ = 1 − Φ(0.3) = 0.38209 (the box's other sides are 10σ away)
        let exact = r.exact_inside.unwrap();
        assert!((exact - 0.382_088_6).abs() < 1e-6, "{exact}");
        assert!((r.inside - exact).abs() < 0.03);
        assert!(r.splits > 0 && r.stop.is_none());
        // max_depth 0: the partition of the input itself
        let none = SplitForRegionsOptions { max_depth: 0, ..o };
        let r0 = split_for_regions_report(&none, &lib).unwrap();
        assert_eq!(
            (r0.splits, r0.inside, r0.inside_mask),
            (0, 0.0, vec![false])
        );
    }

    #[test]
    fn fig5_request_selects_one_step_or_all() {
        let report = NegativeInformationReport::fig5().unwrap();
        assert_eq!(report.steps.len(), 3);
        let sc = NegativeInformationScenario::fig5().unwrap();
        let steps = sc.run().unwrap();
        assert_eq!(
            report.steps[1],
            NegativeInformationStepReport::from(&steps[1])
        );
        assert_eq!(report.steps[1].depth, steps[1].split.depth);
        let two = NegativeInformationOptions { step: Some(2) }
            .select(&report)
            .unwrap();
        assert_eq!(
            two,
            NegativeInformationResult::Step(report.steps[1].clone())
        );
        let all = NegativeInformationOptions::default()
            .select(&report)
            .unwrap();
        assert_eq!(all, NegativeInformationResult::Whole(report.clone()));
        let e = NegativeInformationOptions { step: Some(4) }
            .select(&report)
            .unwrap_err();
        assert_eq!(e.to_string(), "step must be an integer in [1, 3], got 4");
    }

    #[cfg(feature = "std")]
    #[test]
    fn memos_give_the_uncached_values_and_do_not_keep_errors() {
        let o = SplitLibraryOptions {
            components: 4,
            lambda_: 0.001,
            spacing: Spacing::Equal,
        };
        assert_eq!(o.library_memo().unwrap(), o.library().unwrap());
        assert_eq!(o.library_memo().unwrap(), o.library().unwrap());
        let other = SplitLibraryOptions {
            components: 3,
            ..o.clone()
        };
        assert_eq!(other.library_memo().unwrap(), other.library().unwrap());
        let bad = SplitLibraryOptions {
            components: 1,
            ..o.clone()
        };
        assert_eq!(bad.library_memo().unwrap_err(), bad.library().unwrap_err());
        assert_eq!(o.library_memo().unwrap(), o.library().unwrap());
        let fig5 = NegativeInformationReport::fig5().unwrap();
        assert_eq!(NegativeInformationReport::fig5_memo().unwrap(), fig5);
        assert_eq!(NegativeInformationReport::fig5_memo().unwrap(), fig5);
    }
}
