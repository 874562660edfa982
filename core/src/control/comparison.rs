//! The Monte Carlo comparison of the four control schemes (Fig. 3 of paper `004`): the mean
//! OSPA and its localisation and cardinality parts over time, with standard errors.

use alloc::vec;
use alloc::vec::Vec;

use super::case_study::{ControlOptions, ControlRun, Scheme};
use crate::error::{Error, Result};
use crate::math::fns::sqrt;
use crate::math::rng::{js_safe_seed, seeded};
use crate::smc::State;

/// The cap on the runs per scheme of [`CompareOptions`].
pub const MAX_RUNS: usize = 1_000;
/// The cap on the number of schemes of [`CompareOptions`].
pub const MAX_SCHEMES: usize = 16;

/// Options of the comparison of Fig. 3 of Ristic & Vo, "Sensor control for multi-object state-space estimation using random finite sets" (paper 004): `runs` seeded runs of each scheme of the case study,
/// averaged (the rest as in [`ControlOptions`]).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CompareOptions {
    /// The number of Monte Carlo runs per scheme (1 … 1,000).
    pub runs: usize,
    /// The number K of steps of each run (1 … 1,000).
    pub steps: usize,
    /// The master seed; run r of every scheme uses the same derived seed ([`run_seeds`]).
    /// Omitted: entropy (a binding draws it).
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub seed: Option<u64>,
    /// The control schemes to compare (default all four: renyi, fisher, pent, random; 1 … 16 of them).
    #[cfg_attr(feature = "serde", serde(default = "CompareOptions::default_schemes"))]
    pub schemes: Vec<Scheme>,
    /// The number N of multi-object particles (default 750; 1 … 20,000).
    #[cfg_attr(
        feature = "serde",
        serde(default = "crate::control::ControlOptions::default_particles")
    )]
    pub particles: usize,
    /// The number M of ideal future scans per Rényi reward (default 200; 1 … 2,000).
    #[cfg_attr(
        feature = "serde",
        serde(default = "crate::control::ControlOptions::default_future_scans")
    )]
    pub future_scans: usize,
    /// The order α > 0 of the Rényi divergence (default 0.5; 1 is the Kullback–Leibler
    /// divergence).
    #[cfg_attr(
        feature = "serde",
        serde(default = "crate::control::ControlOptions::default_alpha")
    )]
    pub alpha: f64,
    /// The sensor's initial location [x, y] in m (default [0, 0]).
    #[cfg_attr(
        feature = "serde",
        serde(default = "crate::control::ControlOptions::default_start")
    )]
    pub start: State,
    /// The largest number n_max of objects in a particle (default 4; 1 … 8).
    #[cfg_attr(
        feature = "serde",
        serde(default = "crate::control::ControlOptions::default_max_objects")
    )]
    pub max_objects: usize,
}

impl CompareOptions {
    /// All four schemes, in the order of Fig. 3.
    pub fn default_schemes() -> Vec<Scheme> {
        Scheme::ALL.to_vec()
    }

    /// The options of one run (its scheme [`Scheme::Random`], replaced per scheme; no seed).
    pub fn run_options(&self) -> ControlOptions {
        ControlOptions {
            particles: self.particles,
            future_scans: self.future_scans,
            alpha: self.alpha,
            start: self.start,
            max_objects: self.max_objects,
            ..ControlOptions::paper(Scheme::Random, self.steps)
        }
    }

    /// The bindings' caps, then the run options' ([`ControlOptions::check_limits`] and
    /// [`ControlOptions::validate`]).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `runs` (1 … [`MAX_RUNS`]) or `schemes.length`
    /// (1 … [`MAX_SCHEMES`]), or the run options' errors.
    pub fn check(&self) -> Result<()> {
        Error::check_range("runs", self.runs, 1, MAX_RUNS)?;
        Error::check_range("schemes.length", self.schemes.len(), 1, MAX_SCHEMES)?;
        let run = self.run_options();
        run.check_limits()?;
        run.validate()
    }

    /// Checks the options ([`CompareOptions::check`]) and runs the comparison from `seed`
    /// ([`compare_schemes`]; `progress` as there).
    ///
    /// # Errors
    /// The options' errors, the runs', or the one `progress` returns.
    pub fn compare<E: From<Error>>(
        &self,
        seed: u64,
        progress: impl FnMut(usize, usize) -> core::result::Result<(), E>,
    ) -> core::result::Result<Comparison, E> {
        self.check()?;
        let schemes = compare_schemes(
            &self.run_options(),
            &self.schemes,
            self.runs,
            seed,
            progress,
        )?;
        Ok(Comparison {
            seed,
            run_seeds: run_seeds(seed, self.runs),
            runs: self.runs,
            steps: self.steps,
            schemes,
        })
    }
}

/// The result of the comparison of Fig. 3 of Ristic & Vo, "Sensor control for multi-object
/// state-space estimation using random finite sets" (paper 004): each scheme's OSPA errors averaged
/// over the runs.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Comparison {
    /// The master seed used (the option's, or the fresh one drawn).
    pub seed: u64,
    /// The seed of run r (the same for every scheme; 53-bit integers): a run of the case
    /// study seeded with it, with the same options and scheme, repeats that run exactly.
    pub run_seeds: Vec<u64>,
    /// The number of Monte Carlo runs per scheme.
    pub runs: usize,
    /// The number K of steps of each run.
    pub steps: usize,
    /// One entry per requested scheme, in order.
    pub schemes: Vec<SchemeSummary>,
}

/// A mean over runs per step, with its standard error (sample sd / √runs; 0 for one run).
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MeanSeries {
    /// The mean over the runs at each step k = 1 … K.
    pub mean: Vec<f64>,
    /// The standard error of that mean at each step k = 1 … K.
    pub standard_error: Vec<f64>,
}

/// One scheme's OSPA errors (eqs. (24)–(26) of Ristic & Vo, "Sensor control for multi-object state-space estimation using random finite sets", paper 004) averaged over the runs, per step.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SchemeSummary {
    /// The control scheme.
    pub scheme: Scheme,
    /// The OSPA distance (24) (c = 100 m, p = 2), in m.
    pub distance: MeanSeries,
    /// The OSPA localisation part (26), in m.
    pub localisation: MeanSeries,
    /// The OSPA cardinality part (25), in m.
    pub cardinality: MeanSeries,
}

/// The OSPA series (distance, localisation, cardinality) of one run of `config` from `seed`.
pub fn run_series(config: &ControlOptions, seed: u64) -> Result<Vec<[f64; 3]>> {
    let mut run = ControlRun::new(config.clone(), seed)?;
    (0..config.steps)
        .map(|_| run.step().map(|s| s.ospa.to_array()))
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
    base: &ControlOptions,
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
    let configs: Vec<ControlOptions> = schemes
        .iter()
        .map(|&scheme| ControlOptions {
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
    use alloc::string::ToString;

    #[test]
    fn fig3_summaries_have_the_stated_shape_and_progress_counts() {
        let mut cfg = ControlOptions::paper(Scheme::Random, 3);
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

    /// The options' checks in the npm package's order: runs, the number of schemes, then the
    /// run's caps and values; `compare` returns the seeds and the summaries of
    /// `compare_schemes`.
    #[test]
    fn fig3_options_check_runs_schemes_and_the_run_caps() {
        let ok = CompareOptions {
            runs: 2,
            steps: 2,
            seed: None,
            schemes: alloc::vec![Scheme::Random],
            particles: 30,
            future_scans: 2,
            alpha: 0.5,
            start: [0.0, 0.0],
            max_objects: 4,
        };
        let out = ok.compare::<Error>(5, |_, _| Ok(())).unwrap();
        assert_eq!((out.seed, out.runs, out.steps), (5, 2, 2));
        assert_eq!(out.run_seeds, run_seeds(5, 2));
        let direct =
            compare_schemes::<Error>(&ok.run_options(), &ok.schemes, 2, 5, |_, _| Ok(())).unwrap();
        assert_eq!(out.schemes, direct);
        let field = |o: &CompareOptions| o.check().unwrap_err().field().to_string();
        let with = |f: fn(&mut CompareOptions)| {
            let mut o = ok.clone();
            f(&mut o);
            o
        };
        type Change = fn(&mut CompareOptions);
        let cases: [(Change, &str); 6] = [
            (
                |o| (o.runs, o.steps, o.schemes) = (0, 0, alloc::vec![]),
                "runs",
            ),
            (|o| o.runs = MAX_RUNS + 1, "runs"),
            (
                |o| (o.steps, o.schemes) = (0, alloc::vec![]),
                "schemes.length",
            ),
            (
                |o| o.schemes = alloc::vec![Scheme::Pent; 17],
                "schemes.length",
            ),
            (|o| (o.steps, o.alpha) = (0, 0.0), "steps"),
            (
                |o| (o.particles, o.future_scans, o.alpha) = (2000, 501, 0.0),
                "future_scans",
            ),
        ];
        for (f, what) in cases {
            assert_eq!(field(&with(f)), what);
        }
        assert_eq!(field(&with(|o| o.alpha = 0.0)), "alpha");
        assert_eq!(CompareOptions::default_schemes(), Scheme::ALL.to_vec());
    }
}
