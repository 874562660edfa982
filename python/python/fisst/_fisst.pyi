"""Type stubs of the compiled module ``fisst._fisst`` (checked by ``python -m mypy.stubtest fisst``)."""

from collections.abc import Iterator, Mapping, Sequence
from typing import Any, TypeAlias, final

import numpy as np
import numpy.typing as npt

__version__: str
__all__ = [
    "Result",
    "__version__",
    "gospa",
    "gospa_series",
    "linear_assignment",
    "mb_alternative_estimate",
    "mb_decision_map",
    "mb_identical_component_counts",
    "mb_mean_square_error",
    "mb_optimal_estimate",
    "multi_bernoulli_cardinality",
    "multi_bernoulli_leave_one_out",
    "ospa",
    "ospa_series",
    "uospa",
]

#: A point set: an ``(n, d)`` array of numbers (or a list of ``n`` points of length ``d``;
#: an empty sequence is the empty set).
_PointSet: TypeAlias = npt.ArrayLike

@final
class Result(Mapping[str, Any]):
    """A result of a fisst function: the core's result type with its fields as attributes."""

    def __new__(cls, name: str, fields: dict[str, Any]) -> Result: ...
    @property
    def type_name(self) -> str: ...
    def __getattr__(self, attr: str) -> Any: ...
    def __getitem__(self, key: str, /) -> Any: ...
    def __len__(self) -> int: ...
    def __iter__(self) -> Iterator[str]: ...
    def __contains__(self, key: object, /) -> bool: ...
    def keys(self) -> list[str]: ...  # type: ignore[override]
    def values(self) -> list[Any]: ...  # type: ignore[override]
    def items(self) -> list[tuple[str, Any]]: ...  # type: ignore[override]
    def to_dict(self) -> dict[str, Any]: ...
    def __eq__(self, value: object, /) -> bool: ...
    def __reduce__(self) -> tuple[Any, ...]: ...

def gospa(
    truth: _PointSet, estimate: _PointSet, *, c: float, p: float = 2.0, alpha: float = 2.0
) -> Result: ...
def ospa(truth: _PointSet, estimate: _PointSet, *, c: float, p: float = 2.0) -> Result: ...
def uospa(truth: _PointSet, estimate: _PointSet, *, c: float, p: float = 2.0) -> Result: ...
def gospa_series(
    *,
    truths: Sequence[_PointSet],
    estimates: Sequence[_PointSet],
    c: float,
    p: float = 2.0,
    alpha: float = 2.0,
) -> Result: ...
def ospa_series(
    *, truths: Sequence[_PointSet], estimates: Sequence[_PointSet], c: float, p: float = 2.0
) -> Result: ...
def linear_assignment(cost: npt.ArrayLike) -> Result: ...
def multi_bernoulli_cardinality(existence: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
def multi_bernoulli_leave_one_out(existence: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
def mb_optimal_estimate(
    *, existence: npt.ArrayLike, metric: str, c: float = 1.0, p: float = 2.0, alpha: float = 2.0
) -> Result: ...
def mb_mean_square_error(
    *,
    report: Sequence[bool] | npt.ArrayLike,
    existence: npt.ArrayLike,
    metric: str,
    c: float = 1.0,
    p: float = 2.0,
    alpha: float = 2.0,
) -> float: ...
def mb_alternative_estimate(
    *, existence: npt.ArrayLike, method: str, ln_peak: npt.ArrayLike | None = None, ln_c: float = 0.0
) -> Result: ...
def mb_decision_map(
    *, estimator: str, resolution: int = 100, c: float = 1.0, p: float = 2.0, alpha: float = 2.0
) -> Result: ...
def mb_identical_component_counts(*, existence: float, max_components: int) -> Result: ...
