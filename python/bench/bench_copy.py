#!/usr/bin/env python3
"""Size and cost of copying and pickling a simulation mid-run (a benchmark, not a test).

For a scene run to a time, prints the state's bytes (Simulation::save_state),
the pickle's bytes (the scene document + the state + the threads), and the
wall time of copy.copy, pickle.dumps and pickle.loads against one step and
against building the simulation from its scene. A copy builds a simulation
of the same scene (settle included, if the scene asks for one) and restores
the state into it.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_copy.py [scene.json] [--until 0.05]
"""
import argparse
import copy
import pickle
import statistics
import sys
import time

import dda


def median_seconds(f, rounds):
    times = []
    for _ in range(rounds):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene", nargs="?", default="repro/scenes/collapse_case1.json")
    ap.add_argument("--until", type=float, default=0.05, help="s of simulated time before the copies")
    ap.add_argument("--rounds", type=int, default=5)
    a = ap.parse_args()
    scene = dda.load_scene(a.scene)
    sim = dda.Simulation(scene)
    sim.run(until=a.until)
    state = sim._save_state()
    blob = pickle.dumps(sim, protocol=pickle.HIGHEST_PROTOCOL)
    n = a.rounds
    t_step = median_seconds(sim.step, n)
    t_build = median_seconds(lambda: type(sim)(scene), n)
    t_copy = median_seconds(lambda: copy.copy(sim), n)
    t_dumps = median_seconds(lambda: pickle.dumps(sim, protocol=pickle.HIGHEST_PROTOCOL), n)
    t_loads = median_seconds(lambda: pickle.loads(blob), n)
    contacts = len(sim.contacts()) if hasattr(sim, "contacts") else sim.contact_count
    print(f"{a.scene}: {sim.block_count} polygons, step {sim.step_count} (t = {sim.time:g} s), {contacts} contacts")
    print(f"state {len(state)} bytes, pickle {len(blob)} bytes (scene document {len(sim._document[0])} bytes)")
    print(f"medians of {n}: step {t_step * 1e3:.3f} ms, build from the scene {t_build * 1e3:.3f} ms, "
          f"copy.copy {t_copy * 1e3:.3f} ms, pickle.dumps {t_dumps * 1e3:.3f} ms, pickle.loads {t_loads * 1e3:.3f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
