"""The splitting exports and the worked examples of paper 001 (LeGrand & Ferrari, "Split Happens!")."""

import pickle

import numpy as np
import pytest

import fisst

I2 = [[1.0, 0.0], [0.0, 1.0]]
UNIT = [{"weight": 1.0, "mean": [0.0, 0.0], "cov": I2}]
HALF = {"box": {"min": [0.3, -10.0], "max": [10.0, 10.0]}}


def test_split_library_is_table1_and_its_objective():
    t = fisst.split_library(components=4, lambda_=0.001)
    assert t.type_name == "SplitLibraryReport"
    # Table I of paper 001, as printed
    assert t.weights.tolist() == [0.10766586425362, 0.39233413574638, 0.39233413574638, 0.10766586425362]
    assert t.means.tolist() == [-1.42237156603631, -0.47412385534547, 0.47412385534547, 1.42237156603631]
    assert t.sigma == 0.58160633157686
    assert abs(t.variance - (t.sigma**2 + float(np.sum(t.weights * t.means**2)))) < 1e-15
    free = fisst.split_library(components=4, lambda_=0.001, spacing="free")
    assert free.objective < t.objective  # a larger family, a lower J of eq. (13)


def test_split_for_regions_partition_mask_and_exact_mass():
    r = fisst.split_for_regions(mixture=UNIT, regions=[HALF])
    w = np.array([c["weight"] for c in r.mixture])
    assert r.inside_mask.dtype == np.bool_ and len(r.inside_mask) == len(w)
    assert w[r.inside_mask].sum() == pytest.approx(r.inside, abs=1e-12)
    assert r.inside + r.outside == pytest.approx(1.0, abs=1e-9)
    # eq. (8): ⟨1_S, N(0, I)⟩ = 1 − Φ(0.3)
    assert r.exact_inside == pytest.approx(0.3820885778, abs=1e-9)
    assert abs(r.inside - r.exact_inside) < 0.03 and r.splits > 0 and r.stop is None
    capped = fisst.split_for_regions(mixture=UNIT, regions=[HALF], max_depth=1)
    assert capped.stop == "maxDepth" and capped.depth == 1
    # the regions in any order give the same split
    disc = {"ball": {"center": [0.0, 0.0], "radius": 1.0}}
    a = fisst.split_for_regions(mixture=UNIT, regions=[HALF, disc])
    b = fisst.split_for_regions(mixture=UNIT, regions=[disc, HALF])
    assert len(a.mixture) == len(b.mixture)
    assert pickle.loads(pickle.dumps(r)).inside == r.inside


def test_negative_information_scenario_whole_and_one_step():
    whole = fisst.negative_information_scenario()
    assert whole.type_name == "NegativeInformationReport"
    assert whole.fov["box"].min.tolist() == [-1.5, -1.5] and whole.fov["box"].max.tolist() == [1.5, 1.5]
    assert [s.step for s in whole.steps] == [1, 2, 3]
    two = fisst.negative_information_scenario(step=2)
    assert two.non_detection_prob == whole.steps[1].non_detection_prob
    assert len(two.split) >= len(two.predicted) and two.depth >= 1
    # each update leaves little mass in the FoV (Fig. 5)
    assert all(s.posterior_inside < s.predicted_inside for s in whole.steps)


def test_airport_scenario_is_seeded_and_its_config_drives_a_filter():
    a = fisst.airport_scenario(seed=7, steps=5)
    assert a.truth[4].state.tolist() == fisst.airport_scenario(seed=7, steps=5).truth[4].state.tolist()
    assert (a.seed, a.config.seed, len(a.truth), len(a.reports)) == (7, 7, 5, 5)
    assert len(a.anchors) == 10 and set(a.fov) == {"union"} and set(a.fov["union"][0]) == {"ball"}
    assert set(a.config.transition) == {"F", "Q"}
    assert fisst.airport_scenario(steps=0).seed >= 0  # a fresh seed, reported


@pytest.mark.parametrize(
    "call, kind, message",
    [
        (lambda: fisst.split_library(components=17, lambda_=0.001), ValueError, "components must be an integer in [2, 16], got 17"),
        (lambda: fisst.split_library(components=4, lambda_=0.0), ValueError, "lambda_ must be"),
        (lambda: fisst.split_library(components=4), TypeError, "split_library() missing required keyword argument 'lambda_'"),
        (lambda: fisst.split_library(components=4, lambda_=0.001, spacing="wide"), TypeError, "spacing: unknown variant `wide`"),
        (lambda: fisst.split_for_regions(mixture=UNIT, regions=[]), ValueError, "regions must have 1 to 32 entries, got 0"),
        (lambda: fisst.split_for_regions(mixture=[{"weight": 1, "mean": [0, 0], "cov": [[1, 2], [2, 1]]}], regions=[HALF]), ValueError, "mixture[0].cov"),
        (lambda: fisst.split_for_regions(mixture=UNIT, regions=[{"box": {"min": [1, 1], "max": [-1, -1]}}]), ValueError, "regions[0]"),
        (lambda: fisst.split_for_regions(mixture=UNIT, regions=[HALF], grid_points=200), ValueError, "grid_points^position_dims: collocation points per component = 40000 exceeds 20000 (at most 141)"),
        (lambda: fisst.split_for_regions(mixture=UNIT, regions=[HALF], grid_points=141, max_components=50000), ValueError, "max_components: "),
        (lambda: fisst.negative_information_scenario(step=4), ValueError, "step must be an integer in [1, 3], got 4"),
        (lambda: fisst.airport_scenario(seed=1, steps=2001), ValueError, "steps must be an integer in [0, 2000], got 2001"),
        (lambda: fisst.airport_scenario(seed="1"), TypeError, "seed"),
    ],
)
def test_errors_name_the_argument(call, kind, message):
    with pytest.raises(kind) as info:
        call()
    assert str(info.value).startswith(message), str(info.value)
