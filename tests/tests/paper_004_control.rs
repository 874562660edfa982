//! Paper 004 (Ristic & Vo), Fig. 3: the four sensor-control schemes over seeded Monte Carlo
//! runs, at a reduced size so that `cargo test` stays quick (N = 200 particles, M = 30 future
//! scans, 24 runs of 25 steps; the paper: N = 750, M = 200, 200 runs; the full size is the
//! `#[ignore]`d test below and `benches/src/bin/control_comparison.rs`).
//!
//! "At the end" is the mean over the last 5 steps (k = 21 … 25) of the run-averaged series,
//! which halves the noise of a single step.

use fisst::control::{ControlOptions, Scheme, SchemeSummary, compare_schemes};

fn tail(s: &[f64]) -> f64 {
    s[s.len() - 5..].iter().sum::<f64>() / 5.0
}

fn comparison(runs: usize, steps: usize, particles: usize, scans: usize) -> Vec<SchemeSummary> {
    let mut cfg = ControlOptions::paper(Scheme::Renyi, steps);
    cfg.particles = particles;
    cfg.future_scans = scans;
    compare_schemes::<fisst::Error>(
        &cfg,
        &[Scheme::Renyi, Scheme::Fisher, Scheme::Pent, Scheme::Random],
        runs,
        2026,
        |_, _| Ok(()),
    )
    .unwrap()
}

fn check_findings(out: &[SchemeSummary]) {
    let end: Vec<(f64, f64, f64)> = out
        .iter()
        .map(|s| {
            (
                tail(&s.distance.mean),
                tail(&s.localisation.mean),
                tail(&s.cardinality.mean),
            )
        })
        .collect();
    for (s, e) in out.iter().zip(&end) {
        println!(
            "{:?}: OSPA {:.1} (se {:.1} at K), localisation {:.1}, cardinality {:.1}",
            s.scheme,
            e.0,
            s.distance.standard_error.last().unwrap(),
            e.1,
            e.2
        );
    }
    let (renyi, fisher, pent, random) = (end[0], end[1], end[2], end[3]);
    // Rényi has the lowest mean OSPA at the end, by at least 5 m against each other scheme.
    for other in [fisher, pent, random] {
        assert!(renyi.0 + 5.0 < other.0, "Rényi {renyi:?} vs {other:?}");
    }
    // Random beats PENT at the end (by any margin: the paper's own gap is small).
    assert!(random.0 < pent.0, "random {random:?} vs PENT {pent:?}");
    // Localisation dominates: for every scheme the localisation part is at least twice the
    // cardinality part.
    for e in &end {
        assert!(e.1 > 2.0 * e.2, "{e:?}");
    }
}

#[test]
fn fig3_findings_at_reduced_size() {
    check_findings(&comparison(24, 25, 200, 30));
}

/// The paper's size: N = 750, M = 200, 200 runs (tens of minutes on two cores).
#[test]
#[ignore]
fn fig3_findings_at_the_paper_size() {
    check_findings(&comparison(200, 40, 750, 200));
}
