"""Shared reading, saving and command line of the figure scripts, and the
drawing of the potential-field maps (Paper A Figs. 4b, 5).

The potential maps' grid CSVs are written by the potential_fields driver:
'#' comment lines, a header 'x,y,inside,d_exit,phi', rows y-major (x varies
fastest).
"""
import csv
import math
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402


def read_records(path, comments_after_header=True):
    """(comment lines, header, data records as lists of strings) of a driver's CSV
    file. Lines starting with '#' before the header are comments, and so are
    those after it unless comments_after_header is False (a table whose text
    cells may start with '#'); empty lines are skipped. Fails when there is no
    header or no data row."""
    comments, rows, header = [], [], None
    with open(path, newline="") as f:
        for rec in csv.reader(f):
            if not rec:
                continue
            if rec[0].startswith("#") and (header is None or comments_after_header):
                comments.append(",".join(rec).lstrip("# ").rstrip())
            elif header is None:
                header = rec
            else:
                rows.append(rec)
    if header is None or not rows:
        raise SystemExit(f"{path}: no header or no data rows")
    return comments, header, rows


def read_csv(path):
    """Returns (comment lines, {column: float array}). Fails on non-finite data."""
    comments, header, rows = read_records(path)
    data = np.array([[float(v) for v in rec] for rec in rows], dtype=float)
    if not np.all(np.isfinite(data)):
        raise SystemExit(f"{path}: non-finite values")
    return comments, {name: data[:, i] for i, name in enumerate(header)}


def read_rows(path):
    """The rows of a CSV file as dicts (comment lines skipped); fails when there are none."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    return rows


def finite(text):
    """A CSV field as a finite float; fails on NaN or inf."""
    x = float(text)
    if not math.isfinite(x):
        raise SystemExit(f"non-finite value {text!r}")
    return x


def snapshot_outlines(sn, sel):
    """The closed outlines (x, y) of the blocks in the rows sel of a snapshot
    table (columns time, block, x, y: one row per vertex), block by block."""
    for b in np.unique(sn["block"][sel]):
        m = sel & (sn["block"] == b)
        x, y = sn["x"][m], sn["y"][m]
        yield np.append(x, x[0]), np.append(y, y[0])


def save_atomic(fig, out_png):
    os.makedirs(os.path.dirname(out_png) or ".", exist_ok=True)
    tmp = out_png + ".tmp"
    fig.savefig(tmp, dpi=150, format="png")
    plt.close(fig)
    os.replace(tmp, out_png)


def save_tight(fig, out_png, **tight_layout):
    """Lays the figure out tightly (tight_layout's arguments, e.g. rect) and saves it atomically."""
    fig.tight_layout(**tight_layout)
    save_atomic(fig, out_png)


def script_main(main, doc, n_args=2):
    """A figure script's command line: main(*args) with exactly n_args
    arguments (DATA_DIR OUT_PNG by default), else the usage (the script's doc)."""
    if len(sys.argv) != n_args + 1:
        raise SystemExit(doc)
    main(*sys.argv[1:])


def draw_potential(data_dir, name, title, out_png, highlight_below=None):
    """Filled contours of phi inside the polygon, outline on top, from the
    potential_fields driver's <name>_grid.csv and <name>_outline.csv in data_dir.

    highlight_below: edges shorter than this (m) are drawn in red and labelled.
    """
    grid_csv = os.path.join(data_dir, name + "_grid.csv")
    outline_csv = os.path.join(data_dir, name + "_outline.csv")
    notes, g = read_csv(grid_csv)
    _, o = read_csv(outline_csv)
    xs = np.unique(g["x"])
    ys = np.unique(g["y"])
    nx, ny = xs.size, ys.size
    if nx * ny != g["x"].size:
        raise SystemExit(f"{grid_csv}: {g['x'].size} rows are not a {nx} x {ny} grid")
    X = g["x"].reshape(ny, nx)
    Y = g["y"].reshape(ny, nx)
    phi = g["phi"].reshape(ny, nx)
    inside = g["inside"].reshape(ny, nx) > 0.5
    field = np.ma.masked_where(~inside, phi)

    fig, ax = plt.subplots(figsize=(7.5, 6.5), layout="constrained")
    top = float(phi.max())
    levels = np.linspace(0.0, top, 21)
    cf = ax.contourf(X, Y, field, levels=levels, cmap="viridis")
    ax.contour(X, Y, field, levels=levels[1::2], colors="white", linewidths=0.4, alpha=0.7)
    cb = fig.colorbar(cf, ax=ax, shrink=0.85)
    cb.locator = matplotlib.ticker.MaxNLocator(8)
    cb.update_ticks()
    cb.set_label(r"potential $\varphi = k_n\, d_{exit} / H$  (Pa)")

    px = np.append(o["x"], o["x"][0])
    py = np.append(o["y"], o["y"][0])
    ax.plot(px, py, "k-", lw=1.2, label="polygon outline (reconstructed)")
    ax.plot([], [], "-", color="0.75", lw=0.8, label="iso-potential lines (white)")
    if highlight_below is not None:
        n = o["x"].size
        first = True
        for i in range(n):
            if o["edge_length"][i] < highlight_below:
                j = (i + 1) % n
                ax.plot([o["x"][i], o["x"][j]], [o["y"][i], o["y"][j]], "r-", lw=3.0,
                        label="edges shorter than %g m" % highlight_below if first else None)
                first = False
                mx, my = 0.5 * (o["x"][i] + o["x"][j]), 0.5 * (o["y"][i] + o["y"][j])
                ax.annotate(f"{o['edge_length'][i]:.3g} m edge", (mx, my), xytext=(12, 8),
                            textcoords="offset points", color="red", fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.09), ncol=3, frameon=False)
    note = next((c for c in notes if c.startswith("RECONSTRUCTED")), "")
    ax.text(0.0, -0.17, textwrap.fill(note + f". Grid {nx} x {ny}; white: outside (phi = 0).", 110),
            transform=ax.transAxes, fontsize=7, color="0.3", va="top")
    save_atomic(fig, out_png)
