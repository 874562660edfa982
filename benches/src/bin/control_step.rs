//! One Rényi control step of paper 004 at the paper's size (N = 750, M = 200, 17 actions)
//! after 5 warm-up steps, as in `benches/control.rs` (`control_step/renyi`), for instruction
//! counts: only `timed_step` is counted with
//!
//! `RAYON_NUM_THREADS=1 valgrind --tool=callgrind --toggle-collect='*timed_step*' target/release/control_step [particles=750] [futureScans=200] [steps=1]`
//!
//! It prints the rewards (to check that a change left the numbers as they were) and the time.
use fisst::control::{ControlOptions, ControlRun, Scheme, StepOutcome};
use std::hint::black_box;
use std::time::Instant;

#[inline(never)]
fn timed_step(run: &mut ControlRun) -> StepOutcome {
    black_box(run.step().unwrap())
}

fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("integer arguments"))
        .collect();
    let get = |i: usize, d: usize| args.get(i).copied().unwrap_or(d);
    let (particles, scans, steps) = (get(0, 750), get(1, 200), get(2, 1));
    let mut cfg = ControlOptions::paper(Scheme::Renyi, 1000);
    cfg.particles = particles;
    cfg.future_scans = scans;
    let mut run = ControlRun::new(cfg, 3).unwrap();
    for _ in 0..5 {
        run.step().unwrap();
    }
    for _ in 0..steps {
        let t = Instant::now();
        let out = timed_step(&mut run);
        let ms = t.elapsed().as_secs_f64() * 1e3;
        println!("k={} {ms:.1} ms action={}", out.k, out.action.index);
        for r in &out.rewards {
            println!("{r:?}");
        }
    }
}
