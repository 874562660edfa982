"""fisst.stonesoup against Stone Soup 1.9.1's own metric generators on a Stone Soup scenario:
GOSPA equal to 1e-12 (with and without a switching penalty), OSPA equal at p = 1, and at
p = 2, where the two differ, fisst's value is the optimum (brute force over every assignment
on the small steps)."""

import datetime
import itertools
import math

import numpy as np
import pytest

stonesoup = pytest.importorskip("stonesoup")

from stonesoup.measures import Euclidean, Mahalanobis  # noqa: E402
from stonesoup.metricgenerator.manager import MultiManager  # noqa: E402
from stonesoup.metricgenerator.ospametric import GOSPAMetric as SSGOSPA  # noqa: E402
from stonesoup.metricgenerator.ospametric import OSPAMetric as SSOSPA  # noqa: E402
from stonesoup.types.groundtruth import GroundTruthPath, GroundTruthState  # noqa: E402
from stonesoup.types.state import GaussianState  # noqa: E402
from stonesoup.types.track import Track  # noqa: E402

from fisst import stonesoup as fs  # noqa: E402

START = datetime.datetime(2026, 12, 4)


def scenario(seed=3, steps=40, objects=7, crowded=1.0):
    """Objects moving in 2-D (state x, vx, y, vy) that appear and vanish; tracks are noisy
    copies, some missing, plus false tracks."""
    rng = np.random.default_rng(seed)
    truths, tracks = set(), set()
    for _ in range(objects):
        born, dies = sorted(rng.integers(0, steps, 2))
        x = np.array([rng.uniform(0, 20 * crowded), rng.normal(), rng.uniform(0, 20 * crowded), rng.normal()])
        path, track = GroundTruthPath(), Track()
        for k in range(born, dies + 1):
            x = x + np.array([x[1], 0, x[3], 0]) * 0.5
            t = START + datetime.timedelta(seconds=k)
            path.append(GroundTruthState(x.reshape(-1, 1), timestamp=t))
            if rng.uniform() < 0.85:
                track.append(GaussianState((x + rng.normal(0, 0.7, 4)).reshape(-1, 1), np.eye(4), timestamp=t))
        truths.add(path)
        if len(track):
            tracks.add(track)
    for _ in range(3):
        track = Track()
        k0 = int(rng.integers(0, steps - 5))
        for k in range(k0, k0 + 5):
            y = rng.uniform(0, 20 * crowded, 4)
            track.append(GaussianState(y.reshape(-1, 1), np.eye(4), timestamp=START + datetime.timedelta(seconds=k)))
        tracks.add(track)
    return truths, tracks


def run(generators, truths, tracks):
    manager = MultiManager(generators)
    manager.add_data({"groundtruth_paths": truths, "tracks": tracks})
    return manager.generate_metrics()


def steps_of(metric):
    return metric.value if isinstance(metric.value, list) else [metric]


@pytest.mark.parametrize("p", [1, 2])
@pytest.mark.parametrize("switching", [0.0, 3.0])
def test_gospa_equals_stone_soups(p, switching):
    truths, tracks = scenario()
    measure = Euclidean(mapping=[0, 2])
    args = dict(p=p, c=5, switching_penalty=switching, measure=measure)
    ss = run([SSGOSPA(**args, generator_name="ss")], truths, tracks)["ss"]["GOSPA Metrics"]
    ours = run([fs.GOSPAMetric(**args, generator_name="fisst")], truths, tracks)["fisst"]["GOSPA Metrics"]
    assert type(ours) is type(ss) and ours.title == ss.title and ours.time_range == ss.time_range
    assert len(ours.value) == len(ss.value) > 10
    for a, b in zip(ours.value, ss.value):
        assert a.timestamp == b.timestamp and a.title == b.title
        assert set(a.value) == set(b.value)
        for key in b.value:
            assert a.value[key] == pytest.approx(b.value[key], rel=1e-12, abs=1e-12), (key, a.timestamp)


def brute_ospa(x, y, c, p):
    n = max(len(x), len(y))
    if n == 0:
        return 0.0
    s, l = (x, y) if len(x) <= len(y) else (y, x)
    best = min(
        (sum(min(math.dist(s[i], l[j]), c) ** p for i, j in enumerate(perm)) for perm in itertools.permutations(range(len(l)), len(s))),
        default=0.0,
    )
    return ((best + c**p * (n - len(s))) / n) ** (1 / p)


def test_ospa_equals_stone_soups_at_p1_and_is_the_optimum_at_p2():
    truths, tracks = scenario(seed=0, steps=60, objects=12, crowded=0.1)
    measure = Euclidean(mapping=[0, 2])
    for p in (1, 2):
        ss = run([SSOSPA(p=p, c=6, measure=measure, generator_name="ss")], truths, tracks)["ss"]["OSPA distances"]
        ours = run([fs.OSPAMetric(p=p, c=6, measure=measure, generator_name="f")], truths, tracks)["f"]["OSPA distances"]
        assert ours.title == ss.title and len(ours.value) == len(ss.value)
        by_time = fs.points_by_time(truths, [0, 2])
        est_by_time = fs.points_by_time(tracks, [0, 2])
        differ = checked = 0
        for a, b in zip(ours.value, ss.value):
            assert a.timestamp == b.timestamp
            if p == 1:
                assert a.value == pytest.approx(b.value, rel=1e-12, abs=1e-12)
                continue
            assert a.value <= b.value + 1e-12  # never above Stone Soup's
            if abs(a.value - b.value) > 1e-12:
                differ += 1
                x = by_time.get(a.timestamp, (np.empty((0, 2)), None))[0].tolist()
                y = est_by_time.get(a.timestamp, (np.empty((0, 2)), None))[0].tolist()
                if max(len(x), len(y)) <= 8:
                    checked += 1
                    assert a.value == pytest.approx(brute_ospa(x, y, 6, 2), rel=1e-12, abs=1e-12)
        if p == 2:
            print(f"OSPA p = 2: fisst below Stone Soup at {differ} of {len(ours.value)} steps")
            assert differ > 0 and checked > 0, "the crowded scenario should show Stone Soup's p = 1 assignment"



def test_unsupported_arguments_are_value_errors_naming_them():
    with pytest.raises(ValueError, match="^measure = Mahalanobis is not supported"):
        fs.GOSPAMetric(p=1, c=2, measure=Mahalanobis())
    with pytest.raises(ValueError, match="^p = inf is not supported"):
        fs.OSPAMetric(p=np.inf, c=2)
    with pytest.raises(ValueError, match="^switching_penalty = 1 is not supported by OSPA"):
        fs.OSPAMetric(p=1, c=2, switching_penalty=1)
    with pytest.raises(ValueError, match="^c must be finite and > 0"):
        fs.GOSPAMetric(p=1, c=-2)


def test_gospa_distance_is_plottable():
    import matplotlib

    matplotlib.use("Agg")
    from stonesoup.plotter import MetricPlotter

    truths, tracks = scenario()
    metrics = run([fs.GOSPADistanceMetric(p=1, c=5, measure=Euclidean(mapping=[0, 2]))], truths, tracks)
    m = metrics["gospa_distance_generator"]["GOSPA distance"]
    assert all(isinstance(s.value, float) for s in m.value)
    plotter = MetricPlotter()
    plotter.plot_metrics(metrics)
    assert plotter.fig is not None


def test_conversions():
    truths, _ = scenario(steps=8, objects=2)
    states, ids = fs.extract_states(truths)
    assert len(states) == len(ids)
    pts = fs.state_points(states, [0, 2])
    assert pts.shape == (len(states), 2)
    grouped = fs.points_by_time(truths)
    assert sum(len(v[0]) for v in grouped.values()) == len(states)
    with pytest.raises(TypeError, match=r"objects\[0\] must be a State"):
        fs.extract_states([1])


def naive_by_time(objects):
    """The grouping points_by_time gives, by a plain loop over the states."""
    out = {}
    for i, obj in enumerate(objects):
        states = list(obj.last_timestamp_generator()) if isinstance(obj, (Track, GroundTruthPath)) else [obj]
        for s in states:
            pts, ids = out.setdefault(s.timestamp, ([], []))
            pts.append(np.asarray(s.state_vector, dtype=float).ravel())
            ids.append(i)
    return out


@pytest.mark.parametrize("shuffle", [False, True])
def test_points_by_time_flat_states_and_mixed_objects(shuffle):
    rng = np.random.default_rng(11)
    truths, tracks = scenario(steps=12, objects=4)
    flat = [s for path in truths for s in path]
    if shuffle:
        flat = [flat[i] for i in rng.permutation(len(flat))]
    mixed = [*tracks, *flat[:5]]  # sequences of states and single states together
    for objects in (flat, mixed):
        got, want = fs.points_by_time(objects), naive_by_time(objects)
        assert list(got) == list(want)  # timestamps in order of first appearance
        for t, (pts, ids) in got.items():
            np.testing.assert_array_equal(pts, np.array(want[t][0]))
            np.testing.assert_array_equal(ids, want[t][1])
    states, ids = fs.extract_states(flat)
    assert states == flat and ids == list(range(len(flat)))
    with pytest.raises(TypeError, match=r"objects\[1\] must be a State"):
        fs.extract_states([flat[0], "not a state"])
