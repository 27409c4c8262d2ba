"""Paper B Figs. 13-15: the two prisms before, at and after the touch, with the
refined contact patch, elements coloured by x-velocity (elastic wave).

usage: figB13_15_prisms.py DATA_DIR OUT_PNG   (DATA_DIR from B_6_two_prisms)
"""
import os
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdem_common import plt, read_table, save_atomic  # noqa: E402
import matplotlib.colors  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
notes, s = read_table(os.path.join(sys.argv[1], "snapshots.csv"), text=("label",))
_, c = read_table(os.path.join(sys.argv[1], "clones.csv"), text=("label",))

ids = sorted(set(int(v) for v in s["snapshot"]), key=lambda i: float(s["time"][s["snapshot"] == i][0]))
norm = matplotlib.colors.Normalize(vmin=0.0, vmax=3.6)
cmap = plt.get_cmap("turbo")

def label(sid):
    return s["label"][s["snapshot"] == sid][0]


full = [i for i in ids if label(i).startswith("Fig. 13") or "15b" in label(i)]
zoom = [i for i in ids if i not in full]
fig = plt.figure(figsize=(3.4 * max(len(zoom), 4), 8.3), layout="constrained")
fig.get_layout_engine().set(rect=(0.0, 0.04, 1.0, 0.96))  # room for the note below
top, bottom = fig.subfigures(2, 1, height_ratios=[1.0, 1.25])
ax_top = top.subplots(1, len(full))
ax_bot = bottom.subplots(1, len(zoom))


def draw(ax, sid, window=None):
    m = s["snapshot"] == sid
    tris = np.stack([np.column_stack([s[f"x{k}"][m], s[f"y{k}"][m]]) for k in range(3)], axis=1)
    fine = s["fine"][m] > 0.5
    vx = s["vx"][m]
    coarse_pc = PolyCollection(tris[~fine], array=vx[~fine], cmap=cmap, norm=norm, edgecolors="k", linewidths=0.8)
    fine_pc = PolyCollection(tris[fine], array=vx[fine], cmap=cmap, norm=norm, edgecolors="0.25", linewidths=0.25)
    ax.add_collection(coarse_pc)
    ax.add_collection(fine_pc)
    cm = c["snapshot"] == sid
    if np.any(cm):
        ax.plot(c["x"][cm], c["y"][cm], "o", ms=7, mfc="none", mec="magenta", mew=1.8, label="clone node")
        ax.legend(loc="lower right", fontsize=7)
    if window is None:
        ax.set_xlim(tris[..., 0].min() - 0.3, tris[..., 0].max() + 0.3)
        ax.set_ylim(tris[..., 1].min() - 0.3, tris[..., 1].max() + 0.3)
    else:
        ax.set_xlim(*window[0])
        ax.set_ylim(*window[1])
    ax.set_aspect("equal")
    ax.set_title(f"{s['label'][m][0]}\n{np.count_nonzero(fine)} patch elements", fontsize=9)
    ax.tick_params(labelsize=7)
    return coarse_pc


pc = None
for k, sid in enumerate(full):
    pc = draw(ax_top[k], sid)
for k, sid in enumerate(zoom):
    pc = draw(ax_bot[k], sid, window=((-0.3, 4.7), (-3.8, 3.8)))
cb = fig.colorbar(pc, ax=list(ax_bot), shrink=0.8, pad=0.01)
cb.set_label("element mean x-velocity (m/s)")
note = next((n for n in notes if "rebuilt" in n), "")
top.suptitle("Paper B Figs. 13-15: two prisms, clone node and local subdivision (top: whole blocks; "
             "bottom: contact zone of block j, moving with it)", fontsize=11)
fig.text(0.01, 0.005, textwrap.fill("Note: " + note + ". Thin lines: the refined patch (k x k sub-elements within c dt2 "
                                    "of the contact point), integrated with dt/n; deformations are too small to see "
                                    "at this scale, the colours show the elastic wave.", 180),
         fontsize=7, color="0.3", va="bottom")
save_atomic(fig, sys.argv[2])
