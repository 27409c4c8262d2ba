"""Scenes from files, JSON text, dicts and Python calls: the same validation
and messages as `dda check`, and to_json() round trips."""
import json
import re
import subprocess

import numpy as np
import pytest

import dda


def check_stderr(cli, path):
    r = subprocess.run([str(cli), "check", str(path)], capture_output=True, text=True)
    assert r.returncode == 2, r.stdout
    return r.stderr.strip()


def test_bad_files_give_dda_checks_message_field_and_position(cli, bad_dir):
    files = sorted(bad_dir.glob("*.json"))
    assert len(files) >= 8
    for f in files:
        expected = check_stderr(cli, f)
        with pytest.raises(dda.SceneError) as e:
            dda.Scene.from_file(f)
        err = e.value
        assert isinstance(err, ValueError)
        assert str(err) == expected
        assert err.source == str(f)
        # The message is "<file>[:<line>:<col>]: <field>: <reason>".
        m = re.match(re.escape(str(f)) + r"(?::(\d+):(\d+))?: (?:near )?(\S+): (.*)$", expected)
        assert m, expected
        assert (err.line, err.column) == ((int(m.group(1)), int(m.group(2))) if m.group(1) else (None, None))
        assert err.field == m.group(3)
        assert err.reason == m.group(4)


def test_the_same_text_as_a_string_gives_the_same_message(cli, bad_dir):
    for f in sorted(bad_dir.glob("*.json")):
        expected = check_stderr(cli, f).replace(str(f), "<string>", 1)
        with pytest.raises(dda.SceneError) as e:
            dda.Scene.from_json(f.read_text())
        assert str(e.value) == expected


def test_dict_errors_name_the_field_without_a_position():
    d = {"materials": [{"density": 2000, "young": 1e9, "poisson": 0.25}],
         "blocks": [{"rect": [0, 0, 1, 1]}, {"vertices": [[2, 0], [2, 1], [3, 0]]}],
         "contact": {"kn": 1e7}, "dt": 1e-4, "duration": 0.01}
    with pytest.raises(dda.SceneError) as e:
        dda.Scene.from_dict(d)
    assert e.value.field == "blocks[1].vertices[0]"
    assert (e.value.line, e.value.column) == (None, None)
    assert str(e.value) == "<scene>: blocks[1].vertices[0]: clockwise vertex order (counter-clockwise required)"
    d["blocks"][1]["vertices"] = [[2, 0], [3, 0], [2, 1]]
    d["materials"][0]["densty"] = 1
    with pytest.raises(dda.SceneError, match=r"materials\[0\]\.densty: unknown key \(did you mean 'density'\?\)"):
        dda.Scene.from_dict(d)
    del d["materials"][0]["densty"]
    assert dda.Scene.from_dict(d).block_count == 2


def test_built_scene_errors_name_the_field():
    s = dda.Scene(dt=1e-4, duration=0.1)
    s.material(density=2000, young=1e9, poisson=0.25)
    s.rect(0, 0, 1, 1)
    with pytest.raises(dda.SceneError) as e:
        s.check()
    assert (e.value.field, e.value.reason) == ("contact", "missing required key")
    s.contact(kn=0.0)
    with pytest.raises(dda.SceneError) as e:
        s.check()
    assert str(e.value) == "<scene>: contact.kn: must be positive"
    s.contact(kn=1e7, friction_deg=30)
    with pytest.raises(dda.SceneError) as e:
        dda.Simulation(s)
    assert e.value.field == "contact.friction_deg"
    s.contact(kn=1e7)
    s.rect(0.5, 0.5, 1, 1)
    with pytest.raises(dda.SceneError, match=r"blocks\[0\]: overlaps blocks\[1\] at t = 0"):
        dda.Simulation(s)


def collapse_built(description):
    """repro/scenes/collapse_case1.json built in Python."""
    s = dda.Scene(name="collapse_case1", dt=1e-4, duration=7.5, gravity=(0.0, -9.81), broad_phase="sweep")
    s.set("description", description)
    rock = s.material(density=2700, young=2e9, poisson=0.3, name="rock")
    s.region(np.array([[0, 0], [20, 0], [20, 50], [0, 50]]),
             [dda.JointSet(80, 1.5, (0, 0)), dda.JointSet(40, 2.5, (0, 0))],
             min_area=0.5, material="rock", group=0, name="rock")
    assert rock == 0
    s.boundary((0, 60), (0, 0), depth=5, group=1)
    s.boundary((-5, 0), (200, 0), depth=5, group=1)
    s.contact(kn=2e9, kt=1e9, friction_deg=15, friction_rules=[((0, 1), 35)])
    s.output(every=500, snapshots=[0.0, 2.5, 5.0, 7.5])
    return s


def test_a_scene_built_in_python_is_the_files_scene(cli, scenes_dir):
    f = scenes_dir / "collapse_case1.json"
    built = collapse_built(json.loads(f.read_text())["description"])
    read = dda.Scene.from_file(f)
    assert built.resolved_json() == read.resolved_json()
    # `dda check`'s count of generated blocks and dropped slivers.
    out = subprocess.run([str(cli), "check", str(f)], capture_output=True, text=True, check=True).stdout
    g = built.generated[0]
    assert f"{g['count']} blocks generated from region 0, {g['dropped']} slivers dropped" in out
    assert g["first_block"] == 0 and g["count"] == built.block_count > 100


def test_to_json_round_trips(scenes_dir):
    for f in sorted(scenes_dir.glob("*.json")):
        s = dda.Scene.from_file(f)
        back = dda.Scene.from_json(s.to_json())
        assert back == s and back.to_dict() == json.loads(f.read_text())
        assert back.resolved_json() == s.resolved_json()
    built = collapse_built("built in Python")
    assert built.to_dict()["generated"][0]["joint_sets"][1] == {"dip_deg": 40, "spacing": 2.5, "origin": [0, 0]}
    back = dda.Scene.from_json(built.to_json(indent=2))
    assert back == built and back.resolved_json() == built.resolved_json()
    # The library's own form (every vertex written out) reads back to itself.
    resolved = dda.Scene.from_json(built.resolved_json())
    assert resolved.resolved_json() == built.resolved_json()


def test_numbers_round_trip_bit_for_bit():
    x = [0.1 + 0.2, 1 / 3, 2.0 ** -40, 1e-300 * 3.3, np.nextafter(1.0, 2.0)]
    s = dda.Scene(dt=1e-4, duration=0.01)
    s.material(density=2000, young=1e9, poisson=0.25)
    s.block([[x[0], x[1]], [x[0] + 1, x[1]], [x[0] + 1, x[1] + x[4]]], velocity=(x[2], x[3]))
    s.contact(kn=1e7)
    back = dda.Scene.from_json(s.to_json())
    v, _ = back.block_vertices()
    assert v[0, 0] == x[0] and v[0, 1] == x[1] and v[2, 1] == x[1] + x[4]
    assert back.to_dict()["blocks"][0]["velocity"] == [x[2], x[3]]


def test_files_and_dicts_load_alike(scenes_dir):
    f = scenes_dir / "drop_on_ground.json"
    a = dda.load_scene(str(f))
    b = dda.load_scene(json.loads(f.read_text()))
    c = dda.load_scene(f.read_text())
    assert a.resolved_json() == b.resolved_json() == c.resolved_json()
    with pytest.raises(dda.SceneError, match=r"\.missing: cannot open"):
        dda.load_scene(str(f) + ".missing")


def test_a_scene_pickles_as_its_document(scenes_dir):
    import pickle
    s = dda.Scene.from_file(scenes_dir / "incline.json")
    back = pickle.loads(pickle.dumps(s))
    assert back == s and back.resolved_json() == s.resolved_json()
