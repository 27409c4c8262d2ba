"""The papers' own stated values, drawn beside our results and labelled as the paper's.

Each value cites where it stands in the paper's text (the extracted text in
the shared papers directory: Paper A "potential contact, explicit DDA",
Paper B "two-scale contact, CDEM"); the papers' figures are lost, so only
numbers printed in the text are here. A figure draws these with paper_style()
so that a reader tells the paper's values from ours at a glance.
"""
import math

# ----------------------------------------------------------------------------
# Paper A
# ----------------------------------------------------------------------------
# Sect. 3.2.2: "In these examples, kn = 1 Pa and H = 1 m" (Figs. 4-5).
A_FIG45_KN = 1.0  # Pa
A_FIG45_H = 1.0   # m

# Sect. 4.1 and Table 4: A at 1 m/s along ox, B at rest; "the two blocks
# exchange their kinetic energy during the collision process and the results
# satisfy the conservation of momentum" -> after the impact v_A = 0,
# v_B = 1 m/s. Table 4: kn 10 MPa, dt 0.0001 s.
A_41_SPEED = 1.0        # m/s
A_41_KN = 10e6          # Pa
A_41_DT = 1e-4          # s

# Sect. 4.2: "the block system will move in a symmetric way during the
# collision process" (Fig. 10, after 1.0 s): mirror asymmetry zero.
A_42_DURATION = 1.0     # s

# Sect. 4.3, Eq. 30: l = 1/2 g (sin(theta) - cos(theta) tan(phi)) t^2, for
# "friction angle phi = 0, 10, 20 deg"; "Good agreements are obtained for
# numerical results and analytical results" (Fig. 12). The incline angle
# theta is not printed (Fig. 11 is lost).
A_43_PHIS = (0.0, 10.0, 20.0)  # deg


def a_eq30(g, theta_deg, phi_deg, t):
    """Paper A Eq. 30: the sliding distance of a block released from rest (m)."""
    th, ph = math.radians(theta_deg), math.radians(phi_deg)
    return 0.5 * g * (math.sin(th) - math.cos(th) * math.tan(ph)) * t * t


# Table 5 (Sect. 5): kn 50 MPa for 5.1-5.3; dt 0.0001 s (5.1, 5.3) and
# 0.00002 s (5.2).
A_5_KN = 50e6           # Pa
A_51_DT = 1e-4          # s
A_52_DT = 2e-5          # s
A_53_DT = 1e-4          # s
# Sect. 5.1: "In case 1, the height of B is 0.1 m while its height 1 m in case 2."
A_51_B_HEIGHTS = (0.1, 1.0)  # m
# Sect. 5.2: "Two identical triangles with a small angle of 5 deg ... with an
# initial velocity of 1 m/s ... the final configuration after 0.2 s".
A_52_APEX_DEG = 5.0
A_52_SPEED = 1.0        # m/s
A_52_DURATION = 0.2     # s
# Sect. 5.3: "the bottom block has a small edge of 0.01 m compared to the
# typical block size scale around 1 m. For this case, when block penetrations
# around 0.01 m is allowed ..."; "The configurations after 0.2 s".
A_53_SMALL_EDGE = 0.01  # m
A_53_PENETRATION = 0.01  # m ("around")
A_53_DURATION = 0.2     # s

# Sect. 6.1: "Comparison of the simulation results at 2.5 s, 5.0 s, and 7.5 s
# using different joint friction angles (case 1 of 15 deg and case 2 of
# 30 deg)"; "A faster collapsing process and a larger runout mass were
# observed with lower friction angle."
A_61_TIMES = (2.5, 5.0, 7.5)  # s
A_61_FRICTION = (15.0, 30.0)  # deg
# Sect. 6.2: "total simulation time 3.5 s"; "The left part will fail in
# slumping pattern, while the right part will fail with toppling pattern."
A_62_DURATION = 3.5     # s

# ----------------------------------------------------------------------------
# Paper B (Sect. 6, "Verification examples")
# ----------------------------------------------------------------------------
# "The time step is 5 x 10^-4 s ... The initial velocity of block i is
# 3.0 m/s, and that of block j is 0.0 m/s ... Their initial distance is 1 m".
B_DT = 5e-4             # s
B_SPEED_I = 3.0         # m/s
B_GAP = 1.0             # m
# "At a time of 0.3333 s, vertex A of block i touches the edge of block j.
# Here, the time of 0.3333 s is in the step from 0.3335 to 0.3340 s".
B_TOUCH = 0.3333        # s
B_TOUCH_STEP = (0.3335, 0.3340)  # s, as printed
# "The velocity of block j is increased from 0.0 to 3.205 m/s (Figure 14(c))";
# Fig. 14: "(a) 0.3335 s; (b) 0.3340 s; (c) 0.3400 s".
B_VJ_FIG14C = 3.205     # m/s
B_FIG14_TIMES = (0.3335, 0.3340, 0.3400)  # s
# Fig. 15: "Separation of the unified node, and the two blocks. (a) 0.3405 s;
# (b) 0.4960 s."
B_FIG15_TIMES = (0.3405, 0.4960)  # s
# Fig. 16: "the velocity of block j after collision is approximately equal to
# the initial velocity of block i. A little energy loss occurs".
B_VJ_AFTER = B_SPEED_I  # m/s ("approximately equal")

# ----------------------------------------------------------------------------
# Drawing
# ----------------------------------------------------------------------------
PAPER_COLOUR = "black"


def paper_style(**extra):
    """Line style of a paper's value: thin black dash-dot, under our curves."""
    style = dict(color=PAPER_COLOUR, ls="-.", lw=1.0, zorder=1.5)
    style.update(extra)
    return style


BAND_STYLE = dict(color="tab:green", alpha=0.15, lw=0, zorder=0)
