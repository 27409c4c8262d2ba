"""Expected verdicts of every claim row: compare a run with the committed list, or rewrite it.

usage: verdicts.py compare CLAIMS_DIR EXPECTED_CSV [CONTROL_TESTS]
       verdicts.py write   CLAIMS_DIR EXPECTED_CSV

CLAIMS_DIR holds the drivers' <driver>.csv files (repro/common/claims.hpp).
EXPECTED_CSV (repro/expected_verdicts.csv) has one line per row:
  driver,id,scope,kind,verdict,cause
with scope paper, extension, option or suite; kind check, fitted (a check
on a scene fitted to the number it checks) or measurement; verdict PASS or
FAIL for a check or a fitted check and "-" for a measurement; cause the
FAIL's cause category (empty for a PASS or a measurement).

compare exits 1, listing the rows, when a row's scope, kind, verdict or
cause differs from the list, a listed row is missing, a row is new, an id
repeats, a row has no valid scope, or a failing check has no cause or no
root cause (every FAIL is explained); it exits 0 otherwise. With CONTROL_TESTS (a file with the test-case names of
repro_controls_tests, one per line: its --list-test-names-only), a row whose
control reads "repro_controls: <name>" must name one of them: a control that
does not exist controls nothing. write replaces EXPECTED_CSV with the run's verdicts
(make expected-verdicts); commit that change on its own, saying why.
"""
import csv
import glob
import os
import sys

FIELDS = ["driver", "id", "scope", "kind", "verdict", "cause"]
SCOPES = ("paper", "extension", "option", "suite")
KINDS = ("check", "fitted", "measurement")
CAUSES = ("paper_method", "missing_data", "our_reading", "implementation")


CONTROL_PREFIX = "repro_controls: "


def run_verdicts(claims_dir, tests=None):
    """{(driver, id): (scope, kind, verdict, cause)} of a run, and the problems found;
    tests: the repro_controls test-case names a row's control must be among."""
    rows, problems = {}, []
    files = sorted(glob.glob(os.path.join(claims_dir, "*.csv")))
    if not files:
        problems.append(f"no claim files in {claims_dir}")
    for path in files:
        driver = os.path.splitext(os.path.basename(path))[0]
        with open(path, newline="", encoding="utf-8") as f:
            for rec in csv.DictReader(f):
                if any(rec.get(k) is None for k in ("id", "scope", "kind", "status", "cause", "root_cause")):
                    problems.append(f"{driver}: a row lacks id/scope/kind/status/cause/root_cause (old claims format?)")
                    break
                key = (driver, rec["id"])
                kind, scope = rec["kind"], rec["scope"]
                verdict = rec["status"] if kind in ("check", "fitted") else "-"
                cause = rec["cause"] if verdict == "FAIL" else ""
                if key in rows:
                    problems.append(f"{driver} {rec['id']}: id repeats")
                if scope not in SCOPES:
                    problems.append(f"{driver} {rec['id']}: scope '{scope}' is none of {', '.join(SCOPES)}")
                if kind not in KINDS:
                    problems.append(f"{driver} {rec['id']}: kind '{kind}' is none of {', '.join(KINDS)}")
                if verdict == "FAIL" and cause not in CAUSES:
                    problems.append(f"{driver} {rec['id']}: FAIL without a cause")
                elif verdict == "FAIL" and not rec["root_cause"]:
                    problems.append(f"{driver} {rec['id']}: FAIL without a root cause")
                control = rec.get("control") or ""
                if tests is not None and control.startswith(CONTROL_PREFIX) and \
                        control[len(CONTROL_PREFIX):] not in tests:
                    problems.append(f"{driver} {rec['id']}: names control '{control[len(CONTROL_PREFIX):]}', "
                                    f"not a test case of repro_controls")
                rows[key] = (scope, kind, verdict, cause)
    return rows, problems


def read_expected(path):
    with open(path, newline="", encoding="utf-8") as f:
        return {(r["driver"], r["id"]): (r["scope"], r["kind"], r["verdict"], r["cause"]) for r in csv.DictReader(f)}


def show(v):
    if v is None:
        return "absent"
    scope, kind, verdict, cause = v
    text = kind if verdict == "-" else (f"{verdict}" + (" (fitted)" if kind == "fitted" else "")
                                        + (f" ({cause})" if cause else ""))
    return f"{text} [{scope}]"


def compare(claims_dir, expected_path, tests_path=None):
    tests = None
    if tests_path:
        with open(tests_path, encoding="utf-8") as f:
            tests = {line.strip() for line in f if line.strip()}
    got, problems = run_verdicts(claims_dir, tests)
    want = read_expected(expected_path)
    changed = []
    for key in sorted(set(got) | set(want)):
        g, w = got.get(key), want.get(key)
        if g != w:
            changed.append(f"  {key[0]} {key[1]}: expected {show(w)}, got {show(g)}")
    checks = [v for v in got.values() if v[1] in ("check", "fitted")]
    print(f"verdicts: {len(got)} rows from {claims_dir}: {len(checks)} checks "
          f"({sum(v[2] == 'PASS' for v in checks)} PASS, {sum(v[2] == 'FAIL' for v in checks)} FAIL, "
          f"{sum(v[1] == 'fitted' for v in checks)} of them fitted), {len(got) - len(checks)} measurements")
    for p in problems:
        print(f"verdicts: problem: {p}")
    if changed:
        print(f"verdicts: {len(changed)} row(s) differ from {expected_path}:")
        print("\n".join(changed))
        print("If a change is intended: make expected-verdicts, then commit "
              f"{expected_path} on its own, saying why.")
    if changed or problems:
        return 1
    print(f"verdicts: every row matches {expected_path}")
    return 0


def write(claims_dir, expected_path):
    got, problems = run_verdicts(claims_dir)
    for p in problems:
        print(f"verdicts: problem: {p}")
    if problems:
        return 1
    tmp = expected_path + ".tmp"
    with open(tmp, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(FIELDS)
        for key in sorted(got):
            w.writerow([key[0], key[1], *got[key]])
    os.replace(tmp, expected_path)
    print(f"verdicts: wrote {len(got)} rows to {expected_path}")
    return 0


def main(argv):
    if argv[1:2] == ["compare"] and len(argv) in (4, 5):
        return compare(*argv[2:])
    if argv[1:2] == ["write"] and len(argv) == 4:
        return write(argv[2], argv[3])
    raise SystemExit(__doc__)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
