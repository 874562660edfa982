//! Recursive Gaussian splitting along region boundaries and mixture reduction (Section IV of
//! LeGrand & Ferrari, "Split Happens! Imprecise and negative information in Gaussian mixture
//! random finite set filtering", paper 001).

use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, read, write};
use crate::names::Renamed;
use fisst::splitting::{
    NegativeInformationOptions, NegativeInformationReport, ReduceMixtureOptions, Spacing,
    SplitForRegionsOptions as CoreSplitForRegionsOptions, SplitLibrary, SplitLibraryOptions,
    SplitLibraryReport, check_reduce_input, split_for_regions_report,
};

// The results are the core's own types written under the contract's names (`ts_aliases.rs`),
// their TypeScript generated from the core's source by build.rs.

// `splitForRegions` reads the core's own `SplitForRegionsOptions` (its TypeScript is generated
// by build.rs from the core's source; its mixture is a `GaussianMixture`, declared in
// `types.rs`).

/// A split library's key: (R, λ as bits, spacing).
type LibraryKey = (usize, u64, Spacing);

thread_local! {
    /// The last library computed (the demo page calls with the same R and λ repeatedly;
    /// an optimisation costs a few ms in wasm).
    static LAST_LIBRARY: std::cell::RefCell<Option<(LibraryKey, SplitLibrary)>> =
        const { std::cell::RefCell::new(None) };
}

/// [`SplitLibraryOptions::library`], memoised on the last (R, λ, spacing); errors name the
/// fields under `options`.
fn library(o: &SplitLibraryOptions) -> JsResult<SplitLibrary> {
    let key = (o.components, o.lambda_.to_bits(), o.spacing);
    if let Some(lib) = LAST_LIBRARY.with(|c| {
        c.borrow()
            .as_ref()
            .filter(|(k, _)| *k == key)
            .map(|(_, l)| l.clone())
    }) {
        return Ok(lib);
    }
    let lib = o.library().or_throw_rendered("options")?;
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
    let lib = library(&o)?;
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
    let library = library(&request.library_options())?;
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

thread_local! {
    /// The Fig. 5 scenario: deterministic, so computed once (about 8 ms in wasm) and shared by
    /// every later call.
    static FIG5: std::cell::OnceCell<NegativeInformationReport> =
        const { std::cell::OnceCell::new() };
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
    let report = match FIG5.with(|c| c.get().cloned()) {
        Some(r) => r,
        None => {
            let r = NegativeInformationReport::fig5().or_throw()?;
            FIG5.with(|c| c.get_or_init(|| r).clone())
        }
    };
    write(&Renamed::new(
        &o.select(&report).or_throw_rendered("options")?,
    ))
}
