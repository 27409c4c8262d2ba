"""Merge every claims CSV into one Markdown report.

usage: report.py CLAIMS_DIR REPORT_MD

Each <CLAIMS_DIR>/*.csv has the columns section,claim,paper,measured,
tolerance,status (status PASS or FAIL), written by a driver. The report lists
them sorted by section (natural order: 3.2.2 < 4.1 < 4.10 < B-6), then by file
and row. A file that cannot be read, lacks a column or has another status is
listed under "Problems" and counted as failing. The report is written
atomically (tmp + rename); with no claim files it says so.
"""
import csv
import glob
import os
import re
import sys

COLUMNS = ["section", "claim", "paper", "measured", "tolerance", "status"]


def natural_key(text):
    return [(0, int(t), "") if t.isdigit() else (1, 0, t.lower()) for t in re.split(r"(\d+)", text) if t]


def cell(text):
    """Markdown table cell: no line breaks, pipes escaped."""
    return " ".join(str(text).split()).replace("|", "\\|")


def read_claims(path):
    rows, problems = [], []
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            missing = [c for c in COLUMNS if c not in (reader.fieldnames or [])]
            if missing:
                return [], [f"`{os.path.basename(path)}`: missing column(s) {', '.join(missing)}"]
            for line, rec in enumerate(reader, start=2):
                if None in rec or any(rec[c] is None for c in COLUMNS):
                    problems.append(f"`{os.path.basename(path)}` line {line}: wrong number of fields")
                    continue
                status = rec["status"].strip().upper()
                if status not in ("PASS", "FAIL"):
                    problems.append(f"`{os.path.basename(path)}` line {line}: status '{rec['status']}'"
                                    " is neither PASS nor FAIL")
                    continue
                rows.append(dict(rec, status=status))
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        problems.append(f"`{os.path.basename(path)}`: cannot read ({e})")
    return rows, problems


def main(argv):
    if len(argv) != 3:
        raise SystemExit(__doc__)
    claims_dir, out_path = argv[1], argv[2]
    files = sorted(glob.glob(os.path.join(claims_dir, "*.csv")))
    rows, problems = [], []
    for order, path in enumerate(files):
        r, p = read_claims(path)
        for i, rec in enumerate(r):
            rec["_order"] = (order, i)
            rec["_file"] = os.path.basename(path)
        rows += r
        problems += p
    rows.sort(key=lambda r: (natural_key(r["section"]), r["_order"]))

    passed = sum(r["status"] == "PASS" for r in rows)
    total = len(rows) + len(problems)
    lines = ["# Reproduction report", ""]
    if not files:
        lines += [f"No claim files yet: `{claims_dir}` has no `*.csv`. Run the drivers (`make repro`).", ""]
    else:
        lines += [f"**{passed} of {total} claims pass** ({len(files)} claim file(s) in `{claims_dir}`"
                  + (f"; {len(problems)} unreadable row(s) or file(s) counted as failing" if problems else "")
                  + ").", ""]
        if rows:
            lines += ["| Section | Claim | Paper | Measured | Tolerance | Status |",
                      "|---|---|---|---|---|---|"]
            for r in rows:
                status = "PASS" if r["status"] == "PASS" else "**FAIL**"
                lines.append("| " + " | ".join(cell(r[c]) for c in COLUMNS[:5]) + f" | {status} |")
            lines.append("")
        if problems:
            lines += ["## Problems", ""] + [f"- {p}" for p in problems] + [""]
            for p in problems:
                print(f"report.py: warning: {p}", file=sys.stderr)

    fig_dir = os.path.join(os.path.dirname(os.path.abspath(out_path)), "figures")
    figs = sorted(glob.glob(os.path.join(fig_dir, "*.png")))
    if figs:
        rel = os.path.relpath(fig_dir, os.path.dirname(os.path.abspath(out_path)))
        lines += ["## Figures", ""] + [f"- [{os.path.basename(f)}]({rel}/{os.path.basename(f)})" for f in figs] + [""]

    os.makedirs(os.path.dirname(os.path.abspath(out_path)), exist_ok=True)
    tmp = out_path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write("\n".join(lines).rstrip("\n") + "\n")
    os.replace(tmp, out_path)


if __name__ == "__main__":
    main(sys.argv)
