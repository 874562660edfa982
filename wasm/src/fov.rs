//! Field-of-view cardinality pmfs and the sensor-placement map (Sections VI–VII of
//! `001_0f0df91eee9b30d5.txt`).

use js_sys::Float64Array;
use serde::{Deserialize, Serialize};
use tsify::Tsify;
use wasm_bindgen::prelude::*;

use crate::boundary::{JsResult, OrThrow, check_range, range_error, read, write};
use crate::types::{
    self, Bernoulli, Grid, MultiObjectDensity, Region, WeightedGaussian, check_gaussian_count,
};
use fisst::fov::{
    FOV_MASS_BUDGET_US, MAX_CARDINALITY_LEN, MAX_DENSITY_GRID_WORK, MAX_SCENE_COUNT,
    MAX_VARIANCE_MAP_WORK, MultiObjectDensity as CoreDensity, SceneOptions, fov_cardinality,
    fov_mass_work_us, grid_work, mixture_density_grid, placement_scene, variance_map,
};

fn one() -> f64 {
    1.0
}

/// Options of `fovCardinality`.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct FovCardinalityOptions {
    /// The multi-object density (at most 10,000 Gaussians in all; the call is refused when
    /// its masses would take more than about 2 s).
    pub rfs: MultiObjectDensity,
    /// The field of view S, in the position subspace (the first state components).
    pub fov: Region,
    /// p_D in [0, 1] (default 1): with p_D < 1 the pmf is that of object-originated
    /// detections, eq. (75).
    #[serde(default = "one")]
    pub detection_probability: f64,
}

/// Result of `fovCardinality`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct FovCardinalityResult {
    /// `pmf[n]`: probability of n objects (detections) in the FoV, n = 0 … (Poisson and
    /// i.i.d. cluster: up to where the tail is below 1e-15).
    pub pmf: Vec<f64>,
    /// The mean count (closed form).
    pub mean: f64,
    /// The variance of the count (closed form).
    pub variance: f64,
    /// ⟨1_S, p_i⟩ for each Gaussian in input order (each mixture component for Poisson and
    /// i.i.d. cluster; for glmb, hypothesis 0's components, then hypothesis 1's, …), without
    /// p_D.
    pub mass_in_fov: Vec<f64>,
}

/// Options of `fovVarianceMap`.
#[derive(Deserialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct FovVarianceMapOptions {
    /// The multi-Bernoulli (2D or more; the first two state components are positions).
    pub multi_bernoulli: Vec<Bernoulli>,
    /// FoV width and height, > 0 (an axis-aligned box centred on each grid point).
    pub fov_size: (f64, f64),
    /// The FoV centres; components × cells at most 2e8.
    pub grid: Grid,
}

/// Result of `fovVarianceMap`.
#[derive(Serialize, Tsify)]
pub struct FovVarianceMapResult {
    /// `variance[j * nx + i]` is the FoV-count variance with the FoV centred at (x_i, y_j):
    /// row-major, y the outer index.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    pub variance: Float64Array,
    /// The centre `[x, y]` of the largest variance.
    pub argmax: (f64, f64),
    /// The largest variance.
    pub max: f64,
}

fn hundred() -> usize {
    100
}

fn seed_one() -> u64 {
    1
}

fn three() -> f64 {
    3.0
}

fn sigma_default() -> (f64, f64) {
    (0.1, 0.5)
}

/// Options of `placementScene`, every one optional.
#[derive(Deserialize, Tsify)]
pub struct PlacementSceneOptions {
    /// Components, an integer in [0, 10000] (default 100).
    #[serde(default = "hundred")]
    pub count: usize,
    /// The seed, an integer in [0, 2^53 − 1] (default 1: this function documents a fixed
    /// default, so the same call always gives the same scene).
    #[serde(default = "seed_one")]
    pub seed: u64,
    /// Means uniform in [−extent, extent]², extent > 0 (default 3).
    #[serde(default = "three")]
    pub extent: f64,
    /// Principal standard deviations uniform in [min, max], 0 < min ≤ max (default
    /// [0.1, 0.5]). Existence is uniform in [0.35, 1).
    #[serde(default = "sigma_default")]
    pub sigma: (f64, f64),
}

/// One component of a placement scene.
#[derive(Serialize, Tsify)]
pub struct SceneComponent {
    /// Existence probability.
    pub existence: f64,
    /// Mean `[x, y]`.
    pub mean: (f64, f64),
    /// Covariance `[[a, b], [b, c]]`.
    pub cov: ((f64, f64), (f64, f64)),
}

/// A seeded multi-Bernoulli scene; `multiBernoulli` is ready for `fovCardinality` and
/// `fovVarianceMap`.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct PlacementSceneResult {
    /// The components.
    pub multi_bernoulli: Vec<SceneComponent>,
}

/// Options of `mixtureDensityGrid`.
#[derive(Deserialize, Tsify)]
pub struct MixtureDensityGridOptions {
    /// Σ weight · N(mean, cov); components of 3 or more dimensions use their first two
    /// (position) components.
    pub mixture: Vec<WeightedGaussian>,
    /// Positions; components × cells at most 2.5e7.
    pub grid: Grid,
}

/// The pmf of the number of objects inside a field of view (Propositions 1–4 of the "Split
/// happens!" paper): options `{ rfs, fov, detectionProbability = 1 }` (see the
/// `FovCardinalityOptions` type); returns `{ pmf, mean, variance, massInFov }`.
#[cfg(feature = "splitting")]
#[wasm_bindgen(js_name = fovCardinality, unchecked_return_type = "FovCardinalityResult")]
pub fn fov_cardinality_js(
    #[wasm_bindgen(unchecked_param_type = "FovCardinalityOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: FovCardinalityOptions = read(options, "options")?;
    let density = match o.rfs {
        MultiObjectDensity::MultiBernoulli(c) => {
            CoreDensity::MultiBernoulli(types::bernoullis(c, "options.rfs.multiBernoulli")?)
        }
        MultiObjectDensity::Poisson(m) => {
            CoreDensity::Poisson(types::mixture(m, "options.rfs.poisson")?)
        }
        MultiObjectDensity::IidCluster(c) => {
            let cardinality = c.cardinality.0;
            if cardinality.len() > MAX_CARDINALITY_LEN {
                return Err(range_error(format!(
                    "options.rfs.iidCluster.cardinality has {} entries, at most \
                     {MAX_CARDINALITY_LEN} are supported",
                    cardinality.len()
                )));
            }
            CoreDensity::IidCluster {
                cardinality,
                density: types::mixture(c.density, "options.rfs.iidCluster.density")?,
            }
        }
        MultiObjectDensity::Glmb(hyps) => {
            let total: usize = hyps.iter().map(|h| h.components.len()).sum();
            if total > types::MAX_GAUSSIANS {
                return Err(range_error(format!(
                    "options.rfs.glmb has {total} components in all, at most {} are supported",
                    types::MAX_GAUSSIANS
                )));
            }
            let mut out = Vec::with_capacity(hyps.len());
            for (h, hyp) in hyps.into_iter().enumerate() {
                let gs = hyp
                    .components
                    .into_iter()
                    .enumerate()
                    .map(|(i, g)| g.into_core(&format!("options.rfs.glmb[{h}].components[{i}]")))
                    .collect::<JsResult<Vec<_>>>()?;
                out.push((hyp.weight, gs));
            }
            CoreDensity::Glmb(out)
        }
    };
    let (fov, _) = o.fov.into_core("options.fov")?;
    let work = fov_mass_work_us(&density, &fov);
    if work > FOV_MASS_BUDGET_US {
        return Err(range_error(format!(
            "options.fov: {} Gaussian masses in this region would take about {:.0} s; use \
             fewer components, fewer polygon vertices or fewer FoV dimensions",
            density.gaussian_count(),
            work * 1e-6
        )));
    }
    let res = fov_cardinality(&density, &fov, o.detection_probability).or_throw_in("options")?;
    write(&FovCardinalityResult {
        pmf: res.cardinality.pmf,
        mean: res.cardinality.mean,
        variance: res.cardinality.variance,
        mass_in_fov: res.mass_in_fov,
    })
}

/// The FoV-count variance of a multi-Bernoulli over a grid of FoV centres, and its maximiser
/// (Section VII of the "Split happens!" paper): options
/// `{ multiBernoulli, fovSize: [width, height], grid: { x: [min, max, count], y: [min, max,
/// count] } }`; returns `{ variance: Float64Array (row-major, y outer), argmax: [x, y], max }`.
#[cfg(feature = "splitting")]
#[wasm_bindgen(js_name = fovVarianceMap, unchecked_return_type = "FovVarianceMapResult")]
pub fn fov_variance_map(
    #[wasm_bindgen(unchecked_param_type = "FovVarianceMapOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let o: FovVarianceMapOptions = read(options, "options")?;
    let comps = types::bernoullis(o.multi_bernoulli, "options.multiBernoulli")?;
    let (x, y) = o.grid.into_core("options.grid")?;
    if grid_work(comps.len(), x, y) > MAX_VARIANCE_MAP_WORK {
        return Err(range_error(format!(
            "options.multiBernoulli.length × grid cells is {}, at most {MAX_VARIANCE_MAP_WORK:e} is \
             supported",
            comps.len() * x.count * y.count
        )));
    }
    let map = variance_map(&comps, [o.fov_size.0, o.fov_size.1], x, y).or_throw_in("options")?;
    write(&FovVarianceMapResult {
        variance: Float64Array::from(map.variance.as_slice()),
        argmax: (map.argmax[0], map.argmax[1]),
        max: map.max,
    })
}

/// A seeded random multi-Bernoulli scene like the sensor-placement example of the "Split
/// happens!" paper (Section VII, Figs 9–10): options `{ count = 100, seed = 1, extent = 3,
/// sigma = [0.1, 0.5] }` (see `PlacementSceneOptions`); returns `{ multiBernoulli: [{
/// existence, mean: [x, y], cov: [[a, b], [b, c]] }, …] }`. The same seed gives the same
/// scene on every platform, and a smaller `count` is a prefix of a larger one.
#[cfg(feature = "splitting")]
#[wasm_bindgen(js_name = placementScene, unchecked_return_type = "PlacementSceneResult")]
pub fn placement_scene_js(
    #[wasm_bindgen(unchecked_optional_param_type = "PlacementSceneOptions")] options: Option<
        JsValue,
    >,
) -> JsResult<JsValue> {
    let o: Option<PlacementSceneOptions> = read(options.unwrap_or(JsValue::UNDEFINED), "options")?;
    let o = o.unwrap_or(PlacementSceneOptions {
        count: hundred(),
        seed: seed_one(),
        extent: three(),
        sigma: sigma_default(),
    });
    let count = check_range("options.count", o.count, 0, MAX_SCENE_COUNT)?;
    let scene = placement_scene(&SceneOptions {
        count,
        seed: o.seed,
        extent: o.extent,
        sigma: [o.sigma.0, o.sigma.1],
    })
    .or_throw_in("options")?;
    let multi_bernoulli = scene
        .iter()
        .map(|(r, g)| {
            let (m, p) = (g.mean(), g.cov());
            SceneComponent {
                existence: *r,
                mean: (m[0], m[1]),
                cov: ((p[(0, 0)], p[(0, 1)]), (p[(1, 0)], p[(1, 1)])),
            }
        })
        .collect();
    write(&PlacementSceneResult { multi_bernoulli })
}

/// A Gaussian mixture's density Σ w N(s; m, P) at every position of a grid, e.g. a
/// multi-Bernoulli's PHD Σ r N(s; m, P) as a heat map (Fig. 9 of the "Split happens!" paper):
/// options `{ mixture: [{ weight, mean, cov }, …], grid: { x: [min, max, count], y: [min, max,
/// count] } }`; returns a `Float64Array`, row-major with y as the outer index (entry
/// `j * nx + i`). Components of 3 or more dimensions contribute their position marginal (first
/// two components).
#[wasm_bindgen(js_name = mixtureDensityGrid)]
pub fn mixture_density_grid_js(
    #[wasm_bindgen(unchecked_param_type = "MixtureDensityGridOptions")] options: JsValue,
) -> JsResult<Float64Array> {
    let o: MixtureDensityGridOptions = read(options, "options")?;
    check_gaussian_count(o.mixture.len(), "options.mixture")?;
    let mix = types::mixture(o.mixture, "options.mixture")?;
    let (x, y) = o.grid.into_core("options.grid")?;
    if grid_work(mix.len(), x, y) > MAX_DENSITY_GRID_WORK {
        return Err(range_error(format!(
            "options.mixture.length × grid cells is {}, at most {MAX_DENSITY_GRID_WORK:e} is \
             supported",
            mix.len() * x.count * y.count
        )));
    }
    let d = mixture_density_grid(&mix, x, y).or_throw_in("options")?;
    Ok(Float64Array::from(d.as_slice()))
}
