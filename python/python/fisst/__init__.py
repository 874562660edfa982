"""fisst: random-finite-set estimation, exact and fast, from Python.

The same library as the npm package ``fisst`` and the Rust crate ``fisst``, under the npm
names in snake_case: ``gospa``, ``ospa``, ``uospa``, ``gospa_series``, ``ospa_series``,
``linear_assignment``, ... Point sets go in as ``(n, d)`` numpy arrays (lists and other
array-likes are converted once); results come back as :class:`Result` objects whose numeric
arrays are numpy arrays. Every function names the paper and equation it implements in its
docstring (``help(fisst.gospa)``).
"""

from ._fisst import (
    Result,
    __version__,
    bernoulli_loss_curve,
    bernoulli_threshold_curve,
    compare_schemes,
    gaussian_fisher_information,
    gm_bernoulli_predict,
    gm_bernoulli_update,
    GmBernoulliFilter,
    gospa,
    gospa_series,
    jde_bound_no_clutter,
    jde_example2,
    jde_example2_regularity,
    jde_sequential_bound,
    linear_assignment,
    mb_alternative_estimate,
    mb_decision_map,
    mb_identical_component_counts,
    mb_mean_square_error,
    mb_optimal_estimate,
    multi_bernoulli_cardinality,
    multi_bernoulli_leave_one_out,
    multi_object_likelihood,
    ospa,
    ospa_series,
    ParticleBernoulliFilter,
    SensorControlRun,
    uospa,
)

__all__ = [
    "Result",
    "__version__",
    "bernoulli_loss_curve",
    "bernoulli_threshold_curve",
    "compare_schemes",
    "gaussian_fisher_information",
    "gm_bernoulli_predict",
    "gm_bernoulli_update",
    "GmBernoulliFilter",
    "gospa",
    "gospa_series",
    "jde_bound_no_clutter",
    "jde_example2",
    "jde_example2_regularity",
    "jde_sequential_bound",
    "linear_assignment",
    "mb_alternative_estimate",
    "mb_decision_map",
    "mb_identical_component_counts",
    "mb_mean_square_error",
    "mb_optimal_estimate",
    "multi_bernoulli_cardinality",
    "multi_bernoulli_leave_one_out",
    "multi_object_likelihood",
    "ospa",
    "ospa_series",
    "ParticleBernoulliFilter",
    "SensorControlRun",
    "uospa",
]
