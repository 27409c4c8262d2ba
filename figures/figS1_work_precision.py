"""Work-precision diagrams (S1): error against run time, one curve per option.

usage: figS1_work_precision.py DATA_DIR OUT_PNG SCENE
  DATA_DIR from the work_precision driver (runs.csv, orders.csv); SCENE is
  the scene column's text up to its first space-separated word set, e.g.
  "4.1", "4.3", "resting", "5.2", "5.1", "5.3", "free", "damped".

One panel per measure: error (relative, or m) against the median wall time
of the runs, log-log; each curve is labelled with its observed order p
(least-squares slope of log error on log dt over the 4 smallest dt above
round-off) or 'round-off' / 'plateau'. The star marks the paper's dt.
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import plt, save_atomic  # noqa: E402


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def number(text):
    if text == "":
        return None
    x = float(text)
    if not math.isfinite(x):
        raise SystemExit(f"non-finite value {text!r}")
    return x


def main(argv):
    if len(argv) != 4:
        raise SystemExit(__doc__)
    data_dir, out_png, key = argv[1], argv[2], argv[3]
    runs = [r for r in read_rows(os.path.join(data_dir, "runs.csv")) if r["scene"].startswith(key)]
    orders = [r for r in read_rows(os.path.join(data_dir, "orders.csv")) if r["scene"].startswith(key)]
    if not runs:
        raise SystemExit(f"no runs for scene {key!r}")
    scene = runs[0]["scene"]
    measures = list(dict.fromkeys(r["measure"] for r in runs))
    options = list(dict.fromkeys(r["option"] for r in runs))
    order_of = {(o["option"], o["measure"]): o for o in orders}

    ncol = min(3, len(measures))
    nrow = (len(measures) + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(5.2 * ncol, 4.3 * nrow), squeeze=False)
    styles = [("o", "-"), ("s", "--"), ("^", "-."), ("v", ":"), ("D", "-")]
    for ax, measure in zip(axes.flat, measures):
        stopped = []
        for i, option in enumerate(options):
            rows = [r for r in runs if r["option"] == option and r["measure"] == measure]
            ok = [r for r in rows if r["status"] == "ok" and number(r["error"]) is not None
                  and number(r["error"]) > 0.0]
            if not ok:
                continue
            t = [number(r["wall_s"]) for r in ok]
            e = [number(r["error"]) for r in ok]
            o = order_of.get((option, measure), {})
            if o.get("order"):
                label = f"{option}: p = {float(o['order']):.2f}"
            else:
                label = f"{option}: {o.get('note') or 'no order'}"
            marker, ls = styles[i % len(styles)]
            ax.loglog(t, e, marker=marker, ls=ls, ms=5 if i == 0 else 4, mfc="none" if i % 2 else None, label=label)
            if o.get("error_at_paper_dt") and o.get("wall_at_paper_dt") and float(o["error_at_paper_dt"]) > 0.0:
                ax.plot([float(o["wall_at_paper_dt"])], [float(o["error_at_paper_dt"])], "k*", ms=11, zorder=5)
            for r in rows:
                if r["status"] != "ok":
                    stopped.append((float(r["dt"]), float(r["dt_over_crit_start"])))
        if stopped:
            dt, ratio = min(stopped)
            ax.text(0.02, 0.02, f"stopped from dt = {dt:.3g} s (dt/dt_crit = {ratio:.2f})",
                    transform=ax.transAxes, fontsize=7, color="0.3")
        ax.set_title(measure, fontsize=10)
        ax.set_xlabel("median wall time per run (s)")
        ax.set_ylabel("error")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=6.5, loc="best", framealpha=0.7)
    for ax in list(axes.flat)[len(measures):]:
        ax.axis("off")
    fig.suptitle(f"S1 work precision: {scene} (star: paper's dt; dt halves along each curve)", fontsize=11)
    fig.tight_layout()
    save_atomic(fig, out_png)


if __name__ == "__main__":
    main(sys.argv)
