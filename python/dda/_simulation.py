"""A simulation of a scene (Paper A's DDA blocks with the potential contact)."""
from . import _core
from ._errors import SceneError
from ._scene import load_scene

__all__ = ["Simulation"]


class Simulation(_core.Simulation):
    """Explicit DDA of a scene, stepped from Python.

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

    def __init__(self, scene, threads=1):
        scene = load_scene(scene)
        scene_file = scene.scene_file
        try:
            super().__init__(scene_file, threads, scene._source)
        except _core.RawSceneError as e:
            raise SceneError.from_library(str(e), scene._source, positions=False) from None
        self.scene = scene

    def run(self, until=None, every=1, callback=None):
        """Steps until time + dt/2 >= until (default: the scene's duration),
        as `dda run` does. callback(sim), if given, is called after every
        step whose count is a multiple of `every`, and after the last step.
        Returns the number of steps taken."""
        if until is None:
            until = self.scene_file.duration
        return self._run(float(until), int(every), callback)

    def __repr__(self):
        return (f"dda.Simulation({self.block_count} polygons, t = {self.time:g} s, step {self.step_count}, "
                f"dt = {self.dt:g} s)")
