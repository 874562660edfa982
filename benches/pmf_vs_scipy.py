#!/usr/bin/env python3
"""The multi-Bernoulli FoV cardinality pmf (88) side by side: scipy.stats.poisson_binom.pmf
against fisst natively (fisst::fov::multi_bernoulli) and through the npm package in Node
(multiBernoulliCardinality, and fovCardinality end to end), on the same inclusion
probabilities r_S = r <1_S, p> (r uniform in [0.35, 1), the mass uniform in [0, 1)), for
M = 10 ... 10 000. Prints median times, ratios, and the accuracy of each against an
extended-precision reference (the same convolution in numpy.longdouble, 64-bit mantissa on
x86-64): max abs error, max relative error over entries >= 1e-300, negative entries,
sum - 1.

    python3 benches/pmf_vs_scipy.py        (needs numpy, scipy; `make pkg` first)
"""
import json, os, subprocess, sys, tempfile, time
import numpy as np
from scipy.stats import poisson_binom

HERE = os.path.dirname(os.path.abspath(__file__))
SIZES = [10, 100, 1000, 10_000]


def reference(r):
    """Poisson-binomial pmf by the convolution recursion in long double (sums of nonnegative
    products only, so the relative error of every entry is ~M * 1e-19)."""
    r = np.asarray(r, dtype=np.longdouble)
    pmf = np.zeros(len(r) + 1, dtype=np.longdouble)
    pmf[0] = 1
    for k, ri in enumerate(r):
        pmf[1:k + 2] = pmf[1:k + 2] * (1 - ri) + pmf[0:k + 1] * ri
        pmf[0] *= 1 - ri
    return pmf


def accuracy(p, ref):
    p = np.asarray(p, dtype=np.float64)
    assert len(p) == len(ref), (len(p), len(ref))
    err = np.abs(p.astype(np.longdouble) - ref)
    big = ref >= 1e-300
    rel = float(np.max(err[big] / ref[big]))
    return float(np.max(err)), rel, int(np.sum(p < 0)), float(np.sum(p.astype(np.longdouble)) - 1)


def median_time(f, reps):
    times, out = [], None
    for _ in range(reps):
        t0 = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), out


def main():
    root = os.path.dirname(HERE)
    subprocess.run(["cargo", "build", "--release", "--quiet", "--bin", "fov_timing"],
                   cwd=HERE, check=True)
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(HERE, "target"))
    native = os.path.join(target, "release", "fov_timing")
    rng = np.random.default_rng(2026)
    rows = []
    for m in SIZES:
        r = (0.35 + 0.65 * rng.uniform(size=m)) * rng.uniform(size=m)
        reps = 200 if m <= 100 else (20 if m <= 1000 else 3)
        t_scipy, p_scipy = median_time(lambda: poisson_binom.pmf(np.arange(m + 1), r), reps)
        with tempfile.TemporaryDirectory() as tmp:
            inp, out_native, out_node = (os.path.join(tmp, f) for f in ("in.json", "n.json", "j.json"))
            with open(inp, "w") as f:
                json.dump({"r": r.tolist()}, f)
            nreps = max(reps, 7)
            t_native = float(subprocess.run([native, "pmf", inp, str(nreps), out_native],
                                            capture_output=True, text=True, check=True).stdout)
            t_pb, t_fov = map(float, subprocess.run(
                ["node", os.path.join(HERE, "fov_node.mjs"), "pmf", inp, str(nreps), out_node],
                capture_output=True, text=True, check=True, cwd=root).stdout.split())
            with open(out_native) as f:
                p_native = json.load(f)["pmf"]
            with open(out_node) as f:
                node = json.load(f)
        ref = reference(r)
        rows.append((m, t_scipy, t_native, t_pb, t_fov,
                     {"scipy": accuracy(p_scipy, ref), "fisst native": accuracy(p_native, ref),
                      "npm multiBernoulliCardinality": accuracy(node["pmf"], ref),
                      "npm fovCardinality": accuracy(node["fovPmf"], ref)}))
        assert p_native == node["pmf"], "native and wasm differ"

    print("Multi-Bernoulli FoV pmf (88), M inclusion probabilities; median wall time per call\n")
    print(f"{'M':>6} {'scipy ms':>10} {'native ms':>10} {'node pb ms':>11} {'node fov ms':>12} "
          f"{'scipy/native':>13} {'scipy/node pb':>14} {'scipy/node fov':>15}")
    for m, ts, tn, tp, tf, _ in rows:
        print(f"{m:>6} {1e3 * ts:>10.3f} {1e3 * tn:>10.4f} {1e3 * tp:>11.4f} {1e3 * tf:>12.4f} "
              f"{ts / tn:>13.1f} {ts / tp:>14.1f} {ts / tf:>15.1f}")
    print("\nAccuracy against the long-double convolution "
          "(max abs error, max rel error over entries >= 1e-300, negative entries, sum - 1)\n")
    print(f"{'M':>6} {'implementation':<30} {'max abs err':>12} {'max rel err':>12} "
          f"{'negative':>9} {'sum - 1':>10}")
    for m, *_, acc in rows:
        for name, (a, rel, neg, s) in acc.items():
            print(f"{m:>6} {name:<30} {a:>12.2e} {rel:>12.2e} {neg:>9} {s:>10.1e}")


if __name__ == "__main__":
    sys.exit(main())
