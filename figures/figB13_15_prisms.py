"""Paper B Figs. 13-15: the two prisms before, at and after the touch, with the
refined contact patch, elements coloured by x-velocity (elastic wave).

usage: figB13_15_prisms.py DATA_DIR OUT_PNG   (DATA_DIR from B_6_two_prisms)

Each panel is one snapshot of snapshots.csv, labelled with the paper's
figure and time it stands for; the title names the subdivision mode the
file records. The geometry is reconstructed (Paper B Fig. 12 is lost).
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
fig = plt.figure(figsize=(3.4 * max(len(zoom), 4), 9.0), layout="constrained")
fig.get_layout_engine().set(rect=(0.0, 0.05, 1.0, 0.9))  # room for the title above and the note below
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
    if window is None:
        ax.set_xlim(tris[..., 0].min() - 0.3, tris[..., 0].max() + 0.3)
        ax.set_ylim(tris[..., 1].min() - 0.3, tris[..., 1].max() + 0.3)
    else:
        ax.set_xlim(*window[0])
        ax.set_ylim(*window[1])
    ax.set_aspect("equal")
    ax.set_title(f"{s['label'][m][0]}\n{np.count_nonzero(fine)} patch elements", fontsize=9)
    ax.set_xlabel("x (m)", fontsize=8)
    ax.set_ylabel("y (m)", fontsize=8)
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
mode = next((n.split(":", 1)[1].strip() for n in notes if n.startswith("subdivision mode:")), "mode not recorded")
fig.suptitle("Paper B Figs. 13-15: two prisms (i at 3.0 m/s onto j at rest), clone node and local subdivision, ours "
             "at the paper's times\nsubdivision mode: %s; top: whole blocks; bottom: contact zone of block j, moving "
             "with it (geometry reconstructed)" % mode, fontsize=10)
handles = [plt.Line2D([], [], marker="o", ls="", ms=7, mfc="none", mec="magenta", mew=1.8),
           plt.Line2D([], [], color="k", lw=0.8), plt.Line2D([], [], color="0.25", lw=0.25)]
fig.legend(handles, ["clone node (contact points joined)", "coarse CST elements", "refined patch sub-elements"],
           loc="lower right", bbox_to_anchor=(1.0, 0.0), fontsize=8, ncol=3)
fig.text(0.01, 0.005, textwrap.fill("Note: " + note + ". Thin lines: the refined patch (k x k sub-elements within c dt2 "
                                    "of the contact point), integrated with dt/n; deformations are too small to see "
                                    "at this scale, the colours show the elastic wave.", 180),
         fontsize=7, color="0.3", va="bottom")
save_atomic(fig, sys.argv[2])
