"""The example scripts (examples/python/, one headline figure of each paper through the Python
package) run with the Agg backend and each writes a PNG."""

import importlib.util
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCRIPTS = sorted((ROOT / "examples" / "python").glob("fig*.py"))

pytest.importorskip("matplotlib")


@pytest.mark.parametrize("script", SCRIPTS, ids=[s.stem for s in SCRIPTS])
def test_example_writes_its_figure(script, tmp_path):
    spec = importlib.util.spec_from_file_location(script.stem, script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    out = tmp_path / f"{script.stem}.png"
    kwargs = {"runs": 2, "steps": 10, "particles": 100, "future_scans": 10} if "004" in script.stem else {}
    assert module.main(str(out), **kwargs) == str(out)
    data = out.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 20_000


def test_every_paper_has_an_example():
    papers = {s.stem.split("_")[1] for s in SCRIPTS}
    assert {"000", "001", "002", "003", "004"} <= papers
