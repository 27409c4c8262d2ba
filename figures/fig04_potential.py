"""Paper A Fig. 4b: shortest-exit potential of a convex polygon with small edges.

usage: fig04_potential.py DATA_DIR OUT_PNG   (DATA_DIR from the potential_fields driver)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import draw_potential  # noqa: E402

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
data, out = sys.argv[1], sys.argv[2]
draw_potential(os.path.join(data, "fig04b_grid.csv"), os.path.join(data, "fig04b_outline.csv"),
               "Paper A Fig. 4b: shortest-exit potential (Eqs. 12-14), polygon with small edges\n"
               "(geometry reconstructed, figure lost; kn = 1 Pa, H = 1 m as in Sect. 3.2.2)",
               out, highlight_below=0.1)
