#!/usr/bin/python3
"""Draws a `dda run` output directory into one PNG: the blocks at chosen times, the energy budget
over time and the number of contacts.

Reads DIR/run.json, DIR/timeseries.csv and DIR/snapshots.csv (and DIR/blocks.csv, if the run wrote
it, to colour the blocks by speed). The snapshot panels show the snapshots nearest the requested
times (`output.snapshots` of the scene decides which exist); each panel's title gives the time
drawn. Fixed blocks are grey, boundary polygons hatched.

Usage:
  plot_run.py DIR [--times T [T ...]] [--out PNG] [--title TEXT]
    --times  snapshot times to draw, s (default: up to 4 snapshots spread over the run)
    --out    the PNG (default DIR/run.png)
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import np, plt, save_atomic  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
import matplotlib.colors  # noqa: E402


def read_table(path):
    """{column: float array} of a CSV file with a header line; None if the file has no rows."""
    with open(path) as f:
        header = f.readline().strip().split(",")
        data = np.loadtxt(f, delimiter=",", ndmin=2)
    if data.size == 0:
        return None
    if not np.all(np.isfinite(data)):
        raise SystemExit(f"{path}: non-finite values")
    return {name: data[:, i] for i, name in enumerate(header)}


def snapshot_polygons(snap, t):
    """[(block, N x 2 vertices)] of the snapshot at time t."""
    rows = np.flatnonzero(snap["time"] == t)
    blocks = snap["block"][rows].astype(int)
    xy = np.column_stack([snap["x"][rows], snap["y"][rows]])
    cuts = np.flatnonzero(np.r_[True, blocks[1:] != blocks[:-1]])
    return list(zip(blocks[cuts], np.split(xy, cuts[1:])))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir")
    ap.add_argument("--times", type=float, nargs="+")
    ap.add_argument("--out")
    ap.add_argument("--title")
    a = ap.parse_args()
    d = a.dir
    with open(os.path.join(d, "run.json")) as f:
        run = json.load(f)
    ts = read_table(os.path.join(d, "timeseries.csv"))
    if ts is None:
        raise SystemExit(f"{d}/timeseries.csv: no rows")
    snap = read_table(os.path.join(d, "snapshots.csv"))
    table = read_table(os.path.join(d, "blocks.csv")) if os.path.exists(os.path.join(d, "blocks.csv")) else None
    kinds = {b["index"]: ("boundary" if b["kind"] == "boundary" else "fixed" if b["fixed"] else "free")
             for b in run["blocks"]}

    snap_times = np.unique(snap["time"]) if snap is not None else np.array([])
    if a.times:
        if snap_times.size == 0:
            raise SystemExit(f"{d}/snapshots.csv: no snapshots to draw")
        shown = []
        for t in a.times:
            near = float(snap_times[np.argmin(np.abs(snap_times - t))])
            if abs(near - t) > 0.5 * run["dt"]:
                print(f"plot_run: no snapshot at t = {t} s; drawing the nearest, t = {near:g} s "
                      f"(snapshot times: {', '.join(f'{x:g}' for x in snap_times)})", file=sys.stderr)
            if near not in shown:
                shown.append(near)
    else:
        pick = np.unique(np.linspace(0, snap_times.size - 1, min(4, snap_times.size)).round().astype(int))
        shown = [float(snap_times[i]) for i in pick]

    # Speed colour scale over the blocks drawn (blocks.csv), else one colour.
    speed_at = {}
    if table is not None:
        for t in shown:
            rows = np.flatnonzero(table["time"] == t)
            if rows.size:
                speed_at[t] = dict(zip(table["block"][rows].astype(int),
                                       np.hypot(table["vx"][rows], table["vy"][rows])))
    vmax = max([max(s.values()) for s in speed_at.values() if s] + [0.0])
    norm = matplotlib.colors.Normalize(0.0, vmax if vmax > 0 else 1.0)

    n = max(1, len(shown))
    # Shared limits: every polygon of every drawn snapshot.
    allxy = np.concatenate([p for t in shown for _, p in snapshot_polygons(snap, t)]) if shown else np.zeros((1, 2))
    lo, hi = allxy.min(axis=0), allxy.max(axis=0)
    pad = 0.03 * max(max(hi - lo), 1e-9)
    # The panels' height follows the scene's aspect ratio (within limits).
    width = max(10.0, 3.4 * n)
    aspect = (hi[1] - lo[1] + 2 * pad) / (hi[0] - lo[0] + 2 * pad)
    top = float(np.clip(0.85 * width / n * aspect, 1.6, 6.0))
    fig = plt.figure(figsize=(width, top + 4.2))
    grid = fig.add_gridspec(2, n, height_ratios=[top + 0.6, 3.0], hspace=0.3, wspace=0.25,
                            top=1 - 0.55 / (top + 4.2), bottom=0.45 / (top + 4.2), left=0.06, right=0.94)
    last_pc = None
    for k, t in enumerate(shown):
        ax = fig.add_subplot(grid[0, k])
        polys = snapshot_polygons(snap, t)
        free = [(b, p) for b, p in polys if kinds.get(b) == "free"]
        fixed = [p for b, p in polys if kinds.get(b) == "fixed"]
        bound = [p for b, p in polys if kinds.get(b) == "boundary"]
        if bound:
            ax.add_collection(PolyCollection(bound, facecolors="0.9", edgecolors="0.4", hatch="///", linewidths=0.5))
        if fixed:
            ax.add_collection(PolyCollection(fixed, facecolors="0.65", edgecolors="k", linewidths=0.4))
        if free:
            if t in speed_at:
                pc = PolyCollection([p for _, p in free], array=np.array([speed_at[t][b] for b, _ in free]),
                                    cmap="viridis", norm=norm, edgecolors="k", linewidths=0.4)
                last_pc = pc
            else:
                pc = PolyCollection([p for _, p in free], facecolors="#d9b38c", edgecolors="k", linewidths=0.4)
            ax.add_collection(pc)
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
        ax.set_aspect("equal")
        ax.set_title(f"t = {t:g} s", fontsize=10)
        ax.tick_params(labelsize=7)
        if k == 0:
            ax.set_ylabel("y (m)", fontsize=8)
        ax.set_xlabel("x (m)", fontsize=8)
    if last_pc is not None:
        cb = fig.colorbar(last_pc, ax=fig.axes[:len(shown)], shrink=0.8, pad=0.01)
        cb.set_label("speed (m/s)", fontsize=8)
        cb.ax.tick_params(labelsize=7)

    t = ts["time"]
    ax = fig.add_subplot(grid[1, : max(1, n - 1)] if n > 1 else grid[1, 0])
    e0 = ts["E_total"][0]
    curves = [("E_kinetic", "kinetic"), ("E_strain", "strain"), ("E_contact", "contact"),
              ("E_friction_spring", "friction springs"), ("E_dissipated", "dissipated")]
    for col, label in curves:
        ax.plot(t, ts[col], lw=1.2, label=label)
    g = ts["E_gravity"] - ts["E_gravity"][0]
    if np.any(g != 0):
        ax.plot(t, g, lw=1.2, label="gravity (from t = 0)")
    ax.plot(t, ts["E_balance_error"], "k--", lw=1.0, label="balance error")
    ax.axhline(0.0, color="0.6", lw=0.5)
    ax.set_xlabel("t (s)", fontsize=8)
    ax.set_ylabel("energy (J/m)", fontsize=8)
    err = np.max(np.abs(ts["E_balance_error"]))
    scale = max(np.max(np.abs(ts[c])) for c, _ in curves) or 1.0
    ax.set_title(f"energy budget: E_total(0) = {e0:.4g} J/m, largest |balance error| = {err:.3g} J/m "
                 f"({100 * err / scale:.2g} % of the largest term)", fontsize=9)
    ax.legend(fontsize=7, ncol=2)
    ax.tick_params(labelsize=7)
    if n > 1:
        ax2 = fig.add_subplot(grid[1, n - 1])
    else:
        ax2 = ax.twinx()
    ax2.step(t, ts["contacts"], where="post", color="C3", lw=1.0)
    ax2.set_xlabel("t (s)", fontsize=8)
    ax2.set_ylabel("contacts", fontsize=8)
    ax2.set_title("contacts", fontsize=9)
    ax2.tick_params(labelsize=7)
    ax2.yaxis.get_major_locator().set_params(integer=True)

    title = a.title or (f"{run.get('name') or os.path.basename(run['scene'])}: {run['status']}, "
                        f"{run['steps']} steps of {run['dt']:g} s to t = {run['time']:g} s, "
                        f"{sum(1 for b in run['blocks'] if b['kind'] == 'block')} blocks")
    fig.suptitle(title, fontsize=11)
    out = a.out or os.path.join(d, "run.png")
    save_atomic(fig, out)
    print(f"plot_run: wrote {out} (snapshots at t = {', '.join(f'{x:g}' for x in shown)} s)")


if __name__ == "__main__":
    main()
