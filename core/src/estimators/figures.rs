//! The figures of `003_…` (García-Fernández & Svensson, "Spooky effect in optimal OSPA
//! estimation and how GOSPA solves it", Fusion 2019) as functions: the decision maps of
//! Figs 1 and 2 (two far-apart components, every (r1, r2) of a grid) and the reported counts of
//! Fig. 3 (n identical components, eq. (11)).
//!
//! Both evaluate the estimators of [`multi_bernoulli`](super::multi_bernoulli) (the optimal
//! GOSPA, OSPA and UOSPA estimates, (9) and the top-k search) and of
//! [`alternatives`](super::alternatives) (MaM, JoM, MAP cardinality) cell by cell.

use alloc::vec;
use alloc::vec::Vec;

use super::alternatives::{AlternativeMethod, alternative_estimate, map_cardinality_estimate};
use super::multi_bernoulli::{SetMetric, optimal_estimate};
use crate::error::{Error, Result, check_probability};
use crate::metrics::{default_alpha, default_order};

/// Largest [`DecisionMapOptions::resolution`]: 2000 × 2000 cells.
pub const MAX_DECISION_MAP_RESOLUTION: usize = 2000;

/// Largest [`IdenticalComponentCountsOptions::max_components`]: 300. Each n costs an OSPA
/// estimate of O(n² log n), so the call costs O(N³ log N): about 0.3 s at the cap in Node
/// (1000, the cap before, took about 8 s).
pub const MAX_IDENTICAL_COMPONENTS: usize = 300;

/// An estimator whose decisions [`decision_map`] maps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "kebab-case"))]
pub enum DecisionEstimator {
    /// The optimal GOSPA estimate (with the map's `alpha`).
    Gospa,
    /// `ospa`: the estimate that minimises the mean OSPA error.
    Ospa,
    /// `uospa`: the estimate that minimises the mean UOSPA error.
    Uospa,
    /// `mam`: the marginal multi-target estimator (Fig. 2).
    Mam,
    /// `jom`: the joint multi-target estimator (Fig. 2).
    Jom,
    /// MAP cardinality, then the most probable components (Fig. 2).
    MapCardinality,
}

/// The default [`DecisionMapOptions::resolution`]: 100 cells per axis.
pub const fn default_resolution() -> usize {
    100
}

/// The default cut-off c of the figures' metrics: 1 (the components are far apart, so the
/// decisions do not depend on it).
pub const fn default_cutoff() -> f64 {
    1.0
}

/// Options of [`decision_map`] (Figs. 1–2 of García-Fernández & Svensson, "Spooky effect in optimal
/// OSPA estimation and how GOSPA solves it" (paper 003)).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DecisionMapOptions {
    /// The estimator whose decisions are mapped.
    pub estimator: DecisionEstimator,
    /// Cells per axis (default 100), an integer in [1, 2000] ([`MAX_DECISION_MAP_RESOLUTION`]).
    #[cfg_attr(feature = "serde", serde(default = "default_resolution"))]
    pub resolution: usize,
    /// The metrics' cut-off c > 0 (default 1; the metric estimators only).
    #[cfg_attr(feature = "serde", serde(default = "default_cutoff"))]
    pub c: f64,
    /// The metrics' order p ≥ 1 (default 2; the metric estimators only).
    #[cfg_attr(feature = "serde", serde(default = "default_order"))]
    pub p: f64,
    /// GOSPA's α in (0, 2] (default 2; used by the GOSPA estimator `"gospa"` only).
    #[cfg_attr(feature = "serde", serde(default = "default_alpha"))]
    pub alpha: f64,
}

impl DecisionMapOptions {
    /// The options for `estimator` with every other field at its default.
    pub fn new(estimator: DecisionEstimator) -> Self {
        Self {
            estimator,
            resolution: default_resolution(),
            c: default_cutoff(),
            p: default_order(),
            alpha: default_alpha(),
        }
    }
}

/// A decision map: the decision of every cell of a grid of (r1, r2).
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DecisionMap {
    /// The number of grid cells per axis (the map has resolution² cells).
    pub resolution: usize,
    /// `decisions[row * resolution + col]` = u1 + 2·u2 at r1 = (col + ½)/resolution,
    /// r2 = (row + ½)/resolution.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::bytes"))]
    pub decisions: Vec<u8>,
}

/// Figs 1 and 2 of `003_…`: for two far-apart components and every cell of a
/// `resolution × resolution` grid of existence probabilities (r1, r2) (cell centres,
/// r = (i + ½)/resolution), the estimate coded as `u1 + 2·u2`, row-major with r2 as the outer
/// (row) index. MaM and JoM use equal covariances (`ln_peak` 0) and ln c = 0.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `resolution` outside [1,
/// [`MAX_DECISION_MAP_RESOLUTION`]]; for the metric estimators, as
/// [`optimal_estimate`] for `c`, `p` and `alpha`.
///
/// # Examples
/// ```
/// use fisst::estimators::figures::{decision_map, DecisionEstimator, DecisionMapOptions};
/// let map = decision_map(&DecisionMapOptions {
///     resolution: 2,
///     ..DecisionMapOptions::new(DecisionEstimator::Gospa)
/// })?;
/// // GOSPA reports a component exactly when its r > 1/2 (eq. (9)).
/// assert_eq!(map.decisions, vec![0, 1, 2, 3]);
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn decision_map(options: &DecisionMapOptions) -> Result<DecisionMap> {
    let res = options.resolution;
    if !(1..=MAX_DECISION_MAP_RESOLUTION).contains(&res) {
        return Err(Error::parameter(
            "resolution",
            res as f64,
            "an integer in [1, 2000]",
        ));
    }
    let metric = match options.estimator {
        DecisionEstimator::Gospa => Some(SetMetric::Gospa {
            alpha: options.alpha,
        }),
        DecisionEstimator::Ospa => Some(SetMetric::Ospa),
        DecisionEstimator::Uospa => Some(SetMetric::Uospa),
        _ => None,
    };
    let method = match options.estimator {
        DecisionEstimator::Jom => AlternativeMethod::Jom,
        DecisionEstimator::MapCardinality => AlternativeMethod::MapCardinality,
        _ => AlternativeMethod::Mam,
    };
    let mut decisions = vec![0u8; res * res];
    for row in 0..res {
        for col in 0..res {
            let r = [
                (col as f64 + 0.5) / res as f64,
                (row as f64 + 0.5) / res as f64,
            ];
            let u = match metric {
                Some(m) => optimal_estimate(&r, m, options.c, options.p)?.report,
                None => alternative_estimate(&r, method, &[0.0, 0.0], 0.0)?,
            };
            decisions[row * res + col] = u8::from(u[0]) + 2 * u8::from(u[1]);
        }
    }
    Ok(DecisionMap {
        resolution: res,
        decisions,
    })
}

/// Options of [`identical_component_counts`] (both required).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct IdenticalComponentCountsOptions {
    /// The common existence probability r in [0, 1].
    pub existence: f64,
    /// n runs over 1 … `max_components`, an integer in [1, 300] ([`MAX_IDENTICAL_COMPONENTS`]),
    /// as the call costs O(N³ log N) for N = `max_components`.
    pub max_components: usize,
}

/// For each n, the number of targets each rule reports ([`identical_component_counts`]).
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct IdenticalComponentCounts {
    /// The number of identical components n = 1 … `max_components`.
    pub n: Vec<usize>,
    /// The number of targets the optimal GOSPA estimate (α = 2) reports, for each n.
    pub gospa: Vec<usize>,
    /// The number of targets the optimal OSPA estimate reports, for each n.
    pub ospa: Vec<usize>,
    /// The number of targets the optimal UOSPA estimate reports, for each n.
    pub uospa: Vec<usize>,
    /// The number of targets the MAP-cardinality rule reports, for each n.
    pub map_cardinality: Vec<usize>,
}

/// Fig. 3 of `003_…`: the number of reported targets for n = 1 … `max_components` identical
/// far-apart components of existence r, under the optimal GOSPA (α = 2), OSPA and UOSPA
/// estimates (c = 1, p = 2; the counts do not depend on c or p) and the MAP-cardinality rule.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `max_components` outside [1,
/// [`MAX_IDENTICAL_COMPONENTS`]]; [`Error::InvalidProbability`] naming `existence`.
///
/// # Examples
/// ```
/// use fisst::estimators::figures::{identical_component_counts, IdenticalComponentCountsOptions};
/// let k = identical_component_counts(&IdenticalComponentCountsOptions {
///     existence: 0.4,
///     max_components: 3,
/// })?;
/// assert_eq!(k.gospa, vec![0, 0, 0]); // r ≤ 1/2: GOSPA reports nothing, eq. (9)
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn identical_component_counts(
    options: &IdenticalComponentCountsOptions,
) -> Result<IdenticalComponentCounts> {
    let max_n = options.max_components;
    if !(1..=MAX_IDENTICAL_COMPONENTS).contains(&max_n) {
        return Err(Error::parameter(
            "max_components",
            max_n as f64,
            "an integer in [1, 300]",
        ));
    }
    let r = check_probability(|| "existence".into(), options.existence)?;
    let count = |u: &[bool]| u.iter().filter(|&&b| b).count();
    let mut out = IdenticalComponentCounts {
        n: Vec::with_capacity(max_n),
        gospa: Vec::with_capacity(max_n),
        ospa: Vec::with_capacity(max_n),
        uospa: Vec::with_capacity(max_n),
        map_cardinality: Vec::with_capacity(max_n),
    };
    for n in 1..=max_n {
        let rs = vec![r; n];
        let best = |m| optimal_estimate(&rs, m, 1.0, 2.0).map(|e| count(&e.report));
        out.n.push(n);
        out.gospa.push(best(SetMetric::GOSPA)?);
        out.ospa.push(best(SetMetric::Ospa)?);
        out.uospa.push(best(SetMetric::Uospa)?);
        out.map_cardinality
            .push(count(&map_cardinality_estimate(&rs)?));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimators::alternatives::mam_estimate;

    #[test]
    fn fig1_decision_map_cells_are_the_optimal_estimates() {
        for estimator in [
            DecisionEstimator::Gospa,
            DecisionEstimator::Ospa,
            DecisionEstimator::Uospa,
        ] {
            let o = DecisionMapOptions {
                resolution: 7,
                ..DecisionMapOptions::new(estimator)
            };
            let map = decision_map(&o).unwrap();
            assert_eq!(map.resolution, 7);
            assert_eq!(map.decisions.len(), 49);
            let metric = match estimator {
                DecisionEstimator::Gospa => SetMetric::GOSPA,
                DecisionEstimator::Ospa => SetMetric::Ospa,
                _ => SetMetric::Uospa,
            };
            for row in 0..7 {
                for col in 0..7 {
                    let r = [(col as f64 + 0.5) / 7.0, (row as f64 + 0.5) / 7.0];
                    let u = optimal_estimate(&r, metric, 1.0, 2.0).unwrap().report;
                    let code = u8::from(u[0]) + 2 * u8::from(u[1]);
                    assert_eq!(map.decisions[row * 7 + col], code, "{estimator:?} {r:?}");
                }
            }
        }
    }

    #[test]
    fn fig2_decision_map_uses_the_alternatives_with_equal_covariances() {
        let o = DecisionMapOptions {
            resolution: 5,
            c: -1.0, // ignored by the alternatives
            ..DecisionMapOptions::new(DecisionEstimator::Mam)
        };
        let map = decision_map(&o).unwrap();
        let r = [0.9, 0.3];
        let u = mam_estimate(&r, &[0.0, 0.0]).unwrap();
        assert_eq!(map.decisions[5 + 4], u8::from(u[0]) + 2 * u8::from(u[1]));
        let jom = decision_map(&DecisionMapOptions {
            resolution: 5,
            ..DecisionMapOptions::new(DecisionEstimator::Jom)
        })
        .unwrap();
        assert_eq!(jom.decisions[0], 0);
        assert_eq!(jom.decisions[24], 3);
    }

    #[test]
    fn fig1_decision_map_checks_its_options() {
        for resolution in [0, 2001] {
            let e = decision_map(&DecisionMapOptions {
                resolution,
                ..DecisionMapOptions::new(DecisionEstimator::Ospa)
            })
            .unwrap_err();
            assert_eq!(
                alloc::string::ToString::to_string(&e),
                alloc::format!("resolution must be an integer in [1, 2000], got {resolution}")
            );
        }
        let e = decision_map(&DecisionMapOptions {
            alpha: 3.0,
            ..DecisionMapOptions::new(DecisionEstimator::Gospa)
        })
        .unwrap_err();
        assert_eq!(e.field(), "alpha");
    }

    #[test]
    fn fig3_counts_follow_eq9_and_eq11() {
        let k = identical_component_counts(&IdenticalComponentCountsOptions {
            existence: 0.6,
            max_components: 40,
        })
        .unwrap();
        assert_eq!(k.n, (1..=40).collect::<Vec<_>>());
        // (9): GOSPA reports every component with r > 1/2.
        assert_eq!(k.gospa, k.n);
        // (11): OSPA reports all or nothing.
        assert!(k.ospa.iter().zip(&k.n).all(|(&o, &n)| o == 0 || o == n));
        // UOSPA moves one by one and never reports more than n.
        assert!(k.uospa.iter().zip(&k.n).all(|(&u, &n)| u <= n));
        assert!(k.uospa.windows(2).all(|w| w[1] <= w[0] + 1));
        assert_eq!(k.map_cardinality.len(), 40);
    }

    #[test]
    fn fig3_counts_check_their_options() {
        for max_components in [0, MAX_IDENTICAL_COMPONENTS + 1, 1000] {
            let e = identical_component_counts(&IdenticalComponentCountsOptions {
                existence: 0.5,
                max_components,
            })
            .unwrap_err();
            assert_eq!(e.field(), "max_components");
        }
        let e = identical_component_counts(&IdenticalComponentCountsOptions {
            existence: f64::NAN,
            max_components: 3,
        })
        .unwrap_err();
        assert_eq!(e.field(), "existence");
    }
}
