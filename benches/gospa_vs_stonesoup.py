#!/usr/bin/env python3
"""Whole-scenario GOSPA and OSPA side by side: Stone Soup 1.9.1's GOSPAMetric and OSPAMetric
(`compute_over_time`, what `MetricManager` calls) against fisst's `Gospa::series` /
`Ospa::series` natively (the `series_timing` bench binary), on one seeded scenario of 1,000
time steps with 10-50 objects per step, in one run.

Scenario (seed 15): at each step 10-50 truths uniform in [0, 1000]^2; each detected with
probability 0.9 with Gaussian noise of sigma = 2 per coordinate; 0-5 uniform false estimates.
c = 10, alpha = 2, p = 1 and p = 2. A second, crowded run puts the same objects in
[0, 100]^2, where assignments are often ambiguous (that is where minimising the wrong sum
shows).

Agreement is checked step by step (distance, localisation, missed and false counts) to 1e-9
relative. Stone Soup's GOSPAMetric assigns on min(d, c)^p (it raises to p before the
assignment), so it agrees at every p; its OSPAMetric assigns on min(d, c) and raises the
assigned distances to p afterwards, which minimises the wrong sum for p != 1: it agrees at
p = 1 and is never below fisst's (the optimum) at p = 2, where the table shows how often and
by how much it is above.

Node: `node_series` times the npm package's `gospaSeries` / `ospaSeries` once the bindings
exist (`benches/series_node.mjs` reports when they do not); it is the only function to
change for it.

    python3 benches/gospa_vs_stonesoup.py   (creates benches/.venv with stonesoup==1.9.1,
                                             numpy and scipy on first use)
"""
import datetime, json, os, subprocess, sys, tempfile, time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import _venv  # noqa: E402

_venv.ensure(["numpy", "scipy", "stonesoup"], ["numpy", "scipy", "stonesoup==1.9.1"])

import numpy as np  # noqa: E402
import stonesoup  # noqa: E402
from stonesoup.metricgenerator.ospametric import GOSPAMetric, OSPAMetric  # noqa: E402
from stonesoup.types.groundtruth import GroundTruthState  # noqa: E402
from stonesoup.types.state import State, StateVector  # noqa: E402

ROOT = os.path.dirname(HERE)
TARGET = os.environ.get("CARGO_TARGET_DIR", os.path.join(HERE, "target"))
STEPS, C, SEED = 1000, 10.0, 15


def scenario(side, steps=STEPS, seed=SEED):
    """Per step: 10-50 truths in [0, side]^2, 90 % detected with sigma = 2, 0-5 clutter."""
    rng = np.random.default_rng(seed)
    truths, estimates = [], []
    for _ in range(steps):
        n = int(rng.integers(10, 51))
        x = rng.uniform(0, side, size=(n, 2))
        detected = x[rng.uniform(size=n) < 0.9]
        y = detected + rng.normal(scale=2.0, size=detected.shape)
        y = np.vstack([y, rng.uniform(0, side, size=(int(rng.integers(0, 6)), 2))])
        truths.append(x)
        estimates.append(rng.permutation(y))
    return truths, estimates


def stonesoup_states(truths, estimates):
    """Stone Soup's inputs: one state per point, timestamped by step, with an id each."""
    t0 = datetime.datetime(2026, 1, 1)
    truth_states, truth_ids, est_states, est_ids = [], [], [], []
    for t, (x, y) in enumerate(zip(truths, estimates)):
        stamp = t0 + datetime.timedelta(seconds=t)
        for pt in x:
            truth_states.append(GroundTruthState(StateVector(pt), timestamp=stamp))
            truth_ids.append(len(truth_ids))
        for pt in y:
            est_states.append(State(StateVector(pt), timestamp=stamp))
            est_ids.append(len(est_ids))
    return truth_states, truth_ids, est_states, est_ids


def stonesoup_series(metric, states, p):
    """Stone Soup's per-step values and the seconds `compute_over_time` takes."""
    truth_states, truth_ids, est_states, est_ids = states
    t0 = time.perf_counter()
    if metric == "gospa":
        out = GOSPAMetric(c=C, p=p).compute_over_time(est_states, est_ids, truth_states,
                                                      truth_ids)
    else:
        out = OSPAMetric(c=C, p=p).compute_over_time(est_states, est_ids, truth_states,
                                                     truth_ids)
    seconds = time.perf_counter() - t0
    steps = sorted(out.value, key=lambda m: m.timestamp)
    if metric == "ospa":
        return seconds, {"distance": [float(m.value) for m in steps]}
    unit = C ** p / 2  # Stone Soup reports missed/false as costs: count * c^p / 2
    return seconds, {
        "distance": [float(m.value["distance"]) for m in steps],
        "localisation": [float(m.value["localisation"]) for m in steps],
        "missed": [float(m.value["missed"]) / unit for m in steps],
        "false_targets": [float(m.value["false"]) / unit for m in steps],
    }


def write_input(truths, estimates, p):
    f = tempfile.NamedTemporaryFile("w", suffix=".json", delete=False)
    json.dump({"truths": [x.tolist() for x in truths],
               "estimates": [y.tolist() for y in estimates], "c": C, "p": p, "alpha": 2.0}, f)
    f.close()
    return f.name


def native_series(metric, path, reps):
    """fisst natively: `Gospa::series` / `Ospa::series` (parallel over steps with rayon)."""
    exe = os.path.join(TARGET, "release", "series_timing")
    with tempfile.NamedTemporaryFile(suffix=".json", delete=False) as f:
        out_path = f.name
    try:
        seconds = float(subprocess.run([exe, metric, path, str(reps), out_path],
                                       capture_output=True, text=True, check=True).stdout)
        with open(out_path) as f:
            return seconds, json.load(f)
    finally:
        os.unlink(out_path)


def node_series(metric, path, reps):
    """fisst in Node: the npm package's `gospaSeries` / `ospaSeries`, or None while the
    bindings do not exist (series_node.mjs exits with status 3)."""
    if not os.path.exists(os.path.join(ROOT, "wasm", "pkg", "node.js")):
        return None
    with tempfile.NamedTemporaryFile(suffix=".json", delete=False) as f:
        out_path = f.name
    try:
        r = subprocess.run(["node", os.path.join(HERE, "series_node.mjs"), metric, path,
                            str(reps), out_path], capture_output=True, text=True, cwd=ROOT)
        if r.returncode == 3:
            return None
        r.check_returncode()
        with open(out_path) as f:
            return float(r.stdout), json.load(f)
    finally:
        os.unlink(out_path)


def compare(ours, theirs, keys):
    """(max relative difference, steps where theirs is above ours by > 1e-9 relative)."""
    worst, above = 0.0, 0
    for k in keys:
        a, b = np.asarray(ours[k], dtype=float), np.asarray(theirs[k], dtype=float)
        rel = np.abs(a - b) / (1 + np.abs(a))
        worst = max(worst, float(rel.max()))
        if k == "distance":
            above = int(np.sum(b - a > 1e-9 * (1 + np.abs(a))))
    return worst, above


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet", "--bin", "series_timing"],
                   cwd=HERE, check=True)
    print(f"stonesoup {stonesoup.__version__}; {STEPS} steps, 10-50 truths per step, c = {C}; "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    for side in [1000.0, 100.0]:
        truths, estimates = scenario(side)
        objects = sum(len(x) for x in truths), sum(len(y) for y in estimates)
        print(f"\nobjects in [0, {side:.0f}]^2: {objects[0]} truths, {objects[1]} estimates")
        states = stonesoup_states(truths, estimates)
        print(f"{'metric':>6} {'p':>3} {'stonesoup s':>12} {'native ms':>10} {'node ms':>9} "
              f"{'ss/native':>10} {'ss/node':>8} {'max rel diff':>13} {'ss above':>9}")
        for metric, p in [("gospa", 1.0), ("gospa", 2.0), ("ospa", 1.0), ("ospa", 2.0)]:
            path = write_input(truths, estimates, p)
            try:
                t_ss, ss = stonesoup_series(metric, states, p)
                t_native, ours = native_series(metric, path, 5)
                node = node_series(metric, path, 5)
            finally:
                os.unlink(path)
            keys = ["distance"] if metric == "ospa" else [
                "distance", "localisation", "missed", "false_targets"]
            worst, above = compare(ours, ss, keys)
            if node is not None:
                node_worst, _ = compare(ours, node[1], keys)
                assert node_worst <= 1e-12, (metric, p, node_worst)
            if metric == "gospa" or p == 1.0:
                assert worst <= 1e-9, (metric, p, worst)
            else:
                assert all(b >= a - 1e-9 * (1 + a)
                           for a, b in zip(ours["distance"], ss["distance"]))
            t_node = None if node is None else node[0]
            print(f"{metric:>6} {p:>3.0f} {t_ss:>12.3f} {1e3 * t_native:>10.3f} "
                  f"{'n/a' if t_node is None else f'{1e3 * t_node:.3f}':>9} "
                  f"{t_ss / t_native:>10.0f} "
                  f"{'n/a' if t_node is None else f'{t_ss / t_node:.0f}':>8} "
                  f"{worst:>13.2e} {above:>9}")
    print("\nmax rel diff: the largest |fisst - Stone Soup| / (1 + |fisst|) over all steps and "
          "fields;\nss above: steps where Stone Soup's distance exceeds fisst's (the optimum) "
          "by more than 1e-9.")

if __name__ == "__main__":
    sys.exit(main())
