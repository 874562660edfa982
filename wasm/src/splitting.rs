//! Recursive Gaussian splitting along region boundaries and mixture reduction (Section IV of
//! `001_0f0df91eee9b30d5.txt`, "Split happens!").

use wasm_bindgen::prelude::*;

use crate::convert::{
    JsResult, Options, OrThrow, array, boolean_array, number_array, object, range_error, string,
};
use crate::fov::{mixture as mixture_from_js, region as region_from_js};
use fisst::gaussian::GaussianMixture;
use fisst::mixture::{merge_close, prune, runnalls};
use fisst::regions::Region;
use fisst::splitting::{
    NegativeInformationScenario, NegativeInformationStep, Spacing, SplitLibrary, SplitOptions,
    SplitStop, partition, split_for_regions,
};
use js_sys::Array;

/// At most this many regions in one `splitForRegions` call.
const MAX_REGIONS: usize = 32;
/// At most this many collocation points N_g^{n_s} (before the ball cut) per component.
const MAX_GRID: usize = 20_000;
/// Largest `maxComponents` of `splitForRegions`.
const MAX_SPLIT_COMPONENTS: usize = 50_000;
/// Budget of one `splitForRegions` call: maxComponents × grid points × Σ region weights, a
/// worst-case count of inclusion tests (≈ 5 ns each natively: a few seconds in wasm).
const SPLIT_WORK_BUDGET: f64 = 5e8;
/// Budget of the exact inside mass reported by `splitForRegions`, in estimated native µs.
const EXACT_MASS_BUDGET_US: f64 = 5e5;
/// At most this many components enter Runnalls' reduction (O(L²) bound evaluations).
const MAX_RUNNALLS_INPUT: usize = 5_000;

#[wasm_bindgen(typescript_custom_section)]
const TS_SPLITTING: &'static str = r#"
export interface SplitLibraryOptions {
  /** R, the number of components: an integer in [2, 16]. */
  components: number;
  /** λ of eq. (13), in [1e-6, 10]. */
  lambda: number;
  /** 'equal' (default): symmetric, equally spaced means (Table I's family); 'free': symmetric free means (lower J). */
  spacing?: 'equal' | 'free';
}

/**
 * An R-component split of N(0, 1): weights (sum 1), ascending symmetric means, the common σ̃,
 * `objective` = J of eq. (13), and `variance` = σ̃² + Σ w m² (Table I: 0.9503).
 * `components: 4, lambda: 0.001, spacing: 'equal'` returns Table I verbatim.
 */
export interface SplitLibraryResult {
  weights: number[];
  means: number[];
  sigma: number;
  objective: number;
  variance: number;
}

export interface SplitForRegionsOptions {
  /** The mixture to split: weights ≥ 0, means of length n, covariances n × n. */
  mixture: FovWeightedGaussian[];
  /** One or more regions (at most 32) of dimension `positionDims`. */
  regions: FovRegion[];
  /** n_s: the first `positionDims` state components are positions (default 2). */
  positionDims?: number;
  /** w_min: lighter components are not split (default 0.01; absolute weight). */
  minWeight?: number;
  /** R (default 3), an integer in [2, 16]. */
  components?: number;
  /** λ of the split library (default 0.001). */
  lambda?: number;
  /** Split library family (default 'equal'). */
  spacing?: 'equal' | 'free';
  /** ζ, the collocation grid's Mahalanobis radius (default 2, as the authors' pyest).
   *  Components whose boundary lies beyond ζ are not split, which floors the partition error
   *  at a few 1e-3 to 1e-2 of mass; 3 lowers that part to about 1e-4, with more components. */
  gridBound?: number;
  /** N_g, grid points per axis (default 15; N_g^positionDims ≤ 20000). */
  gridPoints?: number;
  /** Recursion depth cap (default 16, at most 64); 0 splits nothing: the result is the mean-based partition of `mixture` itself. */
  maxDepth?: number;
  /** Component count cap (default 10000, at most 50000). */
  maxComponents?: number;
}

/**
 * `mixture`: the split mixture (same shape as the input; each input component replaced in
 * place by its descendants). `inside` / `outside`: the mean-based partition (11)–(12) of it
 * for the first region (sums of weights); `insideMask[i]`: whether component i of `mixture` is
 * in p_S, i.e. its mean (position part) lies in the first region (`inside` is the sum of the
 * weights it selects). `exactInside`: ⟨1_S, p⟩ of the first region under
 * the input mixture (null when too costly: more than ~0.5 s of masses, or positionDims > 4).
 * `depth`: recursion levels used; `splits`: split operations; `stop`: null, or the cap that
 * stopped the recursion.
 */
export interface SplitForRegionsResult {
  mixture: FovWeightedGaussian[];
  inside: number;
  outside: number;
  insideMask: boolean[];
  exactInside: number | null;
  depth: number;
  splits: number;
  stop: null | 'maxDepth' | 'maxComponents';
}

export interface ReduceMixtureOptions {
  mixture: FovWeightedGaussian[];
  /** Drop components lighter than this, renormalising the rest (default 0: keep all). */
  pruneBelow?: number;
  /** Vo & Ma merge within this Mahalanobis distance (U = distance²); omitted: no merging. */
  mergeDistance?: number;
  /** Runnalls' reduction to at most this many components; omitted: no cap. */
  maxComponents?: number;
}

/** One predict → split → non-detection update cycle of the Fig. 5 scenario. */
export interface NegativeInformationStep {
  step: number;
  /** p_{k|k−1}. */
  predicted: FovWeightedGaussian[];
  /** Algorithm 1 applied to it (R = 3, λ = 0.001, w_min = 0.01). */
  split: FovWeightedGaussian[];
  /** p_{k|k}: the mean-based partition's outside part, normalised. */
  posterior: FovWeightedGaussian[];
  /** 1 − Δ_k, the predicted probability of the non-detection. */
  nonDetectionProb: number;
  /** ⟨1_S, p_{k|k−1}⟩ and ⟨1_S, p_{k|k}⟩, exact. */
  predictedInside: number;
  posteriorInside: number;
  depth: number;
  splits: number;
}

/** The Fig. 5 scenario: FoV, initial mixture (state x, y, ẋ, ẏ) and the three steps. */
export interface NegativeInformationScenario {
  fov: FovRegion;
  initial: FovWeightedGaussian[];
  steps: NegativeInformationStep[];
}
"#;

/// A mixture as `[{ weight, mean, cov }]` with `cov` nested row arrays.
fn mixture_to_js(m: &GaussianMixture) -> JsValue {
    m.components()
        .iter()
        .map(|(w, g)| -> JsValue {
            let n = g.dim();
            let cov: Array = (0..n)
                .map(|i| -> JsValue {
                    let row: Vec<f64> = (0..n).map(|j| g.cov()[(i, j)]).collect();
                    number_array(&row)
                })
                .collect();
            object(&[
                ("weight", (*w).into()),
                ("mean", number_array(g.mean().as_slice())),
                ("cov", cov.into()),
            ])
        })
        .collect::<Array>()
        .into()
}

fn spacing(opts: &Options) -> JsResult<Spacing> {
    match opts.get("spacing")? {
        None => Ok(Spacing::Equal),
        Some(v) => match string(&v, "spacing")?.as_str() {
            "equal" => Ok(Spacing::Equal),
            "free" => Ok(Spacing::Free),
            other => Err(range_error(format!(
                "spacing must be 'equal' or 'free', got {other:?}"
            ))),
        },
    }
}

/// The optimal R-component split of N(0, 1) of eqs. (13)–(14): options
/// `{ components, lambda, spacing = 'equal' }`; returns `{ weights, means, sigma, objective,
/// variance }`. `components: 4, lambda: 0.001` with equal spacing is Table I verbatim.
#[wasm_bindgen(js_name = splitLibrary, unchecked_return_type = "SplitLibraryResult")]
pub fn split_library_js(
    #[wasm_bindgen(unchecked_param_type = "SplitLibraryOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    opts.require("components")?;
    let r = opts.integer_or("components", 3, 2, 16)?;
    let lambda = opts.number("lambda")?;
    let lib = library(r, lambda, spacing(&opts)?)?;
    Ok(library_to_js(&lib))
}

/// A split library's key: (R, λ as bits, spacing).
type LibraryKey = (usize, u64, Spacing);

thread_local! {
    /// The last library computed (the demo page calls with the same R and λ repeatedly;
    /// an optimisation costs a few ms in wasm).
    static LAST_LIBRARY: std::cell::RefCell<Option<(LibraryKey, SplitLibrary)>> =
        const { std::cell::RefCell::new(None) };
}

/// [`SplitLibrary::for_components`], memoised on the last (R, λ, spacing).
fn library(r: usize, lambda: f64, spacing: Spacing) -> JsResult<SplitLibrary> {
    let key = (r, lambda.to_bits(), spacing);
    if let Some(lib) = LAST_LIBRARY.with(|c| {
        c.borrow()
            .as_ref()
            .filter(|(k, _)| *k == key)
            .map(|(_, l)| l.clone())
    }) {
        return Ok(lib);
    }
    let lib = SplitLibrary::for_components(r, lambda, spacing).or_throw()?;
    LAST_LIBRARY.with(|c| *c.borrow_mut() = Some((key, lib.clone())));
    Ok(lib)
}

fn library_to_js(lib: &SplitLibrary) -> JsValue {
    object(&[
        ("weights", number_array(lib.weights())),
        ("means", number_array(lib.means())),
        ("sigma", lib.sigma().into()),
        ("objective", lib.objective().into()),
        ("variance", lib.variance().into()),
    ])
}

/// `regions`: a non-empty array of fov-shaped regions; with each region's mass-cost estimate.
fn regions_from_js(v: &JsValue) -> JsResult<Vec<(Region, f64)>> {
    let arr = array(v, "regions", "an array of regions")?;
    let len = arr.length() as usize;
    if len == 0 || len > MAX_REGIONS {
        return Err(range_error(format!(
            "regions must have 1 to {MAX_REGIONS} entries, got {len}"
        )));
    }
    arr.iter()
        .enumerate()
        .map(|(i, r)| region_from_js(&r, &format!("regions[{i}]")))
        .collect()
}

fn stop_to_js(stop: Option<SplitStop>) -> JsValue {
    match stop {
        None => JsValue::NULL,
        Some(SplitStop::MaxDepth) => "maxDepth".into(),
        Some(SplitStop::MaxComponents) => "maxComponents".into(),
    }
}

/// Algorithm 2 (Algorithm 1 for one region) of the "Split happens!" paper: recursively
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
    let opts = Options::new(&options, "options", true)?;
    let mixture = mixture_from_js(&opts.require("mixture")?, "mixture")?;
    let regions = regions_from_js(&opts.require("regions")?)?;
    let position_dims = opts.integer_or("positionDims", 2, 1, 8)?;
    let min_weight = opts.number_or("minWeight", 0.01)?;
    let r = opts.integer_or("components", 3, 2, 16)?;
    let lambda = opts.number_or("lambda", 0.001)?;
    let spacing = spacing(&opts)?;
    let grid_bound = opts.number_or("gridBound", 2.0)?;
    let grid_points = opts.integer_or("gridPoints", 15, 2, MAX_GRID)?;
    let max_depth = opts.integer_or("maxDepth", 16, 0, 64)?;
    let max_components = opts.integer_or("maxComponents", 10_000, 1, MAX_SPLIT_COMPONENTS)?;
    let grid_size = (0..position_dims)
        .try_fold(1usize, |acc, _| acc.checked_mul(grid_points))
        .filter(|&g| g <= MAX_GRID)
        .ok_or_else(|| {
            range_error(format!(
                "gridPoints^positionDims must be at most {MAX_GRID}, got \
                 {grid_points}^{position_dims}"
            ))
        })?;
    // Inclusion tests cost about 1 (box), 2 (disc), 2 + vertices/15 (polygon) units; the
    // region converter's mass-cost estimate (1, 150, 150 + 10·vertices µs) maps onto it.
    let region_work: f64 = regions.iter().map(|(_, c)| 1.0 + c / 150.0).sum();
    let work = max_components as f64 * grid_size as f64 * region_work;
    if work > SPLIT_WORK_BUDGET {
        return Err(range_error(format!(
            "maxComponents × gridPoints^positionDims × regions is {work:.2e} inclusion tests in \
             the worst case, at most {SPLIT_WORK_BUDGET:e} are allowed; lower maxComponents, \
             gridPoints or the number of regions"
        )));
    }
    let library = library(r, lambda, spacing)?;
    let split_opts = SplitOptions {
        position_dims,
        min_weight,
        grid_bound,
        grid_points,
        max_depth,
        max_components,
    };
    let only: Vec<Region> = regions.iter().map(|(reg, _)| reg.clone()).collect();
    let out = split_for_regions(&mixture, &only, &library, &split_opts).or_throw()?;
    let Some((first, cost)) = regions.first() else {
        return Err(range_error("regions must not be empty"));
    };
    let part = partition(&out.mixture, first).or_throw()?;
    // The same inclusion test as the partition (11)–(12), per component.
    let inside_mask: Vec<bool> = out
        .mixture
        .components()
        .iter()
        .map(|(_, g)| first.contains(g.mean().as_slice()))
        .collect();
    let affordable = mixture.len() as f64 * cost <= EXACT_MASS_BUDGET_US;
    let exact_inside = if affordable && first.dim() <= fisst::regions::MAX_MASS_DIM {
        let mut total = 0.0;
        for (i, (w, g)) in mixture.components().iter().enumerate() {
            total += w * first
                .gaussian_mass(g, &format!("mixture[{i}]"))
                .or_throw()?
                .value;
        }
        JsValue::from_f64(total)
    } else {
        JsValue::NULL
    };
    Ok(object(&[
        ("mixture", mixture_to_js(&out.mixture)),
        ("inside", part.inside_weight.into()),
        ("outside", part.outside_weight.into()),
        ("insideMask", boolean_array(&inside_mask)),
        ("exactInside", exact_inside),
        ("depth", (out.depth as f64).into()),
        ("splits", (out.splits as f64).into()),
        ("stop", stop_to_js(out.stop)),
    ]))
}

/// Mixture reduction: prune (renormalising), Vo & Ma's Mahalanobis merge, then Runnalls'
/// KL-based reduction, each pass only when asked. Options `{ mixture, pruneBelow = 0,
/// mergeDistance, maxComponents }`; returns the reduced mixture (same shape). The total
/// weight is preserved; merges preserve the mixture's mean and covariance.
#[wasm_bindgen(js_name = reduceMixture, unchecked_return_type = "FovWeightedGaussian[]")]
pub fn reduce_mixture_js(
    #[wasm_bindgen(unchecked_param_type = "ReduceMixtureOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    let mixture = mixture_from_js(&opts.require("mixture")?, "mixture")?;
    let prune_below = opts.number_or("pruneBelow", 0.0)?;
    let merge_distance = match opts.get("mergeDistance")? {
        Some(_) => Some(opts.number("mergeDistance")?),
        None => None,
    };
    let max_components = match opts.get("maxComponents")? {
        Some(_) => Some(opts.integer_or("maxComponents", 1, 1, 1_000_000)?),
        None => None,
    };
    let mut out = prune(&mixture, prune_below).or_throw()?;
    if let Some(d) = merge_distance {
        out = merge_close(&out, d).or_throw()?;
    }
    if let Some(max) = max_components {
        if out.len() > max && out.len() > MAX_RUNNALLS_INPUT {
            return Err(range_error(format!(
                "maxComponents: Runnalls' reduction takes at most {MAX_RUNNALLS_INPUT} \
                 components, {} remain after pruning and merging; raise pruneBelow or \
                 mergeDistance",
                out.len()
            )));
        }
        out = runnalls(&out, max).or_throw()?;
    }
    Ok(mixture_to_js(&out))
}

fn step_to_js(s: &NegativeInformationStep) -> JsValue {
    object(&[
        ("step", (s.step as f64).into()),
        ("predicted", mixture_to_js(&s.predicted)),
        ("split", mixture_to_js(&s.split.mixture)),
        ("posterior", mixture_to_js(&s.posterior)),
        ("nonDetectionProb", s.non_detection_prob.into()),
        ("predictedInside", s.predicted_inside.into()),
        ("posteriorInside", s.posterior_inside.into()),
        ("depth", (s.split.depth as f64).into()),
        ("splits", (s.split.splits as f64).into()),
    ])
}

/// The negative-information example of Fig. 5 (Section IV-G): a constant-velocity object
/// crossing a square FoV with three non-detections (p_D = 1), split by Algorithm 1 with
/// w_min = 0.01, R = 3, λ = 0.001 (the scenario's numbers are in the Rust docs of
/// `NegativeInformationScenario::fig5`). Options `{ step }` (optional, 1–3): without it returns
/// `{ fov, initial, steps }`, with it the one step.
#[wasm_bindgen(
    js_name = negativeInformationScenario,
    unchecked_return_type = "NegativeInformationScenario | NegativeInformationStep"
)]
pub fn negative_information_scenario_js(
    #[wasm_bindgen(unchecked_optional_param_type = "{ step?: number }")] options: Option<JsValue>,
) -> JsResult<JsValue> {
    let opts = Options::new(&options.unwrap_or(JsValue::UNDEFINED), "options", false)?;
    let step = match opts.get("step")? {
        Some(_) => Some(opts.integer_or("step", 1, 1, 3)?),
        None => None,
    };
    let sc = NegativeInformationScenario::fig5().or_throw()?;
    let steps = sc.run().or_throw()?;
    if let Some(k) = step {
        return steps
            .get(k - 1)
            .map(step_to_js)
            .ok_or_else(|| range_error(format!("step must be in [1, {}]", steps.len())));
    }
    let fov = object(&[(
        "box",
        object(&[
            (
                "min",
                number_array(&NegativeInformationScenario::FIG5_FOV[0]),
            ),
            (
                "max",
                number_array(&NegativeInformationScenario::FIG5_FOV[1]),
            ),
        ]),
    )]);
    Ok(object(&[
        ("fov", fov),
        ("initial", mixture_to_js(&sc.initial)),
        (
            "steps",
            steps.iter().map(step_to_js).collect::<Array>().into(),
        ),
    ]))
}
