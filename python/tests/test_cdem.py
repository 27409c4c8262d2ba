"""Paper B's model from Python (dda.CdemSimulation): the same bits as
`dda run`, the mesh read-outs against the scene's geometry, the energy
account, momentum, the touch of the two prisms, guard stops, Ctrl-C, and
copies and pickles in contact that continue with the same bits."""
import copy
import json
import pickle
import subprocess

import numpy as np
import pytest

import dda
from sweep_cases import first_touch, prisms_at
from stepping_helpers import interrupted_run, python_run_csv


def prisms(scenes_dir, **change):
    d = json.loads((scenes_dir / "two_prisms.json").read_text())
    for k, v in change.items():
        d[k] = v
    return d


def test_a_cdem_scene_runs_paper_b_model_with_the_same_bytes_as_dda_run(cli, scenes_dir, tmp_path):
    scene = scenes_dir / "two_prisms.json"
    subprocess.run([str(cli), "run", str(scene), "--out", str(tmp_path), "--quiet"], check=True)
    ts, snap, sim = python_run_csv(scene)
    assert type(sim) is dda.CdemSimulation and sim.scene_file.model == "cdem"
    cli_ts = (tmp_path / "timeseries.csv").read_text()
    cli_snap = (tmp_path / "snapshots.csv").read_text()
    assert len(cli_ts.splitlines()) == sim.step_count + 2 > 100  # header, t = 0, every step
    assert ts == cli_ts
    assert snap == cli_snap
    assert len(sim.touches()["time"]) >= 1  # the prisms met


def test_the_prisms_touch_once_at_one_third_of_a_second_and_keep_their_momentum(scenes_dir):
    sim = dda.Simulation(prisms(scenes_dir))
    p0 = sim.momentum.copy()
    m = sim.masses
    # 7 m x 7 m triangles of rock, block i at 3 m/s.
    assert m == pytest.approx([2700 * 24.5] * 2, rel=1e-12)
    assert p0 == pytest.approx([3.0 * m[0], 0.0], abs=1e-9 * m[0])
    sim.run(until=0.4)
    t = sim.touches()
    # The gap of 1 m closed at 3 m/s: t = 1/3 s.
    assert t["time"][0] == pytest.approx(1.0 / 3.0, rel=1e-12)
    assert t["main_block"][0] != t["target_block"][0]
    # Eq. 5 is the measured loss of a lone clone's impact.
    assert t["energy_loss"][0] == pytest.approx(t["energy_loss_eq5"][0], rel=1e-9)
    # No gravity, no fixed block: the momentum stays (the sub-model returns forces that keep it).
    assert np.abs(sim.momentum - p0).max() <= 1e-12 * abs(p0[0])
    # Block j moves off after the impact.
    assert sim.velocities[1, 0] > 0.1


def test_energy_and_its_account(scenes_dir):
    sim = dda.Simulation(prisms(scenes_dir))
    sim.run(until=0.45)
    e, a = sim.energy(), sim.energy_account()
    assert a["time"] == sim.time
    assert e.initial == a["initial"] == pytest.approx(0.5 * sim.masses[0] * 3.0 ** 2, rel=1e-12)
    assert (e.kinetic, e.strain, e.gravity) == (a["kinetic"], a["strain"], a["gravity"])
    assert e.friction_spring == 0.0
    assert e.dissipated == pytest.approx(a["touch_loss"] + a["refine_loss"] + a["deletion_loss"], rel=1e-12)
    # The account closes: initial = kinetic + strain + gravity + losses + other.
    closed = a["kinetic"] + a["strain"] + a["gravity"] + a["touch_loss"] + a["refine_loss"] + a["deletion_loss"]
    assert closed + a["other"] == pytest.approx(a["initial"], rel=1e-12)
    assert e.balance_error == pytest.approx(-a["other"], abs=1e-9 * a["initial"])
    assert a["touch_loss"] > 0
    row = sim.timeseries_row([0, 1])
    header = dda.timeseries_header([0, 1], rotation=False)
    assert len(row) == len(header) and "b0_rot" not in header
    assert row[header.index("E_total")] == e.total and row[header.index("px")] == sim.momentum[0]


def test_nodes_and_elements_cover_the_blocks(scenes_dir):
    sim = dda.Simulation(prisms(scenes_dir))
    # At t = 0 the triangles tile each block: their areas sum to the outline's.
    x0 = sim.node_positions
    for b in range(sim.block_count):
        p = x0[sim.elements(b)]
        tri = 0.5 * ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1])
                     - (p[:, 2, 0] - p[:, 0, 0]) * (p[:, 1, 1] - p[:, 0, 1]))
        o = sim.outline(b)
        outline_area = 0.5 * np.sum(o[:, 0] * np.roll(o[:, 1], -1) - np.roll(o[:, 0], -1) * o[:, 1])
        assert outline_area == pytest.approx(24.5, rel=1e-12)
        assert tri.sum() == pytest.approx(outline_area, rel=1e-12)
    sim.run(until=0.34)  # inside the contact
    n = sim.node_count
    x, v, mass, blk, kind = (sim.node_positions, sim.node_velocities, sim.node_masses, sim.node_blocks,
                             sim.node_kinds)
    assert x.shape == v.shape == (n, 2) and mass.shape == blk.shape == kind.shape == (n,)
    assert set(kind) <= {"coarse", "fine", "hanging", "dead"}
    for b in range(sim.block_count):
        el = sim.elements(b)
        assert el.ndim == 2 and el.shape[1] == 3 and len(el) > 0
        assert (blk[el] == b).all()
        p = x[el]  # (m, 3, 2)
        tri = 0.5 * ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1])
                     - (p[:, 2, 0] - p[:, 0, 0]) * (p[:, 1, 1] - p[:, 0, 1]))
        assert (tri > 0).all()  # counter-clockwise, none inverted
        assert tri.sum() == pytest.approx(24.5, rel=1e-3)  # deformed a little
        # Lumped masses: the block's mass, and its mean position the mass-weighted one.
        live = (blk == b) & (kind != "dead")
        assert mass[live].sum() == pytest.approx(sim.masses[b], rel=1e-12)
        assert (mass[live] @ x[live]) / mass[live].sum() == pytest.approx(sim.positions[b], abs=1e-12)
    all_el = sim.elements()
    assert len(all_el) == len(sim.element_blocks()) == len(sim.element_stresses())
    assert np.abs(sim.element_stresses()).max() > 0  # stressed by the impact
    c = sim.clones()
    assert len(c["main_node"]) == sim.contact_count >= 1
    assert c["point"].shape == c["force"].shape == c["target"].shape == (sim.contact_count, 2)


def test_run_stops_where_dda_run_stops_and_calls_back(scenes_dir):
    sim = dda.Simulation(prisms(scenes_dir))
    seen = []
    n = sim.run(until=0.0105, every=5, callback=lambda s: seen.append(s.step_count))
    assert n == sim.step_count == 21 and sim.time + 0.5 * sim.dt >= 0.0105 > sim.time - 0.5 * sim.dt
    assert seen == [5, 10, 15, 20, 21]
    assert sim.run(until=0.0105) == 0
    sim.step(3)
    sim.step()
    assert sim.step_count == 25


def test_ctrl_c_stops_a_long_run_and_leaves_the_simulation_usable(scenes_dir):
    sim = dda.Simulation(prisms(scenes_dir))
    latency = interrupted_run(sim, 1e5)  # 2e8 steps
    assert 0 < sim.time < 1e3 and latency < 2.0
    # Usable, in the state of a run that was never interrupted.
    n = sim.step_count
    sim.step(7)
    ref = dda.Simulation(prisms(scenes_dir))
    ref.step(n + 7)
    assert np.array_equal(ref.node_positions, sim.node_positions)
    assert np.array_equal(ref.node_velocities, sim.node_velocities)


def test_a_guard_stop_is_a_simulation_error(scenes_dir):
    d = prisms(scenes_dir)
    d["blocks"][0]["velocity"] = [3000.0, 0.0]  # a hypervelocity impact: the sub-model's elements invert
    sim = dda.Simulation(d)
    with pytest.raises(dda.SimulationError, match="inverted") as e:
        sim.run()
    assert e.value.reason == "area_collapsed"
    assert np.isfinite(sim.node_positions).all()  # readable at the failed step


def test_scene_errors_and_threads(scenes_dir):
    d = prisms(scenes_dir, dt=0.05)
    with pytest.raises(dda.SceneError, match="critical step") as e:
        dda.Simulation(d)
    assert e.value.field == "dt"
    with pytest.raises(ValueError, match="one thread"):
        dda.Simulation(prisms(scenes_dir), threads=2)
    with pytest.raises(ValueError, match="Paper A's model runs in dda.Simulation"):
        dda.CdemSimulation(scenes_dir / "two_squares.json")
    assert type(dda.CdemSimulation(prisms(scenes_dir))) is dda.CdemSimulation


def cdem_state_bytes(sim):
    """Every state read-out of a dda.CdemSimulation, as raw bytes by name."""
    out = {name: np.ascontiguousarray(getattr(sim, name)).tobytes()
           for name in ("positions", "velocities", "displacements", "masses", "node_positions", "node_velocities",
                        "node_masses", "node_blocks", "node_kinds", "momentum")}
    out["elements"] = sim.elements().tobytes()
    out["element_stresses"] = sim.element_stresses().tobytes()
    for table in ("clones", "touches", "separations", "slips", "submodels"):
        for k, v in getattr(sim, table)().items():
            out[f"{table}.{k}"] = np.asarray(v).tobytes()
    out["energy"] = np.array(list(sim.energy().as_dict().values())).tobytes()
    out["energy_account"] = np.array(list(sim.energy_account().values())).tobytes()
    out["clock"] = np.array([sim.time, sim.step_count, sim.contact_count, sim.live_submodels]).tobytes()
    return out


def cdem_differing(a, b):
    sa, sb = cdem_state_bytes(a), cdem_state_bytes(b)
    return sorted(k for k in sa if sa[k] != sb[k])


def prisms_variant(scenes_dir, variant):
    """The two prisms with Sect. 5 as written (the file), refined in place,
    with a Coulomb impact at an angle, or the node-to-edge penalty baseline."""
    d = prisms(scenes_dir)
    if variant == "in_place":
        d["cdem"]["subdivision_mode"] = "in_place"
    elif variant == "coulomb":
        d["cdem"]["touch_impact"] = "coulomb"
        d["cdem"]["strength"] = {"friction_deg": 10}
        d["blocks"][0]["velocity"] = [3.0, 1.5]
    elif variant == "penalty_baseline":
        d["cdem"] = {"contact": "node_to_edge_penalty", "divisions": 2}
    return d


@pytest.mark.parametrize("variant", ["submodel", "in_place", "coulomb", "penalty_baseline"])
@pytest.mark.parametrize("how", ["copy", "deepcopy", "pickle"])
def test_a_copy_in_contact_continues_with_the_same_bits(scenes_dir, variant, how):
    original = dda.Simulation(prisms_variant(scenes_dir, variant))
    original.run(until=0.3338)  # in contact: the clone and the refined elements are state
    assert original.contact_count >= 1
    if variant in ("submodel", "coulomb"):
        assert original.live_submodels == 1
    if variant == "in_place":
        assert (original.node_kinds == "fine").any()
    if how == "copy":
        twin = copy.copy(original)
    elif how == "deepcopy":
        twin = copy.deepcopy(original)
    else:
        twin = pickle.loads(pickle.dumps(original))
    assert type(twin) is dda.CdemSimulation and twin.scene == original.scene
    assert cdem_differing(original, twin) == []
    original.run(until=0.45)
    twin.run(until=0.45)
    assert twin.step_count == original.step_count == 900
    assert cdem_differing(original, twin) == []
    assert original.timeseries_row([0, 1]) == twin.timeseries_row([0, 1])


def test_the_cdem_comparison_sees_one_step(scenes_dir):
    # Negative control: the same comparison finds a copy one step ahead.
    sim = dda.Simulation(prisms(scenes_dir))
    sim.run(until=0.3338)
    a, b = copy.copy(sim), copy.copy(sim)
    b.step()
    assert {"node_positions", "node_velocities", "energy_account", "clock"} <= set(cdem_differing(a, b))
    a.step()
    assert cdem_differing(a, b) == []


def test_a_cdem_state_that_does_not_fit_is_refused(scenes_dir):
    sim = dda.Simulation(prisms(scenes_dir))
    sim.run(until=0.3338)
    state = sim._save_state()
    with pytest.raises(ValueError, match="truncated"):
        dda.Simulation(prisms(scenes_dir))._restore_state(state[:len(state) // 2])
    finer = prisms(scenes_dir)
    finer["cdem"]["divisions"] = 3
    with pytest.raises(ValueError, match="another scene"):
        dda.Simulation(finer)._restore_state(state)


def test_a_sweep_runs_paper_b_model(scenes_dir):
    # Local worker processes run the cdem scene: the 1 m gap closes at 1 / speed.
    params = [{"speed": 2.0}, {"speed": 4.0}, {"speed": 3000.0}]
    t = dda.sweep(prisms_at, params, first_touch, until=0.6, workers=2)
    assert [r["error"] for r in t[:2]] == [None, None]
    assert [r["touch_time"] for r in t[:2]] == pytest.approx([0.5, 0.25], rel=1e-12)
    assert t[2]["error"].startswith("SimulationError (area_collapsed)")
