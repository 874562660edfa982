#!/usr/bin/env python3
"""GOSPA (alpha = 2, p = 2) side by side, on the same point sets in one run:

- scipy:  cdist + linear_sum_assignment on min(d, c)^p (the dense way, as Stone Soup does it);
- before: fisst's method before issue 15, natively (the full n x m distance matrix and one
          dense assignment per component of the "closer than c" graph;
          fisst_benches::baseline_gospa);
- native: fisst natively (grid for the pairs closer than c, sparse exact matching);
- node:   fisst through the npm package in Node (`gospa`, wasm32; after warm-up calls, and
          including the conversion of the JS point arrays by the current bindings).

Scenes, each density: the sparse scenes of the first version of this script (side 10 sqrt(n),
c = 5: small components); issue 15's percolating scene (n truths uniform in a square of side
100 sqrt(n / 1000), 90 % of them with an estimate within sigma = 1, 10 % uniform estimates,
c = 5: a giant component) at n = 1,000, 5,000 and 100,000; and the same points with c above
the diameter, where every pair is closer than c. SciPy and "before" need the full distance
matrix, so they are skipped at n = 100,000 (80 GB). Then the native peak memory (maximum
resident set size, /usr/bin/time -v) of `gospa_scene`, which generates the scene natively.

Prints median wall times, the ratios and the load average (the machine may be shared: the
ratios come from one run, so load affects both sides).

    python3 benches/gospa_vs_scipy.py        (numpy, scipy: installs them in benches/.venv if
                                              missing; `make pkg` first for the Node column)
"""
import json, os, re, subprocess, sys, tempfile, time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import _venv  # noqa: E402

_venv.ensure(["numpy", "scipy"], ["numpy", "scipy"])

import numpy as np  # noqa: E402
from scipy.optimize import linear_sum_assignment  # noqa: E402
from scipy.spatial.distance import cdist  # noqa: E402

ROOT = os.path.dirname(HERE)
TARGET = os.environ.get("CARGO_TARGET_DIR", os.path.join(HERE, "target"))
C, P = 5.0, 2.0


def sparse_scene(n, rng):
    """The scenes of the first version of this script (kept, same generator and seed)."""
    side = 10.0 * np.sqrt(n)
    truth = rng.uniform(0, side, size=(n, 2))
    keep = rng.uniform(size=n) < 0.9
    est = truth[keep] + rng.normal(scale=1.0, size=(keep.sum(), 2))
    est = np.vstack([est, rng.uniform(0, side, size=(n // 10, 2))])
    return truth, est


def percolating_scene(n, rng):
    """Issue 15: n truths uniform in [0, 100 sqrt(n/1000)]^2, 90 % detected within sigma = 1,
    10 % uniform estimates."""
    side = 100.0 * np.sqrt(n / 1000)
    truth = rng.uniform(0, side, size=(n, 2))
    k = n * 9 // 10
    est = np.vstack([truth[:k] + rng.normal(size=(k, 2)), rng.uniform(0, side, size=(n - k, 2))])
    return truth, est


def all_pairs_cutoff(n):
    """A cut-off above every distance of a percolating scene (diagonal plus 10 sigma twice)."""
    return 100.0 * np.sqrt(n / 1000) * np.sqrt(2) + 20.0


def gospa_scipy(x, y, c, p=P):
    """GOSPA (alpha = 2) as Stone Soup computes it, with the assignment on min(d, c)^p."""
    if len(x) == 0 and len(y) == 0:
        return 0.0
    d = cdist(x, y)
    cost = np.minimum(d, c) ** p
    rows, cols = linear_sum_assignment(cost)
    assigned = d[rows, cols] < c
    loc = float(np.sum(d[rows, cols][assigned] ** p))
    unassigned = len(x) + len(y) - 2 * int(np.sum(assigned))
    return (loc + c ** p / 2 * unassigned) ** (1 / p)


def median_time(f, reps):
    times = []
    out = None
    for _ in range(reps):
        t0 = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), out


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, check=True, **kw).stdout


def node_available():
    return os.path.exists(os.path.join(ROOT, "wasm", "pkg", "node.js"))


def fmt(t):
    return "n/a" if t is None else f"{1e3 * t:.3f}"


def ratio(a, b):
    return "n/a" if a is None or b is None else f"{a / b:.3f}"


def peak_rss_kb(args):
    """Maximum resident set size of a native run, from /usr/bin/time -v (None without it)."""
    if not os.path.exists("/usr/bin/time"):
        return None
    err = subprocess.run(["/usr/bin/time", "-v", *args], capture_output=True, text=True,
                         check=True).stderr
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", err)
    return int(m.group(1)) if m else None


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet", "--bin", "gospa_timing",
                    "--bin", "gospa_scene"], cwd=HERE, check=True)
    timing = os.path.join(TARGET, "release", "gospa_timing")
    scene_bin = os.path.join(TARGET, "release", "gospa_scene")
    node = node_available()
    if not node:
        print("(no wasm/pkg: run `make pkg` for the Node column)")

    rng_sparse = np.random.default_rng(2026)
    rng = np.random.default_rng(15)
    scenes = [("sparse", n, *sparse_scene(n, rng_sparse), C) for n in [10, 100, 500, 1000, 2000]]
    for n in [1000, 5000, 100_000]:
        scenes.append(("percolating", n, *percolating_scene(n, rng), C))
    for n in [1000, 2000]:
        truth, est = percolating_scene(n, rng)
        scenes.append(("all-pairs", n, truth, est, all_pairs_cutoff(n)))

    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    print(f"{'scene':>12} {'n':>7} {'m':>7} {'pairs<c':>10} {'scipy ms':>10} {'before ms':>10} "
          f"{'native ms':>10} {'node ms':>10} {'nat/scipy':>10} {'node/scipy':>10} "
          f"{'nat/before':>10}")
    for kind, n, truth, est, c in scenes:
        reps = 200 if n <= 100 else (20 if n <= 1000 else (5 if n <= 5000 else 3))
        dense_ok = n <= 5000
        pairs = None
        t_scipy = d_scipy = None
        if dense_ok:
            d = cdist(truth, est)
            pairs = int(np.sum(d < c))
            del d
            t_scipy, d_scipy = median_time(lambda: gospa_scipy(truth, est, c), reps)
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            json.dump({"truth": truth.tolist(), "estimate": est.tolist(), "c": c, "p": P}, f)
            path = f.name
        try:
            out = run([timing, path, str(reps)]).split()
            t_native, d_native = float(out[0]), float(out[1])
            t_before = d_before = None
            if dense_ok:
                out = run([timing, path, str(reps), "baseline"]).split()
                t_before, d_before = float(out[0]), float(out[1])
            t_node = d_node = None
            if node:
                out = run(["node", os.path.join(HERE, "gospa_node.mjs"), path, str(reps)],
                          cwd=ROOT).split()
                t_node, d_node = float(out[0]), float(out[1])
        finally:
            os.unlink(path)
        reference = d_scipy if d_scipy is not None else d_native
        for d in (d_native, d_node, d_before):
            if d is not None:
                assert abs(d - reference) <= 1e-9 * (1 + reference), (kind, n, d, reference)
        print(f"{kind:>12} {n:>7} {len(est):>7} {pairs if pairs is not None else 'n/a':>10} "
              f"{fmt(t_scipy):>10} {fmt(t_before):>10} {fmt(t_native):>10} {fmt(t_node):>10} "
              f"{ratio(t_native, t_scipy):>10} {ratio(t_node, t_scipy):>10} "
              f"{ratio(t_native, t_before):>10}")

    print("\npeak memory natively (maximum resident set size of gospa_scene, one evaluation,"
          " scene generated natively with the same construction)")
    print(f"{'scene':>12} {'n':>7} {'method':>8} {'peak MB':>9} {'ms':>9}")
    for kind, n, methods in [("percolating", 5000, ["before", "fisst"]),
                             ("percolating", 100_000, ["fisst"]),
                             ("all-pairs", 2000, ["before", "fisst"])]:
        for method in methods:
            args = [scene_bin, kind, str(n), "1"] + (["baseline"] if method == "before" else [])
            kb = peak_rss_kb(args)
            seconds = json.loads(run(args))["seconds"]
            print(f"{kind:>12} {n:>7} {method:>8} "
                  f"{'n/a' if kb is None else f'{kb / 1024:.1f}':>9} {1e3 * seconds:>9.1f}")


if __name__ == "__main__":
    sys.exit(main())
