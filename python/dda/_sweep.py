"""Sweeps: independent runs over a list of parameter sets, on local worker
processes or on a Dask distributed cluster, collected into one table.

Each run is make_scene(p, rng) -> a scene, run to `until` (default: the
scene's duration), then measure(sim, p) -> a dict of outputs. rng is a
numpy Generator seeded from the parameters alone (seed_of(p)): a rerun, on
any number of workers of either kind, gives the same table (apart from the
wall times). A run that fails (a scene error, a guard stop, an exception in
make_scene or measure) is a row with its error; the other runs go on. A run
whose worker process is lost (killed, crashed) is started again.
"""
import csv
import hashlib
import json
import math
import os
import time
import traceback

import numpy as np

from ._errors import SceneError, SimulationError

__all__ = ["sweep", "seed_of", "SweepTable"]

#: Columns every row has, after the parameters and the outputs.
RUN_COLUMNS = ("seed", "steps", "time", "wall_s", "error")


def _canonical(p):
    """p as canonical JSON (sorted keys, numpy values as plain numbers)."""
    from ._scene import _plain
    return json.dumps(_plain(p), sort_keys=True, separators=(",", ":"), allow_nan=True)


def seed_of(p):
    """The run's seed: 64 bits of SHA-256 of the parameters' canonical JSON.
    The same parameters give the same seed in any process, on any machine."""
    return int.from_bytes(hashlib.sha256(_canonical(p).encode()).digest()[:8], "little")


def _plain_output(v):
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, np.ndarray):
        return v.tolist()
    return v


def _run_one(make_scene, measure, p, until, threads):
    """One run in a worker: its row (never raises, apart from KeyboardInterrupt)."""
    from ._simulation import Simulation
    seed = seed_of(p)
    row = dict(p)
    outputs, drawn, steps, t, error = {}, {}, 0, None, None
    start = time.perf_counter()
    sim = None
    try:
        scene = make_scene(p, np.random.default_rng(seed))
        if isinstance(scene, tuple):  # (scene, the inputs it drew)
            scene, drawn = scene
            drawn = {k: _plain_output(v) for k, v in dict(drawn).items()}
            clash = [k for k in drawn if k in p or k in RUN_COLUMNS]
            if clash:
                drawn = {}
                raise ValueError(f"make_scene: inputs named like a parameter or a run column: {clash}")
        sim = Simulation(scene, threads=threads)
        sim.run(until=until)
        if measure is not None:
            outputs = {k: _plain_output(v) for k, v in dict(measure(sim, p)).items()}
            clash = [k for k in outputs if k in p or k in drawn or k in RUN_COLUMNS]
            if clash:
                outputs = {}
                raise ValueError(f"measure: outputs named like a parameter or a run column: {clash}")
    except (SceneError, SimulationError) as e:
        error = f"{type(e).__name__}: {e}"
        if isinstance(e, SimulationError):
            error = f"SimulationError ({e.reason}): {e}"
    except Exception as e:  # noqa: BLE001 - a failed run is a row, whatever failed
        error = f"{type(e).__name__}: {e} [{traceback.extract_tb(e.__traceback__)[-1].name}]"
    if sim is not None:
        steps, t = sim.step_count, sim.time
    row.update(drawn)
    row.update(outputs)
    row.update(seed=seed, steps=steps, time=t, wall_s=time.perf_counter() - start, error=error)
    return row


# --- local processes ------------------------------------------------------
_started = None  # the worker's queue of started task indices (set by _init_worker)


def _init_worker(queue):
    global _started
    _started = queue


def _local_task(index, make_scene, measure, p, until, threads):
    _started.put(index)  # synchronous (SimpleQueue): seen even if the worker dies right after
    return _run_one(make_scene, measure, p, until, threads)


def _lost_row(p, attempts):
    row = dict(p)
    row.update(seed=seed_of(p), steps=0, time=None, wall_s=None,
               error=f"WorkerLost: the worker process running this run died {attempts} times")
    return row


def _run_local(make_scene, measure, params, until, threads, workers, retries):
    import multiprocessing as mp
    from concurrent.futures import ProcessPoolExecutor, as_completed
    from concurrent.futures.process import BrokenProcessPool

    # Spawned workers: a fork of a process with threads (OpenMP, Dask) may hang.
    ctx = mp.get_context("spawn")
    n = len(params)
    rows, lost = [None] * n, [0] * n
    workers = max(1, min(workers or os.cpu_count() or 1, n))
    pending = list(range(n))
    while pending:
        queue = ctx.SimpleQueue()
        with ProcessPoolExecutor(max_workers=min(workers, len(pending)), mp_context=ctx, initializer=_init_worker,
                                 initargs=(queue,)) as pool:
            futures = {pool.submit(_local_task, i, make_scene, measure, params[i], until, threads): i
                       for i in pending}
            for f in as_completed(futures):
                try:
                    rows[futures[f]] = f.result()
                except BrokenProcessPool:
                    pass  # a worker died: its run and the runs queued behind it are started again below
        started = set()
        while not queue.empty():
            started.add(queue.get())
        for i in pending:
            if rows[i] is None and i in started:  # running when its worker died
                lost[i] += 1
                if lost[i] > retries:
                    rows[i] = _lost_row(params[i], lost[i])
        pending = [i for i in pending if rows[i] is None]
    return rows, lost


# --- Dask -----------------------------------------------------------------
def _run_dask(make_scene, measure, params, until, threads, scheduler, retries):
    try:
        from distributed import Client
    except ImportError as e:
        raise ImportError("dda.sweep(scheduler=...) runs on Dask's distributed (Debian package "
                          "python3-distributed)") from e

    client = scheduler if isinstance(scheduler, Client) else Client(scheduler)
    try:
        n = len(params)
        rows, lost = [None] * n, [0] * n
        futures = {}
        for i in range(n):
            futures[i] = client.submit(_run_one, make_scene, measure, params[i], until, threads, pure=False)
        while futures:
            again = {}
            for i, f in futures.items():
                try:
                    rows[i] = f.result()
                except Exception as e:  # noqa: BLE001 - KilledWorker and the like: the worker was lost
                    # The scheduler already moved the run to another worker up to
                    # distributed.scheduler.allowed-failures times; we submit it
                    # again `retries` times more.
                    lost[i] += 1
                    if lost[i] > retries:
                        rows[i] = _lost_row(params[i], lost[i])
                        rows[i]["error"] += f" ({type(e).__name__}: {e})"
                    else:
                        again[i] = client.submit(_run_one, make_scene, measure, params[i], until, threads,
                                                 pure=False)
            futures = again
        return rows, lost
    finally:
        if client is not scheduler:
            client.close()


def sweep(make_scene, params, measure=None, *, until=None, threads=1, scheduler=None, workers=None, retries=2):
    """Runs one simulation per parameter set; returns a SweepTable with a row
    per parameter set, in the order of `params`.

    make_scene(p, rng): the scene of parameter set p (a dict); rng is a
        numpy Generator seeded with seed_of(p) (draw random inputs from it).
        Returns a dda.Scene (or what dda.Simulation accepts), or a pair
        (scene, inputs) whose dict `inputs` (the values drawn) joins the row.
    params: a list of dicts (JSON-able values).
    measure(sim, p): the run's outputs, a dict (called after the run).
    until: simulated time of each run, s (default: the scene's duration).
    threads: threads of each run.
    scheduler: None: local worker processes (`workers` of them, default
        the CPU count); a Dask scheduler address ("tcp://host:port") or a
        distributed.Client: its cluster's workers.
    retries: how many more times a run is started when its worker is lost.

    Every row holds the parameters, the outputs, seed, steps, time (reached;
    None if no simulation was made), wall_s and error (None, or the error
    that stopped the run; its outputs are then missing). make_scene and measure must be picklable (functions
    defined at the top level of a module).
    """
    params = [dict(p) for p in params]
    if scheduler is None:
        rows, lost = _run_local(make_scene, measure, params, until, threads, workers, retries)
    else:
        rows, lost = _run_dask(make_scene, measure, params, until, threads, scheduler, retries)
    return SweepTable(rows, params, lost=lost)


class SweepTable(list):
    """The rows of a sweep (dicts), in the order of its parameters.

    params: the parameter sets.
    columns: parameter columns, drawn inputs and outputs, then seed, steps, time, wall_s, error.
    lost: per row, how often its worker was lost before it finished.
    """

    def __init__(self, rows, params, lost=None):
        super().__init__(rows)
        self.params = [dict(p) for p in params]
        self.lost = list(lost) if lost is not None else [0] * len(rows)

    @property
    def columns(self):
        cols = []
        for r in self.params + list(self):  # the parameters' keys first, then the outputs'
            for k in r:
                if k not in cols and k not in RUN_COLUMNS:
                    cols.append(k)
        return cols + list(RUN_COLUMNS)

    def column(self, name):
        """The column as a numpy array (missing values NaN for numbers, None otherwise)."""
        values = [r.get(name) for r in self]
        if all(v is None or (isinstance(v, (int, float)) and not isinstance(v, bool)) for v in values):
            return np.array([math.nan if v is None else v for v in values], dtype=float)
        return np.array(values, dtype=object)

    @property
    def failed(self):
        """The rows with an error."""
        return [r for r in self if r.get("error")]

    def without(self, *names):
        """The rows without these columns (e.g. "wall_s", to compare two runs)."""
        return [{k: v for k, v in r.items() if k not in names} for r in self]

    def to_csv(self, path):
        """Writes the table (via a temporary file renamed into place)."""
        cols = self.columns
        tmp = str(path) + ".tmp"
        with open(tmp, "w", newline="", encoding="utf-8") as f:
            w = csv.writer(f)
            w.writerow(cols)
            for r in self:
                w.writerow(["" if r.get(c) is None else (repr(r[c]) if isinstance(r[c], float) else r[c])
                            for c in cols])
        os.replace(tmp, path)

    def __repr__(self):
        return f"SweepTable({len(self)} rows, {len(self.failed)} failed, columns {self.columns})"
