//! The options and results of the field-of-view calls of Sections VI–VII of `001_…` (LeGrand,
//! Ferrari, "Split happens!") as the bindings take and give them (feature `serde`, Rust field
//! names): [`FovCardinalityOptions`] → [`FovCardinalityResult`] (the pmf (72)–(73) of the number
//! of objects in a field of view), [`FovVarianceMapOptions`] → [`FovVarianceMapResult`] (the
//! sensor placement of Section VII, Fig. 10) and [`MixtureDensityGridOptions`] (the PHD (99) over
//! a grid, Fig. 9). Each `run` checks the size caps and work budgets of [`super::budget`] before
//! it starts, so a call that would take more than a few seconds is refused with an error naming
//! the field to lower.

use alloc::vec::Vec;

use crate::error::{Error, Result};
use crate::gaussian::{Gaussian, GaussianMixture, MAX_GAUSSIANS};
use crate::regions::Region;

use super::{
    FOV_MASS_BUDGET_US, FovCount, GridAxis, IidCluster, MAX_CARDINALITY_LEN, MAX_DENSITY_GRID_WORK,
    MAX_GRID_AXIS, MAX_VARIANCE_MAP_WORK, MultiObjectDensity, VarianceMap, fov_cardinality,
    fov_mass_work_us, mixture_density_grid, variance_map,
};

/// At most this many vertices in one polygon of a field of view (the regions' own cap, as
/// [`crate::regions::MAX_MEMBERS`] is of a union's members).
pub use crate::regions::MAX_VERTICES;

/// The default detection probability p_D of [`FovCardinalityOptions`]: 1 (the pmf of objects,
/// not of detections).
pub const DEFAULT_DETECTION_PROBABILITY: f64 = 1.0;

#[cfg(feature = "serde")]
fn default_detection_probability() -> f64 {
    DEFAULT_DETECTION_PROBABILITY
}

/// The options of the FoV cardinality pmf, Propositions 1–4 ((72)–(92)) of `001_…`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FovCardinalityOptions {
    /// The multi-object density of the random finite set X (`rfs`: the papers' name for X;
    /// at most 10,000 Gaussians in all ([`MAX_GAUSSIANS`]), an i.i.d. cluster's cardinality
    /// pmf at most 20,001 entries ([`MAX_CARDINALITY_LEN`]); the call is refused when its
    /// masses would take more than about 2 s).
    pub rfs: MultiObjectDensity,
    /// The field of view S, in the position subspace (the first state components); polygons of
    /// at most 1,000 vertices ([`MAX_VERTICES`]), unions of at most as many members.
    pub fov: Region,
    /// The detection probability p_D ∈ [0, 1] (default 1, [`DEFAULT_DETECTION_PROBABILITY`]):
    /// with p_D < 1 the pmf is that of object-originated detections, eq. (75).
    #[cfg_attr(feature = "serde", serde(default = "default_detection_probability"))]
    pub detection_probability: f64,
}

impl FovCardinalityOptions {
    /// The size caps and the work budget ([`FOV_MASS_BUDGET_US`], about 2 s of masses by
    /// [`fov_mass_work_us`]) of these options.
    ///
    /// # Errors
    /// [`Error::Count`] naming `rfs.glmb` (more than [`MAX_GAUSSIANS`] components in all),
    /// `rfs.iid_cluster.cardinality` (more than [`MAX_CARDINALITY_LEN`] entries);
    /// [`Error::OverBudget`] naming `rfs` when the masses would take more than about 2 s.
    pub fn check_work(&self) -> Result<()> {
        match &self.rfs {
            MultiObjectDensity::Glmb(h) => {
                let total = h.iter().map(|(_, c)| c.len()).sum();
                Error::check_count("rfs.glmb", "components in all", total, 0, MAX_GAUSSIANS)?;
            }
            MultiObjectDensity::IidCluster(IidCluster { cardinality, .. }) => Error::check_count(
                "rfs.iid_cluster.cardinality",
                "entries",
                cardinality.len(),
                0,
                MAX_CARDINALITY_LEN,
            )?,
            MultiObjectDensity::Poisson(_) | MultiObjectDensity::MultiBernoulli(_) => {}
        }
        let work = fov_mass_work_us(&self.rfs, &self.fov);
        if work > FOV_MASS_BUDGET_US {
            let per_mass = self.fov.mass_cost_us().max(f64::MIN_POSITIVE);
            return Err(Error::OverBudget {
                what: "rfs".into(),
                measure: "Gaussians × estimated µs per mass in the fov",
                work: work as usize,
                limit: "2·10^6 µs (about 2 s); use fewer components, fewer polygon vertices or \
                        fewer FoV dimensions",
                at_most: (FOV_MASS_BUDGET_US / per_mass) as usize,
            });
        }
        Ok(())
    }

    /// The pmf of the number of objects (detections) in the FoV, Propositions 1–4 of `001_…`
    /// ((72)–(73), with (75) for p_D < 1): [`check_work`](Self::check_work), then
    /// [`fov_cardinality`].
    ///
    /// # Errors
    /// Those of [`check_work`](Self::check_work) and of [`fov_cardinality`].
    pub fn run(&self) -> Result<FovCardinalityResult> {
        self.check_work()?;
        fov_cardinality(&self.rfs, &self.fov, self.detection_probability)
            .map(FovCardinalityResult::from)
    }
}

/// The pmf of the number of objects in the field of view (eqs. (72)–(92) of `001_…`), flat
/// ([`FovCardinalityOptions::run`]).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FovCardinalityResult {
    /// `pmf[n]`: probability of n objects (detections) in the FoV, n = 0 … (Poisson and i.i.d.
    /// cluster: up to where the tail is below 1e-15).
    pub pmf: Vec<f64>,
    /// The mean number of objects (detections) in the FoV (closed form).
    pub mean: f64,
    /// The variance of the number of objects (detections) in the FoV (closed form).
    pub variance: f64,
    /// The mass in the FoV, ⟨1_S, p_i⟩ ∈ [0, 1], of each Gaussian in input order (each mixture
    /// component for Poisson and i.i.d. cluster; for a GLMB hypothesis 0's components, then
    /// hypothesis 1's, …), without p_D.
    pub mass_in_fov: Vec<f64>,
}

impl From<FovCount> for FovCardinalityResult {
    fn from(c: FovCount) -> Self {
        FovCardinalityResult {
            pmf: c.cardinality.pmf,
            mean: c.cardinality.mean,
            variance: c.cardinality.variance,
            mass_in_fov: c.mass_in_fov,
        }
    }
}

/// A grid axis `[min, max, count]`: `count` points from `min` to `max` (like linspace).
pub type Axis = [f64; 3];

/// A 2D grid of positions, one axis `[min, max, count]` per coordinate (`count` points from
/// `min` to `max`, like linspace; `count` an integer in [1, 4096] ([`MAX_GRID_AXIS`])).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Grid {
    /// The x axis `[min, max, count]`, `count` in [1, 4096].
    pub x: Axis,
    /// The y axis `[min, max, count]`, `count` in [1, 4096].
    pub y: Axis,
}

fn axis([min, max, count]: [f64; 3], name: &str) -> Result<GridAxis> {
    if libm::trunc(count) != count || !(1.0..=MAX_GRID_AXIS as f64).contains(&count) {
        return Err(Error::parameter(
            alloc::format!("{name}[2]"),
            count,
            "an integer count in [1, 4096]",
        ));
    }
    Ok(GridAxis {
        min,
        max,
        count: count as usize,
    })
}

impl Grid {
    /// Both axes as [`GridAxis`] values.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `grid.x[2]` or `grid.y[2]` for a count that is not an
    /// integer in [1, [`MAX_GRID_AXIS`]].
    pub fn axes(&self) -> Result<(GridAxis, GridAxis)> {
        Ok((axis(self.x, "grid.x")?, axis(self.y, "grid.y")?))
    }
}

/// The options of the FoV-count variance map of Section VII of `001_…` (Fig. 10): a
/// multi-Bernoulli, an axis-aligned FoV of size `fov_size` and a grid of FoV centres.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FovVarianceMapOptions {
    /// The multi-Bernoulli (2D or more; the first two state components are positions), as
    /// `[{existence, mean, cov}, …]`.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::bernoullis"))]
    pub multi_bernoulli: Vec<(f64, Gaussian)>,
    /// FoV width and height, finite and > 0 (a box centred on each grid point).
    pub fov_size: [f64; 2],
    /// The grid of FoV centres; components × cells at most 2e8 ([`MAX_VARIANCE_MAP_WORK`]).
    pub grid: Grid,
}

impl FovVarianceMapOptions {
    /// The variance of the FoV count (88) at every FoV centre of the grid and its maximiser
    /// (Section VII of `001_…`), by [`variance_map`], after the grid and work checks.
    ///
    /// # Errors
    /// Those of [`Grid::axes`]; [`Error::OverBudget`] naming `multi_bernoulli` when components
    /// × grid cells exceed [`MAX_VARIANCE_MAP_WORK`]; those of [`variance_map`].
    pub fn run(&self) -> Result<VarianceMap> {
        let (x, y) = self.grid.axes()?;
        Error::check_work(
            "multi_bernoulli",
            "components × grid cells",
            "2·10^8",
            x.count * y.count,
            self.multi_bernoulli.len(),
            MAX_VARIANCE_MAP_WORK as usize,
        )?;
        variance_map(&self.multi_bernoulli, self.fov_size, x, y)
    }
}

/// A [`VarianceMap`] as a table: `variance[j][i]` is the FoV-count variance with the FoV centred
/// at (x_i, y_j) (`ny` rows of `nx`, y the outer index), with the maximiser `argmax` = `[x, y]`
/// and the maximum `max` (Section VII of `001_…`).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FovVarianceMapResult {
    /// The variances, `ny` rows of `nx`.
    pub variance: Vec<Vec<f64>>,
    /// The FoV centre `[x, y]` of the largest variance (the best placement).
    pub argmax: [f64; 2],
    /// The largest FoV-count variance over the grid.
    pub max: f64,
}

impl From<VarianceMap> for FovVarianceMapResult {
    fn from(m: VarianceMap) -> Self {
        FovVarianceMapResult {
            variance: m
                .variance
                .chunks(m.nx.max(1))
                .map(<[f64]>::to_vec)
                .collect(),
            argmax: m.argmax,
            max: m.max,
        }
    }
}

/// The options of a Gaussian mixture's density over a grid, e.g. the PHD (99) of a
/// multi-Bernoulli as a heat map (Fig. 9 of `001_…`).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MixtureDensityGridOptions {
    /// The mixture Σ weight · N(mean, cov); components of 3 or more dimensions use their first
    /// two (position) components. Its peak, Σ weight / √det(2π cov), must stay below the
    /// largest double (about 1.8e308; an error naming the weight that passes it).
    pub mixture: GaussianMixture,
    /// The grid of positions; components × cells at most 2.5e7 ([`MAX_DENSITY_GRID_WORK`]).
    pub grid: Grid,
}

impl MixtureDensityGridOptions {
    /// The density at every grid position, row-major with y the outer index (entry
    /// `j * nx + i` at (x_i, y_j)), by [`mixture_density_grid`], after the grid and work
    /// checks.
    ///
    /// # Errors
    /// Those of [`Grid::axes`]; [`Error::OverBudget`] naming `mixture` when components × grid
    /// cells exceed [`MAX_DENSITY_GRID_WORK`]; those of [`mixture_density_grid`].
    pub fn run(&self) -> Result<Vec<f64>> {
        let (x, y) = self.grid.axes()?;
        Error::check_work(
            "mixture",
            "components × grid cells",
            "2.5·10^7",
            x.count * y.count,
            self.mixture.len(),
            MAX_DENSITY_GRID_WORK as usize,
        )?;
        mixture_density_grid(&self.mixture, x, y)
    }

    /// [`run`](Self::run) as `ny` rows of `nx` values (`rows[j][i]` at (x_i, y_j)).
    ///
    /// # Errors
    /// Those of [`run`](Self::run).
    pub fn run_rows(&self) -> Result<Vec<Vec<f64>>> {
        let nx = self.grid.axes()?.0.count;
        Ok(self.run()?.chunks(nx).map(<[f64]>::to_vec).collect())
    }
}

/// A GLMB's hypotheses `Vec<(weight, components)>` as `[{weight, components: [{mean, cov},
/// …]}, …]` (feature `serde`).
#[cfg(feature = "serde")]
pub(crate) mod glmb_hypotheses {
    use alloc::vec::Vec;

    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    use crate::gaussian::Gaussian;

    #[derive(Serialize)]
    #[serde(rename = "GlmbHypothesis")]
    struct HypothesisRef<'a> {
        weight: f64,
        components: &'a [Gaussian],
    }

    #[derive(Deserialize)]
    #[serde(rename = "GlmbHypothesis")]
    struct Hypothesis {
        weight: f64,
        components: Vec<Gaussian>,
    }

    pub fn serialize<S: Serializer>(v: &[(f64, Vec<Gaussian>)], s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(v.iter().map(|(w, c)| HypothesisRef {
            weight: *w,
            components: c,
        }))
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(
        d: D,
    ) -> Result<Vec<(f64, Vec<Gaussian>)>, D::Error> {
        Ok(Vec::<Hypothesis>::deserialize(d)?
            .into_iter()
            .map(|h| (h.weight, h.components))
            .collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::string::ToString;
    use alloc::vec;

    fn g(x: f64) -> Gaussian {
        Gaussian::from_slices(&[x, 0.0], &[0.01, 0.0, 0.0, 0.01], "g").unwrap()
    }

    #[test]
    fn eq72_run_is_fov_cardinality_flattened() {
        let rfs = MultiObjectDensity::MultiBernoulli(vec![(0.5, g(0.0)), (0.9, g(9.0))]);
        let fov = Region::axis_box(&[-1.0, -1.0], &[1.0, 1.0], "fov").unwrap();
        let o = FovCardinalityOptions {
            rfs: rfs.clone(),
            fov: fov.clone(),
            detection_probability: 0.8,
        };
        let direct = fov_cardinality(&rfs, &fov, 0.8).unwrap();
        let r = o.run().unwrap();
        assert_eq!(r.pmf, direct.cardinality.pmf);
        assert_eq!(r.mean.to_bits(), direct.cardinality.mean.to_bits());
        assert_eq!(r.variance.to_bits(), direct.cardinality.variance.to_bits());
        assert_eq!(r.mass_in_fov, direct.mass_in_fov);
    }

    #[test]
    fn eq72_caps_name_the_rust_fields() {
        let fov = Region::axis_box(&[-1.0, -1.0], &[1.0, 1.0], "fov").unwrap();
        let glmb = FovCardinalityOptions {
            rfs: MultiObjectDensity::Glmb(vec![(1.0, vec![g(0.0); MAX_GAUSSIANS + 1])]),
            fov: fov.clone(),
            detection_probability: 1.0,
        };
        let e = glmb.run().unwrap_err();
        assert_eq!(e.field(), "rfs.glmb");
        assert!(e.to_string().contains("10001 components in all"), "{e}");
        let iid = FovCardinalityOptions {
            rfs: MultiObjectDensity::IidCluster(IidCluster {
                cardinality: vec![0.0; MAX_CARDINALITY_LEN + 1],
                density: GaussianMixture::new(vec![(1.0, g(0.0))], "d").unwrap(),
            }),
            fov: fov.clone(),
            detection_probability: 1.0,
        };
        assert_eq!(
            iid.run().unwrap_err().field(),
            "rfs.iid_cluster.cardinality"
        );
        let pd = FovCardinalityOptions {
            rfs: MultiObjectDensity::MultiBernoulli(vec![(0.5, g(0.0))]),
            fov,
            detection_probability: 90.0,
        };
        assert_eq!(pd.run().unwrap_err().field(), "detection_probability");
    }

    #[test]
    fn eq72_the_mass_budget_names_rfs() {
        // 10,000 components in a 1,000-vertex polygon: far above 2 s of masses.
        let many: Vec<[f64; 2]> = (0..MAX_VERTICES)
            .map(|i| {
                let t = i as f64 * core::f64::consts::TAU / MAX_VERTICES as f64;
                [libm::cos(t), libm::sin(t)]
            })
            .collect();
        let fov = Region::polygon(&many, "fov").unwrap();
        let o = FovCardinalityOptions {
            rfs: MultiObjectDensity::MultiBernoulli(vec![(0.5, g(0.0)); MAX_GAUSSIANS]),
            fov: fov.clone(),
            detection_probability: 1.0,
        };
        assert!(fov_mass_work_us(&o.rfs, &fov) > FOV_MASS_BUDGET_US);
        let e = o.run().unwrap_err();
        assert!(matches!(e, Error::OverBudget { .. }), "{e}");
        assert_eq!(e.field(), "rfs");
    }

    #[test]
    fn fig10_grid_axes_and_work_caps() {
        let grid = Grid {
            x: [0.0, 1.0, 3.0],
            y: [0.0, 2.0, 2.5],
        };
        assert_eq!(grid.axes().unwrap_err().field(), "grid.y[2]");
        let grid = Grid {
            x: [0.0, 1.0, 3.0],
            y: [0.0, 2.0, 2.0],
        };
        let (x, y) = grid.axes().unwrap();
        assert_eq!((x.count, y.count), (3, 2));
        let o = FovVarianceMapOptions {
            multi_bernoulli: vec![(0.5, g(0.0)), (0.7, g(1.0))],
            fov_size: [1.0, 1.0],
            grid,
        };
        let rows = FovVarianceMapResult::from(o.run().unwrap());
        let flat = o.run().unwrap();
        assert_eq!(rows.variance.len(), 2);
        assert_eq!(rows.variance.concat(), flat.variance);
        assert_eq!(rows.argmax, flat.argmax);
        let big = Grid {
            x: [0.0, 1.0, 4096.0],
            y: [0.0, 1.0, 4096.0],
        };
        let o = FovVarianceMapOptions {
            multi_bernoulli: vec![(0.5, g(0.0)); 12],
            fov_size: [1.0, 1.0],
            grid: big,
        };
        let e = o.run().unwrap_err();
        assert_eq!(e.field(), "multi_bernoulli");
        let m = MixtureDensityGridOptions {
            mixture: GaussianMixture::new(vec![(1.0, g(0.0)); 2], "m").unwrap(),
            grid: big,
        };
        assert_eq!(m.run().unwrap_err().field(), "mixture");
        let m = MixtureDensityGridOptions {
            mixture: GaussianMixture::new(vec![(1.0, g(0.0))], "m").unwrap(),
            grid: Grid {
                x: [-1.0, 1.0, 3.0],
                y: [0.0, 1.0, 2.0],
            },
        };
        let rows = m.run_rows().unwrap();
        assert_eq!(rows.concat(), m.run().unwrap());
        assert_eq!((rows.len(), rows[0].len()), (2, 3));
    }
}
