//! Reproductions of Narykov, Üney & Ralph, "Optimal Bernoulli point estimation with
//! applications" (`000_…`), Section IV, through the public API: the thresholds printed with
//! Fig. 2, Fig. 2's comparison of the optimal and the conventional (p > 0.5) estimates, and
//! Fig. 3's threshold curves for the r0 and c_M/c_A values the figure shows. All for the
//! paper's Bernoulli-Gaussians, s = N(μ, σ²) in 1D.

use fisst::bernoulli::{
    ApplicationLoss, BernoulliEstimate, Costs, SpatialDensity, estimate, isotropic_threshold_curve,
};

/// Theorem III.3 for a Bernoulli-Gaussian with existence p and s = N(0, σ²).
fn bernoulli_gaussian(p: f64, sigma: f64, r0: f64, costs: Costs) -> BernoulliEstimate {
    let s = SpatialDensity::gaussian_from_slices(&[0.0], &[sigma * sigma]).unwrap();
    estimate(p, &s, &ApplicationLoss::new(costs, r0).unwrap()).unwrap()
}

fn mmol(asset: f64, countermeasure: f64) -> Costs {
    Costs::mmol(asset, countermeasure).unwrap()
}

/// σ = 0.01, 0.02, …, 20.
fn sigma_grid() -> Vec<f64> {
    (1..=2000).map(|i| i as f64 / 100.0).collect()
}

fn increasing(g: &[f64]) -> bool {
    g.windows(2).all(|w| w[1] >= w[0])
}

#[test]
fn fig2_thresholds_to_the_printed_digits() {
    // μ = 0, σ = 1, r0 = 1: Γ1 = 0.5943 for MPE (Fig. 2a) and 0.1628 for MMOL with c_A = 0.9,
    // c_M = 0.1 (Fig. 2b).
    let e = bernoulli_gaussian(0.5, 1.0, 1.0, Costs::mpe());
    assert_eq!(format!("{:.4}", e.threshold.gamma), "0.5943");
    assert_eq!(e.mmuc.center, vec![0.0]); // a* = μ (Sherman's theorem)
    let e = bernoulli_gaussian(0.5, 1.0, 1.0, mmol(0.9, 0.1));
    assert_eq!(format!("{:.4}", e.threshold.gamma), "0.1628");
    // The closed-form curve of Fig. 3 gives the same numbers.
    let g = isotropic_threshold_curve(&[1.0], 1.0, &mmol(0.9, 0.1), 1).unwrap();
    assert_eq!(g[0], e.threshold.gamma);
}

#[test]
fn fig2_optimal_threshold_wins_exactly_between_it_and_one_half() {
    // On p = 0, 1e-4, …, 1: the optimal estimate's expected loss never exceeds that of the
    // conventional rule (report {μ} when p > 0.5); it is strictly lower exactly for p between
    // Γ1 and 0.5 — [0.5, 0.5943] for MPE, [0.1628, 0.5] for MMOL — and equal elsewhere.
    let n = 10_000;
    for (costs, printed) in [(Costs::mpe(), 0.5943), (mmol(0.9, 0.1), 0.1628)] {
        let gamma = bernoulli_gaussian(0.5, 1.0, 1.0, costs).threshold.gamma;
        let (lo, hi) = (gamma.min(0.5), gamma.max(0.5));
        let mut wins = Vec::new();
        for k in 0..=n {
            let p = k as f64 / n as f64;
            let e = bernoulli_gaussian(p, 1.0, 1.0, costs);
            let conventional = if p > 0.5 {
                e.expected_loss_singleton
            } else {
                e.expected_loss_empty
            };
            let optimal = e.expected_loss();
            assert!(optimal <= conventional + 1e-15, "p={p}");
            if optimal < conventional - 1e-12 {
                wins.push(p);
                assert!(lo <= p && p <= hi, "p={p} outside [{lo}, {hi}]");
            } else if p < lo || p > hi {
                assert_eq!(optimal, conventional, "p={p}");
            }
        }
        // One unbroken band from one threshold to the other, to the grid step.
        let step = 1.0 / n as f64;
        assert_eq!(
            wins.len(),
            ((wins[wins.len() - 1] - wins[0]) / step).round() as usize + 1
        );
        assert!(wins[0] - lo <= step + 1e-12 && hi - wins[wins.len() - 1] <= step + 1e-12);
        let band = if printed > 0.5 {
            (0.5, printed)
        } else {
            (printed, 0.5)
        };
        assert!((wins[0] - band.0).abs() < 2e-4, "{} vs {band:?}", wins[0]);
        assert!((wins[wins.len() - 1] - band.1).abs() < 2e-4);
    }
}

#[test]
fn fig3a_mpe_threshold_rises_from_one_half_with_sigma() {
    let sigmas = sigma_grid();
    let curves: Vec<Vec<f64>> = [0.1, 1.0, 3.0, 5.0, 10.0]
        .iter()
        .map(|&r0| isotropic_threshold_curve(&sigmas, r0, &Costs::mpe(), 1).unwrap())
        .collect();
    for (g, r0) in curves.iter().zip([0.1, 1.0, 3.0, 5.0, 10.0]) {
        // Bounded below by 0.5 (p < 0.5 is never reported) and above by 1; higher for more
        // spatial uncertainty, from 0.5 as σ → 0.
        assert!(g.iter().all(|&x| (0.5..1.0).contains(&x)), "r0={r0}");
        assert!(increasing(g) && g[g.len() - 1] > g[0], "r0={r0}");
        assert!(g[0] - 0.5 < 1e-3, "r0={r0}: {}", g[0]);
        // Γ depends on σ/r0 alone: the curve for r0 = 1 rescaled.
        for (i, &s) in sigmas.iter().enumerate().step_by(97) {
            let unit = isotropic_threshold_curve(&[s / r0], 1.0, &Costs::mpe(), 1).unwrap()[0];
            assert!((g[i] - unit).abs() < 1e-14, "r0={r0} σ={s}");
        }
    }
    // A larger tolerance lowers the curve (the figure's ordering).
    for w in curves.windows(2) {
        assert!(w[0].iter().zip(&w[1]).all(|(a, b)| a >= b));
    }
    // "When p > 0.5 it may be estimated as no target in case the uncertainty is high with
    // respect to r0": p = 0.9 with r0 = 1 is reported at σ = 1 and withheld at σ = 10.
    assert!(bernoulli_gaussian(0.9, 1.0, 1.0, Costs::mpe()).declare);
    let e = bernoulli_gaussian(0.9, 10.0, 1.0, Costs::mpe());
    assert!(!e.declare && e.estimate.is_none() && e.threshold.gamma > 0.9);
}

#[test]
fn fig3b_mmol_threshold_is_bounded_below_by_the_cost_ratio() {
    let sigmas = sigma_grid();
    // r0 = 0.1, 1, 3, 5, 10 at c_M/c_A = 0.25 (solid in Fig. 3b).
    let r0s = [0.1, 1.0, 3.0, 5.0, 10.0];
    let curves: Vec<Vec<f64>> = r0s
        .iter()
        .map(|&r0| isotropic_threshold_curve(&sigmas, r0, &mmol(1.0, 0.25), 1).unwrap())
        .collect();
    for (g, r0) in curves.iter().zip(r0s) {
        assert!(g.iter().all(|&x| x >= 0.25) && increasing(g), "r0={r0}");
        assert!(g[0] - 0.25 < 1e-3, "r0={r0}"); // c_M/c_A < 0.5: below the conventional 0.5
        // Γ > 1 (never reported) once q(a*) > 1 − c_M/c_A: within σ ≤ 20 for r0 ≤ 5.
        assert_eq!(g[g.len() - 1] > 1.0, r0 <= 5.0, "r0={r0}");
    }
    for w in curves.windows(2) {
        assert!(w[0].iter().zip(&w[1]).all(|(a, b)| a >= b));
    }
    // c_M/c_A = 0, 0.25, 0.5, 0.75, 1 at r0 = 10 (dotted), with c_A = 0.9.
    let ratios = [0.0, 0.25, 0.5, 0.75, 1.0];
    let curves: Vec<Vec<f64>> = ratios
        .iter()
        .map(|&k| isotropic_threshold_curve(&sigmas, 10.0, &mmol(0.9, 0.9 * k), 1).unwrap())
        .collect();
    for (g, k) in curves.iter().zip(ratios) {
        assert!(
            g.iter().all(|&x| x >= k * (1.0 - 1e-15)) && increasing(g),
            "k={k}"
        );
        assert!((g[0] - k).abs() < 1e-12, "k={k}: {}", g[0]);
    }
    for w in curves.windows(2) {
        assert!(w[0].iter().zip(&w[1]).all(|(a, b)| a < b));
    }
    // c_M = 0: always reported (Γ = 0), even for a tiny p and a wide density.
    assert!(curves[0].iter().all(|&x| x == 0.0));
    let e = bernoulli_gaussian(1e-6, 20.0, 10.0, mmol(0.9, 0.0));
    assert_eq!(e.estimate, Some(vec![0.0]));
    // c_M ≥ c_A: never reported (Γ ≥ 1), even for p = 1 and a narrow density.
    assert!(curves[4].iter().all(|&x| x >= 1.0));
    for cm in [0.9, 1.5] {
        let e = bernoulli_gaussian(1.0, 0.01, 10.0, mmol(0.9, cm));
        assert!(!e.declare && e.estimate.is_none(), "c_M={cm}");
    }
}
