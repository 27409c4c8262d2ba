"""Copies and pickles of a simulation hold its full state: copy.copy,
copy.deepcopy and pickle mid-run continue with the same bits as the
original; the comparison sees one step of difference; a state that does not
fit is refused; a copy while another thread steps is refused."""
import concurrent.futures
import copy
import multiprocessing
import pickle

import numpy as np
import pytest

import dda
from copy_cases import step_and_send_back
from stepping_helpers import refused_while_stepping


def toppling_stack(n=5, friction_deg=25.0):
    """n blocks, each shifted 0.28 m right of the one below, on a floor with
    friction: the stack leans over and slides, so that each pair's contact
    and friction history (the shear springs, sticking or sliding) matter."""
    s = dda.Scene(dt=1e-4, duration=2.0, gravity=(0, -9.81))
    s.material(density=2500, young=1e9, poisson=0.25)
    for k in range(n):
        s.rect(0.28 * k, 0.001 + k * 0.501, 1.0, 0.5, name=f"b{k}")
    s.boundary((-5, 0), (10, 0))
    s.contact(kn=1e9, kt=5e8, friction_deg=friction_deg)
    return s


def state_bytes(sim):
    """Every state read-out of a simulation, as raw bytes by name."""
    c = sim.contacts()
    out = {name: np.ascontiguousarray(getattr(sim, name)).tobytes()
           for name in ("centroids", "velocities", "spins", "rotations", "velocity_dofs", "displacements", "stresses",
                        "vertices", "vertex_offsets", "momentum")}
    out.update({"contacts." + name: np.ascontiguousarray(getattr(c, name)).tobytes()
                for name in ("pairs", "normal_forces", "shear_forces", "points", "couples", "ip_areas", "sliding",
                             "ip_vertices")})
    out["energy"] = np.array(list(sim.energy().as_dict().values())).tobytes()
    out["clock"] = np.array([sim.time, sim.step_count]).tobytes()
    return out


def differing(a, b):
    sa, sb = state_bytes(a), state_bytes(b)
    return sorted(k for k in sa if sa[k] != sb[k])


@pytest.fixture(scope="module")
def mid_run():
    sim = dda.Simulation(toppling_stack())
    sim.step(3000)
    # The history a copy must carry: contacts, stored shear springs, friction work.
    e = sim.energy()
    assert len(sim.contacts()) >= 4 and e.friction_spring > 0 and e.dissipated > 0
    return sim


@pytest.mark.parametrize("how", ["copy", "deepcopy", "pickle", "pickle-0", "pickle-threads"])
def test_a_copy_continues_with_the_same_bits(mid_run, how):
    original = copy.deepcopy(mid_run)  # the fixture itself stays at step 3000
    if how == "copy":
        twin = copy.copy(original)
        assert twin.scene is original.scene
    elif how == "deepcopy":
        twin = copy.deepcopy(original)
        assert twin.scene is not original.scene and twin.scene == original.scene
    elif how == "pickle-0":
        twin = pickle.loads(pickle.dumps(original, protocol=0))
    else:
        twin = pickle.loads(pickle.dumps(original, protocol=pickle.HIGHEST_PROTOCOL))
        assert twin.scene == original.scene and twin.threads == original.threads
        if how == "pickle-threads":
            twin.threads = 2  # any thread count gives the same bits
    assert type(twin) is dda.Simulation and twin is not original
    assert differing(original, twin) == []
    original.step(2000)
    twin.run(until=original.time)
    assert twin.step_count == original.step_count == 5000
    assert differing(original, twin) == []
    assert original.timeseries_row(range(5)) == twin.timeseries_row(range(5))
    # They are two simulations: stepping one leaves the other.
    twin.step()
    assert original.step_count == 5000


def test_a_pickle_continues_in_another_process(mid_run):
    # What a sweep fanning out from one prepared state does: the pickle goes
    # to a spawned process, steps there, and comes back with the same bits.
    original = copy.copy(mid_run)
    with concurrent.futures.ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn")) as pool:
        there = pool.submit(step_and_send_back, original, 1500).result(timeout=300)
    original.step(1500)
    assert there.step_count == original.step_count == 4500
    assert differing(original, there) == []


def test_the_comparison_sees_one_step(mid_run):
    # Negative control: the same comparison finds a copy one step ahead.
    a, b = copy.copy(mid_run), copy.copy(mid_run)
    b.step()
    a_state = differing(a, b)
    assert {"centroids", "velocity_dofs", "displacements", "energy", "clock"} <= set(a_state)
    a.step()
    assert differing(a, b) == []


def test_a_pickle_keeps_the_scene_it_was_made_of():
    # The scene changes after the simulation was made of it: a pickle holds
    # the document the simulation runs, not the changed one.
    s = toppling_stack(n=2)
    sim = dda.Simulation(s)
    sim.step(100)
    s.rect(5.0, 0.001, 1.0, 1.0, name="later")
    twin = pickle.loads(pickle.dumps(sim))
    assert twin.scene_block_count == 2 and twin.scene != s
    assert differing(sim, twin) == []


def test_a_state_that_does_not_fit_is_refused(mid_run):
    state = mid_run._save_state()
    other = dda.Simulation(toppling_stack(n=4))
    with pytest.raises(ValueError, match="another scene"):
        other._restore_state(state)
    same = dda.Simulation(toppling_stack())
    with pytest.raises(ValueError, match="truncated"):
        same._restore_state(state[:len(state) // 2])
    with pytest.raises(ValueError, match="left over"):
        same._restore_state(state + b"\0")


def test_a_copy_while_another_thread_steps_is_refused():
    sim = dda.Simulation(toppling_stack(n=2))
    refused = refused_while_stepping(sim, {"copy": copy.copy, "deepcopy": copy.deepcopy, "pickle": pickle.dumps},
                                     enough=2)
    assert min(refused.values()) >= 2, refused
    twin = copy.copy(sim)  # once it stopped, a copy is made
    assert differing(sim, twin) == []
