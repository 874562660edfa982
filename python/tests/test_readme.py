"""The README's Python quick start runs and prints what its comments say."""

import contextlib
import io
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_readme_python_snippet_prints_what_it_says():
    readme = (ROOT / "README.md").read_text()
    m = re.search(r"<!-- readme-test: python -->\s*```python\n(.*?)```", readme, re.S)
    assert m, "the README has a Python snippet marked readme-test"
    code = m.group(1)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(code, "README.md", "exec"), {})
    printed = out.getvalue().splitlines()
    # each print is followed by its expected output, as a comment (the same line or the next)
    expected = []
    lines = code.splitlines()
    for i, line in enumerate(lines):
        if line.strip().startswith("print(") or line.strip().startswith("print ("):
            same_line = re.search(r"\)\s*#\s*(.*)$", line)
            if same_line:
                expected.append(same_line.group(1).strip())
            else:
                expected.append(lines[i + 1].strip().lstrip("#").strip())
    assert [p.strip() for p in printed] == expected
