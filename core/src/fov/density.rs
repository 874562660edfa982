//! FoV cardinality pmfs of multi-object densities with Gaussian(-mixture) single-object
//! densities: the masses ⟨1_S, p⟩ by [`Region::gaussian_mass`], then the pmfs of
//! [`super::pmf`].

use alloc::string::String;
use alloc::vec::Vec;

use crate::error::{Error, Result, Shape, check_probability};
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::math::fns;
use crate::math::sum::sum;
use crate::regions::Region;

use super::pmf::{self, FovCardinality, GlmbHypothesis};

/// A multi-object density whose single-object densities are Gaussians or Gaussian mixtures
/// (eq. (7) of `001_…`).
///
/// Written as options, it has exactly one key: `poisson` (a mixture
/// `[{weight, mean, cov}, …]`), `iid_cluster` (`{cardinality, density}`), `multi_bernoulli`
/// (`[{existence, mean, cov}, …]`) or `glmb` (`[{weight, components: [{mean, cov}, …]}, …]`).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "snake_case")
)]
pub enum MultiObjectDensity {
    /// Poisson RFS (76) with PHD D(x) = Σ_i w_i N(x; m_i, P_i); N_X = Σ_i w_i.
    Poisson(GaussianMixture),
    /// i.i.d. cluster RFS (83): cardinality pmf ρ(0), ρ(1), … and single-object density p
    /// (a mixture whose weights sum to 1).
    IidCluster(IidCluster),
    /// Multi-Bernoulli RFS (87): (existence r⁽ⁱ⁾, density p⁽ⁱ⁾) per component.
    MultiBernoulli(
        #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::bernoullis"))]
        Vec<(f64, Gaussian)>,
    ),
    /// GLMB (91): one entry per hypothesis (ξ, I): its weight w⁽ξ⁾(I) and the densities
    /// p⁽ξ,ℓ⁾ of its labels ℓ ∈ I.
    Glmb(
        #[cfg_attr(feature = "serde", serde(with = "super::options::glmb_hypotheses"))]
        Vec<(f64, Vec<Gaussian>)>,
    ),
}

/// Numbers `[x, …]`, written under this name, which the JavaScript binding declares (a list
/// of numbers or a `Float64Array`).
type Numbers = Vec<f64>;

/// An i.i.d. cluster density: a cardinality pmf and one single-object density
/// ([`MultiObjectDensity::IidCluster`]).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct IidCluster {
    /// The cardinality pmf ρ(0), ρ(1), …: ρ(n) is the probability of n objects (sums to 1; at
    /// most 20,001 entries).
    pub cardinality: Numbers,
    /// The single-object density p(x) as a mixture (weights sum to 1).
    pub density: GaussianMixture,
}

/// [`fov_cardinality`]'s result.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FovCount {
    /// The pmf of the number of objects (or of object detections, for p_D < 1) in S, its mean
    /// and variance.
    pub cardinality: FovCardinality,
    /// ⟨1_S, p_i⟩ for every Gaussian in the order given (every mixture component for Poisson
    /// and i.i.d. cluster; for a GLMB the components of hypothesis 0, then of hypothesis 1,
    /// …). Without p_D.
    pub mass_in_fov: Vec<f64>,
}

fn masses<'a>(
    fov: &Region,
    gaussians: impl Iterator<Item = (String, &'a Gaussian)>,
) -> Result<Vec<f64>> {
    let gaussians: Vec<(String, &Gaussian)> = gaussians.collect();
    // When no component has the FoV's dimension, the likelier mistake is the FoV (a 3-D box over
    // 2-D objects): name its field first and the mean it disagrees with (in the Rust names
    // these errors use). A single odd component is blamed itself, by the mass below.
    if let Some((name, g)) = gaussians.first()
        && gaussians.iter().all(|(_, g)| g.dim() < fov.dim())
    {
        let (field, dim) = crate::filters::validate::region_dim_field(fov);
        return Err(Error::shapes(
            alloc::format!("fov.{field}"),
            Shape::Length(dim),
            alloc::format!("{name}.mean"),
            Shape::Length(g.dim()),
        ));
    }
    gaussians
        .into_iter()
        .map(|(name, g)| fov.gaussian_mass(g, &name).map(|m| m.value))
        .collect()
}

fn weights_sum_to_one(weights: impl Iterator<Item = f64>, what: &str) -> Result<f64> {
    let total = sum(weights);
    if fns::abs(total - 1.0) <= 1e-9 {
        Ok(total)
    } else {
        Err(Error::parameter(
            what,
            total,
            "weights summing to 1 within 1e-9 (the value is their sum)",
        ))
    }
}

fn renamed(e: Error, prefix: &str, from: &str) -> Error {
    let rename = |what: String| {
        let rest = what.strip_prefix(from).unwrap_or(&what);
        alloc::format!("{prefix}{rest}")
    };
    match e {
        Error::InvalidParameter {
            what,
            value,
            expected,
        } => Error::InvalidParameter {
            what: rename(what),
            value,
            expected,
        },
        Error::InvalidProbability { what, value } => Error::InvalidProbability {
            what: rename(what),
            value,
        },
        Error::DimensionMismatch {
            what,
            expected,
            found,
        } => Error::DimensionMismatch {
            what: rename(what),
            expected,
            found,
        },
        Error::NotPositiveDefinite { what } => Error::NotPositiveDefinite { what: rename(what) },
        Error::Unsupported { what, reason } => Error::Unsupported {
            what: rename(what),
            reason,
        },
        e => e.map_field(|what| rename(what.into())),
    }
}

/// The pmf of the number of objects inside the field of view S — or, with p_D < 1, of
/// object-originated detections, the variant (75) of `001_…`:
///
/// ```text
/// ρ_S(n_Z | X) = Σ_{Xⁿ ⊆ X} [p_D 1_S(·)]^{Xⁿ} [1 − p_D 1_S(·)]^{X∖Xⁿ}      (75)
/// ```
///
/// with a constant p_D, so every ⟨1_S, p⟩ below becomes p_D ⟨1_S, p⟩. By density:
/// Poisson (78) → [`pmf::poisson`] with λ_S = p_D Σ_i w_i ⟨1_S, N_i⟩; i.i.d. cluster (84) →
/// [`pmf::iid_cluster`] with q = p_D Σ_i w_i ⟨1_S, N_i⟩; multi-Bernoulli (88)–(89) →
/// [`pmf::multi_bernoulli`] with r_S⁽ⁱ⁾ = p_D r⁽ⁱ⁾ ⟨1_S, p⁽ⁱ⁾⟩; GLMB (92) → [`pmf::glmb`].
/// The masses come from [`Region::gaussian_mass`] (see there for their accuracy).
///
/// Error messages use the Rust field names (`rfs.multi_bernoulli[3].existence`,
/// `rfs.poisson[1].mean`, `rfs.iid_cluster.cardinality[2]`, `rfs.glmb[0].weight`,
/// `detection_probability`).
///
/// # Errors
/// [`Error::InvalidProbability`] for p_D or an existence outside [0, 1];
/// [`Error::InvalidParameter`] for i.i.d.-cluster density weights or GLMB weights that do not
/// sum to 1 within 1e-9, or a bad cardinality pmf; [`Error::ShapeMismatch`] for a
/// Gaussian with fewer components than the region (naming the region's field, `fov.box.min`); [`Error::Unsupported`] for a Poisson pmf
/// longer than [`pmf::MAX_PMF_LEN`] or a region of more than 4 dimensions.
///
/// # Examples
/// ```
/// use fisst::fov::{fov_cardinality, MultiObjectDensity};
/// use fisst::gaussian::Gaussian;
/// use fisst::regions::Region;
/// let g = |x: f64| Gaussian::from_slices(&[x, 0.0], &[0.01, 0.0, 0.0, 0.01], "p").unwrap();
/// // Two objects far inside the FoV, one far outside.
/// let mb = MultiObjectDensity::MultiBernoulli(vec![(0.5, g(0.0)), (0.5, g(0.5)), (0.9, g(9.0))]);
/// let fov = Region::axis_box(&[-1.0, -1.0], &[1.0, 1.0], "fov")?;
/// let c = fov_cardinality(&mb, &fov, 1.0)?;
/// assert!((c.cardinality.pmf[1] - 0.5).abs() < 1e-12);
/// assert!((c.cardinality.variance - 0.5).abs() < 1e-12);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn fov_cardinality(
    density: &MultiObjectDensity,
    fov: &Region,
    detection_prob: f64,
) -> Result<FovCount> {
    let pd = check_probability(|| "detection_probability".into(), detection_prob)?;
    match density {
        MultiObjectDensity::Poisson(phd) => {
            let mass_in_fov = masses(
                fov,
                phd.components()
                    .iter()
                    .enumerate()
                    .map(|(i, (_, g))| (alloc::format!("rfs.poisson[{i}]"), g)),
            )?;
            let lambda = pd
                * sum(phd
                    .components()
                    .iter()
                    .zip(&mass_in_fov)
                    .map(|((w, _), m)| w * m));
            let cardinality =
                pmf::poisson(lambda).map_err(|e| renamed(e, "rfs.poisson", "inside"))?;
            Ok(FovCount {
                cardinality,
                mass_in_fov,
            })
        }
        MultiObjectDensity::IidCluster(IidCluster {
            cardinality,
            density,
        }) => {
            let total = weights_sum_to_one(
                density.components().iter().map(|(w, _)| *w),
                "rfs.iid_cluster.density",
            )?;
            let mass_in_fov = masses(
                fov,
                density
                    .components()
                    .iter()
                    .enumerate()
                    .map(|(i, (_, g))| (alloc::format!("rfs.iid_cluster.density[{i}]"), g)),
            )?;
            let q = pd
                * sum(density
                    .components()
                    .iter()
                    .zip(&mass_in_fov)
                    .map(|((w, _), m)| w / total * m));
            let cardinality = pmf::iid_cluster(cardinality, q.clamp(0.0, 1.0))
                .map_err(|e| renamed(e, "rfs.iid_cluster.cardinality", "cardinality"))?;
            Ok(FovCount {
                cardinality,
                mass_in_fov,
            })
        }
        MultiObjectDensity::MultiBernoulli(components) => {
            for (i, (r, _)) in components.iter().enumerate() {
                check_probability(|| alloc::format!("rfs.multi_bernoulli[{i}].existence"), *r)?;
            }
            let mass_in_fov = masses(
                fov,
                components
                    .iter()
                    .enumerate()
                    .map(|(i, (_, g))| (alloc::format!("rfs.multi_bernoulli[{i}]"), g)),
            )?;
            let inside: Vec<f64> = components
                .iter()
                .zip(&mass_in_fov)
                .map(|((r, _), m)| pd * r * m)
                .collect();
            Ok(FovCount {
                cardinality: pmf::multi_bernoulli_unchecked(&inside),
                mass_in_fov,
            })
        }
        MultiObjectDensity::Glmb(hypotheses) => {
            for (h, (w, _)) in hypotheses.iter().enumerate() {
                if !(w.is_finite() && *w >= 0.0) {
                    return Err(Error::parameter(
                        alloc::format!("rfs.glmb[{h}].weight"),
                        *w,
                        "finite and >= 0",
                    ));
                }
            }
            weights_sum_to_one(hypotheses.iter().map(|(w, _)| *w), "rfs.glmb")?;
            let mut mass_in_fov = Vec::new();
            let mut hyps = Vec::with_capacity(hypotheses.len());
            for (h, (w, comps)) in hypotheses.iter().enumerate() {
                let m = masses(
                    fov,
                    comps
                        .iter()
                        .enumerate()
                        .map(|(l, g)| (alloc::format!("rfs.glmb[{h}].components[{l}]"), g)),
                )?;
                hyps.push(GlmbHypothesis {
                    weight: *w,
                    inside: m.iter().map(|x| pd * x).collect(),
                });
                mass_in_fov.extend(m);
            }
            let cardinality = pmf::glmb(&hyps).map_err(|e| renamed(e, "rfs.glmb", "hypotheses"))?;
            Ok(FovCount {
                cardinality,
                mass_in_fov,
            })
        }
    }
}
