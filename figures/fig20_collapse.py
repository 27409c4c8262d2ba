"""Paper A Fig. 20: collapse of the jointed rock column (Sect. 6.1).

usage: fig20_collapse.py DATA_DIR OUT_PNG            (DATA_DIR from the collapse driver)
       fig20_collapse.py --runout DATA_DIR OUT_PNG

Default: the block system at 2.5, 5.0 and 7.5 s (rows) for case 1 (joint
friction 15 deg) and case 2 (30 deg) (columns), blocks coloured by speed on
one colour scale, as the paper's panels a-f (times beyond a shortened run are
left out). --runout: front position, mean centroid drop and runout mass
versus time for both cases, with crosses at the end for the reruns with the
blocks renumbered (renumbered.csv: the spread a round-off-level change gives).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blocks_common import Frames, draw_blocks, draw_boundaries, np, plt, read_boundaries, read_csv, save_atomic  # noqa: E402
import matplotlib.colors  # noqa: E402
import paper_common as paper  # noqa: E402
from paper_common import paper_style  # noqa: E402

# Paper A Sect. 6.1's statement on the two cases, drawn as text beside ours.
PAPER_SAYS = "paper (Sect. 6.1): 'a faster collapsing process and a larger runout mass ... with lower friction angle'"

args = sys.argv[1:]
runout = bool(args) and args[0] == "--runout"
if runout:
    args = args[1:]
if len(args) != 2:
    raise SystemExit(__doc__)
data, out_png = args
cases = [("case1", "case 1: joint friction 15 deg"), ("case2", "case 2: joint friction 30 deg")]


def runout_figure():
    fig, (a1, a2, a3) = plt.subplots(1, 3, figsize=(13, 4))
    renumbered_path = os.path.join(data, "renumbered.csv")
    renumbered = read_csv(renumbered_path)[1] if os.path.exists(renumbered_path) else None
    for k, (c, label) in enumerate(cases, start=1):
        _, s = read_csv(os.path.join(data, c, "series.csv"))
        line, = a1.plot(s["time"], s["front_x"], label="ours, " + label)
        a2.plot(s["time"], s["mean_drop"], label="ours, " + label)
        a3.plot(s["time"], 100.0 * s["runout_mass"], label="ours, " + label)
        if renumbered is not None:
            # The same case rerun with its blocks numbered by centroid x and
            # by centroid y: where a round-off-level change ends the run.
            mine = renumbered["case"] == k
            t_end = np.full(int(mine.sum()), s["time"][-1])
            first = k == 1
            a1.plot(t_end, renumbered["front_x_end"][mine], "x", color=line.get_color(), ms=7,
                    label="end, blocks renumbered (x, y) and as generated" if first else None)
            a2.plot(t_end, renumbered["mean_drop_end"][mine], "x", color=line.get_color(), ms=7)
            a3.plot(t_end, 100.0 * renumbered["runout_mass_end"][mine], "x", color=line.get_color(), ms=7)
    for k, t in enumerate(paper.A_61_TIMES):
        for a in (a1, a2, a3):
            a.axvline(t, **paper_style(lw=0.8, label="paper's snapshot times (Fig. 20)" if k == 0 else None))
    a1.set_ylabel("front: largest block x (m)")
    a2.set_ylabel("mass-weighted mean centroid drop (m)")
    a3.set_ylabel("runout mass: centroid beyond x = 20 m (%)")
    for a in (a1, a2, a3):
        a.set_xlabel("time (s)")
        a.grid(alpha=0.3)
    a1.legend(loc="upper left", fontsize=7.5)
    fig.suptitle("Paper A Sect. 6.1: collapse of a jointed rock column, front, mean drop and runout mass of the two "
                 "cases against time (geometry reconstructed, Fig. 19 lost)\n" + PAPER_SAYS, fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.92))
    save_atomic(fig, out_png)


if runout:
    runout_figure()
    sys.exit(0)

frames = {c: Frames(os.path.join(data, c)) for c, _ in cases}
bounds = read_boundaries(os.path.join(data, "boundaries.csv"))
t_end = min(f.times[-1] for f in frames.values())
times = [t for t in (2.5, 5.0, 7.5) if t <= t_end + 1e-9] or [t_end]

# One speed scale for every panel: the 99th percentile of all shown speeds.
speeds = np.concatenate([frames[c].state(t, "speed") for c, _ in cases for t in times])
vmax = max(float(np.percentile(speeds, 99)), 1e-3)
norm = matplotlib.colors.Normalize(0.0, vmax)
xmax = max(max(p[:, 0].max() for p in frames[c].polygons(t)) for c, _ in cases for t in times)
xmax = max(xmax + 5.0, 40.0)

panel_w = 7.0  # inches per panel; the height follows the equal-aspect data box
panel_h = panel_w * 59.0 / (xmax + 6.0) + 0.55
fig, axes = plt.subplots(len(times), 2, figsize=(2 * panel_w + 1.4, panel_h * len(times) + 0.7), squeeze=False,
                         sharex=True, sharey=True)
letters = "abcdef"
for r, t in enumerate(times):
    for k, (c, label) in enumerate(cases):
        ax = axes[r][k]
        draw_boundaries(ax, bounds, shade=2.0)
        for p in frames[c].polygons(0.0):
            ax.add_patch(plt.Polygon(p, closed=True, fill=False, edgecolor="0.75", lw=0.3, zorder=1.5))
        pc = draw_blocks(ax, frames[c].polygons(t), frames[c].state(t, "speed"), norm, cmap="plasma", lw=0.25)
        ax.set_xlim(-6.0, xmax)
        ax.set_ylim(-3.0, 56.0)
        ax.set_aspect("equal")
        ax.set_title("(%s) %s, t = %.1f s" % (letters[2 * r + k], label, frames[c].nearest(t)), fontsize=9)
        if r == len(times) - 1:
            ax.set_xlabel("x (m)")
        if k == 0:
            ax.set_ylabel("y (m)")
fig.suptitle("Paper A Fig. 20: collapse of a jointed rock column, ours at the paper's times for joint friction 15 deg "
             "(left) and 30 deg (right)\ngeometry reconstructed (Fig. 19 lost): 20 m x 50 m column, joints dip 80/40 deg, "
             "spacing 1.5/2.5 m; the paper's method (friction update Eq. 26)\n" + PAPER_SAYS, fontsize=10)
axes[0][0].plot([], [], color="0.75", lw=1.0, label="blocks at t = 0")
axes[0][0].add_patch(plt.Rectangle((0, 0), 0, 0, facecolor="0.85", edgecolor="0.2", hatch="///",
                                   label="fixed boundary (solid side hatched)"))
axes[0][0].legend(fontsize=7, loc="upper right")
fig.tight_layout(rect=(0, 0, 0.92, 0.95))
cax = fig.add_axes((0.93, 0.15, 0.015, 0.7))
cb = fig.colorbar(pc, cax=cax)
cb.set_label("block speed (m/s)")
save_atomic(fig, out_png)
