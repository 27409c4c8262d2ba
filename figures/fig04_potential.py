"""Paper A Fig. 4b: shortest-exit potential of a convex polygon with small edges.

usage: fig04_potential.py DATA_DIR OUT_PNG   (DATA_DIR from the potential_fields driver)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import draw_potential, script_main  # noqa: E402

TITLE = ("Paper A Fig. 4b: shortest-exit potential (Eqs. 12-14), polygon with small edges\n"
         "(geometry reconstructed, figure lost; kn = 1 Pa, H = 1 m as in Sect. 3.2.2)")

if __name__ == "__main__":
    script_main(lambda data, out: draw_potential(data, "fig04b", TITLE, out, highlight_below=0.1), __doc__)
