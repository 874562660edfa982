"""Every function's Python result equals the npm package's on the same inputs (bit for bit):
tests/js/python/fixture.mjs calls the npm package (tests/js/node_modules/fisst, installed by
`make test-js`) and prints its results; the same calls go through the Python package under
its names (snake_case functions and keywords, the options object as keyword arguments)."""

import json
import pathlib
import re
import shutil
import subprocess

import numpy as np
import pytest

import fisst

ROOT = pathlib.Path(__file__).resolve().parents[2]
FIXTURE = ROOT / "tests" / "js" / "python" / "fixture.mjs"
POSITIONAL = {"gospa": 2, "ospa": 2, "uospa": 2, "linearAssignment": 1, "multiBernoulliCardinality": 1, "multiBernoulliLeaveOneOut": 1}
MATRICES = {"F", "Q", "H", "R"}


def snake(name: str) -> str:
    if name in MATRICES:
        return name
    if name == "lambda":  # a Python keyword: the keyword argument is lambda_
        return "lambda_"
    return re.sub(r"(?<=[a-z0-9])([A-Z])", r"_\1", name).lower()


def region(v):
    """A JavaScript region in the core's (Python's) form: disc -> ball, polygon -> vertices."""
    if isinstance(v, dict) and len(v) == 1:
        (k, x), = v.items()
        if k == "disc":
            return {"ball": x}
        if k == "polygon":
            return {"polygon": {"vertices": x}}
        if k in ("union", "intersection"):
            return {k: [region(r) for r in x]}
        if k == "complement":
            return {k: region(x)}
    return v


def regions_core(v):
    """A JavaScript result in the core's (Python's) region form: every {"disc": …} a {"ball": …}."""
    if isinstance(v, dict):
        if set(v) == {"disc"}:
            return {"ball": regions_core(v["disc"])}
        return {k: regions_core(x) for k, x in v.items()}
    if isinstance(v, list):
        return [regions_core(x) for x in v]
    return v


def keys_snake(v):
    if isinstance(v, dict):
        if set(v) == {"nonFinite"}:
            return float(v["nonFinite"].replace("Infinity", "inf"))
        return {snake(k): keys_snake(x) for k, x in v.items()}
    if isinstance(v, list):
        return [keys_snake(x) for x in v]
    return v


def plain(v):
    """A Python result as plain data (lists, dicts, floats) to compare with the JSON."""
    if isinstance(v, fisst.Result):
        return {k: plain(x) for k, x in v.items()}
    if isinstance(v, np.ndarray):
        return plain(v.tolist())
    if isinstance(v, (list, tuple)):
        return [plain(x) for x in v]
    if isinstance(v, dict):
        return {k: plain(x) for k, x in v.items()}
    if isinstance(v, (bool, np.bool_)):
        return bool(v)
    if isinstance(v, (int, np.integer)):
        return int(v)
    if isinstance(v, (float, np.floating)):
        return float(v)
    return v


def same(a, b, path="result"):
    if isinstance(b, dict):
        assert isinstance(a, dict), f"{path}: {a!r} vs {b!r}"
        assert set(a) == set(b), f"{path}: keys {sorted(a)} vs {sorted(b)}"
        for k in b:
            same(a[k], b[k], f"{path}.{k}")
    elif isinstance(b, list):
        assert isinstance(a, list) and len(a) == len(b), f"{path}: {a!r} vs {b!r}"
        for i, (x, y) in enumerate(zip(a, b)):
            same(x, y, f"{path}[{i}]")
    elif isinstance(b, bool) or isinstance(a, bool):
        assert a == b, f"{path}: {a!r} vs {b!r}"
    elif isinstance(b, (int, float)):
        assert isinstance(a, (int, float)) and (a == b or (np.isnan(a) and np.isnan(b))), f"{path}: {a!r} vs {b!r}"
        assert float(a).hex() == float(b).hex(), f"{path}: {a!r} vs {b!r} (bits)"
    else:
        assert a == b, f"{path}: {a!r} vs {b!r}"


def load():
    node = shutil.which("node")
    if node is None or not (ROOT / "tests" / "js" / "node_modules" / "fisst").exists():
        pytest.skip("node and the installed npm package (make test-js) are needed", allow_module_level=True)
    out = subprocess.run([node, str(FIXTURE)], cwd=ROOT / "tests" / "js", capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


CASES = load() if FIXTURE.exists() else []


@pytest.mark.parametrize("case", CASES, ids=[f"{c['fn']}-{i}" for i, c in enumerate(CASES)])
def test_python_equals_the_npm_package(case):
    fn, args = case["fn"], case["args"]
    if fn in ("GmBernoulliFilter", "ParticleBernoulliFilter"):
        f = getattr(fisst, fn)(**keys_snake(args[0]))
        got = []
        for scan in case["scans"]:
            f.predict()
            info = f.update(measurements=scan["measurements"]) if isinstance(scan, dict) else f.update([region(r) for r in scan])
            step = {"info": plain(info), "existence": f.existence}
            step.update({"mixture": plain(f.mixture)} if fn == "GmBernoulliFilter" else {"weights": plain(f.weights)})
            got.append(step)
        same(got, keys_snake(case["result"]))
        return
    if fn == "SensorControlRun":
        run = fisst.SensorControlRun(**keys_snake(args[0]))
        got = [plain(run.step()) for _ in range(3)]
        same(got, keys_snake(case["result"]))
        return
    n = POSITIONAL.get(fn, 0)
    positional = args[:n]
    kwargs = keys_snake(args[n]) if len(args) > n else {}
    if "fov" in kwargs:
        kwargs["fov"] = region(kwargs["fov"])
    if "regions" in kwargs:
        kwargs["regions"] = [region(r) for r in kwargs["regions"]]
    got = plain(getattr(fisst, snake(fn))(*positional, **kwargs))
    if fn == "fovVarianceMap":
        # Python's variance is (ny, nx), npm's a row-major Float64Array: the same numbers
        got["variance"] = [v for row in got["variance"] for v in row]
    if fn == "mixtureDensityGrid":
        got = [v for row in got for v in row]
    same(got, regions_core(keys_snake(case["result"])))
