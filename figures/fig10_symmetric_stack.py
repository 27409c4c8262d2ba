"""Paper A Fig. 10: centroid traces of the symmetric stack (Sect. 4.2).

usage: fig10_symmetric_stack.py DATA_DIR OUT_PNG   (DATA_DIR from the symmetric_stack driver)

Left: the blocks at t = 0 and at the end, each centroid's trace, and the
mirror image of each left-hand trace about the axis x = 0 (the paper's
statement: the system moves symmetrically, so the mirror image lies on the
right-hand trace). Right: the largest mirror asymmetry of the centroids
against time with the row's pass band (below 1e-6 m).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paper_common import BAND_STYLE, paper_style  # noqa: E402
from potential_common import np, plt, read_csv, save_tight, script_main, snapshot_outlines  # noqa: E402

POSITION_TOL = 1e-6  # m: the row's criterion (repro/4_2_symmetric_stack/symmetric_stack.hpp, kPositionTol)
FLOOR = 1e-17        # m: zeros drawn at this level on the log axis


def main(data, out_png):
    notes, tr = read_csv(os.path.join(data, "traces.csv"))
    _, sn = read_csv(os.path.join(data, "snapshots.csv"))
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(13, 6.6), gridspec_kw={"width_ratios": [3, 2]})
    times = np.unique(sn["time"])
    for t, style in zip([times[0], times[-1]], [dict(color="0.7", lw=1), dict(color="k", lw=1.2)]):
        for x, y in snapshot_outlines(sn, sn["time"] == t):
            ax.plot(x, y, **style)
    ax.plot([], [], color="0.7", label="blocks at t = 0")
    ax.plot([], [], color="k", label="blocks at t = %.1f s" % times[-1])
    n = sum(1 for k in tr if k.startswith("x"))
    x0 = [tr["x%d" % i][0] for i in range(n)]
    y0 = [tr["y%d" % i][0] for i in range(n)]
    for i in range(n):
        moved = np.hypot(tr["x%d" % i] - x0[i], tr["y%d" % i] - y0[i]).max()
        if moved == 0.0:
            continue  # the fixed base
        side = "on the axis" if abs(x0[i]) < 1e-12 else ("left" if x0[i] < 0 else "right")
        ax.plot(tr["x%d" % i], tr["y%d" % i], lw=2.0,
                label="ours: centroid of block %d (%s), travels up to %.2g m" % (i, side, moved))
    # The paper's statement: each left-hand block's trace mirrored about
    # x = 0 lies on its partner's; blocks on the axis stay on it.
    first = True
    for i in range(n):
        if x0[i] < -1e-12:
            ax.plot(-tr["x%d" % i], tr["y%d" % i], **paper_style(lw=1.2, zorder=4),
                    label="paper (Sect. 4.2): symmetric motion;\nmirror image of a left trace" if first else None)
            first = False
    ax.axvline(0.0, color="r", lw=0.6, ls=":", label="symmetry axis x = 0")
    ax.set_aspect("equal")
    ax.set_ylim(-3.4, 3.6)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("Paper A Fig. 10: a pentagon falling on a symmetric stack, centroid traces over %.1f s\n"
                 "(geometry reconstructed: Fig. 9 lost; the base is fixed)" % times[-1], fontsize=10)
    ax.legend(fontsize=7, loc="lower center", ncol=2, framealpha=0.95)

    ax2.axhspan(FLOOR / 10.0, POSITION_TOL, **BAND_STYLE)
    ax2.semilogy(tr["time"], np.maximum(tr["asymmetry"], FLOOR), color="C0", label="ours: largest mirror asymmetry")
    ax2.axhline(POSITION_TOL, color="tab:green", ls=":", lw=1.2, label="pass band: < %g m" % POSITION_TOL)
    ax2.axhline(FLOOR, **paper_style(label="paper: symmetric (zero, drawn at %g m)" % FLOOR))
    ax2.set_ylim(FLOOR / 10.0, 1e-3)
    ax2.set_xlabel("time (s)")
    ax2.set_ylabel("max over mirror pairs of |x_i + x_j|, |y_i - y_j| (m)")
    ax2.set_title("mirror asymmetry of the centroids", fontsize=10)
    ax2.legend(fontsize=8, loc="upper left")
    ax2.grid(alpha=0.3)
    save_tight(fig, out_png)


if __name__ == "__main__":
    script_main(main, __doc__)
