"""Scenes and measures of the sweep tests (a module of their own: worker
processes import them by name)."""
import os
import signal

import dda


def sliding_block(p, rng):
    """A block pushed along a floor with friction p["phi"] degrees, at a
    speed drawn from rng; p["kn"] (optional) its contact stiffness."""
    if p.get("die_once"):
        # A worker lost mid-run: the first attempt kills its own process.
        marker = p["die_once"]
        if not os.path.exists(marker):
            open(marker, "w").close()
            os.kill(os.getpid(), signal.SIGKILL)
    s = dda.Scene(dt=1e-4, duration=0.2, gravity=(0.0, -9.81), strains=False)
    s.material(density=2000, young=1e9, poisson=0.25)
    speed = rng.uniform(0.5, 1.0) * p.get("speed", 1.0)
    s.rect(0.0, 0.0, 0.5, 0.5, velocity=(speed, -speed * p.get("dive", 0.0)))
    s.boundary((-1.0, 0.0), (10.0, 0.0), depth=1.0)
    s.contact(kn=p.get("kn", 1e9), kt=1e8, friction_deg=p["phi"])
    return s


def slide(sim, p):
    if p.get("bad_measure"):
        raise KeyError("no such output")
    return {"slide": float(sim.displacements[0, 0]), "vx": float(sim.velocities[0, 0])}


def prisms_at(p, rng):
    """The two prisms of Paper B (repro/scenes/two_prisms.json, the cdem
    model) with block i at p["speed"] m/s."""
    import json
    import pathlib
    scenes = pathlib.Path(os.environ.get("DDA_SCENES_DIR", pathlib.Path(__file__).resolve().parents[2] / "repro" /
                                         "scenes"))
    d = json.loads((scenes / "two_prisms.json").read_text())
    d["blocks"][0]["velocity"] = [p["speed"], 0.0]
    return d


def first_touch(sim, p):
    t = sim.touches()["time"]
    return {"touch_time": float(t[0]) if len(t) else None, "px": float(sim.momentum[0])}
