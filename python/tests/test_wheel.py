"""The wheel in dist/ (what `make test-python` or `make wheel` built) installs into a fresh
virtual environment and imports there: one abi3 wheel for Python >= 3.10."""

import pathlib
import subprocess
import sys
import venv

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_the_wheel_installs_into_a_fresh_venv_and_imports(tmp_path):
    wheels = sorted((ROOT / "dist").glob("fisst-*.whl"))
    if not wheels:
        pytest.skip("no wheel in dist/ (make wheel or make test-python builds one)")
    wheel = wheels[-1]
    assert "abi3" in wheel.name and "x86_64" in wheel.name, wheel.name
    env = tmp_path / "venv"
    venv.create(env, with_pip=True)
    python = env / "bin" / "python"
    subprocess.run([python, "-m", "pip", "install", "--quiet", "--disable-pip-version-check", str(wheel)], check=True)
    code = (
        "import fisst, numpy; g = fisst.gospa([[0, 0], [10, 0]], [[0, 1]], c=2); "
        "assert g.distance == 3 ** 0.5 and g.assignment.tolist() == [[0, 0]]; "
        "import fisst._fisst as m; print(m.__file__, fisst.__version__)"
    )
    out = subprocess.run([python, "-c", code], check=True, capture_output=True, text=True, cwd=tmp_path)
    assert str(env) in out.stdout, out.stdout  # imported from the fresh venv, not the checkout
    assert sys.version_info >= (3, 10)
