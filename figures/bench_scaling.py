"""Block-count scaling of the explicit DDA step (make bench).

usage: bench_scaling.py SCALING_CSV OUT_PNG   (CSV from bench_collapse --scaling --csv)

Left: CPU microseconds per step (all threads: the work, which other jobs
sharing the cores do not stretch) against the number of blocks, 1 and 2
threads, log-log, with the fitted power law of each and a slope-1 guide; the
wall time of rows whose CPU/wall shows shared cores (below 0.9 x threads) is
drawn hollow beside it. Right: CPU ns per block-step and per touching pair,
which stay flat when the cost is linear.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import np, plt, save_atomic  # noqa: E402


def read_table(path):
    """The numeric columns of the scaling CSV as float arrays (the shape column is text)."""
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f)]
    if not rows:
        raise SystemExit(f"{path}: no data rows")
    out = {}
    for key in rows[0]:
        try:
            out[key] = np.array([float(r[key]) for r in rows])
        except ValueError:
            continue
    if not all(np.all(np.isfinite(v)) for v in out.values()):
        raise SystemExit(f"{path}: non-finite values")
    return out


if len(sys.argv) != 3:
    raise SystemExit(__doc__)
d = read_table(sys.argv[1])
fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
cpu = d["cpu_us_per_step"] if "cpu_us_per_step" in d else d["us_per_step"] * d["cpu_per_wall"]
for threads, color in ((1, "tab:blue"), (2, "tab:orange")):
    m = d["threads"] == threads
    if not np.any(m):
        continue
    n, us, wall = d["blocks"][m], cpu[m], d["us_per_step"][m]
    shared = d["cpu_per_wall"][m] < 0.9 * threads
    p = np.polyfit(np.log(n), np.log(us), 1)
    ax.loglog(n, us, "o-", color=color, label="%d thread(s), CPU: ~ blocks^%.2f" % (threads, p[0]))
    if np.any(shared):
        ax.loglog(n[shared], wall[shared], "o", mfc="none", color=color,
                  label="%d thread(s), wall time, cores shared" % threads)
    ax2.semilogx(n, 1e3 * us / n, "o-", color=color, label="per block-step, %d thread(s)" % threads)
    ax2.semilogx(n, 1e3 * us / d["touching_per_step"][m], "s--", color=color,
                 label="per touching pair, %d thread(s)" % threads)
m1 = d["threads"] == 1
n0, u0 = d["blocks"][m1][0], cpu[m1][0]
guide = np.array([n0, d["blocks"].max()])
ax.loglog(guide, u0 * guide / n0, "k:", lw=1, label="slope 1 (linear)")
ax.set_xlabel("blocks")
ax.set_ylabel("time per step (us)")
ax.set_title("6.1 joint-set scenes, %d to %d blocks" % (d["blocks"].min(), d["blocks"].max()))
ax.legend(fontsize=8)
ax.grid(alpha=0.3, which="both")
ax2.set_xlabel("blocks")
ax2.set_ylabel("CPU ns")
ax2.set_title("cost per block-step and per touching pair")
ax2.legend(fontsize=8)
ax2.grid(alpha=0.3, which="both")
fig.tight_layout()
save_atomic(fig, sys.argv[2])
