//! Bernoulli filters (LeGrand & Ferrari, "Split Happens!", paper 001, Section V): `gmBernoulliPredict`, `gmBernoulliUpdate`, the
//! classes `GmBernoulliFilter` and `ParticleBernoulliFilter`, and `airportScenario`.

use std::format;
use std::vec::Vec;

use serde::Deserialize;
use tsify::Tsify;
use wasm_bindgen::prelude::*;

use crate::boundary::{
    JsResult, OrThrow, core_error, core_error_rendered, read, render_path, seed_or_entropy, write,
};
use fisst::filters::{
    self as core_filters, BernoulliFilterConfig, EstimateOptions, GmBernoulliPredictOptions,
    GmBernoulliUpdateOptions, ParticleOptions,
};
use fisst::regions::Region;
use fisst::sim::airport::{AirportScenarioOptions, AirportScenarioReport};

// `clutter` is the core's `Clutter` (its density reads as a number or an array, the core's
// `ScalarOr`), and `reduction` the core's `ReductionOptions` (omitted: the filters' default
// reduction); their TypeScript is generated, their names kept (`ts_aliases.rs`).

/// The GM Bernoulli prediction, eqs. (40)–(49) of LeGrand & Ferrari, "Split Happens! Imprecise and
/// negative information in Gaussian mixture random finite set filtering" (paper 001). Options `{
/// existence, mixture, transition: { F, Q }, survival, birth: { probability, mixture } }`; returns
/// `{ existence, mixture }`.
#[wasm_bindgen(js_name = gmBernoulliPredict, unchecked_return_type = "GmBernoulliResult")]
pub fn gm_bernoulli_predict(
    #[wasm_bindgen(unchecked_param_type = "GmBernoulliPredictOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: GmBernoulliPredictOptions = read(options, "options")?;
    let (state, config) = o.build().or_throw_rendered("options")?;
    let out = core_filters::gm_bernoulli_predict(&state, &config).or_throw_rendered("options")?;
    write(&out)
}

/// The GM Bernoulli update (Algorithm 3 of LeGrand & Ferrari, "Split Happens! Imprecise and
/// negative information in Gaussian mixture random finite set filtering" (paper 001): split about
/// ∂S, every ∂ζ and every exclusion, zeroth-order weights (57)–(58), existence (54), two-pass
/// reduction), or with `measurements` and `likelihood` the vector-measurement update. Returns `{
/// existence, mixture, delta, splitComponents }`.
#[wasm_bindgen(js_name = gmBernoulliUpdate, unchecked_return_type = "GmBernoulliUpdateResult")]
pub fn gm_bernoulli_update(
    #[wasm_bindgen(unchecked_param_type = "GmBernoulliUpdateOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: GmBernoulliUpdateOptions = read(options, "options")?;
    let out = o.run().or_throw_rendered("options")?;
    write(&out)
}

/// The argument of `update`: `Region[]` or `{ measurements }`.
enum Scan {
    Reports(Vec<Region>),
    Measurements(Vec<Vec<f64>>),
}

#[derive(Deserialize)]
struct MeasurementsArg {
    measurements: Vec<Vec<f64>>,
}

fn scan(value: JsValue) -> JsResult<Scan> {
    if js_sys::Array::is_array(&value) {
        Ok(Scan::Reports(read(value, "reports")?))
    } else {
        let m: MeasurementsArg = read(value, "reports")?;
        Ok(Scan::Measurements(m.measurements))
    }
}

/// The error of a class's `update`: a field of the scan (`reports[i]`, `reports`,
/// `measurements[i]`) under the argument `reports`, any other (the clutter, the exclusions, the
/// likelihood, the filter's mixture, and the field a scan's disagrees with, `positionDims` or
/// `likelihood.H`) under `config`, where it was set.
fn scan_error(e: fisst::Error) -> JsValue {
    let field = e.field();
    let root = if field.starts_with("reports") {
        ""
    } else if field.starts_with("measurements") {
        "reports"
    } else {
        return core_error_rendered(e, "config");
    };
    // the scan's field under its argument, the one it disagrees with (`position_dims`,
    // `likelihood.h`) in the config
    let e = e
        .map_other(|o| format!("config.{o}"))
        .map_field(|f| match root {
            "" => f.into(),
            _ => format!("{root}.{f}"),
        });
    core_error(e.map_paths(render_path))
}

/// Options of `estimate`: the loss (7) of the optimal Bernoulli estimate (Narykov, Üney & Ralph,
/// "Optimal Bernoulli point estimation with applications" (paper 000)), `radius` and `costs`
/// together (`FilterEstimateLoss`); omitted (or neither): no `report`.
#[derive(Deserialize, Tsify, Default)]
#[tsify(type = "FilterEstimateLoss | { radius?: undefined; costs?: undefined }")]
pub struct FilterEstimateOptions(core_filters::EstimateLossOptions);

// `radius` and `costs` go together (`FilterEstimateOptions`), and with them `report` is never
// null: overloads of both filters' `estimate` (interfaces merged into the classes;
// scripts/pkg-guards.mjs places them after the classes, so they are tried first).
#[wasm_bindgen(typescript_custom_section)]
const ESTIMATE_OVERLOADS: &str = r#"
/**
 * The loss (7) of Narykov, Üney & Ralph, "Optimal Bernoulli point estimation with
 * applications" (paper 000), for `estimate`'s `report`: r0 and the costs, always given
 * together.
 */
export interface FilterEstimateLoss {
    /**
     * r0 > 0, the radius of the loss's tolerance ball (a position distance).
     */
    radius: number;
    /**
     * The costs of the loss (7).
     */
    costs: BernoulliCosts;
}
export interface GmBernoulliFilter {
    /**
     * With the loss (7): `report`, the optimal Bernoulli point estimate, is never null.
     */
    estimate(options: FilterEstimateLoss): FilterEstimateResult & { report: BernoulliEstimateResult };
    /**
     * Without a loss: `{ existence, mean, cov }` and `report: null`.
     */
    estimate(options?: { radius?: undefined; costs?: undefined }): FilterEstimateResult & { report: null };
}
export interface ParticleBernoulliFilter {
    /**
     * With the loss (7): `report`, the optimal Bernoulli point estimate, is never null.
     */
    estimate(options: FilterEstimateLoss): FilterEstimateResult & { report: BernoulliEstimateResult };
    /**
     * Without a loss: `{ existence, mean, cov }` and `report: null`.
     */
    estimate(options?: { radius?: undefined; costs?: undefined }): FilterEstimateResult & { report: null };
}
"#;

fn estimate_options(options: JsValue) -> JsResult<EstimateOptions> {
    let o: Option<FilterEstimateOptions> = read(options, "options")?;
    o.unwrap_or_default()
        .0
        .options()
        .or_throw_rendered("options")
}

/// The methods both filter classes share, each on the class's core filter `inner`: `update`
/// (the core filter is unchanged when it fails), `estimate` and the `existence` getter.
macro_rules! filter_methods {
    ($class:ident, $js:literal) => {
        #[wasm_bindgen(js_class = $js)]
        impl $class {
            /// The update with `Region[]` (imprecise reports; `[]`: the non-detection update)
            /// or `{ measurements }`. Returns `{ delta, splitComponents }`. Work caps, a
            /// RangeError naming `reports` beyond: GM vector update, components × measurements
            /// × ⌈n²/16⌉ ≤ 2^18; particle filter, particles × reports × (1 + MCMC moves) ≤
            /// 2·10^7.
            #[wasm_bindgen(unchecked_return_type = "{ delta: number; splitComponents: number }")]
            pub fn update(
                &mut self,
                #[wasm_bindgen(unchecked_param_type = "Region[] | { measurements: Point[] }")]
                reports: JsValue,
            ) -> JsResult<JsValue> {
                let info = match scan(reports)? {
                    Scan::Reports(r) => self.inner.update(&r),
                    Scan::Measurements(z) => self.inner.update_measurements(&z),
                };
                write(&info.map_err(scan_error)?)
            }

            /// `{ existence, mean, cov, report }`; options `{ radius, costs }` for `report`.
            #[wasm_bindgen(unchecked_return_type = "FilterEstimateResult")]
            pub fn estimate(
                &self,
                #[wasm_bindgen(unchecked_optional_param_type = "FilterEstimateOptions")]
                options: JsValue,
            ) -> JsResult<JsValue> {
                let o = estimate_options(options)?;
                let e = self.inner.estimate(&o).map_err(estimate_error)?;
                write(&core_filters::FilterEstimateReport::from(e))
            }

            /// The current existence probability r ∈ [0, 1].
            #[wasm_bindgen(getter)]
            pub fn existence(&self) -> f64 {
                self.inner.existence()
            }
        }
    };
}

/// The error of a class's `estimate`: under `config` when it names the transition (the
/// particle filter's particles overflowed in a prediction, a fault of the config's model),
/// else under the argument `options`.
fn estimate_error(e: fisst::Error) -> JsValue {
    let root = if e.field() == "transition" {
        "config"
    } else {
        "options"
    };
    core_error_rendered(e, root)
}

/// The GM Bernoulli filter (Algorithm 3 of LeGrand & Ferrari, "Split Happens! Imprecise and
/// negative information in Gaussian mixture random finite set filtering" (paper 001)). Call
/// `free()` when done.
#[wasm_bindgen(js_name = GmBernoulliFilter)]
pub struct GmBernoulliFilterJs {
    inner: core_filters::GmBernoulliFilter,
}

filter_methods!(GmBernoulliFilterJs, "GmBernoulliFilter");

#[wasm_bindgen(js_class = GmBernoulliFilter)]
impl GmBernoulliFilterJs {
    /// A filter with the initial Bernoulli of `config`; validates `config`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "BernoulliFilterConfig")] config: JsValue,
    ) -> JsResult<GmBernoulliFilterJs> {
        let c: BernoulliFilterConfig = read(config, "config")?;
        let (config, _) = c.build().or_throw_rendered("config")?;
        Ok(Self {
            inner: core_filters::GmBernoulliFilter::new(config).or_throw_rendered("config")?,
        })
    }

    /// One prediction (40)–(49); on failure the filter is unchanged.
    pub fn predict(&mut self) -> JsResult<()> {
        self.inner.predict().or_throw_rendered("config")
    }

    /// The current spatial density p(x), a Gaussian mixture (a copy).
    #[wasm_bindgen(getter, unchecked_return_type = "MixtureComponent[]")]
    pub fn mixture(&self) -> JsResult<JsValue> {
        write(self.inner.mixture())
    }
}

/// The Bernoulli particle filter (Ristic, Vo, Vo & Farina, "A tutorial on Bernoulli filters:
/// theory, implementation and applications", reference 23 of LeGrand & Ferrari, "Split Happens!
/// Imprecise and negative information in Gaussian mixture random finite set filtering" (paper
/// 001)), with the models of a `BernoulliFilterConfig`. Call `free()` when done.
#[wasm_bindgen(js_name = ParticleBernoulliFilter)]
pub struct ParticleBernoulliFilterJs {
    inner: core_filters::ParticleBernoulliFilter,
    seed: u64,
}

filter_methods!(ParticleBernoulliFilterJs, "ParticleBernoulliFilter");

#[wasm_bindgen(js_class = ParticleBernoulliFilter)]
impl ParticleBernoulliFilterJs {
    /// A filter with N particles drawn from the initial Bernoulli of `config`; validates `config`
    /// (with `particles`, `mcmcMoves`, `seed`).
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "BernoulliFilterConfig")] config: JsValue,
    ) -> JsResult<ParticleBernoulliFilterJs> {
        let c: BernoulliFilterConfig = read(config, "config")?;
        let asked = c.seed;
        let (config, particle) = c.build().or_throw_rendered("config")?;
        let seed = seed_or_entropy(asked)?;
        let options = ParticleOptions { seed, ..particle };
        Ok(Self {
            inner: core_filters::ParticleBernoulliFilter::new(config, options)
                .or_throw_rendered("config")?,
            seed,
        })
    }

    /// One prediction step (survival, birth and the motion model of `config`).
    pub fn predict(&mut self) {
        self.inner.predict();
    }

    /// The particles, one state per row (a copy; equal weights after an update).
    #[wasm_bindgen(getter, unchecked_return_type = "number[][]")]
    pub fn particles(&self) -> JsResult<JsValue> {
        let d = self.inner.dim();
        let rows: Vec<&[f64]> = self.inner.particles().chunks_exact(d).collect();
        write(&rows)
    }

    /// The normalised particle weights, one per particle (equal after an update).
    #[wasm_bindgen(getter)]
    pub fn weights(&self) -> Vec<f64> {
        self.inner.weights().to_vec()
    }

    /// The seed of the filter's random numbers (the config's, or the fresh one drawn).
    #[wasm_bindgen(getter)]
    pub fn seed(&self) -> f64 {
        self.seed as f64
    }
}

/// The airport example of LeGrand & Ferrari, "Split Happens! Imprecise and negative information in
/// Gaussian mixture random finite set filtering" (paper 001), Section V-C (Figs. 6–8): a seeded
/// walk through a concourse with ten anchors and four exclusion rectangles, and the reports.
/// Options `{ seed, steps = 60 }`; report `a` at step k is `{ disc: { center: anchors[a].position,
/// radius: anchors[a].radius } }`.
#[wasm_bindgen(js_name = airportScenario, unchecked_return_type = "AirportScenarioResult")]
pub fn airport_scenario(
    #[wasm_bindgen(unchecked_optional_param_type = "AirportScenarioOptions")] options: Option<
        JsValue,
    >,
) -> JsResult<JsValue> {
    let o: AirportScenarioOptions = match options {
        None => AirportScenarioOptions::default(),
        Some(options) => read(options, "options")?,
    };
    let seed = seed_or_entropy(o.seed)?;
    let report = AirportScenarioReport::new(seed, o.steps).or_throw_rendered("options")?;
    write(&report)
}
