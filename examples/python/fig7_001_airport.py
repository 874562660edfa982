"""Fig. 7(b) and Fig. 8(a) of paper 001 (LeGrand & Ferrari, "Split Happens! Imprecise and
negative information in Gaussian mixture random finite set filtering", Section V-C): a person
walks through an airport concourse and is reported only as "near anchor a" (p_D = 0.9 inside
the anchors' discs, Poisson clutter λ_c = 0.25). The GM Bernoulli filter (Algorithm 3: the
density split along the report and field-of-view boundaries) and the Bernoulli particle filter
run on the same seeded reports: (a) the posterior probability of existence r_{k|k} over time
(Fig. 7(b)), falling after consecutive misdetections (shaded); (b) the position error of the
MMSE estimate and the root sum square (RSS) of its conditional covariance (Fig. 8(a)).

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


def main(out="fig7_001_airport.png", seed=3, particles=5000):
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
    for k, reported in enumerate(s.reports):
        scan = [discs[a] for a in reported]
        for name, f in (("GM", gm), ("PF", pf)):
            f.predict()
            f.update(scan)
            existence[name].append(f.existence)
            e = f.estimate()
            error[name].append(np.linalg.norm(np.asarray(e.mean)[:2] - truth[k, :2]))
            rss[name].append(np.sqrt(np.trace(np.asarray(e.cov)[:2, :2])))
    missed = [k for k, a in enumerate(s.true_reports) if a is None]

    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.4), constrained_layout=True)
    for ax in (a, b):
        for k in missed:
            ax.axvspan(t[k] - s.dt / 2, t[k] + s.dt / 2, color="#eeeeee", lw=0)
        ax.set_xlabel("time t [s]")
        ax.set_xlim(0, t[-1] + s.dt / 2)
    a.plot(t, existence["GM"], "-o", ms=3, label="GM Bernoulli filter")
    a.plot(t, existence["PF"], "--s", ms=3, label=f"Bernoulli PF ({particles} particles)")
    a.set_ylim(0, 1.05)
    a.set_ylabel(r"probability of existence $r_{k|k}$")
    a.set_title("(a) Fig. 7(b): existence (grey: no true report)")
    a.legend(loc="lower right", fontsize=8)
    for name, style in (("GM", "-"), ("PF", "--")):
        b.plot(t, error[name], style, label=f"{name} MMSE position error")
        b.plot(t, rss[name], style, alpha=0.6, label=f"{name} covariance RSS")
    b.set_ylabel("position [dist]")
    b.set_title("(b) Fig. 8(a): position error and conditional RSS")
    b.legend(fontsize=8)
    fig.suptitle(f"Paper 001, airport example (Section V-C), seed {s.seed}")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main(*sys.argv[1:2]))
