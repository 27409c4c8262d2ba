"""ctest of the claims tools: figures/report.py and repro/common/verdicts.py.

usage: test_claims_tools.py SOURCE_DIR

Writes small claim files in a temporary directory and checks that
 - the headline counts each paper's own claims (scope paper) apart from the
   extensions, options and suite tests, each on its own line, and never one
   number adding them up; a measurement is never a PASS, a fitted check is
   never counted as reproduced, a check without a negative control is
   listed with the measurements;
 - each paper's ledger lists its own claims in the paper's order, opens
   with "reproduced in full" or "in part" and says what is out of scope;
 - a FAIL links to its root cause, which the "Why claims fail" section
   explains once with its rows; a FAIL without a cause, a row without a
   scope and a row whose text names source files or the project's history
   are listed as problems;
 - no table cell is longer than the report's limit, and a report of clean
   rows has no line matching the words it must not use;
 - the provenance block gives commit, compiler and flags (from a build
   tree), machine, OS, date, wall time and the reconstructed scenes;
 - every root cause the drivers can name (repro/common/claims.cpp) has a
   paragraph in the report;
 - figures appear inline (markdown image), claims.json holds every row with
   its scope;
 - verdicts.py compare fails on a row naming a control test case that does
   not exist, and on a row without a scope;
 - verdicts.py write + compare round-trips, and compare fails, naming the
   row, on a changed verdict, a changed scope, a new row, a missing row and
   a FAIL without a cause.
"""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile
import time

HEADER = ["id", "section", "scope", "kind", "claim", "paper", "measured", "tolerance", "status", "cause",
          "root_cause", "cause_text", "control", "run_time_s"]
FORBIDDEN = re.compile(r"issue [0-9]|item [0-9]|spec|\.cpp|\.hpp|::", re.IGNORECASE)


def write(path, rows):
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(HEADER)
        for r in rows:
            w.writerow(r)


def row(id_, kind="check", status="PASS", cause="", control="ctl", text="", scope="paper", root="",
        measured="1.0", paper="'a quote' (Sect. 1)"):
    if status == "FAIL" and cause and not root:
        root = {"paper_method": "friction_start_up", "missing_data": "unstated_setup",
                "our_reading": "sub_model_reading", "implementation": "unexplained"}[cause]
    return [id_, id_.split(":")[0], scope, kind, "claim " + id_, paper, measured, "< 2", status, cause, root, text,
            control if kind != "measurement" else "", "1.5"]


def run(args, expect_rc):
    p = subprocess.run([sys.executable] + args, capture_output=True, text=True)
    if p.returncode != expect_rc:
        raise SystemExit(f"FAIL: {' '.join(args)} returned {p.returncode}, expected {expect_rc}\n"
                         f"{p.stdout}\n{p.stderr}")
    return p.stdout


def table_cells(text):
    """Every cell of every Markdown table row (split at unescaped pipes)."""
    cells = []
    for line in text.splitlines():
        if line.startswith("|") and not re.match(r"^\|(-+\|)+$", line):
            cells += [c.strip() for c in re.split(r"(?<!\\)\|", line)[1:-1]]
    return cells


def main(src):
    report = os.path.join(src, "figures", "report.py")
    verdicts = os.path.join(src, "repro", "common", "verdicts.py")
    failures = []

    def check(cond, what):
        if not cond:
            failures.append(what)

    # Every root cause the drivers can name has a paragraph in the report.
    with open(os.path.join(src, "repro", "common", "claims.cpp"), encoding="utf-8") as f:
        cpp_roots = set(re.findall(r'case Root::k\w+: return "(\w+)";', f.read()))
    sys.path.insert(0, os.path.join(src, "figures"))
    import report as report_module  # noqa: E402
    check(len(cpp_roots) >= 10, "root names found in claims.cpp")
    check(cpp_roots == set(report_module.ROOTS), f"root causes of claims.cpp and the report's ROOTS differ: "
                                                 f"{sorted(cpp_roots ^ set(report_module.ROOTS))}")
    for key, (title, cause, text, option, _) in report_module.ROOTS.items():
        check(cause in report_module.CAUSES, f"root cause {key}: category {cause}")
        check(option is None or option in report_module.OPTIONS, f"root cause {key}: option {option}")
        check(not FORBIDDEN.search(title + " " + text), f"root cause {key}: forbidden words")
    for key, parts in report_module.OPTIONS.items():
        check(not FORBIDDEN.search(" ".join(parts)), f"option {key}: forbidden words")

    with tempfile.TemporaryDirectory() as tmp:
        claims = os.path.join(tmp, "claims")
        os.makedirs(claims)
        os.makedirs(os.path.join(tmp, "figures"))
        open(os.path.join(tmp, "figures", "fig08_two_squares.png"), "wb").close()
        long_text = "a long measurement; " * 40
        write(os.path.join(claims, "4_1_two_squares.csv"),
              [row("4.1:a", measured=long_text), row("4.1:b", status="FAIL", cause="missing_data", text="geometry lost"),
               row("4.1:m", kind="measurement", status=""), row("4.1:u", control=""),
               row("4.1:x", scope="extension"), row("4.1:o", scope="option", status="FAIL", cause="implementation")])
        write(os.path.join(claims, "3_1_contact_statements.csv"), [row("3.1.2:e")])
        write(os.path.join(claims, "B_6_two_prisms.csv"),
              [row("B-6:f", kind="fitted"), row("B-6:r", status="FAIL", cause="our_reading", text="drift 0.39"),
               row("B-6:t")])
        write(os.path.join(claims, "S1_work_precision.csv"), [row("S1:x", scope="suite")])
        md, js = os.path.join(tmp, "report.md"), os.path.join(tmp, "claims.json")
        # A build tree as CMake leaves it (Makefile generator).
        build = os.path.join(tmp, "build")
        os.makedirs(os.path.join(build, "lib", "CMakeFiles", "dda.dir"))
        with open(os.path.join(build, "CMakeCache.txt"), "w", encoding="utf-8") as f:
            f.write(f"CMAKE_BUILD_TYPE:STRING=Release\nCMAKE_CXX_COMPILER:FILEPATH={sys.executable}\n"
                    "CMAKE_CXX_FLAGS_RELEASE:STRING=-O3 -DNDEBUG\nDDA_LTO:BOOL=ON\n")
        with open(os.path.join(build, "lib", "CMakeFiles", "dda.dir", "flags.make"), "w", encoding="utf-8") as f:
            f.write("CXX_DEFINES = -DDDA_HAVE_OPENMP\n\nCXX_FLAGS = -O3 -DNDEBUG -fopenmp -std=c++17\n")
        run([report, "--build", build, "--started", str(time.time() - 42), claims, md, js], 0)
        text = open(md, encoding="utf-8").read()

        # Headline: each paper's own claims, then the other scopes on lines of their own.
        # Paper A: 3.1.2:e and 4.1:a pass, 4.1:b fails; 4.1:m and 4.1:u are measurements.
        check("- **Paper A: 2 of 3 of its claims reproduced (2 of its statements measured without a verdict)**"
              in text, "Paper A headline")
        # Paper B: B-6:t passes, B-6:r fails, B-6:f is fitted (not counted as reproduced).
        check("- **Paper B: 1 of 3 of its claims reproduced (1 more agrees only on a scene we fitted to that "
              "number, not counted)**" in text, "Paper B headline: a fitted check is not reproduced")
        check("- Tests beyond the papers: Paper A 1 of 1 checks pass" in text, "extensions on their own line")
        check("- Our options beside the papers' methods: Paper A 0 of 1 checks pass" in text, "options line")
        check("- The suite's own tests (guards, integrator orders, work-precision, stability maps): 1 of 1 checks "
              "pass" in text, "suite line")
        check(not re.search(r"\b[0-9]+ of [0-9]+ checks pass \([0-9]+ measurements", text.split("## ")[1]),
              "no single number adding the scopes up")
        # The ledgers: the paper's claims in its order, reproduced in part, out of scope.
        ledger_a = text.split("## Paper A: its claims")[1].split("\n## ")[0]
        check("Paper A's results were reproduced in part: 2 of its 3 claims checked here pass, 1 fail" in ledger_a,
              "ledger opening line")
        check(ledger_a.index("| 3.1.2 |") < ledger_a.index("| 4.1 |"), "ledger in the paper's order")
        check("claim 4.1:x" not in ledger_a and "| extension |" not in ledger_a, "ledger holds scope paper only")
        check("Out of scope for Paper A:" in ledger_a, "ledger says what is out of scope")
        check("Paper B's results were reproduced in part" in text, "Paper B ledger")
        # A FAIL links to its root cause, explained once with its rows.
        check("**FAIL**: [A set-up the paper does not give](#cause-unstated_setup)" in ledger_a,
              "ledger FAIL links to its root cause")
        why = text.split("## Why claims fail")[1].split("\n## ")[0]
        check(why.count("### A set-up the paper does not give") == 1, "root cause listed once")
        check('<a id="cause-sub_model_reading"></a>' in why and "Our reading of Paper B" in why,
              "our reading of an incompletely stated section is a root cause")
        check("*Our reading of a section the paper leaves incomplete.*" in why, "our_reading category named")
        # Provenance.
        head = text.split("## What was reproduced")[0]
        for what in ("**Commit:**", "**Compiler:**", "flags `-O3 -DNDEBUG -fopenmp -std=c++17 -DDDA_HAVE_OPENMP`",
                     "link-time optimisation on", "**Machine:**", "**OS:**", "**Date:**", "**Wall time:** 4",
                     "**Reconstructed geometry**", "Paper B Sect. 6 (the prisms of Fig. 12"):
            check(what in head, f"provenance: {what}")
        # Cells: none above the limit; the long text is cut, claims.json keeps it.
        cells = table_cells(text)
        check(cells and max(len(c) for c in cells) <= 300, f"cell length {max(len(c) for c in cells)}")
        check("a long measurement; a long measurement" in text and "…" in text, "a long cell is cut, not dropped")
        check(len([ln for ln in text.splitlines() if FORBIDDEN.search(ln)]) == 0,
              "a report of clean rows has no forbidden words")
        check("![fig08_two_squares.png](figures/fig08_two_squares.png)" in text, "figure inline")
        # 5 controlled passing checks in the scene tables, 3 of them scope paper in the ledgers too.
        check(text.count("| PASS |") == 8, "only controlled passing checks are shown as PASS")
        check("measured (criterion met; no negative control)" in text, "uncontrolled check listed as measurement")
        rows = json.load(open(js, encoding="utf-8"))
        check(len(rows) == 11 and all(r["scope"] in ("paper", "extension", "option", "suite") for r in rows),
              "claims.json holds every row with its scope")
        check({r["class"] for r in rows} == {"pass", "fail", "fitted", "measurement", "unverified"},
              "claims.json holds every row with its class")
        check(any(r["measured"] == long_text for r in rows), "claims.json keeps the full text")

        # A row without a scope and a row naming the project's history are problems.
        write(os.path.join(claims, "S1_work_precision.csv"),
              [row("S1:x", scope=""), row("S1:y", scope="suite", measured="see model.cpp")])
        run([report, claims, md, js], 0)
        text = open(md, encoding="utf-8").read()
        check("S1_work_precision.csv line 2: scope '' is none of paper, extension, option, suite" in text,
              "a row without a scope is a problem")
        check("S1_work_precision.csv line 3: measured of row S1:y name source files, code or the project's "
              "history" in text, "forbidden words are a problem")
        write(os.path.join(claims, "S1_work_precision.csv"), [row("S1:x", scope="suite")])

        expected = os.path.join(tmp, "expected.csv")
        run([verdicts, "write", claims, expected], 0)
        run([verdicts, "compare", claims, expected], 0)
        check(open(expected, encoding="utf-8").readline().strip() == "driver,id,scope,kind,verdict,cause",
              "expected verdicts list the scope")
        # A row naming a repro_controls test case that does not exist.
        tests = os.path.join(tmp, "control_tests.txt")
        with open(tests, "w", encoding="utf-8") as f:
            f.write("4.1 real control\n")
        write(os.path.join(claims, "S1_work_precision.csv"),
              [row("S1:x", scope="suite", control="repro_controls: 4.1 real control")])
        run([verdicts, "compare", claims, expected, tests], 0)
        write(os.path.join(claims, "S1_work_precision.csv"),
              [row("S1:x", scope="suite", control="repro_controls: no such test")])
        out = run([verdicts, "compare", claims, expected, tests], 1)
        check("names control 'no such test', not a test case of repro_controls" in out, "missing control test named")
        # A row without a scope, a changed scope.
        write(os.path.join(claims, "S1_work_precision.csv"), [row("S1:x", scope="")])
        out = run([verdicts, "compare", claims, expected], 1)
        check("S1_work_precision S1:x: scope '' is none of paper, extension, option, suite" in out,
              "verdicts: a row without a scope")
        write(os.path.join(claims, "S1_work_precision.csv"), [row("S1:x", scope="extension")])
        out = run([verdicts, "compare", claims, expected], 1)
        check("S1_work_precision S1:x: expected PASS [suite], got PASS [extension]" in out, "changed scope named")
        # A changed verdict, a new row, a missing row.
        write(os.path.join(claims, "S1_work_precision.csv"),
              [row("S1:x", scope="suite", status="FAIL", cause="implementation", text="bug"),
               row("S1:new", scope="suite")])
        write(os.path.join(claims, "4_1_two_squares.csv"),
              [row("4.1:a"), row("4.1:b", status="FAIL", cause="missing_data", text="geometry lost"),
               row("4.1:u", control=""), row("4.1:x", scope="extension"),
               row("4.1:o", scope="option", status="FAIL", cause="implementation")])
        out = run([verdicts, "compare", claims, expected], 1)
        check("S1_work_precision S1:x: expected PASS [suite], got FAIL (implementation) [suite]" in out,
              "changed verdict named")
        check("S1_work_precision S1:new: expected absent" in out, "new row named")
        check("4_1_two_squares 4.1:m: expected measurement [paper], got absent" in out, "missing row named")
        # A FAIL without a cause fails even when the list expects it.
        write(os.path.join(claims, "S1_work_precision.csv"), [row("S1:x", scope="suite", status="FAIL")])
        for name in ("4_1_two_squares.csv", "3_1_contact_statements.csv", "B_6_two_prisms.csv"):
            os.remove(os.path.join(claims, name))
        run([verdicts, "write", claims, expected], 1)
        out = run([verdicts, "compare", claims, expected], 1)
        check("FAIL without a cause" in out, "FAIL without a cause is a problem")
        # The report lists it as a problem too.
        run([report, claims, md, js], 0)
        check("FAIL without a cause" in open(md, encoding="utf-8").read(), "report lists an unexplained FAIL")

    if failures:
        raise SystemExit("FAIL: " + "; ".join(failures))
    print("claims tools: all checks passed")


if __name__ == "__main__":
    main(sys.argv[1])
