"""dda.sweep on local worker processes and on a two-worker local Dask
cluster: the same table, failed runs as rows, seeds from the parameters,
lost workers retried."""
import math
import warnings

import numpy as np
import pytest

import dda
from sweep_cases import slide, sliding_block

PARAMS = [{"phi": 20}, {"phi": 30}, {"phi": 30, "kn": -1.0}, {"phi": 25, "speed": 200.0, "dive": 1.0, "kn": 1e5},
          {"phi": 35}, {"phi": 30, "bad_measure": True}, {"phi": 40}]


@pytest.fixture(scope="module")
def cluster():
    """Two worker processes (each with its nanny, which restarts a lost one) on loopback."""
    distributed = pytest.importorskip("distributed")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)  # tornado's make_current, inside distributed
        with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                      dashboard_address=None, silence_logs=40) as c:
            yield c


def check_table(t):
    assert [{k: r[k] for k in p} for r, p in zip(t, PARAMS)] == PARAMS  # in the order of the parameters
    assert t.columns == ["phi", "kn", "speed", "dive", "bad_measure", "slide", "vx", "seed", "steps", "time",
                         "wall_s", "error"]
    ok = [r for r in t if r["error"] is None]
    assert len(ok) == 4 and all(r["steps"] == 2000 and math.isfinite(r["slide"]) for r in ok)
    assert t[2]["error"] == "SceneError: <scene>: contact.kn: must be positive"
    assert (t[2]["steps"], t[2]["time"]) == (0, None)
    assert t[3]["error"].startswith("SimulationError (") and 0 < t[3]["steps"] < 2000
    assert t[5]["error"].startswith("KeyError:") and "slide" not in t[5]
    assert [r["seed"] for r in t] == [dda.seed_of(p) for p in PARAMS]
    # The friction angle orders the slides (same speed distribution).
    slides = {r["phi"]: r["slide"] for r in ok}
    assert slides[20] > slides[30] > 0 and slides[40] > 0


def test_local_processes_and_dask_give_the_same_table(cluster):
    local = dda.sweep(sliding_block, PARAMS, slide, workers=2)
    check_table(local)
    dask = dda.sweep(sliding_block, PARAMS, slide, scheduler=cluster.scheduler_address)
    check_table(dask)
    assert local.without("wall_s") == dask.without("wall_s")
    col = local.column("slide")
    assert np.isnan(col[[2, 3, 5]]).all() and np.isfinite(col[[0, 1, 4, 6]]).all()


def test_seeds_come_from_the_parameters_alone():
    assert dda.seed_of({"a": 1, "b": 2.5}) == dda.seed_of({"b": 2.5, "a": 1}) == dda.seed_of(
        {"a": np.int64(1), "b": np.float64(2.5)})
    assert dda.seed_of({"a": 1}) != dda.seed_of({"a": 2})


def test_a_lost_worker_is_retried(cluster, tmp_path):
    params = [{"phi": 30}, {"phi": 30, "die_once": str(tmp_path / "local")}, {"phi": 35}]
    local = dda.sweep(sliding_block, params, slide, workers=2)
    assert (tmp_path / "local").exists() and local.lost[1] == 1
    assert [r["error"] for r in local] == [None, None, None]
    params[1]["die_once"] = str(tmp_path / "dask")
    dask = dda.sweep(sliding_block, params, slide, scheduler=cluster.scheduler_address)
    assert (tmp_path / "dask").exists()
    assert [r["error"] for r in dask] == [None, None, None]
    # The retried run is the run that would have run: same outputs as its twin without a loss.
    assert local[1]["slide"] != local[0]["slide"]  # another seed (die_once is a parameter)
    for t in (local, dask):
        assert t[1]["steps"] == 2000


def test_a_run_lost_every_time_is_a_row(tmp_path):
    # retries=0: the first loss is final; the others finish.
    params = [{"phi": 30}, {"phi": 30, "die_once": str(tmp_path / "m")}]
    t = dda.sweep(sliding_block, params, slide, workers=1, retries=0)
    assert t[0]["error"] is None
    assert t[1]["error"].startswith("WorkerLost") and t.lost == [0, 1]
