"""fisst.campaign on Dask against the native comparison (issue 28's benchmarks), ratios from one
run: Fig. 3 of paper 004 (four schemes) at `--runs` runs:

  native   `control_comparison` (benches/src/bin, compare_schemes on all cores with rayon)
  1 worker a local Dask cluster of one thread
  2 threads the default local cluster (threads on both cores)
  2 procs  `dask scheduler` + two `dask worker` programs (one thread each) on loopback

    .venv/bin/python benches/campaign_dask.py [--runs 40] [--steps 40] [--particles 750]
                                             [--future-scans 200] [--seed 1]

Goals: two workers ≥ 1.8× one; the campaign's time within 5% of the native program's; the
cluster path no slower than the local one. The tables of the three campaigns are checked equal
bit for bit, and their summary against the native program's last-step figures.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import distributed
import pandas as pd

import fisst
import fisst.campaign as fc

ROOT = Path(__file__).resolve().parents[1]


def native(args) -> tuple[float, str]:
    env = {**os.environ, "CARGO_TARGET_DIR": os.environ.get("CARGO_TARGET_DIR", str(ROOT / "target"))}
    subprocess.run(["cargo", "build", "--release", "--quiet", "--bin", "control_comparison"], cwd=ROOT / "benches",
                   env=env, check=True)
    exe = Path(env["CARGO_TARGET_DIR"]) / "release" / "control_comparison"
    out = subprocess.run([str(exe), str(args.runs), str(args.steps), str(args.particles), str(args.future_scans),
                          str(args.seed)], capture_output=True, text=True, check=True).stdout
    return max(float(re.search(r"time=([0-9.]+) s", out).group(1)), 0.05), out


def timed(client, args) -> tuple[float, pd.DataFrame]:
    t = time.perf_counter()
    c = fc.run("control", runs=args.runs, seed=args.seed, client=client, progress=False, steps=args.steps,
               particles=args.particles, future_scans=args.future_scans)
    return time.perf_counter() - t, c


def scheduler_with_two_workers(tmp: Path):
    file = tmp / "scheduler.json"
    py = sys.executable
    procs = [subprocess.Popen([py, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", "0",
                               "--no-dashboard", "--scheduler-file", str(file)],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    while not file.exists():
        time.sleep(0.1)
    address = json.loads(file.read_text())["address"]
    for _ in range(2):
        procs.append(subprocess.Popen([py, "-m", "distributed.cli.dask_worker", address, "--nthreads", "1",
                                       "--no-nanny", "--no-dashboard", "--host", "127.0.0.1"],
                                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
    with distributed.Client(address) as c:
        c.wait_for_workers(2, timeout=60)
    return address, procs


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("--runs", type=int, default=40)
    p.add_argument("--steps", type=int, default=40)
    p.add_argument("--particles", type=int, default=750)
    p.add_argument("--future-scans", type=int, default=200)
    p.add_argument("--seed", type=int, default=1)
    args = p.parse_args()
    print(f"# Fig. 3 of paper 004: {args.runs} runs x 4 schemes, K = {args.steps}, N = {args.particles}, "
          f"M = {args.future_scans}, seed {args.seed}; fisst {fisst.__version__}, {os.cpu_count()} cores")
    t_native, text = native(args)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address=None, scheduler_kwargs={"dashboard_address": ":0"}) as cluster, distributed.Client(cluster) as client:
        t_one, one = timed(client, args)
    t_two, two = timed(None, args)
    with tempfile.TemporaryDirectory() as tmp:
        address, procs = scheduler_with_two_workers(Path(tmp))
        try:
            t_procs, procs_c = timed(address, args)
        finally:
            for proc in reversed(procs):
                proc.send_signal(signal.SIGTERM)
                proc.wait(timeout=30)
    for other in (two, procs_c):
        pd.testing.assert_frame_equal(other.table, one.table, check_exact=True)
    rows = [("native control_comparison (rayon, 2 threads)", t_native),
            ("campaign, 1 worker thread", t_one),
            ("campaign, local cluster of 2 threads", t_two),
            ("campaign, dask scheduler + 2 worker programs", t_procs)]
    print(f"{'':48s} {'seconds':>9s}")
    for name, t in rows:
        print(f"{name:48s} {t:9.1f}")
    print(f"two threads / one worker: {t_one / t_two:.2f}x (goal >= 1.8x)")
    print(f"campaign overhead vs native: {100 * (t_two / t_native - 1):+.1f}% (goal < 5%)")
    print(f"scheduler + 2 worker programs vs local threads: {t_procs / t_two:.2f}x (goal <= 1)")
    # the native program's last-step means against the campaign's summary
    s = one.summary()
    k = s["step"].max()
    for line in text.splitlines():
        m = re.match(r"^(Renyi|Fisher|Pent|Random)\s+([0-9.]+) ±", line)
        if m:
            mine = s[(s["scheme"] == m.group(1).lower()) & (s["step"] == k) & (s["quantity"] == "distance")]["mean"].item()
            assert abs(mine - float(m.group(2))) < 0.006, (m.group(1), mine, m.group(2))
    print("tables bit-identical across the three campaigns; last-step OSPA equal to the native program's")


if __name__ == "__main__":
    main()
