//! The Monte Carlo comparison of the four control schemes (Fig. 3 of paper `004`): the mean
//! OSPA and its localisation and cardinality parts over time, with standard errors.

use alloc::vec;
use alloc::vec::Vec;

use super::case_study::{ControlConfig, ControlRun, Scheme};
use crate::error::Result;
use crate::math::fns::sqrt;
use crate::math::rng::{js_safe_seed, seeded};

/// A mean over runs with its standard error, per time step.
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MeanSeries {
    /// The mean at k = 1 … K.
    pub mean: Vec<f64>,
    /// The sample standard deviation / √runs (0 for one run).
    pub standard_error: Vec<f64>,
}

/// One scheme's averaged errors.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SchemeSummary {
    /// The scheme.
    pub scheme: Scheme,
    /// OSPA (24).
    pub distance: MeanSeries,
    /// Its localisation part (26).
    pub localisation: MeanSeries,
    /// Its cardinality part (25).
    pub cardinality: MeanSeries,
}

/// The OSPA series (distance, localisation, cardinality) of one run of `config` from `seed`.
pub fn run_series(config: &ControlConfig, seed: u64) -> Result<Vec<[f64; 3]>> {
    let mut run = ControlRun::new(config.clone(), seed)?;
    (0..config.steps)
        .map(|_| run.step().map(|s| s.ospa))
        .collect()
}

/// The per-run seeds derived from `seed`: run r of every scheme uses the same seed.
pub fn run_seeds(seed: u64, runs: usize) -> Vec<u64> {
    let mut rng = seeded(seed);
    (0..runs).map(|_| js_safe_seed(&mut rng)).collect()
}

fn summarise(scheme: Scheme, series: &[Vec<[f64; 3]>], steps: usize) -> SchemeSummary {
    let runs = series.len() as f64;
    let part = |p: usize| {
        let mut out = MeanSeries {
            mean: vec![0.0; steps],
            standard_error: vec![0.0; steps],
        };
        for k in 0..steps {
            let m = series.iter().map(|s| s[k][p]).sum::<f64>() / runs;
            let var = if series.len() > 1 {
                series
                    .iter()
                    .map(|s| (s[k][p] - m) * (s[k][p] - m))
                    .sum::<f64>()
                    / (runs - 1.0)
            } else {
                0.0
            };
            out.mean[k] = m;
            out.standard_error[k] = sqrt(var / runs);
        }
        out
    };
    SchemeSummary {
        scheme,
        distance: part(0),
        localisation: part(1),
        cardinality: part(2),
    }
}

/// Runs `runs` seeded runs of `base` (its scheme replaced) for each of `schemes` and averages
/// the OSPA series. `progress(done, total)` is called as runs finish (total = runs ·
/// schemes); an error it returns stops the comparison. With the `parallel` feature the runs
/// go in batches across all cores (progress after each batch); results are identical.
pub fn compare_schemes<E>(
    base: &ControlConfig,
    schemes: &[Scheme],
    runs: usize,
    seed: u64,
    mut progress: impl FnMut(usize, usize) -> core::result::Result<(), E>,
) -> core::result::Result<Vec<SchemeSummary>, E>
where
    E: From<crate::Error>,
{
    base.validate()?;
    let seeds = run_seeds(seed, runs);
    let jobs: Vec<(usize, u64)> = (0..schemes.len())
        .flat_map(|s| seeds.iter().map(move |&r| (s, r)))
        .collect();
    let total = jobs.len();
    let configs: Vec<ControlConfig> = schemes
        .iter()
        .map(|&scheme| ControlConfig {
            scheme,
            ..base.clone()
        })
        .collect();
    let mut results: Vec<Vec<[f64; 3]>> = Vec::with_capacity(total);
    #[cfg(feature = "parallel")]
    let batch = 2 * rayon::current_num_threads();
    #[cfg(not(feature = "parallel"))]
    let batch = 1;
    for chunk in jobs.chunks(batch.max(1)) {
        #[cfg(feature = "parallel")]
        let done: Vec<Result<Vec<[f64; 3]>>> = {
            use rayon::prelude::*;
            chunk
                .par_iter()
                .map(|&(s, r)| run_series(&configs[s], r))
                .collect()
        };
        #[cfg(not(feature = "parallel"))]
        let done: Vec<Result<Vec<[f64; 3]>>> = chunk
            .iter()
            .map(|&(s, r)| run_series(&configs[s], r))
            .collect();
        for d in done {
            results.push(d?);
        }
        progress(results.len(), total)?;
    }
    Ok(schemes
        .iter()
        .enumerate()
        .map(|(s, &scheme)| summarise(scheme, &results[s * runs..(s + 1) * runs], base.steps))
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fig3_summaries_have_the_stated_shape_and_progress_counts() {
        let mut cfg = ControlConfig::paper(Scheme::Random, 3);
        cfg.particles = 50;
        cfg.future_scans = 5;
        let mut calls = Vec::new();
        let out = compare_schemes::<crate::Error>(
            &cfg,
            &[Scheme::Random, Scheme::Fisher],
            3,
            1,
            |d, t| {
                calls.push((d, t));
                Ok(())
            },
        )
        .unwrap();
        assert_eq!(out.len(), 2);
        assert_eq!(out[1].scheme, Scheme::Fisher);
        assert_eq!(out[0].distance.mean.len(), 3);
        assert_eq!(calls.last(), Some(&(6, 6)));
        // The same seed gives the same numbers; the mean is the mean of the runs.
        let seeds = run_seeds(1, 3);
        let series: Vec<Vec<[f64; 3]>> = seeds
            .iter()
            .map(|&s| run_series(&cfg, s).unwrap())
            .collect();
        let m = (series[0][2][0] + series[1][2][0] + series[2][2][0]) / 3.0;
        assert!((out[0].distance.mean[2] - m).abs() < 1e-12);
        for s in &out {
            for k in 0..3 {
                let (d, l, c) = (
                    s.distance.mean[k],
                    s.localisation.mean[k],
                    s.cardinality.mean[k],
                );
                assert!(d <= 100.0 + 1e-9 && l <= d + 1e-9 && c <= d + 1e-9);
            }
        }
    }
}
