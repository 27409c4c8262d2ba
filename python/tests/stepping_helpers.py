"""Helpers of the tests of stepping in another thread and Ctrl-C, shared by
both models' tests."""
import os
import signal
import threading
import time

import pytest


def interrupted_run(sim, until, after=0.3):
    """sim.run(until) with SIGINT sent `after` s into it: asserts that it raised
    KeyboardInterrupt; returns the wall time from the signal to the exception, s."""
    sent = []

    def interrupt():
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(after, interrupt)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            sim.run(until=until)
        caught = time.perf_counter()
    finally:
        timer.cancel()
    latency = caught - sent[0]
    print(f"Ctrl-C to KeyboardInterrupt: {latency * 1e3:.1f} ms after {sim.step_count} steps")
    return latency


def refused_while_stepping(sim, calls, enough=3, tries=4000):
    """Runs sim in another thread and calls each of `calls` (name -> f(sim))
    on it meanwhile, until each was refused `enough` times with the
    RuntimeError of a simulation stepping in another thread (or `tries`
    rounds); stops the run. Returns name -> times refused."""
    started, stop = threading.Event(), threading.Event()

    def callback(s):
        started.set()
        if stop.is_set():
            raise StopIteration

    t = threading.Thread(target=lambda: pytest.raises(StopIteration, sim.run, until=1e3, every=100,
                                                      callback=callback))
    t.start()
    started.wait(10)
    refused = dict.fromkeys(calls, 0)
    for _ in range(tries):
        for name, call in calls.items():
            try:
                call(sim)
            except RuntimeError as e:
                assert "stepping in another thread" in str(e)
                refused[name] += 1
        if min(refused.values()) >= enough:
            break
        time.sleep(0.0002)
    stop.set()
    t.join(10)
    assert not t.is_alive()
    return refused
