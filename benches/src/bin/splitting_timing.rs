//! Native timings of the splitting and reduction code (issue 5): Algorithm 1 per time step of
//! the Fig. 5 scenario of `001_…`, Runnalls' reduction of 1000 components to 100, and the
//! split-library optimiser. Not a test: run it in release mode, from `benches/`,
//!
//! ```text
//! cargo run --release --bin splitting_timing
//! ```
//!
//! and read the medians and minima it prints.

use fisst::mixture::runnalls;
use fisst::splitting::{
    NegativeInformationScenario, Spacing, SplitLibrary, non_detection_update, predict,
    split_for_region,
};
use fisst_benches::{cloud, median_min_us as time_us};

fn main() {
    let sc = NegativeInformationScenario::fig5().unwrap();
    // The predicted mixtures of the three steps (Algorithm 1's inputs).
    let steps = sc.run().unwrap();
    println!("Fig. 5 scenario (R = 3, lambda = 0.001, w_min = 0.01):");
    let mut total = 0.0;
    for s in &steps {
        let (us, min) = time_us(201, || {
            let out = split_for_region(&s.predicted, &sc.fov, &sc.library, &sc.options).unwrap();
            std::hint::black_box(out);
        });
        total += us;
        println!(
            "  step {}: Algorithm 1 median {:>7.1} us, min {:>7.1} us  ({} -> {} components, \
             depth {})",
            s.step,
            us,
            min,
            s.predicted.len(),
            s.split.mixture.len(),
            s.split.depth
        );
    }
    println!(
        "  mean of the medians: {:.1} us",
        total / steps.len() as f64
    );
    let (full, full_min) = time_us(101, || {
        let mut post = sc.initial.clone();
        for _ in 0..sc.steps {
            let pred = predict(&post, &sc.transition, &sc.process_noise).unwrap();
            let split = split_for_region(&pred, &sc.fov, &sc.library, &sc.options).unwrap();
            post = non_detection_update(&split.mixture, &sc.fov, 1.0)
                .unwrap()
                .0;
        }
        std::hint::black_box(post);
    });
    println!("  predict + split + update, 3 steps: median {full:.1} us, min {full_min:.1} us");

    let big = cloud(1000);
    let (us, min) = time_us(11, || {
        std::hint::black_box(runnalls(&big, 100).unwrap());
    });
    println!(
        "Runnalls 1000 -> 100 components (4D): median {:.1} ms, min {:.1} ms",
        us / 1000.0,
        min / 1000.0
    );

    for (r, spacing) in [
        (3, Spacing::Equal),
        (4, Spacing::Equal),
        (4, Spacing::Free),
        (8, Spacing::Free),
    ] {
        let (us, min) = time_us(11, || {
            std::hint::black_box(SplitLibrary::optimise(r, 0.001, spacing).unwrap());
        });
        println!(
            "SplitLibrary::optimise({r}, 0.001, {spacing:?}): median {:.2} ms, min {:.2} ms",
            us / 1000.0,
            min / 1000.0
        );
    }
}
