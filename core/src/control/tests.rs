//! Tests of the sensor control: the batched Rényi kernel (17) against its reference and its
//! pinned bits, and a reduced run of Algorithm 1.

use alloc::vec;
use alloc::vec::Vec;

use super::case_study::{ControlOptions, ControlRun, Scheme};
use super::reference::RenyiReference;
use super::renyi_kernel::{FutureScans, SCANS_PER_TASK, renyi_reward, renyi_rewards};
use crate::error::{Error, Phrase};
use crate::math::rng::seeded;
use crate::smc::LikelihoodWorkspace;

/// The four settings of the kernel tests, each after 4 steps of its own seed (11, 12, 13, 14),
/// with 30 future scans drawn from seed 99: the paper's settings (N = 200, M = 30) with noise
/// of 40σ on every third scan (pair factors underflow to 0), n_max = 6 (sets beyond the fixed
/// kernels), α = 1, and σ₀ = 0.1 (factors above 1: the log path).
fn cases() -> Vec<(ControlOptions, ControlRun, FutureScans)> {
    let base = {
        let mut c = ControlOptions::paper(Scheme::Renyi, 6);
        c.particles = 200;
        c.future_scans = 30;
        c
    };
    let mut configs = vec![base.clone(), base.clone(), base.clone(), base];
    configs[1].max_objects = 6;
    configs[2].alpha = 1.0;
    configs[3].sensor.sigma0 = 0.1;
    configs[3].sensor.sigma_slope = 1e-7;
    configs
        .into_iter()
        .enumerate()
        .map(|(ci, cfg)| {
            let mut run = ControlRun::new(cfg.clone(), 11 + ci as u64).unwrap();
            for _ in 0..4 {
                run.step().unwrap();
            }
            let mut scans = FutureScans::draw(
                &run.particles,
                cfg.future_scans,
                cfg.max_objects,
                &mut seeded(99),
            );
            if ci == 0 {
                for (k, e) in scans.noise.iter_mut().enumerate() {
                    if k % 3 == 0 {
                        *e *= 40.0;
                    }
                }
            }
            (cfg, run, scans)
        })
        .collect()
}

/// The batched evaluation of (17) gives the rewards of the plain reference to rounding, in
/// the four settings of [`cases`].
#[test]
fn eq17_renyi_reward_matches_the_reference() {
    let (mut checked, mut differ) = (0usize, 0usize);
    for (ci, (cfg, run, scans)) in cases().iter().enumerate() {
        let reference = RenyiReference::new(cfg, &run.model, &run.particles);
        let from = *run.sensor_path().last().unwrap();
        let mut ws = LikelihoodWorkspace::new();
        for a in cfg.actions.actions(from, &cfg.area) {
            if !a.inside {
                continue;
            }
            let fast = renyi_reward(cfg, &run.model, &run.particles, a.position, scans, &mut ws);
            let exact = reference.reward(a.position, scans);
            assert!(
                (fast - exact).abs() <= 1e-12 * exact.abs().max(1e-300),
                "case {ci}, action {}: {fast} vs {exact}",
                a.index
            );
            assert!(exact > 0.0, "case {ci}: {exact}");
            checked += 1;
            differ += usize::from(fast.to_bits() != exact.to_bits());
        }
    }
    // 11 + 17 + 17 + 10 actions inside the area.
    assert_eq!(checked, 55);
    // The plain path was taken: its rounding differs from the log path's in these many.
    assert_eq!(differ, 41);
}

/// The rewards (17) of every action (−∞ outside the area) in the four settings of [`cases`],
/// as f64 bits: computed by `renyi_rewards` at commit cdd158c (main before the kernel moved
/// to `renyi_kernel.rs`), whose rewards were then also checked bit for bit against the
/// per-particle evaluation of 2caa890 that the batched kernel replaced; re-pinned when the
/// kernel's pair factors moved from libm's exp to [`crate::math::exp`] (issue 29): 12 of
/// the 68 changed, by at most 7.4·10⁻¹⁶ relatively; none changed when that exp became the
/// table method (both round correctly for over 99 % of arguments), and again when the fixed
/// kernels folded their last row into the final sum (`smc/fixed.rs`, issue 29): 14 changed,
/// by at most 7.6·10⁻¹⁶ relatively.
const PINNED: [[u64; 17]; 4] = [
    [
        0x4003_778f_3789_f0dc,
        0x4002_3fb9_129d_fc1f,
        0x4001_a788_3bd0_7e69,
        0x4002_2154_1225_f25c,
        0x4002_b990_a012_204d,
        0xfff0_0000_0000_0000,
        0xfff0_0000_0000_0000,
        0xfff0_0000_0000_0000,
        0x4004_61b6_76cd_176f,
        0x4001_a6ab_a240_a65e,
        0x4000_ae0a_a4e7_53a8,
        0x4000_c8b0_06e5_a5e0,
        0x4002_1c06_5210_644d,
        0xfff0_0000_0000_0000,
        0xfff0_0000_0000_0000,
        0xfff0_0000_0000_0000,
        0x4004_a0d4_a7de_c4e9,
    ],
    [
        0x3fe3_8b7f_6743_56f6,
        0x3fe6_2e49_3c45_7ae5,
        0x3fe6_dda0_d51b_52a6,
        0x3fe5_9ea7_bab8_ee41,
        0x3fe3_7db2_e4dc_ba06,
        0x3fe1_422f_018b_2975,
        0x3fe1_b0c8_5bd2_8e82,
        0x3fe2_aa47_302b_fb32,
        0x3fe3_d657_1ba0_36dc,
        0x3fe8_ce8e_c3ca_e53f,
        0x3fe8_25a3_9c43_bb97,
        0x3fe5_693a_4eed_a140,
        0x3fe3_3111_4bdd_4ac7,
        0x3fde_6b62_132d_1953,
        0x3fe0_b73e_dc93_c1d0,
        0x3fe2_2897_bd7c_7ec2,
        0x3fe4_176c_924c_9037,
    ],
    [
        0x4001_4d45_db7a_5dc6,
        0x4002_dbb0_74ba_cf0d,
        0x4001_14b2_7ed7_ed71,
        0x3ffc_f671_0385_91ba,
        0x3ffc_4e1a_82bd_b7f7,
        0x3ffe_e2ed_b49b_61b1,
        0x4001_858a_ee1c_26e4,
        0x4003_427e_4b90_9963,
        0x4003_a9ef_5b42_bcc3,
        0x4004_8c40_c36f_19c7,
        0x4001_610b_6ec9_742f,
        0x3ffc_d8e2_0e2d_fb1e,
        0x3ff7_7b7e_37e0_f519,
        0x3ffc_4b06_9aa4_a98c,
        0x4001_fb88_88ce_463a,
        0x4005_1fcb_7393_b650,
        0x4006_1e58_4f66_2214,
    ],
    [
        0x4014_f152_1f29_5f9e,
        0x4014_c0b9_c54f_28fc,
        0x4014_e1ce_69d1_36a6,
        0xfff0_0000_0000_0000,
        0xfff0_0000_0000_0000,
        0xfff0_0000_0000_0000,
        0x4014_e723_33b0_5dab,
        0x4014_ce19_4df9_9cae,
        0x4014_e753_a58c_3da9,
        0x4014_f819_9b57_81ef,
        0x4014_dbf0_2450_a38c,
        0xfff0_0000_0000_0000,
        0xfff0_0000_0000_0000,
        0xfff0_0000_0000_0000,
        0xfff0_0000_0000_0000,
        0x4014_97d0_653e_6009,
        0x4014_e60b_a559_9406,
    ],
];

/// The kernel's rewards are the pinned bits (value stability: a change of the float
/// operations or their order shows here).
#[test]
fn eq17_renyi_rewards_are_pinned() {
    for (ci, (cfg, run, scans)) in cases().iter().enumerate() {
        let from = *run.sensor_path().last().unwrap();
        let actions = cfg.actions.actions(from, &cfg.area);
        let rewards = renyi_rewards(cfg, &run.model, &run.particles, &actions, scans);
        let bits: Vec<u64> = rewards.iter().map(|r| r.to_bits()).collect();
        assert_eq!(bits, PINNED[ci], "case {ci}: {rewards:?}");
    }
}

/// The rewards evaluated in tasks of [`SCANS_PER_TASK`] scans (in parallel with
/// `parallel`) are the bits of one [`renyi_reward`] per action.
#[test]
fn eq17_chunked_rewards_are_the_whole_ones() {
    let mut cfg = ControlOptions::paper(Scheme::Renyi, 6);
    cfg.particles = 200;
    cfg.future_scans = 2 * SCANS_PER_TASK + 7;
    let mut run = ControlRun::new(cfg.clone(), 21).unwrap();
    for _ in 0..3 {
        run.step().unwrap();
    }
    let scans = FutureScans::draw(
        &run.particles,
        cfg.future_scans,
        cfg.max_objects,
        &mut seeded(4),
    );
    let from = *run.sensor_path().last().unwrap();
    let actions = cfg.actions.actions(from, &cfg.area);
    let chunked = renyi_rewards(&cfg, &run.model, &run.particles, &actions, &scans);
    let mut ws = LikelihoodWorkspace::new();
    let mut inside = 0;
    for (a, r) in actions.iter().zip(&chunked) {
        if !a.inside {
            assert_eq!(*r, f64::NEG_INFINITY);
            continue;
        }
        let whole = renyi_reward(
            &cfg,
            &run.model,
            &run.particles,
            a.position,
            &scans,
            &mut ws,
        );
        assert_eq!(r.to_bits(), whole.to_bits(), "action {}", a.index);
        inside += 1;
    }
    assert_eq!(inside, 16);
}

/// Algorithm 1 on a reduced case study (N = 300, M = 40, K = 30, seed 5) finds both sources:
/// over the last 10 steps the estimated cardinality is 2 (OSPA cardinality part 0) and the
/// OSPA (c = 100, p = 2) at most 40 m, and at the end each source has an estimate within
/// 45 m.
#[test]
fn alg1_reduced_run_localises_both_sources() {
    let mut cfg = ControlOptions::paper(Scheme::Renyi, 30);
    cfg.particles = 300;
    cfg.future_scans = 40;
    let truth = cfg.truth.clone();
    let mut run = ControlRun::new(cfg, 5).unwrap();
    let mut last = None;
    for k in 1..=30 {
        let s = run.step().unwrap();
        assert_eq!(s.k, k);
        assert_eq!(s.rewards.len(), 17);
        assert!(s.rewards.iter().all(|r| !r.is_nan()));
        std::println!(
            "k={k} n̂={} ospa={:?} x̂={:?}",
            s.estimate.cardinality,
            s.ospa,
            s.estimate.states
        );
        if k > 20 {
            assert_eq!(s.estimate.cardinality, 2, "k={k}");
            assert_eq!(s.ospa.cardinality, 0.0, "k={k}");
            assert!(s.ospa.distance <= 40.0, "k={k}: {:?}", s.ospa);
        }
        last = Some(s);
    }
    let last = last.unwrap();
    for x in &truth {
        let nearest = last
            .estimate
            .states
            .iter()
            .map(|e| libm::hypot(e[0] - x[0], e[1] - x[1]))
            .fold(f64::INFINITY, f64::min);
        assert!(nearest <= 45.0, "{x:?}: {nearest} m");
    }
    assert!(run.step().is_err());
    assert_eq!(run.sensor_path().len(), 31);
}

/// A step after the last one fails naming `step` (the bindings' words) and leaves the run unchanged: particles,
/// path, scans and both random streams (every field, through `Debug`).
#[test]
fn alg1_step_after_the_last_leaves_the_run_unchanged() {
    let mut cfg = ControlOptions::paper(Scheme::Random, 2);
    cfg.particles = 50;
    let mut run = ControlRun::new(cfg, 3).unwrap();
    run.step().unwrap();
    run.step().unwrap();
    let before = alloc::format!("{run:?}");
    let e = run.step().unwrap_err();
    assert_eq!(e.field(), "step");
    assert_eq!(
        alloc::format!("{e}"),
        "step: the run has done all its 2 steps"
    );
    assert_eq!(alloc::format!("{run:?}"), before);
    assert_eq!(run.k(), 2);
}

/// The bindings' caps say their range in the message, with the values of the constants,
/// in the order particles, future_scans, steps, max_objects, then N·M; a second fault
/// (α = 0, checked by `validate`) is reported after them.
#[test]
fn alg1_work_caps_name_the_field_and_the_range() {
    use super::case_study::{
        MAX_FUTURE_SCANS, MAX_MAX_OBJECTS, MAX_PARTICLES, MAX_STEPS, MAX_WORK, WORK_MEASURE,
        work_weight,
    };
    let mut base = ControlOptions::paper(Scheme::Random, 1);
    (base.particles, base.future_scans) = (1, 1);
    assert!(base.check_limits().is_ok());
    type Set = fn(&mut ControlOptions, usize);
    let cases: [(&str, usize, Set); 4] = [
        ("particles", MAX_PARTICLES, |c, v| c.particles = v),
        ("future_scans", MAX_FUTURE_SCANS, |c, v| c.future_scans = v),
        ("steps", MAX_STEPS, |c, v| c.steps = v),
        ("max_objects", MAX_MAX_OBJECTS, |c, v| c.max_objects = v),
    ];
    for (what, max, set) in cases {
        for bad in [0, max + 1] {
            let mut c = base.clone();
            set(&mut c, bad);
            c.alpha = 0.0;
            assert_eq!(c.check_limits(), Err(Error::range(what, bad, 1, max)));
        }
        let mut c = base.clone();
        set(&mut c, max);
        assert!(c.check_limits().is_ok());
    }
    // N·M: after the four ranges, naming M with the largest M within the cap.
    let mut c = base.clone();
    (c.particles, c.future_scans) = (2000, 151);
    let over = Err(Error::form(
        "future_scans",
        false,
        vec![
            Phrase::text(": "),
            Phrase::name(WORK_MEASURE),
            Phrase::text(" must be at most 300000, got 302000"),
        ],
    ));
    assert_eq!(c.check_limits(), over.clone());
    c.steps = 0;
    assert_eq!(c.check_limits().unwrap_err().field(), "steps");
    c.steps = 1;
    c.alpha = 0.0;
    assert_eq!(c.check_limits(), over);
    (c.particles, c.future_scans) = (2000, MAX_WORK / 2000);
    assert!(c.check_limits().is_ok());
    assert_eq!(c.validate().unwrap_err().field(), "alpha");
    // Five objects weigh 4 (a unit costs 2.6 times as much as at four), each one past five
    // doubles it: n_max = 8 allows 1/32 of the scans.
    assert_eq!(
        (1..=8).map(work_weight).collect::<Vec<_>>(),
        [1, 1, 1, 1, 4, 8, 16, 32]
    );
    assert_eq!(work_weight(usize::MAX), usize::MAX);
    c.max_objects = 5;
    (c.particles, c.future_scans) = (1500, 51);
    assert_eq!(c.check_limits().unwrap_err().field(), "future_scans");
    c.future_scans = 50;
    assert!(c.check_limits().is_ok());
    c.max_objects = 8;
    (c.particles, c.future_scans) = (1000, 10);
    let e = c.check_limits().unwrap_err();
    assert_eq!(
        alloc::format!("{e}"),
        "future_scans: particles · future_scans · (max_objects ≤ 4 ? 1 : 2^(max_objects − 3)) must be at most 300000, got 320000"
    );
    let js = e
        .within("options")
        .map_names(|n| n.replace("_scans", "Scans"));
    assert!(alloc::format!("{js}").starts_with("options.future_scans: particles · futureScans"));
    c.future_scans = 9;
    assert!(c.check_limits().is_ok());
}
