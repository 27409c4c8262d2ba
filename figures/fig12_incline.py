"""Paper A Fig. 12: sliding distance on the incline vs Eq. 30 (Sect. 4.3).

usage: fig12_incline.py DATA_DIR OUT_PNG   (DATA_DIR from the incline driver)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import np, plt, read_csv, save_atomic  # noqa: E402

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
_, d = read_csv(os.path.join(sys.argv[1], "sliding.csv"))
fig, (ax, ax2) = plt.subplots(2, 1, figsize=(6.5, 6.5), sharex=True, gridspec_kw={"height_ratios": [3, 1]})
for phi in np.unique(d["phi_deg"]):
    m = d["phi_deg"] == phi
    line, = ax.plot(d["time"][m], d["distance"][m], label="DDA, phi = %g deg" % phi)
    ax.plot(d["time"][m], d["analytic"][m], "k:", lw=1)
    rel = (d["distance"][m] - d["analytic"][m]) / np.maximum(d["analytic"][m], 1e-12)
    ax2.plot(d["time"][m], rel, color=line.get_color())
ax.plot([], [], "k:", label="Eq. 30")
ax.set_ylabel("sliding distance (m)")
ax.set_title("Paper A Fig. 12: block on a 30 deg incline (reconstructed geometry)")
ax.legend()
ax.grid(alpha=0.3)
ax2.set_xlabel("time (s)")
ax2.set_ylabel("relative error")
ax2.grid(alpha=0.3)
fig.tight_layout()
save_atomic(fig, sys.argv[2])
