"""Animation (GIF) of one Sect. 6.1 collapse case: blocks coloured by speed.

usage: anim_collapse.py DATA_DIR CASE OUT_GIF   (DATA_DIR from the collapse driver, CASE: case1 or case2)

One frame per written time (every 0.1 s), 10 frames per second (real time).
Needs Pillow (Debian python3-pil, a dependency of python3-matplotlib).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blocks_common import Frames, draw_blocks, draw_boundaries, np, plt, read_boundaries  # noqa: E402
import matplotlib.animation  # noqa: E402
import matplotlib.colors  # noqa: E402

if len(sys.argv) != 4:
    raise SystemExit(__doc__)
data, case, out_gif = sys.argv[1:]
labels = {"case1": "case 1: joint friction 15 deg", "case2": "case 2: joint friction 30 deg"}
if case not in labels:
    raise SystemExit("CASE must be case1 or case2")
fr = Frames(os.path.join(data, case))
bounds = read_boundaries(os.path.join(data, "boundaries.csv"))
times = fr.times

# Fixed axes and colour scale over the whole run (both from this case).
xmax = max(max(p[:, 0].max() for p in fr.polygons(t)) for t in times)
xmax = max(xmax + 5.0, 40.0)
speeds = np.concatenate([fr.state(t, "speed") for t in times])
norm = matplotlib.colors.Normalize(0.0, max(float(np.percentile(speeds, 99)), 1e-3))

width = 4.0 + 8.0 * (xmax + 6.0) / 62.0
fig, ax = plt.subplots(figsize=(min(width, 16.0), 6.0))
draw_boundaries(ax, bounds, shade=2.0)
pc = draw_blocks(ax, fr.polygons(times[0]), fr.state(times[0], "speed"), norm, cmap="plasma", lw=0.25)
cb = fig.colorbar(pc, ax=ax, shrink=0.85)
cb.set_label("block speed (m/s)")
ax.set_xlim(-6.0, xmax)
ax.set_ylim(-3.0, 56.0)
ax.set_aspect("equal")
ax.set_xlabel("x (m)")
ax.set_ylabel("y (m)")
ax.add_patch(plt.Rectangle((0, 0), 0, 0, facecolor="0.85", edgecolor="0.2", hatch="///",
                           label="fixed boundary (solid side hatched)"))
ax.legend(fontsize=7, loc="upper right")
title = ax.set_title("\n", fontsize=9)
fig.tight_layout()


def update(k):
    t = times[k]
    pc.set_verts(fr.polygons(t))
    pc.set_array(fr.state(t, "speed"))
    title.set_text("Paper A Sect. 6.1: collapse of a jointed rock column, ours (geometry reconstructed, Fig. 19 lost)\n"
                   "%s, t = %.1f s; the paper shows t = 2.5, 5.0, 7.5 s (Fig. 20)" % (labels[case], t))
    return pc, title


anim = matplotlib.animation.FuncAnimation(fig, update, frames=len(times), blit=False)
os.makedirs(os.path.dirname(out_gif) or ".", exist_ok=True)
root, ext = os.path.splitext(out_gif)
tmp = root + ".tmp" + ext  # Pillow picks the format from the extension
anim.save(tmp, writer=matplotlib.animation.PillowWriter(fps=10), dpi=80)
plt.close(fig)
os.replace(tmp, out_gif)
