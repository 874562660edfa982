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

    name: str
    title: str
    defaults: Settings
    check: Callable[[Settings], None]
    task: Callable[[Settings, int, int], pd.DataFrame]
    keys: tuple[str, ...]
    values: tuple[str, ...]
    plot: Callable[..., Any]


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


EXPERIMENTS: dict[str, Experiment] = {
    "control": Experiment(
        name="control",
        title="Fig. 3 of paper 004: sensor-control schemes, OSPA error per step",
        defaults=CONTROL_DEFAULTS,
        check=control_check,
        task=control_task,
        keys=("scheme", "step"),
        values=OSPA_PARTS,
        plot=control_plot,
    ),
}
