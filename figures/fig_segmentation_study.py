"""Is Paper A's segmentation (Sect. 3.2.3) exact? Paper rule (both small-edge readings) vs exact integration.

usage: fig_segmentation_study.py DATA_DIR OUT_PNG   (DATA_DIR from the segmentation driver)
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import np, plt, read_csv, save_atomic  # noqa: E402

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
REPLACE = "SPEC.md's reading (virtual node replaces the vertex rays)"
fig, axes = plt.subplots(2, 2, figsize=(13, 10))
ax = axes[0, 0]
names = [r["scene"] for r in summary]
y = np.arange(len(names))
for key, mk, lab in (("max_force_error_paper", "o", PAPER + ": max"),
                     ("p99_force_error_paper", "|", "same, 99th percentile"),
                     ("max_force_error_replace", "x", REPLACE + ": max")):
    ax.semilogx(np.maximum([float(r[key]) for r in summary], FLOOR), y, mk, ms=8, label=lab)
ax.set_yticks(y)
ax.set_yticklabels(names, fontsize=8)
ax.invert_yaxis()
ax.axvline(1e-8, color="0.5", ls=":", lw=1)
ax.set_xlabel("relative error of the normal force |f_paper - f_exact| / |f_exact|")
ax.set_title("(a) per contact and step along the Sect. 4-5 runs (library defaults)", fontsize=10)
ax.legend(fontsize=7, loc="upper center")
ax.grid(alpha=0.3)

for ax, key, title in ((axes[0, 1], "force_error_paper", "(b) fuzzed pairs, " + PAPER),
                       (axes[1, 0], "force_error_replace", "(c) fuzzed pairs, " + REPLACE)):
    small = fz["has_small_edge"] > 0.5
    for sel, col, lab in ((~small, "C0", "no edge < 0.05 H"), (small, "C3", "with an edge < 0.05 H (virtual node)")):
        ax.loglog(np.maximum(fz["depth_ratio"][sel], 1e-4), np.maximum(fz[key][sel], FLOOR), ".", ms=2, color=col,
                  alpha=0.5, label=lab)
    nonzero = 100.0 * np.mean(fz[key] > 1e-8)
    ax.axhline(1e-8, color="0.5", ls=":", lw=1)
    ax.set_xlabel("overlap thickness / smaller inscribed diameter")
    ax.set_ylabel("relative normal-force error (1e-17 = exact)")
    ax.set_title(title + "\n%d pairs, %.2g %% with an error > 1e-8" % (fz["depth_ratio"].size, nonzero), fontsize=9)
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
fig.suptitle("Is Paper A's segmentation exact? Paper segmentation (Sect. 3.2.3) under both small-edge readings vs "
             "exact piecewise integration", fontsize=11)
fig.tight_layout()
save_atomic(fig, sys.argv[2])
