"""Beyond Paper A Sect. 5: the extreme-geometry table (smaller angles, edges, thinner blocks) as a figure.

usage: fig_extreme_geometry.py DATA_DIR OUT_PNG   (DATA_DIR from the extreme_geometry driver)
"""
import csv
import math
import os
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import plt, save_atomic  # noqa: E402

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
with open(os.path.join(sys.argv[1], "table.csv"), newline="") as f:
    rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
if not rows:
    raise SystemExit("table.csv: no rows")


def num(text, unit=""):
    if text == "":
        return ""
    x = float(text)
    if not math.isfinite(x):
        raise SystemExit("table.csv: non-finite value")
    return "n/a" if x < 0 else "%.2g%s" % (x, unit)


header = ["case", "dt (s)", "dt_crit (s)", "at the paper's dt", "energy err.", "asymmetry", "peak overlap",
          "cause (d1 stable dt, guard off; d2 exact; d3 dt/10)", "d1: stable dt, guard off"]
def short(verdict):
    """First clause of a verdict; names the solver guard that stopped a run."""
    if verdict.startswith("stopped"):
        for key, name in (("a vertex moved", "step-motion guard"), ("energy grew", "energy guard"),
                          ("non-finite", "non-finite state"), ("area collapsed", "collapsed block")):
            if key in verdict:
                return "stopped: " + name
        return "stopped by the solver"
    return verdict.split(":")[0].split(";")[0]


cells, colours = [], []
for r in rows:
    clean = r["paper_clean"] == "1"
    verdict = "clean" if clean else short(r["paper_verdict"])
    d1 = "" if clean else ("clean" if r["d1_clean"] == "1" else short(r["d1_verdict"]))
    cells.append([r["family"] + " " + r["case"], num(r["paper_dt"]), num(r["dt_crit"]), verdict,
                  num(r["paper_energy_error"]) if r["paper_verdict"][:7] != "stopped" else "-",
                  num(r["paper_asymmetry"], " m") if r["paper_verdict"][:7] != "stopped" else "-",
                  num(r["paper_overlap_thickness"], " m") if r["paper_verdict"][:7] != "stopped" else "-",
                  "\n".join(textwrap.wrap(r["cause_brief"], 60)), d1])
    colours.append(["#d9f2d9" if clean else "#f8d7d7"] * len(header))
fig, ax = plt.subplots(figsize=(17, 0.42 * len(rows) + 1.6))
ax.axis("off")
t = ax.table(cellText=cells, colLabels=header, cellColours=colours, loc="center", cellLoc="left")
t.auto_set_font_size(False)
t.set_fontsize(7)
t.auto_set_column_width(list(range(len(header))))
for (i, _), c in t.get_celld().items():
    c.set_height(0.9 / (len(rows) + 1))
ax.set_title("Beyond Paper A Sect. 5 (reconstructed scenes): green = clean at the paper's dt (finishes, no "
             "flip-through, energy error < 1 %, asymmetry < 1e-9 m)", fontsize=10)
save_atomic(fig, sys.argv[2])
