"""What a worker process does with a pickled simulation in the copy tests (a
module of its own: spawned processes import it by name)."""


def step_and_send_back(sim, n):
    """Steps the simulation it was sent n more steps; returns it (pickled back)."""
    sim.step(n)
    return sim
