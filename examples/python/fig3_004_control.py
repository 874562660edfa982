"""Fig. 3 of paper 004 (Ristic & Vo, "Sensor control for multi-object state-space estimation
using random finite sets"), at a reduced size: the mean OSPA error (c = 100, p = 2) of the
SMC multi-object filter over time for the four sensor-control schemes (Rényi divergence,
Fisher information, PENT, random), averaged over seeded Monte Carlo runs, with ±1 standard
error. The paper uses 750 particles, 200 future scans and 500 runs; `main(runs=..., ...)`
takes the full size.

    python examples/python/fig3_004_control.py [out.png]
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import fisst  # noqa: E402

NAMES = {"renyi": "Rényi (α = 0.5)", "fisher": "Fisher", "pent": "PENT", "random": "random"}


def main(out="fig3_004_control.png", runs=8, steps=40, particles=300, future_scans=40, seed=2024):
    c = fisst.compare_schemes(runs=runs, steps=steps, particles=particles, future_scans=future_scans, seed=seed)
    fig, ax = plt.subplots(figsize=(7.5, 4.6), constrained_layout=True)
    k = np.arange(1, c.steps + 1)
    for s in c.schemes:
        mean, se = s.distance.mean, s.distance.standard_error
        ax.plot(k, mean, label=NAMES.get(s.scheme, s.scheme))
        ax.fill_between(k, mean - se, mean + se, alpha=0.2)
    ax.set_xlabel("time step k")
    ax.set_ylabel("mean OSPA error (m), c = 100, p = 2")
    ax.set_title(f"Fig. 3 of paper 004, reduced: {runs} runs, N = {particles} particles, M = {future_scans} future scans")
    ax.legend()
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main(*sys.argv[1:2]))
