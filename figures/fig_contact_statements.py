"""Paper A Eqs. 10-11: is the normal force the negative gradient of the contact energy?

usage: fig_contact_statements.py DATA_DIR OUT_PNG
  DATA_DIR from the contact_statements driver (gradient.csv).

One point per random overlapping convex pair: the force's relative distance
from the energy gradient, |f + grad E| / |grad E|, against how deep the
overlap is (the intersection polygon's inscribed diameter), for the paper's
segmentation (Sect. 3.2.3) and the exact integration. The dashed line is the
row's criterion (1e-6); points at 1e-16 are exact to round-off.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paper_common import BAND_STYLE, paper_style  # noqa: E402
from potential_common import finite, plt, read_rows, save_atomic, script_main  # noqa: E402

FLOOR = 1e-16      # errors below are drawn at this level (log axis)
TOLERANCE = 1e-6   # the rows' criterion on every pair (repro/3_1_contact_statements/contact_statements.hpp, gradient_row)


def main(data_dir, out_png):
    rows = read_rows(os.path.join(data_dir, "gradient.csv"))
    depth = [finite(r["depth"]) for r in rows]
    fig, ax = plt.subplots(figsize=(8.5, 5.5))
    lo = min(min(finite(r["error_paper"]), finite(r["error_exact"])) for r in rows)
    ax.axhspan(max(lo, FLOOR) / 10.0, TOLERANCE, **BAND_STYLE, label="pass band: < %g on every pair" % TOLERANCE)
    for key, label, style in (("error_paper", "ours, the paper's segmentation (Sect. 3.2.3)", "o"),
                              ("error_exact", "ours, exact integration (an option, not the paper's)", "s")):
        err = [max(finite(r[key]), FLOOR) for r in rows]
        worst = max(err)
        ax.loglog(depth, err, style, ms=2.5, alpha=0.6, label="%s: largest %.2g" % (label, worst))
    ax.axhline(TOLERANCE, color="tab:green", ls=":", lw=1.2)
    ax.plot([], [], **paper_style(), label="paper (Eqs. 10-11): f = -grad E exactly (error 0)")
    ax.set_ylim(max(lo, FLOOR) / 10.0, 1e7)  # room for the legend above the points
    ax.set_xlabel("overlap depth: inscribed diameter of the intersection polygon (m)")
    ax.set_ylabel("relative error of the force, |f + grad E| / |grad E|")
    ax.set_title(f"Paper A Eqs. 10-11: is the normal force the negative gradient of the contact energy?\n"
                 f"{len(rows)} random overlapping convex pairs (grad E by central differences of the exact energy)",
                 fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper center", framealpha=0.95)
    save_atomic(fig, out_png)


if __name__ == "__main__":
    script_main(main, __doc__)
