"""Fig. 1 of paper 003 (García-Fernández & Svensson, "Spooky effect in optimal OSPA estimation
and how GOSPA solves it"): for a multi-Bernoulli of two far-apart components with existence
probabilities (r1, r2), how many components each estimator reports. OSPA's optimal estimate
reports both components where GOSPA's reports one or none: the spooky effect.

    python examples/python/fig1_003_decision_maps.py [out.png]
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

import fisst  # noqa: E402

ESTIMATORS = [("gospa", "GOSPA (α = 2)"), ("ospa", "OSPA"), ("uospa", "UOSPA"), ("mam", "MaM"), ("jom", "JoM"), ("map-cardinality", "MAP cardinality")]
# decisions: 0 none, 1 component 1, 2 component 2, 3 both
COLOURS = ListedColormap(["#f0f0f0", "#56b4e9", "#e69f00", "#009e73"])


def main(out="fig1_003_decision_maps.png", resolution=200):
    fig, axes = plt.subplots(2, 3, figsize=(11, 7.4), constrained_layout=True)
    for ax, (estimator, title) in zip(axes.flat, ESTIMATORS):
        m = fisst.mb_decision_map(estimator=estimator, resolution=resolution)
        grid = np.asarray(m.decisions).reshape(m.resolution, m.resolution)  # row: r2, column: r1
        ax.imshow(grid, origin="lower", extent=(0, 1, 0, 1), cmap=COLOURS, vmin=0, vmax=3, interpolation="nearest")
        ax.set_title(title)
        ax.set_xlabel("r₁")
        ax.set_ylabel("r₂")
    handles = [plt.Rectangle((0, 0), 1, 1, color=COLOURS(i)) for i in range(4)]
    fig.legend(handles, ["report none", "report component 1", "report component 2", "report both"], loc="outside lower center", ncols=4)
    fig.suptitle("Fig. 1 of paper 003: which components each estimator reports (c = 1, p = 2)")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main(*sys.argv[1:2]))
