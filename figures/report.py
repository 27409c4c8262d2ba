"""Merge every claims CSV into the reproduction report (Markdown) and a JSON file.

usage: report.py [--build DIR] [--started EPOCH] CLAIMS_DIR REPORT_MD [CLAIMS_JSON]

Each <CLAIMS_DIR>/<driver>.csv is written by a driver (repro/common/claims.hpp)
with the columns of COLUMNS. Every row has
  - a scope: 'paper' (a statement the paper makes, quoted with where it
    stands), 'extension' (a test beyond the paper), 'option' (our option
    beside a paper-method row) or 'suite' (the suite's own guards, integrator
    orders, work-precision, stability maps);
  - a kind: 'check' (a criterion computed from the run that can come out
    FAIL, with a negative control: the same criterion applied to a
    deliberately wrong configuration FAILs in make test), 'fitted' (a check
    on a scene whose geometry or parameter was fitted to the number it
    checks: shown, never counted as reproduced) or 'measurement' (a number
    with no verdict). A check without a negative control is listed with the
    measurements;
  - for a failing check: a cause category (CAUSES), a root cause (ROOTS: one
    paragraph of the report each) and the full text (claims.json).

The report: provenance (commit, compiler and flags from the build tree --build,
machine, OS, date, wall time since --started, the scenes on reconstructed
geometry), then per paper "X of Y of its claims reproduced" with the
extensions, options and suite tests on lines of their own, the ledger of each
paper's own claims in the paper's order, the root causes of the failing rows,
then each scene with its figures and rows, and a glossary of the options.
Table cells are cut to MAX_CELL characters (the full texts are in the JSON).
The JSON file holds every row (all columns, the driver and the row's class).
An unreadable file, a row with an unknown scope, kind, status or root cause,
or a row whose text names source files or the project's history is listed
under "Problems" (an unreadable row is counted as a failing check).
Outputs are written atomically.
"""
import csv
import datetime
import glob
import json
import os
import platform
import re
import subprocess
import sys
import time

COLUMNS = ["id", "section", "scope", "kind", "claim", "paper", "measured", "tolerance", "status", "cause",
           "root_cause", "cause_text", "control", "run_time_s"]
SCOPES = {"paper": "the paper's claims", "extension": "tests beyond the paper",
          "option": "our options beside the paper's method", "suite": "the suite's own tests"}
KINDS = ("check", "fitted", "measurement")
# Cause categories of a failing check. (The report never prints the word
# "spec" in any form: its text is checked against FORBIDDEN.)
CAUSES = {"paper_method": "the paper's method as published",
          "missing_data": "data the paper does not give, or gives inconsistently",
          "our_reading": "our reading of a section the paper leaves incomplete",
          "implementation": "our implementation"}
MAX_CELL = 300      # characters of a table cell
LEDGER_CELL = 200   # characters of a ledger cell (the reviewer's first table)
LEDGER_CLAIM = 120  # characters of the ledger's "what we checked" cell
# What the report's text must not contain: development history, the project's
# source files and code identifiers (the rows speak of the papers).
FORBIDDEN = re.compile(r"issue [0-9]|item [0-9]|spec|\.cpp|\.hpp|::", re.IGNORECASE)

# ---------------------------------------------------------------------------
# The scenes. Per driver: (paper, heading, the paper's statement, figure files
# under out/figures, what is reconstructed or None). Paper is "Paper A",
# "Paper B", "Both papers" (a comparison of their methods) or "Suite".
# ---------------------------------------------------------------------------
DRIVERS = {
    "3_1_exact_geometry": ("Paper A", "Sect. 3.1.3: the intersection polygon, against an exact intersection",
                           "The contact integrals run over the intersection polygon of the two blocks.", [], None),
    "3_1_contact_statements": ("Paper A", "Sects. 3.1.2, 3.2.1, 3.2.4: entrance block, the force as the energy "
                               "gradient, Eq. 20",
                               "A and B overlap if and only if a0 lies in the entrance block E (Sect. 3.1.2); the "
                               "normal force is the negative gradient of the contact energy (Eqs. 10-11) and acts on a "
                               "line through pg (Eq. 20).", ["fig_contact_statements.png"], None),
    "3_2_2_potential_fields": ("Paper A", "Sect. 3.2.2: the new potential function (Figs. 4b, 5)",
                               "The potential is defined at every point inside a polygon, zero on its boundary, "
                               "proportional to the distance to the boundary (Eqs. 12-14), for convex and concave "
                               "polygons and small edges alike.", ["fig04b_potential.png", "fig05_potential.png"],
                               "the polygons of Figs. 4 and 5"),
    "3_2_2_previous_potential": ("Paper A", "Sect. 3.2.2: the previous sub-polygon potential (Fig. 4a)",
                                 "The previous sub-polygon potential leaves an inner region undefined and depends "
                                 "on the edge lengths (Fig. 4a).", ["fig04a_previous_potential.png"],
                                 "the polygon of Fig. 4a and the previous definition's construction"),
    "4_1_two_squares": ("Paper A", "Sect. 4.1: collision of two identical polygons (Figs. 7-8)",
                        "Two identical squares collide; the velocities are exchanged and momentum is conserved.",
                        ["fig08_two_squares.png"], None),
    "4_2_symmetric_stack": ("Paper A", "Sect. 4.2: a polygon on a symmetric polygonal stack (Figs. 9-10)",
                            "The response of the symmetric stack stays symmetric.", ["fig10_symmetric_stack.png"],
                            "the stack of Fig. 9"),
    "4_3_incline": ("Paper A", "Sect. 4.3: sliding block on an inclined plane (Figs. 11-12)",
                    "The sliding distance follows the analytic solution (Eq. 30): 'Good agreements' (Fig. 12).",
                    ["fig12_incline.png"], "the incline of Fig. 11: slope angle and block size"),
    "5_1_bouncing_block": ("Paper A", "Sect. 5.1: polygons of different sizes (Figs. 13-14)",
                           "'The current approach using a unified H value lead to very similar block bouncing "
                           "response' for the two cases, while the inscribed radius leads 'to significantly "
                           "different block bouncing response'.", ["fig14_bouncing_block.png"],
                           "the blocks of Fig. 13 apart from B's heights"),
    "5_2_small_angles": ("Paper A", "Sect. 5.2: polygons with small angles (Figs. 15-16)",
                         "'The two triangles move symmetrically regarding the collision centroid'.",
                         ["fig16_small_angles.png"], "the triangles of Fig. 15 apart from the 5 deg angle"),
    "5_3_small_edges": ("Paper A", "Sect. 5.3: polygons with small edges (Figs. 17-18)",
                        "'The results show the proposed approach can treat contacts of small edges with good "
                        "robustness'.", ["fig18_small_edges.png"], "the blocks of Fig. 17 apart from the 0.01 m edge"),
    "5_4_extreme_geometry": ("Paper A", "Beyond Sect. 5: extreme geometry",
                             "Not in the paper (it stops at 5 deg and 0.01 m): how small angles and edges can get.",
                             ["extreme_geometry.png"], "the Sect. 5 scenes, scaled"),
    "5_5_segmentation": ("Paper A", "Beyond Sect. 3.2.3: is the paper's segmentation exact?",
                         "The segmentation of the contact (Sect. 3.2.3) against exact integration of Eqs. 10-11.",
                         ["segmentation_study.png"], None),
    "6_1_collapse": ("Paper A", "Sect. 6.1: frictional collapse of a rock mass (Figs. 19-20)",
                     "'A faster collapsing process and a larger runout mass were observed with lower friction "
                     "angle.'", ["fig20_collapse.png", "fig20_collapse_runout.png", "anim_collapse_case1.gif"],
                     "the slope and boundary of Fig. 19 around the 20 m x 50 m region"),
    "6_2_toppling_slumping": ("Paper A", "Sect. 6.2: rock toppling and slumping (Figs. 21-22)",
                              "'The left part will fail in slumping pattern, while the right part will fail with "
                              "toppling pattern.'", ["fig22_toppling.png"], "the valley of Fig. 21"),
    "B_6_two_prisms": ("Paper B", "Sect. 6: two prisms, two-scale contact (Figs. 12-16)",
                       "Vertex A touches j's edge at 0.3333 s; j's velocity 'is increased from 0.0 to 3.205 m/s'; "
                       "the clone node separates (Fig. 15a, 0.3405 s); momentum is conserved with 'a little energy "
                       "loss'.", ["figB13_15_prisms.png", "figB16_displacement.png"],
                       "the prisms of Fig. 12, whose dimensions the text does not give"),
    "B_7_contact_comparison": ("Both papers", "Penalty (A) against two-scale (B) contact on the same collisions",
                               "A comparison neither paper makes: touch time, momentum, energy and contact duration.",
                               ["figB_comparison.png"], "Paper B's prisms, as in Sect. 6"),
    "B_8_bar_waves": ("Both papers", "Waves against theory: two elastic bars head on",
                      "Not in the papers: 1D bar theory (contact 2L/c, stress rho c v / 2, velocities exchanged) "
                      "against CDEM with and without subdivision and Paper A's 6-DOF blocks.",
                      ["figB_bar_waves.png"], None),
    "B_9_impact_study": ("Paper B", "Beyond Sect. 6: an impact study of the two-scale contact",
                         "Not in the paper: oblique impacts of two squares over angle, speed, friction and "
                         "subdivision, against no pass-through, energy, Eq. 5 and the rigid-body Coulomb impact law.",
                         ["figB_impact_study.png"], None),
    "S1_work_precision": ("Suite", "S1: work precision, error against run time",
                          "Not in the papers: convergence orders and conservation of the integration.",
                          ["figS1a_two_squares.png", "figS1b_incline.png", "figS1c_resting_block.png",
                           "figS1d_triangles.png", "figS1e_bouncing_block.png", "figS1f_small_edge.png",
                           "figS1g_free_rotation.png", "figS1h_damped_flight.png"], None),
    "S2_stability_maps": ("Suite", "S2: stability maps and the critical time step",
                          "Not in the papers: the predicted critical step against the linearised and empirical "
                          "limits.", ["figS2_stability_maps.png"], None),
    "S3_penetration_map": ("Suite", "S3: penetration map",
                           "Not in the papers: where two blocks would pass through each other, the penetration "
                           "guard stops the run.", ["figS3_penetration_map.png"], None),
    "S3_extreme_cases": ("Suite", "S3: extreme cases",
                         "Not in the papers: high speed, deep penetration, stiff contacts and the guards.", [], None),
}
PAPER_ORDER = ["Paper A", "Paper B", "Both papers", "Suite", "Other"]

# What of each paper is out of scope, and why (the ledger lists it).
OUT_OF_SCOPE = {
    "Paper A": [
        "Figs. 1-3 and 6 (the method's sketches) and Tables 1-3 (the detection algorithms): lost with the figures; "
        "the algorithms are rebuilt from the text and tested on their own statements (Sects. 3.1-3.2).",
        "The exact curves of Figs. 8, 10, 12, 14, 16, 18, 20 and 22: the paper prints no numbers for them; we "
        "check what the text says of each figure, and draw the rebuilt scenes beside the analytic values where "
        "there are any (Eq. 30).",
        "Sect. 1-2 (review, the DDA equations): the basis of the method, exercised by every scene, not claims "
        "with a result to compare.",
        "Sect. 7's summary of contributions: the statements it repeats are the rows of Sects. 3-6.",
    ],
    "Paper B": [
        "Sect. 2's three-dimensional contact detection (shrunken edges, six contact types, Figs. 1-3): the "
        "reproduction is two-dimensional, as the paper's example is.",
        "Eqs. 2, 3, 5 and 11 as printed: lost from the text we have; the model uses the standard constant-strain "
        "triangle and the inelastic-impact loss of two point masses, which Eq. 4 and the surrounding text "
        "determine.",
        "The prisms' dimensions and mesh (Fig. 12 lost): rebuilt; rows that need them say so.",
        "Sect. 7's future work (mesh equality, many contact nodes, sliding contact nodes, parallel refinement): "
        "not claims of the paper.",
    ],
}

# ---------------------------------------------------------------------------
# Root causes: each failing check names one (its root_cause column). Per key:
# title, cause category, the argument in words, the option that fixes it (a
# key of OPTIONS, or None) and the rows whose numbers are the evidence (ids
# "<driver>/<row id>"; the report prints their measured values and verdicts).
# ---------------------------------------------------------------------------
ROOTS = {
    "friction_start_up": (
        "The finite tangential spring, loaded at once at the start", "paper_method",
        "Every contact starts with an unloaded stick spring of the paper's finite kt (Sect. 3.2.5, Eq. 25), and "
        "the paper's undamped explicit scheme applies gravity at once. The spring overshoots: on the incline the "
        "block gains a lead in its stick phase that rigid Coulomb friction (Eq. 30) does not have, and rocks on "
        "its soft contact; on a slope that friction should hold, the block slips in its stick oscillations; in "
        "the valley of Sect. 6.2 each slope slides on its base before the springs hold it, and then ratchets on "
        "at every re-stick of Eq. 26. A stiffer kt, a smaller dt or the exact integration do not close the gap; "
        "starting from a settled state with loaded springs does.",
        "friction_start_up",
        ["4_3_incline/4.3 (option):phi-20-deg-friction-start-up-option-settled-with-sticking-contacts-not-t",
         "4_3_incline/4.3 (option):rest-start-up",
         "6_2_toppling_slumping/6.2 (option):premise-each-slope-as-one-block-stays-on-its-30-deg-base-friction-32-deg"]),
    "friction_update": (
        "Eq. 26 restarts a sliding pair's spring from zero shear", "paper_method",
        "After a sliding step the paper keeps only that step's relative displacement (Sect. 3.2.6), so a pair "
        "that sticks again starts from zero shear: a block that slid to a stop on a slope its friction can hold "
        "creeps on, step by step. An elastic-plastic return mapping keeps the shear at the friction limit and "
        "the block stays put.",
        "return_mapping",
        ["4_3_incline/4.3 (option):creep-a-block-that-slid-to-a-stop-on-a-slope-gentler-than-its-friction-a"]),
    "segmentation": (
        "The paper's segmentation is not the contact energy's gradient", "paper_method",
        "Sect. 3.2.3 splits each edge of the intersection polygon at its ends, its midpoint and the crossings "
        "of the polygons' angle-bisector rays, and integrates each piece by the trapezoid rule (Eq. 16). The "
        "potential's kinks lie on the polygons' medial axes, which those rays do not cover in general (a "
        "rectangle's middle segment): on such overlaps the force is off the gradient of the contact energy "
        "(Eq. 10) and its moment about the loading point pg does not vanish (Eq. 20). On the paper's own scenes "
        "the difference stays at round-off (the segmentation study).",
        "exact_integration",
        ["3_1_contact_statements/3.2.1:force-is-energy-gradient-exact",
         "3_1_contact_statements/3.2.4:zero-moment-about-pg-exact"]),
    "thin_block": (
        "A penalty too soft for a thin block lets the blocks pass through", "paper_method",
        "The potential of Eq. 12 pushes two blocks apart only until their overlap reaches the middle of the "
        "thinner one. Where the contact cannot store the impact energy within that depth (kn too low for the "
        "block's thickness and speed), the blocks pass through each other at any time step; the suite's "
        "penetration guard stops such runs. Where the paper's own kn sits against this threshold is in the "
        "stability map's rows.",
        "stiff_kn",
        ["S2_stability_maps/S2 / map:map-bouncing_unified-no-failure-below-predicted",
         "5_4_extreme_geometry/5.1 (option 5.4):bouncing-block-b-height-0.01-m-unified-h-runs-clean-with-kn-raised-to-ke"]),
    "small_geometry_step": (
        "The paper's fixed time step above the critical step of smaller geometry", "paper_method",
        "Below the paper's sizes (5 deg angles, 0.01 m edges, a 0.1 m block) the critical time step falls below "
        "the paper's fixed dt: the run is unstable or inaccurate at that dt and clean at a step below the "
        "predicted critical step.",
        "dt_fraction", []),
    "stiff_bounce": (
        "A stiff penalty bounce amplifies a round-off tilt", "paper_method",
        "With kn raised to stop the thinnest blocks, every landing of the falling block amplifies its round-off "
        "tilt (its rocking mode): the first landing leaves it symmetric to round-off, the later ones do not.",
        None, []),
    "clone_impact": (
        "The clone's inelastic impact takes the whole tangential velocity", "paper_method",
        "Paper B forms each clone by a perfectly inelastic impact of the two contact points (Eq. 4, 'no "
        "slipping occurs' in the touch step): it takes their whole relative velocity, tangential included, "
        "whatever the friction angle; the Mohr-Coulomb limit (Eqs. 7-10) caps the shear force only afterwards. "
        "The tangential impulse of an oblique impact therefore exceeds Coulomb's mu J_n (even at mu = 0) and is "
        "off the rigid-body stick/slide law. The Coulomb touch option caps each touch's impulse; it does not yet "
        "pass in every cell (its own root cause below).",
        None, ["B_9_impact_study/B-9:coulomb-option"]),
    "nodal_peak": (
        "A nodal value of a coarse mesh read as the block's velocity", "paper_method",
        "Paper B's 3.205 m/s for block j is above block i's initial 3.0 m/s, which j's block average cannot "
        "exceed (equal masses: momentum and energy); it is a nodal value of a coarse mesh, which falls with "
        "every refinement.", None, []),
    "mesh_dispersion": (
        "A coarse CST mesh disperses the elastic wave", "paper_method",
        "Constant-strain triangles carry a wave with a dispersed front; on a coarse mesh the contact duration "
        "and stress are off the 1D theory by the mesh's error, which falls with refinement.", None, []),
    "sub_model_reading": (
        "Our reading of Paper B Sect. 5's sub-model", "our_reading",
        "Sect. 5 steps (1)-(5) subdivide the colliding elements, solve the sub-elements with the initial nodes' "
        "velocities as boundary conditions (Eq. 12, time step dt/n) and transfer 'the forces of the element' to "
        "the initial nodes. They do not say which mass the sub-model's free nodes carry, nor how the forces are "
        "transferred, nor where the clone sits. We return the element forces on every sub-node to the initial "
        "nodes by their linear weights (momentum to round-off; the literal reading, the forces on the prescribed "
        "sub-nodes only, is an option and drifts) and keep the clone between the coarse nodes (step 2): its Eq. 4 "
        "loss is the coarse mesh's, and the free sub-nodes' fine-scale energy stays outside the coarse energy "
        "account. Where a row fails for this reason the failure may be our reading's, not the paper's. The rows "
        "give the run's numbers; the in-place refinement beside puts the clone between patch nodes of small mass.",
        "in_place", ["B_6_two_prisms/B-6:submodel-momentum",
                     "B_6_two_prisms/B-6:submodel-vs-inplace-energy"]),
    "unstated_setup": (
        "A set-up the paper does not give", "missing_data",
        "The paper does not give this scene's geometry or start (its figure is lost or the text is silent); the "
        "row runs a set-up of ours, which the paper's result need not match.", None, []),
    "printed_numbers": (
        "The paper's printed numbers disagree with each other", "missing_data",
        "Paper B prints the touch at 0.3333 s 'in the step from 0.3335 to 0.3340 s'; with t0 = 0 and its dt = "
        "5e-4 s, 1/3 s lies in the step [0.3330, 0.3335] s. Our touch time matches the printed 0.3333 s, so the "
        "printed step cannot match too.", None, ["B_6_two_prisms/B-6:vertex-a-of-block-i-touches-block-j-s-edge-at-the-two-stage-touch-time"]),
    "corner_normal": (
        "Our contact normal at a corner-to-corner touch", "implementation",
        "Where a corner arrives within the contact tolerance of the other block's corner, our node-to-edge "
        "detection ties it to the perpendicular face, whose normal is tangential to the impact face: the "
        "Coulomb touch option's normal impulses then act as tangential ones for the blocks. The choice of "
        "normal is ours; the paper does not fix it.", None, []),
    "unexplained": (
        "Not explained yet", "implementation",
        "A failure of our implementation that no argument above explains; the row's text says what was "
        "expected.", None, []),
}

# Options beside the paper's method: the words the report uses, what the
# option does, and how it is set (the scene-file key, lib/io/SCHEMA.md, where
# a scene file can set it).
OPTIONS = {
    "friction_start_up": (
        "friction start-up",
        "the scene first settles, damped, with every contact sticking, so that each tangential spring starts "
        "loaded with its static shear; then the run starts undamped (not the paper's start)",
        "`damping`: `mass` > 0, `settle_time` > 0, `settle_sticking`: true"),
    "return_mapping": (
        "return-mapping friction update",
        "a sliding pair keeps its shear at the friction limit instead of restarting from one step's "
        "displacement (not the paper's Eq. 26)",
        "`contact.friction_update`: `return_mapping`"),
    "exact_integration": (
        "exact integration",
        "splits each edge of the intersection polygon at the potential's true breakpoints instead of the "
        "paper's bisector rays",
        "`contact.integration`: `exact_envelope`"),
    "replacing_reading": (
        "replacing reading of the small-edge rule",
        "a short edge's virtual node replaces the two vertices' rays instead of adding a third (the paper's "
        "text keeps all three)",
        "`contact.small_edge_rays`: `virtual_replaces_vertex`"),
    "stiff_kn": (
        "stiffer contact",
        "kn raised so that the contact stores the impact energy within the thin block's half thickness",
        "`contact.kn`"),
    "dt_fraction": (
        "time step from the predicted critical step",
        "dt set to a fraction of the solver's predicted critical step instead of the paper's fixed dt",
        "`dt_fraction`"),
    "in_place": (
        "in-place refinement",
        "Paper B's colliding elements refined in place: their mass moves into the refined patch and the clone "
        "forms between patch nodes",
        "the two-scale model's subdivision mode 'in place' (Paper B's model has no scene file; its drivers set "
        "it)"),
    "coulomb_touch": (
        "Coulomb touch",
        "caps each touch's tangential impulse at mu times its normal impulse (Paper B's Eq. 4 takes the whole "
        "tangential velocity)",
        "the two-scale model's touch impact 'Coulomb' (set by its drivers)"),
    "energy_matched_deletion": (
        "energy-matched patch deletion",
        "hands the refined patch's energy to the coarse mesh when the patch is deleted, instead of the "
        "restriction of Sect. 5",
        "the two-scale model's patch deletion 'energy matched' (set by its drivers)"),
}


def natural_key(text):
    return [(0, int(t), "") if t.isdigit() else (1, 0, t.lower()) for t in re.split(r"(\d+)", text) if t]


def flat(text):
    """One line, pipes escaped (a Markdown table cell)."""
    return " ".join(str(text).split()).replace("|", "\\|")


def shorten(text, limit=MAX_CELL):
    """`text` on one line, cut to at most `limit` characters at a clause boundary ('; ', ', ' or a space),
    marked with an ellipsis; the full text stays in claims.json."""
    text = " ".join(str(text).split())
    if len(text) <= limit:
        return flat(text)
    head = text[:limit - 2]
    for sep in ("; ", ". ", ", ", " "):
        cut = head.rfind(sep)
        if cut >= limit // 2:
            head = head[:cut]
            break
    return flat(head.rstrip(" ,;.") + " …")


def row_class(r):
    """'pass', 'fail', 'fitted', 'unverified' (a check without a negative control) or 'measurement'."""
    if r["kind"] == "measurement":
        return "measurement"
    if not r["control"].strip():
        return "unverified"
    if r["kind"] == "fitted":
        return "fitted"
    return "pass" if r["status"] == "PASS" else "fail"


def read_claims(path):
    """(rows, problems, warnings): a problem is an unreadable file or row (counted as a failing check), a
    warning a readable row with a defect (no scope, a FAIL without a cause or root cause, forbidden words),
    listed but not counted twice."""
    rows, problems, warnings = [], [], []
    name = os.path.basename(path)
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            missing = [c for c in COLUMNS if c not in (reader.fieldnames or [])]
            if missing:
                return [], [f"{name}: missing column(s) {', '.join(missing)}"], []
            for line, rec in enumerate(reader, start=2):
                if None in rec or any(rec[c] is None for c in COLUMNS):
                    problems.append(f"{name} line {line}: wrong number of fields")
                    continue
                kind, status = rec["kind"].strip(), rec["status"].strip().upper()
                if kind not in KINDS or (kind != "measurement" and status not in ("PASS", "FAIL")) \
                        or (kind == "measurement" and status):
                    problems.append(f"{name} line {line}: kind '{kind}' with status '{rec['status']}'")
                    continue
                if rec["scope"] not in SCOPES:
                    warnings.append(f"{name} line {line}: scope '{rec['scope']}' is none of "
                                    f"{', '.join(SCOPES)} ({rec['id']})")
                if kind != "measurement" and status == "FAIL":
                    if rec["cause"] not in CAUSES:
                        warnings.append(f"{name} line {line}: FAIL without a cause ({rec['id']})")
                    elif rec["root_cause"] not in ROOTS:
                        warnings.append(f"{name} line {line}: FAIL with root cause '{rec['root_cause']}', "
                                        f"not one the report explains ({rec['id']})")
                    elif ROOTS[rec["root_cause"]][1] != rec["cause"]:
                        warnings.append(f"{name} line {line}: root cause '{rec['root_cause']}' is not of the "
                                        f"cause '{rec['cause']}' ({rec['id']})")
                bad = [c for c in ("section", "claim", "paper", "measured", "tolerance")
                       if FORBIDDEN.search(rec[c])]
                if bad:
                    warnings.append(f"{name} line {line}: {', '.join(bad)} of row {rec['id']} name source files, "
                                    "code or the project's history")
                rows.append(dict(rec, kind=kind, status=status))
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        problems.append(f"{name}: cannot read ({e})")
    return rows, problems, warnings


def tally(rows):
    """{'pass', 'fail', 'fitted', 'measurement', 'unverified'} counts of rows."""
    c = {"pass": 0, "fail": 0, "fitted": 0, "unverified": 0, "measurement": 0}
    for r in rows:
        c[row_class(r)] += 1
    return c


def checks_text(c, noun="checks"):
    """'N of M checks pass (K measurements)' for rows of one scope."""
    checks = c["pass"] + c["fail"] + c["fitted"]
    text = f"{c['pass']} of {checks} {noun} pass"
    extra = []
    if c["fitted"]:
        extra.append(f"{c['fitted']} on a scene fitted to the number they check, not counted")
    measured = c["measurement"] + c["unverified"]
    if measured:
        extra.append(f"{measured} measurement{'s' if measured != 1 else ''}"
                     + (f", {c['unverified']} of them checks without a negative control" if c["unverified"] else ""))
    return text + (f" ({'; '.join(extra)})" if extra else "")


def claims_headline(paper, c):
    """'Paper A: X of Y of its claims reproduced' and what is beside it."""
    checks = c["pass"] + c["fail"] + c["fitted"]
    text = f"{paper}: {c['pass']} of {checks} of its claims reproduced"
    extra = []
    if c["fitted"]:
        extra.append(f"{c['fitted']} more {'agrees' if c['fitted'] == 1 else 'agree'} only on a scene we fitted "
                     "to that number, not counted")
    measured = c["measurement"] + c["unverified"]
    if measured:
        extra.append(f"{measured} of its statements measured without a verdict")
    return text + (f" ({'; '.join(extra)})" if extra else "")


def verdict_cell(r, anchors=True):
    cls = row_class(r)
    if cls == "pass":
        return "PASS"
    if cls == "fitted":
        return f"{r['status']} on a fitted scene (not counted)"
    if cls == "fail":
        root = ROOTS.get(r["root_cause"])
        if root and anchors:
            return f"**FAIL**: [{root[0]}](#cause-{r['root_cause']})"
        return "**FAIL**: " + (root[0] if root else CAUSES.get(r["cause"], "no cause given"))
    if cls == "unverified":
        return f"measured (criterion {'met' if r['status'] == 'PASS' else 'not met'}; no negative control)"
    return "measured"


def write_atomic(path, text):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


# ---------------------------------------------------------------------------
# Provenance
# ---------------------------------------------------------------------------
def run_text(args, cwd=None):
    try:
        p = subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=20)
        return p.stdout.strip() if p.returncode == 0 else None
    except (OSError, subprocess.SubprocessError):
        return None


def read_cmake_cache(build):
    cache = {}
    try:
        with open(os.path.join(build, "CMakeCache.txt"), encoding="utf-8") as f:
            for line in f:
                m = re.match(r"^([A-Za-z0-9_]+):[A-Z]+=(.*)$", line.rstrip("\n"))
                if m:
                    cache[m.group(1)] = m.group(2)
    except OSError:
        pass
    return cache


def compile_flags(build):
    """The library's compile flags as the build tree has them (Makefile generator), or None."""
    try:
        with open(os.path.join(build, "lib", "CMakeFiles", "dda.dir", "flags.make"), encoding="utf-8") as f:
            text = f.read()
    except OSError:
        return None
    flags = re.search(r"^CXX_FLAGS = (.*)$", text, re.MULTILINE)
    defines = re.search(r"^CXX_DEFINES = (.*)$", text, re.MULTILINE)
    return " ".join(x.group(1).strip() for x in (flags, defines) if x)


def cpu_model():
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.lower().startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def os_name():
    try:
        with open("/etc/os-release", encoding="utf-8") as f:
            for line in f:
                if line.startswith("PRETTY_NAME="):
                    return line.split("=", 1)[1].strip().strip('"') + f", kernel {platform.release()}"
    except OSError:
        pass
    return f"{platform.system()} {platform.release()}"


def provenance(src, build, started, driver_seconds, files):
    """Lines of the provenance block."""
    lines = []
    commit = run_text(["git", "rev-parse", "--short=12", "HEAD"], cwd=src)
    if commit:
        changed = run_text(["git", "status", "--porcelain", "--untracked-files=no"], cwd=src)
        n = len(changed.splitlines()) if changed else 0
        lines.append(f"- **Commit:** {commit}" + (f", with {n} modified file{'s' if n != 1 else ''} not committed"
                                                  if n else ", tree unmodified"))
    else:
        lines.append("- **Commit:** not a git checkout")
    if build:
        cache = read_cmake_cache(build)
        cxx = cache.get("CMAKE_CXX_COMPILER")
        version = run_text([cxx, "--version"]) if cxx else None
        flags = compile_flags(build)
        if flags is None:
            flags = " ".join(x for x in (cache.get("CMAKE_CXX_FLAGS", ""),
                                         cache.get("CMAKE_CXX_FLAGS_" + cache.get("CMAKE_BUILD_TYPE", "").upper(),
                                                   "")) if x)
        lto = cache.get("DDA_LTO")
        lines.append(f"- **Compiler:** {version.splitlines()[0] if version else cxx or 'unknown'}; "
                     f"{cache.get('CMAKE_BUILD_TYPE') or 'no'} build, flags `{flags or 'none'}`"
                     + (f", link-time optimisation {'on' if lto in ('ON', 'TRUE', '1') else 'off'}" if lto else ""))
    else:
        lines.append("- **Compiler:** not recorded (no build tree given)")
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:
        cores = os.cpu_count()
    lines.append(f"- **Machine:** {cpu_model()}, {cores} core{'s' if cores != 1 else ''} available "
                 f"({os.cpu_count()} in the machine); **OS:** {os_name()}")
    now = datetime.datetime.now(datetime.timezone.utc)
    stamps = [os.path.getmtime(p) for p in files]
    when = f"- **Date:** report written {now.strftime('%Y-%m-%d %H:%M UTC')}"
    if stamps:
        first = datetime.datetime.fromtimestamp(min(stamps), datetime.timezone.utc)
        when += f"; claim files written {first.strftime('%Y-%m-%d %H:%M')} to " \
                f"{datetime.datetime.fromtimestamp(max(stamps), datetime.timezone.utc).strftime('%H:%M UTC')}"
    lines.append(when)
    wall = f"- **Wall time:** the drivers' own run times add up to {driver_seconds:.0f} s"
    if started is not None:
        wall = (f"- **Wall time:** {time.time() - started:.0f} s for the make run that wrote this report (build, "
                f"drivers whose inputs changed, figures); the drivers' own run times add up to "
                f"{driver_seconds:.0f} s")
    lines.append(wall)
    rebuilt = [f"{v[0]} {v[1].split(':')[0]} ({v[4]})" for v in DRIVERS.values() if v[4] and v[0] != "Both papers"]
    lines.append("- **Reconstructed geometry** (a figure of the paper is lost): " + "; ".join(rebuilt))
    return lines


# ---------------------------------------------------------------------------
# The report
# ---------------------------------------------------------------------------
def paper_of(driver):
    return DRIVERS.get(driver, ("Other",))[0]


def ledger(paper, rows):
    """The ledger of one paper: its own claims (scope paper) in the paper's order."""
    own = sorted(rows, key=lambda r: natural_key(r["section"]))  # stable: driver order within a section
    c = tally(own)
    checks = c["pass"] + c["fail"] + c["fitted"]
    if checks and c["pass"] == checks:
        opening = f"{paper}'s results were reproduced in full: all {checks} of its claims checked here pass."
    else:
        opening = (f"{paper}'s results were reproduced in part: {c['pass']} of its {checks} claims checked here "
                   f"pass" + (f", {c['fail']} fail" if c["fail"] else "")
                   + (f", {c['fitted']} {'agrees' if c['fitted'] == 1 else 'agree'} only on a scene fitted to that "
                      "number" if c["fitted"] else "") + ".")
    measured = c["measurement"] + c["unverified"]
    if measured:
        opening += f" {measured} of its statements are measured without a verdict."
    lines = [opening, "",
             "| Where | The paper says | What we checked | This run | Verdict |", "|---|---|---|---|---|"]
    for r in own:
        lines.append(f"| {flat(r['section'])} | {shorten(r['paper'], LEDGER_CELL)} | "
                     f"{shorten(r['claim'], LEDGER_CLAIM)} | {shorten(r['measured'], LEDGER_CELL)} | "
                     f"{verdict_cell(r)} |")
    lines += ["", f"Out of scope for {paper}:", ""] + [f"- {x}" for x in OUT_OF_SCOPE.get(paper, [])] + [""]
    return lines


def root_section(all_rows, problems):
    """Each root cause once: its argument, the rows it explains, the evidence, the option that fixes it."""
    by_key = {(r["driver"], r["id"]): r for r in all_rows}
    failing = [r for r in all_rows if row_class(r) in ("fail", "unverified", "fitted") and r["status"] == "FAIL"]
    used = [k for k in ROOTS if any(r["root_cause"] == k for r in failing)]
    lines = ["## Why claims fail", "",
             "Each root cause once, with the rows it explains (scope in brackets), the evidence and, where one "
             "exists, the option that fixes it. The full text of every row's cause is in claims.json.", ""]
    if not used:
        return lines + ["No check fails.", ""]
    for k in used:
        title, cause, text, option, evidence = ROOTS[k]
        rows = [r for r in failing if r["root_cause"] == k]
        lines += [f'<a id="cause-{k}"></a>', "", f"### {title}", "",
                  f"*{CAUSES[cause].capitalize()}.* {text}", ""]
        lines.append("Rows: " + "; ".join(f"{flat(r['section'])} {shorten(r['claim'], 120)} ({r['scope']})"
                                          for r in rows) + ".")
        lines.append("")
        ev = []
        for e in evidence:
            driver, _, rid = e.partition("/")
            r = by_key.get((driver, rid))
            if r is None:
                problems.append(f"root cause '{k}': evidence row {e} not in this run")
                continue
            ev.append(f"- {flat(r['section'])} {shorten(r['claim'], 120)}: {shorten(r['measured'], 220)} "
                      f"({verdict_cell(r, anchors=False)})")
        if ev:
            lines += ["Evidence:", ""] + ev + [""]
        if option:
            words, _, _ = OPTIONS[option]
            lines += [f"Option that fixes it: {words} (see the glossary).", ""]
    return lines


def main(argv):
    args = list(argv[1:])
    build, started = None, None
    while args and args[0].startswith("--"):
        if len(args) < 2:
            raise SystemExit(__doc__)
        flag, value = args[0], args[1]
        if flag == "--build":
            build = value
        elif flag == "--started":
            started = float(value)
        else:
            raise SystemExit(__doc__)
        args = args[2:]
    if len(args) not in (2, 3):
        raise SystemExit(__doc__)
    claims_dir, out_path = args[0], args[1]
    json_path = args[2] if len(args) == 3 else os.path.join(os.path.dirname(os.path.abspath(out_path)),
                                                             "claims.json")
    src = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    files = sorted(glob.glob(os.path.join(claims_dir, "*.csv")))
    by_driver, problems, warnings = {}, [], []
    for path in files:
        r, p, w = read_claims(path)
        warnings += w
        driver = os.path.splitext(os.path.basename(path))[0]
        for rec in r:
            rec["driver"] = driver
        by_driver[driver] = r
        problems += p
    drivers = sorted(by_driver, key=lambda d: (PAPER_ORDER.index(paper_of(d)), natural_key(d)))
    all_rows = [r for d in drivers for r in by_driver[d]]
    report_dir = os.path.dirname(os.path.abspath(out_path))
    fig_dir = os.path.join(report_dir, "figures")
    fig_rel = os.path.relpath(fig_dir, report_dir)

    def run_time(d):
        times = [float(r["run_time_s"]) for r in by_driver[d] if r["run_time_s"]]
        return max(times) if times else 0.0

    lines = ["# Reproduction report", ""]
    if not files:
        lines += [f"No claim files yet: {claims_dir} has no claim files. Run the drivers (make repro).", ""]
    else:
        lines += provenance(src, build, started, sum(run_time(d) for d in drivers), files) + [""]
        lines += ["## What was reproduced", ""]
        for paper in ("Paper A", "Paper B"):
            own = [r for r in all_rows if paper_of(r["driver"]) == paper and r["scope"] == "paper"]
            lines.append(f"- **{claims_headline(paper, tally(own))}** ([ledger](#ledger-{paper[-1].lower()}))")
        for scope, noun in (("extension", "Tests beyond the papers"), ("option", "Our options beside the papers' "
                                                                      "methods")):
            parts = []
            for paper in ("Paper A", "Paper B", "Both papers"):
                rows = [r for r in all_rows if paper_of(r["driver"]) == paper and r["scope"] == scope]
                if rows:
                    label = "comparing the two" if paper == "Both papers" else paper
                    parts.append(f"{label} {checks_text(tally(rows))}")
            if parts:
                lines.append(f"- {noun}: " + "; ".join(parts))
        suite = [r for r in all_rows if r["scope"] == "suite"]
        if suite:
            lines.append("- The suite's own tests (guards, integrator orders, work-precision, stability maps): "
                         + checks_text(tally(suite)))
        if problems:
            lines.append(f"- {len(problems)} unreadable row(s) or file(s): see Problems")
        lines += ["",
                  "A *check* has a criterion computed from the run that can come out PASS or FAIL, and a negative "
                  "control in make test (the same criterion applied to a deliberately wrong configuration must "
                  "FAIL). A *measurement* reports a number with no verdict. A check on a scene whose geometry or "
                  "parameter we fitted to the number it checks is shown but never counted as reproduced. The "
                  "counts above are never added up: a paper's claims, our tests beyond it, our options and the "
                  "suite's own tests answer different questions.", ""]
        for paper in ("Paper A", "Paper B"):
            own = [r for r in all_rows if paper_of(r["driver"]) == paper and r["scope"] == "paper"]
            lines += [f'<a id="ledger-{paper[-1].lower()}"></a>', "", f"## {paper}: its claims", ""]
            lines += ledger(paper, own)
        lines += root_section(all_rows, problems)
        lines += ["## The scenes in detail", "",
                  "Per scene: the paper's statement, the figures, every row with its scope. Cells are cut to "
                  f"{MAX_CELL} characters (marked …); claims.json has the full texts.", "",
                  "| Scene | Paper's claims | Beyond the paper | Options | Suite | Measurements | Run time (s) |",
                  "|---|---|---|---|---|---|---|"]
        for d in drivers:
            cells = []
            for scope in ("paper", "extension", "option", "suite"):
                c = tally([r for r in by_driver[d] if r["scope"] == scope])
                n = c["pass"] + c["fail"] + c["fitted"]
                cells.append(f"{c['pass']} / {n}" if n else "-")
            c = tally(by_driver[d])
            title = DRIVERS.get(d, ("", d))[1]
            lines.append(f"| [{flat(title)}](#{d.lower()}) | " + " | ".join(cells)
                         + f" | {c['measurement'] + c['unverified']} | {run_time(d):.3g} |")
        lines += ["", "(pass / checks; fitted rows count among the checks, not among the passes)", ""]
        for d in drivers:
            paper, title, statement, figs, _ = DRIVERS.get(d, ("Other", d, "", [], None))
            rows = by_driver[d]
            lines += [f'<a id="{d.lower()}"></a>', "", f"### {paper}, {title}", ""]
            if statement:
                lines += [f"**The paper:** {statement}", ""]
            lines += [f"Run time {run_time(d):.3g} s.", ""]
            for fig in figs:
                if os.path.exists(os.path.join(fig_dir, fig)):
                    lines += [f"![{fig}]({fig_rel}/{fig})", ""]
                else:
                    lines += [f"*(figure {fig} not made yet: make repro)*", ""]
            if rows:
                lines += ["| Id | Scope | Claim | Paper | Measured | Criterion | Verdict |",
                          "|---|---|---|---|---|---|---|"]
                for r in rows:
                    lines.append("| " + " | ".join(shorten(r[k]) for k in ("id", "scope", "claim", "paper",
                                                                           "measured", "tolerance"))
                                 + f" | {verdict_cell(r)} |")
                lines.append("")
        if OPTIONS:
            lines += ['<a id="glossary"></a>', "", "## Glossary of options", "",
                      "Our options beside the papers' methods (the paper's method is the default wherever a "
                      "figure of the paper is reproduced):", "",
                      "| Option | What it does | How to set it |", "|---|---|---|"]
            for words, what, how in OPTIONS.values():
                lines.append(f"| {flat(words)} | {flat(what)} | {flat(how)} |")
            lines.append("")
        if problems or warnings:
            lines += ["## Problems", ""] + [f"- {flat(p)}" for p in problems + warnings] + [""]
            for p in problems + warnings:
                print(f"report.py: warning: {p}", file=sys.stderr)

    write_atomic(out_path, "\n".join(lines).rstrip("\n") + "\n")
    write_atomic(json_path, json.dumps([dict((k, r[k]) for k in ["driver"] + COLUMNS) | {"class": row_class(r)}
                                        for r in all_rows], indent=1) + "\n")


if __name__ == "__main__":
    main(sys.argv)
