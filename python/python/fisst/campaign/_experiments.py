"""The experiments a campaign can run. Each is a table of settings with their defaults, a check
of the settings (the core's, so the errors name the setting), a task (one run: a pandas
DataFrame of rows, one per step and variant), the columns its summary groups by and the
figure it draws. The task functions are module-level so that Dask can send them to worker
processes by reference."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

import numpy as np
import pandas as pd

from .. import _fisst

Settings = dict[str, Any]


@dataclass(frozen=True)
class Experiment:
    """One kind of campaign: its settings' defaults, its check, its one-run task and how its
    runs are summarised and drawn."""

    title: str
    defaults: Settings
    check: Callable[[Settings], None]
    task: Callable[[Settings, int, int], pd.DataFrame]
    keys: tuple[str, ...]
    values: tuple[str, ...]
    plot: Callable[..., Any]
    #: Columns that do not depend on the run (taken as they are in the summary, standard error 0).
    constants: tuple[str, ...] = ()
    #: Columns of wall time: the only ones that differ between two campaigns of one seed.
    timing: tuple[str, ...] = ()


# ---------------------------------------------------------------------------------------------
# "control": Fig. 3 of paper 004 (Ristic & Vo, "Sensor control for multi-object state-space
# estimation using random finite sets"): one run = one run seed with every scheme, as
# `compare_schemes` runs its run r; rows (scheme, step) with the OSPA distance (24) and its
# localisation (26) and cardinality (25) parts (c = 100 m, p = 2).

CONTROL_DEFAULTS: Settings = {
    "steps": 40,
    "schemes": ["renyi", "fisher", "pent", "random"],
    "particles": 750,
    "future_scans": 200,
    "alpha": 0.5,
    "start": [0.0, 0.0],
    "max_objects": 4,
}

OSPA_PARTS = ("distance", "localisation", "cardinality")


def control_check(settings: Settings) -> None:
    """The checks of ``compare_schemes`` on one run with these settings."""
    _fisst._campaign_control_check(runs=1, **settings)


def control_task(settings: Settings, run: int, run_seed: int) -> pd.DataFrame:
    """Run ``run`` (seed ``run_seed``) of every scheme, on one thread."""
    series = _fisst._campaign_control_run(run_seed, runs=1, **settings)
    schemes = list(settings["schemes"])
    steps = int(settings["steps"])
    frame = pd.DataFrame(
        {
            "run": np.full(len(schemes) * steps, run, dtype=np.int64),
            "run_seed": np.full(len(schemes) * steps, run_seed, dtype=np.uint64),
            "scheme": np.repeat(schemes, steps),
            "step": np.tile(np.arange(1, steps + 1, dtype=np.int64), len(schemes)),
        }
    )
    for i, part in enumerate(OSPA_PARTS):
        frame[part] = series[:, :, i].reshape(-1)
    return frame


CONTROL_NAMES = {"renyi": "Rényi", "fisher": "Fisher", "pent": "PENT", "random": "random"}


def control_plot(summary: pd.DataFrame, settings: Settings, runs: int, ax: Any = None) -> Any:
    """Fig. 3 of paper 004: the mean OSPA error per step of each scheme, with ±1 standard
    error bands (and the localisation and cardinality parts below it)."""
    import matplotlib.pyplot as plt

    if ax is None:
        fig, axes = plt.subplots(
            3, 1, figsize=(7.5, 8.0), sharex=True, constrained_layout=True,
            gridspec_kw={"height_ratios": [2, 1, 1]},
        )
    else:
        fig, axes = ax.figure, [ax]
    for panel, part in zip(axes, OSPA_PARTS):
        for scheme in settings["schemes"]:
            rows = summary[(summary["scheme"] == scheme) & (summary["quantity"] == part)]
            k, mean, se = rows["step"].to_numpy(), rows["mean"].to_numpy(), rows["standard_error"].to_numpy()
            label = CONTROL_NAMES.get(scheme, scheme)
            if scheme == "renyi":
                label += f" (α = {settings['alpha']:g})"
            (line,) = panel.plot(k, mean, label=label)
            panel.fill_between(k, mean - se, mean + se, color=line.get_color(), alpha=0.2, linewidth=0)
        panel.set_ylabel(f"OSPA {part} (m)" if part != "distance" else "mean OSPA error (m)")
        panel.grid(alpha=0.3)
    axes[0].legend()
    axes[0].set_title(
        f"Fig. 3 of paper 004: {runs} runs, N = {settings['particles']} particles, "
        f"M = {settings['future_scans']} future scans (c = 100 m, p = 2, ±1 s.e.)",
        fontsize=10,
    )
    axes[-1].set_xlabel("time step k")
    return fig


# ---------------------------------------------------------------------------------------------
# "airport": Section V-C, Figs. 6–8 of paper 001 (LeGrand & Ferrari, "Split Happens!"): one run =
# the seeded scenario of its run seed, then the GM Bernoulli filter (Algorithm 3) and the particle
# Bernoulli filter (its seed the run seed, as `airport_scenario` gives it) on the same reports;
# rows (filter, step).

AIRPORT_DEFAULTS: Settings = {"steps": 60, "particles": 5000, "mcmc_moves": 1}
AIRPORT_FILTERS = ("gm", "particle")
AIRPORT_VALUES = ("existence", "position_error", "position_rss", "covered", "seconds")


def airport_check(settings: Settings) -> None:
    _fisst._campaign_airport_check(**settings)


def airport_task(settings: Settings, run: int, run_seed: int) -> pd.DataFrame:
    """Run ``run``: both filters over the scenario of ``run_seed``, on one thread."""
    out = _fisst._campaign_airport_run(run_seed, **settings)
    steps = int(settings["steps"])
    n = len(AIRPORT_FILTERS) * steps
    frame = pd.DataFrame(
        {
            "run": np.full(n, run, dtype=np.int64),
            "run_seed": np.full(n, run_seed, dtype=np.uint64),
            "filter": np.repeat(AIRPORT_FILTERS, steps),
            "step": np.tile(np.arange(1, steps + 1, dtype=np.int64), len(AIRPORT_FILTERS)),
            "existence": out[:, :, 0].reshape(-1),
            "position_error": out[:, :, 1].reshape(-1),
            "position_rss": out[:, :, 2].reshape(-1),
            "nees": out[:, :, 3].reshape(-1),
        }
    )
    # inside the 3σ position ellipse (squared Mahalanobis distance ≤ 9), as a 0/1 float so that
    # its mean over runs is the coverage
    frame["covered"] = (frame["nees"] <= 9.0).astype(np.float64)
    frame["seconds"] = out[:, :, 4].reshape(-1)
    return frame


AIRPORT_LABELS = {
    "existence": "existence r(k|k)",
    "position_error": "position error (m)",
    "position_rss": "position covariance RSS (m)",
    "covered": "3σ coverage",
}


def airport_plot(summary: pd.DataFrame, settings: Settings, runs: int, ax: Any = None) -> Any:
    """Figs. 7–8 of paper 001 over the runs: existence, position error, covariance RSS and 3σ
    coverage per report time for both filters, ±1 standard error."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 2, figsize=(10, 6.5), sharex=True, constrained_layout=True)
    names = {"gm": "GM Bernoulli (Alg. 3)", "particle": f"particle Bernoulli ({settings['particles']} particles)"}
    for panel, quantity in zip(axes.flat, AIRPORT_LABELS):
        for name in AIRPORT_FILTERS:
            rows = summary[(summary["filter"] == name) & (summary["quantity"] == quantity)]
            t = rows["step"].to_numpy() * 15.0 / 60.0
            mean, se = rows["mean"].to_numpy(), rows["standard_error"].to_numpy()
            (line,) = panel.plot(t, mean, label=names[name])
            panel.fill_between(t, mean - se, mean + se, color=line.get_color(), alpha=0.2, linewidth=0)
        panel.set_ylabel(AIRPORT_LABELS[quantity])
        panel.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=9)
    for panel in axes[1]:
        panel.set_xlabel("time (min), a report every 15 s")
    fig.suptitle(f"Airport example of paper 001 (Section V-C, Figs. 7–8): {runs} seeded runs, ±1 s.e.", fontsize=11)
    return fig


# ---------------------------------------------------------------------------------------------
# "bounds": paper 002 (Rezaeian & Vo): the mean squared error of the optimal joint
# detector-estimator (MAP detection and the posterior mean; the cheaper rule on Z = ∅), by
# Monte Carlo, against the bound (31) it attains (Theorem 1) over a grid of the existence r and
# the detection probability P̄o, for the scalar linear-Gaussian system of Fig. 2; rows
# (detection_probability, existence).

BOUNDS_DEFAULTS: Settings = {
    "existence": [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9],
    "detection_probability": [0.25, 0.5, 0.75, 1.0],
    "prior_variance": 25.0,
    "posterior_variance": 1.0,
    "false_alarm_error": 25.0,
    "miss_error": 25.0,
    "samples": 2000,
    "empty_rule": "optimal",
}


def bounds_check(settings: Settings) -> None:
    _fisst._campaign_bounds_check(**settings)


def bounds_task(settings: Settings, run: int, run_seed: int) -> pd.DataFrame:
    """Run ``run``: the Monte Carlo at every grid point with seed ``run_seed``, on one thread."""
    out = _fisst._campaign_bounds_run(run_seed, **settings)
    po, r = list(settings["detection_probability"]), list(settings["existence"])
    n = len(po) * len(r)
    return pd.DataFrame(
        {
            "run": np.full(n, run, dtype=np.int64),
            "run_seed": np.full(n, run_seed, dtype=np.uint64),
            "detection_probability": np.repeat(np.asarray(po, dtype=np.float64), len(r)),
            "existence": np.tile(np.asarray(r, dtype=np.float64), len(po)),
            "mse": out[:, :, 0].reshape(-1),
            "mse_se": out[:, :, 1].reshape(-1),
            "bound": out[:, :, 2].reshape(-1),
            "map_bound": out[:, :, 3].reshape(-1),
        }
    )


def bounds_plot(summary: pd.DataFrame, settings: Settings, runs: int, ax: Any = None) -> Any:
    """Fig. 2 (left) of paper 002 with its Monte Carlo: the bound (31) against r for each P̄o
    (lines; dashed: MAP detection on Z = ∅) and the optimal detector-estimator's mean squared
    error over the runs (markers, ±2 standard errors)."""
    import matplotlib.pyplot as plt

    if ax is None:
        fig, ax = plt.subplots(figsize=(7.5, 4.8), constrained_layout=True)
    else:
        fig = ax.figure
    for po in settings["detection_probability"]:
        rows = summary[summary["detection_probability"] == po]
        get = lambda q, col="mean": rows[rows["quantity"] == q][col].to_numpy()  # noqa: E731
        r = rows[rows["quantity"] == "mse"]["existence"].to_numpy()
        (line,) = ax.plot(r, get("bound"), label=f"P̄o = {po:g}: bound (31)")
        ax.plot(r, get("map_bound"), color=line.get_color(), ls="--", lw=1)
        ax.errorbar(r, get("mse"), yerr=2 * get("mse", "standard_error"), fmt="o", ms=4,
                    color=line.get_color(), capsize=2)
    ax.set_xlabel("existence probability r")
    ax.set_ylabel("mean squared error")
    ax.set_title(
        f"Fig. 2 of paper 002 with Monte Carlo: {runs} runs x {settings['samples']} draws per point; "
        f"σf² = {settings['prior_variance']:g}, σh² = {settings['posterior_variance']:g}, "
        f"e0² = {settings['false_alarm_error']:g}, e1² = {settings['miss_error']:g}\n"
        "markers: optimal detector-estimator (±2 s.e.); dashed: MAP detection on Z = ∅",
        fontsize=9,
    )
    ax.legend(fontsize=8)
    return fig


EXPERIMENTS: dict[str, Experiment] = {
    "control": Experiment(
        title="Fig. 3 of paper 004: sensor-control schemes, OSPA error per step",
        defaults=CONTROL_DEFAULTS,
        check=control_check,
        task=control_task,
        keys=("scheme", "step"),
        values=OSPA_PARTS,
        plot=control_plot,
    ),
    "airport": Experiment(
        title="Section V-C of paper 001: both Bernoulli filters on the airport reports",
        defaults=AIRPORT_DEFAULTS,
        check=airport_check,
        task=airport_task,
        keys=("filter", "step"),
        values=AIRPORT_VALUES,
        plot=airport_plot,
        timing=("seconds",),
    ),
    "bounds": Experiment(
        title="paper 002: the optimal detector-estimator's MSE against the bound (31)",
        defaults=BOUNDS_DEFAULTS,
        check=bounds_check,
        task=bounds_task,
        keys=("detection_probability", "existence"),
        values=("mse",),
        plot=bounds_plot,
        constants=("bound", "map_bound"),
    ),
}
