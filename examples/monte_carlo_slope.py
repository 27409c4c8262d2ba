#!/usr/bin/env python3
"""Monte Carlo of a jointed rock slope: how likely is a runout beyond a threshold?

A 6 m high rock slope with a 65 degree face stands on a flat floor against a
fixed back wall. Two persistent joint sets cut it into blocks:
  - a set dipping out of the face (toward the floor, +x): dip ~ Normal(35, 6)
    degrees, spacing ~ LogNormal(median 1.4 m, sigma 0.25);
  - a set dipping steeply into the slope: dip 100 degrees (80 toward -x),
    spacing ~ LogNormal(median 1.8 m, sigma 0.25).
Joints have a friction angle of 30 degrees, the blocks 35 degrees on the
floor. Where the first set dips steeper than its friction angle, the blocks
it daylights slide out onto the floor. Each realisation is run for 2 s of
simulated time (rigid blocks); its runout is how far the rock mass
reached beyond the toe (its furthest vertex). The study estimates the probability that
the runout exceeds a threshold, with a 95 % Wilson score interval, from N
realisations, and draws the runouts against the dips drawn.

This is an illustration of dda.sweep, not a slope design: the geometry,
distributions and friction angles are made up for it.

    PYTHONPATH=build/python /usr/bin/python3 examples/monte_carlo_slope.py --n 200 --out out/monte_carlo
    ... --scheduler tcp://host:8786   (the runs on a Dask cluster instead of local processes)

Writes <out>/realisations.csv (one row per realisation, failed runs with
their error) and <out>/runout.png, and prints the estimate.
"""
import argparse
import math
import os
import sys

import numpy as np

import dda

HEIGHT = 6.0           # m
FACE_DEG = 65.0        # face angle, degrees
BACK = -12.0           # x of the back wall, m (the toe is at x = 0)
JOINT_FRICTION = 30.0  # degrees
FLOOR_FRICTION = 35.0  # degrees
DURATION = 2.0         # s


def slope_scene(p, rng):
    """One realisation: the joint sets drawn from rng. Returns the scene and
    the values drawn (they go into the realisation's row)."""
    dip = float(rng.normal(35.0, 6.0))
    spacing_out = float(1.4 * math.exp(rng.normal(0.0, 0.25)))
    spacing_in = float(1.8 * math.exp(rng.normal(0.0, 0.25)))
    offset = float(rng.uniform(0.0, 1.0))  # where the sets' lines fall, as a fraction of their spacing
    s = dda.Scene(name="jointed_slope", dt_fraction=0.4, duration=p.get("duration", DURATION), gravity=(0.0, -9.81),
                  strains=False, broad_phase="sweep")
    s.material(density=2600, young=5e9, poisson=0.25, name="rock")
    crest = -HEIGHT / math.tan(math.radians(FACE_DEG))
    s.region([(BACK, 0.0), (0.0, 0.0), (crest, HEIGHT), (BACK, HEIGHT)],
             [dda.JointSet(dip, spacing_out, (0.0, offset * spacing_out)),
              dda.JointSet(100.0, spacing_in, (offset * spacing_in, 0.0))],
             min_area=0.3, material="rock", group=0, name="rock")
    s.boundary((BACK, HEIGHT + 2.0), (BACK, 0.0), depth=2.0, group=1)  # back wall, solid at x < BACK
    s.boundary((BACK - 1.0, 0.0), (40.0, 0.0), depth=2.0, group=1)     # floor, solid below
    s.contact(kn=2e9, kt=8e8, friction_deg=JOINT_FRICTION, friction_rules=[((0, 1), FLOOR_FRICTION)])
    return s, {"dip_deg": dip, "spacing_out": spacing_out, "spacing_in": spacing_in}


def runout(sim, p):
    """How far the rock mass reached beyond the toe (x = 0): its furthest
    vertex, m (0 at t = 0); and how many blocks' centroids passed the toe."""
    n = sim.scene_block_count
    x = sim.vertices[:sim.vertex_offsets[n], 0]
    return {"runout": float(max(0.0, x.max())), "blocks_out": int((sim.centroids[:n, 0] > 0.0).sum()),
            "blocks": int(n)}


def wilson(k, n, z=1.959963984540054):
    """95 % Wilson score interval of a binomial proportion k / n."""
    if n == 0:
        return math.nan, math.nan
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, centre - half), min(1.0, centre + half)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=200, help="realisations (default 200)")
    ap.add_argument("--threshold", type=float, default=1.0, help="runout threshold, m (default 1)")
    ap.add_argument("--duration", type=float, default=DURATION, help="simulated time per realisation, s")
    ap.add_argument("--out", default="out/monte_carlo", help="output directory")
    ap.add_argument("--workers", type=int, default=None, help="local worker processes (default: the CPU count)")
    ap.add_argument("--scheduler", default=None, help="a Dask scheduler address instead of local processes")
    a = ap.parse_args(argv)

    params = [{"study": "jointed_slope", "realisation": i, "duration": a.duration} for i in range(a.n)]
    table = dda.sweep(slope_scene, params, runout, workers=a.workers, scheduler=a.scheduler)
    os.makedirs(a.out, exist_ok=True)
    table.to_csv(os.path.join(a.out, "realisations.csv"))

    ok = [r for r in table if r["error"] is None]
    k = sum(r["runout"] > a.threshold for r in ok)
    lo, hi = wilson(k, len(ok))
    print(f"{len(table)} realisations, {len(ok)} ran to t = {a.duration:g} s, {len(table) - len(ok)} stopped "
          f"by a guard or failed (left out of the estimate)")
    for r in table.failed:
        print(f"  realisation {r['realisation']}: {r['error'][:160]}")
    runouts = np.array([r["runout"] for r in ok])
    if len(ok):
        print(f"runout: median {np.median(runouts):.2f} m, max {runouts.max():.2f} m; "
              f"blocks per slope {min(r['blocks'] for r in ok)}-{max(r['blocks'] for r in ok)}")
    print(f"P(runout > {a.threshold:g} m) = {k}/{len(ok)} = {k / max(1, len(ok)):.3f}, "
          f"95 % Wilson interval [{lo:.3f}, {hi:.3f}]")
    print(f"wall time per realisation: median {np.median([r['wall_s'] for r in ok]):.2f} s" if ok else "")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    dips = np.array([r["dip_deg"] for r in ok])
    exceed = runouts > a.threshold
    ax1.scatter(dips[~exceed], runouts[~exceed], s=14, label=f"runout <= {a.threshold:g} m")
    ax1.scatter(dips[exceed], runouts[exceed], s=14, color="C3", label=f"runout > {a.threshold:g} m")
    ax1.axhline(a.threshold, color="k", lw=0.8, ls="--")
    ax1.axvline(JOINT_FRICTION, color="grey", lw=0.8, ls=":", label="joint friction angle")
    ax1.set_xlabel("dip of the out-of-face joint set, deg")
    ax1.set_ylabel("runout beyond the toe, m")
    ax1.legend(fontsize=8)
    ax2.hist(runouts, bins=max(5, int(math.sqrt(max(1, len(ok))))), color="C0")
    ax2.axvline(a.threshold, color="k", lw=0.8, ls="--")
    ax2.set_xlabel("runout beyond the toe, m")
    ax2.set_ylabel("realisations")
    ax2.set_title(f"P(runout > {a.threshold:g} m) = {k / max(1, len(ok)):.2f} [{lo:.2f}, {hi:.2f}] (95 %)",
                  fontsize=9)
    fig.tight_layout()
    png = os.path.join(a.out, "runout.png")
    fig.savefig(png + ".tmp.png", dpi=120)
    os.replace(png + ".tmp.png", png)
    print(f"wrote {os.path.join(a.out, 'realisations.csv')} and {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
