//! Sensor control with the SMC multi-object filter (paper 004, Ristic & Vo, "Sensor control for
//! multi-object state-space estimation using random finite sets"):
//! `multiObjectLikelihood` (eq. (20)), `SensorControlRun` (Algorithm 1) and `compareSchemes`
//! (Fig. 3). They read and write the core's own types (`fisst::control`), renamed at the
//! boundary; their TypeScript is generated from the core's source (`build.rs`), under the
//! contract's names below. The shapes are also listed in `core/src/control/JS_SHAPES.md`.

use std::string::String;

use fisst::control::MultiObjectLikelihoodOptions;
use fisst::control::{CompareOptions, ControlOptions, ControlParticles, ControlRun};
use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, core_error_rendered, de_error, read};
use crate::boundary::{seed_or_entropy, write};

// The options of `compareSchemes` (with the callback); the contract's names for the core's
// types are aliases (`ts_aliases.rs`).
#[wasm_bindgen(typescript_custom_section)]
const CONTROL_TYPES: &str = r#"
/** Options of `compareSchemes`: the core's `CompareOptions`, and a progress callback. */
export type CompareSchemesOptions = CompareOptions & {
    /** Called as runs finish with (done, total), total = runs · schemes.length. */
    onProgress?: (done: number, total: number) => void;
};
"#;

/// A core error about `options` in JavaScript names (the caps are worded by the core).
fn options_error(e: fisst::Error) -> JsValue {
    core_error_rendered(e, "options")
}

/// The multi-object likelihood (20) of Ristic & Vo, "Sensor control for multi-object state-space
/// estimation using random finite sets" (paper 004) for one particle, in log space, summing over
/// the associations θ by dynamic programming over subsets (exact; no enumeration). Options `{
/// likelihoods, detectionProbability, clutterRate, clutterDensity }`; returns `{ logLikelihood }`.
#[wasm_bindgen(
    js_name = multiObjectLikelihood,
    unchecked_return_type = "MultiObjectLikelihoodResult"
)]
pub fn multi_object_likelihood(
    #[wasm_bindgen(unchecked_param_type = "MultiObjectLikelihoodOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: MultiObjectLikelihoodOptions = read(options, "options")?;
    write(&o.evaluate().map_err(options_error)?)
}

/// One run of Algorithm 1 of Ristic & Vo, "Sensor control for multi-object state-space estimation
/// using random finite sets" (paper 004) on its range-only case study. Call `free()` when done.
#[wasm_bindgen(js_name = SensorControlRun)]
pub struct SensorControlRunJs {
    inner: ControlRun,
    seed: u64,
}

#[wasm_bindgen(js_class = SensorControlRun)]
impl SensorControlRunJs {
    /// A run of the case study with `options` (see `SensorControlRunOptions`); validates them.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "SensorControlRunOptions")] options: JsValue,
    ) -> JsResult<SensorControlRunJs> {
        let o: ControlOptions = read(options, "options")?;
        let seed = seed_or_entropy(o.seed)?;
        o.check_limits().map_err(options_error)?;
        let inner = ControlRun::new(o, seed).map_err(options_error)?;
        Ok(SensorControlRunJs { inner, seed })
    }

    /// One step of Algorithm 1: scan, update (20), resample and regularise, estimate (22),
    /// OSPA, choose the next action. A `RangeError` once `k` reached `steps`.
    #[wasm_bindgen(unchecked_return_type = "ControlStep")]
    pub fn step(&mut self) -> JsResult<JsValue> {
        let s = self.inner.step().map_err(|e| core_error_rendered(e, ""))?;
        write(&s)
    }

    /// The multi-object particles of the filter (a copy; empty before the first step).
    #[wasm_bindgen(getter, unchecked_return_type = "ControlParticles")]
    pub fn particles(&self) -> JsResult<JsValue> {
        write(&ControlParticles::from(self.inner.particles()))
    }

    /// The sensor's path: the start and every location moved to, [x, y] in m (length k + 1).
    #[wasm_bindgen(getter, js_name = sensorPath, unchecked_return_type = "[number, number][]")]
    pub fn sensor_path(&self) -> JsResult<JsValue> {
        write(self.inner.sensor_path())
    }

    /// The true objects' positions [x, y] in m, [[300, 600], [750, 250]].
    #[wasm_bindgen(getter, unchecked_return_type = "[number, number][]")]
    pub fn truth(&self) -> JsResult<JsValue> {
        write(&self.inner.options().truth)
    }

    /// The scans Z_1 … Z_k, ranges in m (measurements[k − 1] was taken at sensorPath[k − 1]).
    #[wasm_bindgen(getter, unchecked_return_type = "number[][]")]
    pub fn measurements(&self) -> JsResult<JsValue> {
        write(self.inner.measurements())
    }

    /// The number k of steps done, 0 … K.
    #[wasm_bindgen(getter)]
    pub fn k(&self) -> usize {
        self.inner.k()
    }

    /// The number K of steps of the run.
    #[wasm_bindgen(getter)]
    pub fn steps(&self) -> usize {
        self.inner.options().steps
    }

    /// The seed of the run's random numbers (a 53-bit integer: the option's, or the fresh one
    /// drawn).
    #[wasm_bindgen(getter)]
    pub fn seed(&self) -> f64 {
        self.seed as f64
    }

    /// The name of the run's control scheme: `'renyi'`, `'fisher'`, `'pent'` or `'random'`.
    #[wasm_bindgen(getter, unchecked_return_type = "Scheme")]
    pub fn scheme(&self) -> String {
        self.inner.options().scheme.name().into()
    }
}

/// Fig. 3 of Ristic & Vo, "Sensor control for multi-object state-space estimation using random
/// finite sets" (paper 004): `runs` seeded runs of each scheme, averaged. Options `{ runs, steps,
/// seed, schemes, onProgress, … }`; returns `{ seed, runs, steps, schemes: [{ scheme, distance,
/// localisation, cardinality }] }`, each part `{ mean, standardError }`.
#[wasm_bindgen(js_name = compareSchemes, unchecked_return_type = "CompareSchemesResult")]
pub fn compare_schemes(
    #[wasm_bindgen(unchecked_param_type = "CompareSchemesOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let (o, progress): (CompareOptions, _) =
        crate::de::from_js_with_callback(options, "options", "onProgress").map_err(de_error)?;
    let seed = seed_or_entropy(o.seed)?;
    let out = o
        .compare::<Failure>(seed, |done, total| match &progress {
            Some(f) => f
                .call2(
                    &JsValue::NULL,
                    &(done as f64).into(),
                    &(total as f64).into(),
                )
                .map(|_| ())
                .map_err(Failure::Js),
            None => Ok(()),
        })
        .map_err(|e| match e {
            Failure::Js(v) => v,
            Failure::Core(e) => options_error(e),
        })?;
    write(&out)
}

/// A failure inside the comparison: a core error or the callback's exception.
enum Failure {
    Core(fisst::Error),
    Js(JsValue),
}

impl From<fisst::Error> for Failure {
    fn from(e: fisst::Error) -> Self {
        Failure::Core(e)
    }
}
