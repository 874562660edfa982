"""Fig. 2 (left) of paper 002 (Rezaeian & Vo, error bounds for joint detection and
estimation): the bound (31) on the risk of any joint detector-estimator against the
existence probability r, without clutter, for a family of detection probabilities P̄o; the
prior variance σf² = 25, the linear-Gaussian posterior variance σh² = 1 (z = x + v) and the
errors charged for a false alarm and a miss e0 = e1 = 25. The dashed curves use the MAP
detector on Z = ∅ (Section IV-A).

    python examples/python/fig2_002_bounds.py [out.png]
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import fisst  # noqa: E402


def main(out="fig2_002_bounds.png", vf=25.0, vh=1.0, e0=25.0, e1=25.0):
    noise = vf * vh / (vf - vh)
    info = fisst.gaussian_fisher_information(prior_variance=vf, gain=1.0, noise_variance=noise)
    rs = np.linspace(0, 1, 201)
    fig, ax = plt.subplots(figsize=(7, 4.6), constrained_layout=True)
    for po, colour in zip([0, 0.25, 0.5, 0.75, 1], ["#d55e00", "#e69f00", "#009e73", "#56b4e9", "#cc79a7"]):
        bounds, maps = [], []
        for r in rs:
            b = fisst.jde_bound_no_clutter(existence=r, detection_probability=po, prior_variance=vf,
                                           posterior_variance=info.posterior_variance, false_alarm_error=e0, miss_error=e1)
            bounds.append(b.bound)
            maps.append(b.map_bound)
        ax.plot(rs, bounds, color=colour, label=f"P̄o = {po}")
        ax.plot(rs, maps, color=colour, ls="--", lw=1)
    ax.set_xlabel("existence probability r")
    ax.set_ylabel("bound on the risk (31)")
    ax.set_title(f"Fig. 2 (left) of paper 002: the bound (31) without clutter\nσf² = {vf:g}, σh² = {vh:g}, e0 = {e0:g}, e1 = {e1:g}; dashed: MAP detection on Z = ∅", fontsize=10)
    ax.legend()
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main(*sys.argv[1:2]))
