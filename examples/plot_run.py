"""Draw what `dda run SCENE --out DIR` wrote: the blocks at each snapshot
(DIR/snapshots.csv) and, from DIR/timeseries.csv, every tracked block's
centroid velocity and the energy budget against time.

usage: /usr/bin/python3 examples/plot_run.py DIR OUT.png

Columns: lib/io/SCHEMA.md ("Run output"). Needs matplotlib (Debian:
python3-matplotlib). The figure is written to OUT.png.tmp, then renamed.
"""
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{path}: no rows")
    return rows


def main(run_dir, out_png):
    series = read_csv(f"{run_dir}/timeseries.csv")
    shots = read_csv(f"{run_dir}/snapshots.csv")
    t = [float(r["time"]) for r in series]
    blocks = sorted({int(m.group(1)) for k in series[0] for m in [re.fullmatch(r"b(\d+)_vx", k)] if m})

    fig, (ax_shape, ax_v, ax_e) = plt.subplots(1, 3, figsize=(15, 4.5))
    polygons = {}
    for r in shots:  # (time, block) -> vertices, counter-clockwise
        polygons.setdefault((float(r["time"]), int(r["block"])), []).append((float(r["x"]), float(r["y"])))
    times = sorted({k[0] for k in polygons})
    for n, ts in enumerate(times):
        colour = plt.cm.viridis(n / max(1, len(times) - 1))
        for (tt, _), xy in polygons.items():
            if tt == ts:
                ax_shape.fill(*zip(*xy), facecolor="none", edgecolor=colour, lw=1)
        ax_shape.plot([], [], color=colour, label=f"t = {ts:g} s")
    ax_shape.set_aspect("equal")
    ax_shape.set_title("blocks at the snapshots")
    ax_shape.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.08), ncol=4)

    for b in blocks:
        ax_v.plot(t, [float(r[f"b{b}_vx"]) for r in series], label=f"block {b} vx")
        ax_v.plot(t, [float(r[f"b{b}_vy"]) for r in series], "--", label=f"block {b} vy")
    ax_v.set_xlabel("t (s)")
    ax_v.set_ylabel("centroid velocity (m/s)")
    ax_v.legend(fontsize=8)

    for col in ("E_kinetic", "E_strain", "E_contact", "E_total", "E_dissipated", "E_balance_error"):
        ax_e.plot(t, [float(r[col]) for r in series], label=col)
    ax_e.set_xlabel("t (s)")
    ax_e.set_ylabel("energy (J per m of thickness)")
    ax_e.legend(fontsize=8)

    fig.tight_layout()
    fig.savefig(out_png + ".tmp", dpi=100, format="png")
    os.replace(out_png + ".tmp", out_png)
    print(f"wrote {out_png}: {len(times)} snapshots, {len(series)} time-series rows, blocks {blocks}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
