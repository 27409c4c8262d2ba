"""Paper A Fig. 18: a vertex hitting a 0.01 m edge (case 1) or the edge next to it (case 2), Sect. 5.3.

usage: fig18_small_edges.py DATA_DIR OUT_PNG   (DATA_DIR from the small_edges driver)

Per case (columns): the blocks at t = 0 and at the end with the contacting
vertex's trace; a zoom on the small edge; the penetration against time
beside the paper's "penetrations around 0.01 m" and the row's pass band
(deepest vertex below 0.05 m).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_common as paper  # noqa: E402
from paper_common import BAND_STYLE, paper_style  # noqa: E402
from potential_common import np, plt, read_csv, save_atomic, snapshot_outlines  # noqa: E402

DEPTH_TOL = 0.05  # m: the row's bound on the deepest vertex (repro/5_3_small_edges/small_edges.hpp, add_claims)

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
_, tr = read_csv(os.path.join(sys.argv[1], "traces.csv"))
_, sn = read_csv(os.path.join(sys.argv[1], "snapshots.csv"))


fig, axes = plt.subplots(3, 2, figsize=(11, 13.5), gridspec_kw={"height_ratios": [3, 2, 1.6]})
for col, case in enumerate([1, 2]):
    t = tr["case"] == case
    s = sn["case"] == case
    times = np.unique(sn["time"][s])
    for row in range(2):
        ax = axes[row, col]
        ax.plot([], [], color="0.6", label="blocks at t = 0")
        ax.plot([], [], color="k", label="blocks at t = %.2f s" % times[-1])
        for tt, style in zip([times[0], times[-1]], [dict(color="0.6", lw=1.0), dict(color="k", lw=1.3)]):
            for x, y in snapshot_outlines(sn, s & (sn["time"] == tt)):
                ax.plot(x, y, **style)
        ax.plot(tr["vertex_x"][t], tr["vertex_y"][t], "C3-", lw=1.2, label="ours: trace of the contacting vertex")
        ax.plot(tr["centroid_x"][t], tr["centroid_y"][t], "C0:", lw=1.5, label="ours: trace of the upper block's centroid")
        ax.set_aspect("equal")
        ax.grid(alpha=0.2)
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        if row == 0:
            ax.set_title("case %d: vertex on the %s\ngrey t = 0, black t = %.2f s" %
                         (case, "0.01 m edge" if case == 1 else "edge next to the small edge", times[-1]), fontsize=10)
            ax.legend(fontsize=7, loc="lower right")
        else:
            x0 = tr["vertex_x"][t][0]
            ax.set_xlim(x0 - 0.06, x0 + 0.06)
            ax.set_ylim(0.94, 1.04)
            ax.set_title("zoom on the small edge: peak overlap %.3g m, deepest vertex %.3g m" %
                         (tr["overlap_thickness"][t].max(), tr["vertex_depth"][t].max()), fontsize=9)
    ax = axes[2, col]
    ax.axhspan(0.0, DEPTH_TOL, **BAND_STYLE, label="pass band: deepest vertex < %g m" % DEPTH_TOL)
    ax.plot(tr["time"][t], tr["vertex_depth"][t], "C3-", label="ours: deepest vertex inside the other block")
    ax.plot(tr["time"][t], tr["overlap_thickness"][t], "C0--", label="ours: overlap thickness (inscribed diameter)")
    ax.axhline(paper.A_53_PENETRATION, **paper_style(label="paper (Sect. 5.3): 'penetrations around 0.01 m'"))
    ax.set_ylim(0.0, 1.3 * DEPTH_TOL)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("penetration (m)")
    ax.set_title("case %d: penetration against time" % case, fontsize=10)
    ax.legend(fontsize=7, loc="upper right")
    ax.grid(alpha=0.3)
fig.suptitle("Paper A Fig. 18: a block's vertex hitting a 0.01 m edge (case 1) or the edge next to it (case 2), "
             "0.2 s, dt = 1e-4 s\n(geometry reconstructed, Fig. 17 lost; the paper's segmentation and small-edge rule: "
             "vertex + virtual-node rays, the library default)", fontsize=10)
fig.tight_layout(rect=(0, 0, 1, 0.965))
save_atomic(fig, sys.argv[2])
