"""Merge every claims CSV into a review-style Markdown report and a JSON file.

usage: report.py CLAIMS_DIR REPORT_MD [CLAIMS_JSON]

Each <CLAIMS_DIR>/<driver>.csv is written by a driver (repro/common/claims.hpp)
with the columns id,section,kind,claim,paper,measured,tolerance,status,cause,
cause_text,control,run_time_s. Rows are of two kinds (issue 21):
  - a check: status PASS or FAIL, a FAIL with a cause (paper_method,
    missing_data, implementation) and a text;
  - a measurement: a number with no verdict, never counted as PASS.
A check counts as a check only when it names its negative control (a ctest
that applies the same criterion to a deliberately wrong configuration and
asserts FAIL); a check without one is listed with the measurements, its
criterion's outcome shown in words, and counted apart.

The report: a headline per paper ("N of M checks pass (K measurements)"), a
summary table (per driver: checks, pass, fail by cause, measurements, run
time), then per driver the paper's statement, its figures inline, its rows.
The JSON file holds every row (all columns, plus the driver). A file that
cannot be read or a row with an unknown kind/status is listed under
"Problems" and counted as a failing check. Outputs are written atomically.
"""
import csv
import glob
import json
import os
import re
import sys

COLUMNS = ["id", "section", "kind", "claim", "paper", "measured", "tolerance", "status", "cause",
           "cause_text", "control", "run_time_s"]
CAUSES = {"paper_method": "paper's method", "missing_data": "missing data", "implementation": "our implementation"}

# Per driver: (paper, heading, the paper's statement, figure files under out/figures).
# The statements quote or paraphrase the papers as the drivers' header comments cite them.
DRIVERS = {
    "3_1_exact_geometry": ("Paper A", "Sect. 3.1.3: the intersection polygon, against CGAL's exact intersection",
                           "The contact integrals run over the intersection polygon of the two blocks.", []),
    "3_1_contact_statements": ("Paper A", "Sects. 3.1.2, 3.2.1, 3.2.4: entrance block, the force as the energy gradient, Eq. 20",
                               "A and B overlap if and only if a0 lies in the entrance block E (Sect. 3.1.2); the "
                               "normal force is the negative gradient of the contact energy (Eqs. 10-11) and acts on a line through pg (Eq. 20).",
                               ["fig_contact_statements.png"]),
    "3_2_2_potential_fields": ("Paper A", "Sect. 3.2.2: the new potential function (Figs. 4b, 5)",
                               "The potential is defined at every point inside a polygon, zero on its boundary, "
                               "proportional to the distance to the boundary (Eqs. 12-14), for convex and concave "
                               "polygons and small edges alike.",
                               ["fig04b_potential.png", "fig05_potential.png"]),
    "3_2_2_previous_potential": ("Paper A", "Sect. 3.2.2: the previous sub-polygon potential (Fig. 4a)",
                                 "The previous sub-polygon potential leaves an inner region undefined and depends "
                                 "on the edge lengths (Fig. 4a; reconstructed).",
                                 ["fig04a_previous_potential.png"]),
    "4_1_two_squares": ("Paper A", "Sect. 4.1: collision of two identical polygons (Figs. 7-8)",
                        "Two identical squares collide; the velocities are exchanged and energy is conserved.",
                        ["fig08_two_squares.png"]),
    "4_2_symmetric_stack": ("Paper A", "Sect. 4.2: a polygon on a symmetric polygonal stack (Figs. 9-10)",
                            "The response of the symmetric stack stays symmetric.", ["fig10_symmetric_stack.png"]),
    "4_3_incline": ("Paper A", "Sect. 4.3: sliding block on an inclined plane (Figs. 11-12)",
                    "The sliding distance follows the analytic solution (Eq. 30): 'good agreements' (Fig. 12).",
                    ["fig12_incline.png"]),
    "5_1_bouncing_block": ("Paper A", "Sect. 5.1: polygons of different sizes (Figs. 13-14)",
                           "'The current approach using a unified H value leads to very similar block bouncing "
                           "response' for the two cases, while the inscribed radius 'lead[s] to significantly "
                           "different block bouncing response'.", ["fig14_bouncing_block.png"]),
    "5_2_small_angles": ("Paper A", "Sect. 5.2: polygons with small angles (Figs. 15-16)",
                         "'The two triangles move symmetrically regarding the collision centroid'.",
                         ["fig16_small_angles.png"]),
    "5_3_small_edges": ("Paper A", "Sect. 5.3: polygons with small edges (Figs. 17-18)",
                        "'The proposed approach can treat contacts of small edges with good robustness'; "
                        "penetrations 'around 0.01 m'.", ["fig18_small_edges.png"]),
    "5_4_extreme_geometry": ("Paper A", "Beyond Sect. 5: extreme geometry",
                             "Not in the paper (it stops at 5 deg and 0.01 m): how small angles and edges can get.",
                             ["extreme_geometry.png"]),
    "5_5_segmentation": ("Paper A", "Beyond Sect. 3.2.3: is the paper's segmentation exact?",
                         "The segmentation of the contact (Sect. 3.2.3) against exact integration of Eqs. 10-11.",
                         ["segmentation_study.png"]),
    "6_1_collapse": ("Paper A", "Sect. 6.1: frictional collapse of a rock mass (Figs. 19-20)",
                     "'A faster collapsing process and a larger runout mass were observed with lower friction "
                     "angle.' (geometry reconstructed)",
                     ["fig20_collapse.png", "fig20_collapse_runout.png", "anim_collapse_case1.gif"]),
    "6_2_toppling_slumping": ("Paper A", "Sect. 6.2: rock toppling and slumping (Figs. 21-22)",
                              "'The left part will fail in slumping pattern, while the right part will fail with "
                              "toppling pattern.' (geometry reconstructed)", ["fig22_toppling.png"]),
    "B_6_two_prisms": ("Paper B", "Sect. 6: two prisms, two-scale contact (Figs. 12-16)",
                       "Vertex A touches j's edge at 0.3333 s; j accelerates from 0 to 3.205 m/s; the clone node "
                       "separates at 0.3405 s; momentum is conserved with 'a little energy loss'.",
                       ["figB13_15_prisms.png", "figB16_displacement.png"]),
    "B_7_contact_comparison": ("Paper A vs B", "Penalty (A) against two-scale (B) contact on the same collisions",
                               "A comparison neither paper makes: touch time, momentum, energy and contact duration.",
                               ["figB_comparison.png"]),
    "B_8_bar_waves": ("Paper A vs B", "Waves against theory: two elastic bars head on (issue 23, item 5)",
                      "Not in the papers: 1D bar theory (contact 2L/c, stress rho c v / 2, velocities exchanged) "
                      "against CDEM with and without subdivision and Paper A's 6-DOF blocks.",
                      ["figB_bar_waves.png"]),
    "B_9_impact_study": ("Paper B", "Issue 23 item 2: impact study of the two-scale contact",
                         "Not in the paper: oblique impacts of two squares over angle, speed, friction and "
                         "subdivision, against no pass-through, energy, Eq. 5 and the rigid-body Coulomb impact law.",
                         ["figB_impact_study.png"]),
    "S1_work_precision": ("Supplementary", "S1: work precision, error against run time",
                          "Not in the papers: convergence orders and conservation of the integration.",
                          ["figS1a_two_squares.png", "figS1b_incline.png", "figS1c_resting_block.png",
                           "figS1d_triangles.png", "figS1e_bouncing_block.png", "figS1f_small_edge.png",
                           "figS1g_free_rotation.png", "figS1h_damped_flight.png"]),
    "S2_stability_maps": ("Supplementary", "S2: stability maps and the critical time step",
                          "Not in the papers: the predicted critical step against the linearised and empirical limits.",
                          ["figS2_stability_maps.png"]),
    "S3_penetration_map": ("Supplementary", "S3: penetration map",
                           "Not in the papers: where two blocks would pass through each other, the penetration "
                           "guard stops the run.", ["figS3_penetration_map.png"]),
    "S3_extreme_cases": ("Supplementary", "S3: extreme cases",
                         "Not in the papers: high speed, deep penetration, stiff contacts and the guards.", []),
}
PAPER_ORDER = ["Paper A", "Paper B", "Paper A vs B", "Supplementary", "Other"]


def natural_key(text):
    return [(0, int(t), "") if t.isdigit() else (1, 0, t.lower()) for t in re.split(r"(\d+)", text) if t]


def cell(text):
    """Markdown table cell: no line breaks, pipes escaped."""
    return " ".join(str(text).split()).replace("|", "\\|")


def row_class(r):
    """'pass', 'fail', 'unverified' (a check without a negative control) or 'measurement'."""
    if r["kind"] == "measurement":
        return "measurement"
    if not r["control"].strip():
        return "unverified"
    return "pass" if r["status"] == "PASS" else "fail"


def read_claims(path):
    """(rows, problems, warnings): a problem is an unreadable file or row (counted as a failing check), a
    warning a readable row with a defect (a FAIL without a cause), listed but not counted twice."""
    rows, problems, warnings = [], [], []
    name = os.path.basename(path)
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            missing = [c for c in COLUMNS if c not in (reader.fieldnames or [])]
            if missing:
                return [], [f"`{name}`: missing column(s) {', '.join(missing)}"], []
            for line, rec in enumerate(reader, start=2):
                if None in rec or any(rec[c] is None for c in COLUMNS):
                    problems.append(f"`{name}` line {line}: wrong number of fields")
                    continue
                kind, status = rec["kind"].strip(), rec["status"].strip().upper()
                if kind not in ("check", "measurement") or (kind == "check" and status not in ("PASS", "FAIL")) \
                        or (kind == "measurement" and status):
                    problems.append(f"`{name}` line {line}: kind '{kind}' with status '{rec['status']}'")
                    continue
                if kind == "check" and status == "FAIL" and rec["cause"] not in CAUSES:
                    warnings.append(f"`{name}` line {line}: FAIL without a cause ({rec['id']})")
                rows.append(dict(rec, kind=kind, status=status))
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        problems.append(f"`{name}`: cannot read ({e})")
    return rows, problems, warnings


def counts(rows):
    c = {"pass": 0, "fail": 0, "unverified": 0, "measurement": 0}
    by_cause = {k: 0 for k in CAUSES}
    for r in rows:
        c[row_class(r)] += 1
        # Every failing criterion by cause, with or without a negative control.
        if r["kind"] == "check" and r["status"] == "FAIL" and r["cause"] in by_cause:
            by_cause[r["cause"]] += 1
    return c, by_cause


def headline(c, problems=0):
    checks = c["pass"] + c["fail"] + problems
    text = f"{c['pass']} of {checks} checks pass ({c['measurement'] + c['unverified']} measurements"
    if c["unverified"]:
        text += f", {c['unverified']} of them checks still without a negative control"
    return text + ")"


def status_cell(r):
    cls = row_class(r)
    if cls == "pass":
        return "PASS"
    if cls == "fail":
        return f"**FAIL** ({CAUSES.get(r['cause'], 'no cause')}): {r['cause_text']}"
    if cls == "unverified":
        text = f"measurement (criterion {'met' if r['status'] == 'PASS' else 'not met'}; no negative control yet)"
        if r["status"] == "FAIL" and r["cause"] in CAUSES:
            text += f"; {CAUSES[r['cause']]}: {r['cause_text']}"
        return text
    return "measurement"


def write_atomic(path, text):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


def main(argv):
    if len(argv) not in (3, 4):
        raise SystemExit(__doc__)
    claims_dir, out_path = argv[1], argv[2]
    json_path = argv[3] if len(argv) == 4 else os.path.join(os.path.dirname(os.path.abspath(out_path)),
                                                             "claims.json")
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
    drivers = sorted(by_driver, key=lambda d: (PAPER_ORDER.index(DRIVERS.get(d, ("Other",))[0]), natural_key(d)))
    all_rows = [r for d in drivers for r in by_driver[d]]
    report_dir = os.path.dirname(os.path.abspath(out_path))
    fig_dir = os.path.join(report_dir, "figures")
    fig_rel = os.path.relpath(fig_dir, report_dir)

    lines = ["# Reproduction report", ""]
    if not files:
        lines += [f"No claim files yet: `{claims_dir}` has no `*.csv`. Run the drivers (`make repro`).", ""]
    else:
        c, by_cause = counts(all_rows)
        lines += [f"**{headline(c, len(problems))}**"
                  + (f"; {len(problems)} unreadable row(s) or file(s) counted as failing checks" if problems else "")
                  + ".", ""]
        for paper in PAPER_ORDER:
            rows = [r for d in drivers if DRIVERS.get(d, ("Other",))[0] == paper for r in by_driver[d]]
            if rows:
                lines.append(f"- {paper}: {headline(counts(rows)[0])}")
        lines += ["",
                  "A *check* has a criterion computed from the run that can come out FAIL, and a negative control "
                  "in `make test` (the same criterion applied to a deliberately wrong configuration must FAIL). "
                  "A *measurement* reports a number with no verdict; a check whose criterion has no negative "
                  "control yet is listed as a measurement, with its criterion's outcome in words. Every failing "
                  "criterion names its cause: the paper's method as published, data missing from the paper "
                  "(reconstructed geometry), or our implementation.", "",
                  f"Checks with a negative control: {c['pass'] + c['fail']} of "
                  f"{c['pass'] + c['fail'] + c['unverified']} rows that have a criterion.", "",
                  "The cause columns count every failing criterion, with or without a negative control.", "",
                  "| Section | Checks | Pass | Fail: paper's method | Fail: missing data | Fail: implementation "
                  "| Measurements (of them checks without a control) | Run time (s) |",
                  "|---|---|---|---|---|---|---|---|"]
        for d in drivers:
            dc, dcause = counts(by_driver[d])
            times = [r["run_time_s"] for r in by_driver[d] if r["run_time_s"]]
            title = DRIVERS.get(d, ("", d))[1]
            lines.append(f"| [{cell(title)}](#{d.lower()}) | {dc['pass'] + dc['fail']} | {dc['pass']} | "
                         f"{dcause['paper_method']} | {dcause['missing_data']} | {dcause['implementation']} | "
                         f"{dc['measurement'] + dc['unverified']} ({dc['unverified']}) | "
                         f"{times[-1] if times else '-'} |")
        lines.append(f"| **all** | {c['pass'] + c['fail']} | {c['pass']} | {by_cause['paper_method']} | "
                     f"{by_cause['missing_data']} | {by_cause['implementation']} | "
                     f"{c['measurement'] + c['unverified']} ({c['unverified']}) | |")
        lines.append("")
        for d in drivers:
            paper, title, statement, figs = DRIVERS.get(d, ("Other", d, "", []))
            rows = by_driver[d]
            times = [r["run_time_s"] for r in rows if r["run_time_s"]]
            lines += [f'<a id="{d.lower()}"></a>', "", f"## {paper}, {title}", "",
                      f"**The paper:** {statement}" if statement else "", "",
                      f"**Driver:** `{d}`, run time {times[-1] if times else '?'} s. {headline(counts(rows)[0])}.",
                      ""]
            for fig in figs:
                if os.path.exists(os.path.join(fig_dir, fig)):
                    lines += [f"![{fig}]({fig_rel}/{fig})", ""]
                else:
                    lines += [f"*(figure {fig} not made yet: `make repro`)*", ""]
            if rows:
                lines += ["| Id | Claim | Paper | Measured | Criterion | Verdict |", "|---|---|---|---|---|---|"]
                for r in rows:
                    lines.append("| " + " | ".join(cell(r[k]) for k in ("id", "claim", "paper", "measured",
                                                                           "tolerance"))
                                 + f" | {cell(status_cell(r))} |")
                lines.append("")
        if problems or warnings:
            lines += ["## Problems", ""] + [f"- {p}" for p in problems + warnings] + [""]
            for p in problems + warnings:
                print(f"report.py: warning: {p}", file=sys.stderr)

    write_atomic(out_path, "\n".join(lines).rstrip("\n") + "\n")
    write_atomic(json_path, json.dumps([dict((k, r[k]) for k in ["driver"] + COLUMNS) | {"class": row_class(r)}
                                        for r in all_rows], indent=1) + "\n")


if __name__ == "__main__":
    main(sys.argv)
