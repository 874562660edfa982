"""Stubs of fisst.stonesoup (Stone Soup itself is untyped: its generators are `Any` here)."""

from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

__all__ = [
    "GOSPAMetric",
    "OSPAMetric",
    "GOSPADistanceMetric",
    "extract_states",
    "state_points",
    "points_by_time",
]

def extract_states(objects: Iterable[Any]) -> tuple[list[Any], list[int]]: ...
def state_points(states: Sequence[Any], mapping: Sequence[int] | None = None) -> np.ndarray: ...
def points_by_time(
    objects: Iterable[Any], mapping: Sequence[int] | None = None
) -> dict[Any, tuple[np.ndarray, np.ndarray]]: ...

class GOSPAMetric:
    p: float
    c: float
    switching_penalty: float
    measure: Any
    generator_name: str
    tracks_key: str
    truths_key: str
    def __init__(
        self,
        p: float,
        c: float,
        switching_penalty: float = 0.0,
        measure: Any = None,
        generator_name: str = "gospa_generator",
        tracks_key: str = "tracks",
        truths_key: str = "groundtruth_paths",
    ) -> None: ...
    def compute_metric(self, manager: Any) -> Any: ...

class GOSPADistanceMetric(GOSPAMetric):
    def __init__(
        self,
        p: float,
        c: float,
        switching_penalty: float = 0.0,
        measure: Any = None,
        generator_name: str = "gospa_distance_generator",
        tracks_key: str = "tracks",
        truths_key: str = "groundtruth_paths",
    ) -> None: ...

class OSPAMetric(GOSPAMetric):
    def __init__(
        self,
        p: float,
        c: float,
        switching_penalty: float = 0.0,
        measure: Any = None,
        generator_name: str = "ospa_generator",
        tracks_key: str = "tracks",
        truths_key: str = "groundtruth_paths",
    ) -> None: ...
