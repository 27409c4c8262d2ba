"""Paper A Fig. 22: toppling and slumping of jointed valley slopes (Sect. 6.2).

usage: fig22_toppling.py DATA_DIR OUT_PNG   (DATA_DIR from the toppling_slumping driver)

Top: the blocks at the last written time coloured by displacement magnitude,
t = 0 outlines in grey. Bottom: per slope, the mass-weighted mean rotation
toward the valley and the base slip along the sliding base, versus time,
with the rows' bands (the right slope topples: mean rotation > 10 deg; the
left slope slumps: base slip > 0.5 m with |rotation| < 10 deg) and the
paper's statement at its 3.5 s.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blocks_common import Frames, draw_blocks, draw_boundaries, np, plt, read_boundaries, read_csv  # noqa: E402
import matplotlib.colors  # noqa: E402
import paper_common as paper  # noqa: E402
from paper_common import BAND_STYLE, paper_style  # noqa: E402
from potential_common import save_tight  # noqa: E402

# The rows' bands (repro/6_2_toppling_slumping/rows.cpp): toppling needs a
# mean outward rotation above 10 deg; slumping a base slip above 0.5 m with
# a mean |rotation| below 10 deg.
TOPPLE_DEG = 10.0
SLUMP_SLIP = 0.5  # m

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
data = sys.argv[1]
fr = Frames(data)
bounds = read_boundaries(os.path.join(data, "boundaries.csv"))
notes, se = read_csv(os.path.join(data, "series.csv"))
mode = next((n for n in notes if n.startswith("start:")), "start and friction update not recorded")
t_end = fr.times[-1]

fig = plt.figure(figsize=(11, 8.5))
gs = fig.add_gridspec(2, 2, height_ratios=[1.35, 1])
ax = fig.add_subplot(gs[0, :])
draw_boundaries(ax, bounds, shade=1.5)
for p in fr.polygons(0.0):
    ax.add_patch(plt.Polygon(p, closed=True, fill=False, edgecolor="0.6", lw=0.6, ls="--", zorder=1.5))
disp = np.hypot(fr.state(t_end, "dx"), fr.state(t_end, "dy"))
norm = matplotlib.colors.Normalize(0.0, max(float(disp.max()), 1e-6))
pc = draw_blocks(ax, fr.polygons(t_end), disp, norm, cmap="viridis", lw=0.5)
cb = fig.colorbar(pc, ax=ax, shrink=0.8, pad=0.01)
cb.set_label("displacement (m)")
xs = np.concatenate([p[:, 0] for p in fr.polygons(0.0)] + [p[:, 0] for p in fr.polygons(t_end)])
ys = np.concatenate([p[:, 1] for p in fr.polygons(0.0)] + [p[:, 1] for p in fr.polygons(t_end)])
ax.set_xlim(xs.min() - 3, xs.max() + 3)
ax.set_ylim(min(ys.min(), 0) - 3, ys.max() + 3)
ax.set_aspect("equal")
ax.set_xlabel("x (m)")
ax.set_ylabel("y (m)")
ax.set_title("Paper A Fig. 22: toppling and slumping of jointed valley slopes, blocks at t = %.2f s (dashed: t = 0)\n"
             "geometry reconstructed (Fig. 21 lost): joints dip 75 deg toward +x, spacing 3 m; sliding bases 30 deg, "
             "friction 32 deg; joints 22 deg\n%s" % (t_end, mode), fontsize=9.5)
ax.text(0.02, 0.95, "left slope: joints dip toward the valley", transform=ax.transAxes, fontsize=9, va="top")
ax.text(0.98, 0.95, "right slope: joints dip into the slope", transform=ax.transAxes, fontsize=9, va="top", ha="right")

deg = 180.0 / np.pi
a1 = fig.add_subplot(gs[1, 0])
top = max(float(np.max(se["right_outward_rotation"] * deg)), float(np.max(se["left_outward_rotation"] * deg)), 15.0)
a1.axhspan(TOPPLE_DEG, 1.15 * top, **BAND_STYLE, label="toppling band: mean rotation > %g deg" % TOPPLE_DEG)
a1.plot(se["time"], se["left_outward_rotation"] * deg, label="ours: left slope")
a1.plot(se["time"], se["right_outward_rotation"] * deg, label="ours: right slope")
a1.axvline(paper.A_62_DURATION, **paper_style(label="paper (Sect. 6.2) at 3.5 s: right topples, left slumps"))
a1.set_ylim(min(-2.0, 1.15 * float(np.min(se["left_outward_rotation"] * deg))), 1.15 * top)
a1.set_xlabel("time (s)")
a1.set_ylabel("mass-weighted mean rotation toward the valley (deg)")
a1.legend(fontsize=8, loc="upper left")
a1.grid(alpha=0.3)
a2 = fig.add_subplot(gs[1, 1])
hi = 1.15 * max(float(np.max(se["right_rotation_travel"])), float(np.max(se["left_base_slip"])),
               float(np.max(se["right_base_slip"])), 2.0 * SLUMP_SLIP)
a2.axhspan(SLUMP_SLIP, hi, **BAND_STYLE, label="slumping band (left): base slip > %g m" % SLUMP_SLIP)
a2.plot(se["time"], se["left_base_slip"], label="ours, left: base slip")
a2.plot(se["time"], se["right_base_slip"], label="ours, right: base slip")
a2.plot(se["time"], se["left_rotation_travel"], "--", color="C0", label="ours, left: top travel from rotation")
a2.plot(se["time"], se["right_rotation_travel"], "--", color="C1", label="ours, right: top travel from rotation")
a2.axvline(paper.A_62_DURATION, **paper_style())
a2.set_ylim(min(-0.2, float(np.min(se["left_base_slip"]))), hi)
_, sm = read_csv(os.path.join(data, "summary.csv"))
ctrl = {int(r): i for i, r in enumerate(sm["run"])}
if 1 in ctrl and 2 in ctrl:
    lk, wh = ctrl[1], ctrl[2]
    a2.text(0.02, 0.62, "controls at t = %.2f s:\njoints locked (80 deg): left base slip %.2f m,\n  right rotation %.1f deg\n"
            "each slope ONE block: base slip left %.2f m, right %.2f m"
            % (sm["duration"][lk], sm["left_base_slip"][lk], sm["right_outward_rotation"][lk] * deg,
               sm["left_base_slip"][wh], sm["right_base_slip"][wh]),
            transform=a2.transAxes, fontsize=7.5, va="top", color="0.25")  # below the legend
a2.set_xlabel("time (s)")
a2.set_ylabel("mass-weighted mean along the base, down-dip (m)")
a2.legend(fontsize=7.5, loc="upper left")
a2.grid(alpha=0.3)
save_tight(fig, sys.argv[2])
