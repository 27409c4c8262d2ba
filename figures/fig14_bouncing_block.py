"""Paper A Fig. 14: vertical displacement of the bouncing block A (Sect. 5.1).

usage: fig14_bouncing_block.py DATA_DIR OUT_PNG   (DATA_DIR from the bouncing_block driver)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paper_common import BAND_STYLE  # noqa: E402
from potential_common import np, plt, read_csv, save_tight  # noqa: E402

# The row's criterion (repro/5_1_bouncing_block/bouncing_block.hpp, kRatioMax):
# the largest case 1 - case 2 difference under the unified H is at most half
# of the one under the inscribed-radius H.
RATIO_MAX = 0.5

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
_, d = read_csv(os.path.join(sys.argv[1], "displacement.csv"))
fig, (ax, ax2) = plt.subplots(2, 1, figsize=(8, 7.5), sharex=True, gridspec_kw={"height_ratios": [3, 1.8]})
ax.plot(d["time"], d["case1_unified"], "C0-", lw=1.6, label="ours: case 1 (B 0.1 m high), unified H")
ax.plot(d["time"], d["case2_unified"], "C0--", lw=1.6, label="ours: case 2 (B 1 m high), unified H")
ax.plot(d["time"], d["case1_inscribed"], "C3-", lw=1.0, label="ours: case 1, inscribed-radius H (previous)")
ax.plot(d["time"], d["case2_inscribed"], "C3--", lw=1.0, label="ours: case 2, inscribed-radius H (previous)")
ax.set_ylabel("accumulated vertical displacement of A's centroid (m)")
ax.set_title("Paper A Fig. 14: block A falling and bouncing on a fixed block B of two heights, two H rules\n"
             "(geometry reconstructed, Fig. 13 lost: 1 m square dropped 0.5 m on a 4 m wide B; "
             "kn = 50 MPa, dt = 1e-4 s)", fontsize=9.5)
ax.set_ylim(-0.56, 0.25)
ax.legend(fontsize=7.5, loc="upper center", ncol=2, title="paper (Sect. 5.1): unified H 'very similar' for the two cases,\n"
          "inscribed-radius H 'significantly different'", title_fontsize=7.5)
ax.grid(alpha=0.3)
unified = d["case1_unified"] - d["case2_unified"]
inscribed = d["case1_inscribed"] - d["case2_inscribed"]
band = RATIO_MAX * float(np.max(np.abs(inscribed)))
ax2.axhspan(-band, band, **BAND_STYLE,
            label="pass band of the unified H: |difference| <= %g x the inscribed-radius H's largest" % RATIO_MAX)
ax2.plot(d["time"], unified, "C0-", label="ours: unified H (max |difference| %.3g m)" % np.max(np.abs(unified)))
ax2.plot(d["time"], inscribed, "C3-", label="ours: inscribed-radius H (max %.3g m)" % np.max(np.abs(inscribed)))
ax2.set_xlabel("time (s)")
ax2.set_ylabel("case 1 - case 2 (m)")
ax2.legend(fontsize=7, loc="lower left")
ax2.grid(alpha=0.3)
save_tight(fig, sys.argv[2])
