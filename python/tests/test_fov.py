"""The field-of-view functions of paper 001 (Sections VI–VII) from Python, against independent
oracles: the Poisson pmf (78) and the multi-Bernoulli pmf (88) by enumeration from masses
computed here with math.erf, the variance map cell by cell against fov_cardinality, the density
grid against the Gaussian pdf written out; array shapes and orientation (rows are y); the
scene's prefix property; errors naming the argument in Python's names."""

import itertools
import math

import numpy as np
import pytest

import fisst


def box_mass(mean, var, lo, hi):
    """The mass of N(mean, diag(var)) in the box [lo, hi] (independent axes)."""
    out = 1.0
    for m, v, a, b in zip(mean, var, lo, hi):
        s = math.sqrt(2 * v)
        out *= 0.5 * (math.erf((b - m) / s) - math.erf((a - m) / s))
    return out


def diag(var):
    return [[var[0], 0.0], [0.0, var[1]]]


BOX = {"box": {"min": [-1.0, -0.5], "max": [1.5, 2.0]}}
LO, HI = BOX["box"]["min"], BOX["box"]["max"]


def test_eq78_poisson_pmf_is_poisson_of_the_expected_count_inside():
    comps = [(2.0, [0.0, 0.0], [1.0, 0.5]), (0.7, [1.0, 1.5], [0.3, 0.2]), (1.1, [4.0, 0.0], [0.5, 0.5])]
    phd = [{"weight": w, "mean": m, "cov": diag(v)} for w, m, v in comps]
    r = fisst.fov_cardinality(rfs={"poisson": phd}, fov=BOX, detection_probability=0.8)
    masses = [box_mass(m, v, LO, HI) for _, m, v in comps]
    np.testing.assert_allclose(r.mass_in_fov, masses, rtol=1e-12, atol=1e-15)
    lam = 0.8 * sum(w * q for (w, _, _), q in zip(comps, masses))
    want = [math.exp(-lam) * lam**n / math.factorial(n) for n in range(len(r.pmf))]
    np.testing.assert_allclose(r.pmf, want, rtol=1e-10, atol=1e-15)
    assert r.mean == pytest.approx(lam, rel=1e-12)
    assert r.variance == pytest.approx(lam, rel=1e-12)


def test_eq88_multi_bernoulli_pmf_equals_enumeration():
    comps = [(0.9, [0.0, 0.0], [1.0, 0.5]), (0.4, [1.0, 1.5], [0.3, 0.2]), (0.65, [2.0, -1.0], [0.5, 0.8]), (0.2, [0.5, 0.5], [2.0, 2.0])]
    mb = [{"existence": r, "mean": m, "cov": diag(v)} for r, m, v in comps]
    r = fisst.fov_cardinality(rfs={"multi_bernoulli": mb}, fov=BOX)
    inside = [e * box_mass(m, v, LO, HI) for e, m, v in comps]
    want = np.zeros(len(comps) + 1)
    for bits in itertools.product([0, 1], repeat=len(comps)):
        want[sum(bits)] += math.prod(q if b else 1 - q for q, b in zip(inside, bits))
    np.testing.assert_allclose(r.pmf, want, rtol=1e-11, atol=1e-15)
    assert r.variance == pytest.approx(sum(q * (1 - q) for q in inside), rel=1e-11)


def test_fig10_variance_map_rows_are_y_and_cells_are_fov_cardinality():
    scene = fisst.placement_scene(count=12, seed=4, extent=2.0).multi_bernoulli
    grid = {"x": (-2.0, 2.0, 5), "y": (-1.0, 1.0, 3)}
    vmap = fisst.fov_variance_map(multi_bernoulli=scene, fov_size=(1.0, 0.8), grid=grid)
    assert vmap.variance.shape == (3, 5)
    xs, ys = np.linspace(-2, 2, 5), np.linspace(-1, 1, 3)
    for j, y in enumerate(ys):
        for i, x in enumerate(xs):
            fov = {"box": {"min": [x - 0.5, y - 0.4], "max": [x + 0.5, y + 0.4]}}
            want = fisst.fov_cardinality(rfs={"multi_bernoulli": scene}, fov=fov).variance
            assert vmap.variance[j, i] == pytest.approx(want, rel=1e-9, abs=1e-12)
    j, i = np.unravel_index(np.argmax(vmap.variance), vmap.variance.shape)
    assert list(vmap.argmax) == pytest.approx([xs[i], ys[j]])
    assert vmap.max == vmap.variance.max()


def test_fig9_density_grid_is_the_mixture_pdf_with_rows_y():
    mixture = [{"weight": 0.7, "mean": [0.0, 0.0], "cov": [[1.0, 0.3], [0.3, 0.8]]},
               {"weight": 1.2, "mean": [1.0, -1.0], "cov": [[0.5, 0.0], [0.0, 0.4]]}]
    d = fisst.mixture_density_grid(mixture=mixture, grid={"x": (-2, 2, 6), "y": (-1, 1, 4)})
    assert d.shape == (4, 6)
    for j, y in enumerate(np.linspace(-1, 1, 4)):
        for i, x in enumerate(np.linspace(-2, 2, 6)):
            want = 0.0
            for c in mixture:
                p = np.array(c["cov"])
                e = np.array([x, y]) - c["mean"]
                want += c["weight"] * math.exp(-0.5 * e @ np.linalg.solve(p, e)) / (2 * math.pi * math.sqrt(np.linalg.det(p)))
            assert d[j, i] == pytest.approx(want, rel=1e-12)


def test_scene_is_seeded_a_prefix_and_feeds_the_other_calls():
    big = fisst.placement_scene(count=20, seed=7).multi_bernoulli
    small = fisst.placement_scene(count=5, seed=7).multi_bernoulli
    assert len(big) == 20 and len(small) == 5
    for a, b in zip(small, big):
        assert a.existence == b.existence and (a.mean == b.mean).all() and (a.cov == b.cov).all()
        assert 0.35 <= a.existence < 1 and a.mean.shape == (2,) and a.cov.shape == (2, 2)
    assert fisst.placement_scene().multi_bernoulli[0].existence == fisst.placement_scene(seed=1, count=100).multi_bernoulli[0].existence
    r = fisst.fov_cardinality(rfs={"multi_bernoulli": small}, fov={"ball": {"center": [0, 0], "radius": 10}})
    assert r.mean == pytest.approx(sum(c.existence for c in small), rel=1e-9)


MB = [{"existence": 0.5, "mean": [0.0, 0.0], "cov": [[1.0, 0.0], [0.0, 1.0]]}]
W = {"weight": 1.0, "mean": [0.0, 0.0], "cov": [[1.0, 0.0], [0.0, 1.0]]}


@pytest.mark.parametrize("call, kind, message", [
    (lambda: fisst.fov_cardinality(rfs={"multi_bernoulli": MB}, fov=BOX, detection_probability=90), ValueError, r"^detection_probability must be a probability"),
    (lambda: fisst.fov_cardinality(rfs={"multi_bernoulli": [dict(MB[0], existence=1.5)]}, fov=BOX), ValueError, r"^rfs\.multi_bernoulli\[0\]\.existence"),
    (lambda: fisst.fov_cardinality(rfs={"multi_bernoulli": MB}, fov={"ball": {"center": [0, 0, 0], "radius": 1}}), ValueError, r"^fov\.ball\.center has length 3 but rfs\.multi_bernoulli\[0\]\.mean has length 2"),
    (lambda: fisst.fov_cardinality(rfs={"iid_cluster": {"cardinality": [0.0] * 20002 + [1.0], "density": [W]}}, fov=BOX), ValueError, r"^rfs\.iid_cluster\.cardinality has 20003 entries"),
    (lambda: fisst.fov_cardinality(rfs={"glmb": [{"weight": 0.5, "components": []}]}, fov=BOX), ValueError, r"^rfs\.glmb"),
    (lambda: fisst.fov_cardinality(rfs={"multiBernoulli": MB}, fov=BOX), TypeError, r"^rfs: unknown variant `multiBernoulli`"),
    (lambda: fisst.fov_cardinality(rfs={"multi_bernoulli": MB}), TypeError, r"missing required keyword argument 'fov'"),
    (lambda: fisst.fov_variance_map(multi_bernoulli=MB, fov_size=(1, 0), grid={"x": (0, 1, 2), "y": (0, 1, 2)}), ValueError, r"^fov_size\[1\]"),
    (lambda: fisst.fov_variance_map(multi_bernoulli=MB, fov_size=(1, 1), grid={"x": (0, 1, 2.5), "y": (0, 1, 2)}), ValueError, r"^grid\.x\[2\] must be an integer count in \[1, 4096\]"),
    (lambda: fisst.fov_variance_map(multi_bernoulli=MB * 13, fov_size=(1, 1), grid={"x": (0, 1, 4096), "y": (0, 1, 4096)}), ValueError, r"^multi_bernoulli: components × grid cells"),
    (lambda: fisst.mixture_density_grid(mixture=[W] * 2, grid={"x": (0, 1, 4096), "y": (0, 1, 4096)}), ValueError, r"^mixture: components × grid cells"),
    (lambda: fisst.placement_scene(count=10001), ValueError, r"^count must be an integer in \[0, 10000\]"),
    (lambda: fisst.placement_scene(sigma=(0.5, 0.1)), ValueError, r"^sigma\[1\]"),
])
def test_errors_name_the_argument(call, kind, message):
    with pytest.raises(kind, match=message):
        call()
