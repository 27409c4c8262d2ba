"""Penetration map (S3): what happens to two squares that meet too hard.

usage: figS3_penetration_map.py DATA_DIR OUT_PNG
  DATA_DIR from the penetration_map driver: cells.csv.

Three panels (head on, speed against kn; 30 deg oblique, speed against kn;
head on, speed against dt): each cell coloured by its class with the guards
on (bounced, stopped by the penetration guard, stopped by another guard,
passed through, stuck) and crossed where the same impact without the
penetration guard passes the blocks through each other. The map's row
fails on any 'passed' or 'stuck' cell with the guards on. The star marks
Paper A Sect. 4.1's own impact (1 m/s, kn 10 MPa, dt 1e-4 s, Table 4).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_common as paper  # noqa: E402
from potential_common import finite as f, plt, read_rows, save_atomic  # noqa: E402

CLASSES = [("bounced", "tab:green"), ("guard stop", "tab:blue"), ("other stop", "tab:orange"),
           ("passed", "tab:red"), ("stuck", "tab:purple"), ("missed", "tab:gray")]
MAPS = [("head on, v-kn", "kn", "normal penalty kn (Pa)", "head on, dt = 1e-4 s"),
        ("oblique, v-kn", "kn", "normal penalty kn (Pa)", "30 deg oblique, dt = 1e-4 s"),
        ("head on, v-dt", "dt", "time step dt (s)", "head on, kn = 1e5 Pa")]
FAILING = ("passed", "stuck")  # classes the row counts as failures with the guards on


def main(argv):
    if len(argv) != 3:
        raise SystemExit(__doc__)
    rows = read_rows(os.path.join(argv[1], "cells.csv"))
    fig, axes = plt.subplots(1, 3, figsize=(17, 6.4))
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
        if name == "head on, v-kn" and paper.A_41_KN in xs and paper.A_41_SPEED in ys:
            ax.plot(xs.index(paper.A_41_KN), ys.index(paper.A_41_SPEED), "*", ms=18, mfc="gold", mec="k", zorder=5)
        ax.set_xlim(-0.5, len(xs) - 0.5)
        ax.set_ylim(-0.5, len(ys) - 0.5)
        ax.set_xticks(range(len(xs)), [f"{x:.0e}".replace("e+0", "e").replace("e-0", "e-") for x in xs])
        ax.set_yticks(range(len(ys)), [f"{y:g}" for y in ys])
        ax.set_xlabel(label)
        ax.set_ylabel("impact speed (m/s)")
        ax.set_title("ours: " + title)
    handles = [plt.Rectangle((0, 0), 1, 1, color=c, alpha=0.75) for _, c in CLASSES]
    handles.append(plt.Line2D([], [], color="k", marker="x", ls="", ms=10, mew=2))
    handles.append(plt.Line2D([], [], marker="*", ls="", ms=14, mfc="gold", mec="k"))
    fig.legend(handles, [f"guards on: {n}" + (" (fails the row)" if n in FAILING else "") for n, _ in CLASSES] +
               ["without the penetration guard: passed through", "paper A Sect. 4.1's impact (1 m/s, kn 10 MPa)"],
               loc="lower center", ncol=4, frameon=False)
    fig.suptitle("Beyond the papers: two 1 m squares (Paper A Sect. 4.1 material) meeting too hard, each cell with "
                 "the guards on (colour) and the penetration guard off (cross)\nthe row passes when no cell passes "
                 "through or ends stuck with the guards on")
    fig.tight_layout(rect=(0, 0.1, 1, 0.93))
    save_atomic(fig, argv[2])


if __name__ == "__main__":
    main(sys.argv)
