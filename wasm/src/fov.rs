//! Field-of-view cardinality pmfs and the sensor-placement map (Sections VI–VII of
//! `001_0f0df91eee9b30d5.txt`).

use wasm_bindgen::prelude::*;

use crate::convert::{
    JsResult, Options, OrThrow, array, number, number_array, numbers, object, points, range_error,
    type_error,
};
use fisst::fov::{
    GridAxis, MAX_SCENE_COUNT, MultiObjectDensity, SceneOptions, fov_cardinality,
    mixture_density_grid, placement_scene, variance_map,
};
use fisst::gaussian::{Gaussian, GaussianMixture};
use fisst::regions::Region;
use js_sys::{Array, Float64Array};

/// At most this many Gaussians in one call (each costs one region mass).
const MAX_GAUSSIANS: usize = 10_000;
/// At most this many polygon vertices.
const MAX_VERTICES: usize = 1_000;
/// Budget of one `fovCardinality` call in estimated native microseconds (about 2 s): the
/// number of Gaussians times the cost of one mass for the FoV's kind and dimension.
const MASS_BUDGET_US: f64 = 2e6;
/// At most this many entries of an i.i.d.-cluster cardinality pmf (the thinning is O(n²)).
const MAX_CARDINALITY_LEN: usize = 20_001;
/// At most this many (component, FoV centre) pairs in one variance map.
const MAX_MAP_WORK: f64 = 2e8;
/// At most this many (component, grid point) density evaluations in one `mixtureDensityGrid`
/// call (~80 ns each natively: about 2 s).
const MAX_DENSITY_WORK: f64 = 2.5e7;
/// The largest seed of `placementScene` (integers are exact in a JS number up to 2⁵³ − 1).
const MAX_SEED: f64 = 9_007_199_254_740_991.0;

#[wasm_bindgen(typescript_custom_section)]
const TS_FOV: &'static str = r#"
/** A Gaussian: `mean` (length n) and `cov` (n × n, nested arrays). */
export interface FovGaussian { mean: number[] | Float64Array; cov: (number[] | Float64Array)[]; }

/** A multi-Bernoulli component: existence probability and Gaussian density. */
export interface FovBernoulli extends FovGaussian { existence: number; }

/** A weighted Gaussian (a PHD or mixture component). */
export interface FovWeightedGaussian extends FovGaussian { weight: number; }

/**
 * A multi-object density: exactly one key.
 * - `multiBernoulli`: one entry per potential object.
 * - `poisson`: the PHD as a Gaussian mixture; its weights sum to the expected count N_X.
 * - `iidCluster`: cardinality pmf ρ(0), ρ(1), … (sums to 1) and single-object density (weights sum to 1).
 * - `glmb`: one entry per hypothesis: its weight (all sum to 1) and the densities of its labels.
 */
export type FovRfs =
  | { multiBernoulli: FovBernoulli[] }
  | { poisson: FovWeightedGaussian[] }
  | { iidCluster: { cardinality: number[] | Float64Array; density: FovWeightedGaussian[] } }
  | { glmb: { weight: number; components: FovGaussian[] }[] };

/**
 * A field of view in the position subspace (the first state components):
 * a closed box (any dimension), a closed polygon (2D; either orientation; even–odd rule when
 * self-intersecting), or a closed disc (a ball in higher dimensions).
 */
export type FovRegion =
  | { box: { min: number[] | Float64Array; max: number[] | Float64Array } }
  | { polygon: [number, number][] }
  | { disc: { center: number[] | Float64Array; radius: number } };

export interface FovCardinalityOptions {
  rfs: FovRfs;
  fov: FovRegion;
  /** p_D (default 1): with p_D < 1 the pmf is that of object-originated detections, eq. (75). */
  detectionProbability?: number;
}

/**
 * `pmf[n]`: probability of n objects (detections) in the FoV, n = 0 … (Poisson and
 * i.i.d. cluster: up to where the tail is below 1e-15). `mean`, `variance`: closed forms.
 * `massInFov[i]` = ⟨1_S, p_i⟩ for each Gaussian in input order (each mixture component for
 * Poisson and i.i.d. cluster; for glmb, hypothesis 0's components, then hypothesis 1's, …),
 * without p_D.
 */
export interface FovCardinalityResult {
  pmf: number[];
  mean: number;
  variance: number;
  massInFov: number[];
}

export interface FovVarianceMapOptions {
  multiBernoulli: FovBernoulli[];
  /** FoV width and height (an axis-aligned box centred on each grid point). */
  fovSize: [number, number];
  /** Centres: `[min, max, count]` per axis, `count` in [1, 4096] (like linspace). */
  grid: { x: [number, number, number]; y: [number, number, number] };
}

/**
 * `variance[j * nx + i]` is the FoV-count variance with the FoV centred at (x_i, y_j):
 * row-major, y the outer index. `argmax` is the centre `[x, y]` of the largest, `max` its value.
 */
export interface FovVarianceMapResult {
  variance: Float64Array;
  argmax: [number, number];
  max: number;
}

/**
 * Options of `placementScene`, every one optional: `count` components (integer in [0, 10000],
 * default 100), `seed` (integer in [0, 2^53 − 1], default 1), means uniform in
 * [−extent, extent]² (`extent` > 0, default 3), principal standard deviations uniform in
 * `sigma` = [min, max] (0 < min ≤ max, default [0.1, 0.5]); existence uniform in [0.35, 1).
 */
export interface PlacementSceneOptions {
  count?: number;
  seed?: number;
  extent?: number;
  sigma?: [number, number];
}

/** A seeded multi-Bernoulli scene; `multiBernoulli` is ready for `fovCardinality` and `fovVarianceMap`. */
export interface PlacementSceneResult {
  multiBernoulli: { existence: number; mean: [number, number]; cov: [[number, number], [number, number]] }[];
}

export interface MixtureDensityGridOptions {
  /** Σ weight · N(mean, cov); components of 3 or more dimensions use their first two (position) components. */
  mixture: FovWeightedGaussian[];
  /** Positions: `[min, max, count]` per axis, `count` in [1, 4096] (like linspace). */
  grid: { x: [number, number, number]; y: [number, number, number] };
}
"#;

/// `obj[key]` of the object `path`, or a `TypeError` naming `path.key`.
fn required(obj: &Options, key: &str, path: &str) -> JsResult<JsValue> {
    obj.get(key)?
        .ok_or_else(|| type_error(format!("{path}.{key} is required")))
}

/// `{ mean, cov }` at `path` as a Gaussian named `path` in errors.
fn gaussian(obj: &Options, path: &str) -> JsResult<Gaussian> {
    let mean = numbers(&required(obj, "mean", path)?, &format!("{path}.mean"))?;
    let cov_path = format!("{path}.cov");
    let rows = points(&required(obj, "cov", path)?, &cov_path)?;
    let n = mean.len();
    if rows.len() != n {
        return Err(range_error(format!(
            "{cov_path} has length {}, expected {n}",
            rows.len()
        )));
    }
    let mut flat = Vec::with_capacity(n * n);
    for (i, row) in rows.iter().enumerate() {
        if row.len() != n {
            return Err(range_error(format!(
                "{cov_path}[{i}] has length {}, expected {n}",
                row.len()
            )));
        }
        flat.extend_from_slice(row);
    }
    Gaussian::from_slices(&mean, &flat, path).or_throw()
}

/// An array at `path` of at most [`MAX_GAUSSIANS`] entries, each an object.
fn entries(v: &JsValue, path: &str) -> JsResult<Vec<(String, Options)>> {
    let arr = array(v, path, "an array of objects")?;
    if arr.length() as usize > MAX_GAUSSIANS {
        return Err(range_error(format!(
            "{path} has {} entries, at most {MAX_GAUSSIANS} are supported",
            arr.length()
        )));
    }
    arr.iter()
        .enumerate()
        .map(|(i, e)| {
            let name = format!("{path}[{i}]");
            Options::new(&e, &name, true).map(|o| (name, o))
        })
        .collect()
}

fn bernoullis(v: &JsValue, path: &str) -> JsResult<Vec<(f64, Gaussian)>> {
    entries(v, path)?
        .into_iter()
        .map(|(name, o)| {
            let r = number(
                &required(&o, "existence", &name)?,
                &format!("{name}.existence"),
            )?;
            Ok((r, gaussian(&o, &name)?))
        })
        .collect()
}

pub(crate) fn mixture(v: &JsValue, path: &str) -> JsResult<GaussianMixture> {
    let comps = entries(v, path)?
        .into_iter()
        .map(|(name, o)| {
            let w = number(&required(&o, "weight", &name)?, &format!("{name}.weight"))?;
            Ok((w, gaussian(&o, &name)?))
        })
        .collect::<JsResult<Vec<_>>>()?;
    GaussianMixture::new(comps, path).or_throw()
}

fn rfs(v: &JsValue) -> JsResult<MultiObjectDensity> {
    let o = Options::new(v, "rfs", true)?;
    let keys = ["multiBernoulli", "poisson", "iidCluster", "glmb"];
    let mut found = Vec::new();
    for k in keys {
        if let Some(val) = o.get(k)? {
            found.push((k, val));
        }
    }
    let [(key, val)] = found.as_slice() else {
        return Err(type_error(format!(
            "rfs must have exactly one of the keys multiBernoulli, poisson, iidCluster, glmb \
             (found {})",
            found.len()
        )));
    };
    match *key {
        "multiBernoulli" => Ok(MultiObjectDensity::MultiBernoulli(bernoullis(
            val,
            "rfs.multiBernoulli",
        )?)),
        "poisson" => Ok(MultiObjectDensity::Poisson(mixture(val, "rfs.poisson")?)),
        "iidCluster" => {
            let c = Options::new(val, "rfs.iidCluster", true)?;
            let cardinality = numbers(
                &required(&c, "cardinality", "rfs.iidCluster")?,
                "rfs.iidCluster.cardinality",
            )?;
            if cardinality.len() > MAX_CARDINALITY_LEN {
                return Err(range_error(format!(
                    "rfs.iidCluster.cardinality has {} entries, at most {MAX_CARDINALITY_LEN} \
                     are supported",
                    cardinality.len()
                )));
            }
            let density = mixture(
                &required(&c, "density", "rfs.iidCluster")?,
                "rfs.iidCluster.density",
            )?;
            Ok(MultiObjectDensity::IidCluster {
                cardinality,
                density,
            })
        }
        _ => {
            let mut total = 0usize;
            let mut hyps = Vec::new();
            for (name, h) in entries(val, "rfs.glmb")? {
                let w = number(&required(&h, "weight", &name)?, &format!("{name}.weight"))?;
                let path = format!("{name}.components");
                let comps = entries(&required(&h, "components", &name)?, &path)?;
                total += comps.len();
                if total > MAX_GAUSSIANS {
                    return Err(range_error(format!(
                        "rfs.glmb has more than {MAX_GAUSSIANS} components in all"
                    )));
                }
                let gs = comps
                    .into_iter()
                    .map(|(n, o)| gaussian(&o, &n))
                    .collect::<JsResult<Vec<_>>>()?;
                hyps.push((w, gs));
            }
            Ok(MultiObjectDensity::Glmb(hyps))
        }
    }
}

/// An estimate of the native cost of one Gaussian mass in `fov`, in microseconds (measured:
/// a 2D box ~1 µs, a 2D disc or small polygon ~150–200 µs, a 3D box ~100 µs, a 3D ball
/// ~20 ms; each extra dimension multiplies by ~150).
fn mass_cost_us(kind: &str, dim: usize, vertices: usize) -> f64 {
    let nested = 150f64.powi(dim.saturating_sub(2) as i32);
    match kind {
        "box" if dim <= 2 => 1.0,
        "box" => nested,
        "polygon" => 150.0 + 10.0 * vertices as f64,
        _ if dim <= 1 => 1.0,
        _ => 150.0 * nested,
    }
}

/// A `fov`-shaped region (`{ box }`, `{ polygon }` or `{ disc }`) named `path` in errors, with its
/// mass-cost estimate.
pub(crate) fn region(v: &JsValue, path: &str) -> JsResult<(Region, f64)> {
    let o = Options::new(v, path, true)?;
    let found: Vec<(&str, JsValue)> = ["box", "polygon", "disc"]
        .into_iter()
        .filter_map(|k| o.get(k).transpose().map(|r| r.map(|v| (k, v))))
        .collect::<JsResult<_>>()?;
    let [(key, val)] = found.as_slice() else {
        return Err(type_error(format!(
            "{path} must have exactly one of the keys box, polygon, disc (found {})",
            found.len()
        )));
    };
    match *key {
        "box" => {
            let name = format!("{path}.box");
            let b = Options::new(val, &name, true)?;
            let min = numbers(&required(&b, "min", &name)?, &format!("{name}.min"))?;
            let max = numbers(&required(&b, "max", &name)?, &format!("{name}.max"))?;
            let cost = mass_cost_us("box", min.len(), 0);
            Ok((Region::axis_box(&min, &max, &name).or_throw()?, cost))
        }
        "polygon" => {
            let name = format!("{path}.polygon");
            let pts = points(val, &name)?;
            if pts.len() > MAX_VERTICES {
                return Err(range_error(format!(
                    "{name} has {} vertices, at most {MAX_VERTICES} are supported",
                    pts.len()
                )));
            }
            let mut verts = Vec::with_capacity(pts.len());
            for (i, p) in pts.iter().enumerate() {
                let &[x, y] = p.as_slice() else {
                    return Err(range_error(format!(
                        "{name}[{i}] has length {}, expected 2",
                        p.len()
                    )));
                };
                verts.push([x, y]);
            }
            let cost = mass_cost_us("polygon", 2, verts.len());
            Ok((Region::polygon(&verts, &name).or_throw()?, cost))
        }
        _ => {
            let name = format!("{path}.disc");
            let d = Options::new(val, &name, true)?;
            let center = numbers(&required(&d, "center", &name)?, &format!("{name}.center"))?;
            let radius = number(&required(&d, "radius", &name)?, &format!("{name}.radius"))?;
            let cost = mass_cost_us("disc", center.len(), 0);
            Ok((Region::ball(&center, radius, &name).or_throw()?, cost))
        }
    }
}

/// The pmf of the number of objects inside a field of view (Propositions 1–4 of the "Split
/// happens!" paper): options `{ rfs, fov, detectionProbability = 1 }` (see the
/// `FovCardinalityOptions` type); returns `{ pmf, mean, variance, massInFov }`.
#[wasm_bindgen(js_name = fovCardinality, unchecked_return_type = "FovCardinalityResult")]
pub fn fov_cardinality_js(
    #[wasm_bindgen(unchecked_param_type = "FovCardinalityOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    let density = rfs(&required(&opts, "rfs", "options")?)?;
    let (fov, cost) = region(&required(&opts, "fov", "options")?, "fov")?;
    let count = match &density {
        MultiObjectDensity::Poisson(m) => m.len(),
        MultiObjectDensity::IidCluster { density, .. } => density.len(),
        MultiObjectDensity::MultiBernoulli(c) => c.len(),
        MultiObjectDensity::Glmb(h) => h.iter().map(|(_, c)| c.len()).sum(),
    };
    if count as f64 * cost > MASS_BUDGET_US {
        return Err(range_error(format!(
            "fov: {count} Gaussian masses in this region would take about {:.0} s; use fewer \
             components, fewer polygon vertices or fewer FoV dimensions",
            count as f64 * cost * 1e-6
        )));
    }
    let pd = opts.number_or("detectionProbability", 1.0)?;
    let res = fov_cardinality(&density, &fov, pd).or_throw()?;
    Ok(object(&[
        ("pmf", number_array(&res.cardinality.pmf)),
        ("mean", res.cardinality.mean.into()),
        ("variance", res.cardinality.variance.into()),
        ("massInFov", number_array(&res.mass_in_fov)),
    ]))
}

fn grid_axis(grid: &Options, key: &str) -> JsResult<GridAxis> {
    let path = format!("grid.{key}");
    let v = numbers(&required(grid, key, "grid")?, &path)?;
    let &[min, max, count] = v.as_slice() else {
        return Err(range_error(format!(
            "{path} has length {}, expected 3 ([min, max, count])",
            v.len()
        )));
    };
    if count.fract() != 0.0 || !(1.0..=fisst::fov::MAX_GRID_AXIS as f64).contains(&count) {
        return Err(range_error(format!(
            "{path}[2] must be an integer count in [1, {}], got {count}",
            fisst::fov::MAX_GRID_AXIS
        )));
    }
    Ok(GridAxis {
        min,
        max,
        count: count as usize,
    })
}

/// The FoV-count variance of a multi-Bernoulli over a grid of FoV centres, and its maximiser
/// (Section VII of the "Split happens!" paper): options
/// `{ multiBernoulli, fovSize: [width, height], grid: { x: [min, max, count], y: [min, max,
/// count] } }`; returns `{ variance: Float64Array (row-major, y outer), argmax: [x, y], max }`.
#[wasm_bindgen(js_name = fovVarianceMap, unchecked_return_type = "FovVarianceMapResult")]
pub fn fov_variance_map(
    #[wasm_bindgen(unchecked_param_type = "FovVarianceMapOptions")] options: JsValue,
) -> JsResult<JsValue> {
    let opts = Options::new(&options, "options", true)?;
    let comps = bernoullis(
        &required(&opts, "multiBernoulli", "options")?,
        "multiBernoulli",
    )?;
    let size = numbers(&required(&opts, "fovSize", "options")?, "fovSize")?;
    let &[w, h] = size.as_slice() else {
        return Err(range_error(format!(
            "fovSize has length {}, expected 2 ([width, height])",
            size.len()
        )));
    };
    let grid = Options::new(&required(&opts, "grid", "options")?, "grid", true)?;
    let x = grid_axis(&grid, "x")?;
    let y = grid_axis(&grid, "y")?;
    if comps.len() as f64 * (x.count * y.count) as f64 > MAX_MAP_WORK {
        return Err(range_error(format!(
            "multiBernoulli.length × grid cells is {}, at most {MAX_MAP_WORK:e} is supported",
            comps.len() * x.count * y.count
        )));
    }
    let map = variance_map(&comps, [w, h], x, y).or_throw()?;
    let argmax: JsValue = [map.argmax[0], map.argmax[1]]
        .iter()
        .map(|&v| JsValue::from_f64(v))
        .collect::<Array>()
        .into();
    Ok(object(&[
        (
            "variance",
            Float64Array::from(map.variance.as_slice()).into(),
        ),
        ("argmax", argmax),
        ("max", map.max.into()),
    ]))
}

/// A seeded random multi-Bernoulli scene like the sensor-placement example of the "Split
/// happens!" paper (Section VII, Figs 9–10): options `{ count = 100, seed = 1, extent = 3,
/// sigma = [0.1, 0.5] }` (see `PlacementSceneOptions`); returns `{ multiBernoulli: [{
/// existence, mean: [x, y], cov: [[a, b], [b, c]] }, …] }`. The same seed gives the same scene
/// on every platform, and a smaller `count` is a prefix of a larger one.
#[wasm_bindgen(js_name = placementScene, unchecked_return_type = "PlacementSceneResult")]
pub fn placement_scene_js(
    #[wasm_bindgen(unchecked_optional_param_type = "PlacementSceneOptions")] options: Option<
        JsValue,
    >,
) -> JsResult<JsValue> {
    let opts = Options::new(&options.unwrap_or(JsValue::UNDEFINED), "options", false)?;
    let count = opts.integer_or("count", 100, 0, MAX_SCENE_COUNT)?;
    let seed = opts.number_or("seed", 1.0)?;
    if seed.fract() != 0.0 || !(0.0..=MAX_SEED).contains(&seed) {
        return Err(range_error(format!(
            "seed must be an integer in [0, 2^53 - 1], got {seed}"
        )));
    }
    let extent = opts.number_or("extent", 3.0)?;
    let sigma = match opts.get("sigma")? {
        None => [0.1, 0.5],
        Some(v) => {
            let s = numbers(&v, "sigma")?;
            let &[lo, hi] = s.as_slice() else {
                return Err(range_error(format!(
                    "sigma has length {}, expected 2 ([min, max])",
                    s.len()
                )));
            };
            [lo, hi]
        }
    };
    let scene = placement_scene(&SceneOptions {
        count,
        seed: seed as u64,
        extent,
        sigma,
    })
    .or_throw()?;
    let components: Array = scene
        .iter()
        .map(|(r, g)| {
            let m = g.mean();
            let p = g.cov();
            let cov: Array = [
                number_array(&[p[(0, 0)], p[(0, 1)]]),
                number_array(&[p[(1, 0)], p[(1, 1)]]),
            ]
            .iter()
            .collect();
            object(&[
                ("existence", (*r).into()),
                ("mean", number_array(&[m[0], m[1]])),
                ("cov", cov.into()),
            ])
        })
        .collect();
    Ok(object(&[("multiBernoulli", components.into())]))
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
    let opts = Options::new(&options, "options", true)?;
    let mix = mixture(&required(&opts, "mixture", "options")?, "mixture")?;
    let grid = Options::new(&required(&opts, "grid", "options")?, "grid", true)?;
    let x = grid_axis(&grid, "x")?;
    let y = grid_axis(&grid, "y")?;
    if mix.len() as f64 * (x.count * y.count) as f64 > MAX_DENSITY_WORK {
        return Err(range_error(format!(
            "mixture.length × grid cells is {}, at most {MAX_DENSITY_WORK:e} is supported",
            mix.len() * x.count * y.count
        )));
    }
    let d = mixture_density_grid(&mix, x, y).or_throw()?;
    Ok(Float64Array::from(d.as_slice()))
}
