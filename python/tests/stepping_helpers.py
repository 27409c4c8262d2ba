"""Helpers of both models' tests: `dda run`'s loop from Python, Ctrl-C,
calls from another thread while a simulation steps."""
import os
import signal
import threading
import time

import pytest

import dda


def python_run_csv(scene_path, threads=1):
    """timeseries.csv and snapshots.csv as `dda run` writes them, from a
    Python run: its loop (lib/io/src/run.cpp) with run(). Returns them and
    the simulation."""
    scene = dda.Scene.from_file(scene_path)
    f = scene.scene_file
    sim = dda.Simulation(scene, threads=threads)
    tracked = f.tracked_blocks
    ts = [",".join(dda.timeseries_header(tracked, rotation=f.model == "penalty"))]
    snap = ["time,step,block,vertex,x,y"]
    fmt = dda.format_number
    times, next_snap = f.snapshot_times, [0]

    def row(s):
        ts.append(",".join(str(v) if isinstance(v, int) else fmt(v) for v in s.timeseries_row(tracked)))

    def snapshots(s):
        while next_snap[0] < len(times) and times[next_snap[0]] <= s.time + 0.5 * s.dt:
            for b in range(s.outline_count):
                for k, (x, y) in enumerate(s.outline(b)):
                    snap.append(f"{fmt(s.time)},{s.step_count},{b},{k},{fmt(x)},{fmt(y)}")
            next_snap[0] += 1

    row(sim)
    snapshots(sim)

    def each_step(s):
        if s.step_count % f.output_every == 0 or not (s.time + 0.5 * s.dt < f.duration):
            row(s)
        snapshots(s)

    sim.run(every=1, callback=each_step)
    return "\n".join(ts) + "\n", "\n".join(snap) + "\n", sim


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
