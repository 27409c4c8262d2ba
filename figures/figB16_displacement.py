"""Paper B Fig. 16: x-displacement of the two prisms through the collision.

usage: figB16_displacement.py DATA_DIR OUT_PNG   (DATA_DIR from B_6_two_prisms)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdem_common import plt, read_table, save_atomic  # noqa: E402

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
notes, h = read_table(os.path.join(sys.argv[1], "history.csv"))
_, h0 = read_table(os.path.join(sys.argv[1], "history_nosub.csv"))
fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.6), layout="constrained")
fig.get_layout_engine().set(rect=(0.0, 0.04, 1.0, 0.96))  # room for the note below
ax.plot(h["time"], h["ux_i"], label="block i")
ax.plot(h["time"], h["ux_j"], label="block j")
ax.plot(h0["time"], h0["ux_j"], ":", color="C1", label="block j, no subdivision")
ax.axvline(1.0 / 3.0, color="0.6", lw=0.8, ls="--")
ax.set_xlabel("time (s)")
ax.set_ylabel("x-displacement (m), mass-weighted mean")
ax.set_title("Paper B Fig. 16: x-displacements (touch at 1/3 s)", fontsize=10)
ax.legend(fontsize=8)
ax.grid(alpha=0.3)
w = (h["time"] > 0.330) & (h["time"] < 0.350)
w0 = (h0["time"] > 0.330) & (h0["time"] < 0.350)
ax2.plot(h["time"][w], h["vx_i"][w], label="v_x block i (mean)")
ax2.plot(h["time"][w], h["vx_j"][w], label="v_x block j (mean)")
ax2.plot(h["time"][w], h["vx_max_j"][w], "--", color="C1", lw=0.9, label="largest nodal v_x in j")
ax2.plot(h0["time"][w0], h0["vx_j"][w0], ":", color="C1", label="v_x j, no subdivision")
ax2.axhline(3.205, color="C3", lw=0.8, ls="-.", label="paper: 3.205 m/s (Fig. 14c)")
for t, lab in ((0.3335, "14a"), (0.3400, "14c"), (0.3405, "15a")):
    ax2.axvline(t, color="0.7", lw=0.6)
    ax2.text(t, 0.05, lab, fontsize=7, color="0.4", rotation=90, va="bottom", ha="right")
ax2.set_xlabel("time (s)")
ax2.set_ylabel("x-velocity (m/s)")
ax2.set_title("velocities through the contact", fontsize=10)
ax2.legend(fontsize=7, loc="center right")
ax2.grid(alpha=0.3)
note = next((n for n in notes if "rebuilt" in n), "")
fig.text(0.01, 0.005, note, fontsize=7, color="0.3", va="bottom")
save_atomic(fig, sys.argv[2])
