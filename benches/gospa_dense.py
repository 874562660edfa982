#!/usr/bin/env python3
"""GOSPA (alpha = 2, p = 2) where every pair of points is closer than c (issue 29, goal 4),
with the sparse and percolating scenes of gospa_vs_scipy.py as a check that they are no slower.

Columns, on the same point sets in one run (median wall times):

- scipy:   cdist + linear_sum_assignment on min(d, c)^p (gospa_vs_scipy.gospa_scipy);
- lap:     the same matrix solved by `lap.lapjv` (LAPJV: column reduction, augmenting row
           reduction, then shortest augmenting paths), the same GOSPA value;
- native:  fisst's GOSPA natively (`gospa_timing`); at n = 2,000 with every pair close GOSPA
           refuses the work (MAX_DENSE_WORK = 2^30, about 1,000 x 1,000), so that row times
           what SciPy's side does instead: the min(d, c)^p matrix and
           `fisst::math::linear_assignment` (marked *);
- before:  the same with another `gospa_timing` binary (FISST_BEFORE_TIMING, e.g. one built at
           the commit before issue 29's dense solver), if given;
- node / node before: fisst's `gospa` through the npm package in Node (`gospa_node.mjs`, after
           warm-up calls), with the package entries FISST_NODE_ENTRY (default wasm/pkg/node.js)
           and FISST_BEFORE_NODE_ENTRY, if present.

Dense scenes: n truths and n estimates uniform in the unit square with c = 10, and the
"all-pairs" scene of gospa_vs_scipy.py (its percolating points, c above their diameter).

    python3 benches/gospa_dense.py      (numpy, scipy, lap: installs them in benches/.venv if
                                         missing; CARGO_TARGET_DIR as for the build)

Prints the load average beside the figures (the machine may be shared; the ratios come from
one run, so load affects both sides).
"""
import json, os, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import _venv  # noqa: E402

_venv.ensure(["numpy", "scipy", "lap"], ["numpy", "scipy", "lap"])

import lap  # noqa: E402
import numpy as np  # noqa: E402
from scipy.spatial.distance import cdist  # noqa: E402

from gospa_vs_scipy import (  # noqa: E402
    C, P, all_pairs_cutoff, gospa_scipy, median_time, percolating_scene, sparse_scene,
)

ROOT = os.path.dirname(HERE)
TARGET = os.environ.get("CARGO_TARGET_DIR", os.path.join(HERE, "target"))
MAX_DENSE_N = 1024  # GOSPA's MAX_DENSE_WORK = 2^30 = 1024^3


def gospa_lap(x, y, c, p=P):
    """As gospa_scipy, with the assignment by lap.lapjv (square matrices here)."""
    d = cdist(x, y)
    cost = np.minimum(d, c) ** p
    _, col4row, _ = lap.lapjv(cost)
    rows = np.arange(len(x))
    dd = d[rows, col4row]
    assigned = dd < c
    loc = float(np.sum(dd[assigned] ** p))
    unassigned = len(x) + len(y) - 2 * int(np.sum(assigned))
    return (loc + c ** p / 2 * unassigned) ** (1 / p)


def run(cmd):
    return subprocess.run(cmd, capture_output=True, text=True, check=True, cwd=ROOT).stdout.split()


def fmt(t):
    return "n/a" if t is None else f"{1e3 * t:.2f}"


def ratio(a, b):
    return "n/a" if a is None or b is None else f"{a / b:.3f}"


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet", "--bin", "gospa_timing"], cwd=HERE,
                   check=True)
    timing = os.path.join(TARGET, "release", "gospa_timing")
    before = os.environ.get("FISST_BEFORE_TIMING")
    node_entry = os.environ.get("FISST_NODE_ENTRY", os.path.join(ROOT, "wasm", "pkg", "node.js"))
    node_before = os.environ.get("FISST_BEFORE_NODE_ENTRY")
    node_entries = [e if e and os.path.exists(e) else None for e in (node_entry, node_before)]

    scenes = []
    for n in [1000, 2000]:
        rng = np.random.default_rng(15)
        scenes.append(("unit square", n, rng.uniform(size=(n, 2)), rng.uniform(size=(n, 2)), 10.0))
    rng = np.random.default_rng(15)
    for n in [1000, 2000]:
        truth, est = percolating_scene(n, rng)
        scenes.append(("all-pairs", n, truth, est, all_pairs_cutoff(n)))
    rng_sparse = np.random.default_rng(2026)
    for n in [1000, 2000]:
        scenes.append(("sparse", n, *sparse_scene(n, rng_sparse), C))
    rng = np.random.default_rng(15)
    for n in [1000, 5000]:
        scenes.append(("percolating", n, *percolating_scene(n, rng), C))

    print(f"load average {' '.join(open('/proc/loadavg').read().split()[:3])} "
          f"on {os.cpu_count()} cores")
    cols = ["scipy", "lap", "before", "native", "node before", "node"]
    print(f"{'scene':>12} {'n':>5} " + " ".join(f"{c + ' ms':>14}" for c in cols) +
          f" {'lap/scipy':>9} {'nat/scipy':>9} {'node/scipy':>10} {'nat/before':>10} "
          f"{'node/before':>11}")
    for kind, n, truth, est, c in scenes:
        reps = 9 if n <= 2000 else 5
        dense = kind in ("unit square", "all-pairs")
        t_scipy, d_scipy = median_time(lambda: gospa_scipy(truth, est, c), reps)
        t_lap = None
        if dense:
            t_lap, d_lap = median_time(lambda: gospa_lap(truth, est, c), reps)
            assert abs(d_lap - d_scipy) <= 1e-9 * (1 + d_scipy), (kind, n, d_lap, d_scipy)
        mode = ["assignment"] if dense and n > MAX_DENSE_N else []
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            json.dump({"truth": truth.tolist(), "estimate": est.tolist(), "c": c, "p": P}, f)
            path = f.name
        times = {}
        try:
            for name, binary in [("native", timing), ("before", before)]:
                if binary:
                    t, d = map(float, run([binary, path, str(reps), *mode]))
                    assert abs(d - d_scipy) <= 1e-9 * (1 + d_scipy), (kind, n, name, d, d_scipy)
                    times[name] = t
            for name, entry in zip(["node", "node before"], node_entries):
                if entry and not mode:
                    out = subprocess.run(["node", os.path.join(HERE, "gospa_node.mjs"), path,
                                          str(reps)], capture_output=True, text=True, check=True,
                                         cwd=ROOT, env={**os.environ, "FISST_NODE_ENTRY": entry})
                    t, d = map(float, out.stdout.split())
                    assert abs(d - d_scipy) <= 1e-9 * (1 + d_scipy), (kind, n, name, d, d_scipy)
                    times[name] = t
        finally:
            os.unlink(path)
        row = {"scipy": t_scipy, "lap": t_lap, **times}
        star = "*" if mode else " "
        print(f"{kind:>12} {n:>5}{star}" + " ".join(f"{fmt(row.get(c)):>14}" for c in cols) +
              f" {ratio(t_lap, t_scipy):>9} {ratio(row.get('native'), t_scipy):>9} "
              f"{ratio(row.get('node'), t_scipy):>10} "
              f"{ratio(row.get('native'), row.get('before')):>10} "
              f"{ratio(row.get('node'), row.get('node before')):>11}")
    print("* n = 2,000 with every pair close: beyond GOSPA's MAX_DENSE_WORK; native and before "
          "time the min(d, c)^p matrix + fisst::math::linear_assignment (Node: n/a)")
    print(f"load average {' '.join(open('/proc/loadavg').read().split()[:3])} at the end")


if __name__ == "__main__":
    sys.exit(main())
