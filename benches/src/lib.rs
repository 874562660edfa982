//! Shared inputs and timers for the benchmarks and the timing programs in `src/bin/`: seeded
//! point sets like a tracker's output, a 4D mixture, median wall times.

use fisst::gaussian::{Gaussian, GaussianMixture};
use fisst::math::rng::SplitMix64;

/// The core's portable SplitMix64 stream ([`fisst::math::rng::SplitMix64`]), with the
/// normal draws the benchmark inputs need.
pub struct SplitMix(SplitMix64);

impl SplitMix {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        Self(SplitMix64::new(seed))
    }

    /// A uniform draw in [0, 1) (the top 53 bits of the next output).
    pub fn uniform(&mut self) -> f64 {
        self.0.uniform()
    }

    /// A standard normal draw (Box–Muller).
    pub fn normal(&mut self) -> f64 {
        let u = 1.0 - self.uniform();
        let v = self.uniform();
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

/// n truth points uniform in a square of side 10·√n (constant density), and an estimate with
/// 90 % of them detected (Gaussian-ish noise of scale 1) plus 10 % clutter: the shape of a
/// tracker's output scored with GOSPA (c = 5).
pub fn scene(n: usize, seed: u64) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let mut rng = SplitMix::new(seed);
    let side = 10.0 * (n as f64).sqrt();
    let truth: Vec<[f64; 2]> = (0..n)
        .map(|_| [side * rng.uniform(), side * rng.uniform()])
        .collect();
    let mut estimate = Vec::with_capacity(n);
    for t in &truth {
        if rng.uniform() < 0.9 {
            let noise = |r: &mut SplitMix| (r.uniform() + r.uniform() + r.uniform() - 1.5) * 2.0;
            estimate.push([t[0] + noise(&mut rng), t[1] + noise(&mut rng)]);
        }
    }
    for _ in 0..n / 10 {
        estimate.push([side * rng.uniform(), side * rng.uniform()]);
    }
    (truth, estimate)
}

/// The median wall time in seconds of `reps` calls of `f` (`reps` ≥ 1), and the last result.
pub fn median_time<T>(reps: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let (seconds, out) = times(reps, &mut f);
    (seconds[seconds.len() / 2], out)
}

/// The median and the minimum wall time in microseconds of `reps` calls of `f` (`reps` ≥ 1;
/// the minimum is the robust figure on a shared machine).
pub fn median_min_us(reps: usize, mut f: impl FnMut()) -> (f64, f64) {
    let (seconds, ()) = times(reps, &mut f);
    (seconds[seconds.len() / 2] * 1e6, seconds[0] * 1e6)
}

/// The sorted wall times in seconds of `reps` calls of `f`, and the last result.
fn times<T>(reps: usize, f: &mut impl FnMut() -> T) -> (Vec<f64>, T) {
    assert!(reps >= 1, "at least one repetition");
    let mut seconds = Vec::with_capacity(reps);
    let mut out = None;
    for _ in 0..reps {
        let t0 = std::time::Instant::now();
        out = Some(f());
        seconds.push(t0.elapsed().as_secs_f64());
    }
    seconds.sort_by(f64::total_cmp);
    (seconds, out.expect("reps >= 1"))
}

/// A deterministic 4D mixture of `n` components (a Weyl sequence, no RNG): the input of the
/// Runnalls benchmarks.
pub fn cloud(n: usize) -> GaussianMixture {
    let frac = |x: f64| x - x.floor();
    let comps = (0..n)
        .map(|i| {
            let t = i as f64;
            let m = [
                10.0 * frac(t * 0.618_033_988_75),
                10.0 * frac(t * 0.414_213_562_37),
                frac(t * 0.732_050_807_57) - 0.5,
                frac(t * 0.236_067_977_5) - 0.5,
            ];
            let s = 0.2 + 0.3 * frac(t * 0.302_775_637_73);
            let c = 0.3 * s * s * (frac(t * 0.577_215_664_9) - 0.5);
            #[rustfmt::skip]
            let p = [
                s * s, c, 0.0, 0.0,
                c, s * s, 0.0, 0.0,
                0.0, 0.0, 0.04, 0.0,
                0.0, 0.0, 0.0, 0.04,
            ];
            (
                0.5 + frac(t * 0.141_421_356_2),
                Gaussian::from_slices(&m, &p, "cloud").unwrap(),
            )
        })
        .collect();
    GaussianMixture::new(comps, "cloud").unwrap()
}

/// The percolating scene of issue 15: n truths uniform in a square of side 100·√(n/1000)
/// (1,000 in [0, 100]², density 0.1), 90 % of them with an estimate within σ = 1 (Gaussian
/// noise per coordinate) plus 10 % uniform estimates. With c = 5 the "closer than c" graph
/// has a giant component (each point has ~8 others within c).
pub fn percolating_scene(n: usize, seed: u64) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let mut rng = SplitMix::new(seed);
    let side = 100.0 * (n as f64 / 1000.0).sqrt();
    let truth: Vec<[f64; 2]> = (0..n)
        .map(|_| [side * rng.uniform(), side * rng.uniform()])
        .collect();
    let detected = n * 9 / 10;
    let mut estimate: Vec<[f64; 2]> = truth[..detected]
        .iter()
        .map(|t| [t[0] + rng.normal(), t[1] + rng.normal()])
        .collect();
    for _ in detected..n {
        estimate.push([side * rng.uniform(), side * rng.uniform()]);
    }
    (truth, estimate)
}

/// The cut-off of the sparse and percolating scenes.
pub const C: f64 = 5.0;

/// A cut-off above every distance of a [`percolating_scene`] of side `side`: the scene where
/// every pair is closer than c.
pub fn all_pairs_cutoff(n: usize) -> f64 {
    // side·√2 plus 10σ of noise on both ends.
    100.0 * (n as f64 / 1000.0).sqrt() * std::f64::consts::SQRT_2 + 20.0
}

/// GOSPA (α = 2) by the method of fisst before issue 15, through the public API: the full
/// n × m distance matrix, the components of the "closer than c" graph by union-find, and one
/// dense assignment per component ([`fisst::math::linear_assignment`]) on min(d, c)^p.
/// Returns `(distance, localisation, missed, false_targets)`. Kept as the "before" column of
/// the benchmarks.
pub fn baseline_gospa(x: &[[f64; 2]], y: &[[f64; 2]], c: f64, p: f64) -> (f64, f64, usize, usize) {
    let (n, m) = (x.len(), y.len());
    let powp = |v: f64| if p == 2.0 { v * v } else { v.powf(p) };
    let cp = powp(c);
    let mut dist = Vec::with_capacity(n * m);
    let mut parent: Vec<usize> = (0..n + m).collect();
    fn find(parent: &mut [usize], mut v: usize) -> usize {
        while parent[v] != v {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        v
    }
    let mut has_edge = vec![false; n + m];
    for (i, a) in x.iter().enumerate() {
        for (j, b) in y.iter().enumerate() {
            let d = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt();
            if d < c {
                let (ra, rb) = (find(&mut parent, i), find(&mut parent, n + j));
                if ra != rb {
                    parent[rb] = ra;
                }
                has_edge[i] = true;
                has_edge[n + j] = true;
            }
            dist.push(d);
        }
    }
    let mut comp_of_root = vec![usize::MAX; n + m];
    let mut comps: Vec<(Vec<usize>, Vec<usize>)> = Vec::new();
    for v in (0..n + m).filter(|&v| has_edge[v]) {
        let r = find(&mut parent, v);
        if comp_of_root[r] == usize::MAX {
            comp_of_root[r] = comps.len();
            comps.push((vec![], vec![]));
        }
        let comp = &mut comps[comp_of_root[r]];
        if v < n {
            comp.0.push(v)
        } else {
            comp.1.push(v - n)
        }
    }
    let (mut loc, mut assigned) = (0.0, 0usize);
    let mut costs = Vec::new();
    for (rows, cols) in &comps {
        costs.clear();
        for &i in rows {
            for &j in cols {
                costs.push(powp(dist[i * m + j].min(c)));
            }
        }
        let a = fisst::math::linear_assignment(&costs, rows.len(), cols.len()).unwrap();
        for (r, k) in a.pairs {
            let d = dist[rows[r] * m + cols[k]];
            if d < c {
                loc += powp(d);
                assigned += 1;
            }
        }
    }
    let (missed, false_targets) = (n - assigned, m - assigned);
    let total = loc + cp / 2.0 * (missed + false_targets) as f64;
    (
        if p == 2.0 {
            total.sqrt()
        } else {
            total.powf(1.0 / p)
        },
        loc,
        missed,
        false_targets,
    )
}

/// The peak resident set size of this process in kB (`VmHWM` of /proc/self/status; 0 where
/// it is not available).
pub fn peak_rss_kb() -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse().ok())
        })
        .unwrap_or(0)
}

/// CPU time of the calling thread in seconds (`/proc/thread-self/schedstat`, Linux; 0 where
/// it is not available): on a loaded machine it measures the work, where wall time also
/// measures the wait for a core.
pub fn thread_cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<u64>().ok())
        .map_or(0.0, |ns| ns as f64 * 1e-9)
}
