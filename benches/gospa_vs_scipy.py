#!/usr/bin/env python3
"""GOSPA side by side: SciPy's linear_sum_assignment (the way Stone Soup computes GOSPA, but
with the correct costs min(d, c)^p) against fisst natively and through the npm package in Node,
on the same point sets, in one run. Prints median times and the ratios.

    python3 benches/gospa_vs_scipy.py        (needs numpy, scipy; `make pkg` first)
"""
import json, os, subprocess, sys, tempfile, time
import numpy as np
from scipy.optimize import linear_sum_assignment
from scipy.spatial.distance import cdist

HERE = os.path.dirname(os.path.abspath(__file__))
C, P = 5.0, 2.0


def scene(n, rng):
    side = 10.0 * np.sqrt(n)
    truth = rng.uniform(0, side, size=(n, 2))
    keep = rng.uniform(size=n) < 0.9
    est = truth[keep] + rng.normal(scale=1.0, size=(keep.sum(), 2))
    est = np.vstack([est, rng.uniform(0, side, size=(n // 10, 2))])
    return truth, est


def gospa_scipy(x, y, c=C, p=P):
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


def main():
    root = os.path.dirname(HERE)
    subprocess.run(["cargo", "build", "--release", "--quiet", "--bin", "gospa_timing"],
                   cwd=HERE, check=True)
    native = os.path.join(HERE, "target", "release", "gospa_timing")
    rng = np.random.default_rng(2026)
    print(f"{'n':>6} {'scipy ms':>10} {'native ms':>10} {'node ms':>10} "
          f"{'native/scipy':>13} {'node/scipy':>11}")
    for n in [10, 100, 500, 1000, 2000]:
        truth, est = scene(n, rng)
        reps = 200 if n <= 100 else (20 if n <= 1000 else 7)
        t_scipy, d_scipy = median_time(lambda: gospa_scipy(truth, est), reps)
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            json.dump({"truth": truth.tolist(), "estimate": est.tolist(), "c": C, "p": P}, f)
            path = f.name
        try:
            out = subprocess.run([native, path, str(reps)], capture_output=True, text=True,
                                 check=True).stdout.split()
            t_native, d_native = float(out[0]), float(out[1])
            out = subprocess.run(["node", os.path.join(HERE, "gospa_node.mjs"), path, str(reps)],
                                 capture_output=True, text=True, check=True, cwd=root).stdout.split()
            t_node, d_node = float(out[0]), float(out[1])
        finally:
            os.unlink(path)
        for d in (d_native, d_node):
            assert abs(d - d_scipy) <= 1e-9 * (1 + d_scipy), (n, d, d_scipy)
        print(f"{n:>6} {1e3 * t_scipy:>10.3f} {1e3 * t_native:>10.3f} {1e3 * t_node:>10.3f} "
              f"{t_native / t_scipy:>13.2f} {t_node / t_scipy:>11.2f}")


if __name__ == "__main__":
    sys.exit(main())
