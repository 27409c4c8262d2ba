"""Paper A Fig. 14: vertical displacement of the bouncing block A (Sect. 5.1).

usage: fig14_bouncing_block.py DATA_DIR OUT_PNG   (DATA_DIR from the bouncing_block driver)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import plt, read_csv, save_atomic  # noqa: E402

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
_, d = read_csv(os.path.join(sys.argv[1], "displacement.csv"))
fig, (ax, ax2) = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True, gridspec_kw={"height_ratios": [3, 1.4]})
ax.plot(d["time"], d["case1_unified"], "C0-", lw=1.6, label="case 1 (B 0.1 m), unified H")
ax.plot(d["time"], d["case2_unified"], "C0--", lw=1.6, label="case 2 (B 1 m), unified H")
ax.plot(d["time"], d["case1_inscribed"], "C3-", lw=1.0, label="case 1, inscribed-radius H (previous)")
ax.plot(d["time"], d["case2_inscribed"], "C3--", lw=1.0, label="case 2, inscribed-radius H (previous)")
ax.set_ylabel("accumulated vertical displacement of A (m)")
ax.set_title("Paper A Fig. 14 (reconstructed geometry): block A bouncing on B\n"
             "1 m square dropped 0.5 m on a 4 m wide fixed block, kn = 50 MPa, dt = 1e-4 s", fontsize=10)
ax.legend(fontsize=8, loc="lower left")
ax.grid(alpha=0.3)
ax2.plot(d["time"], d["case1_unified"] - d["case2_unified"], "C0-", label="unified H")
ax2.plot(d["time"], d["case1_inscribed"] - d["case2_inscribed"], "C3-", label="inscribed-radius H")
ax2.set_xlabel("time (s)")
ax2.set_ylabel("case 1 - case 2 (m)")
ax2.legend(fontsize=8)
ax2.grid(alpha=0.3)
fig.tight_layout()
save_atomic(fig, sys.argv[2])
