"""Paper A Fig. 10: centroid traces of the symmetric stack (Sect. 4.2).

usage: fig10_symmetric_stack.py DATA_DIR OUT_PNG   (DATA_DIR from the symmetric_stack driver)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import np, plt, read_csv, save_atomic  # noqa: E402

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
_, tr = read_csv(os.path.join(sys.argv[1], "traces.csv"))
_, sn = read_csv(os.path.join(sys.argv[1], "snapshots.csv"))
fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 5), gridspec_kw={"width_ratios": [3, 2]})
times = np.unique(sn["time"])
for t, style in zip([times[0], times[-1]], [dict(color="0.7", lw=1), dict(color="k", lw=1.2)]):
    sel = sn["time"] == t
    for b in np.unique(sn["block"][sel]):
        m = sel & (sn["block"] == b)
        x, y = sn["x"][m], sn["y"][m]
        ax.plot(np.append(x, x[0]), np.append(y, y[0]), **style, label=None)
n = sum(1 for k in tr if k.startswith("x"))
for i in range(n):
    ax.plot(tr["x%d" % i], tr["y%d" % i], lw=1.5)
ax.axvline(0.0, color="r", lw=0.6, ls=":")
ax.set_aspect("equal")
ax.set_ylim(-1.2, 4.0)
ax.set_title("Fig. 10 (reconstructed geometry): traces over 1 s\ngrey t = 0, black t = %.1f s" % times[-1])
ax2.semilogy(tr["time"], np.maximum(tr["asymmetry"], 1e-17))
ax2.set_xlabel("time (s)")
ax2.set_ylabel("largest mirror asymmetry of centroids (m)")
ax2.grid(alpha=0.3)
fig.tight_layout()
save_atomic(fig, sys.argv[2])
