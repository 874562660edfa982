"""Monte Carlo campaigns: seeded runs of a paper's experiment on Dask, resumable, with a
progress bar, a tidy summary and the paper's figure.

    import fisst.campaign
    c = fisst.campaign.run("control", runs=200, seed=1, out="study/")   # local cluster
    c.summary()          # mean and standard error per scheme, step and OSPA part
    c.plot().savefig("fig3.png")

Each run is one task with the seed ``run_seeds(seed)[run]``, derived exactly as
``fisst.compare_schemes`` derives its ``run_seeds``, so any run can be replayed alone, and a
task runs on one thread: the engine's workers are the parallelism. The result table is the
same, bit for bit, whether the campaign ran serially (``client="serial"``), on a local cluster
of threads (the default), on a local cluster of processes, or on a cluster (a
``distributed.Client`` or a scheduler address ``"tcp://host:8786"``). With ``out`` every
finished run is written at once (one Parquet part per run, atomically), and a campaign run
again with the same ``out`` and settings computes only the runs that are not there yet.

Experiments (``EXPERIMENTS[name].defaults`` lists the settings and their defaults):

- ``"control"``: Fig. 3 of paper 004 (Ristic & Vo): every sensor-control scheme on the same run
  seed; rows (scheme, step) with the OSPA distance and its localisation and cardinality parts.
  Settings as ``fisst.compare_schemes``: ``steps=40``, ``schemes=["renyi", "fisher", "pent",
  "random"]``, ``particles=750``, ``future_scans=200``, ``alpha=0.5``, ``start=[0, 0]``,
  ``max_objects=4``.
- ``"airport"``: Section V-C of paper 001 (LeGrand & Ferrari): the seeded airport scenario, the
  GM and the particle Bernoulli filters on the same reports; rows (filter, step) with the
  existence, the position error, the covariance RSS, the squared Mahalanobis distance ``nees``,
  ``covered`` (inside the 3σ ellipse) and ``seconds`` (wall time of the step: the one column
  that is not the same between two campaigns). Settings ``steps=60``, ``particles=5000``,
  ``mcmc_moves=1``.
- ``"bounds"``: paper 002 (Rezaeian & Vo): the optimal joint detector-estimator's mean squared
  error by Monte Carlo against the bound (31) it attains, over a grid of ``existence`` and
  ``detection_probability`` (Fig. 2's system: ``prior_variance=25``,
  ``posterior_variance=1``, ``false_alarm_error=25``, ``miss_error=25``), ``samples=2000``
  draws per grid point and run, ``empty_rule="optimal"``.

From a shell: ``python -m fisst.campaign control --runs 200 --seed 1 --scheduler tcp://host:8786
--out study/`` prints the summary and writes ``study/figure.png``.
"""

from __future__ import annotations

import difflib
import math
import os
import sys
import time
from pathlib import Path
from typing import Any, Callable, Iterator, Union

import numpy as np
import pandas as pd

from .. import __version__
from .. import _fisst
from . import _store
from ._experiments import EXPERIMENTS, Experiment

__all__ = ["Campaign", "EXPERIMENTS", "run", "run_seeds"]

#: How long a scheduler address may take to answer before ``run`` gives up (seconds).
CONNECT_TIMEOUT = 10.0

Progress = Union[bool, Callable[[int, int], None]]


def run_seeds(seed: int, runs: int) -> list[int]:
    """The seeds of runs ``0 … runs − 1`` of a campaign with master seed ``seed``: the
    ``run_seeds`` of ``fisst.compare_schemes(seed=seed, runs=runs)``. A prefix does not depend
    on ``runs`` (extending a campaign keeps its first runs)."""
    _check_int("seed", seed, 0, 2**64 - 1)
    _check_int("runs", runs, 1, 1_000_000)
    return list(_fisst._campaign_run_seeds(seed, runs))


class Campaign:
    """The outcome of :func:`run`: ``table`` (one row per run, step and variant, in run order),
    ``summary()``, ``plot()``, and what it was run with (``experiment``, ``seed``, ``runs``,
    ``settings``, ``out``; ``computed`` is how many runs this call computed, the rest were
    read from ``out``)."""

    def __init__(self, experiment: str, seed: int, runs: int, settings: dict[str, Any],
                 table: pd.DataFrame, out: Path | None, computed: int) -> None:
        self.experiment = experiment
        self.seed = seed
        self.runs = runs
        self.settings = settings
        self.table = table
        self.out = out
        self.computed = computed

    def __repr__(self) -> str:
        where = f", out={str(self.out)!r}" if self.out is not None else ""
        return (f"Campaign({self.experiment!r}, runs={self.runs}, seed={self.seed}{where}, "
                f"rows={len(self.table)}, computed={self.computed})")

    def summary(self) -> pd.DataFrame:
        """A tidy DataFrame: one row per group of the experiment (``scheme`` and ``step`` for
        ``"control"``) and ``quantity``, with ``mean``, ``standard_error`` (sample standard
        deviation / √runs; 0 for one run) and ``runs``. For ``"control"`` it equals
        ``fisst.compare_schemes`` on the same runs to 1e-12 relative."""
        return summarise(self.table, EXPERIMENTS[self.experiment])

    def plot(self, ax: Any = None) -> Any:
        """The paper's figure (matplotlib): for ``"control"``, Fig. 3 of paper 004 (mean OSPA
        error per step and scheme with ±1 standard error bands, and its two parts)."""
        return EXPERIMENTS[self.experiment].plot(self.summary(), self.settings, self.runs, ax=ax)


def summarise(table: pd.DataFrame, experiment: Experiment) -> pd.DataFrame:
    keys = list(experiment.keys)
    rows = []
    for group, frame in table.groupby(keys, sort=False):
        group = group if isinstance(group, tuple) else (group,)
        n = len(frame)
        for quantity in experiment.constants:
            rows.append((*group, quantity, float(frame[quantity].iloc[0]), 0.0, n))
        for quantity in experiment.values:
            x = frame[quantity].to_numpy(dtype=np.float64)
            # as compare_schemes sums: in run order (a cumulative sum is sequential)
            mean = float(np.cumsum(x)[-1]) / n
            var = float(np.cumsum((x - mean) * (x - mean))[-1]) / (n - 1) if n > 1 else 0.0
            rows.append((*group, quantity, mean, math.sqrt(var / n), n))
    out = pd.DataFrame(rows, columns=[*keys, "quantity", "mean", "standard_error", "runs"])
    return out.sort_values([keys[0], "quantity", *keys[1:]], kind="stable").reset_index(drop=True)


def _check_int(name: str, value: Any, low: int, high: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an int, got {type(value).__name__}")
    if not low <= int(value) <= high:
        raise ValueError(f"{name} must be in [{low}, {high}], got {value}")
    return int(value)


def _is_client(value: Any) -> bool:
    try:
        import distributed
    except ImportError:  # pragma: no cover - the extra is not installed
        return False
    return isinstance(value, distributed.Client)


def _experiment(name: Any) -> Experiment:
    if not isinstance(name, str):
        raise TypeError(f"experiment must be a str, got {type(name).__name__}")
    if name not in EXPERIMENTS:
        close = difflib.get_close_matches(name, EXPERIMENTS, n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise ValueError(
            f"experiment must be one of {', '.join(map(repr, EXPERIMENTS))}, got {name!r}{hint}"
        )
    return EXPERIMENTS[name]


class _Bar:
    """A one-line progress bar on stderr: runs done, elapsed time, an estimate of the time
    left (from the runs computed so far), or a callable ``progress(done, total)``."""

    def __init__(self, progress: Progress, name: str, total: int, done: int) -> None:
        self.callback = progress if callable(progress) else None
        self.show = progress is True
        self.name, self.total, self.start_done = name, total, done
        self.start = time.monotonic()
        self.update(done)

    def update(self, done: int) -> None:
        if self.callback is not None:
            self.callback(done, self.total)
        if not self.show:
            return
        elapsed = time.monotonic() - self.start
        new = done - self.start_done
        left = f", ~{_clock(elapsed / new * (self.total - done))} left" if new and done < self.total else ""
        width = 24
        filled = int(width * done / self.total) if self.total else width
        sys.stderr.write(f"\r{self.name}: [{'#' * filled}{'.' * (width - filled)}] "
                         f"{done}/{self.total} runs, {_clock(elapsed)}{left}   ")
        if done >= self.total:
            sys.stderr.write("\n")
        sys.stderr.flush()


def _clock(seconds: float) -> str:
    s = int(round(seconds))
    return f"{s // 3600}:{s // 60 % 60:02d}:{s % 60:02d}" if s >= 3600 else f"{s // 60}:{s % 60:02d}"


class _Serial:
    """Runs the tasks one after another in this process (``client="serial"``)."""

    def results(self, task: Callable[..., pd.DataFrame], jobs: list[tuple[Any, ...]]) -> Iterator[tuple[int, pd.DataFrame]]:
        for job in jobs:
            yield job[1], task(*job)

    def close(self) -> None:
        pass


class _Dask:
    """Runs the tasks on a Dask ``distributed`` cluster: the client given, a client of the
    scheduler at an address, or (``None``) a new local cluster of threads on this machine's
    cores. Finished runs come back as they finish; a worker lost mid-task costs the task a
    retry."""

    def __init__(self, client: Any) -> None:
        try:
            import distributed
        except ImportError:  # pragma: no cover - the extra is not installed
            raise ImportError(
                "fisst.campaign needs dask[distributed] (pip install 'fisst[campaign]'), or "
                "client='serial'"
            ) from None
        self.own: list[Any] = []
        if client is None:
            # no dashboard; the scheduler's HTTP routes on a free port (not 8787, which another
            # cluster on the machine may hold)
            cluster = distributed.LocalCluster(
                n_workers=1, threads_per_worker=os.cpu_count() or 1, processes=False,
                dashboard_address=None, scheduler_kwargs={"dashboard_address": ":0"},
            )
            self.own.append(cluster)
            client = distributed.Client(cluster)
            self.own.insert(0, client)
        elif isinstance(client, str):
            try:
                client = distributed.Client(client, timeout=f"{CONNECT_TIMEOUT}s")
            except (OSError, TimeoutError) as e:
                raise ConnectionError(
                    f"client: no Dask scheduler answered at {client!r} within "
                    f"{CONNECT_TIMEOUT:g} s ({type(e).__name__})"
                ) from None
            self.own.append(client)
        self.client = client
        self.futures: list[Any] = []

    def results(self, task: Callable[..., pd.DataFrame], jobs: list[tuple[Any, ...]]) -> Iterator[tuple[int, pd.DataFrame]]:
        import distributed

        self.futures = [self.client.submit(task, *job, pure=False, retries=3) for job in jobs]
        index = {f.key: job[1] for f, job in zip(self.futures, jobs)}
        for future in distributed.as_completed(self.futures):
            yield index[future.key], future.result()

    def close(self) -> None:
        if self.futures:
            self.client.cancel(self.futures)
        for thing in self.own:
            thing.close()


def run(experiment: str, *, runs: int, seed: int, client: Any = None,
        out: str | os.PathLike[str] | None = None, progress: Progress = True,
        **settings: Any) -> Campaign:
    """Runs ``runs`` seeded runs of ``experiment`` and returns a :class:`Campaign`.

    ``seed`` is the master seed (run r uses ``run_seeds(seed, runs)[r]``); ``client`` is
    ``None`` (a ``distributed.LocalCluster`` of threads on this machine's cores), ``"serial"``
    (no Dask), a ``distributed.Client`` or a scheduler address (``"tcp://host:8786"``);
    ``out`` a directory that keeps every finished run (resume and extend by running again with
    the same ``out``); ``progress`` ``True`` (a bar on stderr), ``False``, or a callable
    ``progress(done, total)`` (an exception it raises stops the campaign; the runs finished so
    far stay in ``out``). ``settings`` are the experiment's (see ``EXPERIMENTS[name].defaults``).

    Errors: ``TypeError`` / ``ValueError`` naming the argument or setting (an unknown
    experiment, scheme or setting, ``runs`` < 1, settings that differ from those recorded in
    ``out``); ``ConnectionError`` naming ``client`` when a scheduler does not answer within
    ``CONNECT_TIMEOUT`` seconds."""
    spec = _experiment(experiment)
    runs = _check_int("runs", runs, 1, 1_000_000)
    seed = _check_int("seed", seed, 0, 2**64 - 1)
    if not (client is None or isinstance(client, str) or _is_client(client)):
        raise TypeError(
            "client must be None (a local cluster), 'serial', a scheduler address "
            f"('tcp://host:8786') or a distributed.Client, got {type(client).__name__}"
        )
    if not (isinstance(progress, bool) or callable(progress)):
        raise TypeError(f"progress must be a bool or a callable, got {type(progress).__name__}")
    unknown = sorted(set(settings) - set(spec.defaults))
    if unknown:
        close = difflib.get_close_matches(unknown[0], spec.defaults, n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise TypeError(f"run() got an unexpected setting {unknown[0]!r} for {experiment!r}{hint}")
    full = {**spec.defaults, **settings}
    spec.check(full)
    full = _store._canonical(full)
    seeds = run_seeds(seed, runs)
    where = Path(out) if out is not None else None
    done: set[int] = set()
    if where is not None:
        record = {"format": _store.FORMAT, "experiment": experiment, "seed": seed,
                  "settings": full, "fisst_version": __version__}
        done = _store.open_out(where, record)
    todo = [r for r in range(runs) if r not in done]
    have = runs - len(todo)
    frames: dict[int, pd.DataFrame] = {}
    bar = _Bar(progress, experiment, runs, have)
    engine: Any = _Serial() if client == "serial" or not todo else _Dask(client)
    try:
        for r, frame in engine.results(spec.task, [(full, r, seeds[r]) for r in todo]):
            if where is not None:
                _store.write_part(where, r, frame)
            frames[r] = frame
            have += 1
            bar.update(have)
    finally:
        engine.close()
    parts = [frames[r] if r in frames else None for r in range(runs)]
    if where is not None:
        missing = [r for r, f in enumerate(parts) if f is None]
        for r, frame in zip(missing, _store.read_parts(where, missing)):
            parts[r] = frame
    table = pd.concat(parts, ignore_index=True)
    return Campaign(experiment, seed, runs, full, table, where, len(frames))
