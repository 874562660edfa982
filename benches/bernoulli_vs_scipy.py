#!/usr/bin/env python3
"""Optimal Bernoulli point estimation (paper 000) side by side: q(a) = P(|x - a| > r0) for
correlated 2D and 3D Gaussians (and a 10-component 2D mixture), and the MMUC estimate
a* = argmin_a q(a) of that mixture, SciPy against fisst natively (fisst::bernoulli) and through
the npm package in Node (probabilityOutsideBall, mmucEstimate), on the same inputs in one run.

SciPy implementations of q (P(inside) = 1 - q, the Gaussian density written out in numpy):
- "polar": scipy.integrate.dblquad (2D) / tplquad (3D) of the pdf over the ball in polar /
  spherical coordinates about a, epsabs 1e-10 - the first thing one would write.
- "eigen": in the covariance eigenbasis (y = U^T (x - a): independent N(mu_j, lambda_j)), the
  widest coordinate in closed form (a difference of two normal CDFs, scipy.special.ndtr), the
  others by nested scipy.integrate.quad with epsabs 1e-10 (the peak as a breakpoint) - the
  reduction fisst itself uses, in Python.
Accuracy: every q against the "eigen" form at epsabs 1e-14 (the reference); |dq| columns.
a*: scipy.optimize.minimize (Nelder-Mead, xatol 1e-7, fatol 1e-12) of the "eigen" q of the
mixture, started from every component mean and the mixture mean, the best kept (fisst: BFGS
with an analytic gradient from the same starts plus pairwise midpoints, q to 1e-10).

    python3 benches/bernoulli_vs_scipy.py        (needs numpy, scipy; `make pkg` first)
"""
import json, math, os, subprocess, sys, tempfile, time, warnings
import numpy as np
from scipy import integrate, optimize
from scipy.special import ndtr

HERE = os.path.dirname(os.path.abspath(__file__))
R0 = 1.0
TOL = 1e-10
REF_TOL = 1e-13

G2 = {"mean": [0.3, -0.2], "cov": [[1.0, 0.6], [0.6, 0.8]]}
G3 = {"mean": [0.3, -0.2, 0.1], "cov": [[1.0, 0.4, 0.2], [0.4, 0.8, -0.3], [0.2, -0.3, 1.5]]}
CENTERS2 = [[0.3, -0.2], [0.8, 0.2], [1.5, -1.0], [-1.0, 1.2], [2.0, 2.0]]
CENTERS3 = [[0.3, -0.2, 0.1], [0.8, 0.2, -0.4], [1.5, -1.0, 0.5], [-1.0, 1.2, 0.0], [2.0, 2.0, 1.0]]
CENTERS_MIX = [[0.5, -0.5], [0.0, 0.0], [-2.0, 1.0], [2.0, 2.0], [1.0, -2.5]]


class SplitMix:
    """SplitMix64, as fisst_benches::SplitMix: the same draws as benches/benches/bernoulli.rs."""
    MASK = (1 << 64) - 1

    def __init__(self, seed):
        self.s = seed

    def uniform(self):
        self.s = (self.s + 0x9E3779B97F4A7C15) & self.MASK
        z = self.s
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & self.MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & self.MASK
        return ((z ^ (z >> 31)) >> 11) / float(1 << 53)


def mixture10():
    rng = SplitMix(2026)
    comps = []
    for _ in range(10):
        w = 0.2 + 0.8 * rng.uniform()
        m = [-3.0 + 6.0 * rng.uniform(), -3.0 + 6.0 * rng.uniform()]
        sx, sy = 0.3 + 0.5 * rng.uniform(), 0.3 + 0.5 * rng.uniform()
        rho = -0.6 + 1.2 * rng.uniform()
        c = rho * sx * sy
        comps.append({"weight": w, "mean": m, "cov": [[sx * sx, c], [c, sy * sy]]})
    return comps


# ------------------------------------------------------------------ SciPy: q in the eigenbasis
def _phi(y, mu, s):
    return math.exp(-0.5 * ((y - mu) / s) ** 2) / (s * math.sqrt(2 * math.pi))


def _interval_mass(h, mu, s):
    """P(|y| <= h) for y ~ N(mu, s^2)."""
    return ndtr((h - mu) / s) - ndtr((-h - mu) / s)


def _nested(k, rho2, mu, s, tol):
    """P(sum_{j >= k} y_j^2 <= rho2), y_j ~ N(mu_j, s_j^2) independent, s sorted increasing."""
    rho = math.sqrt(max(rho2, 0.0))
    if k == len(mu) - 1:
        return _interval_mass(rho, mu[k], s[k])
    lo, hi = max(-rho, mu[k] - 9 * s[k]), min(rho, mu[k] + 9 * s[k])
    if lo >= hi:
        return 0.0
    f = lambda y: _phi(y, mu[k], s[k]) * _nested(k + 1, (rho - y) * (rho + y), mu, s, tol / 4)
    pts = [mu[k]] if lo < mu[k] < hi else None
    return integrate.quad(f, lo, hi, epsabs=tol / 2, epsrel=0, points=pts, limit=200)[0]


def q_eigen(g, a, r0=R0, tol=TOL):
    lam, u = np.linalg.eigh(np.array(g["cov"]))
    mu = u.T @ (np.array(g["mean"]) - np.array(a))
    order = np.argsort(lam)  # narrowest outermost, widest innermost (closed form)
    return 1.0 - _nested(0, r0 * r0, list(mu[order]), list(np.sqrt(lam[order])), tol)


def q_mixture_eigen(comps, a, tol=TOL):
    total = sum(c["weight"] for c in comps)
    return sum(c["weight"] * q_eigen(c, a, tol=tol) for c in comps) / total


def reference(dens, a):
    """The eigen form at epsabs REF_TOL (quad warns that roundoff limits it near 1e-15)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", integrate.IntegrationWarning)
        return q_mixture_eigen(dens, a, tol=REF_TOL) if isinstance(dens, list) else q_eigen(dens, a, tol=REF_TOL)


# ------------------------------------------------------------------ SciPy: q in polar coordinates
def _pdf(g):
    mean = np.array(g["mean"])
    prec = np.linalg.inv(np.array(g["cov"]))
    norm = 1.0 / math.sqrt((2 * math.pi) ** len(mean) * np.linalg.det(np.array(g["cov"])))
    return mean, prec, norm


def q_polar(g, a):
    mean, prec, norm = _pdf(g)
    d0 = np.array(a) - mean
    if len(mean) == 2:
        p00, p01, p11 = prec[0, 0], prec[0, 1], prec[1, 1]

        def f(theta, r):
            x = d0[0] + r * math.cos(theta)
            y = d0[1] + r * math.sin(theta)
            return norm * math.exp(-0.5 * (p00 * x * x + 2 * p01 * x * y + p11 * y * y)) * r

        inside = integrate.dblquad(f, 0, R0, 0, 2 * math.pi, epsabs=TOL, epsrel=0)[0]
    else:
        def f(phi, theta, r):
            st = math.sin(theta)
            v = d0 + r * np.array([st * math.cos(phi), st * math.sin(phi), math.cos(theta)])
            return norm * math.exp(-0.5 * v @ prec @ v) * r * r * st

        inside = integrate.tplquad(f, 0, R0, 0, math.pi, 0, 2 * math.pi, epsabs=TOL, epsrel=0)[0]
    return 1.0 - inside


# ------------------------------------------------------------------ SciPy: a* by multi-start
def mmuc_scipy(comps):
    total = sum(c["weight"] for c in comps)
    mean = [sum(c["weight"] * c["mean"][i] for c in comps) / total for i in range(2)]
    starts = [c["mean"] for c in comps] + [mean]
    best = None
    for x0 in starts:
        r = optimize.minimize(lambda a: q_mixture_eigen(comps, a), x0, method="Nelder-Mead",
                              options={"xatol": 1e-7, "fatol": 1e-12, "maxiter": 2000})
        if best is None or r.fun < best.fun:
            best = r
    return list(best.x), float(best.fun)


# ------------------------------------------------------------------ runs
def median_time(f, reps):
    times, out = [], None
    for _ in range(reps):
        t0 = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), out


def scipy_q(q, density, centers, reps):
    """Median seconds per call (mean over the centres) and the values."""
    ts, vs = [], []
    for c in centers:
        t, v = median_time(lambda: q(density, c), reps)
        ts.append(t)
        vs.append(v)
    return float(np.mean(ts)), vs


def run_fisst(cases):
    root = os.path.dirname(HERE)
    subprocess.run(["cargo", "build", "--release", "--quiet", "--bin", "bernoulli_timing"],
                   cwd=HERE, check=True)
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(HERE, "target"))
    native = os.path.join(target, "release", "bernoulli_timing")
    with tempfile.TemporaryDirectory() as tmp:
        inp, out_native, out_node = (os.path.join(tmp, f) for f in ("in.json", "n.json", "j.json"))
        with open(inp, "w") as f:
            json.dump({"cases": cases}, f)
        subprocess.run([native, inp, out_native], check=True)
        subprocess.run(["node", os.path.join(HERE, "bernoulli_node.mjs"), inp, out_node],
                       check=True, cwd=root)
        with open(out_native) as f:
            nat = json.load(f)["results"]
        with open(out_node) as f:
            node = json.load(f)["results"]
    for a, b in zip(nat, node):
        assert a["q"] == b["q"] and a.get("center") == b.get("center"), "native and wasm differ"
    return nat, node


def main():
    mix = mixture10()
    cases = [
        {"mode": "q", "density": G2, "centers": CENTERS2, "radius": R0, "reps": 201},
        {"mode": "q", "density": G3, "centers": CENTERS3, "radius": R0, "reps": 51},
        {"mode": "q", "density": {"mixture": mix}, "centers": CENTERS_MIX, "radius": R0, "reps": 101},
        {"mode": "mmuc", "density": {"mixture": mix}, "radius": R0, "reps": 21},
    ]
    nat, node = run_fisst(cases)

    print(f"q(a) = P(|x - a| > r0), r0 = {R0}: 5 centres each (at the mean, near it, in the tails); "
          f"median time per call;\n|dq| = max |q - reference| (reference: the eigen form at "
          f"epsabs {REF_TOL:g}); fisst native and wasm (Node) are bit-identical.\n")
    print(f"{'case':<22} {'polar ms':>9} {'eigen ms':>9} {'native ms':>10} {'node ms':>9} "
          f"{'eigen/native':>13} {'eigen/node':>11} {'|dq| polar':>11} {'|dq| eigen':>11} {'|dq| fisst':>11}")
    # (repetitions of polar, of eigen); polar is not run for the mixture (10 x the 2D time).
    rows = [("2D Gaussian", G2, CENTERS2, 0, (20, 5)), ("3D Gaussian", G3, CENTERS3, 1, (1, 3)),
            ("10-comp. mixture, 2D", mix, CENTERS_MIX, 2, (None, 3))]
    for name, dens, centers, i, (reps_polar, reps_eigen) in rows:
        is_mix = isinstance(dens, list)
        q_e = (lambda d, c: q_mixture_eigen(d, c)) if is_mix else q_eigen
        ref = [reference(dens, c) for c in centers]
        t_e, v_e = scipy_q(q_e, dens, centers, reps_eigen)
        if reps_polar:
            t_p, v_p = scipy_q(q_polar, dens, centers, reps_polar)
            polar = (f"{1e3 * t_p:>9.2f}", f"{max(abs(a - b) for a, b in zip(v_p, ref)):>11.1e}")
        else:
            polar = (f"{'-':>9}", f"{'-':>11}")
        t_n, t_j = nat[i]["seconds"], node[i]["seconds"]
        d_e = max(abs(a - b) for a, b in zip(v_e, ref))
        d_f = max(abs(a - b) for a, b in zip(nat[i]["q"], ref))
        print(f"{name:<22} {polar[0]} {1e3 * t_e:>9.2f} {1e3 * t_n:>10.4f} {1e3 * t_j:>9.4f} "
              f"{t_e / t_n:>13.0f} {t_e / t_j:>11.0f} {polar[1]} {d_e:>11.1e} {d_f:>11.1e}")

    t_s, (a_s, q_s) = median_time(lambda: mmuc_scipy(mix), 1)
    a_f, q_f = nat[3]["center"], nat[3]["q"][0]
    q_f_ref = reference(mix, a_f)
    q_s_ref = reference(mix, a_s)
    print(f"\na* = argmin q(a) of the 10-component 2D mixture (r0 = {R0})\n")
    print(f"{'method':<40} {'time ms':>10} {'a*':>22} {'q(a*) (reference)':>20}")
    print(f"{'scipy Nelder-Mead x 11 starts (eigen q)':<40} {1e3 * t_s:>10.1f} "
          f"({a_s[0]:>9.6f}, {a_s[1]:>9.6f}) {q_s_ref:>20.12f}")
    print(f"{'fisst native (mmuc)':<40} {1e3 * nat[3]['seconds']:>10.3f} "
          f"({a_f[0]:>9.6f}, {a_f[1]:>9.6f}) {q_f_ref:>20.12f}")
    print(f"{'fisst node (mmucEstimate)':<40} {1e3 * node[3]['seconds']:>10.3f} {'(identical)':>22}")
    print(f"\nscipy/native {t_s / nat[3]['seconds']:.0f}x, scipy/node {t_s / node[3]['seconds']:.0f}x; "
          f"|a*_scipy - a*_fisst| = {math.dist(a_s, a_f):.1e}; q(a*): fisst - scipy = "
          f"{q_f_ref - q_s_ref:.1e} (< 0: fisst's centre holds more); "
          f"|q_fisst(a*) - reference| = {abs(q_f - q_f_ref):.1e}")


if __name__ == "__main__":
    sys.exit(main())
