//! Recursive Gaussian splitting along region boundaries and mixture reduction (Section IV of
//! LeGrand & Ferrari, "Split Happens! Imprecise and negative information in Gaussian mixture
//! random finite set filtering", paper 001).

use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, read, write};
use crate::names::Renamed;
use fisst::splitting::{
    NegativeInformationOptions, NegativeInformationReport, ReduceMixtureOptions,
    SplitForRegionsOptions as CoreSplitForRegionsOptions, SplitLibraryOptions, SplitLibraryReport,
    check_reduce_input, split_for_regions_report,
};

// The results are the core's own types written under the contract's names: `splitLibrary`'s
// is generated from the core's source (its name in `ts_aliases.rs`); the others are declared
// here because they hold the contract's shapes the generator does not write (`null` for an
// absent value, mixtures as `MixtureComponent[]`).
#[wasm_bindgen(typescript_custom_section)]
const RESULTS: &str = r#"
/**
 * Result of `splitForRegions`: the split mixture and its mean-based partition (the core's
 * `SplitForRegionsReport`).
 */
export interface SplitForRegionsResult {
    /** The split mixture (each input component replaced in place by its descendants). */
    mixture: MixtureComponent[];
    /** The mean-based partition (11)–(12) for the first region: the inside weight. */
    inside: number;
    /** The mean-based partition for the first region: the outside weight (of the components whose mean lies outside it). */
    outside: number;
    /** `insideMask[i]`: whether component i of `mixture` is in p_S, i.e. its mean (position part) lies in the first region (`inside` is the sum of the weights it selects). */
    insideMask: boolean[];
    /** The exact mass ⟨1_S, p⟩ of the first region S under the input mixture p (null when too costly: more than ~0.5 s of masses, or positionDims > 4). */
    exactInside: number | null;
    /** The number of recursion levels used. */
    depth: number;
    /** The number of split operations (components replaced by R children). */
    splits: number;
    /** null, or the cap that stopped the recursion. */
    stop: null | 'maxDepth' | 'maxComponents';
}
/**
 * One predict → split → non-detection update cycle of the Fig. 5 scenario of LeGrand & Ferrari,
 * "Split Happens! Imprecise and negative information in Gaussian mixture random finite set
 * filtering" (paper 001) (the core's `NegativeInformationStepReport`).
 */
export interface NegativeInformationStep {
    /** The step number k: 1, 2 or 3. */
    step: number;
    /** The predicted density p_{k|k−1}, a Gaussian mixture. */
    predicted: MixtureComponent[];
    /** Algorithm 1 applied to it (R = 3, λ = 0.001, w_min = 0.01). */
    split: MixtureComponent[];
    /** The posterior density p_{k|k}: the mean-based partition's outside part, normalised. */
    posterior: MixtureComponent[];
    /** The predicted probability 1 − Δ_k of the non-detection. */
    nonDetectionProb: number;
    /** The exact predicted mass in the field of view, ⟨1_S, p_{k|k−1}⟩ ∈ [0, 1]. */
    predictedInside: number;
    /** The exact posterior mass in the field of view, ⟨1_S, p_{k|k}⟩ ∈ [0, 1]. */
    posteriorInside: number;
    /** The number of recursion levels used by the split. */
    depth: number;
    /** The number of split operations (components replaced by R children). */
    splits: number;
}
/**
 * Result of `negativeInformationScenario`: the Fig. 5 scenario of LeGrand & Ferrari, "Split
 * Happens! Imprecise and negative information in Gaussian mixture random finite set filtering"
 * (paper 001): FoV, initial mixture (state x, y, ẋ, ẏ) and the three steps (the core's
 * `NegativeInformationReport`).
 */
export interface NegativeInformationScenario {
    /** The field of view S, a box in (x, y). */
    fov: Region;
    /** The initial density p_{0|0}, a Gaussian mixture over (x, y, ẋ, ẏ). */
    initial: MixtureComponent[];
    /** The three predict → split → update steps, k = 1, 2, 3. */
    steps: NegativeInformationStep[];
}
"#;

// `splitForRegions` reads the core's own `SplitForRegionsOptions` (its TypeScript is generated
// by build.rs from the core's source; its mixture is a `GaussianMixture`, declared in
// `types.rs`).

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
    let lib = o.library_memo().or_throw_rendered("options")?;
    write(&Renamed::new(&SplitLibraryReport::from(&lib)))
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
    let request: CoreSplitForRegionsOptions = read(options, "options")?;
    request.validate().or_throw_rendered("options")?;
    let library = request
        .library_options()
        .library_memo()
        .or_throw_rendered("options")?;
    let report = split_for_regions_report(&request, &library).or_throw_rendered("options")?;
    write(&Renamed::new(&report))
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
    write(&o.reduce().or_throw_rendered("options")?)
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
    let o = o.unwrap_or_default();
    o.validate().or_throw_rendered("options")?;
    let report = NegativeInformationReport::fig5_memo().or_throw()?;
    write(&Renamed::new(
        &o.select(&report).or_throw_rendered("options")?,
    ))
}
