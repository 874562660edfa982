"""Figs 9–10 of paper 001 (LeGrand & Ferrari, "Split Happens! Imprecise and negative information
in Gaussian mixture random finite set filtering", Section VII): sensor placement by the variance
of the number of objects in a field of view. A seeded multi-Bernoulli scene of 100 potential
objects (existences in [0.35, 1)); (a) its PHD Σ r N(x; m, P) (eq. (99), Fig. 9) with the means
as orange circles and the 1 × 1 FoV of largest count variance in white; (b) that variance
(eq. (88)'s Σ r_S (1 − r_S)) as a function of the FoV centre (Fig. 10), its maximum a red star;
(c) the pmf of the number of objects in the best FoV (eq. (88)).

    python examples/python/fig9_001_placement.py [out.png]
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

import fisst  # noqa: E402

EXTENT = 3.0
COUNT = 121  # FoV centres (and PHD positions) per axis: a step of 0.05
SIDE = 1.0  # the paper's 1 × 1 FoV


def main(out="fig9_001_placement.png", count=100, seed=1):
    scene = fisst.placement_scene(count=count, seed=seed, extent=EXTENT).multi_bernoulli
    grid = {"x": (-EXTENT, EXTENT, COUNT), "y": (-EXTENT, EXTENT, COUNT)}
    mixture = [{"weight": c.existence, "mean": c.mean, "cov": c.cov} for c in scene]
    phd = fisst.mixture_density_grid(mixture=mixture, grid=grid)  # (ny, nx)
    vmap = fisst.fov_variance_map(multi_bernoulli=scene, fov_size=(SIDE, SIDE), grid=grid)
    cx, cy = vmap.argmax
    half = SIDE / 2
    best = fisst.fov_cardinality(
        rfs={"multi_bernoulli": scene}, fov={"box": {"min": [cx - half, cy - half], "max": [cx + half, cy + half]}}
    )

    step = 2 * EXTENT / (COUNT - 1)
    span = [-EXTENT - step / 2, EXTENT + step / 2] * 2  # pixels centred on the grid points
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(15, 4.8), constrained_layout=True,
                                  gridspec_kw={"width_ratios": [1, 1, 0.8]})
    im = a.imshow(phd, origin="lower", extent=span, cmap="viridis")
    means = np.array([s.mean for s in scene])
    a.scatter(means[:, 0], means[:, 1], s=14, facecolors="none", edgecolors="orange", lw=1)
    a.add_patch(Rectangle((cx - half, cy - half), SIDE, SIDE, fill=False, ec="white", lw=2))
    a.set_title(f"(a) PHD of the {count}-component multi-Bernoulli (99),\nthe best FoV in white")
    fig.colorbar(im, ax=a, shrink=0.85, label="PHD")
    im = b.imshow(vmap.variance, origin="lower", extent=span, cmap="cividis")
    b.plot([cx], [cy], marker="*", ms=16, color="red", mec="white")
    b.set_title(f"(b) Var of the FoV count against the FoV centre;\nmax {vmap.max:.3f} at ({cx:.2f}, {cy:.2f})")
    fig.colorbar(im, ax=b, shrink=0.85, label="Var[|X ∩ S|]")
    for ax in (a, b):
        ax.set_xlabel("x")
        ax.set_ylabel("y")
    n = np.arange(len(best.pmf))
    c.bar(n, best.pmf, color="tab:blue")
    shown = int(np.nonzero(best.pmf > 1e-4)[0].max()) + 2  # up to where the tail is negligible
    c.set_xlim(-0.5, shown - 0.5)
    c.set_xlabel("n, objects in the best FoV")
    c.set_ylabel("ρ_S(n)")
    c.set_title(f"(c) FoV cardinality pmf (88) there:\nmean {best.mean:.3f}, variance {best.variance:.3f}")
    fig.suptitle("Figs 9–10 of paper 001: sensor placement by the FoV cardinality variance (Section VII)")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main(*sys.argv[1:2]))
