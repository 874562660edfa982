"""Type stubs of the compiled module ``fisst._fisst`` (checked by ``python -m mypy.stubtest fisst``)."""

from collections.abc import Callable, Iterator, Mapping, Sequence
from typing import Any, Literal, TypeAlias, final

import numpy as np
import numpy.typing as npt

__version__: str
__all__ = [
    "Result",
    "__version__",
    "bernoulli_estimate",

    "airport_scenario",
    "bernoulli_loss_curve",
    "bernoulli_threshold_curve",
    "compare_schemes",
    "fov_cardinality",
    "fov_variance_map",
    "gaussian_fisher_information",
    "gm_bernoulli_predict",
    "gm_bernoulli_update",
    "GmBernoulliFilter",
    "gospa",
    "gospa_series",
    "jde_bound",
    "jde_bound_no_clutter",
    "jde_example2",
    "jde_example2_regularity",
    "jde_monte_carlo",
    "jde_sequential_bound",
    "linear_assignment",
    "mb_alternative_estimate",
    "mb_decision_map",
    "mb_identical_component_counts",
    "mb_mean_square_error",
    "mb_optimal_estimate",
    "mixture_density_grid",
    "mmuc_estimate",
    "multi_bernoulli_cardinality",
    "multi_bernoulli_leave_one_out",
    "multi_bernoulli_point_estimate",
    "multi_object_likelihood",
    "negative_information_scenario",
    "ospa",
    "ospa_series",
    "ParticleBernoulliFilter",
    "placement_scene",
    "probability_outside_ball",
    "reduce_mixture",
    "SensorControlRun",
    "split_for_regions",
    "split_library",
    "uospa",
    "_campaign_airport_check",
    "_campaign_airport_run",
    "_campaign_bounds_check",
    "_campaign_bounds_run",
    "_campaign_control_check",
    "_campaign_control_run",
    "_campaign_run_seeds",
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
# fisst.campaign's compiled half (private)
def _campaign_run_seeds(seed: int, runs: int) -> list[int]: ...
def _campaign_control_check(**options: Any) -> None: ...
def _campaign_control_run(run_seed: int, **options: Any) -> npt.NDArray[np.float64]: ...
def _campaign_airport_check(**options: Any) -> None: ...
def _campaign_airport_run(run_seed: int, **options: Any) -> npt.NDArray[np.float64]: ...
def _campaign_bounds_check(**options: Any) -> None: ...
def _campaign_bounds_run(run_seed: int, **options: Any) -> npt.NDArray[np.float64]: ...

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

_Costs: TypeAlias = str | dict[str, Any]

def bernoulli_loss_curve(
    *, existences: npt.ArrayLike, miss_probability: float, costs: _Costs, threshold: float | None = None
) -> Result: ...
def bernoulli_threshold_curve(
    *, sigmas: npt.ArrayLike, radius: float, costs: _Costs, dim: int | None = None
) -> npt.NDArray[np.float64]: ...
def jde_bound_no_clutter(
    *,
    existence: float,
    detection_probability: float,
    prior_variance: float,
    posterior_variance: float,
    false_alarm_error: float,
    miss_error: float,
) -> Result: ...
def gaussian_fisher_information(*, prior_variance: float, gain: float, noise_variance: float) -> Result: ...
def jde_sequential_bound(
    *,
    method: str,
    prior_information: float,
    detected_information: float,
    detection_probability: float,
    steps: int,
) -> Result: ...
def jde_example2(
    *,
    existence: float,
    detection_probability: float,
    false_alarm_probability: float,
    false_alarm_error: float,
    miss_error: float | None = None,
) -> Result: ...
def jde_example2_regularity() -> Result: ...
def jde_bound(
    *,
    model: str,
    existence: float,
    prior: dict[str, Any],
    observation: dict[str, Any],
    false_alarm_error: float,
    miss_error: float,
    false_alarm: dict[str, Any] | None = None,
    clutter: dict[str, Any] | None = None,
    dims: int | None = None,
    tolerance: float | None = None,
    samples: int | None = None,
    seed: int | None = None,
    quadrature_cardinality: int | None = None,
) -> Result: ...
def jde_monte_carlo(
    *,
    model: str,
    existence: float,
    prior: dict[str, Any] | str,
    observation: dict[str, Any],
    false_alarm_error: float,
    miss_error: float,
    false_alarm: dict[str, Any] | None = None,
    clutter: dict[str, Any] | None = None,
    empty_rule: str | None = None,
    scans: int | None = None,
    samples: int | None = None,
    seed: int | None = None,
) -> Result: ...
def multi_object_likelihood(
    *,
    likelihoods: npt.ArrayLike,
    detection_probability: float,
    clutter_rate: float,
    clutter_density: npt.ArrayLike,
) -> Result: ...
@final
class SensorControlRun:
    """One run of Algorithm 1 of paper 004 (sensor control with the SMC multi-object filter)."""

    def __new__(cls, **options: Any) -> SensorControlRun: ...
    def step(self) -> Result: ...
    @property
    def particles(self) -> Result: ...
    @property
    def sensor_path(self) -> Any: ...
    @property
    def truth(self) -> Any: ...
    @property
    def measurements(self) -> Any: ...
    @property
    def k(self) -> int: ...
    @property
    def steps(self) -> int: ...
    @property
    def seed(self) -> int: ...
    @property
    def scheme(self) -> str: ...
    def __reduce__(self) -> tuple[Any, ...]: ...
    @staticmethod
    def _restore(options: dict[str, Any], k: int) -> SensorControlRun: ...

def compare_schemes(
    *,
    runs: int,
    steps: int,
    seed: int | None = None,
    schemes: Sequence[str] | None = None,
    particles: int = 750,
    future_scans: int = 200,
    alpha: float = 0.5,
    start: Sequence[float] = [0, 0],
    max_objects: int = 4,
    on_progress: Callable[[int, int], object] | None = None,
) -> Result: ...

_Region: TypeAlias = dict[str, Any]

@final
class GmBernoulliFilter:
    """The GM Bernoulli filter of Algorithm 3 of paper 001 (imprecise reports, negative information)."""

    def __new__(cls, **config: Any) -> GmBernoulliFilter: ...
    def predict(self) -> None: ...
    def update(self, reports: Sequence[_Region] | None = None, *, measurements: npt.ArrayLike | None = None) -> Result: ...
    def estimate(self, *, radius: float | None = None, costs: _Costs | None = None) -> Result: ...
    @property
    def existence(self) -> float: ...
    @property
    def mixture(self) -> Any: ...
    def __reduce__(self) -> tuple[Any, ...]: ...
    @staticmethod
    def _restore(options: dict[str, Any], ops: list[Any]) -> GmBernoulliFilter: ...

@final
class ParticleBernoulliFilter:
    """The particle Bernoulli filter of paper 001 (systematic resampling, an MCMC move)."""

    def __new__(cls, **config: Any) -> ParticleBernoulliFilter: ...
    def predict(self) -> None: ...
    def update(self, reports: Sequence[_Region] | None = None, *, measurements: npt.ArrayLike | None = None) -> Result: ...
    def estimate(self, *, radius: float | None = None, costs: _Costs | None = None) -> Result: ...
    @property
    def existence(self) -> float: ...
    @property
    def particles(self) -> npt.NDArray[np.float64]: ...
    @property
    def weights(self) -> npt.NDArray[np.float64]: ...
    @property
    def seed(self) -> int: ...
    def __reduce__(self) -> tuple[Any, ...]: ...
    @staticmethod
    def _restore(options: dict[str, Any], particle: dict[str, Any], ops: list[Any]) -> ParticleBernoulliFilter: ...

def gm_bernoulli_predict(
    *, existence: float, mixture: Sequence[dict[str, Any]], transition: dict[str, Any], survival: float = 0.99, birth: dict[str, Any] | None = None
) -> Result: ...
def gm_bernoulli_update(
    *,
    existence: float,
    mixture: Sequence[dict[str, Any]],
    reports: Sequence[_Region] | None = None,
    measurements: npt.ArrayLike | None = None,
    likelihood: dict[str, Any] | None = None,
    position_dims: int = 2,
    detection: dict[str, Any],
    clutter: dict[str, Any],
    splitting: dict[str, Any] = ...,
    reduction: dict[str, Any] = ...,
    exclusions: Sequence[_Region] = [],
) -> Result: ...

def probability_outside_ball(*, density: dict[str, Any], center: npt.ArrayLike, radius: float) -> float: ...
def reduce_mixture(
    *,
    mixture: Sequence[dict[str, Any]],
    prune_below: float = 0.0,
    merge_distance: float | None = None,
    max_components: int | None = None,
) -> Any: ...

# Field of view (paper 001, Sections VI–VII)
_GridAxis: TypeAlias = tuple[float, float, float] | Sequence[float]
_Grid: TypeAlias = dict[str, _GridAxis]

def fov_cardinality(
    *, rfs: dict[str, Any], fov: _Region, detection_probability: float = 1.0
) -> Result:
    """The pmf of the number of objects in the field of view ``fov`` (paper 001, Props 1–4,
    eqs. (72)–(92)): a ``Result`` with ``pmf`` (float64 array), ``mean``, ``variance`` and
    ``mass_in_fov`` (float64 array)."""

def fov_variance_map(
    *, multi_bernoulli: Sequence[Mapping[str, Any]], fov_size: Sequence[float], grid: _Grid
) -> Result:
    """The FoV-count variance over a grid of FoV centres (paper 001, Section VII, Fig. 10): a
    ``Result`` with ``variance`` (float64 array of shape ``(ny, nx)``, y the row index),
    ``argmax`` (``[x, y]``) and ``max``."""

def placement_scene(
    *, count: int = 100, seed: int = 1, extent: float = 3.0, sigma: Sequence[float] = (0.1, 0.5)
) -> Result:
    """A seeded multi-Bernoulli scene (paper 001, Section VII, Figs 9–10): a ``Result`` with
    ``multi_bernoulli``, a list of ``Result`` with ``existence``, ``mean`` (shape ``(2,)``) and
    ``cov`` (shape ``(2, 2)``)."""

def mixture_density_grid(*, mixture: Sequence[Mapping[str, Any]], grid: _Grid) -> npt.NDArray[np.float64]:
    """A Gaussian mixture's density over a grid (paper 001, the PHD (99) of Fig. 9): a float64
    array of shape ``(ny, nx)``, ``[j, i]`` at (x_i, y_j)."""

# paper 000's point estimates (bernoulli_estimate, mmuc_estimate, multi_bernoulli_point_estimate)
def bernoulli_estimate(*, existence: float, density: dict[str, Any], radius: float, costs: _Costs) -> Result: ...
def mmuc_estimate(*, density: dict[str, Any], radius: float) -> Result: ...
def multi_bernoulli_point_estimate(
    *, components: Sequence[dict[str, Any]], radius: float, costs: _Costs
) -> Result: ...

# splitting and the worked examples of paper 001
def split_library(*, components: int, lambda_: float, spacing: Literal["equal", "free"] = "equal") -> Result: ...
def split_for_regions(
    *,
    mixture: Sequence[dict[str, Any]],
    regions: Sequence[_Region],
    position_dims: int = 2,
    min_weight: float = 0.01,
    components: int = 3,
    lambda_: float = 0.001,
    spacing: Literal["equal", "free"] = "equal",
    grid_bound: float = 2.0,
    grid_points: int = 15,
    max_depth: int = 16,
    max_components: int = 10000,
) -> Result: ...
def negative_information_scenario(*, step: int | None = None) -> Result: ...
def airport_scenario(*, seed: int | None = None, steps: int = 60) -> Result: ...
