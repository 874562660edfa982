"""A seeded property-based fuzz (hypothesis) over every function of the package: at least
5,000 calls with valid, extreme and wrong inputs. Each call returns a result without NaN or
raises TypeError or ValueError with a message; never a PanicException (a BaseException) or
any other error. `make fuzz-python` runs the same properties with FISST_FUZZ_EXAMPLES=10^6
spread over the functions."""

import math
import os

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import fisst

TOTAL = int(os.environ.get("FISST_FUZZ_EXAMPLES", "6000"))

EXTREMES = [0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 1e-300, 5e-324, 1e300, 1.7976931348623157e308,
            -1e308, float("inf"), float("-inf"), float("nan"), 2.0**53]
number = st.one_of(st.floats(-10, 10), st.sampled_from(EXTREMES), st.integers(-3, 5))
probability = st.one_of(st.floats(0, 1), st.sampled_from([0.0, 1.0, -0.1, 1.1, float("nan")]))
junk = st.sampled_from(["x", None, [], {}, [[]], [["a"]], {"a": 1}, object(), b"\x00", (1, 2)])


def point_set(d):
    return st.one_of(
        st.lists(st.lists(number, min_size=d, max_size=d), max_size=6),
        st.lists(st.lists(st.floats(-5, 5), min_size=d, max_size=d), max_size=6).map(np.array),
    )


points = st.one_of(st.integers(1, 3).flatmap(point_set), junk)
existence = st.one_of(st.lists(probability, max_size=8), st.lists(probability, max_size=8).map(np.array), junk)
metric = st.sampled_from(["gospa", "ospa", "uospa", "x", 3])
kw_number = st.one_of(number, junk)
costs = st.one_of(st.sampled_from(["mpe", "x"]), st.fixed_dictionaries({"mmol": st.fixed_dictionaries({"asset": kw_number, "countermeasure": kw_number})}),
                  st.fixed_dictionaries({"c00": kw_number, "c01": kw_number, "c10": kw_number, "c11": kw_number, "c": kw_number}), junk)

matrix2 = st.one_of(st.just([[1.0, 0.0], [0.0, 1.0]]), st.lists(st.lists(number, min_size=2, max_size=2), min_size=2, max_size=2), junk)
component = st.fixed_dictionaries({"weight": st.one_of(st.floats(0, 2), st.sampled_from(EXTREMES)), "mean": st.one_of(st.lists(number, min_size=2, max_size=2), junk),
                                   "cov": st.one_of(st.just([[1.0, 0.0], [0.0, 1.0]]), matrix2, number)})
mixture = st.one_of(st.lists(component, min_size=1, max_size=3), junk)
transition = st.one_of(st.fixed_dictionaries({"F": matrix2, "Q": matrix2}), junk)
region = st.one_of(
    st.fixed_dictionaries({"box": st.fixed_dictionaries({"min": st.lists(number, min_size=2, max_size=2), "max": st.lists(number, min_size=2, max_size=2)})}),
    st.fixed_dictionaries({"ball": st.fixed_dictionaries({"center": st.lists(number, min_size=2, max_size=2), "radius": number})}),
    junk)
detection = st.one_of(st.fixed_dictionaries({"probability": probability}, optional={"fov": region}), junk)
clutter = st.one_of(st.fixed_dictionaries({"rate": kw_number, "density": kw_number}), junk)
filter_config = st.fixed_dictionaries(
    {"existence": probability, "mixture": mixture, "transition": transition, "detection": detection, "clutter": clutter},
    optional={"survival": probability, "position_dims": st.integers(0, 3), "exclusions": st.lists(region, max_size=2)})


gaussian = st.fixed_dictionaries({"mean": st.one_of(st.lists(number, min_size=2, max_size=2), junk), "cov": st.one_of(matrix2, number)})

# paper 002's jde_bound and jde_monte_carlo (as tests/js/fuzz/specs.mjs): small Monte Carlo sizes
# (samples 100–400, seeded) so that a call stays well under a second; the values around them
# valid, extreme or of the wrong kind
jde_model = st.sampled_from(["I", "II", "III"])
jde_density = st.one_of(
    st.fixed_dictionaries({"gaussian": st.fixed_dictionaries({"mean": st.floats(-5, 5), "variance": st.one_of(st.floats(0.01, 25), st.sampled_from(EXTREMES))})}),
    st.sampled_from([{"uniform": {"low": -2, "high": 2}}, {"uniform": {"low": 0, "high": 1}}, {"table": {"x": [-2, 0, 2], "density": [0, 1, 0]}},
                     {"mixture": [{"weight": 0.5, "mean": 0, "variance": 1}, {"weight": 0.5, "mean": 2, "variance": 0.5}]}]),
    junk)
jde_vector_prior = st.fixed_dictionaries({"multivariate_gaussian": st.one_of(
    st.fixed_dictionaries({"mean": st.lists(st.floats(-5, 5), min_size=2, max_size=2), "cov": st.one_of(st.just([[1.0, 0.2], [0.2, 2.0]]), matrix2, number)}),
    st.fixed_dictionaries({"mean": st.lists(st.floats(-5, 5), min_size=1, max_size=1), "cov": st.one_of(st.floats(0.01, 25), number)}),
    junk)})
jde_detection = st.one_of(probability, st.just({"table": {"x": [-3, 3], "probability": [0.3, 0.9]}}), junk)
jde_observation = st.one_of(st.fixed_dictionaries(
    {"detection_probability": jde_detection},
    optional={"gain": st.one_of(st.floats(-3, 3), st.lists(st.lists(st.floats(-3, 3), min_size=2, max_size=2), min_size=1, max_size=2), st.just([[1.0]]), number, junk),
              "offset": st.one_of(st.floats(-2, 2), st.lists(st.floats(-2, 2), min_size=1, max_size=2), junk),
              "noise_variance": st.one_of(st.floats(0.01, 10), kw_number),
              "noise_cov": st.one_of(st.just([[1.0]]), st.just([[1.0, 0.0], [0.0, 1.0]]), matrix2, number, junk)}), junk)
jde_false = st.one_of(st.none(), st.fixed_dictionaries({"probability": probability, "density": jde_density}),
                      st.fixed_dictionaries({"rate": st.one_of(st.floats(0, 2), kw_number), "density": jde_density}))


def jde_options(prior, extra):
    return st.tuples(jde_model, probability, prior, jde_observation, jde_false, st.floats(0, 100), kw_number, extra).map(
        lambda t: {"model": t[0], "existence": t[1], "prior": t[2], "observation": t[3], "false_alarm_error": t[5], "miss_error": t[6],
                   **({} if t[4] is None else {"false_alarm" if "probability" in t[4] else "clutter": t[4]}), **t[7]})


jde_bound_extra = st.fixed_dictionaries({}, optional={
    "samples": st.one_of(st.integers(100, 400), st.sampled_from([0, 99, 10**6 + 1])), "seed": st.integers(0, 99),
    "dims": st.one_of(st.integers(0, 3), junk), "tolerance": st.one_of(st.sampled_from([1e-6, 1e-15, 0.2]), junk),
    "quadrature_cardinality": st.one_of(st.integers(0, 3), junk)}).map(lambda d: {"samples": 200, "seed": 1, **d})
jde_mc_extra = st.fixed_dictionaries({}, optional={
    "samples": st.one_of(st.integers(2, 400), st.sampled_from([0, 1, 10**7 + 1])), "seed": st.one_of(st.integers(0, 99), st.sampled_from([-1, 2**64])),
    "scans": st.one_of(st.integers(0, 3), junk), "empty_rule": st.sampled_from(["optimal", "map", "declare", "reject", "hpe"])}).map(
        lambda d: {"samples": 200, "seed": 1, **d})
bernoullis = st.one_of(st.lists(st.fixed_dictionaries({"existence": probability, "mean": st.one_of(st.lists(number, min_size=2, max_size=3), junk),
                                                       "cov": st.one_of(matrix2, number)}), max_size=4), junk)
axis = st.one_of(st.tuples(number, number, st.one_of(st.integers(-1, 6), st.sampled_from([0.5, 4097, 1e300, float("nan")]))), junk)
grid = st.one_of(st.fixed_dictionaries({"x": axis, "y": axis}), junk)


def maybe(strategy):
    """A keyword that is sometimes omitted (None here means: leave it out)."""
    return st.one_of(st.none(), strategy)


spatial_density = st.one_of(
    st.fixed_dictionaries({"mean": st.lists(number, min_size=2, max_size=2), "cov": st.one_of(matrix2, number)}),
    st.fixed_dictionaries({"mixture": mixture}),
    st.fixed_dictionaries({"particles": st.lists(st.lists(number, min_size=2, max_size=2), max_size=4)}, optional={"weights": st.lists(number, max_size=4)}),
    junk)

CALLS = {
    "gospa": st.tuples(points, points, st.fixed_dictionaries({"c": kw_number}, optional={"p": kw_number, "alpha": kw_number})),
    "ospa": st.tuples(points, points, st.fixed_dictionaries({"c": kw_number}, optional={"p": kw_number})),
    "uospa": st.tuples(points, points, st.fixed_dictionaries({"c": kw_number}, optional={"p": kw_number})),
    "gospa_series": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"truths": st.lists(points, max_size=4), "estimates": st.lists(points, max_size=4), "c": kw_number},
        optional={"p": kw_number, "alpha": kw_number})),
    "ospa_series": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"truths": st.lists(points, max_size=4), "estimates": st.lists(points, max_size=4), "c": kw_number},
        optional={"p": kw_number})),
    "linear_assignment": st.tuples(points, st.just(None), st.just({})),
    "multi_bernoulli_cardinality": st.tuples(existence, st.just(None), st.just({})),
    "multi_bernoulli_leave_one_out": st.tuples(existence, st.just(None), st.just({})),
    "mb_optimal_estimate": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"existence": existence, "metric": metric},
        optional={"c": kw_number, "p": kw_number, "alpha": kw_number, "bogus": st.just(1)})),
    "mb_mean_square_error": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"existence": existence, "metric": metric, "report": st.lists(st.booleans(), max_size=8)},
        optional={"c": kw_number, "p": kw_number, "alpha": kw_number})),
    "mb_alternative_estimate": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"existence": existence, "method": st.sampled_from(["mam", "jom", "map-cardinality", "x"])},
        optional={"ln_peak": existence, "ln_c": kw_number})),
    "mb_decision_map": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"estimator": st.sampled_from(["gospa", "ospa", "uospa", "mam", "jom", "map-cardinality", "y"])},
        optional={"resolution": st.one_of(st.integers(-2, 60), st.sampled_from([10**6, 2**64])), "c": kw_number, "p": kw_number, "alpha": kw_number})),
    "mb_identical_component_counts": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"existence": kw_number, "max_components": st.one_of(st.integers(-2, 40), st.sampled_from([10**6, 2**70]))})),
    "bernoulli_loss_curve": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"existences": existence, "miss_probability": st.one_of(probability, junk), "costs": costs},
        optional={"threshold": st.one_of(probability, junk)})),
    "bernoulli_threshold_curve": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"sigmas": st.one_of(st.lists(number, max_size=5), junk), "radius": kw_number, "costs": costs},
        optional={"dim": st.one_of(st.integers(-1, 12), junk)})),
    "jde_bound_no_clutter": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"existence": probability, "detection_probability": probability, "prior_variance": kw_number,
         "posterior_variance": kw_number, "false_alarm_error": kw_number, "miss_error": kw_number})),
    "gaussian_fisher_information": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"prior_variance": kw_number, "gain": kw_number, "noise_variance": kw_number})),
    "jde_sequential_bound": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"method": st.sampled_from(["enumeration", "irf", "x"]), "prior_information": kw_number,
         "detected_information": kw_number, "detection_probability": probability,
         "steps": st.one_of(st.integers(-1, 60), st.sampled_from([5000, 5001, 10**9]))})),
    "jde_example2": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"existence": probability, "detection_probability": probability, "false_alarm_probability": probability,
         "false_alarm_error": kw_number}, optional={"miss_error": kw_number})),
    "jde_example2_regularity": st.tuples(st.just(None), st.just(None), st.one_of(st.just({}), st.just({"x": 1}))),
    "jde_bound": st.tuples(st.just(None), st.just(None), st.one_of(
        jde_options(jde_density, jde_bound_extra), jde_options(jde_vector_prior, jde_bound_extra), st.just({"model": "I"}))),
    "jde_monte_carlo": st.tuples(st.just(None), st.just(None), st.one_of(
        jde_options(st.one_of(jde_density, st.just("example2"), st.just("x")), jde_mc_extra),
        jde_options(jde_vector_prior, jde_mc_extra), st.just({"model": "I", "sample": 10}))),
    "multi_object_likelihood": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"likelihoods": st.one_of(st.lists(st.lists(st.one_of(st.floats(0, 2), st.sampled_from(EXTREMES)), min_size=2, max_size=2), max_size=5), junk),
         "detection_probability": probability, "clutter_rate": kw_number,
         "clutter_density": st.one_of(st.lists(st.one_of(st.floats(0, 1), st.sampled_from(EXTREMES)), min_size=2, max_size=2), junk)})),
    "compare_schemes": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"runs": st.one_of(st.integers(-1, 2), junk), "steps": st.one_of(st.integers(-1, 3), junk), "seed": st.integers(0, 99)},
        optional={"schemes": st.lists(st.sampled_from(["renyi", "fisher", "pent", "random", "x"]), max_size=3),
                  "particles": st.integers(-1, 60), "future_scans": st.integers(-1, 8), "alpha": kw_number,
                  "max_objects": st.integers(-1, 9), "start": st.one_of(st.lists(number, min_size=2, max_size=2), junk)})),
    "SensorControlRun": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"scheme": st.sampled_from(["renyi", "fisher", "pent", "random", "x"]), "seed": st.integers(0, 99),
         "steps": st.one_of(st.integers(-1, 3), junk)},
        optional={"particles": st.integers(-1, 60), "future_scans": st.integers(-1, 8), "alpha": kw_number,
                  "max_objects": st.integers(-1, 9), "start": st.one_of(st.lists(number, min_size=2, max_size=2), junk)})),
    "GmBernoulliFilter": st.tuples(st.just(None), st.just(None), filter_config),
    "ParticleBernoulliFilter": st.tuples(st.just(None), st.just(None), filter_config.map(lambda c: {**c, "particles": 50, "seed": 1})),
    "gm_bernoulli_predict": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"existence": probability, "mixture": mixture, "transition": transition},
        optional={"survival": probability, "birth": st.fixed_dictionaries({"probability": probability, "mixture": mixture})})),
    "gm_bernoulli_update": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"existence": probability, "mixture": mixture, "detection": detection, "clutter": clutter},
        optional={"reports": st.lists(region, max_size=2), "position_dims": st.integers(0, 3)})),
    "probability_outside_ball": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"density": st.one_of(st.fixed_dictionaries({"mean": st.lists(number, min_size=2, max_size=2), "cov": st.one_of(matrix2, number)}),
                              st.fixed_dictionaries({"mixture": mixture}),
                              st.fixed_dictionaries({"particles": st.lists(st.lists(number, min_size=2, max_size=2), max_size=4)}, optional={"weights": st.lists(number, max_size=4)}),
                              junk),
         "center": st.one_of(st.lists(number, min_size=2, max_size=2), junk), "radius": kw_number})),
    "reduce_mixture": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"mixture": mixture}, optional={"prune_below": kw_number, "merge_distance": kw_number, "max_components": st.one_of(st.integers(-1, 5), junk)})),
    "fov_cardinality": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"rfs": st.one_of(st.fixed_dictionaries({"multi_bernoulli": bernoullis}), st.fixed_dictionaries({"poisson": mixture}),
                          st.fixed_dictionaries({"iid_cluster": st.fixed_dictionaries({"cardinality": st.one_of(st.lists(probability, max_size=4), junk), "density": mixture})}),
                          st.fixed_dictionaries({"glmb": st.lists(st.fixed_dictionaries({"weight": number, "components": st.lists(gaussian, max_size=2)}), max_size=3)}), junk),
         "fov": st.one_of(region, st.fixed_dictionaries({"polygon": st.fixed_dictionaries({"vertices": st.lists(st.lists(number, min_size=2, max_size=2), max_size=5)})}))},
        optional={"detection_probability": st.one_of(probability, junk)})),
    "fov_variance_map": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"multi_bernoulli": bernoullis, "fov_size": st.one_of(st.lists(number, min_size=2, max_size=2), junk), "grid": grid})),
    "placement_scene": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {}, optional={"count": st.one_of(st.integers(-1, 50), junk), "seed": st.one_of(st.integers(-1, 2**60), junk), "extent": kw_number,
                      "sigma": st.one_of(st.lists(number, min_size=2, max_size=2), junk)})),
    "mixture_density_grid": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries({"mixture": mixture, "grid": grid})),
    # paper 000's point estimates (bernoulli_estimate, mmuc_estimate, multi_bernoulli_point_estimate)
    "bernoulli_estimate": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"existence": probability, "density": spatial_density, "radius": kw_number, "costs": costs})),
    "mmuc_estimate": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"density": spatial_density, "radius": kw_number})),
    "multi_bernoulli_point_estimate": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"components": st.one_of(st.lists(st.fixed_dictionaries({"existence": probability, "density": spatial_density}), max_size=3), junk),
         "radius": kw_number, "costs": costs})),
    # splitting and the worked examples of paper 001
    "split_library": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"components": st.one_of(st.integers(0, 6), st.sampled_from([16, 17, 2**64]), junk), "lambda_": kw_number},
        optional={"spacing": st.sampled_from(["equal", "free", "Equal", 3])})),
    "split_for_regions": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {"mixture": mixture, "regions": st.one_of(st.lists(region, max_size=3), junk)},
        optional={"position_dims": st.integers(-1, 9), "min_weight": kw_number, "components": st.integers(0, 5),
                  "lambda_": st.one_of(st.sampled_from([0.001, 0.01]), junk), "spacing": st.sampled_from(["equal", "free", "x"]),
                  "grid_bound": kw_number, "grid_points": st.one_of(st.integers(-1, 9), st.sampled_from([200, 10**6])),
                  "max_depth": st.integers(-1, 6), "max_components": st.one_of(st.integers(-1, 200), st.sampled_from([50_001, 2**64]))})),
    "negative_information_scenario": st.tuples(st.just(None), st.just(None), st.one_of(
        st.just({}), st.fixed_dictionaries({"step": st.one_of(st.none(), st.integers(-1, 5), junk)}), st.just({"steps": 1}))),
    "airport_scenario": st.tuples(st.just(None), st.just(None), st.fixed_dictionaries(
        {}, optional={"seed": st.one_of(st.integers(0, 99), st.sampled_from([-1, 2**64]), junk),
                      "steps": st.one_of(st.integers(-1, 4), st.sampled_from([2000, 2001, 2**64]), junk)})),
}

assert set(CALLS) == {n for n in fisst.__all__ if callable(getattr(fisst, n)) and n != "Result"}, (
    "every export is fuzzed"
)


def nan_in(value):
    if isinstance(value, float):
        return math.isnan(value)
    if isinstance(value, np.ndarray):
        return value.dtype.kind == "f" and bool(np.isnan(value).any())
    if isinstance(value, (list, tuple)):
        return any(nan_in(v) for v in value)
    if isinstance(value, fisst.Result):
        return any(nan_in(v) for v in value.values())
    return False


def call(name, args):
    a, b, kwargs = args
    positional = [x for x in (a, b) if x is not None] if name in ("gospa", "ospa", "uospa", "linear_assignment", "multi_bernoulli_cardinality", "multi_bernoulli_leave_one_out") else []
    if name in ("linear_assignment", "multi_bernoulli_cardinality", "multi_bernoulli_leave_one_out"):
        positional = [a]
    if name in ("gospa", "ospa", "uospa"):
        positional = [a, b]
    f = getattr(fisst, name)
    try:
        out = f(*positional, **kwargs)
        if name == "SensorControlRun":
            out = out.step()
        if name in ("GmBernoulliFilter", "ParticleBernoulliFilter"):
            out.predict()
            out.update([])
            out = out.estimate()
    except (TypeError, ValueError) as e:
        assert str(e), f"{name}: an empty message"
        return
    except BaseException as e:  # noqa: BLE001 - a PanicException is a BaseException
        raise AssertionError(f"{name}{args!r} raised {type(e).__name__}: {e}") from e
    assert not nan_in(out), f"{name}{args!r} returned a NaN: {out!r}"


def make(name):
    @settings(max_examples=TOTAL // len(CALLS) + 1, derandomize=True, database=None, deadline=None,
              suppress_health_check=list(HealthCheck))
    @given(CALLS[name])
    def run(args):
        call(name, args)

    return run


for _name in CALLS:
    globals()[f"test_fuzz_{_name}"] = make(_name)
