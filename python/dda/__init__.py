"""DDA of convex polygonal blocks from Python: the potential-based penalty
contact of Paper A, or the two-scale contact of Paper B (a scene's "model").

    import dda
    sim = dda.Simulation("repro/scenes/two_squares.json")
    sim.run(until=0.5)
    print(sim.time, sim.centroids[:2], sim.energy().total)

Scene          a scene from a file, JSON text or a dict, or built in Python
Simulation     a scene stepped from Python; state as numpy arrays; copy and
               pickle continue with the same bits
CdemSimulation Paper B's model (what Simulation gives for a "cdem" scene):
               nodes, elements, touches, the energy account
kernel         the contact kernel (overlap, intersection polygon, potential, normal force)
sweep          independent runs over parameters, on local processes or a Dask cluster
SceneError, SimulationError   the library's errors, with their fields
"""
from ._core import Contacts, Energy, timeseries_header, format_number
from ._errors import SceneError, SimulationError
from ._scene import JointSet, Scene, load_scene
from ._simulation import CdemSimulation, Simulation
from . import kernel
from ._sweep import SweepTable, sweep, seed_of

__all__ = ["Scene", "JointSet", "load_scene", "Simulation", "CdemSimulation", "Energy", "Contacts", "SceneError", "SimulationError",
           "kernel", "sweep", "SweepTable", "seed_of", "timeseries_header", "format_number"]
