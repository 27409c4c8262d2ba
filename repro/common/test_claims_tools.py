"""ctest of the claims tools: figures/report.py and repro/common/verdicts.py.

usage: test_claims_tools.py SOURCE_DIR

Writes small claim files in a temporary directory and checks that
 - the headline counts checks only (a measurement is never a PASS; a check
   without a negative control is listed with the measurements),
 - a FAIL shows its cause, a FAIL without a cause is a problem,
 - figures appear inline (markdown image), claims.json holds every row,
 - verdicts.py compare fails on a row naming a control test case that does
   not exist;
 - verdicts.py write + compare round-trips, and compare fails, naming the
   row, on a changed verdict, a new row, a missing row and a FAIL without a
   cause.
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

HEADER = ["id", "section", "kind", "claim", "paper", "measured", "tolerance", "status", "cause", "cause_text",
          "control", "run_time_s"]


def write(path, rows):
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(HEADER)
        for r in rows:
            w.writerow(r)


def row(id_, kind="check", status="PASS", cause="", control="ctl", text=""):
    return [id_, id_.split(":")[0], kind, "claim " + id_, "paper", "1.0", "< 2", status, cause, text,
            control if kind == "check" else "", "1.5"]


def run(args, expect_rc):
    p = subprocess.run([sys.executable] + args, capture_output=True, text=True)
    if p.returncode != expect_rc:
        raise SystemExit(f"FAIL: {' '.join(args)} returned {p.returncode}, expected {expect_rc}\n"
                         f"{p.stdout}\n{p.stderr}")
    return p.stdout


def main(src):
    report = os.path.join(src, "figures", "report.py")
    verdicts = os.path.join(src, "repro", "common", "verdicts.py")
    failures = []

    def check(cond, what):
        if not cond:
            failures.append(what)

    with tempfile.TemporaryDirectory() as tmp:
        claims = os.path.join(tmp, "claims")
        os.makedirs(claims)
        os.makedirs(os.path.join(tmp, "figures"))
        open(os.path.join(tmp, "figures", "fig08_two_squares.png"), "wb").close()
        write(os.path.join(claims, "4_1_two_squares.csv"),
              [row("4.1:a"), row("4.1:b", status="FAIL", cause="missing_data", text="geometry lost"),
               row("4.1:m", kind="measurement", status=""), row("4.1:u", control="")])
        write(os.path.join(claims, "S1_work_precision.csv"), [row("S1:x")])
        md, js = os.path.join(tmp, "report.md"), os.path.join(tmp, "claims.json")
        run([report, claims, md, js], 0)
        text = open(md, encoding="utf-8").read()
        # 2 controlled checks pass (4.1:a, S1:x), 1 fails; 4.1:m and 4.1:u are measurements.
        check("**2 of 3 checks pass (2 measurements, 1 of them checks still without a negative control)" in text,
              "headline counts checks only")
        check("- Paper A: 1 of 2 checks pass" in text, "per-paper headline")
        check("![fig08_two_squares.png](figures/fig08_two_squares.png)" in text, "figure inline")
        check("**FAIL** (missing data): geometry lost" in text, "FAIL shows its cause")
        check(text.count("| PASS |") == 2, "only controlled passing checks are shown as PASS")
        check("measurement (criterion met; no negative control yet)" in text, "uncontrolled check listed as measurement")
        rows = json.load(open(js, encoding="utf-8"))
        check(len(rows) == 5 and {r["class"] for r in rows} == {"pass", "fail", "measurement", "unverified"},
              "claims.json holds every row with its class")

        expected = os.path.join(tmp, "expected.csv")
        run([verdicts, "write", claims, expected], 0)
        run([verdicts, "compare", claims, expected], 0)
        # A row naming a repro_controls test case that does not exist.
        tests = os.path.join(tmp, "control_tests.txt")
        with open(tests, "w", encoding="utf-8") as f:
            f.write("4.1 real control\n")
        write(os.path.join(claims, "S1_work_precision.csv"), [row("S1:x", control="repro_controls: 4.1 real control")])
        run([verdicts, "compare", claims, expected, tests], 0)
        write(os.path.join(claims, "S1_work_precision.csv"), [row("S1:x", control="repro_controls: no such test")])
        out = run([verdicts, "compare", claims, expected, tests], 1)
        check("names control 'no such test', not a test case of repro_controls" in out, "missing control test named")
        write(os.path.join(claims, "S1_work_precision.csv"), [row("S1:x")])
        # A changed verdict, a new row, a missing row.
        write(os.path.join(claims, "S1_work_precision.csv"),
              [row("S1:x", status="FAIL", cause="implementation", text="bug"), row("S1:new")])
        write(os.path.join(claims, "4_1_two_squares.csv"),
              [row("4.1:a"), row("4.1:b", status="FAIL", cause="missing_data", text="geometry lost"),
               row("4.1:u", control="")])
        out = run([verdicts, "compare", claims, expected], 1)
        check("S1_work_precision S1:x: expected PASS, got FAIL (implementation)" in out, "changed verdict named")
        check("S1_work_precision S1:new: expected absent" in out, "new row named")
        check("4_1_two_squares 4.1:m: expected measurement, got absent" in out, "missing row named")
        # A FAIL without a cause fails even when the list expects it.
        write(os.path.join(claims, "S1_work_precision.csv"), [row("S1:x", status="FAIL")])
        os.remove(os.path.join(claims, "4_1_two_squares.csv"))
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
