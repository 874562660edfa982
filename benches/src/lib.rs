//! Shared inputs for the benchmarks: seeded point sets like a tracker's output.

/// SplitMix64: a portable seeded generator.
pub struct SplitMix(u64);

impl SplitMix {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// A uniform draw in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
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

impl SplitMix {
    /// A standard normal draw (Box–Muller).
    pub fn normal(&mut self) -> f64 {
        let u = 1.0 - self.uniform();
        let v = self.uniform();
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
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
