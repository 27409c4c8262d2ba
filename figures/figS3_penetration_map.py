"""Penetration map (S3): what happens to two squares that meet too hard.

usage: figS3_penetration_map.py DATA_DIR OUT_PNG
  DATA_DIR from the penetration_map driver: cells.csv.

Three panels (head on, speed against kn; 30 deg oblique, speed against kn;
head on, speed against dt): each cell coloured by its class with the guards
on (bounced, stopped by the penetration guard, stopped by another guard,
passed through, stuck) and crossed where the same impact without the
penetration guard passes the blocks through each other.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import finite as f, plt, read_rows, save_atomic  # noqa: E402

CLASSES = [("bounced", "tab:green"), ("guard stop", "tab:blue"), ("other stop", "tab:orange"),
           ("passed", "tab:red"), ("stuck", "tab:purple"), ("missed", "tab:gray")]
MAPS = [("head on, v-kn", "kn", "kn, Pa", "head on, dt = 1e-4 s"),
        ("oblique, v-kn", "kn", "kn, Pa", "30 deg oblique, dt = 1e-4 s"),
        ("head on, v-dt", "dt", "dt, s", "head on, kn = 1e5 Pa")]


def main(argv):
    if len(argv) != 3:
        raise SystemExit(__doc__)
    rows = read_rows(os.path.join(argv[1], "cells.csv"))
    fig, axes = plt.subplots(1, 3, figsize=(17, 5.6))
    colour = dict(CLASSES)
    for ax, (name, key, label, title) in zip(axes, MAPS):
        cells = [r for r in rows if r["map"] == name]
        if not cells:
            raise SystemExit(f"cells.csv: no rows for map {name!r}")
        xs = sorted({f(r[key]) for r in cells})
        ys = sorted({f(r["speed"]) for r in cells})
        for r in cells:
            i, j = xs.index(f(r[key])), ys.index(f(r["speed"]))
            if r["guarded"] not in colour:
                raise SystemExit(f"cells.csv: unknown class {r['guarded']!r}")
            ax.add_patch(plt.Rectangle((i - 0.5, j - 0.5), 1, 1, color=colour[r["guarded"]], alpha=0.75))
            if r["unguarded"] == "passed":
                ax.plot(i, j, "kx", ms=11, mew=2)
        ax.set_xlim(-0.5, len(xs) - 0.5)
        ax.set_ylim(-0.5, len(ys) - 0.5)
        ax.set_xticks(range(len(xs)), [f"{x:g}" for x in xs])
        ax.set_yticks(range(len(ys)), [f"{y:g}" for y in ys])
        ax.set_xlabel(label)
        ax.set_ylabel("impact speed, m/s")
        ax.set_title(title)
    handles = [plt.Rectangle((0, 0), 1, 1, color=c, alpha=0.75) for _, c in CLASSES]
    handles.append(plt.Line2D([], [], color="k", marker="x", ls="", ms=10, mew=2))
    fig.legend(handles, [f"guards on: {n}" for n, _ in CLASSES] + ["without the penetration guard: passed through"],
               loc="lower center", ncol=6, frameon=False)
    fig.suptitle("Two 1 m squares (Sect. 4.1 material) meeting too hard: the penetration guard stops every "
                 "impact that would pass through")
    fig.tight_layout(rect=(0, 0.07, 1, 0.95))
    save_atomic(fig, argv[2])


if __name__ == "__main__":
    main(sys.argv)
