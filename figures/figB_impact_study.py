"""Beyond Paper B: an impact study of its two-scale contact, maps of the cells
(impact angle x speed), one panel per friction, run mode and quantity.

Rows: for each run mode in cells.csv (the subdivision column and the
touch_impact column: 'paper' is Eq. 4, 'coulomb' the option beyond the
paper), first the normal restitution e of the block-average velocities,
then the tangential impulse against the rigid-body stick/slide law,
(J_t - J_t,law) / J_n. Each cell is labelled with the per-cell criteria it
fails: P pass-through, E kinetic energy grows, S no separation, L touch loss
above Eq. 5, T run loss above the blocks' Eq. 5, C Coulomb |J_t| > mu J_n,
R off the rigid law; a stopped run is grey with 'stop'. The modes are read
from the data, never assumed.

usage: figB_impact_study.py DATA_DIR OUT_PNG   (DATA_DIR from B_9_impact_study)
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdem_common import plt, save_atomic  # noqa: E402
import numpy as np  # noqa: E402

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
path = os.path.join(sys.argv[1], "cells.csv")
with open(path, newline="") as f:
    rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
if not rows:
    raise SystemExit(f"{path}: no cells")

LETTERS = [("ok_pass_through", "P"), ("ok_energy", "E"), ("ok_separation", "S"), ("ok_touch_loss", "L"),
           ("ok_total_loss", "T"), ("ok_coulomb", "C"), ("ok_rigid_law", "R")]
angles = sorted({float(r["angle_deg"]) for r in rows})
speeds = sorted({float(r["speed"]) for r in rows})
mus = sorted({float(r["mu"]) for r in rows})
# The run modes present, in the order they first appear in the file.
modes = list(dict.fromkeys((r["subdivision"], r.get("touch_impact", "paper")) for r in rows))
# Words for the subdivision values the impact-study driver writes; any other value is shown as written.
SUBDIVISION_WORDS = {"off": "no subdivision", "on": "in-place refinement (option)", "sub-model": "sub-model"}
TOUCH_WORDS = {"paper": "touch by Eq. 4 (paper)", "coulomb": "Coulomb touch (option)"}


def mode_name(mode):
    sub, touch = mode
    return "%s; %s" % (SUBDIVISION_WORDS.get(sub, "subdivision '%s'" % sub), TOUCH_WORDS.get(touch, "touch '%s'" % touch))


def value(r, key):
    """A finished cell's number (a stopped cell's fields are not data)."""
    if r["outcome"] != "ok" or r[key] == "":
        return np.nan
    v = float(r[key])
    if not np.isfinite(v):
        raise SystemExit(f"{path}: non-finite {key}")
    return v


def grid(mode, mu, f):
    z = np.full((len(speeds), len(angles)), np.nan)
    lab = [["" for _ in angles] for _ in speeds]
    for r in rows:
        if (r["subdivision"], r.get("touch_impact", "paper")) != mode or float(r["mu"]) != mu:
            continue
        i, j = speeds.index(float(r["speed"])), angles.index(float(r["angle_deg"]))
        z[i, j] = f(r)
        lab[i][j] = "stop" if r["outcome"] != "ok" else "".join(c for k, c in LETTERS if r[k] != "y")
    return z, lab


def tangential(r):
    jn = value(r, "jn")
    return (value(r, "jt") - value(r, "jt_law")) / jn if jn > 0 else np.nan


panels = [("restitution e", lambda r: value(r, "restitution"), "viridis", (0.4, 0.85)),
          ("(J_t - J_t,law) / J_n", tangential, "RdBu_r", (-1.0, 1.0))]
fig, axes = plt.subplots(2 * len(modes), len(mus), figsize=(4.6 * len(mus), 3.3 * 2 * len(modes)),
                         layout="constrained", squeeze=False)
for p, (name, f, cmap, (lo, hi)) in enumerate(panels):
    for s, mode in enumerate(modes):
        row = len(modes) * p + s
        for c, mu in enumerate(mus):
            ax = axes[row, c]
            z, lab = grid(mode, mu, f)
            cm = plt.get_cmap(cmap).copy()
            cm.set_bad("0.75")
            im = ax.imshow(np.clip(z, lo, hi), origin="lower", cmap=cm, vmin=lo, vmax=hi, aspect="auto")
            for i in range(len(speeds)):
                for j in range(len(angles)):
                    txt = lab[i][j]
                    if p == 0 and txt != "stop" and np.isfinite(z[i, j]):
                        txt = f"{z[i, j]:.2f}" + ("\n" + txt if txt else "")
                    elif p == 1 and txt != "stop" and np.isfinite(z[i, j]):
                        txt = f"{z[i, j]:+.2f}" + ("\n" + txt if txt else "")
                    ax.text(j, i, txt, ha="center", va="center", fontsize=6.5,
                            color="k" if txt == "stop" or (p == 1 and abs(z[i, j]) < 0.6) else "w")
            ax.set_xticks(range(len(angles)), [f"{a:g}" for a in angles])
            ax.set_yticks(range(len(speeds)), [f"{v:g}" for v in speeds])
            ax.set_xlabel("impact angle from the contact normal (deg)")
            ax.set_ylabel("impact speed (m/s)")
            ax.set_title(f"{name}, mu = {mu:g}\n{mode_name(mode)}", fontsize=8.5)
        fig.colorbar(im, ax=axes[row, :], shrink=0.85, label=name)
n_fail = sum(any(r[k] != "y" for k, _ in LETTERS) for r in rows)
fig.suptitle(f"Beyond Paper B: impact study of its two-scale contact, two 1 m squares (Paper B's material),\n"
             f"{len(rows)} cells in {len(modes)} run modes (subdivision; touch), {n_fail} failing at least one criterion; "
             "the paper gives no values for these impacts\n"
             "letters: the criteria a cell fails (P pass-through, E energy grows, S no separation, L touch loss > Eq. 5,\n"
             "T loss > blocks' Eq. 5, C |J_t| > mu J_n, R off the rigid law); grey: run stopped", fontsize=10)
save_atomic(fig, sys.argv[2])
