"""Reading helpers for the Paper B (CDEM) figures: CSV tables with text columns.

potential_common.read_csv reads numeric tables only; the CDEM drivers also
write text columns (labels, scene and model names). The record reading
(with '#' lines as comments before the header only: text cells may start
with '#') and save_atomic are potential_common's.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from potential_common import plt, read_csv, read_records, save_atomic  # noqa: E402,F401


def read_table(path, text=()):
    """Returns (comment lines, {column: array}); columns named in `text` stay
    strings, the others are floats and must be finite."""
    comments, header, rows = read_records(path, comments_after_header=False)
    cols = {}
    for i, name in enumerate(header):
        vals = [r[i] for r in rows]
        if name in text:
            cols[name] = np.array(vals, dtype=object)
        else:
            a = np.array([float(v) for v in vals])
            if not np.all(np.isfinite(a)):
                raise SystemExit(f"{path}: non-finite values in column {name}")
            cols[name] = a
    return comments, cols


def read_rows(path, text=()):
    """Returns (comment lines, [ {column: value} per row ]): columns named in
    `text` stay strings; the others are floats, which must be finite, or None
    where the cell is empty (e.g. a run that stopped has no measured value)."""
    comments, header, rows = read_records(path, comments_after_header=False)
    out = []
    for rec in rows:
        r = dict(zip(header, rec))
        for k, v in r.items():
            if k in text:
                continue
            r[k] = float(v) if v != "" else None
            if r[k] is not None and not np.isfinite(r[k]):
                raise SystemExit(f"{path}: non-finite value in column {k}")
        out.append(r)
    return comments, out
