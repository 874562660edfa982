"""Stone Soup interoperability: drop-in GOSPA and OSPA metric generators, a plottable GOSPA
distance, and conversions from Stone Soup states, tracks and truths to arrays.

Install with ``pip install fisst[stonesoup]`` (tested against ``stonesoup==1.9.1``). Replace::

    from stonesoup.metricgenerator.ospametric import GOSPAMetric, OSPAMetric

with::

    from fisst.stonesoup import GOSPAMetric, OSPAMetric

and a :class:`~stonesoup.metricgenerator.manager.MultiManager` pipeline gives the same metrics
(the same constructor arguments, the same output structure: a ``TimeRangeMetric`` of
``SingleTimeMetric`` per timestamp, or one ``SingleTimeMetric`` for a single timestamp), each
scenario computed by one call into fisst's exact assignment instead of SciPy per step.

Differences, on purpose:

- ``OSPAMetric`` assigns on ``min(d, c)**p`` (the OSPA of Schuhmacher, Vo & Vo 2008); Stone
  Soup 1.9.1 assigns on ``min(d, c)`` whatever p is, which is above the optimum for p != 1.
- ``measure`` must be :class:`stonesoup.measures.Euclidean` (with or without ``mapping`` and
  ``mapping2``); ``p`` must be finite. Anything else is a ``ValueError`` naming the argument.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from operator import attrgetter, itemgetter
from typing import Any

import numpy as np

from . import _fisst

try:
    from stonesoup.base import Property
    from stonesoup.measures import Euclidean
    from stonesoup.metricgenerator.ospametric import GOSPAMetric as _SSGOSPAMetric
    from stonesoup.metricgenerator.ospametric import OSPAMetric as _SSOSPAMetric
    from stonesoup.types.metric import SingleTimeMetric, TimeRangeMetric
    from stonesoup.types.state import State, StateMutableSequence
    from stonesoup.types.time import TimeRange
except ImportError:  # pragma: no cover - exercised without the extra
    raise ImportError(
        "fisst.stonesoup needs Stone Soup: pip install 'fisst[stonesoup]' (or stonesoup>=1.9)"
    ) from None

__all__ = [
    "GOSPAMetric",
    "OSPAMetric",
    "GOSPADistanceMetric",
    "extract_states",
    "state_points",
    "points_by_time",
]


# ----------------------------------------------------------------------------- conversions


def extract_states(objects: Iterable[Any]) -> tuple[list[Any], list[int]]:
    """The states of ``objects`` (tracks, ground-truth paths or single states) and, for each,
    the index of the object it came from: the last state at each timestamp of a track or path,
    as Stone Soup's own metric generators take them."""
    elements = list(objects)
    types = set(map(type, elements))
    kinds: dict[type, bool] = {}  # per type: a sequence of states (True) or one state (False)
    for element_type in types:
        if issubclass(element_type, StateMutableSequence) and not issubclass(element_type, State):
            kinds[element_type] = True
        elif issubclass(element_type, State):
            kinds[element_type] = False
    if len(kinds) == len(types) and not any(kinds.values()):
        # single states only (a flat list of states): no Python loop per element
        return elements, list(range(len(elements)))
    states: list[Any] = []
    ids: list[int] = []
    for i, element in enumerate(elements):
        kind = kinds.get(type(element))
        if kind is None:
            raise TypeError(f"objects[{i}] must be a State, a Track or a GroundTruthPath, got {type(element).__name__}")
        if kind:
            got = list(element.last_timestamp_generator())
            states.extend(got)
            ids.extend([i] * len(got))
        else:
            states.append(element)
            ids.append(i)
    return states, ids


def _reader(states: Sequence[Any], name: str) -> list[Any]:
    """The attribute ``name`` of every state. Stone Soup keeps a plain property's value in the
    instance dict under the property's ``_property_name``; reading it there skips the
    descriptor call (a third of the time of a 60,000-state scenario). Any other case (a
    property with a getter, mixed types) goes through ``getattr``."""
    types = set(map(type, states))
    if len(types) == 1:
        prop = getattr(next(iter(types)), name, None)
        key = getattr(prop, "_property_name", None)
        if isinstance(prop, Property) and getattr(prop, "_getter", None) is None and key:
            try:
                return list(map(itemgetter(key), map(vars, states)))
            except (KeyError, TypeError):
                pass
    return list(map(attrgetter(name), states))


def _vectors(states: Sequence[Any]) -> np.ndarray:
    """The state vectors (``mean`` where a state type has one, as Stone Soup's ``Euclidean``
    does) as one ``(n, d)`` float64 array."""
    if not states:
        return np.empty((0, 0))
    if any(hasattr(t, "mean") for t in set(map(type, states))):
        columns = [getattr(s, "mean", s.state_vector) for s in states]
    else:
        columns = _reader(states, "state_vector")
    try:
        return np.asarray(columns, dtype=np.float64).reshape(len(columns), -1)
    except ValueError as e:
        raise ValueError(f"the states' vectors must all have one dimension: {e}") from None


def state_points(states: Sequence[Any], mapping: Sequence[int] | None = None) -> np.ndarray:
    """The state vectors of ``states`` (their ``mean`` where they have one, as Stone Soup's
    ``Euclidean`` does) as an ``(n, d)`` float64 array, restricted to the coordinates
    ``mapping`` if given."""
    points = _vectors(states)
    if mapping is None:
        return points
    if len(points) == 0:
        return np.empty((0, len(mapping)))
    return points[:, list(mapping)]


def points_by_time(
    objects: Iterable[Any], mapping: Sequence[int] | None = None
) -> dict[Any, tuple[np.ndarray, np.ndarray]]:
    """The states of ``objects`` grouped by timestamp: ``{timestamp: (points, ids)}``, the
    points an ``(n, d)`` array (see :func:`state_points`), ``ids`` the index of each point's
    track or path in ``objects``."""
    states, ids = extract_states(objects)
    if not states:
        return {}
    points = state_points(states, mapping)
    # one code per distinct timestamp, in order of first appearance; the states in order of
    # their codes (as given when already grouped, else one stable sort), then one slice (a view)
    # per timestamp: no Python loop over the states and no copy per group
    stamps = _reader(states, "timestamp")
    index = {t: i for i, t in enumerate(dict.fromkeys(stamps))}
    codes = np.fromiter(map(index.__getitem__, stamps), dtype=np.intp, count=len(states))
    id_array = np.asarray(ids, dtype=np.int64)
    if np.any(codes[1:] < codes[:-1]):
        order = np.argsort(codes, kind="stable")
        points, id_array = points[order], id_array[order]
    counts = np.bincount(codes, minlength=len(index))
    ends = np.cumsum(counts)
    return {
        t: (points[start:end], id_array[start:end])
        for t, start, end in zip(index, (ends - counts).tolist(), ends.tolist())
    }


# ----------------------------------------------------------------------------- the generators


def _check(generator: Any) -> None:
    p, c = generator.p, generator.c
    if not isinstance(p, (int, float, np.integer, np.floating)) or isinstance(p, bool):
        raise TypeError(f"p must be a real number, got {type(p).__name__}")
    if not np.isfinite(p):
        raise ValueError(f"p = {p} is not supported: p must be finite and >= 1 (fisst computes the OSPA/GOSPA of finite order)")
    if not p >= 1:
        raise ValueError(f"p must be >= 1, got {p}")
    if not isinstance(c, (int, float, np.integer, np.floating)) or isinstance(c, bool):
        raise TypeError(f"c must be a real number, got {type(c).__name__}")
    if not (np.isfinite(c) and c > 0):
        raise ValueError(f"c must be finite and > 0, got {c}")
    if not np.isfinite(generator.switching_penalty) or generator.switching_penalty < 0:
        raise ValueError(f"switching_penalty must be finite and >= 0, got {generator.switching_penalty}")
    m = generator.measure
    if type(m) is not Euclidean:
        raise ValueError(
            f"measure = {type(m).__name__} is not supported: fisst's metrics use the Euclidean "
            "distance (stonesoup.measures.Euclidean, with or without mapping)"
        )


def _mappings(measure: Any) -> tuple[Sequence[int] | None, Sequence[int] | None]:
    m1 = None if measure.mapping is None else [int(i) for i in np.asarray(measure.mapping).reshape(-1)]
    m2 = getattr(measure, "mapping2", None)
    m2 = m1 if m2 is None else [int(i) for i in np.asarray(m2).reshape(-1)]
    return m1, m2


def _scenario(generator: Any, manager: Any):
    """(timestamps, track points and ids, truth points and ids) per timestamp, sorted."""
    m1, m2 = _mappings(generator.measure)
    tracks = points_by_time(manager.states_sets[generator.tracks_key], m1)
    truths = points_by_time(manager.states_sets[generator.truths_key], m2)
    times = sorted(set(tracks) | set(truths))
    dim = next((v[0].shape[1] for v in (*tracks.values(), *truths.values()) if v[0].size), 0)
    empty = (np.empty((0, dim)), np.empty(0, dtype=np.int64))
    return times, [tracks.get(t, empty) for t in times], [truths.get(t, empty) for t in times]


def _time_range(times: list[Any]) -> TimeRange:
    return TimeRange(start=times[0], end=times[-1])


class _Switching:
    """Stone Soup's switching loss (the GOSPA switching term of MATLAB's trackGOSPAMetric),
    with the same association history and half penalties."""

    def __init__(self, factor: float, p: float):
        self.history: dict[int, int | None] = {}
        self.factor, self.p = factor, p

    def step(self, mapping: dict[int, int | None]) -> float:
        loss = 0.0
        for truth, track in mapping.items():
            if truth not in self.history and track is None:
                continue
            if truth not in self.history:
                self.history[truth] = track
            elif self.history[truth] != track:
                loss += 0.5
                if track is not None and self.history[truth] is not None:
                    loss += 0.5
                self.history[truth] = track
        return self.factor * loss ** (1 / self.p)


class GOSPAMetric(_SSGOSPAMetric):
    """GOSPA (alpha = 2) per timestamp, as Stone Soup's ``GOSPAMetric`` with the same
    constructor arguments and output (``SingleTimeMetric`` values ``{'distance',
    'localisation', 'missed', 'false', 'switching'}``, where ``missed`` and ``false`` are the
    costs ``c**p / 2`` times the counts, as Stone Soup defines them), computed by fisst
    (García-Fernández & Svensson, paper 003, Def. 2 and Prop. 3)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        _check(self)

    def compute_metric(self, manager: Any) -> Any:
        _check(self)
        times, tracks, truths = _scenario(self, manager)
        if not times:
            raise ValueError("no states: the tracks and truths hold no state at any timestamp")
        c, p = float(self.c), float(self.p)
        dummy = c**p / 2
        switching = _Switching(float(self.switching_penalty), p)
        if self.switching_penalty == 0:
            series = _fisst.gospa_series(truths=[t[0] for t in truths], estimates=[m[0] for m in tracks], c=c, p=p)
            steps = [
                (series.distance[k], series.localisation[k], series.missed[k], series.false_targets[k], None)
                for k in range(len(times))
            ]
        else:
            steps = []
            for (truth, _), (track, _) in zip(truths, tracks):
                g = _fisst.gospa(truth, track, c=c, p=p)
                steps.append((g.distance, g.localisation, g.missed, g.false_targets, g.assignment))
        metrics = []
        for k, t in enumerate(times):
            distance, localisation, missed, false, assignment = steps[k]
            truth_ids, track_ids = truths[k][1], tracks[k][1]
            if assignment is None:
                loss = 0.0  # no switching penalty
            else:
                assigned = {int(i): int(j) for i, j in assignment}
                mapping = {int(truth_ids[i]): (int(track_ids[assigned[i]]) if i in assigned else None) for i in range(len(truth_ids))}
                loss = switching.step(mapping)
            value = {
                "distance": float(np.power(float(distance) ** 2 + loss**2, 0.5)),
                "localisation": float(localisation),
                "missed": dummy * int(missed),
                "false": dummy * int(false),
                "switching": loss,
            }
            metrics.append(SingleTimeMetric(title="GOSPA Metric", value=value, timestamp=t, generator=self))
        if len(metrics) == 1:
            return metrics[0]
        return TimeRangeMetric(title="GOSPA Metrics", value=metrics, time_range=_time_range(times), generator=self)


class GOSPADistanceMetric(GOSPAMetric):
    """The GOSPA distance alone as a plottable metric: a ``TimeRangeMetric`` titled
    ``'GOSPA distance'`` whose values are ``SingleTimeMetric`` of floats, which Stone Soup's
    ``MetricPlotter.plot_metrics`` draws (its ``GOSPAMetric`` values are dicts, which it
    cannot)."""

    generator_name: str = Property(doc="Unique identifier of the generator", default="gospa_distance_generator")

    def compute_metric(self, manager: Any) -> Any:
        full = super().compute_metric(manager)
        steps = full.value if isinstance(full, TimeRangeMetric) else [full]
        values = [
            SingleTimeMetric(title="GOSPA distance", value=s.value["distance"], timestamp=s.timestamp, generator=self)
            for s in steps
        ]
        times = [s.timestamp for s in steps]
        return TimeRangeMetric(title="GOSPA distance", value=values, time_range=_time_range(times), generator=self)


class OSPAMetric(_SSOSPAMetric):
    """OSPA per timestamp, as Stone Soup's ``OSPAMetric`` with the same constructor arguments
    and output (``SingleTimeMetric`` values: the distance), computed by fisst with the
    assignment that is optimal for the given p (Schuhmacher, Vo & Vo 2008)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        _check(self)
        if self.switching_penalty != 0:
            raise ValueError(f"switching_penalty = {self.switching_penalty} is not supported by OSPA (Stone Soup's OSPAMetric ignores it); use GOSPAMetric")

    def compute_metric(self, manager: Any) -> Any:
        _check(self)
        times, tracks, truths = _scenario(self, manager)
        if not times:
            raise ValueError("no states: the tracks and truths hold no state at any timestamp")
        series = _fisst.ospa_series(truths=[t[0] for t in truths], estimates=[m[0] for m in tracks], c=float(self.c), p=float(self.p))
        metrics = [
            SingleTimeMetric(title="OSPA distance", value=float(series.distance[k]), timestamp=t, generator=self)
            for k, t in enumerate(times)
        ]
        if len(metrics) == 1:
            return metrics[0]
        return TimeRangeMetric(title="OSPA distances", value=metrics, time_range=_time_range(times), generator=self)

