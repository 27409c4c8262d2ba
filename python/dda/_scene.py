"""Scenes: a JSON document in the scene-file schema (lib/io/SCHEMA.md),
read from a file, a JSON string or a dict, or built in Python, and validated
by the library's scene-file reader: the same checks and messages as
`dda check` (dda.SceneError with the field and position)."""
import copy
import json
import os
from collections import namedtuple

import numpy as np

from . import _core
from ._errors import SceneError

__all__ = ["Scene", "JointSet", "load_scene"]

#: A family of parallel joints: dip below the horizontal toward +x (degrees,
#: in (0, 180)), spacing normal to the joints (m), a point one joint passes through.
JointSet = namedtuple("JointSet", "dip_deg spacing origin", defaults=((0.0, 0.0),))

def _plain(x):
    """x with numpy arrays and scalars, tuples and JointSets turned into JSON's lists and numbers."""
    if isinstance(x, JointSet):
        return {"dip_deg": _plain(x.dip_deg), "spacing": _plain(x.spacing), "origin": _plain(x.origin)}
    if isinstance(x, np.ndarray):
        return _plain(x.tolist())
    if isinstance(x, (np.floating,)):
        return float(x)
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, np.bool_):
        return bool(x)
    if isinstance(x, dict):
        return {str(k): _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    return x


def _given(**kw):
    """The keyword arguments that were given (None: the schema's default)."""
    return {k: _plain(v) for k, v in kw.items() if v is not None}


class Scene:
    """A scene to simulate: blocks, materials, boundaries, contact, guards, damping.

    Read one with Scene.from_file(path), Scene.from_json(text) or
    Scene.from_dict(d) (validated at once: dda.SceneError), or build one:

        s = dda.Scene(dt=1e-4, duration=1.0, gravity=(0, -9.81))
        rock = s.material(density=2700, young=2e9, poisson=0.3, name="rock")
        s.rect(0, 0, 1, 1, material=rock, name="A")
        s.boundary((-5, 0), (5, 0))
        s.contact(kn=1e9)

    A built scene is validated by check(), and by everything that needs the
    library's scene (Simulation, block_count, ...). Keyword arguments are the
    scene file's keys (SCHEMA.md); an argument left at None is left out of
    the document (the file's default applies). to_json() gives the document
    back; Scene.from_json(s.to_json()) is the same scene.
    """

    def __init__(self, *, dt=None, duration=None, gravity=None, name=None, description=None, dt_fraction=None,
                 strains=None, broad_phase=None, initial_overlap=None, rotation_update=None, max_steps=None):
        self._doc = {"materials": [], "blocks": []}
        self._doc.update(_given(name=name, description=description, gravity=gravity, strains=strains,
                                broad_phase=broad_phase, initial_overlap=initial_overlap, dt=dt,
                                dt_fraction=dt_fraction, duration=duration, max_steps=max_steps,
                                rotation_update=rotation_update))
        self._source, self._read_max_steps = "<scene>", 0
        self._file = None  # the library's validated scene (None: not validated since the last change)

    # --- reading -------------------------------------------------------
    @classmethod
    def from_file(cls, path, max_steps=None):
        """Reads and validates a scene file. max_steps overrides the file's
        (as `dda check --max-steps N`)."""
        path = str(path)
        s = cls.__new__(cls)
        s._source, s._read_max_steps = path, int(max_steps or 0)
        s._file = s._library(lambda: _core.load_scene_file(path, s._read_max_steps))
        with open(path, encoding="utf-8") as f:
            s._doc = json.load(f)
        return s

    @classmethod
    def from_json(cls, text, max_steps=None):
        """Parses and validates scene JSON text (messages start with "<string>")."""
        s = cls.__new__(cls)
        s._source, s._read_max_steps = "<string>", int(max_steps or 0)
        s._file = s._library(lambda: _core.parse_scene(text, "<string>", s._read_max_steps))
        s._doc = json.loads(text)
        return s

    @classmethod
    def _from_document(cls, text, source, max_steps):
        """The scene of _document(): its JSON text, the source that labels its
        messages and the step limit it was read with (validated)."""
        s = cls.__new__(cls)
        s._doc, s._source, s._read_max_steps, s._file = json.loads(text), source, int(max_steps), None
        s.check()
        return s

    def _document(self):
        """(JSON text, source, max_steps): what _from_document makes the same scene of (a simulation keeps it for pickling)."""
        return self.to_json(), self._source, self._read_max_steps

    @classmethod
    def from_dict(cls, d, max_steps=None):
        """Validates a scene given as a dict of the file's keys (messages start with "<scene>")."""
        s = cls.__new__(cls)
        s._doc = copy.deepcopy(_plain(d))
        s._source, s._read_max_steps = "<scene>", int(max_steps or 0)
        s._file = None
        s.check()
        return s

    # --- building ------------------------------------------------------
    def _changed(self):
        self._file = None
        self._source = "<scene>"

    def set(self, key, value):
        """Sets a top-level key of the document (any key of the schema)."""
        self._doc[key] = _plain(value)
        self._changed()
        return self

    def material(self, density, young, poisson, name=None):
        """Adds a material (kg/m^3, Pa, dimensionless); returns its index."""
        self._doc.setdefault("materials", []).append(_given(name=name, density=density, young=young,
                                                            poisson=poisson))
        self._changed()
        return len(self._doc["materials"]) - 1

    def block(self, vertices, *, velocity=None, spin=None, fixed=None, material=None, group=None, name=None,
              rotate_deg=None, about=None):
        """Adds a block from its counter-clockwise vertices ((n, 2), convex);
        returns its index. material: an index or a material's name."""
        self._doc.setdefault("blocks", []).append(
            _given(name=name, vertices=vertices, rotate_deg=rotate_deg, about=about, velocity=velocity, spin=spin,
                   fixed=fixed, material=material, group=group))
        self._changed()
        return len(self._doc["blocks"]) - 1

    def rect(self, x0, y0, width, height, *, velocity=None, spin=None, fixed=None, material=None, group=None,
             name=None, rotate_deg=None, about=None):
        """Adds a rectangular block with lower-left corner (x0, y0); returns its index."""
        self._doc.setdefault("blocks", []).append(
            _given(name=name, rect=[x0, y0, width, height], rotate_deg=rotate_deg, about=about, velocity=velocity,
                   spin=spin, fixed=fixed, material=material, group=group))
        self._changed()
        return len(self._doc["blocks"]) - 1

    def region(self, region, joint_sets=(), *, min_area=None, material=None, group=None, name=None):
        """Adds a region (a simple CCW polygon) cut into blocks by joint sets
        (JointSet or dicts); its blocks come after the listed blocks.
        Returns the region's index (its blocks: generated[index] once validated)."""
        gen = self._doc.get("generated")
        if gen is None:
            gen = self._doc["generated"] = []
        elif isinstance(gen, dict):
            gen = self._doc["generated"] = [gen]
        gen.append(_given(name=name, region=region, joint_sets=[_plain(j) for j in joint_sets], min_area=min_area,
                          material=material, group=group))
        self._changed()
        return len(gen) - 1

    def boundary(self, a, b, *, depth=None, group=None):
        """Adds a boundary segment from a to b (the solid on its right); returns its index."""
        self._doc.setdefault("boundaries", []).append(_given(a=a, b=b, depth=depth, group=group))
        self._changed()
        return len(self._doc["boundaries"]) - 1

    def contact(self, kn, *, kt=None, friction_deg=None, friction_rules=None, h_rule=None, h=None,
                integration=None, small_edge_fraction=None, small_edge_rays=None, friction_update=None):
        """Sets the contact parameters. friction_rules: [((group_a, group_b), friction_deg), ...]
        or the file's form [{"groups": [a, b], "friction_deg": phi}, ...]."""
        if friction_rules is not None:
            friction_rules = [r if isinstance(r, dict) else {"groups": list(r[0]), "friction_deg": r[1]}
                              for r in friction_rules]
        self._doc["contact"] = _given(kn=kn, kt=kt, friction_deg=friction_deg, friction_rules=friction_rules,
                                      h_rule=h_rule, h=h, integration=integration,
                                      small_edge_fraction=small_edge_fraction, small_edge_rays=small_edge_rays,
                                      friction_update=friction_update)
        self._changed()
        return self

    def guards(self, *, max_step_motion=None, max_balance_error=None, max_energy_growth=None,
               energy_check_every=None, max_penetration=None, max_approach_energy=None):
        """Sets the stability guards (the others keep their defaults)."""
        self._doc.setdefault("guards", {}).update(
            _given(max_step_motion=max_step_motion, max_balance_error=max_balance_error,
                   max_energy_growth=max_energy_growth, energy_check_every=energy_check_every,
                   max_penetration=max_penetration, max_approach_energy=max_approach_energy))
        self._changed()
        return self

    def damping(self, *, mass=None, stiffness=None, settle_time=None, settle_sticking=None, settle_slip_time=None):
        """Sets Eq. 5c damping (C = a M + b K) and the settle-then-load options."""
        self._doc.setdefault("damping", {}).update(
            _given(mass=mass, stiffness=stiffness, settle_time=settle_time, settle_sticking=settle_sticking,
                   settle_slip_time=settle_slip_time))
        self._changed()
        return self

    def output(self, *, every=None, snapshots=None, tracked_blocks=None):
        """Sets what `dda run` writes for this scene."""
        self._doc.setdefault("output", {}).update(_given(every=every, snapshots=snapshots,
                                                         tracked_blocks=tracked_blocks))
        self._changed()
        return self

    # --- validation and the library's scene ------------------------------
    def _library(self, call, positions=True):
        try:
            return call()
        except _core.RawSceneError as e:
            raise SceneError.from_library(str(e), self._source, positions=positions) from None

    def check(self):
        """Validates the scene as `dda check` does (dda.SceneError); returns self."""
        if self._file is None:
            # Our JSON text of the document: its line and column mean nothing to the user.
            text = json.dumps(self._doc, allow_nan=True)
            self._file = self._library(lambda: _core.parse_scene(text, self._source, self._read_max_steps),
                                       positions=False)
        return self

    @property
    def scene_file(self):
        """The library's validated scene (_core.SceneFile)."""
        return self.check()._file

    @property
    def block_count(self):
        """Blocks: listed, then generated (boundaries not counted)."""
        return self.scene_file.block_count

    @property
    def generated(self):
        """Per generated region: first_block, count, dropped (slivers), dropped_area (m^2)."""
        return self.scene_file.generated

    @property
    def duration(self):
        return self.scene_file.duration

    def block_vertices(self):
        """(vertices (V, 2), offsets (n + 1,)) of the blocks at t = 0, generated ones included."""
        return self.scene_file.block_vertices()

    def to_dict(self):
        """A copy of the document (the scene file's keys)."""
        return copy.deepcopy(self._doc)

    def to_json(self, indent=None):
        """The document as scene-file JSON (generated regions kept as regions).
        Numbers are written in shortest round-trip form: the same doubles read back."""
        return json.dumps(self._doc, indent=indent, allow_nan=False)

    def save(self, path, indent=2):
        """Writes to_json() to path, via a temporary file renamed into place."""
        tmp = str(path) + ".tmp"
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(self.to_json(indent=indent) + "\n")
        os.replace(tmp, path)

    def resolved_json(self):
        """The library's JSON of the validated scene: every block's vertices
        written out (generated blocks as listed ones), all defaults explicit."""
        return self.scene_file.write_json()

    def __getstate__(self):  # picklable: the document; the library's scene is made again when needed
        state = dict(self.__dict__)
        state["_file"] = None
        return state

    def __eq__(self, other):
        return isinstance(other, Scene) and self._doc == other._doc

    def __repr__(self):
        n = len(self._doc.get("blocks", []))
        g = self._doc.get("generated")
        g = 0 if g is None else (1 if isinstance(g, dict) else len(g))
        return f"dda.Scene({self._source!r}: {n} listed blocks, {g} generated regions)"


def load_scene(source, max_steps=None):
    """A Scene from a path (str or os.PathLike ending in .json or naming a
    file), JSON text (a str starting with '{') or a dict."""
    if isinstance(source, Scene):
        return source
    if isinstance(source, dict):
        return Scene.from_dict(source, max_steps)
    if isinstance(source, str) and source.lstrip().startswith("{"):
        return Scene.from_json(source, max_steps)
    return Scene.from_file(source, max_steps)
