"""Runs a side-by-side script inside benches/.venv when its imports are missing.

`ensure(["numpy", "scipy"], ["numpy", "scipy"])` returns if the modules import; otherwise it
creates benches/.venv (git-ignored) if needed, pip-installs the requirements there, and
re-executes the calling script with the venv's Python.
"""
import importlib, os, subprocess, sys, venv

HERE = os.path.dirname(os.path.abspath(__file__))
VENV = os.path.join(HERE, ".venv")


def ensure(modules, requirements):
    try:
        for m in modules:
            importlib.import_module(m)
        return
    except ImportError:
        pass
    python = os.path.join(VENV, "bin", "python")
    if os.path.realpath(sys.executable) == os.path.realpath(python):
        subprocess.run([python, "-m", "pip", "install", "--quiet", *requirements], check=True)
    else:
        if not os.path.exists(python):
            venv.create(VENV, with_pip=True)
        subprocess.run([python, "-m", "pip", "install", "--quiet", *requirements], check=True)
    os.execv(python, [python, *sys.argv])
