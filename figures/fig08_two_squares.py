"""Paper A Fig. 8: x-velocities of the two colliding squares (Sect. 4.1).

usage: fig08_two_squares.py DATA_DIR OUT_PNG   (DATA_DIR from the two_squares driver)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import plt, read_csv, save_atomic  # noqa: E402

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
_, d = read_csv(os.path.join(sys.argv[1], "velocity.csv"))
fig, (ax, ax2) = plt.subplots(2, 1, figsize=(6.5, 6), sharex=True, gridspec_kw={"height_ratios": [3, 1]})
ax.plot(d["time"], d["vx_A"], label="block A")
ax.plot(d["time"], d["vx_B"], "--", label="block B")
ax.set_ylabel("x-velocity (m/s)")
ax.set_title("Paper A Fig. 8: collision of two squares (dt = 1e-4 s)")
ax.legend()
ax.grid(alpha=0.3)
p0 = d["momentum_x"][0]
e0 = d["total_energy"][0]
ax2.plot(d["time"], (d["momentum_x"] - p0) / p0, label="momentum error")
ax2.plot(d["time"], (d["total_energy"] - e0) / e0, label="energy error")
ax2.set_xlabel("time (s)")
ax2.set_ylabel("relative error")
ax2.legend(fontsize=8)
ax2.grid(alpha=0.3)
fig.tight_layout()
save_atomic(fig, sys.argv[2])
