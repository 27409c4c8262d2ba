"""Paper A Fig. 16: collision of two triangles with a 5 degree angle (Sect. 5.2).

usage: fig16_small_angles.py DATA_DIR OUT_PNG   (DATA_DIR from the small_angles driver)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import np, plt, read_csv, save_atomic  # noqa: E402

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
_, tr = read_csv(os.path.join(sys.argv[1], "traces.csv"))
_, sn = read_csv(os.path.join(sys.argv[1], "snapshots.csv"))


def draw_snapshots(ax, sn):
    times = np.unique(sn["time"])
    for t, style in zip([times[0], times[-1]], [dict(color="0.65", lw=1.0), dict(color="k", lw=1.3)]):
        sel = sn["time"] == t
        for b in np.unique(sn["block"][sel]):
            m = sel & (sn["block"] == b)
            x, y = sn["x"][m], sn["y"][m]
            ax.fill(np.append(x, x[0]), np.append(y, y[0]), fc="none", ec=style["color"], lw=style["lw"])
    return times


fig, (ax, ax2) = plt.subplots(1, 2, figsize=(12, 5.2), gridspec_kw={"width_ratios": [3, 2]})
times = draw_snapshots(ax, sn)
ax.plot(tr["apex0_x"], tr["apex0_y"], "C0-", lw=1.2, label="apex (5 deg) of the lower triangle")
ax.plot(tr["apex1_x"], tr["apex1_y"], "C1-", lw=1.2, label="apex of the upper triangle")
ax.plot(tr["c0_x"], tr["c0_y"], "C0:", lw=1.5, label="centroid, lower")
ax.plot(tr["c1_x"], tr["c1_y"], "C1:", lw=1.5, label="centroid, upper")
ax.plot([0], [0], "r+", ms=12, mew=2, label="collision centre")
ax.set_aspect("equal")
ax.set_xlabel("x (m)")
ax.set_ylabel("y (m)")
ax.legend(fontsize=7, loc="upper left")
ax.set_title("Fig. 16 (reconstructed geometry): grey t = 0, black t = %.2f s" % times[-1], fontsize=10)
ax.grid(alpha=0.2)
ax2.semilogy(tr["time"], np.maximum(tr["asymmetry"], 1e-18), "k-", label="point-symmetry error (m)")
e = tr["total_energy"]
ax2.semilogy(tr["time"], np.maximum(np.abs(e - e[0]) / e[0], 1e-18), "C2-", label="|E - E0| / E0")
ax2.semilogy(tr["time"], np.maximum(tr["overlap_thickness"], 1e-18), "C3-", label="overlap thickness (m)")
ax2.set_ylim(1e-18, 1.0)
ax2.set_xlabel("time (s)")
ax2.legend(fontsize=8)
ax2.grid(alpha=0.3)
ax2.set_title("symmetry, energy and penetration (1e-18 = zero)", fontsize=10)
fig.tight_layout()
save_atomic(fig, sys.argv[2])
