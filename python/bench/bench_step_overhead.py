#!/usr/bin/env python3
"""Cost of stepping from Python over stepping in C++ (a benchmark, not a test).

  1. step(): N calls of sim.step() from a Python loop against N calls of
     dda::Simulation::step() in a C++ loop (_core._time_cpp_steps), on two
     copies of the same scene, rounds alternating; the per-call overhead is
     (Python - C++) / N. The scene: two blocks that never touch (a step of a
     few microseconds, so that the overhead is not lost in the step's own
     noise).
  2. run(): one sim.run() over N steps (chunks of ~2 ms, signals checked
     between them) against the C++ loop: the overhead per step.
  3. Ctrl-C: SIGINT sent to a long run() from a timer thread; the wall time
     until KeyboardInterrupt reaches the caller.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_step_overhead.py [--n 100000] [--rounds 7]

Wall times on a shared machine vary: compare the medians of one run, or
count instructions: the difference between two step counts under callgrind,

    for k in python cpp; do for n in 2000 12000; do valgrind --tool=callgrind \
      --callgrind-out-file=/dev/null python/bench/bench_step_overhead.py --only $k --n $n; done; done

gives instructions per step ((Ir(12000) - Ir(2000)) / 10000) of each kind.
"""
import argparse
import os
import signal
import statistics
import sys
import threading
import time

import dda
from dda import _core


def scene():
    s = dda.Scene(dt=1e-4, duration=1.0)
    s.material(density=2000, young=1e9, poisson=0.25)
    s.rect(-100.0, 0.0, 1.0, 1.0, velocity=(-1.0, 0.0))
    s.rect(100.0, 0.0, 1.0, 1.0, velocity=(1.0, 0.0))
    s.contact(kn=1e7)
    return s


def python_steps(sim, n):
    step = sim.step
    t0 = time.perf_counter()
    for _ in range(n):
        step()
    return time.perf_counter() - t0


def python_run(sim, n):
    t0 = time.perf_counter()
    sim.run(until=(sim.step_count + n) * sim.dt)
    return time.perf_counter() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=100000, help="steps per measurement")
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--only", choices=["python", "cpp"],
                    help="only n steps of one kind, untimed (to count instructions under callgrind)")
    a = ap.parse_args()
    s = scene()
    if a.only:
        sim = dda.Simulation(s)
        python_steps(sim, a.n) if a.only == "python" else _core._time_cpp_steps(sim, a.n)
        return 0
    py_sim, cpp_sim = dda.Simulation(s), dda.Simulation(s)
    python_steps(py_sim, 1000), _core._time_cpp_steps(cpp_sim, 1000)  # warm up
    rows = []
    for _ in range(a.rounds):
        t_py = python_steps(py_sim, a.n)
        t_cpp = _core._time_cpp_steps(cpp_sim, a.n)
        t_run = python_run(py_sim, a.n)
        rows.append((t_py / a.n, t_cpp / a.n, t_run / a.n))
    print(f"== step(1) from Python against Simulation::step() in C++: {a.rounds} rounds of {a.n} steps, "
          f"2 separated blocks")
    print("round  python step() us  C++ step() us  overhead us/call  run() us/step  run overhead us/step")
    for i, (p, c, r) in enumerate(rows):
        print(f"{i:5d}  {p * 1e6:16.3f}  {c * 1e6:13.3f}  {(p - c) * 1e6:16.3f}  {r * 1e6:13.3f}  "
              f"{(r - c) * 1e6:20.3f}")
    over = [p - c for p, c, _ in rows]
    run_over = [r - c for _, c, r in rows]
    print(f"median overhead of step(1): {statistics.median(over) * 1e6:.3f} us per call "
          f"(min {min(over) * 1e6:.3f}, max {max(over) * 1e6:.3f}); C++ step median "
          f"{statistics.median([c for _, c, _ in rows]) * 1e6:.3f} us")
    print(f"median overhead of run(): {statistics.median(run_over) * 1e6:.3f} us per step")

    latencies = []
    for _ in range(5):
        sim = dda.Simulation(s)
        sent = []
        timer = threading.Timer(0.2, lambda: (sent.append(time.perf_counter()), os.kill(os.getpid(), signal.SIGINT)))
        timer.start()
        try:
            sim.run(until=1e6)
        except KeyboardInterrupt:
            latencies.append(time.perf_counter() - sent[0])
        finally:
            timer.cancel()
    print(f"Ctrl-C to KeyboardInterrupt in run(): median {statistics.median(latencies) * 1e3:.2f} ms, "
          f"max {max(latencies) * 1e3:.2f} ms ({len(latencies)} trials)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
