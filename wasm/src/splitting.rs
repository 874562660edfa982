//! Recursive Gaussian splitting along region boundaries and mixture reduction (Section IV of
//! LeGrand & Ferrari, "Split Happens! Imprecise and negative information in Gaussian mixture
//! random finite set filtering", paper 001).

use serde::{Deserialize, Serialize};
use tsify::Tsify;
use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, check_range, range_error, read, write};
use crate::types::{BoxRegion, MixtureComponent, Region, mixture_out};
use fisst::Error;
use fisst::gaussian::GaussianMixture;
use fisst::mixture::{merge_close, prune, runnalls};
use fisst::regions::Region as CoreRegion;
use fisst::splitting::{
    MAX_GRID_SIZE as MAX_GRID, MAX_REDUCED_COMPONENTS, MAX_REGIONS, MAX_RUNNALLS_INPUT,
    MAX_SPLIT_COMPONENTS, MIN_SPLIT_COMPONENTS, NegativeInformationScenario as Fig5Scenario,
    NegativeInformationStep as Fig5Step, SPLIT_WORK_BUDGET, Spacing, SplitLibrary, SplitOptions,
    SplitStop, check_bounded_split, check_reduce_input, defaults, exact_mass_affordable, grid_size,
    partition, split_for_regions, split_work,
};

/// The family of a split library: how its means are spaced.
#[derive(Clone, Copy, Debug, Default, Deserialize, Tsify)]
#[serde(rename_all = "lowercase")]
pub enum SpacingName {
    /// Symmetric, equally spaced means (Table I's family).
    #[default]
    Equal,
    /// Symmetric free means (a lower objective J of eq. (13)).
    Free,
}

impl From<SpacingName> for Spacing {
    fn from(s: SpacingName) -> Self {
        match s {
            SpacingName::Equal => Spacing::Equal,
            SpacingName::Free => Spacing::Free,
        }
    }
}

/// Options of `splitLibrary` (the split library of eqs. (13)–(14) of LeGrand & Ferrari, "Split
/// Happens! Imprecise and negative information in Gaussian mixture random finite set filtering"
/// (paper 001)).
#[derive(Deserialize, Tsify)]
pub struct SplitLibraryOptions {
    /// The number R of components of the split: an integer in [2, 16].
    pub components: usize,
    /// The weight λ ∈ [1e-6, 10] of the σ̃² penalty in the split objective J of eq. (13).
    pub lambda: f64,
    /// `'equal'` (default): symmetric, equally spaced means (Table I's family); `'free'`:
    /// symmetric free means (a lower objective J).
    #[serde(default)]
    pub spacing: SpacingName,
}

/// An R-component split of N(0, 1). `components: 4, lambda: 0.001, spacing: 'equal'`
/// returns Table I of LeGrand & Ferrari, "Split Happens! Imprecise and negative information in
/// Gaussian mixture random finite set filtering" (paper 001) verbatim.
#[derive(Serialize, Tsify)]
pub struct SplitLibraryResult {
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

/// Options of `splitForRegions` (Algorithms 1–2 of LeGrand & Ferrari, "Split Happens! Imprecise and
/// negative information in Gaussian mixture random finite set filtering" (paper 001)).
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct SplitForRegionsOptions {
    /// The mixture to split: weights ≥ 0, means of length n, covariances n × n.
    #[tsify(type = "WeightedGaussian[]")]
    pub mixture: GaussianMixture,
    /// One or more regions (at most 32) of dimension `positionDims`.
    pub regions: Vec<Region>,
    /// The number n_s of position components: the first n_s state components are the position
    /// that regions refer to (default 2; in [1, 8]).
    #[serde(default = "defaults::position_dims")]
    pub position_dims: usize,
    /// The minimum weight w_min ≥ 0 to split: lighter components are not split (default 0.01;
    /// absolute weight).
    #[serde(default = "defaults::min_weight")]
    pub min_weight: f64,
    /// The number R of components each split makes (default 3), an integer in [2, 16].
    #[serde(default = "defaults::components")]
    pub components: usize,
    /// The split library's penalty weight λ of eq. (13) (default 0.001), in [1e-6, 10].
    #[serde(default = "defaults::lambda")]
    pub lambda: f64,
    /// The split library's family: how its means are spaced (default `'equal'`).
    #[serde(default)]
    pub spacing: SpacingName,
    /// The collocation grid's Mahalanobis radius ζ > 0 (default 2, as the authors' pyest).
    /// Components whose boundary lies beyond ζ are not split, which floors the partition
    /// error at a few 1e-3 to 1e-2 of mass; 3 lowers that part to about 1e-4, with more
    /// components.
    #[serde(default = "defaults::grid_bound")]
    pub grid_bound: f64,
    /// The number N_g of collocation grid points per axis (default 15; N_g^positionDims ≤
    /// 20000).
    #[serde(default = "defaults::grid_points")]
    pub grid_points: usize,
    /// The most recursion levels (default 16, at most 64); 0 splits nothing: the result is the
    /// mean-based partition of `mixture` itself.
    #[serde(default = "defaults::max_depth")]
    pub max_depth: usize,
    /// The most components the split may make (default 10000, at most 50000).
    #[serde(default = "defaults::max_components")]
    pub max_components: usize,
}

/// The cap that stopped a recursion.
#[derive(Clone, Copy, Debug, Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub enum StopName {
    /// `maxDepth` was reached.
    MaxDepth,
    /// `maxComponents` was reached.
    MaxComponents,
}

/// Result of `splitForRegions`: the split mixture and its mean-based partition.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct SplitForRegionsResult {
    /// The split mixture (each input component replaced in place by its descendants).
    pub mixture: Vec<MixtureComponent>,
    /// The mean-based partition (11)–(12) for the first region: the inside weight.
    pub inside: f64,
    /// The mean-based partition for the first region: the outside weight (of the components
    /// whose mean lies outside it).
    pub outside: f64,
    /// `insideMask[i]`: whether component i of `mixture` is in p_S, i.e. its mean (position
    /// part) lies in the first region (`inside` is the sum of the weights it selects).
    pub inside_mask: Vec<bool>,
    /// The exact mass ⟨1_S, p⟩ of the first region S under the input mixture p (null when too
    /// costly: more than ~0.5 s of masses, or positionDims > 4).
    #[tsify(type = "number | null")]
    pub exact_inside: Option<f64>,
    /// The number of recursion levels used.
    pub depth: usize,
    /// The number of split operations (components replaced by R children).
    pub splits: usize,
    /// null, or the cap that stopped the recursion.
    #[tsify(type = "null | 'maxDepth' | 'maxComponents'")]
    pub stop: Option<StopName>,
}

/// Options of `reduceMixture`.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct ReduceMixtureOptions {
    /// The mixture to reduce: at most 5000 components.
    #[tsify(type = "WeightedGaussian[]")]
    pub mixture: GaussianMixture,
    /// Drop components lighter than this, renormalising the rest (default 0: keep all).
    #[serde(default)]
    pub prune_below: f64,
    /// Vo & Ma merge within this Mahalanobis distance (U = distance²); omitted: no merging.
    #[tsify(optional)]
    pub merge_distance: Option<f64>,
    /// Runnalls' reduction to at most this many components, an integer in [1, 1e6];
    /// omitted: no cap. Runnalls' reduction takes at most 3000 components (those left after
    /// pruning and merging; a RangeError naming options.maxComponents beyond).
    #[tsify(optional)]
    pub max_components: Option<usize>,
}

/// Options of `negativeInformationScenario` (Fig. 5 of LeGrand & Ferrari, "Split Happens!",
/// paper 001).
#[derive(Deserialize, Tsify)]
pub struct NegativeInformationOptions {
    /// One step, 1–3; omitted: the whole scenario.
    #[tsify(optional)]
    pub step: Option<usize>,
}

/// One predict → split → non-detection update cycle of the Fig. 5 scenario of LeGrand & Ferrari,
/// "Split Happens! Imprecise and negative information in Gaussian mixture random finite set
/// filtering" (paper 001).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct NegativeInformationStep {
    /// The step number k: 1, 2 or 3.
    pub step: usize,
    /// The predicted density p_{k|k−1}, a Gaussian mixture.
    pub predicted: Vec<MixtureComponent>,
    /// Algorithm 1 applied to it (R = 3, λ = 0.001, w_min = 0.01).
    pub split: Vec<MixtureComponent>,
    /// The posterior density p_{k|k}: the mean-based partition's outside part, normalised.
    pub posterior: Vec<MixtureComponent>,
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

/// Result of `negativeInformationScenario`: the Fig. 5 scenario of LeGrand & Ferrari, "Split
/// Happens! Imprecise and negative information in Gaussian mixture random finite set filtering"
/// (paper 001): FoV, initial mixture (state x, y, ẋ, ẏ) and the three steps.
#[derive(Serialize, Tsify)]
pub struct NegativeInformationScenario {
    /// The field of view S, a box in (x, y).
    pub fov: FovBox,
    /// The initial density p_{0|0}, a Gaussian mixture over (x, y, ẋ, ẏ).
    pub initial: Vec<MixtureComponent>,
    /// The three predict → split → update steps, k = 1, 2, 3.
    pub steps: Vec<NegativeInformationStep>,
}

/// A box region as results give it: `{ box: { min, max } }`.
#[derive(Serialize, Tsify)]
#[tsify(type = "Region")]
pub struct FovBox {
    /// The box `{ min, max }`.
    #[serde(rename = "box")]
    pub region: BoxRegion,
}

/// A split library's key: (R, λ as bits, spacing).
type LibraryKey = (usize, u64, Spacing);

thread_local! {
    /// The last library computed (the demo page calls with the same R and λ repeatedly;
    /// an optimisation costs a few ms in wasm).
    static LAST_LIBRARY: std::cell::RefCell<Option<(LibraryKey, SplitLibrary)>> =
        const { std::cell::RefCell::new(None) };
}

/// [`SplitLibrary::for_components`], memoised on the last (R, λ, spacing); errors name the
/// fields under `prefix`.
fn library(r: usize, lambda: f64, spacing: Spacing, prefix: &str) -> JsResult<SplitLibrary> {
    let key = (r, lambda.to_bits(), spacing);
    if let Some(lib) = LAST_LIBRARY.with(|c| {
        c.borrow()
            .as_ref()
            .filter(|(k, _)| *k == key)
            .map(|(_, l)| l.clone())
    }) {
        return Ok(lib);
    }
    let lib = SplitLibrary::for_components(r, lambda, spacing).or_throw_in(prefix)?;
    LAST_LIBRARY.with(|c| *c.borrow_mut() = Some((key, lib.clone())));
    Ok(lib)
}

/// The optimal R-component split of N(0, 1) of eqs. (13)–(14) of LeGrand & Ferrari, "Split
/// Happens! Imprecise and negative information in Gaussian mixture random finite set filtering"
/// (paper 001): options
/// `{ components, lambda, spacing = 'equal' }`; returns `{ weights, means, sigma, objective,
/// variance }`. `components: 4, lambda: 0.001` with equal spacing is Table I verbatim.
#[wasm_bindgen(js_name = splitLibrary, unchecked_return_type = "SplitLibraryResult")]
pub fn split_library_js(
    #[wasm_bindgen(unchecked_param_type = "SplitLibraryOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: SplitLibraryOptions = read(options, "options")?;
    let r = Error::check_range(
        "components",
        o.components,
        MIN_SPLIT_COMPONENTS,
        MAX_SPLIT_COMPONENTS,
    )
    .or_throw_in("options")?;
    let lib = library(r, o.lambda, o.spacing.into(), "options")?;
    write(&SplitLibraryResult {
        weights: lib.weights().to_vec(),
        means: lib.means().to_vec(),
        sigma: lib.sigma(),
        objective: lib.objective(),
        variance: lib.variance(),
    })
}

/// Algorithm 2 (Algorithm 1 for one region) of LeGrand & Ferrari, "Split Happens! Imprecise and
/// negative information in Gaussian mixture random finite set filtering" (paper 001): recursively
/// splits the components of `mixture` that straddle a boundary of any of `regions`, then the
/// mean-based partition for the first region. Options `{ mixture, regions, positionDims = 2,
/// minWeight = 0.01, components = 3, lambda = 0.001, spacing = 'equal', gridBound = 2,
/// gridPoints = 15, maxDepth = 16, maxComponents = 10000 }`; returns `{ mixture, inside,
/// outside, insideMask, exactInside, depth, splits, stop }` (`insideMask[i]`: component i's
/// mean is in the first region). The result does not depend on the order of `regions`.
#[wasm_bindgen(js_name = splitForRegions, unchecked_return_type = "SplitForRegionsResult")]
pub fn split_for_regions_js(
    #[wasm_bindgen(unchecked_param_type = "SplitForRegionsOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: SplitForRegionsOptions = read(options, "options")?;
    let mixture = o.mixture;
    if o.regions.is_empty() || o.regions.len() > MAX_REGIONS {
        return Err(range_error(format!(
            "options.regions must have 1 to {MAX_REGIONS} entries, got {}",
            o.regions.len()
        )));
    }
    let regions = o
        .regions
        .into_iter()
        .enumerate()
        .map(|(i, r)| r.into_core(&format!("options.regions[{i}]")))
        .collect::<JsResult<Vec<(CoreRegion, f64)>>>()?;
    let split_opts = SplitOptions {
        position_dims: o.position_dims,
        min_weight: o.min_weight,
        grid_bound: o.grid_bound,
        grid_points: o.grid_points,
        max_depth: o.max_depth,
        max_components: o.max_components,
    };
    check_bounded_split(o.components, &split_opts).or_throw_rendered("options")?;
    let (position_dims, grid_points) = (o.position_dims, o.grid_points);
    let grid_size = grid_size(position_dims, grid_points).ok_or_else(|| {
        range_error(format!(
            "options.gridPoints^positionDims must be at most {MAX_GRID}, got \
             {grid_points}^{position_dims}"
        ))
    })?;
    let only: Vec<CoreRegion> = regions.into_iter().map(|(reg, _)| reg).collect();
    let work = split_work(o.max_components, grid_size, &only);
    if work > SPLIT_WORK_BUDGET {
        return Err(range_error(format!(
            "options.maxComponents × gridPoints^positionDims × regions is {work:.2e} inclusion \
             tests in the worst case, at most {SPLIT_WORK_BUDGET:e} are allowed; lower \
             maxComponents, gridPoints or the number of regions"
        )));
    }
    let library = library(o.components, o.lambda, o.spacing.into(), "options")?;
    let out = split_for_regions(&mixture, &only, &library, &split_opts).or_throw_in("options")?;
    let first = &only[0];
    let part = partition(&out.mixture, first).or_throw_in("options")?;
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
                .gaussian_mass(g, &format!("options.mixture[{i}]"))
                .or_throw()?
                .value;
        }
        Some(total)
    } else {
        None
    };
    write(&SplitForRegionsResult {
        mixture: mixture_out(&out.mixture),
        inside: part.inside_weight,
        outside: part.outside_weight,
        inside_mask,
        exact_inside,
        depth: out.depth,
        splits: out.splits,
        stop: out.stop.map(|s| match s {
            SplitStop::MaxDepth => StopName::MaxDepth,
            SplitStop::MaxComponents => StopName::MaxComponents,
        }),
    })
}

/// Mixture reduction: prune (renormalising), Vo & Ma's Mahalanobis merge, then Runnalls'
/// KL-based reduction, each pass only when asked. Options `{ mixture, pruneBelow = 0,
/// mergeDistance, maxComponents }`; returns the reduced mixture (same shape). The total
/// weight is preserved; merges preserve the mixture's mean and covariance.
#[wasm_bindgen(js_name = reduceMixture, unchecked_return_type = "MixtureComponent[]")]
pub fn reduce_mixture_js(
    #[wasm_bindgen(unchecked_param_type = "ReduceMixtureOptions")] options: JsValue,
) -> JsResult<JsValue> {
    // The length cap before the components are read: reading 10^6 of them alone takes
    // seconds.
    let given = js_sys::Reflect::get(&options, &JsValue::from_str("mixture")).ok();
    if let Some(a) = given.as_ref().and_then(|m| m.dyn_ref::<js_sys::Array>()) {
        check_reduce_input(a.length() as usize).or_throw_rendered("options")?;
    }
    let o: ReduceMixtureOptions = read(options, "options")?;
    check_reduce_input(o.mixture.len()).or_throw_rendered("options")?;
    let mixture = o.mixture;
    let max_components = o
        .max_components
        .map(|m| Error::check_range("max_components", m, 1, MAX_REDUCED_COMPONENTS))
        .transpose()
        .or_throw_rendered("options")?;
    let mut out = prune(&mixture, o.prune_below).or_throw_in("options")?;
    if let Some(d) = o.merge_distance {
        out = merge_close(&out, d).or_throw_in("options")?;
    }
    if let Some(max) = max_components {
        if out.len() > max && out.len() > MAX_RUNNALLS_INPUT {
            return Err(range_error(format!(
                "options.maxComponents: Runnalls' reduction takes at most {MAX_RUNNALLS_INPUT} \
                 components, {} remain after pruning and merging; raise pruneBelow or \
                 mergeDistance",
                out.len()
            )));
        }
        out = runnalls(&out, max).or_throw_in("options")?;
    }
    write(&mixture_out(&out))
}

thread_local! {
    /// The Fig. 5 scenario and its steps: deterministic, so computed once (about 8 ms in
    /// wasm) and shared by every later call.
    static FIG5: std::cell::OnceCell<(Fig5Scenario, Vec<Fig5Step>)> =
        const { std::cell::OnceCell::new() };
}

/// The Fig. 5 scenario and its three steps (cached).
fn fig5() -> JsResult<(Fig5Scenario, Vec<Fig5Step>)> {
    if let Some(v) = FIG5.with(|c| c.get().cloned()) {
        return Ok(v);
    }
    let sc = Fig5Scenario::fig5().or_throw()?;
    let steps = sc.run().or_throw()?;
    FIG5.with(|c| {
        let _ = c.set((sc.clone(), steps.clone()));
    });
    Ok((sc, steps))
}

fn step_out(s: &Fig5Step) -> NegativeInformationStep {
    NegativeInformationStep {
        step: s.step,
        predicted: mixture_out(&s.predicted),
        split: mixture_out(&s.split.mixture),
        posterior: mixture_out(&s.posterior),
        non_detection_prob: s.non_detection_prob,
        predicted_inside: s.predicted_inside,
        posterior_inside: s.posterior_inside,
        depth: s.split.depth,
        splits: s.split.splits,
    }
}

// Overloads: with `step` the one step, without it the whole scenario (the general signature,
// generated by wasm-bindgen, follows).
#[wasm_bindgen(typescript_custom_section)]
const SCENARIO_OVERLOADS: &str = r#"
/**
 * One step (1–3) of the Fig. 5 negative-information example of LeGrand & Ferrari, "Split
 * Happens! Imprecise and negative information in Gaussian mixture random finite set filtering"
 * (paper 001).
 */
export function negativeInformationScenario(options: NegativeInformationOptions & { step: number }): NegativeInformationStep;
/**
 * The whole Fig. 5 negative-information example of LeGrand & Ferrari, "Split Happens! Imprecise
 * and negative information in Gaussian mixture random finite set filtering" (paper 001):
 * `{ fov, initial, steps }`.
 */
export function negativeInformationScenario(options?: NegativeInformationOptions & { step?: undefined }): NegativeInformationScenario;
"#;

/// The negative-information example of Fig. 5 (Section IV-G) of LeGrand & Ferrari, "Split
/// Happens! Imprecise and negative information in Gaussian mixture random finite set filtering"
/// (paper 001): a constant-velocity object
/// crossing a square FoV with three non-detections (p_D = 1), split by Algorithm 1 with
/// w_min = 0.01, R = 3, λ = 0.001 (the scenario's numbers are in the Rust docs of
/// `NegativeInformationScenario::fig5`). Options `{ step }` (optional, 1–3): without it returns
/// `{ fov, initial, steps }`, with it the one step.
#[wasm_bindgen(
    js_name = negativeInformationScenario,
    unchecked_return_type = "NegativeInformationScenario | NegativeInformationStep"
)]
pub fn negative_information_scenario_js(
    #[wasm_bindgen(unchecked_optional_param_type = "NegativeInformationOptions")] options: Option<
        JsValue,
    >,
) -> JsResult<JsValue> {
    let o: Option<NegativeInformationOptions> =
        read(options.unwrap_or(JsValue::UNDEFINED), "options")?;
    let step = o
        .and_then(|o| o.step)
        .map(|k| check_range("options.step", k, 1, 3))
        .transpose()?;
    let (sc, steps) = fig5()?;
    if let Some(k) = step {
        let s = steps
            .get(k - 1)
            .ok_or_else(|| range_error(format!("options.step must be in [1, {}]", steps.len())))?;
        return write(&step_out(s));
    }
    let [min, max] = Fig5Scenario::FIG5_FOV;
    write(&NegativeInformationScenario {
        fov: FovBox {
            region: BoxRegion {
                min: min.to_vec(),
                max: max.to_vec(),
            },
        },
        initial: mixture_out(&sc.initial),
        steps: steps.iter().map(step_out).collect(),
    })
}
