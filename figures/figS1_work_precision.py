"""Work-precision diagrams (S1): error against run time, one curve per option.

usage: figS1_work_precision.py DATA_DIR OUT_PNG SCENE
  DATA_DIR from the work_precision driver (runs.csv, orders.csv); SCENE is
  the scene column's text up to its first space-separated word set, e.g.
  "4.1", "4.3", "resting", "5.2", "5.1", "5.3", "free", "damped".

One panel per measure: error (relative, or m where the measure says so)
against the median wall time of the runs, log-log; each panel names its
reference (orders.csv), each curve is labelled with its observed order p
(least-squares slope of log error on log dt over the 4 smallest dt above
round-off) or 'round-off' / 'plateau'. The star marks the paper's dt; the
grey wedge is the slope the order rows accept for second order (2 +- 0.3,
with the run time proportional to 1 / dt).
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import np, plt, save_atomic  # noqa: E402

ORDER, ORDER_TOL = 2.0, 0.3  # the order rows' band for velocity Verlet (repro/S1_work_precision/claims.cpp)
EQ30_TOL = 0.01              # the Sect. 4.3 rows' band on Eq. 30 (repro/4_3_incline/incline.hpp, kTol)
ROUNDOFF = 1e-12             # the round-off rows' level on these measures (claims.cpp, roundoff_claim)
ROUNDOFF_MEASURES = ("momentum", "point symmetry (m)", "area", "Eq. 30")


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
    fig, axes = plt.subplots(nrow, ncol, figsize=(5.4 * ncol, 5.0 * nrow), squeeze=False)
    styles = [("o", "-"), ("s", "--"), ("^", "-."), ("v", ":"), ("D", "-")]
    for ax, measure in zip(axes.flat, measures):
        stopped = []
        first_curve = None
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
            ax.loglog(t, e, marker=marker, ls=ls, ms=5 if i == 0 else 4, mfc="none" if i % 2 else None,
                      label="ours, " + label)
            if first_curve is None and len(t) > 1 and o.get("order"):
                first_curve = (t, e)  # the wedge starts on the first curve with a fitted order
            if o.get("error_at_paper_dt") and o.get("wall_at_paper_dt") and float(o["error_at_paper_dt"]) > 0.0:
                ax.plot([float(o["wall_at_paper_dt"])], [float(o["error_at_paper_dt"])], "k*", ms=11, zorder=5)
            for r in rows:
                if r["status"] != "ok":
                    stopped.append((float(r["dt"]), float(r["dt_over_crit_start"])))
        if stopped:
            dt, ratio = min(stopped)
            ax.text(0.02, 0.02, f"stopped from dt = {dt:.3g} s" +
                    (f" (dt/dt_crit = {ratio:.2f} at the start)" if ratio > 0.0 else ""),
                    transform=ax.transAxes, fontsize=7, color="0.3")
        if first_curve is not None:
            # The accepted slope for second order, from the first curve's cheapest run toward its dearest.
            t, e = first_curve
            k = int(np.argmin(t))
            t1 = np.array([t[k], t[k] * 10.0])
            for slope, style in ((ORDER - ORDER_TOL, ":"), (ORDER + ORDER_TOL, ":")):
                ax.loglog(t1, e[k] * (t1 / t[k]) ** (-slope), style, color="0.55", lw=1.0)
            ax.fill_between(t1, e[k] * (t1 / t[k]) ** (-(ORDER - ORDER_TOL)), e[k] * (t1 / t[k]) ** (-(ORDER + ORDER_TOL)),
                            color="0.85", alpha=0.6, lw=0,
                            label=f"slope of order {ORDER:g} +- {ORDER_TOL:g} (band of the rows expecting order 2)")
        if measure in ROUNDOFF_MEASURES:
            ax.axhline(ROUNDOFF, color="tab:purple", ls=":", lw=1.2, label="round-off rows' band: < %g" % ROUNDOFF)
        if measure == "Eq. 30":
            ax.axhline(EQ30_TOL, color="tab:green", ls=":", lw=1.2,
                       label="Sect. 4.3 rows' band: < %g of Eq. 30 (the paper's)" % EQ30_TOL)
        if any(o.get("error_at_paper_dt") for o in orders if o["measure"] == measure):
            ax.plot([], [], "k*", ms=10, label="at the paper's dt")
        reference = next((o["reference"] for o in orders if o["measure"] == measure and o.get("reference")), "")
        ax.set_title(measure + ("\nreference: " + reference if reference else ""), fontsize=9)
        ax.set_xlabel("median wall time per run (s)")
        ax.set_ylabel("error (m)" if "(m)" in measure else "relative error")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=6, loc="best", framealpha=0.8)
    for ax in list(axes.flat)[len(measures):]:
        ax.axis("off")
    fig.suptitle(f"Beyond the papers: work precision of {scene}\nerror against run time over a dt sweep "
                 "(dt halves along each curve; star: the paper's dt)", fontsize=11)
    fig.tight_layout()
    save_atomic(fig, out_png)


if __name__ == "__main__":
    main(sys.argv)
