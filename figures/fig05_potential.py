"""Paper A Fig. 5: shortest-exit potential of a concave polygon.

usage: fig05_potential.py DATA_DIR OUT_PNG   (DATA_DIR from the potential_fields driver)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import draw_potential, script_main  # noqa: E402

TITLE = ("Paper A Fig. 5: shortest-exit potential (Eq. 12: distance to the boundary), concave polygon\n"
         "(geometry reconstructed, figure lost; kn = 1 Pa, H = 1 m as in Sect. 3.2.2)")

if __name__ == "__main__":
    script_main(lambda data, out: draw_potential(data, "fig05", TITLE, out), __doc__)
