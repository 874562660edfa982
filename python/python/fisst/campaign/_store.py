"""A campaign's directory ``out``: ``campaign.json`` (the experiment, the master seed, the
settings and the fisst version) and ``runs/run-NNNNNNN.parquet``, one Parquet part per finished
run (one row per step and variant), each written to a temporary name and then renamed, so that
a part is either whole or absent whatever stops the campaign."""

from __future__ import annotations

import io
import json
import os
import re
from pathlib import Path
from typing import Any, Sequence

import pandas as pd

FORMAT = 1
RECORD = "campaign.json"
RUNS = "runs"
PART = re.compile(r"^run-(\d{7,})\.parquet$")


def _canonical(value: Any) -> Any:
    """Settings as JSON keeps them (tuples become lists), for comparing with a record."""
    return json.loads(json.dumps(value))


def open_out(out: Path, record: dict[str, Any]) -> set[int]:
    """Creates ``out`` (or checks that the campaign recorded there is this one) and returns
    the runs already finished there.

    Raises ``ValueError`` naming the first setting (or ``experiment``, ``seed``,
    ``fisst_version``) that differs from the record: a campaign never mixes runs of two
    set-ups."""
    record = _canonical(record)
    path = out / RECORD
    if path.exists():
        try:
            old = json.loads(path.read_text())
        except (OSError, ValueError) as e:
            raise ValueError(f"out: {path} is not a campaign record ({e})") from None
        for key in ("experiment", "seed", "fisst_version", "format"):
            if old.get(key) != record[key]:
                raise ValueError(
                    f"{key}: {out} holds a campaign with {key}={old.get(key)!r}, this one has "
                    f"{key}={record[key]!r} (use another out, or the recorded {key})"
                )
        old_settings, settings = old.get("settings", {}), record["settings"]
        for key in sorted(set(old_settings) | set(settings)):
            if old_settings.get(key) != settings.get(key):
                raise ValueError(
                    f"{key}: {out} holds a campaign with {key}={old_settings.get(key)!r}, this "
                    f"one has {key}={settings.get(key)!r} (use another out, or the recorded "
                    "settings)"
                )
    else:
        out.mkdir(parents=True, exist_ok=True)
        write_atomically(path, (json.dumps(record, indent=2, sort_keys=True) + "\n").encode())
    (out / RUNS).mkdir(exist_ok=True)
    return finished_runs(out)


def finished_runs(out: Path) -> set[int]:
    """The run indices with a part file in ``out``."""
    done = set()
    for entry in os.scandir(out / RUNS):
        m = PART.match(entry.name)
        if m:
            done.add(int(m.group(1)))
    return done


def part_path(out: Path, run: int) -> Path:
    return out / RUNS / f"run-{run:07d}.parquet"


def write_atomically(path: Path, data: bytes) -> None:
    """Writes ``data`` to ``path`` through a temporary file in the same directory and a
    rename (atomic on POSIX), so that a reader sees the whole file or none."""
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    with open(tmp, "wb") as f:
        f.write(data)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def write_part(out: Path, run: int, frame: pd.DataFrame) -> None:
    """Writes the rows of run ``run`` as its part file, atomically."""
    buffer = io.BytesIO()
    frame.to_parquet(buffer, index=False)
    write_atomically(part_path(out, run), buffer.getvalue())


def read_parts(out: Path, runs: Sequence[int]) -> list[pd.DataFrame]:
    """The part files of ``runs`` in ``out``, in run order."""
    return [pd.read_parquet(part_path(out, r)) for r in runs]
