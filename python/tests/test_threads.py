"""Long calls release the GIL, stop on Ctrl-C, and one run shared by two threads is an error
that says so (not PyO3's "Already borrowed")."""

import _thread
import threading
import time

import numpy as np
import pytest

import fisst


def big_scene(n=3000, seed=1):
    rng = np.random.default_rng(seed)
    return rng.uniform(0, 60, (n, 2)), rng.uniform(0, 60, (n, 2))


def test_a_long_call_releases_the_gil():
    # While one thread is inside gospa_series (GIL released), the main thread keeps running
    # Python code: the counter advances during the call.
    rng = np.random.default_rng(2)
    truths = [rng.uniform(0, 40, (300, 2)) for _ in range(200)]
    estimates = [rng.uniform(0, 40, (300, 2)) for _ in range(200)]
    done = threading.Event()
    ticks_during = []

    def work():
        fisst.gospa_series(truths=truths, estimates=estimates, c=3.0)
        done.set()

    t = threading.Thread(target=work)
    t.start()
    ticks = 0
    while not done.is_set():
        ticks += 1
        time.sleep(0)
    ticks_during.append(ticks)
    t.join()
    assert ticks_during[0] > 10, ticks_during


def test_ctrl_c_stops_compare_schemes_with_keyboard_interrupt():
    # interrupt_main() raises SIGINT's KeyboardInterrupt in the main thread, which is inside
    # compare_schemes: the core checks for signals as runs finish.
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        fisst.compare_schemes(runs=400, steps=40, particles=300, future_scans=30, seed=1, schemes=["renyi"])
    assert time.monotonic() - start < 30
    timer.cancel()


def test_one_run_from_two_threads_is_a_clear_error():
    # A Rényi step of 4000 particles × 60 future scans takes 40–180 ms on two cores; the main
    # thread touches the run while the other thread is inside it. Which thread enters first is
    # up to the scheduler, so a scenario where the main thread's call came first (it then runs
    # and the other thread's call is the one refused) is tried again with a fresh run.
    for _ in range(20):
        run = fisst.SensorControlRun(
            scheme="renyi", seed=1, steps=3, particles=4000, future_scans=60
        )
        started = threading.Event()
        refused_there = []

        def step():
            started.set()
            try:
                run.step()
            except RuntimeError as e:
                refused_there.append(e)

        t = threading.Thread(target=step)
        t.start()
        started.wait()
        time.sleep(0.002)
        try:
            run.step()
        except RuntimeError as e:
            assert str(e).startswith("SensorControlRun is in use by another thread"), e
            t.join()
            assert not refused_there
            assert run.k == 1  # the refused call left the run as it was
            return
        t.join()
        # The main thread came first: then the other thread's call, if it overlapped, was the
        # refused one and left the run after the main thread's step.
        if refused_there:
            assert str(refused_there[0]).startswith("SensorControlRun is in use by another thread")
            assert run.k == 1, run.k
    raise AssertionError("in 20 tries the main thread never met the run in use")
