"""Paper A Fig. 16: collision of two triangles with a 5 degree angle (Sect. 5.2).

usage: fig16_small_angles.py DATA_DIR OUT_PNG   (DATA_DIR from the small_angles driver)

Left: the triangles at t = 0 and at the end, the traces of the 5 deg apexes
and of the centroids, and the point image of the lower triangle's traces
through the collision centre (the paper's statement: the two move
symmetrically about it, so the image lies on the upper triangle's traces).
Right: the point-symmetry error and the overlap thickness (m), and the
energy error, each with its row's criterion.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paper_common import BAND_STYLE, paper_style  # noqa: E402
from potential_common import np, plt, read_csv, save_tight, script_main, snapshot_outlines  # noqa: E402

# The rows' criteria (repro/5_2_small_angles/small_angles.hpp).
SYMMETRY_TOL = 1e-9  # m, kSymmetryTol
ENERGY_TOL = 0.01    # relative, kEnergyTol
FLOOR = 1e-18        # zeros drawn at this level on the log axes


def draw_snapshots(ax, sn):
    times = np.unique(sn["time"])
    for t, style in zip([times[0], times[-1]], [dict(color="0.65", lw=1.0), dict(color="k", lw=1.3)]):
        for x, y in snapshot_outlines(sn, sn["time"] == t):
            ax.fill(x, y, fc="none", ec=style["color"], lw=style["lw"])
    ax.plot([], [], color="0.65", label="triangles at t = 0")
    ax.plot([], [], color="k", label="triangles at t = %.2f s" % times[-1])
    return times


def main(data, out_png):
    notes, tr = read_csv(os.path.join(data, "traces.csv"))
    _, sn = read_csv(os.path.join(data, "snapshots.csv"))
    fig = plt.figure(figsize=(14, 6.2))
    gs = fig.add_gridspec(2, 2, width_ratios=[3, 2])
    ax = fig.add_subplot(gs[:, 0])
    times = draw_snapshots(ax, sn)
    ax.plot(tr["apex0_x"], tr["apex0_y"], "C0-", lw=1.6, label="ours: 5 deg apex of the lower triangle")
    ax.plot(tr["apex1_x"], tr["apex1_y"], "C1-", lw=1.6, label="ours: 5 deg apex of the upper triangle")
    ax.plot(tr["c0_x"], tr["c0_y"], "C0:", lw=1.8, label="ours: centroid, lower")
    ax.plot(tr["c1_x"], tr["c1_y"], "C1:", lw=1.8, label="ours: centroid, upper")
    # The paper's statement: point symmetry through the collision centre (0, 0).
    ax.plot(-tr["apex0_x"], -tr["apex0_y"], **paper_style(lw=1.2, zorder=4),
            label="paper (Sect. 5.2): symmetric about the collision centre;\n"
                  "point image of the lower triangle's traces")
    ax.plot(-tr["c0_x"], -tr["c0_y"], **paper_style(lw=1.2, zorder=4))
    ax.plot([0], [0], "r+", ms=12, mew=2, label="collision centre (0, 0)")
    ax.set_aspect("equal")
    ax.set_ylim(-0.62, 0.42)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.legend(fontsize=7, loc="lower center", ncol=2, framealpha=0.95)
    ax.set_title("Paper A Fig. 16: two 5 deg triangles at +-1 m/s, configuration after %.2f s\n"
                 "(geometry reconstructed, Fig. 15 lost; kn 50 MPa, dt 2e-5 s, frictionless)" % times[-1], fontsize=10)
    ax.grid(alpha=0.2)

    a1 = fig.add_subplot(gs[0, 1])
    a1.axhspan(FLOOR, SYMMETRY_TOL, **BAND_STYLE)
    a1.semilogy(tr["time"], np.maximum(tr["asymmetry"], FLOOR), "k-",
                label="ours: point-symmetry error, max |v0_k + v1_k - 2c|")
    a1.axhline(SYMMETRY_TOL, color="tab:green", ls=":", label="pass band: < %g m (paper: symmetric)" % SYMMETRY_TOL)
    a1.semilogy(tr["time"], np.maximum(tr["overlap_thickness"], FLOOR), "C3-",
                label="ours: overlap thickness (information)")
    a1.set_ylim(FLOOR, 1.0)
    a1.set_ylabel("length (m)")
    a1.set_title("symmetry and penetration (zeros drawn at %g)" % FLOOR, fontsize=9)
    a1.legend(fontsize=7, loc="center right")
    a1.grid(alpha=0.3)
    a2 = fig.add_subplot(gs[1, 1], sharex=a1)
    e = tr["total_energy"]
    a2.axhspan(FLOOR, ENERGY_TOL, **BAND_STYLE)
    a2.semilogy(tr["time"], np.maximum(np.abs(e - e[0]) / e[0], FLOOR), "C2-", label="ours: |E - E0| / E0")
    a2.axhline(ENERGY_TOL, color="tab:green", ls=":", label="pass band: < %g" % ENERGY_TOL)
    a2.set_ylim(1e-8, 1.0)
    a2.set_xlabel("time (s)")
    a2.set_ylabel("relative energy error")
    a2.legend(fontsize=7, loc="lower right")
    a2.grid(alpha=0.3)
    save_tight(fig, out_png)


if __name__ == "__main__":
    script_main(main, __doc__)
