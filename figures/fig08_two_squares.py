"""Paper A Fig. 8: x-velocities of the two colliding squares (Sect. 4.1).

usage: fig08_two_squares.py DATA_DIR OUT_PNG   (DATA_DIR from the two_squares driver)

Top: both blocks' x-velocities beside the paper's statement (the velocities
are exchanged: A stops, B leaves at A's 1 m/s) and the rows' bands at the end
of the run (|v_A| and |v_B - 1 m/s| below 0.01 m/s). Bottom: the momentum and
energy errors against their criteria (1e-9 and 1 %).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_common as paper  # noqa: E402
from paper_common import BAND_STYLE, paper_style  # noqa: E402
from potential_common import np, plt, read_csv, save_tight, script_main  # noqa: E402

# The rows' criteria (repro/4_1_two_squares/two_squares.hpp).
VELOCITY_TOL = 0.01  # m/s, kVelocityTol: on v_A and v_B - 1 m/s at the end
MOMENTUM_TOL = 1e-9  # relative, kMomentumTol
ENERGY_TOL = 1e-2    # relative, kEnergyTol
FLOOR = 1e-17        # zeros drawn at this level on the log axis


def main(data, out_png):
    _, d = read_csv(os.path.join(data, "velocity.csv"))
    t = d["time"]
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(8, 7.5), sharex=True, gridspec_kw={"height_ratios": [3, 2]})
    ax.plot(t, d["vx_A"], color="C0", lw=2.2, label="ours: block A")
    ax.plot(t, d["vx_B"], "--", color="C1", lw=2.2, label="ours: block B")
    # The paper's statement: after the collision the velocities are exchanged
    # (drawn from our contact's midpoint on; the paper gives no touch time).
    moving = np.abs(np.diff(d["vx_A"])) > 1e-9
    t_mid = 0.5 * (t[1:][moving][0] + t[1:][moving][-1]) if moving.any() else 0.5 * t[-1]
    ax.step([t[0], t_mid, t[-1]], [paper.A_41_SPEED, 0.0, 0.0], where="post", **paper_style())
    ax.step([t[0], t_mid, t[-1]], [0.0, paper.A_41_SPEED, paper.A_41_SPEED], where="post",
            **paper_style(label="paper (Sect. 4.1): velocities exchanged\n(A stops, B leaves at 1 m/s)"))
    for v in (0.0, paper.A_41_SPEED):
        ax.fill_between([t_mid, t[-1]], v - VELOCITY_TOL, v + VELOCITY_TOL, **BAND_STYLE)
    ax.fill_between([], [], [], **BAND_STYLE, label="pass band at t = %g s:\n+-%g m/s around the paper's" %
                    (t[-1], VELOCITY_TOL))
    ax.set_ylabel("x-velocity of the block centroid (m/s)")
    ax.set_title("Paper A Fig. 8: two 1 m squares, A at 1 m/s onto B at rest (kn 10 MPa, dt 1e-4 s)\n"
                 "the 0.5 m gap is ours (Fig. 7 lost)", fontsize=10)
    ax.legend(fontsize=8, loc="center right", bbox_to_anchor=(1.0, 0.45))
    ax.grid(alpha=0.3)

    p0 = d["momentum_x"][0]
    e0 = d["total_energy"][0]
    ax2.semilogy(t, np.maximum(np.abs(d["momentum_x"] - p0) / abs(p0), FLOOR), color="C2",
                 label="ours: |p - p0| / p0")
    ax2.semilogy(t, np.maximum(np.abs(d["total_energy"] - e0) / e0, FLOOR), color="C3",
                 label="ours: |E - E0| / E0")
    ax2.axhline(MOMENTUM_TOL, color="C2", ls=":", lw=1.2,
                label="momentum criterion %g (paper: momentum conserved)" % MOMENTUM_TOL)
    ax2.axhline(ENERGY_TOL, color="C3", ls=":", lw=1.2, label="energy criterion %g" % ENERGY_TOL)
    ax2.text(0.99, 0.03, "zeros drawn at %g" % FLOOR, transform=ax2.transAxes, ha="right", fontsize=7, color="0.4")
    ax2.set_ylim(FLOOR / 10.0, 1.0)
    ax2.set_xlabel("time (s)")
    ax2.set_ylabel("relative error")
    ax2.legend(fontsize=7, loc="center left", ncol=1)
    ax2.grid(alpha=0.3, which="major")
    save_tight(fig, out_png)


if __name__ == "__main__":
    script_main(main, __doc__)
