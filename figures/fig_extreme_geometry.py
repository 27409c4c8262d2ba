"""Beyond Paper A Sect. 5: the Sect. 5 scenes with ever smaller angles, edges and thicknesses.

usage: fig_extreme_geometry.py DATA_DIR OUT_PNG   (DATA_DIR from the extreme_geometry driver)

One panel per scene family (table.csv's family column): the time step over
the solver's predicted critical step, dt / dt_crit, against the size pushed
past the paper's (5.1: the fixed block's thickness; 5.2: the apex angle;
5.3: the small edge), for the run at the paper's dt (filled: clean; cross:
not clean, with the reason) and, where that failed, the rerun at a stable
dt with the step-motion guard off (d1, hollow). Below dt / dt_crit = 1 the
step is predicted stable. The dotted vertical line is the paper's own size.
A run is clean if it finishes without flip-through, its energy error is
below 1 % and, where the scene is symmetric, its asymmetry below 1e-9 m.
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_common as paper  # noqa: E402
from paper_common import BAND_STYLE, paper_style  # noqa: E402
from potential_common import plt, save_tight, script_main  # noqa: E402

# Per family: the x-axis quantity, its unit, how to tell the series apart
# (a text in the case label) and the paper's own size (paper_common).
FAMILIES = {
    "5.1": ("thickness of the fixed block B", "m", (("unified H", "unified H (paper's)"),
                                                    ("inscribed-radius H", "inscribed-radius H (previous)")),
            paper.A_51_B_HEIGHTS[0], "paper's case 1: B 0.1 m (Sect. 5.1)"),
    "5.2": ("apex angle of the two triangles", "deg", (("", "point-symmetric triangles"),),
            paper.A_52_APEX_DEG, "paper's 5 deg (Sect. 5.2)"),
    "5.3": ("length of the small edge", "m", (("impact on", "vertex on the small edge (case 1)"),
                                              ("impact next to", "vertex next to it (case 2)")),
            paper.A_53_SMALL_EDGE, "paper's 0.01 m (Sect. 5.3)"),
}
TITLES = {"5.1": "5.1 bouncing block on a thinner B", "5.2": "5.2 triangles with smaller angles",
          "5.3": "5.3 vertex impact on a smaller edge"}


def number(text, path):
    x = float(text)
    if not math.isfinite(x):
        raise SystemExit(f"{path}: non-finite value")
    return x


def short(verdict):
    """First clause of a verdict; names the solver guard that stopped a run."""
    if verdict.startswith("stopped"):
        for key, name in (("a vertex moved", "stopped: step-motion guard"), ("energy grew", "stopped: energy guard"),
                          ("non-finite", "stopped: non-finite state"), ("area collapsed", "stopped: block collapsed"),
                          ("penetrat", "stopped: penetration guard")):
            if key in verdict:
                return name
        return "stopped by the solver"
    return verdict.split(":")[0].split(";")[0]


def main(data, out_png):
    path = os.path.join(data, "table.csv")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    families = [fam for fam in FAMILIES if any(r["family"] == fam for r in rows)]
    unknown = sorted({r["family"] for r in rows} - set(FAMILIES))
    if unknown:
        raise SystemExit(f"{path}: no axis for families {unknown}")
    fig, axes = plt.subplots(1, len(families), figsize=(6.0 * len(families), 6.8), squeeze=False)
    markers = ["o", "s"]
    for ax, fam in zip(axes[0], families):
        quantity, unit, series, paper_size, paper_label = FAMILIES[fam]
        mine = [r for r in rows if r["family"] == fam]
        ratios = []
        for k, (key, name) in enumerate(series):
            sel = [r for r in mine if key in r["case"]]
            if not sel:
                continue
            col = "C%d" % k
            # A second series on the same sizes is drawn at 0.85 x the size, so both stay visible.
            shift = 1.0 if k == 0 else 0.85
            xs = [shift * number(r["parameter"], path) for r in sel]
            ys = [number(r["paper_dt"], path) / number(r["dt_crit"], path) for r in sel]
            ratios += ys
            ax.plot(xs, ys, "-", color=col, lw=0.8, alpha=0.6)
            said = None
            for idx, (r, x, y) in enumerate(zip(sel, xs, ys)):
                clean = r["paper_clean"] == "1"
                ax.plot([x], [y], markers[k] if clean else "x", color=col, ms=8 if clean else 9, mew=2)
                reason = None if clean else (r["paper_verdict"] and short(r["paper_verdict"]), r["cause_brief"])
                if reason is not None and reason != said:  # say a reason where it first appears along the series
                    ax.annotate(short(r["paper_verdict"]) + ("\n" + r["cause_brief"] if r["cause_brief"] else ""),
                                (x, y), xytext=(6, (-4 - 20 * (idx % 2)) if k == 0 else (6 + 20 * (idx % 2))),
                                textcoords="offset points", fontsize=6, color=col, va="top" if k == 0 else "bottom")
                said = reason
                if r["d1_dt"]:
                    y1 = number(r["d1_dt"], path) / number(r["dt_crit"], path)
                    ratios.append(y1)
                    ax.plot([x], [y1], markers[k], mfc="none", color=col, ms=8,
                            mew=1.2 if r["d1_clean"] == "1" else 0.6, alpha=1.0 if r["d1_clean"] == "1" else 0.5)
                    ax.plot([x, x], [y, y1], ":", color=col, lw=0.8)
            ax.plot([], [], markers[k], color=col, ms=7,
                    label=f"{name}: clean at the paper's dt" + (" (drawn at 0.85 x its size)" if k else ""))
            ax.plot([], [], "x", color=col, ms=8, mew=2, label=f"{name}: not clean at the paper's dt")
        ax.plot([], [], "o", mfc="none", color="0.3", ms=7,
                label="rerun d1: dt = min(paper's, dt_crit / 2), guard off\n(bold: clean; faint: still not clean)")
        lo, hi = min(ratios + [0.05]) / 3.0, max(ratios + [1.0]) * 4.0
        ax.axhspan(lo, 1.0, **BAND_STYLE, label="dt <= dt_crit: predicted stable")
        ax.axhline(1.0, color="tab:green", ls=":", lw=1.2)
        ax.axvline(paper_size, **paper_style(ls=":", lw=1.5, label=paper_label))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(lo, hi)
        xs_all = [number(r["parameter"], path) for r in mine]
        ax.set_xlim(max(xs_all) * 2.5, min(xs_all) / 8.0)  # smaller to the right: past the paper's size
        ax.set_xlabel(f"{quantity} ({unit}); smaller to the right")
        ax.set_ylabel("time step / predicted critical step, dt / dt_crit")
        ax.set_title(TITLES.get(fam, fam), fontsize=10)
        ax.grid(alpha=0.3, which="major")
        ax.legend(fontsize=6.5, loc="upper left", framealpha=0.95)
    fig.suptitle("Beyond Paper A Sect. 5: the Sect. 5 scenes pushed past the paper's sizes, each run at the paper's dt "
                 "(geometry reconstructed, Figs. 13, 15, 17 lost)\nclean = finishes, no flip-through, energy error < 1 %, "
                 "asymmetry < 1e-9 m; dt_crit: the solver's predicted critical step", fontsize=10)
    save_tight(fig, out_png, rect=(0, 0, 1, 0.93))


if __name__ == "__main__":
    script_main(main, __doc__)
