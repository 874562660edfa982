"""fisst.jde_bound and fisst.jde_monte_carlo (paper 002, Rezaeian & Vo, "Error bounds for joint
detection and estimation of a single object with random finite set observation"): the npm
package's numbers for the same inputs, the defaults, the seed, numpy inputs, and errors that
name the argument (TypeError for a wrong kind of value, ValueError for a bad value)."""

import pickle
import threading
import time

import numpy as np
import pytest

import fisst

U = {"uniform": {"low": -10, "high": 10}}
SCALAR = dict(model="I", existence=0.5, prior={"gaussian": {"mean": 1, "variance": 4}},
              observation={"detection_probability": 0.9, "noise_variance": 1}, false_alarm_error=15, miss_error=20)
VECTOR = dict(model="I", existence=0.6, prior={"multivariate_gaussian": {"mean": [0, 1], "cov": [[2, 0.5], [0.5, 1]]}},
              observation={"detection_probability": 0.8, "gain": [[1, 0], [0, 1]], "noise_cov": [[1, 0], [0, 2]]},
              false_alarm_error=50, miss_error=60)
MC = dict(model="II", existence=0.5, prior={"gaussian": {"mean": 0, "variance": 1}},
          observation={"detection_probability": 0.9, "noise_variance": 1}, clutter={"rate": 1, "density": U},
          false_alarm_error=1, miss_error=1, samples=300, seed=5, empty_rule="map")


def bits(x):
    return float(x).hex()


def test_thm2_equals_the_npm_package():
    # node: fisst.jdeBound({ model: 'II', existence: 0.7, prior: { gaussian: { mean: 1, variance: 4 } },
    #   observation: { detectionProbability: { table: { x: [-3, 3], probability: [0.3, 0.9] } }, noiseVariance: 1 },
    #   clutter: { rate: 0.5, density: U }, falseAlarmError: 10, missError: 20, samples: 500, seed: 3 })
    r = fisst.jde_bound(model="II", existence=0.7, prior={"gaussian": {"mean": 1, "variance": 4}},
                        observation={"detection_probability": {"table": {"x": [-3, 3], "probability": [0.3, 0.9]}}, "noise_variance": 1},
                        clutter={"rate": 0.5, "density": U}, false_alarm_error=10, miss_error=20, samples=500, seed=3)
    assert bits(r.bound) == bits(4.3553567451734505)
    assert bits(r.error) == bits(0.09182000924972392)
    assert r.seed == 3
    assert r.phase in ("HPE", "LPE")
    assert r.bound == min(r.hpe, r.lpe)


def test_eq11_monte_carlo_equals_the_npm_package():
    # node: fisst.jdeMonteCarlo({ model: 'II', existence: 0.5, prior: { gaussian: { mean: 0, variance: 1 } },
    #   observation: { detectionProbability: 0.9, noiseVariance: 1 }, clutter: { rate: 1, density: U },
    #   falseAlarmError: 1, missError: 1, samples: 300, seed: 5, emptyRule: 'map' })
    m = fisst.jde_monte_carlo(**MC)
    assert bits(m.mse) == bits(0.42837571927561496)
    assert bits(m.se) == bits(0.0389954241762204)
    assert m.seed == 5 and m.samples == 300
    assert m.mse == pytest.approx(m.false_alarm + m.miss + m.estimation)


def test_cor3_the_monte_carlo_lies_above_the_bound_it_attains():
    # no clutter, a Gaussian prior: the bound (31) is attained by the optimal detector-estimator
    b = fisst.jde_bound(**SCALAR)
    m = fisst.jde_monte_carlo(**SCALAR, samples=20_000, seed=1)
    assert abs(m.mse - b.bound) < 4 * m.se


def test_defaults_are_the_npm_packages():
    # gain 1, offset 0; the Monte Carlo's samples 20,000, one scan, the optimal rule on Z = ∅
    explicit = dict(SCALAR, observation={"detection_probability": 0.9, "gain": 1, "offset": 0, "noise_variance": 1})
    assert fisst.jde_bound(**SCALAR).bound == fisst.jde_bound(**explicit).bound
    a = fisst.jde_monte_carlo(**SCALAR, seed=4)
    b = fisst.jde_monte_carlo(**SCALAR, seed=4, samples=20_000, scans=1, empty_rule="optimal")
    assert a == b and a.samples == 20_000 and len(a.scans) == 1


def test_the_seed_reproduces_the_run():
    a = fisst.jde_monte_carlo(**dict(MC, seed=None))
    assert isinstance(a.seed, int)
    assert fisst.jde_monte_carlo(**dict(MC, seed=a.seed)) == a
    assert fisst.jde_monte_carlo(**dict(MC, seed=a.seed + 1)).mse != a.mse
    # Theorem 2's Monte Carlo: omitted seed drawn and reported
    r = fisst.jde_bound(**dict(SCALAR, model="II", samples=200))
    assert "seed" not in r.keys()  # no clutter: nothing sampled, no seed (as in the npm package)
    r = fisst.jde_bound(**dict(SCALAR, model="II", clutter={"rate": 0.5, "density": U}, samples=200))
    assert fisst.jde_bound(**dict(SCALAR, model="II", clutter={"rate": 0.5, "density": U}, samples=200, seed=r.seed)).bound == r.bound


def test_eq63_vector_prior_takes_numpy_arrays():
    ref = fisst.jde_bound(**VECTOR)
    assert ref.components is not None and len(ref.components) == 2
    assert ref.inverse_information_matrix.shape == (2, 2)
    arrays = dict(VECTOR, prior={"multivariate_gaussian": {"mean": np.array([0, 1], dtype=np.int64),
                                                           "cov": np.array([[2, 0.5], [0.5, 1]], dtype=np.float32)}},
                  observation={"detection_probability": np.float64(0.8), "gain": np.eye(2)[:, ::1], "noise_cov": np.array([1.0, 0, 0, 2])})
    got = fisst.jde_bound(**arrays)
    assert got.bound == ref.bound
    np.testing.assert_array_equal(got.inverse_information_matrix, ref.inverse_information_matrix)
    assert pickle.loads(pickle.dumps(got)) == got


@pytest.mark.parametrize("change, error, start", [
    (dict(observation={"detection_probability": 0.9, "gain": [[1.0]], "noise_variance": 1}), TypeError, "observation.gain must be a number with a 1D prior"),
    (dict(observation={"detection_probability": 0.9, "noise_cov": [[1.0]], "noise_variance": 1}), TypeError, "observation.noise_cov is for a multivariate_gaussian prior"),
    (dict(observation={"detection_probability": 0.9}), TypeError, "observation.noise_variance is required"),
    (dict(observation={"detection_probability": 0.9, "noise_variance": 0}), ValueError, "observation.noise_variance"),
    (dict(observation={"detection_probability": 1.5, "noise_variance": 1}), ValueError, "observation.detection_probability"),
    (dict(clutter={"rate": 1, "density": U}), TypeError, "clutter is for model 'II' (use false_alarm with model 'I')"),
    (dict(existence=2), ValueError, "existence must be a probability"),
    (dict(prior={"gaussian": {"mean": 0, "variance": -1}}), ValueError, "prior"),
    (dict(prior={"gausian": {}}), TypeError, "prior"),
    (dict(model="III"), TypeError, "model"),
    (dict(dims=2), ValueError, "dims"),
    (dict(false_alarm={"probability": 1.2, "density": U}), ValueError, "false_alarm.probability"),
    (dict(tolerance="x"), TypeError, "tolerance"),
    (dict(bogus=1), TypeError, "jde_bound() got an unexpected keyword argument 'bogus'"),
])
def test_jde_bound_errors_name_the_argument(change, error, start):
    with pytest.raises(error) as e:
        fisst.jde_bound(**dict(SCALAR, **change))
    assert str(e.value).startswith(start), str(e.value)


@pytest.mark.parametrize("change, error, start", [
    (dict(observation={"detection_probability": 0.8, "gain": 1, "noise_cov": [[1]]}), TypeError, "observation.gain must be H, m rows of 2 numbers"),
    (dict(observation={"detection_probability": 0.8, "gain": [[1, 0.5], [1]], "noise_cov": [[1, 0], [0, 1]]}), ValueError,
     "observation.gain[1] has length 1, expected 2 (the state dimension)"),
    (dict(observation={"detection_probability": 0.8, "gain": [[1, 0]], "noise_variance": 1, "noise_cov": [[1]]}), TypeError,
     "observation.noise_variance and observation.noise_cov are alternatives: give one"),
    (dict(observation={"detection_probability": {"table": {"x": [0, 1], "probability": [0.5, 0.9]}}, "gain": [[1, 0]], "noise_cov": [[1]]}), TypeError,
     "observation.detection_probability must be a number (a constant P_o) with a multivariate_gaussian prior"),
    (dict(prior={"multivariate_gaussian": {"mean": [0, 0], "cov": [[1.25, 0], [0, -0.25]]}}), ValueError,
     "prior.multivariate_gaussian.cov is not positive definite (smallest eigenvalue -0.25)"),
    (dict(prior={"multivariate_gaussian": {"mean": [0, 0], "cov": 1}}), TypeError, "prior.multivariate_gaussian.cov must be a nested 2×2 array"),
])
def test_eq63_vector_errors_name_the_argument(change, error, start):
    with pytest.raises(error) as e:
        fisst.jde_bound(**dict(VECTOR, **change))
    assert str(e.value).startswith(start), str(e.value)


@pytest.mark.parametrize("change, error, start", [
    (dict(samples=1), ValueError, "samples"),
    (dict(samples=6_000_000), ValueError, "samples"),
    (dict(scans=2), ValueError, "scans"),
    (dict(empty_rule="hpe"), TypeError, "empty_rule"),
    (dict(seed=-1), (TypeError, ValueError), "seed"),
    (dict(clutter=None, false_alarm={"probability": 0.2, "density": U}), TypeError, "false_alarm is for model 'I' (use clutter with model 'II')"),
    (dict(prior="example2", observation={"detection_probability": {"table": {"x": [0, 1], "probability": [0.5, 0.9]}}}), TypeError,
     "observation.detection_probability must be a number (a constant P_o) for 'example2'"),
    (dict(prior={"uniform": {"low": 0, "high": 1}}), ValueError, "prior"),
    (dict(sample=10), TypeError, "jde_monte_carlo() got an unexpected keyword argument 'sample'"),
])
def test_jde_monte_carlo_errors_name_the_argument(change, error, start):
    options = dict(MC, **change)
    options = {k: v for k, v in options.items() if v is not None}
    with pytest.raises(error) as e:
        fisst.jde_monte_carlo(**options)
    assert str(e.value).startswith(start), str(e.value)


def test_help_cites_the_paper():
    for f in (fisst.jde_bound, fisst.jde_monte_carlo):
        assert "paper 002" in f.__doc__
    assert "(63)" in fisst.jde_bound.__doc__ and "(11)" in fisst.jde_monte_carlo.__doc__


def test_the_monte_carlo_releases_the_gil():
    # while one thread runs 5·10^6 simulated scenes (GIL released), the main thread keeps
    # running Python code, and the result is the same as in the main thread
    done = threading.Event()
    out = []

    def work():
        out.append(fisst.jde_monte_carlo(**SCALAR, samples=5_000_000, seed=1))
        done.set()

    t = threading.Thread(target=work)
    t.start()
    ticks = 0
    while not done.is_set():
        ticks += 1
        time.sleep(0)
    t.join()
    assert ticks > 10, ticks
    assert out[0] == fisst.jde_monte_carlo(**SCALAR, samples=5_000_000, seed=1)
