"""The metrics and multi-Bernoulli estimators from Python: independent oracles (brute-force
assignment over every injective map), the parity fixture (bit for bit with the native build),
array-likes in, numpy out, results, and errors that name the argument."""

import itertools
import json
import math
import pathlib
import pickle

import numpy as np
import pytest

import fisst

ROOT = pathlib.Path(__file__).resolve().parents[2]
FIXTURE = json.loads((ROOT / "tests" / "data" / "parity.json").read_text())


def cut_sum(x, y, c, p):
    """min over injective maps of the smaller set into the larger of sum min(d, c)^p."""
    s, l = (x, y) if len(x) <= len(y) else (y, x)
    if not s:
        return 0.0
    best = math.inf
    for perm in itertools.permutations(range(len(l)), len(s)):
        total = sum(min(math.dist(s[i], l[j]), c) ** p for i, j in enumerate(perm))
        best = min(best, total)
    return best


def gospa_oracle(x, y, c, p, alpha=2.0):
    # Def. 2 of paper 003: (min sum d_c^p + c^p / alpha * (|X| + |Y| - 2 min)) ^ (1/p)
    k = min(len(x), len(y))
    return (cut_sum(x, y, c, p) + c**p / alpha * (len(x) + len(y) - 2 * k)) ** (1 / p)


def ospa_oracle(x, y, c, p):
    n = max(len(x), len(y))
    if n == 0:
        return 0.0
    return ((cut_sum(x, y, c, p) + c**p * abs(len(x) - len(y))) / n) ** (1 / p)


def random_sets(rng, m, n, d=2):
    return rng.uniform(0, 4, (m, d)).tolist(), rng.uniform(0, 4, (n, d)).tolist()


def test_gospa_and_ospa_equal_brute_force_on_small_sets():
    rng = np.random.default_rng(20261204)
    for _ in range(60):
        x, y = random_sets(rng, rng.integers(0, 5), rng.integers(0, 5))
        c = float(rng.uniform(0.5, 3))
        for p in (1.0, 2.0, 3.5):
            g = fisst.gospa(x, y, c=c, p=p)
            assert g.distance == pytest.approx(gospa_oracle(x, y, c, p), rel=1e-12, abs=1e-12)
            # Prop. 3: distance^p = localisation + c^p / 2 (missed + false targets)
            parts = g.localisation + c**p / 2 * (g.missed + g.false_targets)
            assert g.distance**p == pytest.approx(parts, rel=1e-12, abs=1e-12)
            # every truth point is assigned or missed, every estimate assigned or false
            assert len(g.assignment) + g.missed == len(x)
            assert len(g.assignment) + g.false_targets == len(y)
            o = fisst.ospa(x, y, c=c, p=p)
            assert o.distance == pytest.approx(ospa_oracle(x, y, c, p), rel=1e-12, abs=1e-12)
            u = fisst.uospa(x, y, c=c, p=p)
            assert u.distance == pytest.approx(gospa_oracle(x, y, c, p, alpha=1.0), rel=1e-12, abs=1e-12)
            a = fisst.gospa(x, y, c=c, p=p, alpha=1.5)
            assert a.distance == pytest.approx(gospa_oracle(x, y, c, p, alpha=1.5), rel=1e-12, abs=1e-12)
            assert "localisation" not in a  # the decomposition exists for alpha = 2 only


def test_parity_fixture_bit_for_bit():
    for case in FIXTURE["gospa"]:
        g = fisst.gospa(case["truth"], case["estimate"], c=case["c"], p=case["p"], alpha=case["alpha"])
        assert g.distance == case["expected"]["distance"]
        if case["alpha"] == 2:
            assert g.localisation == case["expected"]["localisation"]
            assert g.assignment.tolist() == case["expected"]["assignment"] or (
                len(case["expected"]["assignment"]) == 0 and g.assignment.size == 0
            )
    for case in FIXTURE["ospa"]:
        o = fisst.ospa(case["truth"], case["estimate"], c=case["c"], p=case["p"])
        assert [o.distance, o.localisation, o.cardinality] == case["expected"]
    for case in FIXTURE["cardinality"]:
        assert fisst.multi_bernoulli_cardinality(case["existence"]).tolist() == case["expected"]
    for case in FIXTURE["optimal"]:
        e = fisst.mb_optimal_estimate(existence=case["existence"], metric=case["metric"], c=case["c"], p=case["p"])
        assert e.report.tolist() == case["expected"]["report"]
        assert e.mean_square_error == case["expected"]["meanSquareError"]


def test_array_likes_are_converted_once_and_agree():
    x = [[0.0, 0.0], [1.0, 2.0], [3.0, 1.0]]
    y = [[0.5, 0.0], [3.0, 1.5]]
    ref = fisst.gospa(x, y, c=2.0)
    forms = [
        np.array(x),
        np.array(x, dtype=np.float32).astype(np.float64),
        np.asfortranarray(np.array(x)),
        np.array([[0, 0, 9], [1, 2, 9], [3, 1, 9]], dtype=float)[:, :2],  # non-contiguous
        tuple(tuple(r) for r in x),
    ]
    for f in forms:
        assert fisst.gospa(f, y, c=2.0) == ref
    ints = fisst.gospa(np.array([[0, 0], [1, 2]]), [[0, 1]], c=2)
    assert ints == fisst.gospa([[0.0, 0.0], [1.0, 2.0]], [[0.0, 1.0]], c=2.0)
    f32 = fisst.gospa(np.array(x, dtype=np.float32), y, c=2.0)
    assert f32.distance == pytest.approx(ref.distance, rel=1e-6)
    assert fisst.gospa([], [], c=1.0).distance == 0.0
    assert fisst.gospa(np.empty((0, 2)), [[1.0, 1.0]], c=2.0).distance == pytest.approx(2 / math.sqrt(2))


def test_pandas_frames_are_point_sets():
    pd = pytest.importorskip("pandas")
    x = pd.DataFrame({"x": [0.0, 1.0], "y": [0.0, 2.0]})
    assert fisst.gospa(x, [[0.0, 1.0]], c=2.0) == fisst.gospa([[0.0, 0.0], [1.0, 2.0]], [[0.0, 1.0]], c=2.0)


def test_results_are_objects_with_attributes_repr_mapping_and_pickle():
    g = fisst.gospa([[0, 0], [10, 0]], [[0, 1]], c=2)
    assert isinstance(g, fisst.Result)
    assert g.type_name == "GospaReport"
    assert set(g.keys()) == {"distance", "localisation", "missed", "false_targets", "assignment"}
    assert g["distance"] == g.distance
    assert isinstance(g.assignment, np.ndarray) and g.assignment.dtype == np.int64
    assert g.assignment.tolist() == [[0, 0]]
    assert repr(g).startswith("GospaReport(distance=1.7320508075688772, localisation=1.0, missed=1")
    assert pickle.loads(pickle.dumps(g)) == g
    assert g != fisst.gospa([[0, 0]], [[0, 1]], c=2)
    with pytest.raises(AttributeError, match="GospaReport has no field 'missd'"):
        g.missd  # noqa: B018
    s = fisst.gospa_series(truths=[[[0, 0]], []], estimates=[[[0, 1]], [[1, 1]]], c=2)
    assert s.type_name == "GospaSeries"
    assert s.distance.dtype == np.float64 and s.distance.shape == (2,)
    assert s.missed.tolist() == [0, 0] and s.false_targets.tolist() == [0, 1]
    assert s.mean_distance == pytest.approx((1.0 + math.sqrt(2)) / 2)
    assert pickle.loads(pickle.dumps(s)) == s
    o = fisst.ospa_series(truths=[[[0, 0]], []], estimates=[[[0, 1]], [[1, 1]]], c=2)
    for t in range(2):
        one = fisst.ospa([[[0, 0]], []][t], [[[0, 1]], [[1, 1]]][t], c=2)
        assert o.distance[t] == one.distance
    a = fisst.linear_assignment([[1, 2], [3, 0]])
    assert a.pairs.tolist() == [[0, 0], [1, 1]] and a.cost == 1.0


def test_series_equal_per_step_calls():
    rng = np.random.default_rng(7)
    truths, estimates = [], []
    for _ in range(30):
        x, y = random_sets(rng, rng.integers(0, 6), rng.integers(0, 6))
        truths.append(x)
        estimates.append(y)
    s = fisst.gospa_series(truths=truths, estimates=estimates, c=1.5, p=1)
    for t, (x, y) in enumerate(zip(truths, estimates)):
        assert s.distance[t] == fisst.gospa(x, y, c=1.5, p=1).distance


def test_multi_bernoulli_estimators():
    e = fisst.mb_optimal_estimate(existence=[0.4, 0.4], metric="ospa")
    assert e.type_name == "MbEstimate" and e.report.dtype == np.bool_
    r = np.array([0.3, 0.7, 0.55])
    pmf = fisst.multi_bernoulli_cardinality(r)
    # eq. (6) by enumeration
    brute = np.zeros(4)
    for bits in itertools.product([0, 1], repeat=3):
        brute[sum(bits)] += np.prod([ri if b else 1 - ri for ri, b in zip(r, bits)])
    assert np.allclose(pmf, brute, rtol=0, atol=1e-15)
    loo = fisst.multi_bernoulli_leave_one_out(r)
    assert loo.shape == (3, 3)
    assert np.allclose(loo[0], fisst.multi_bernoulli_cardinality(r[1:]), atol=1e-15)
    mse = fisst.mb_mean_square_error(report=e.report, existence=[0.4, 0.4], metric="ospa")
    assert mse == e.mean_square_error
    m = fisst.mb_decision_map(estimator="gospa", resolution=4)
    assert m.type_name == "DecisionMap"
    counts = fisst.mb_identical_component_counts(existence=0.6, max_components=3)
    assert counts.n.tolist() == [1, 2, 3]


@pytest.mark.parametrize(
    "call, kind, message",
    [
        (lambda: fisst.gospa([[0, 0]], [[0]], c=2), ValueError, "estimate[0] has length 1, expected 2"),
        (lambda: fisst.gospa([[0, 0]], [[0, 0]], c=-1), ValueError, "c must be finite and > 0, got -1"),
        (lambda: fisst.gospa([[0, 0]], [[0, 0]], c="a"), TypeError, "c must be a real number, got str"),
        (lambda: fisst.gospa("x", [[0, 0]], c=1), TypeError, "truth must be an (n, d) array of numbers, got str"),
        (lambda: fisst.gospa([[0, float("nan")]], [[0, 0]], c=1), ValueError, "truth[0][1] must be finite, got NaN"),
        (lambda: fisst.gospa([0, 1], [[0, 0]], c=1), ValueError, "truth must be an (n, d) array (one row per point), got shape (2,)"),
        (lambda: fisst.gospa([[0, 0]], [[0, 0]], c=1, p=0.5), ValueError, "p must be"),
        (lambda: fisst.gospa_series(truths=[[[0, 0]]], estimates=[[[0]]], c=1), ValueError, "estimates[0][0]"),
        (lambda: fisst.mb_optimal_estimate(existence=[0.4], metric="ospa", cc=1), TypeError, "mb_optimal_estimate() got an unexpected keyword argument 'cc'"),
        (lambda: fisst.mb_optimal_estimate(existence=[0.4]), TypeError, "mb_optimal_estimate() missing required keyword argument 'metric'"),
        (lambda: fisst.mb_optimal_estimate(existence=[0.4, 1.4], metric="ospa"), ValueError, "existence[1] must be a probability in [0, 1], got 1.4"),
        (lambda: fisst.mb_optimal_estimate(existence=[0.4, "x"], metric="ospa"), TypeError, "existence[1]"),
        (lambda: fisst.mb_optimal_estimate(existence=[0.4], metric="opsa"), TypeError, "metric: unknown variant `opsa`"),
        (lambda: fisst.linear_assignment([[1, 2], [3]]), TypeError, "cost must be an (n, d) array of numbers"),
    ],
)
def test_errors_name_the_argument(call, kind, message):
    with pytest.raises(kind) as info:
        call()
    assert str(info.value).startswith(message), str(info.value)


def test_docstrings_name_the_paper_and_the_signature():
    import inspect

    assert "paper 003" in fisst.gospa.__doc__ and "Prop. 3" in fisst.gospa.__doc__
    assert str(inspect.signature(fisst.gospa)) == "(truth, estimate, *, c, p=2.0, alpha=2.0)"
    assert str(inspect.signature(fisst.mb_optimal_estimate)) == "(*, existence, metric, c=1.0, p=2.0, alpha=2.0)"
    for name in fisst.__all__:
        obj = getattr(fisst, name)
        if callable(obj):
            assert obj.__doc__ and len(obj.__doc__) > 40, name


def test_fixed_size_and_slice_points_give_the_same_bits():
    """2-D and 3-D point sets go to the core as fixed-size points, others as slices: padding
    with zero coordinates (exact) switches the path and must not change a bit."""
    rng = np.random.default_rng(5)
    for n, m in [(0, 4), (5, 0), (7, 9), (40, 33)]:
        x, y = rng.uniform(0, 10, (n, 2)), rng.uniform(0, 10, (m, 2))
        pad = lambda a, d: np.hstack([a, np.zeros((len(a), d - 2))])  # noqa: E731
        for p in (1.0, 2.0, 3.5):
            ref = fisst.gospa(x, y, c=3.0, p=p)
            for d in (3, 4, 5):
                g = fisst.gospa(pad(x, d), pad(y, d), c=3.0, p=p)
                assert (g.distance, g.localisation, g.missed, g.false_targets) == (
                    ref.distance, ref.localisation, ref.missed, ref.false_targets)
                assert g.assignment.tolist() == ref.assignment.tolist()
                assert fisst.ospa(pad(x, d), pad(y, d), c=3.0, p=p) == fisst.ospa(x, y, c=3.0, p=p)
                assert fisst.uospa(pad(x, d), pad(y, d), c=3.0, p=p).distance == fisst.uospa(x, y, c=3.0, p=p).distance
        s2 = fisst.gospa_series(truths=[x, x[:1], []], estimates=[y, [], y[:2]], c=3.0)
        s4 = fisst.gospa_series(truths=[pad(x, 4), pad(x[:1], 4), []], estimates=[pad(y, 4), [], pad(y[:2], 4)], c=3.0)
        assert s2.distance.tobytes() == s4.distance.tobytes()
    # a 2-D set against a 3-D one is still the core's error, naming the argument
    with pytest.raises(ValueError, match=r"^estimate\[0\] has length 3, expected 2"):
        fisst.gospa([[0.0, 0.0]], [[0.0, 0.0, 0.0]], c=1.0)
