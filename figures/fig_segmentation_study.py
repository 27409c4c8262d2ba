"""Is Paper A's segmentation (Sect. 3.2.3) exact? Paper rule (both small-edge readings) vs exact integration.

usage: fig_segmentation_study.py DATA_DIR OUT_PNG   (DATA_DIR from the segmentation driver)
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paper_common import BAND_STYLE, paper_style  # noqa: E402
from potential_common import np, plt, read_csv, save_atomic  # noqa: E402

# The rows' criterion: a relative force error above this is not round-off
# (repro/5_5_segmentation/segmentation.hpp, kExactTolerance).
EXACT_TOL = 1e-8

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
data = sys.argv[1]
FLOOR = 1e-17


def text_rows(path):
    with open(path, newline="") as f:
        return [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]


summary = text_rows(os.path.join(data, "summary.csv"))
runs = text_rows(os.path.join(data, "trajectory_runs.csv"))
_, fz = read_csv(os.path.join(data, "fuzz.csv"))
_, tr = read_csv(os.path.join(data, "trajectories.csv"))
for rows, path in ((summary, "summary.csv"), (runs, "trajectory_runs.csv")):
    if not rows:
        raise SystemExit(f"{path}: no rows")

PAPER = "paper's rule, library default (vertex + virtual-node rays)"
REPLACE = "replacing reading (virtual node replaces the vertex rays; an option)"
fig, axes = plt.subplots(2, 2, figsize=(13, 10))
ax = axes[0, 0]
names = [r["scene"] for r in summary]
y = np.arange(len(names))
for key, mk, lab in (("max_force_error_paper", "o", "ours, paper's rule (default): max"),
                     ("p99_force_error_paper", "|", "same, 99th percentile"),
                     ("max_force_error_replace", "x", "ours, replacing reading: max")):
    ax.semilogx(np.maximum([float(r[key]) for r in summary], FLOOR), y, mk, ms=8, label=lab)
ax.set_yticks(y)
ax.set_yticklabels(names, fontsize=8)
ax.invert_yaxis()
ax.axvspan(FLOOR / 10.0, EXACT_TOL, **BAND_STYLE, label="pass band: < %g (round-off)" % EXACT_TOL)
ax.axvline(FLOOR, **paper_style(label="paper (Sect. 3.2.3): 'computed\naccurately piece by piece' (error 0)"))
ax.set_xlim(FLOOR / 10.0, 1e4)
ax.set_xlabel("relative error of the normal force |f_paper - f_exact| / |f_exact| (1e-17: exact)")
ax.set_title("(a) per contact and step along the Sect. 4-5 runs (library defaults)", fontsize=10)
ax.legend(fontsize=6.5, loc="center left", bbox_to_anchor=(0.47, 0.55))
ax.grid(alpha=0.3)

for ax, key, title in ((axes[0, 1], "force_error_paper", "(b) fuzzed pairs, " + PAPER),
                       (axes[1, 0], "force_error_replace", "(c) fuzzed pairs, " + REPLACE)):
    small = fz["has_small_edge"] > 0.5
    for sel, col, lab in ((~small, "C0", "no edge < 0.05 H"), (small, "C3", "with an edge < 0.05 H (virtual node)")):
        ax.loglog(np.maximum(fz["depth_ratio"][sel], 1e-4), np.maximum(fz[key][sel], FLOOR), ".", ms=2, color=col,
                  alpha=0.5, label=lab)
    nonzero = 100.0 * np.mean(fz[key] > EXACT_TOL)
    ax.axhspan(FLOOR / 10.0, EXACT_TOL, **BAND_STYLE)
    ax.axhline(EXACT_TOL, color="tab:green", ls=":", lw=1, label="round-off bound %g" % EXACT_TOL)
    ax.set_xlabel("overlap thickness / smaller inscribed diameter (dimensionless)")
    ax.set_ylabel("relative normal-force error (1e-17 = exact)")
    ax.set_title(title + "\n%d random pairs, %.2g %% with an error > %g" % (fz["depth_ratio"].size, nonzero, EXACT_TOL),
                 fontsize=9)
    ax.legend(fontsize=8, markerscale=5, loc="upper left")
    ax.grid(alpha=0.3)

ax = axes[1, 1]
for i, r in enumerate(runs):
    k = int(r["scene"])
    m = tr["scene"] == k
    col = "C%d" % (i % 10)
    ax.semilogy(tr["time"][m], np.maximum(tr["difference_paper"][m], FLOOR), lw=1.0, color=col,
                label="%s: max %.2g / %.2g" % (r["name"], float(r["max_difference_paper"]),
                                                float(r["max_difference_replace"])))
    if float(r["max_difference_replace"]) != float(r["max_difference_paper"]):
        ax.semilogy(tr["time"][m], np.maximum(tr["difference_replace"][m], FLOOR), lw=1.0, ls="--", color=col)
ax.set_xlabel("time (s)")
ax.set_ylabel("|run - exact-integration run| of the watched quantity (m or m/s)")
ax.set_title("(d) trajectories: solid = paper's rule (default), dashed = replacing reading\n"
             "(drawn only where it differs); legend: max paper's rule / replacing", fontsize=9)
ax.legend(fontsize=6.5, loc="center right")
ax.grid(alpha=0.3)
fig.suptitle("Beyond Paper A Sect. 3.2.3: is the paper's segmentation exact? Its normal force under both small-edge "
             "readings against the exact piecewise integration\n(Sect. 4-5 scenes reconstructed; green: within round-off)",
             fontsize=11)
fig.tight_layout(rect=(0, 0, 1, 0.96))
save_atomic(fig, sys.argv[2])
