//! The computation of the Cortex-M example, as one `no_std` function shared by the firmware
//! (`src/board.rs`, on QEMU's Cortex-M4) and the native build (`src/main.rs`), so that the same
//! code runs on both and `run.sh` can compare their outputs bit for bit.
//!
//! [`run`] writes three results of the core, each f64 as its exact bits (`to_bits`, in hex)
//! beside its shortest decimal:
//! 1. GOSPA (c = 5, p = 2, α = 2) between two small point sets, with its decomposition
//!    (García-Fernández & Svensson, "Spooky effect in optimal OSPA estimation and how GOSPA
//!    solves it", paper `003`, Prop. 3).
//! 2. The spooky effect: the optimal estimates of a multi-Bernoulli with r = (0.4, 0.4) under
//!    OSPA (reports both) and GOSPA (reports neither) (paper `003`, eqs. (9)–(11), Fig. 1).
//! 3. The airport example of paper `001` (Section V-C): 60 steps of the GM Bernoulli filter
//!    (Algorithm 3) on the seeded "near the gate" reports, its estimate at each step and the
//!    final one in full.

#![no_std]

extern crate alloc;

mod peak_alloc;

pub use peak_alloc::PeakAlloc;

use core::fmt::{self, Write};
use fisst::estimators::multi_bernoulli::{SetMetric, optimal_estimate};
use fisst::filters::{EstimateOptions, GmBernoulliFilter};
use fisst::metrics::Gospa;
use fisst::sim::airport::airport_scenario;

/// The seed of the airport scenario (its walk, misses and false reports).
pub const AIRPORT_SEED: u64 = 7;
/// The number of scans of the airport scenario.
pub const AIRPORT_STEPS: usize = 60;

/// Why [`run`] stopped: the core refused an input, or the output could not be written.
#[derive(Debug)]
pub enum RunError {
    /// An error of the core.
    Fisst(fisst::Error),
    /// The writer failed.
    Write,
}

impl From<fisst::Error> for RunError {
    fn from(e: fisst::Error) -> Self {
        RunError::Fisst(e)
    }
}

impl From<fmt::Error> for RunError {
    fn from(_: fmt::Error) -> Self {
        RunError::Write
    }
}

impl fmt::Display for RunError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RunError::Fisst(e) => write!(f, "fisst: {e}"),
            RunError::Write => f.write_str("the output could not be written"),
        }
    }
}

/// Writes `name = <bits in hex> (<value>)`: the bits are what `run.sh` compares, the value
/// (Rust's shortest round-trip decimal) is for reading.
fn number(out: &mut dyn Write, name: &str, x: f64) -> fmt::Result {
    writeln!(out, "{name} = {:016x} ({x})", x.to_bits())
}

/// Runs the three computations and writes their results to `out` (see the module doc).
pub fn run(out: &mut dyn Write) -> Result<(), RunError> {
    // 1. GOSPA between a truth of two points and an estimate of three.
    let truth = [[0.0, 0.0], [10.0, 0.0]];
    let estimate = [[0.5, 0.0], [30.0, 0.0], [40.0, 0.0]];
    let g = Gospa::new(5.0, 2.0, 2.0)?.decompose(&truth, &estimate)?;
    writeln!(out, "GOSPA (c = 5, p = 2, alpha = 2)")?;
    number(out, "  distance", g.distance)?;
    number(out, "  localisation", g.localisation)?;
    writeln!(
        out,
        "  missed = {}, false targets = {}, assignment = {:?}",
        g.missed, g.false_targets, g.assignment
    )?;

    // 2. The spooky effect: two far-apart potential targets, each existing with r = 0.4.
    let r = [0.4, 0.4];
    writeln!(
        out,
        "Optimal multi-Bernoulli estimate, r = {r:?} (c = 1, p = 2)"
    )?;
    for (name, metric) in [("OSPA", SetMetric::Ospa), ("GOSPA", SetMetric::GOSPA)] {
        let best = optimal_estimate(&r, metric, 1.0, 2.0)?;
        writeln!(out, "  {name}: report = {:?}", best.report)?;
        number(out, "    mean error", best.mean_error)?;
    }

    // 3. The airport GM Bernoulli filter: predict, update with the scan's report discs, estimate.
    let scenario = airport_scenario(AIRPORT_SEED, AIRPORT_STEPS)?;
    let mut filter = GmBernoulliFilter::new(scenario.config.clone())?;
    writeln!(
        out,
        "Airport GM Bernoulli filter (seed {AIRPORT_SEED}, {AIRPORT_STEPS} steps): k, reports, existence r, position x, y (m)"
    )?;
    let mut last = None;
    for k in 0..AIRPORT_STEPS {
        filter.predict()?;
        filter.update(&scenario.report_regions(k))?;
        let e = filter.estimate(&EstimateOptions::default())?;
        let (r, x, y) = (e.existence, e.mean[0], e.mean[1]);
        writeln!(
            out,
            "  {k:2} {} {:016x} ({r:.4}) {:016x} ({x:.2}) {:016x} ({y:.2})",
            scenario.reports[k].len(),
            r.to_bits(),
            x.to_bits(),
            y.to_bits()
        )?;
        last = Some(e);
    }
    if let Some(e) = last {
        writeln!(out, "  final estimate")?;
        number(out, "    existence", e.existence)?;
        for (i, m) in e.mean.iter().enumerate() {
            number(out, &alloc::format!("    mean[{i}]"), *m)?;
        }
        for (i, row) in e.cov.iter().enumerate() {
            for (j, c) in row.iter().enumerate() {
                number(out, &alloc::format!("    cov[{i}][{j}]"), *c)?;
            }
        }
    }
    Ok(())
}
