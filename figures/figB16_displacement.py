"""Paper B Fig. 16: x-displacement of the two prisms through the collision, with the paper's numbers.

usage: figB16_displacement.py DATA_DIR OUT_PNG   (DATA_DIR from B_6_two_prisms)

Left: the blocks' mass-weighted x-displacements (history.csv, and block j
without subdivision, history_nosub.csv) beside the paper's touch at 0.3333 s
and its statement that j leaves at about i's initial 3.0 m/s (drawn as the
slope of j's displacement from the touch on). Right: the velocities through
the contact beside the paper's 3.205 m/s at Fig. 14c (0.3400 s) with the
row's band (j's largest nodal x-velocity there above 3.0 m/s and within 10 %
of 3.205 m/s), the paper's touch step 0.3335-0.3340 s and its Fig. 14-15
times. Each curve names the subdivision mode its file records.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_common as paper  # noqa: E402
from cdem_common import plt, read_table, save_atomic  # noqa: E402
from paper_common import BAND_STYLE, paper_style  # noqa: E402
from potential_common import script_main  # noqa: E402

# The Fig. 14c row's band (repro/B_6_two_prisms/two_prisms.hpp, fig14c_met):
# j's largest nodal x-velocity at 0.3400 s above 3.0 m/s and within 10 % of 3.205 m/s.
FIG14C_REL = 0.10


def mode_of(notes):
    """The subdivision mode a file records ('subdivision mode: ...'), or says it does not."""
    return next((n.split(":", 1)[1].strip() for n in notes if n.startswith("subdivision mode:")), "mode not recorded")


def main(data, out_png):
    notes, h = read_table(os.path.join(data, "history.csv"))
    notes0, h0 = read_table(os.path.join(data, "history_nosub.csv"))
    mode, mode0 = mode_of(notes), mode_of(notes0)
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(14, 6.0), layout="constrained")
    fig.get_layout_engine().set(rect=(0.0, 0.05, 1.0, 0.95))  # room for the notes below
    ax.plot(h["time"], h["ux_i"], color="C0", lw=1.8, label="ours: block i")
    ax.plot(h["time"], h["ux_j"], color="C1", lw=1.8, label="ours: block j")
    ax.plot(h0["time"], h0["ux_j"], ":", color="C1", lw=1.5, label="ours: block j, no subdivision")
    t_end = float(h["time"][-1])
    ax.axvline(paper.B_TOUCH, **paper_style(ls="--", label="paper: touch at %.4f s" % paper.B_TOUCH))
    ax.plot([paper.B_TOUCH, t_end], [0.0, paper.B_VJ_AFTER * (t_end - paper.B_TOUCH)],
            **paper_style(label="paper (Fig. 16): j leaves at about i's initial %.1f m/s" % paper.B_VJ_AFTER))
    ax.plot([0.0, paper.B_TOUCH], [0.0, paper.B_SPEED_I * paper.B_TOUCH],
            **paper_style(ls=":", label="paper: i at %.1f m/s, 1 m gap" % paper.B_SPEED_I))
    ax.set_xlabel("time (s)")
    ax.set_ylabel("x-displacement, mass-weighted mean of the block (m)")
    ax.set_title("Paper B Fig. 16: x-displacements of the two prisms", fontsize=10)
    ax.legend(fontsize=7.5, loc="upper left")
    ax.grid(alpha=0.3)

    lo_t, hi_t = 0.330, 0.350
    w = (h["time"] > lo_t) & (h["time"] < hi_t)
    w0 = (h0["time"] > lo_t) & (h0["time"] < hi_t)
    band_lo = max(paper.B_SPEED_I, (1.0 - FIG14C_REL) * paper.B_VJ_FIG14C)
    band_hi = (1.0 + FIG14C_REL) * paper.B_VJ_FIG14C
    t14c = paper.B_FIG14_TIMES[2]
    ax2.fill_between([t14c - 0.00025, t14c + 0.00025], band_lo, band_hi, **BAND_STYLE,
                     label="pass band at Fig. 14c: largest nodal v_x in j\nin (3.0, 3.205 x 1.1] m/s")
    ax2.axvspan(*paper.B_TOUCH_STEP, color="0.85", lw=0, zorder=0, label="paper: touch 'in the step from "
                "0.3335 to 0.3340 s'")
    ax2.plot(h["time"][w], h["vx_i"][w], color="C0", lw=1.6, label="ours: v_x of block i (mean)")
    ax2.plot(h["time"][w], h["vx_j"][w], color="C1", lw=1.6, label="ours: v_x of block j (mean)")
    ax2.plot(h["time"][w], h["vx_max_j"][w], "--", color="C1", lw=1.0, label="ours: largest nodal v_x in j")
    ax2.plot(h0["time"][w0], h0["vx_j"][w0], ":", color="C1", lw=1.5, label="ours: v_x of j, no subdivision")
    ax2.plot([t14c], [paper.B_VJ_FIG14C], "*", color="k", ms=12, zorder=7,
             label="paper (Fig. 14c): j 'from 0.0 to %.3f m/s' at %.4f s" % (paper.B_VJ_FIG14C, t14c))
    ax2.axhline(paper.B_VJ_AFTER, **paper_style(label="paper (Fig. 16): j after the collision ~ %.1f m/s" %
                                               paper.B_VJ_AFTER))
    ax2.axvline(paper.B_TOUCH, **paper_style(ls="--"))
    for t, lab in zip(paper.B_FIG14_TIMES + paper.B_FIG15_TIMES[:1], ("14a", "14b", "14c", "15a")):
        ax2.axvline(t, color="0.7", lw=0.6)
        ax2.text(t, -0.25, lab, fontsize=7, color="0.35", rotation=90, va="bottom", ha="right")
    ax2.set_xlim(lo_t, hi_t)
    ax2.set_ylim(-0.35, 3.9)
    ax2.set_xlabel("time (s); grey lines: the paper's Fig. 14-15 times")
    ax2.set_ylabel("x-velocity (m/s)")
    ax2.set_title("velocities through the contact, beside the paper's numbers", fontsize=10)
    ax2.legend(fontsize=7, loc="lower right", bbox_to_anchor=(1.0, 0.08))
    ax2.grid(alpha=0.3)
    geometry = next((n.split("; ", 1)[1] for n in notes if "rebuilt" in n and "; " in n), "")
    fig.suptitle("Paper B Sect. 6: two prisms, i at 3.0 m/s onto j at rest, dt 5e-4 s, ours beside the paper's numbers\n"
                 "solid and dashed: subdivision mode '%s'; dotted: '%s'" % (mode, mode0), fontsize=10)
    fig.text(0.01, 0.005, "Geometry reconstructed: " + geometry, fontsize=7.5, color="0.3", va="bottom")
    save_atomic(fig, out_png)


if __name__ == "__main__":
    script_main(main, __doc__)
