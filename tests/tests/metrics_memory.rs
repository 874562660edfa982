//! OSPA/GOSPA never allocate `O(|X|·|Y|)` for Euclidean points: peak heap use measured with a
//! counting global allocator (issue 15). The scene that aborted the wasm module before
//! (20,000 truths and 20,000 estimates at the percolating density, whose full distance matrix
//! is 3.2 GB) must run in a few MB, and an input over `MAX_CLOSE_PAIRS` must fail before
//! storing its pairs.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use fisst::metrics::{Gospa, MAX_CLOSE_PAIRS, Ospa};
use fisst_tests::Lcg;

struct Counting;

static CURRENT: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);
/// The tests of this file measure one at a time.
static SERIAL: Mutex<()> = Mutex::new(());

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let now = CURRENT.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
            PEAK.fetch_max(now, Ordering::Relaxed);
        }
        p
    }

    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        unsafe { System.dealloc(p, layout) };
        CURRENT.fetch_sub(layout.size(), Ordering::Relaxed);
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Peak heap bytes allocated by `f` above what was allocated before it.
fn peak_during<T>(f: impl FnOnce() -> T) -> (T, usize) {
    let base = CURRENT.load(Ordering::Relaxed);
    PEAK.store(base, Ordering::Relaxed);
    let out = f();
    (out, PEAK.load(Ordering::Relaxed) - base)
}

/// Issue 15's percolating scene at n points: truths uniform in a square of side
/// 100·√(n/1000), 90 % detected within ±1.7 (uniform noise), 10 % uniform clutter.
fn percolating(n: usize, seed: u64) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let mut rng = Lcg::new(seed);
    let side = 100.0 * (n as f64 / 1000.0).sqrt();
    let truth: Vec<[f64; 2]> = (0..n)
        .map(|_| [side * rng.uniform(), side * rng.uniform()])
        .collect();
    let mut estimate: Vec<[f64; 2]> = truth[..n * 9 / 10]
        .iter()
        .map(|t| {
            [
                t[0] + 3.4 * (rng.uniform() - 0.5),
                t[1] + 3.4 * (rng.uniform() - 0.5),
            ]
        })
        .collect();
    estimate.extend((0..n / 10).map(|_| [side * rng.uniform(), side * rng.uniform()]));
    (truth, estimate)
}

#[test]
fn twenty_thousand_percolating_points_take_megabytes_not_gigabytes() {
    let _serial = SERIAL.lock().unwrap();
    let (x, y) = percolating(20_000, 15);
    let g = Gospa::new(5.0, 2.0, 2.0).unwrap();
    let (d, peak) = peak_during(|| g.decompose(&x, &y).unwrap());
    // The full distance matrix would be 20,000² · 8 B = 3.2 GB; the pairs closer than c
    // (~8 per point, 12 B each) and the O(n + m) arrays take a few MB.
    assert!(peak < 24 << 20, "peak heap {peak} bytes");
    assert!(d.missed > 0 && d.false_targets > 0 && d.assignment.len() > 15_000);
    let (o, peak) = peak_during(|| Ospa::new(5.0, 2.0).unwrap().distance(&x, &y).unwrap());
    assert!(peak < 24 << 20, "peak heap {peak} bytes");
    assert!(o > 0.0 && o < 5.0);
}

#[test]
fn over_the_cap_fails_before_storing_the_pairs() {
    let _serial = SERIAL.lock().unwrap();
    // n² just above the cap, all pairs within c: the count runs without storing anything.
    let n = (MAX_CLOSE_PAIRS as f64).sqrt() as usize + 1;
    let x: Vec<[f64; 1]> = (0..n).map(|i| [i as f64 * 1e-3]).collect();
    let g = Gospa::new(1e6, 1.0, 2.0).unwrap();
    let (e, peak) = peak_during(|| g.distance(&x, &x).unwrap_err());
    assert_eq!(e.field(), "truth × estimate pairs closer than c");
    assert!(e.to_string().contains(&format!("got {}", n * n)), "{e}");
    assert!(peak < 4 << 20, "peak heap {peak} bytes");
}
