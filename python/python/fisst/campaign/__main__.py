"""``python -m fisst.campaign EXPERIMENT --runs N [--seed S] [--scheduler ADDRESS] [--out DIR]
[--figure PNG] [--serial] [--SETTING VALUE ...]``: runs a campaign (see ``fisst.campaign.run``),
prints its summary at the last step and writes the paper's figure (``DIR/figure.png`` with
``--out``). Settings are the experiment's, as ``--future-scans 40`` or ``--schemes renyi,pent``.
"""

from __future__ import annotations

import argparse
import json
import sys
from typing import Any

from . import EXPERIMENTS, run


def _value(text: str, default: Any) -> Any:
    """A setting's value from the command line, typed like its default."""
    if isinstance(default, list):
        items = [t for t in text.split(",") if t]
        return [type(default[0])(t) if default else t for t in items]
    if isinstance(default, bool):
        return text.lower() in ("1", "true", "yes")
    if isinstance(default, int):
        return int(text)
    if isinstance(default, float):
        return float(text)
    if isinstance(default, str):
        return text
    return json.loads(text)


def _shown(value: Any) -> str:
    """A default as it is written on the command line."""
    if isinstance(value, list):
        return ",".join(_shown(v) for v in value)
    return f"{value:g}" if isinstance(value, float) else str(value)


def main(argv: list[str] | None = None) -> int:
    settings_help = "\n".join(
        f"  {name} ({e.title}):\n    "
        + " ".join(f"--{k.replace('_', '-')} {_shown(v)}" for k, v in e.defaults.items())
        for name, e in EXPERIMENTS.items()
    )
    parser = argparse.ArgumentParser(
        prog="python -m fisst.campaign", description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="settings and their defaults (lists comma-separated):\n" + settings_help,
    )
    parser.add_argument("experiment", choices=sorted(EXPERIMENTS))
    parser.add_argument("--runs", type=int, required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--scheduler", help="a Dask scheduler address, tcp://host:8786 (default: a local cluster)")
    parser.add_argument("--serial", action="store_true", help="no Dask: run the tasks one after another here")
    parser.add_argument("--out", help="a directory keeping every finished run (resume by running again)")
    parser.add_argument("--figure", help="where to write the figure (default DIR/figure.png with --out)")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    args, rest = parser.parse_known_args(argv)
    defaults = EXPERIMENTS[args.experiment].defaults
    settings: dict[str, Any] = {}
    while rest:
        flag = rest.pop(0)
        name = flag.lstrip("-").replace("-", "_")
        if not flag.startswith("--") or name not in defaults or not rest:
            parser.error(f"unknown setting {flag!r} for {args.experiment} (settings: "
                         + ", ".join("--" + k.replace("_", "-") for k in defaults) + ")")
        settings[name] = _value(rest.pop(0), defaults[name])
    client: Any = "serial" if args.serial else args.scheduler
    c = run(args.experiment, runs=args.runs, seed=args.seed, client=client, out=args.out,
            progress=not args.quiet, **settings)
    summary = c.summary()
    last = summary[summary["step"] == summary["step"].max()] if "step" in summary else summary
    print(c)
    print(last.to_string(index=False))
    figure = args.figure or (f"{args.out}/figure.png" if args.out else None)
    if figure:
        import matplotlib

        matplotlib.use("Agg")
        c.plot().savefig(figure, dpi=110)
        print(f"figure: {figure}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
