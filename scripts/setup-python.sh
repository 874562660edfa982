#!/usr/bin/env bash
# The Python virtual environment of the project, `.venv` (git-ignored), with what building and
# testing the Python package needs, from PyPI; skips whatever is already there.
#   scripts/setup-python.sh           maturin, numpy, pytest, hypothesis, pandas, mypy, stonesoup
#                                     1.9.1 (the interoperability tests), matplotlib, and
#                                     dask[distributed] and pyarrow (fisst.campaign)
set -euo pipefail
cd "$(dirname "$0")/.."

say() { printf '[setup-python] %s\n' "$*"; }

python=${PYTHON:-python3}
command -v "$python" >/dev/null || { echo "[setup-python] $python (>= 3.10) is required" >&2; exit 1; }
if [ ! -x .venv/bin/python ]; then
  say "$python -m venv .venv"
  "$python" -m venv .venv
fi
need=()
for spec in "maturin>=1.8,<2:maturin" "numpy>=1.23:numpy" "pytest>=8:pytest" "hypothesis>=6:hypothesis" \
            "pandas>=2:pandas" "mypy>=1.10:mypy" "stonesoup==1.9.1:stonesoup" "matplotlib>=3.7:matplotlib" \
            "dask[distributed]>=2024.1:distributed" "pyarrow>=14:pyarrow"; do
  module=${spec##*:}
  .venv/bin/python -c "import $module" 2>/dev/null || need+=("${spec%:*}")
done
if [ ${#need[@]} -gt 0 ]; then
  say "pip install ${need[*]}"
  .venv/bin/python -m pip install --quiet --disable-pip-version-check "${need[@]}"
fi
say "ok ($(.venv/bin/python --version))"
