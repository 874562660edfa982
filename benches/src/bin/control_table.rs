//! Every sensor-control step a user waits for (issue 29, goal 2; paper 004, Algorithm 1 with
//! the Rényi reward (17) at the paper's size, N = 750, M = 200, 17 actions): the first `steps`
//! steps of each seed in `seeds`, each step timed on its own, on one thread.
//!
//! `RAYON_NUM_THREADS=1 target/release/control_table [first_seed=1] [last_seed=10] [steps=12]`
//!
//! Prints one row per seed (ms per step), the worst and the mean step, the load average, and a
//! checksum of every step's rewards and action and one of the actions alone (FNV-1a over their bits) to show that a change
//! left the numbers as they were. `benches/control_node.mjs table` prints the same table
//! through the npm package in Node. For instruction counts run it under
//! `valgrind --tool=callgrind` with a single seed and few steps (`control_table 1 1 2` counts
//! seed 1's steps 1–2 and the set-up). Not `--toggle-collect='*timed_step*'`: even with one
//! thread the rewards run on rayon's worker thread, whose stack has no `timed_step`, so that
//! counts almost nothing.
//!
//! Measured (issue 29, 2026-12-04, load average 5–6 from three builds): seeds 1–10, steps
//! 1–12, one native thread: worst 402–476 ms (seed 1, step 4), mean 91–124 ms; seed 1's first
//! four steps are 18.2e9 instructions (callgrind), 40 % in the subset sum over matchings
//! (`smc::matchings`), 27 % in the kernel's exps (perf, line tables). Two inline exps were
//! tried in the kernel and measured no faster (so not kept): fdlibm's steps with selects
//! (libm's bits: 18.9e9 Ir) and a degree-13 Taylor polynomial without division (≤ 0.87 ulp,
//! the actions of all 120 steps unchanged: 17.7e9 Ir, 18.4e9 with the range test hoisted);
//! rustc leaves the kernel's exp loop scalar (no `mulpd`) though the same loop alone
//! vectorises.
//!
//! After the batch kernel of (20) took n, m ≤ 4 unrolled, four particles as lanes (h-control,
//! same checksums: rewards and actions bit for bit): seed 1's steps 1–2 are 2.45e9
//! instructions instead of 8.25e9 and the whole table (seeds 1–10, steps 1–12) 90.5e9 instead
//! of 108.5e9 (callgrind, whole program), of which 10.1e9 in the subset sum
//! (`BatchLikelihood::scaled_likelihoods`), the rest in the kernel around it, mostly its exps
//! (perf: the subset sum ~15 % of seed 1's steps 1–4 and ~7 % of seed 9's, exp 50–60 %).
//! The 40 % above was `dp_row` inlined into the batch's tables for n = m = 4, which had no
//! unrolled kernel; `ln_sum_matchings` itself is under 1 %. Seeds 1–10, steps 1–12, load
//! average 4.4–4.8 on 2 cores: worst 199–306 ms, mean 66–108 ms (before, same conditions:
//! worst 506–592 ms, mean 88–110 ms).
//!
//! After the kernel's exps moved to `math::exp::exp_kernel` (h-exp: branch-free, the
//! arguments above the cut packed and the exp loop vectorised, two SSE2 lanes; Estrin rather
//! than Horner, which left the loop bound by latency and no faster than libm): seeds 1–10,
//! steps 1–12, one native thread, load average 1.2–1.7 (other helpers building), run
//! alternately with the previous binary: worst 120–121 ms, mean 44.7–45.5 ms (before:
//! worst 148–198 ms, mean 54.0–56.1 ms); `control_table 1 3 12` 1.59–1.63 s of user time
//! instead of 1.98–2.03 s. Checksums: rewards and actions e74298192fb1b66d (was
//! 16638fc83d394cc3: the rewards' last bits), actions d0cbc2f3b0c64a8c (unchanged); the same
//! in Node. Seed 1's steps 1–4 and the set-up (`control_table 1 1 4` under callgrind) are
//! 5.81e9 instructions instead of 6.07e9: the gain is mostly in latency (libm's exp has a
//! division and branches; the Horner form of the new one, as many instructions, gained 4 %).
//!
//! Where the rest goes (2026-12-05, 422dfaa, load average 0.6–1.0; one native thread: worst
//! 122.8–125.9 ms, mean 44.2–44.8 ms; Node: worst 158–168 ms, mean 51.3–55.0 ms), each by a
//! temporary change, none kept:
//! - seed 1's steps 1–4 are 5.0 M of their 6.9 M (particle, scan) evaluations with four
//!   objects and four measurements, 16 pairs each;
//! - below the kernel's cut (no exp): 36 % of the pairs of seeds 1–10 (50 % in seed 1's
//!   steps 1–6); of those above (exponents up to 52 above the cut), half are in the top 4
//!   (48–52 above it; a third in seed 1's steps 1–6), then 15 % at 44–48, 8 % at 40–44,
//!   thinning to 1.5 % at 0–4;
//! - an exp costing almost nothing (a 6-flop stand-in with wrong values) makes the table's
//!   worst 74 ms and mean 23.7 ms: the exps are about half of the time, the pairs' exponents
//!   and the subset sum the other half; a table-driven 1-ulp exp would save about a third of
//!   an exp's 53 operations, ≈ 15 % of a step;
//! - replacing a particle's likelihood by its all-missed floor when its excess is below
//!   10⁻¹⁷ of Σ w T (and of Σ w √T) would spare 0.14 % of the pairs: the particles are tight
//!   against σ;
//! - every pair's exp in one fused loop with a select instead of packing those above the cut
//!   (the same bits): 3–7 % slower.
//!
//! After the kernel's pairs went in blocks of 16 (2026-12-05, issue 29: each block's
//! exponents counted against the cut, then zeroed, one exp loop, or packed; 26 % of the blocks
//! have no pair above the cut, 50 % all, 24 % some; the same checksums), element-wise minimum
//! of two runs, alternately with the binary before, load average 1.0: worst 118.9–120.1 ms,
//! mean 40.2–40.4 ms (before: worst 132.7–139.7, mean 48.9–50.7); in Node (minimum of three
//! runs of `benches/control_node.mjs table`) worst 163.3 ms, mean 50.3 ms (before: 200.1,
//! 59.6). Ordering each cardinality group's particles by the range of their first object, so
//! that a block holds neighbours, changed neither (native 122.6–129.1 / 41.4–42.9, Node
//! 168.1 / 50.3): not kept.
//!
//! After the kernel's exp became Tang's table method (`math::exp::exp_kernel_lanes`: 2^{i/32}
//! from a table, a degree-6 polynomial, three passes over a block of 16 so that two of them
//! vectorise; 31 operations instead of 56), 2026-12-05, load average 1.1, minimum of two runs
//! each: worst 90.8 ms, mean 30.3 ms (the blocked polynomial exp just before: 128.6, 41.9);
//! Node (`benches/control_node.mjs table`, minimum of three): worst 154.6 ms, mean 44.8 ms
//! (before: 175.9, 51.3). Checksums: rewards and actions eaacc73d9ac9e257 (the rewards' last
//! bits), actions d0cbc2f3b0c64a8c (unchanged); the same in Node. In Node the table loads are
//! dear: with every load from entry 0 (wrong values) the table is 148.8 / 40.0 ms. Where
//! seed 1's steps 1–4 go now (perf natively; `node --cpu-prof` in Node, by wasm function):
//! the exps 31 % (Node 24 %), the exponents and packing 33 % (31 %), the subset sum
//! (`BatchLikelihood::scaled_likelihoods`) 30 % (37 %).
//!
//! After the table's pairs became one 16-byte entry and the fixed kernels of the subset sum
//! folded their last row into the final sum (`smc/fixed.rs`, with the objects as the columns:
//! Σ_S miss^{n−|S|−1}·dp[S]·(κ·miss + Σ_{c∉S} f_c) instead of a row of subset updates and a
//! product per subset), 2026-12-05, with a fresh-clone `make test` running beside it (load
//! average 3.3–3.5), alternately with the binary and package before: seed 1's steps 1–6 407
//! against 435 ms of CPU time natively; Node, minimum of two runs each: worst 135.3–139.0 ms,
//! mean 40.7–42.9 ms (before: 156.4–162.2, 42.7–46.8). Checksums b4bf0a7f0c9297b2 (rewards'
//! last bits; 14 of the 68 pinned rewards of `control/tests.rs` moved, by at most 7.6·10⁻¹⁶
//! relatively) and d0cbc2f3b0c64a8c (actions unchanged), the same in Node.
//!
//! The session's end (2026-12-05, c4b4953 against 7dc61c3, idle machine, load average
//! 0.6–1.2; element-wise minimum of two native and three Node runs): one native thread worst
//! 139.5 → 90.2 ms, mean 49.9 → 28.9 ms; Node worst 195.6 → 142.9 ms, mean 61.5 → 42.5 ms;
//! Node/native 1.58 (worst), 1.47 (mean). In Node only seed 1's steps 4–6 (142.9, 115.4,
//! 121.6 ms) are above 100 ms. The worst step (seed 1, step 4) is 1.53e9 instructions
//! natively (callgrind: `control_table 1 1 4` less `control_table 1 1 3`), 2.11e9 before.
use fisst::control::{ControlOptions, ControlRun, Scheme, StepOutcome};
use std::hint::black_box;
use std::time::Instant;

#[inline(never)]
fn timed_step(run: &mut ControlRun) -> StepOutcome {
    black_box(run.step().unwrap())
}

fn fnv(hash: &mut u64, bits: u64) {
    for byte in bits.to_le_bytes() {
        *hash ^= byte as u64;
        *hash = hash.wrapping_mul(0x100_0000_01b3);
    }
}

fn main() {
    let args: Vec<u64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("integer arguments"))
        .collect();
    let get = |i: usize, d: u64| args.get(i).copied().unwrap_or(d);
    let (first, last, steps) = (get(0, 1), get(1, 10), get(2, 12) as usize);
    let mut hash = 0xcbf2_9ce4_8422_2325u64;
    let mut actions_hash = hash;
    let mut all = Vec::new();
    println!("paper 004, Renyi scheme, N = 750, M = 200: ms per step (one thread)");
    for seed in first..=last {
        let mut run = ControlRun::new(ControlOptions::paper(Scheme::Renyi, 1000), seed).unwrap();
        let mut row = Vec::with_capacity(steps);
        for _ in 0..steps {
            let t = Instant::now();
            let out = timed_step(&mut run);
            row.push(t.elapsed().as_secs_f64() * 1e3);
            for r in &out.rewards {
                fnv(&mut hash, r.to_bits());
            }
            fnv(&mut hash, out.action.index as u64);
            fnv(&mut actions_hash, out.action.index as u64);
        }
        let cells: Vec<String> = row.iter().map(|ms| format!("{ms:6.1}")).collect();
        println!("seed {seed:>2}: {}", cells.join(" "));
        all.extend(row);
    }
    let worst = all.iter().cloned().fold(0.0, f64::max);
    let mean = all.iter().sum::<f64>() / all.len() as f64;
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "worst {worst:.1} ms, mean {mean:.1} ms over {} steps; load average {}",
        all.len(),
        load.split_whitespace().next().unwrap_or("?")
    );
    println!("checksum of rewards and actions: {hash:016x}; of the actions: {actions_hash:016x}");
}
