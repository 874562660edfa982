"""Figs. 7 and 8 of paper 001 (LeGrand & Ferrari, "Split Happens! Imprecise and negative
information in Gaussian mixture random finite set filtering", Section V-C): a person walks
through an airport concourse and is reported only as "near anchor a" (p_D = 0.9 inside the
anchors' discs, Poisson clutter λ_c = 0.25). The GM Bernoulli filter (Algorithm 3: the density
split along the report and field-of-view boundaries) and the Bernoulli particle filter run on
the same seeded reports:

- Fig. 7(a): the true trajectory, the GM filter's MMSE estimates and its position density at
  k = 15, 25, 55 (t = 225, 375, 825 s), over the concourse map (anchors' discs, walls);
- Fig. 7(b): the posterior probability of existence r_{k|k} over time, falling after
  consecutive misdetections (shaded);
- Fig. 8(a) and (b): the error of the MMSE estimate and the root sum square (RSS) of its
  conditional covariance, for position and for velocity.

    python examples/python/fig7_001_airport.py [out.png]
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import fisst  # noqa: E402


def plain(v):
    """A result as plain dicts and lists (to pass it back as keyword arguments)."""
    if isinstance(v, (fisst.Result, dict)):
        return {k: plain(x) for k, x in v.items()}
    if isinstance(v, np.ndarray):
        return v.tolist()
    if isinstance(v, (list, tuple)):
        return [plain(x) for x in v]
    return v


def position_density(mixture, xs, ys):
    """The GM posterior's position marginal (the weighted sum of each component's 2-D
    Gaussian over the first two state coordinates) on the grid ``xs`` × ``ys``."""
    gx, gy = np.meshgrid(xs, ys)
    pts = np.stack([gx.ravel(), gy.ravel()], axis=1)
    total = np.zeros(len(pts))
    for c in mixture:
        mean, cov = np.asarray(c.mean)[:2], np.asarray(c.cov)[:2, :2]
        d = pts - mean
        sol = np.linalg.solve(cov, d.T).T
        total += c.weight * np.exp(-0.5 * np.sum(d * sol, axis=1)) / (2 * np.pi * np.sqrt(np.linalg.det(cov)))
    return total.reshape(gx.shape)


def draw_map(ax, s):
    """The concourse: the walls and kiosks (the exclusion boxes inside it) and the anchors'
    report discs."""
    for region in s.exclusions:
        if "box" in region:
            box = region["box"]
            lo, hi = np.asarray(box.min), np.asarray(box.max)
            ax.add_patch(plt.Rectangle(lo, *(hi - lo), color="#bbbbbb", lw=0, zorder=0))
    for anchor in s.anchors:
        ax.add_patch(plt.Circle(anchor.position, anchor.radius, fill=False, ls=":", lw=0.7, color="#7a7a7a"))
        ax.annotate(anchor.name, anchor.position, fontsize=6.5, ha="center", va="center", color="#555555")
    box = s.concourse["box"]
    ax.set_xlim(box.min[0], box.max[0])
    ax.set_ylim(box.min[1], box.max[1])
    ax.set_aspect("equal")


def main(out="fig7_001_airport.png", seed=3, particles=5000, snapshots=(15, 25, 55)):
    s = fisst.airport_scenario(seed=seed, steps=60)
    config = plain(s.config)
    model = {k: v for k, v in config.items() if k not in ("particles", "mcmc_moves", "seed")}
    gm = fisst.GmBernoulliFilter(**model)
    pf = fisst.ParticleBernoulliFilter(**model, particles=particles, mcmc_moves=config["mcmc_moves"], seed=seed)
    discs = [{"ball": {"center": a.position.tolist(), "radius": a.radius}} for a in s.anchors]
    t = np.array([p.t for p in s.truth])
    truth = np.array([p.state for p in s.truth])
    existence = {"GM": [], "PF": []}
    error = {"GM": [], "PF": []}
    rss = {"GM": [], "PF": []}
    verror = {"GM": [], "PF": []}
    vrss = {"GM": [], "PF": []}
    gm_means, densities = [], {}
    for k, reported in enumerate(s.reports):
        scan = [discs[a] for a in reported]
        for name, f in (("GM", gm), ("PF", pf)):
            f.predict()
            f.update(scan)
            existence[name].append(f.existence)
            e = f.estimate()
            mean, cov = np.asarray(e.mean), np.asarray(e.cov)
            error[name].append(np.linalg.norm(mean[:2] - truth[k, :2]))
            rss[name].append(np.sqrt(np.trace(cov[:2, :2])))
            verror[name].append(np.linalg.norm(mean[2:] - truth[k, 2:]))
            vrss[name].append(np.sqrt(np.trace(cov[2:, 2:])))
            if name == "GM":
                gm_means.append(mean[:2])
                if k + 1 in snapshots:  # k counts from 0; the paper's time step k from 1
                    densities[k + 1] = f.mixture
    missed = [k for k, a in enumerate(s.true_reports) if a is None]
    gm_means = np.array(gm_means)

    fig = plt.figure(figsize=(13, 6.4), constrained_layout=True)
    grid = fig.add_gridspec(2, 3, height_ratios=[0.55, 1.0])
    m = fig.add_subplot(grid[0, :])
    draw_map(m, s)
    box = s.concourse["box"]
    xs = np.linspace(box.min[0], box.max[0], 601)
    ys = np.linspace(box.min[1], box.max[1], 61)
    for step, colour in zip(snapshots, ("#9467bd", "#2ca02c", "#d62728")):
        density = position_density(densities[step], xs, ys)
        levels = density.max() * np.array([0.05, 0.25, 0.6])
        m.contour(xs, ys, density, levels=levels, colors=colour, linewidths=0.9)
        m.plot(*gm_means[step - 1], "o", mfc="none", mec=colour, ms=9, label=f"density at k = {step} (t = {t[step - 1]:.0f} s)")
    m.plot(truth[:, 0], truth[:, 1], "k-", lw=1.2, label="true trajectory")
    m.plot(gm_means[:, 0], gm_means[:, 1], "x", color="C0", ms=4, label="GM MMSE estimates")
    m.set_xlabel("x [dist]")
    m.set_ylabel("y [dist]")
    m.set_title("(a) Fig. 7(a): trajectory, GM estimates and position densities (grey: walls; dotted: anchors' report discs)")
    m.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.0, 1.0), frameon=False)

    a, b, c = (fig.add_subplot(grid[1, i]) for i in range(3))
    for ax in (a, b, c):
        for k in missed:
            ax.axvspan(t[k] - s.dt / 2, t[k] + s.dt / 2, color="#eeeeee", lw=0)
        ax.set_xlabel("time t [s]")
        ax.set_xlim(0, t[-1] + s.dt / 2)
    a.plot(t, existence["GM"], "-o", ms=3, label="GM Bernoulli filter")
    a.plot(t, existence["PF"], "--s", ms=3, color="C1", label=f"Bernoulli PF ({particles} particles)")
    a.set_ylim(0, 1.05)
    a.set_ylabel(r"probability of existence $r_{k|k}$")
    a.set_title("(b) Fig. 7(b): existence (grey: no true report)")
    a.legend(loc="lower right", fontsize=8)
    for name, colour in (("GM", "C0"), ("PF", "C1")):
        b.plot(t, error[name], "-", color=colour, lw=1.1, label=f"{name} MMSE error")
        b.plot(t, rss[name], ":", color=colour, lw=1.8, label=f"{name} covariance RSS")
        c.plot(t, verror[name], "-", color=colour, lw=1.1, label=f"{name} MMSE error")
        c.plot(t, vrss[name], ":", color=colour, lw=1.8, label=f"{name} covariance RSS")
    b.set_ylabel("position [dist]")
    b.set_title("(c) Fig. 8(a): position error and RSS")
    b.legend(fontsize=8)
    c.set_ylabel("velocity [dist/s]")
    c.set_title("(d) Fig. 8(b): velocity error and RSS")
    c.legend(fontsize=8)
    fig.suptitle(f"Paper 001, airport example (Section V-C), seed {s.seed}")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main(*sys.argv[1:2]))
