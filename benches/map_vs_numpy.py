#!/usr/bin/env python3
"""The sensor-placement variance map (Section VII of paper 001, Figs 9-10) side by side: a
straightforward numpy/scipy implementation against fisst natively (fisst::fov::variance_map)
and through the npm package in Node (fovVarianceMap), on the same seeded scene
(placementScene: 100 components, FoV centres on 121 x 121 points of [-3, 3]^2, a 1 x 1 FoV).

The numpy/scipy map: for every component, vectorised over all FoV centres, the box mass by
inclusion-exclusion of four bivariate normal CDFs, each from Owen's T function
(scipy.special.owens_t, Patefield-Tandy, ~1e-16 absolute):

    Phi2(h, k; rho) = Phi(h)/2 + Phi(k)/2 - T(h, a_h) - T(k, a_k) - beta,
    a_h = (k - rho h)/(h sqrt(1 - rho^2)),  a_k = (h - rho k)/(k sqrt(1 - rho^2)),
    beta = 1/2 if h k < 0 or (h k = 0 and h + k < 0), else 0,

then Var = sum_i r_S (1 - r_S). Its accuracy: the printed max |diff| to fisst's map, and
Owen's T against scipy.stats.multivariate_normal.cdf on sample boxes and corners.
scipy.stats.multivariate_normal.cdf is not used for the whole map: in SciPy 1.17 it is a
randomised quasi-Monte Carlo integration (Genz-Bretz; default abseps 1e-5, far more accurate
in 2D in practice) called once per box from Python; its time per box is printed, with the
time the whole map would take.

    python3 benches/map_vs_numpy.py        (needs numpy, scipy; `make pkg` first)
"""
import json, os, subprocess, sys, tempfile, time
import numpy as np
from scipy.special import ndtr, owens_t
from scipy.stats import multivariate_normal

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = {"count": 100, "seed": 1, "extent": 3.0}
GRID = [-3.0, 3.0, 121]


def bvn_cdf(h, k, rho):
    """Phi2(h, k; rho), vectorised, through Owen's T."""
    h, k = np.broadcast_arrays(np.asarray(h, float), np.asarray(k, float))
    s = np.sqrt(1.0 - rho * rho)
    with np.errstate(divide="ignore", invalid="ignore"):
        a_h = (k - rho * h) / (h * s)
        a_k = (h - rho * k) / (k * s)
    # h = 0 (or k = 0): T(0, +-inf) = +-1/4 is the limit; both zero: 1/4 + asin(rho)/2pi.
    a_h = np.where(h == 0, np.copysign(np.inf, k - rho * h), a_h)
    a_k = np.where(k == 0, np.copysign(np.inf, h - rho * k), a_k)
    hk = h * k
    beta = np.where((hk < 0) | ((hk == 0) & (h + k < 0)), 0.5, 0.0)
    out = 0.5 * ndtr(h) + 0.5 * ndtr(k) - owens_t(h, a_h) - owens_t(k, a_k) - beta
    both = (h == 0) & (k == 0)
    return np.where(both, 0.25 + np.arcsin(rho) / (2 * np.pi), out)


def box_mass(lo_x, hi_x, lo_y, hi_y, mean, cov):
    sx, sy = np.sqrt(cov[0][0]), np.sqrt(cov[1][1])
    rho = cov[0][1] / (sx * sy)
    x0, x1 = (lo_x - mean[0]) / sx, (hi_x - mean[0]) / sx
    y0, y1 = (lo_y - mean[1]) / sy, (hi_y - mean[1]) / sy
    f = lambda a, b: bvn_cdf(a, b, rho)
    return f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0)


def variance_map_numpy(scene, side, grid):
    lo, hi, n = grid
    step = (hi - lo) / (n - 1)
    c = lo + np.arange(n) * step  # the centres exactly as fisst computes them
    cx, cy = np.meshgrid(c, c)  # rows: y (outer), columns: x
    var = np.zeros_like(cx)
    for comp in scene:
        m = box_mass(cx - side / 2, cx + side / 2, cy - side / 2, cy + side / 2,
                     comp["mean"], comp["cov"])
        q = comp["existence"] * np.clip(m, 0.0, 1.0)
        var += q * (1 - q)
    k = int(np.argmax(var))
    return var.ravel(), [float(c[k % n]), float(c[k // n])], float(var.ravel()[k])


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
    rows = []
    for side in [1.0, 0.97]:
        job = {**SCENE, "side": side, "grid": GRID}
        with tempfile.TemporaryDirectory() as tmp:
            inp, out_native, out_node = (os.path.join(tmp, f) for f in ("in.json", "n.json", "j.json"))
            with open(inp, "w") as f:
                json.dump(job, f)
            t_native = float(subprocess.run([native, "map", inp, "15", out_native],
                                            capture_output=True, text=True, check=True).stdout)
            t_node = float(subprocess.run(
                ["node", os.path.join(HERE, "fov_node.mjs"), "map", inp, "15", out_node],
                capture_output=True, text=True, check=True, cwd=root).stdout)
            with open(out_native) as f:
                nat = json.load(f)
            with open(out_node) as f:
                node = json.load(f)
        scene = nat["scene"]
        t_np, (var_np, argmax_np, max_np) = median_time(lambda: variance_map_numpy(scene, side, GRID), 3)
        v_nat = np.array(nat["variance"])
        assert node["variance"] == nat["variance"], "native and wasm maps differ"
        rows.append((side, t_np, t_native, t_node, float(np.max(np.abs(var_np - v_nat))),
                     argmax_np, nat["argmax"], max_np, nat["max"]))

    cells = GRID[2] ** 2
    print(f"Variance map: {SCENE['count']} components x {GRID[2]}^2 FoV centres "
          f"({SCENE['count'] * cells} box masses); median wall time\n")
    print(f"{'FoV side':>8} {'numpy ms':>10} {'native ms':>10} {'node ms':>9} {'numpy/native':>13} "
          f"{'numpy/node':>11} {'max |diff|':>11} {'argmax numpy':>16} {'argmax fisst':>16}")
    for side, tn, tr, tj, diff, am_np, am, mx_np, mx in rows:
        fa = lambda a: f"({a[0]:.2f}, {a[1]:.2f})"
        print(f"{side:>8} {1e3 * tn:>10.1f} {1e3 * tr:>10.2f} {1e3 * tj:>9.2f} {tn / tr:>13.1f} "
              f"{tn / tj:>11.1f} {diff:>11.2e} {fa(am_np):>16} {fa(am):>16}")

    # scipy.stats.multivariate_normal.cdf on a sample of the same boxes.
    rng = np.random.default_rng(7)
    scene = nat["scene"]
    sample = [(scene[rng.integers(len(scene))], rng.uniform(-3, 3, size=2)) for _ in range(40)]
    errs, t0 = [], time.perf_counter()
    for comp, (x, y) in sample:
        lo, hi = np.array([x - 0.5, y - 0.5]), np.array([x + 0.5, y + 0.5])
        p = multivariate_normal(comp["mean"], comp["cov"]).cdf(hi, lower_limit=lo)
        errs.append(abs(p - box_mass(lo[0], hi[0], lo[1], hi[1], comp["mean"], comp["cov"])))
    per_box = (time.perf_counter() - t0) / len(sample)
    print(f"\nscipy.stats.multivariate_normal.cdf (QMC): {1e3 * per_box:.2f} ms per box, "
          f"max |diff| to Owen's T {max(errs):.1e} on {len(sample)} boxes; the whole map "
          f"({SCENE['count'] * cells} boxes) would take ~{per_box * SCENE['count'] * cells:.0f} s")
    # Owen's T Phi2 at single corners (both signs of h, k and rho) against scipy's.
    worst = 0.0
    for a, b, rho in zip(rng.normal(size=20) * 3, rng.normal(size=20) * 3, rng.uniform(-0.95, 0.95, 20)):
        scipy_cdf = multivariate_normal([0, 0], [[1, rho], [rho, 1]]).cdf([a, b])
        worst = max(worst, abs(float(bvn_cdf(a, b, rho)) - scipy_cdf))
    print(f"Owen's T Phi2 vs scipy.stats.multivariate_normal.cdf at 20 random corners: max |diff| {worst:.1e}")


if __name__ == "__main__":
    sys.exit(main())
