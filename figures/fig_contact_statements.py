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
from potential_common import finite, plt, read_rows, save_atomic  # noqa: E402

FLOOR = 1e-16  # errors below are drawn at this level (log axis)


def main(data_dir, out_png):
    rows = read_rows(os.path.join(data_dir, "gradient.csv"))
    depth = [finite(r["depth"]) for r in rows]
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    for key, label, style in (("error_paper", "paper's segmentation (Sect. 3.2.3)", "o"),
                              ("error_exact", "exact integration (not the paper's)", "s")):
        err = [max(finite(r[key]), FLOOR) for r in rows]
        ax.loglog(depth, err, style, ms=2.5, alpha=0.6, label=label)
    ax.axhline(1e-6, color="k", ls="--", lw=1, label="criterion 1e-6")
    ax.set_xlabel("overlap depth: inscribed diameter of the intersection polygon (m)")
    ax.set_ylabel("|f + grad E| / |grad E|")
    ax.set_title(f"Eqs. 10-11 on {len(rows)} random convex pairs: force against the energy's gradient", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    save_atomic(fig, out_png)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2])
