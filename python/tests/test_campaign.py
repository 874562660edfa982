"""fisst.campaign (issue 28): the same table serially, on a local cluster of threads, of
processes and on a scheduler with two worker programs on loopback; a killed worker costs a
retry; an interrupted campaign resumes to the uninterrupted table; bad settings name the
setting within a bounded time; the summary equals compare_schemes; the command line."""

import json
import os
import signal
import socket
import subprocess
import sys
import time

import numpy as np
import pandas as pd
import pytest

import fisst
import fisst.campaign as fc

distributed = pytest.importorskip("distributed")
pytest.importorskip("pyarrow")

SMALL = dict(steps=4, particles=60, future_scans=6)


def serial(runs=4, seed=7, **kw):
    return fc.run("control", runs=runs, seed=seed, client="serial", progress=False, **{**SMALL, **kw})


def start_cluster(tmp_path, workers=2):
    """`dask scheduler` and `dask worker` programs on loopback (no nanny: a killed worker
    stays dead). Returns the scheduler address and the processes."""
    file = tmp_path / "scheduler.json"
    env = {**os.environ, "DASK_DISTRIBUTED__WORKER__DAEMON": "False"}
    py = sys.executable
    procs = [subprocess.Popen([py, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1",
                               "--port", "0", "--no-dashboard", "--scheduler-file", str(file)],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)]
    deadline = time.monotonic() + 60
    while not file.exists() and time.monotonic() < deadline:
        time.sleep(0.1)
    address = json.loads(file.read_text())["address"]
    for _ in range(workers):
        procs.append(subprocess.Popen([py, "-m", "distributed.cli.dask_worker", address, "--nthreads", "1",
                                       "--no-nanny", "--no-dashboard", "--host", "127.0.0.1"],
                                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env))
    with distributed.Client(address, timeout="30s") as c:
        c.wait_for_workers(workers, timeout=60)
    return address, procs


def stop(procs):
    for p in reversed(procs):
        if p.poll() is None:
            p.send_signal(signal.SIGTERM)
    for p in procs:
        try:
            p.wait(timeout=20)
        except subprocess.TimeoutExpired:
            p.kill()


def test_the_same_table_serially_on_threads_on_processes_and_on_a_scheduler(tmp_path):
    reference = serial()
    assert list(reference.table["run"].unique()) == [0, 1, 2, 3]
    # a local cluster of threads (the default)
    threads = fc.run("control", runs=4, seed=7, progress=False, **SMALL)
    pd.testing.assert_frame_equal(threads.table, reference.table, check_exact=True)
    # a local cluster of processes
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, scheduler_kwargs={"dashboard_address": ":0"}) as cluster, distributed.Client(cluster) as client:
        processes = fc.run("control", runs=4, seed=7, client=client, progress=False, **SMALL)
    pd.testing.assert_frame_equal(processes.table, reference.table, check_exact=True)
    # `dask scheduler` and two `dask worker` programs on loopback, by address
    address, procs = start_cluster(tmp_path)
    try:
        remote = fc.run("control", runs=4, seed=7, client=address, progress=False, **SMALL)
    finally:
        stop(procs)
    pd.testing.assert_frame_equal(remote.table, reference.table, check_exact=True)
    # each row's numbers are bit-identical, not only close
    for t in (threads, processes, remote):
        for part in ("distance", "localisation", "cardinality"):
            assert t.table[part].to_numpy().tobytes() == reference.table[part].to_numpy().tobytes()


def test_a_killed_worker_costs_a_retry_not_the_campaign(tmp_path):
    settings = dict(steps=6, particles=150, future_scans=20)
    reference = fc.run("control", runs=6, seed=3, client="serial", progress=False, **settings)
    address, procs = start_cluster(tmp_path)
    killed = []

    def kill_one(done, total):
        if done == 1 and not killed:
            procs[1].kill()  # the first worker program, mid-campaign
            killed.append(done)

    try:
        c = fc.run("control", runs=6, seed=3, client=address, progress=kill_one,
                   out=tmp_path / "study", **settings)
    finally:
        stop(procs)
    assert killed and procs[1].returncode is not None
    pd.testing.assert_frame_equal(c.table, reference.table, check_exact=True)


class Stop(Exception):
    pass


def test_an_interrupted_campaign_resumes_to_the_uninterrupted_table(tmp_path):
    out = tmp_path / "study"
    whole = serial(runs=5)

    def stop_after_two(done, total):
        if done == 2:
            raise Stop

    with pytest.raises(Stop):
        fc.run("control", runs=5, seed=7, client="serial", out=out, progress=stop_after_two, **SMALL)
    assert sorted(os.listdir(out / "runs")) == ["run-0000000.parquet", "run-0000001.parquet"]
    resumed = fc.run("control", runs=5, seed=7, client="serial", out=out, progress=False, **SMALL)
    assert resumed.computed == 3
    pd.testing.assert_frame_equal(resumed.table, whole.table, check_exact=True)
    # on a local cluster too, and extended to more runs: only the new runs are computed
    more = fc.run("control", runs=7, seed=7, out=out, progress=False, **SMALL)
    assert more.computed == 2
    pd.testing.assert_frame_equal(more.table, serial(runs=7).table, check_exact=True)
    # run again: nothing left to compute, the same table
    again = fc.run("control", runs=7, seed=7, out=out, progress=False, **SMALL)
    assert again.computed == 0
    pd.testing.assert_frame_equal(again.table, more.table, check_exact=True)
    # no temporary file is left behind
    assert not [n for n in os.listdir(out / "runs") if n.startswith(".")]


def test_a_different_set_up_in_the_same_out_is_an_error(tmp_path):
    out = tmp_path / "study"
    fc.run("control", runs=1, seed=7, client="serial", out=out, progress=False, **SMALL)
    with pytest.raises(ValueError, match=r"^particles: .* particles=60, this one has particles=61"):
        fc.run("control", runs=2, seed=7, client="serial", out=out, progress=False, **{**SMALL, "particles": 61})
    with pytest.raises(ValueError, match=r"^seed: .* seed=7, this one has seed=8"):
        fc.run("control", runs=2, seed=8, client="serial", out=out, progress=False, **SMALL)
    record = json.loads((out / "campaign.json").read_text())
    record["fisst_version"] = "0.0.0"
    (out / "campaign.json").write_text(json.dumps(record))
    with pytest.raises(ValueError, match=r"^fisst_version: .*'0\.0\.0'"):
        fc.run("control", runs=2, seed=7, client="serial", out=out, progress=False, **SMALL)


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        (dict(experiment="contrl"), ValueError, r"^experiment must be one of 'control', 'airport', 'bounds', got 'contrl' \(did you mean 'control'\?\)"),
        (dict(experiment=3), TypeError, r"^experiment must be a str"),
        (dict(runs=0), ValueError, r"^runs must be in \[1, 1000000\], got 0"),
        (dict(runs=-5), ValueError, r"^runs must be in"),
        (dict(runs=2.5), TypeError, r"^runs must be an int"),
        (dict(seed=-1), ValueError, r"^seed must be in"),
        (dict(schemes=["renyi", "foo"]), TypeError, r"^schemes\[1\]: unknown variant `foo`, expected one of `renyi`"),
        (dict(particles=0), ValueError, r"^particles"),
        (dict(particles=20_000, future_scans=2_000), ValueError, r"^future_scans"),
        (dict(partcles=10), TypeError, r"unexpected setting 'partcles' for 'control' \(did you mean 'particles'\?\)"),
        (dict(client=3), TypeError, r"^client must be"),
        (dict(progress="yes"), TypeError, r"^progress must be"),
    ],
)
def test_bad_settings_name_the_setting(kwargs, error, message):
    args = {"experiment": "control", "runs": 2, "seed": 1, "client": "serial", "progress": False, **SMALL, **kwargs}
    with pytest.raises(error, match=message):
        fc.run(args.pop("experiment"), **args)


def test_a_scheduler_that_does_not_answer_is_an_error_naming_client_in_bounded_time(monkeypatch):
    monkeypatch.setattr(fc, "CONNECT_TIMEOUT", 2.0)
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    start = time.monotonic()
    with pytest.raises(ConnectionError, match=r"^client: no Dask scheduler answered at 'tcp://127\.0\.0\.1:\d+' within 2 s"):
        fc.run("control", runs=1, seed=1, client=f"tcp://127.0.0.1:{port}", progress=False, **SMALL)
    assert time.monotonic() - start < 30


def test_the_summary_equals_compare_schemes_and_the_seeds_are_its_run_seeds():
    c = serial(runs=5, seed=11)
    ref = fisst.compare_schemes(runs=5, seed=11, **SMALL)
    assert fc.run_seeds(11, 5) == [int(s) for s in ref.run_seeds]
    assert fc.run_seeds(11, 3) == fc.run_seeds(11, 5)[:3]
    s = c.summary()
    assert list(s.columns) == ["scheme", "step", "quantity", "mean", "standard_error", "runs"]
    for scheme in ref.schemes:
        for q in ("distance", "localisation", "cardinality"):
            rows = s[(s["scheme"] == scheme.scheme) & (s["quantity"] == q)]
            assert list(rows["step"]) == [1, 2, 3, 4] and set(rows["runs"]) == {5}
            want = getattr(scheme, q)
            np.testing.assert_allclose(rows["mean"].to_numpy(), want.mean, rtol=1e-12, atol=0)
            np.testing.assert_allclose(rows["standard_error"].to_numpy(), want.standard_error, rtol=1e-12, atol=1e-300)
    # and any run replays alone: run r is a SensorControlRun with seed run_seeds[r]
    r = 3
    run = fisst.SensorControlRun(scheme="pent", seed=fc.run_seeds(11, 5)[r], steps=4, particles=60, future_scans=6)
    replay = [run.step().ospa.distance for _ in range(4)]
    table = c.table[(c.table["run"] == r) & (c.table["scheme"] == "pent")]
    assert table["distance"].tolist() == replay


def test_the_plot_is_fig3_and_the_command_line_writes_it(tmp_path):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    fig = serial(runs=3).plot()
    assert len(fig.axes) == 3 and len(fig.axes[0].lines) == 4
    out = tmp_path / "study"
    done = subprocess.run(
        [sys.executable, "-m", "fisst.campaign", "control", "--runs", "2", "--seed", "5", "--serial", "--quiet",
         "--out", str(out), "--steps", "3", "--particles", "40", "--future-scans", "4", "--schemes", "renyi,random"],
        capture_output=True, text=True, timeout=300,
    )
    assert done.returncode == 0, done.stderr
    assert "Campaign('control', runs=2, seed=5" in done.stdout and "renyi" in done.stdout
    assert (out / "figure.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert json.loads((out / "campaign.json").read_text())["settings"]["schemes"] == ["renyi", "random"]
    bad = subprocess.run([sys.executable, "-m", "fisst.campaign", "control", "--runs", "2", "--partcles", "3"],
                         capture_output=True, text=True, timeout=120)
    assert bad.returncode == 2 and "unknown setting '--partcles'" in bad.stderr


def without_timing(c):
    return c.table.drop(columns=list(fc.EXPERIMENTS[c.experiment].timing))


def test_airport_runs_both_filters_the_same_on_threads_and_serially():
    small = dict(steps=20, particles=400)
    a = fc.run("airport", runs=4, seed=5, client="serial", progress=False, **small)
    b = fc.run("airport", runs=4, seed=5, progress=False, **small)
    pd.testing.assert_frame_equal(without_timing(a), without_timing(b), check_exact=True)
    t = a.table
    assert list(t.columns) == ["run", "run_seed", "filter", "step", "existence", "position_error", "position_rss",
                               "nees", "covered", "seconds"]
    assert len(t) == 4 * 2 * 20 and set(t["filter"]) == {"gm", "particle"}
    assert t["existence"].between(0, 1).all() and (t["position_rss"] > 0).all() and (t["seconds"] >= 0).all()
    # Fig. 7a: the truth inside the 3σ ellipse nearly always (the paper test holds ≥ 0.95 over
    # 24 runs of 60 steps)
    assert t[t["filter"] == "gm"]["covered"].mean() >= 0.85
    # the GM filter does not depend on the particle filter's settings
    c = fc.run("airport", runs=4, seed=5, client="serial", progress=False, steps=20, particles=300, mcmc_moves=0)
    gm = lambda x: without_timing(x)[x.table["filter"] == "gm"].reset_index(drop=True)  # noqa: E731
    pd.testing.assert_frame_equal(gm(a), gm(c), check_exact=True)
    assert not without_timing(a).equals(without_timing(c))
    s = a.summary()
    assert set(s["quantity"]) == {"existence", "position_error", "position_rss", "covered", "seconds"}
    assert len(a.plot().axes) == 4


def test_bounds_monte_carlo_attains_the_bound_31():
    """Theorem 1 of paper 002: MAP detection with the posterior mean (and the cheaper rule on
    Z = ∅) attains the bound (31): over 20 runs × 2,000 draws the mean squared error is within
    4.5 pooled standard errors of it at every grid point."""
    b = fc.run("bounds", runs=20, seed=3, progress=False)
    serial_b = fc.run("bounds", runs=20, seed=3, client="serial", progress=False)
    pd.testing.assert_frame_equal(b.table, serial_b.table, check_exact=True)
    g = b.table.groupby(["detection_probability", "existence"])
    mse, bound = g["mse"].mean(), g["bound"].first()
    pooled = np.sqrt(g["mse_se"].apply(lambda s: (s**2).sum())) / g.size()
    z = ((mse - bound) / pooled).to_numpy()
    assert len(z) == 36 and np.all(np.abs(z) < 4.5), z
    s = b.summary()
    assert set(s["quantity"]) == {"mse", "bound", "map_bound"}
    assert (s[s["quantity"] == "bound"]["standard_error"] == 0).all()
    assert len(b.plot().axes) == 1


@pytest.mark.parametrize(
    "experiment, settings, error, message",
    [
        ("airport", dict(steps=0), ValueError, r"^steps"),
        ("airport", dict(particles=0), ValueError, r"^particles"),
        ("airport", dict(step=3), TypeError, r"unexpected setting 'step' for 'airport' \(did you mean 'steps'\?\)"),
        ("bounds", dict(posterior_variance=30.0), ValueError, r"^posterior_variance"),
        ("bounds", dict(existence=[]), ValueError, r"^existence"),
        ("bounds", dict(existence=[0.5, 1.5]), ValueError, r"^existence"),
        ("bounds", dict(samples=1), ValueError, r"^samples"),
        ("bounds", dict(empty_rule="sometimes"), TypeError, r"^empty_rule: unknown variant"),
    ],
)
def test_bad_airport_and_bounds_settings_name_the_setting(experiment, settings, error, message):
    with pytest.raises(error, match=message):
        fc.run(experiment, runs=1, seed=1, client="serial", progress=False, **settings)


def test_an_airport_run_is_the_public_filters_on_airport_scenario():
    """A campaign's airport run is what a user gets from the public API: the scenario of the run
    seed, GmBernoulliFilter and ParticleBernoulliFilter made from its one config (the particle
    keys ignored by the GM filter, as in the npm package), updated with each step's reports."""
    seed = fc.run_seeds(9, 1)[0]
    steps, particles = 12, 300
    sc = fisst.airport_scenario(seed=seed, steps=steps)
    config = {**dict(sc.config), "particles": particles}
    gm, pf = fisst.GmBernoulliFilter(**config), fisst.ParticleBernoulliFilter(**config)
    rows = {"gm": [], "particle": []}
    for k in range(steps):
        reports = [{"ball": {"center": sc.anchors[a].position, "radius": sc.anchors[a].radius}} for a in sc.reports[k]]
        for name, f in (("gm", gm), ("particle", pf)):
            f.predict()
            f.update(reports)
            e = f.estimate()
            rows[name].append((e.existence, float(np.hypot(*(sc.truth[k].state[:2] - e.mean[:2])))))
    c = fc.run("airport", runs=1, seed=9, client="serial", progress=False, steps=steps, particles=particles)
    for name in ("gm", "particle"):
        t = c.table[c.table["filter"] == name]
        assert t["existence"].tolist() == [r[0] for r in rows[name]]
        np.testing.assert_allclose(t["position_error"], [r[1] for r in rows[name]], rtol=1e-12)
    with pytest.raises(TypeError, match=r"particles"):
        fisst.GmBernoulliFilter(**{**dict(sc.config), "particles": "many"})
