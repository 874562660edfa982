"""Fig. 3 of paper 000 (Narykov, Üney & Ralph, "Optimal Bernoulli point estimation with
applications"): the optimal reporting threshold Γ of eq. (11) against the standard deviation
σ of the spatial density, (a) for the MPE costs at several tolerance radii r0 and (b) for the
MMOL costs at r0 = 1 and several ratios c_M / c_A. A Bernoulli is reported when its existence
probability exceeds Γ; where Γ > 1 it is never reported.

    python examples/python/fig3_000_threshold.py [out.png]
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import fisst  # noqa: E402


def main(out="fig3_000_threshold.png"):
    sigmas = np.concatenate([[0.001], 0.025 * np.arange(1, 401)])
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.4), constrained_layout=True, sharey=True)
    for r0 in [0.1, 1, 3, 5, 10]:
        a.plot(sigmas, fisst.bernoulli_threshold_curve(sigmas=sigmas, radius=r0, costs="mpe"), label=f"r₀ = {r0}")
    a.set_title("(a) MPE costs")
    for k in [0, 0.25, 0.5, 0.75, 1]:
        gamma = fisst.bernoulli_threshold_curve(sigmas=sigmas, radius=1.0, costs={"mmol": {"asset": 1.0, "countermeasure": k}})
        b.plot(sigmas, gamma, label=f"c_M / c_A = {k}")
    b.set_title("(b) MMOL costs, r₀ = 1")
    for ax in (a, b):
        ax.axhline(0.5, color="black", ls="--", lw=1, label="conventional 0.5")
        ax.axhspan(1, 1.2, color="#fde2e2")
        ax.set_xlim(0, 10)
        ax.set_ylim(0, 1.2)
        ax.set_xlabel("σ, standard deviation of the spatial density")
        ax.legend(fontsize=8)
    a.set_ylabel("reporting threshold Γ")
    fig.suptitle("Fig. 3 of paper 000: the optimal existence threshold Γ (11) against σ (1-D)")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main(*sys.argv[1:2]))
