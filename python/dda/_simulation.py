"""A simulation of a scene: Paper A's DDA blocks with the potential-based
penalty contact (dda.Simulation), or Paper B's two-scale contact on
CST-meshed blocks (dda.CdemSimulation), as the scene's "model" says."""
import copy

from . import _core
from ._errors import SceneError
from ._scene import Scene, load_scene

__all__ = ["Simulation", "CdemSimulation"]


def _unpickle(cls, document, threads, state):
    """A pickled simulation back: its scene from the document, its state restored."""
    sim = cls.__new__(cls)
    sim._build(Scene._from_document(*document), None, threads, document)
    sim._restore_state(state)
    return sim


class _Copyable:
    """copy.copy, copy.deepcopy and pickle of a simulation: a new simulation
    of the same scene given the full state of this one (_save_state, the
    library's save_state: the checkpoint's bytes). It continues with the
    same bits as this one would."""

    def _copy(self, scene):
        state = self._save_state()  # first: RuntimeError while another thread steps
        new = type(self).__new__(type(self))
        new._build(scene, self.scene_file, self.threads, self._document)
        new._restore_state(state)
        return new

    def __copy__(self):
        """A simulation with this one's state and the same dda.Scene object."""
        return self._copy(self.scene)

    def __deepcopy__(self, memo):
        """A simulation with this one's state and a copy of its dda.Scene."""
        return self._copy(copy.deepcopy(self.scene, memo))

    def __reduce__(self):
        # The scene document as the simulation was made of it, the state bytes, the threads.
        return _unpickle, (type(self), self._document, self.threads, self._save_state())


class _Stepped(_Copyable):
    """What both simulations share on the Python side: their construction
    from a scene, run(), copy and pickle."""

    def _build(self, scene, scene_file, threads, document):
        """Builds the C++ model of scene_file (None: the scene's); document: what a pickle keeps."""
        self.__dict__.pop("_loaded", None)
        try:
            if scene_file is None:
                scene_file = scene.scene_file
            self._core_class.__init__(self, scene_file, threads, scene._source)
        except _core.RawSceneError as e:
            raise SceneError.from_library(str(e), scene._source, positions=False) from None
        self.scene = scene
        self._document = document

    def run(self, until=None, every=1, callback=None):
        """Steps until time + dt/2 >= until (default: the scene's duration),
        as `dda run` does. callback(sim), if given, is called after every
        step whose count is a multiple of `every`, and after the last step.
        Returns the number of steps taken."""
        if until is None:
            until = self.scene_file.duration
        return self._run(float(until), int(every), callback)


class Simulation(_Stepped, _core.Simulation):
    """Explicit DDA of a scene, stepped from Python (Paper A's model; for a
    scene whose "model" is "cdem", dda.Simulation(scene) gives a
    dda.CdemSimulation, Paper B's model).

        sim = dda.Simulation(scene, threads=1)
        sim.step()                     # one step
        sim.step(100)                  # 100 steps
        sim.run(until=2.0, every=50, callback=lambda s: print(s.time))

    scene: a dda.Scene, or what dda.load_scene takes (a path, JSON text, a dict).
    threads: threads of each step (results are bit-identical for any count).

    Stepping releases the GIL; Ctrl-C stops a long step(n) or run() between
    two steps (KeyboardInterrupt) and leaves the simulation usable. A guard
    that stops the run raises dda.SimulationError (reason, step, time,
    block, pair).

    copy.copy(sim), copy.deepcopy(sim) and pickle give a simulation with
    the full state of this one (blocks, contact and friction history, the
    guards' and the energy budget's accumulators, the clock): it continues
    with the same bits. A pickle holds the scene document, the state bytes
    and the thread count. copy.copy shares the dda.Scene object,
    copy.deepcopy copies it.

    State (one row per polygon: the scene's blocks, then one per boundary
    segment). These properties return COPIES, the caller's to keep:
      centroids (n, 2), velocities (n, 2), spins (n,), rotations (n,),
      velocity_dofs (n, 6), displacements (n, 6), stresses (n, 3),
      masses, areas, potential_lengths, fixed (n,), momentum (2,),
      vertices (V, 2) with vertex_offsets (n + 1,), polygon(i) (m, 2),
      energy() (dda.Energy), contacts() (dda.Contacts).
    These methods return READ-ONLY VIEWS of the state, without a copy: they
    show the current step's values and change in place at the next step:
      velocity_dofs_view(), displacements_view(), stresses_view().
    """

    def __new__(cls, scene=None, threads=1):
        # A scene of Paper B's model gives a dda.CdemSimulation.
        if cls is Simulation and scene is not None:
            scene = load_scene(scene)
            if scene.scene_file.model == "cdem":
                return CdemSimulation(scene, threads)
        sim = super().__new__(cls)
        sim._loaded = scene  # the scene read once, for __init__
        return sim

    def __init__(self, scene, threads=1):
        scene = self.__dict__.pop("_loaded", None) or load_scene(scene)
        self._build(scene, scene.scene_file, threads, scene._document())

    _core_class = _core.Simulation

    def __repr__(self):
        return (f"dda.Simulation({self.block_count} polygons, t = {self.time:g} s, step {self.step_count}, "
                f"dt = {self.dt:g} s)")


class CdemSimulation(_Stepped, _core.CdemSimulation):
    """Paper B's model of a scene whose "model" is "cdem": blocks meshed
    into constant-strain triangles, the two-scale contact (two time stages,
    clone nodes, local subdivision), stepped from Python.

        sim = dda.Simulation("repro/scenes/two_prisms.json")   # a dda.CdemSimulation
        sim.run(until=0.4)
        print(sim.time, sim.positions, sim.energy(), sim.energy_account()["touch_loss"])

    dda.Simulation(scene) makes one for such a scene (and dda.CdemSimulation(scene)
    does directly). It steps on one thread (threads must be 1). step(n),
    run(until, every, callback), time, step_count, dt, the GIL, Ctrl-C and
    other threads as dda.Simulation; a guard or a contact that cannot be
    resolved raises dda.SimulationError (ContactError's node and depth as
    attributes node, depth). copy.copy, copy.deepcopy and pickle hold the
    full state (nodes, mesh, clones, sub-models or patches, the energy
    ledger, the touch log, the clock: Model::save_state) and continue with
    the same bits, as for dda.Simulation.

    State, COPIES:
      per block: positions (n, 2) mass-weighted mean node position,
        velocities (n, 2) momentum / mass, displacements (n, 2), masses (n,),
        outline(b) (m, 2);
      per node: node_positions, node_velocities (N, 2), node_masses,
        node_blocks, node_kinds (N,) (every node ever made; "dead" ones
        were removed with their refinement);
      per element: elements(block=-1) (m, 3) node indices of the active
        triangles, element_blocks(), element_stresses(block=-1) (m, 3);
      contact: clones(), touches(), separations(), slips(), submodels()
        (dicts of columns), contact_count, live_submodels;
      energy() (dda.Energy: dissipated = the touch, refinement and deletion
        losses), energy_account() (dict), momentum (2,),
        timeseries_row(tracked) (with dda.timeseries_header(tracked, rotation=False)).
    """

    def __init__(self, scene, threads=1):
        scene = load_scene(scene)
        self._build(scene, scene.scene_file, threads, scene._document())

    _core_class = _core.CdemSimulation

    def __repr__(self):
        return (f"dda.CdemSimulation({self.block_count} blocks, {self.node_count} nodes, t = {self.time:g} s, "
                f"step {self.step_count}, dt = {self.dt:g} s)")
